"""Checks of problem 19: the parallel-axis theorem, composite bodies, and the inertia of the object of Figure 21
(about the 3-axis, as a multiple of m/120)."""

import numpy as np

from checks._answers import typed_failure
from checks._effects import assert_no_side_effects
from checks._rigid import FINITE, ROTATIONS, compact, vectors
from grader import strategies as st
from grader.checking import EXACT, STAGE_RANDOM, STAGE_VALUES, Mistake, Tol, check, fail
from probes import problem_19 as p19

TITLE = "Calculating Inertia Matrices"

#: the answer is an integer multiple of m/120
INTEGER = Tol("integer answer", 0.5)
SIGN_HINT = ("The parallel-axis term is ADDED: I_O = I_G + m (|r|² E - r r^T). The inertia about the centre of "
             "gravity is the smallest about any parallel axis.")


@st.composite
def inertias(draw):
    A = draw(ROTATIONS)
    x2, y2, z2 = (draw(st.floats(0.1, 3.0, **FINITE)) for _ in range(3))
    return A @ np.diag([y2 + z2, x2 + z2, x2 + y2]) @ A.T


MASSES = st.floats(0.1, 10.0, **FINITE)


def _steiner(r):
    r = np.asarray(r, dtype=float)
    return (r @ r) * np.eye(3) - np.outer(r, r)


@check(1, title="parallel_axis(I_G, m, r) = I_G + m (|r|² E - r r^T) on random bodies", stage=STAGE_RANDOM,
       group="parallel_axis")
def check_parallel_axis(ctx):
    def mistakes(args, expected):
        I_G, m, r = args
        return [Mistake("sign_flip", I_G - m * _steiner(r), SIGN_HINT),
                Mistake("missing_outer_product", I_G + m * (r @ r) * np.eye(3), "The shift is m (|r|² E - r r^T): "
                        "the outer product r r^T is missing (it gives the off-diagonal products of inertia)."),
                Mistake("outer_sign", I_G + m * ((r @ r) * np.eye(3) + np.outer(r, r)), "The outer product is "
                        "subtracted: m (|r|² E - r r^T).")]

    ctx.student(p19.parallel_axis, np.eye(3), 1.0, [1.0, 2.0, 3.0])
    ctx.compare_random(p19.parallel_axis, st.tuples(inertias(), MASSES, vectors(3.0)),
                       name="parallel_axis(I_G, m, r)", tol=EXACT, mistakes=mistakes, examples=10,
                       describe=lambda a: f"I_G = {compact(a[0])}, m = {a[1]!r}, r = {compact(a[2])}")


@st.composite
def composites(draw):
    n = draw(st.integers(1, 4))
    masses = np.array([draw(MASSES) for _ in range(n)])
    centres = np.array([draw(vectors(3.0)) for _ in range(n)])
    return masses, centres, np.array([draw(inertias()) for _ in range(n)])


@check(1, title="composite_inertia: the parts' inertias shifted to the common centre of gravity and summed (random "
       "parts)", stage=STAGE_RANDOM, group="composite_inertia")
def check_composite_inertia(ctx):
    def mistakes(args, expected):
        masses, centres, inertias = args
        r_G = masses @ centres / masses.sum()
        return [
            Mistake("about_origin", sum(I + m * _steiner(r) for m, r, I in zip(masses, centres, inertias)),
                    "The parts are shifted to the common centre of gravity r_G = sum m_k r_k / sum m_k, not to the "
                    "origin: use r_k - r_G."),
            Mistake("sign_flip", sum(I - m * _steiner(r - r_G) for m, r, I in zip(masses, centres, inertias)),
                    SIGN_HINT),
            Mistake("no_parallel_axis", sum(inertias), "Each part's inertia is about its own centre: shift it to "
                    "the common centre of gravity with the parallel-axis theorem before summing."),
        ]

    ctx.student(p19.composite, [1.0], [[0.0, 0.0, 0.0]], [np.eye(3)])
    ctx.compare_random(p19.composite, composites(), name="composite_inertia", tol=EXACT,
                       mistakes=mistakes, examples=10)


def _figure_21(blocks, steiner_sign=1.0, own_factor=1.0):
    """I3 / (m/120) of the object of Figure 21 from the package's blocks (m = 1), with a mistake applied: the sign
    of the parallel-axis term, or a factor on each block's own moment (4 for m/3 instead of m/12)."""
    masses, centres, inertias = (np.asarray(x, dtype=float) for x in blocks)
    r_G = masses @ centres / masses.sum()
    I = sum(own_factor * I_k + steiner_sign * m * _steiner(r - r_G) for m, r, I_k in zip(masses, centres, inertias))
    return 120 * I[2, 2]


@check(2, title="answers.toml: I3 of the object of Figure 21 as a multiple of m/120", stage=STAGE_VALUES,
       group="answer")
def check_answer(ctx):
    expected = ctx.reference(p19.answer)
    blocks = ctx.reference(p19.blocks)
    given = ctx.answer("I3_in_m_over_120")
    try:
        value = float(given)
    except (TypeError, ValueError):
        fail(f"[problem_19] I3_in_m_over_120 must be a number, got {given!r}.")
    if abs(value - expected) <= INTEGER.atol:
        return
    message = (f"I3 / (m/120) is not the expected value.\ntolerance: {INTEGER}\ngot: {value:g}\nexpected: "
               f"{expected:g} (the parallel-axis theorem over the central 4 x 2 block of 0.8 m and the two 1 x 1 "
               "blocks of 0.1 m at (±1.5, ±1.5))")
    for name, mistaken, hint in (
        ("parallel_axis_sign", _figure_21(blocks, steiner_sign=-1.0), SIGN_HINT),
        ("no_parallel_axis", _figure_21(blocks, steiner_sign=0.0), "The small blocks are off the centre of gravity: "
         "add m_k |r_k|² (parallel-axis theorem) to their own moments."),
        ("one_third", _figure_21(blocks, own_factor=4.0), "A block's own moment is m/12 (w² + d²), not m/3."),
    ):
        if abs(value - mistaken) <= INTEGER.atol:
            fail(message, f"{hint} (That gives {mistaken:g}.)", name)
    raise typed_failure(ctx, message, "", "", value, expected, INTEGER, "I3 / (m/120)")


# ------------------------------------------------------------------------------------ side effects

#: a rotated, non-diagonal inertia and a second body for the side-effect check
_SIDE_I = np.array([[2.0, -0.3, 0.1], [-0.3, 1.5, 0.2], [0.1, 0.2, 1.2]])


@check(1, title="parallel_axis and composite_inertia leave their arguments unchanged, return a new array on every "
       "call and keep no state", stage=STAGE_RANDOM + 1, group="parallel_axis")
def check_side_effects(ctx):
    assert_no_side_effects(ctx, "inertia", "parallel_axis", [_SIDE_I, 2.0, np.array([0.3, -0.5, 1.0])],
                           [0.5 * _SIDE_I, 1.0, np.array([-1.0, 0.2, 0.4])], ("I_G", "m", "r"))
    assert_no_side_effects(ctx, "inertia", "composite_inertia",
                           [np.array([1.0, 2.0]), np.array([[0.3, -0.5, 1.0], [-1.0, 0.2, 0.4]]),
                            np.array([_SIDE_I, 0.5 * _SIDE_I])],
                           [np.array([3.0]), np.array([[1.0, 1.0, 0.0]]), np.array([_SIDE_I])],
                           ("masses", "centres", "inertias"))
