"""Shared by the checks of problems 21, 22, 26 and 27: strategies for planar arms, the known mistakes of the arm
(asked of the reference through the probe ``problem_21.mistakes``), and diagnoses of Jacobians (swapped columns,
sign flips)."""

from itertools import combinations

import numpy as np

from grader import strategies as st
from grader.checking import EXACT, Mistake, Tol, assert_close
from probes import problem_21 as p21

__all__ = [
    "FINITE", "LENGTHS", "ANGLES", "LINKS", "CASES", "SIZES", "H", "CENTRAL_DIFFERENCES", "CONFIGURATIONS", "FD_LINK",
    "DEGREES_HINT", "HORIZONTAL_HINT", "SIGN_HINT", "JACOBIAN_SIGN_HINT", "as_degrees", "swapped_columns",
    "sign_flips", "_chain_mistakes", "_jacobian_reference_mistakes", "_describe", "_strategy", "_compare_chain",
]

FINITE = dict(allow_nan=False, allow_infinity=False)
LENGTHS = st.floats(0.05, 1.0, **FINITE)
ANGLES = st.floats(-np.pi, np.pi, **FINITE)
LINKS = st.floats(0.05, 1.0, **FINITE)
CASES = {"a": st.tuples(LENGTHS, ANGLES), "b": st.tuples(LENGTHS, ANGLES, LENGTHS, ANGLES)}
#: joints and rows of x per case: (number of joints, number of coordinates)
SIZES = {"a": (2, 6), "b": (4, 9)}

#: step and tolerance of the central differences of the student's own chain
H = 1e-6
CENTRAL_DIFFERENCES = Tol("central differences, h = 1e-6", 1e-6, 1e-6)
#: configurations at which the Jacobians are differentiated (no special angles)
CONFIGURATIONS = {
    "a": [(0.3, 0.7), (0.15, -2.1)],
    "b": [(0.3, 0.7, 0.2, -1.1), (0.1, -2.5, 0.45, 0.4)],
}
FD_LINK = 0.4

DEGREES_HINT = ("The joint angles are in radians: your function treats them as degrees (np.deg2rad of an angle "
                "that already is in radians).")
HORIZONTAL_HINT = (
    "The orientation gamma is measured from the VERTICAL, counter-clockwise positive: a segment of orientation "
    "gamma and length s spans s * (-sin gamma, cos gamma), and the first (vertical) segment has gamma = 0. "
    "You measured it from the horizontal."
)
SIGN_HINT = ("Angles are positive counter-clockwise, so a segment tilted by gamma > 0 leans to the LEFT: it spans "
             "s * (-sin gamma, cos gamma).")
JACOBIAN_SIGN_HINT = ("Remember d/dq cos(q) = -sin(q), d/dq sin(q) = +cos(q), and that a segment at gamma spans "
                      "s * (-sin gamma, cos gamma).")


# ------------------------------------------------------------------------------------ mistaken arms


def as_degrees(q):
    """``q`` with its angles (q2, q4, ...) read as degrees."""
    return np.asarray(q, dtype=float) * np.tile([1.0, np.pi / 180.0], len(q) // 2)


def swapped_columns(J, names=None):
    """``J`` with two columns swapped, for every pair of columns; ``names`` describes the joint variables (by
    default those of the planar arm: prismatic and rotational joints alternating)."""
    J = np.asarray(J, dtype=float)
    names = names or [f"q{j + 1} ({'an angle' if j % 2 else 'a length'})" for j in range(J.shape[1])]
    found = []
    for i, j in combinations(range(J.shape[1]), 2):
        swapped = J.copy()
        swapped[:, [i, j]] = J[:, [j, i]]
        found.append(Mistake("swapped", swapped, (
            f"Columns {i + 1} and {j + 1} are swapped: column j of J holds the derivatives with respect to the j-th "
            f"joint variable (column {i + 1}: {names[i]}, column {j + 1}: {names[j]}).")))
    return found


def sign_flips(got, expected, tol, hint):
    """The mistake "some entries of ``expected`` with the wrong sign" when that is what ``got`` is, naming them."""
    try:
        got = np.asarray(got, dtype=float)
        expected = np.asarray(expected, dtype=float)
    except (TypeError, ValueError):
        return []
    if got.shape != expected.shape:
        return []
    bound = tol.atol + tol.rtol * np.abs(expected)
    flipped = (np.abs(got + expected) <= bound) & (np.abs(expected) > bound)
    if not flipped.any():
        return []
    entries = ", ".join("[" + ",".join(map(str, index)) + "]" for index in zip(*np.nonzero(flipped)))
    return [Mistake("sign_flip", np.where(flipped, -expected, expected),
                    f"The entries {entries} have the wrong sign. {hint}")]


def _chain_mistakes(ctx, q, d):
    """Modelled mistakes of the constraint function, asked of the reference (a sign flip is found from the
    student's value)."""
    found = ctx.reference(p21.mistakes, q, d)["chain"]
    return [
        Mistake("degrees", found["degrees"], DEGREES_HINT),
        Mistake("horizontal", found["horizontal_offset"], HORIZONTAL_HINT
                + " Your positions are right but every orientation is 90 deg too large."),
        Mistake("horizontal", found["horizontal"], HORIZONTAL_HINT),
    ]


def _jacobian_reference_mistakes(ctx, case, q, d, expected):
    found = ctx.reference(p21.mistakes, q, d)["jacobian"]
    return [
        *swapped_columns(expected),
        Mistake("degrees", ctx.reference(p21.jacobian, case, as_degrees(q), d), DEGREES_HINT),
        Mistake("degrees", found["degrees"], DEGREES_HINT),
        Mistake("horizontal", found["horizontal"], HORIZONTAL_HINT),
    ]


def _describe(function):
    return lambda args: f"{function}(q={np.asarray(args[1]).tolist()!r}, d={args[2]!r})"


def _strategy(case):
    return st.tuples(st.just(case), CASES[case].map(np.array), LINKS)


# ------------------------------------------------------------------------------------ the constraint functions


def _compare_chain(ctx, case):
    def compare(got, expected, args):
        mistakes = _chain_mistakes(ctx, args[1], args[2]) + sign_flips(got, expected, EXACT, SIGN_HINT)
        assert_close(got, expected, f"chain_{case}(q, d)", EXACT, mistakes)

    ctx.compare_random(p21.chain, _strategy(case), name=f"chain_{case}(q, d)", tol=EXACT, compare=compare,
                       describe=_describe(f"chain_{case}"))
