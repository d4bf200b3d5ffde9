"""Checks of problem 21: the constraint functions f_a, f_b of the planar arms and their Jacobians.

The mistaken arms (``walk``) and the diagnoses of Jacobians (``swapped_columns``, ``sign_flips``) are shared with
problems 22 and 26.
"""

from itertools import combinations

import numpy as np
from hypothesis import strategies as st

from grader.checking import (
    EXACT,
    SHEET,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    CheckFailure,
    Mistake,
    Tol,
    as_array,
    assert_close,
    check,
    fail,
)

TITLE = "2D Kinematics"

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


def direction(gamma, mistake=None):
    """Unit vector of a segment of orientation ``gamma``, as the sheet defines it or as a mistake reads it."""
    if mistake in ("horizontal", "horizontal_all"):
        return np.array([np.cos(gamma), np.sin(gamma)])
    return np.array([-np.sin(gamma), np.cos(gamma)])


def walk(q, d, mistake=None):
    """The arm of problems 21 and 22 with ``mistake`` applied: ``(points, end)``, ``points[k-1] = (x_k, y_k,
    g_{k-1}, g_k)`` for ``k = 1..n`` and ``end = (xe, ye, g_n)``.  Complex ``q`` is kept (complex-step derivatives).

    Mistakes: ``degrees`` (radians read as degrees), ``horizontal`` (segments along (cos g, sin g) after the
    vertical first one), ``horizontal_all`` (every segment along (cos g, sin g)), ``horizontal_offset`` (right
    positions, orientations from the horizontal: +90 deg), ``joint_order`` (each segment after its own rotation),
    ``no_final_link`` (d left out).
    """
    pairs = np.asarray(q).reshape(-1, 2)
    if mistake == "degrees":
        pairs = pairs * np.array([1.0, np.pi / 180.0])
    offset = np.pi / 2 if mistake == "horizontal_offset" else 0.0
    point, gamma, points = np.zeros(2), 0.0, []
    for k, (length, turn) in enumerate(pairs):
        before = gamma
        if mistake == "joint_order":
            gamma = gamma + turn
        along = np.array([0.0, 1.0]) if k == 0 and mistake == "horizontal" else direction(gamma, mistake)
        point = point + length * along
        if mistake != "joint_order":
            gamma = gamma + turn
        points.append(np.array([*point, before + offset, gamma + offset]))
    link = 0.0 if mistake == "no_final_link" else d
    return points, np.array([*(point + link * direction(gamma, mistake)), gamma + offset])


def as_degrees(q):
    """``q`` with its angles (q2, q4, ...) read as degrees."""
    return np.asarray(q, dtype=float) * np.tile([1.0, np.pi / 180.0], len(q) // 2)


def layout(q, d, mistake=None):
    """``x_a`` / ``x_b`` of problem 21: each point with the orientation of the segment arriving there, then the end
    effector."""
    points, end = walk(q, d, mistake)
    return np.concatenate([*(p[:3] for p in points), end])


def complex_step(f, q):
    """Jacobian of ``f`` at ``q`` by complex steps (exact to rounding)."""
    q = np.asarray(q, dtype=float)
    return np.column_stack([np.imag(f(q + 1e-30j * e)) / 1e-30 for e in np.eye(q.size)])


def swapped_columns(J, names=None):
    """``J`` with two columns swapped, for every pair of columns; ``names`` describes the joint variables (by
    default those of the planar arm: prismatic and rotational joints alternating)."""
    J = np.asarray(J, dtype=float)
    names = names or [f"q{j + 1} ({'an angle' if j % 2 else 'a length'})" for j in range(J.shape[1])]
    found = []
    for i, j in combinations(range(J.shape[1]), 2):
        swapped = J.copy()
        swapped[:, [i, j]] = J[:, [j, i]]
        found.append(Mistake("swapped_columns", swapped, (
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


def _chain_mistakes(q, d):
    """Modelled mistakes of the constraint function (a sign flip is found from the student's value)."""
    return [
        Mistake("degrees", layout(q, d, "degrees"), DEGREES_HINT),
        Mistake("horizontal", layout(q, d, "horizontal_offset"), HORIZONTAL_HINT
                + " Your positions are right but every orientation is 90 deg too large."),
        Mistake("horizontal", layout(q, d, "horizontal"), HORIZONTAL_HINT),
    ]


def _jacobian_reference_mistakes(case, q, d, expected):
    from reference import planar

    analytic = planar.jacobian_a if case == "a" else planar.jacobian_b
    return [
        *swapped_columns(expected),
        Mistake("degrees", analytic(as_degrees(q), d), DEGREES_HINT),
        Mistake("degrees", complex_step(lambda p: layout(p, d, "degrees"), q), DEGREES_HINT),
        Mistake("horizontal", complex_step(lambda p: layout(p, d, "horizontal"), q), HORIZONTAL_HINT),
    ]


def _describe(function):
    return lambda args: f"{function}(q={np.asarray(args[1]).tolist()!r}, d={args[2]!r})"


def _strategy(case):
    return st.tuples(st.just(case), CASES[case].map(np.array), LINKS)


# ------------------------------------------------------------------------------------ the constraint functions


def _compare_chain(ctx, case):
    def compare(got, expected, args):
        mistakes = _chain_mistakes(args[1], args[2]) + sign_flips(got, expected, EXACT, SIGN_HINT)
        assert_close(got, expected, f"chain_{case}(q, d)", EXACT, mistakes)

    ctx.compare_random("problem_21.chain", _strategy(case), name=f"chain_{case}(q, d)", tol=EXACT, compare=compare,
                       describe=_describe(f"chain_{case}"))


@check(2, title="chain_a(q, d) = (x1, y1, gamma1, xe, ye, gammae) on random q and d", stage=STAGE_RANDOM,
       group="chain_a")
def check_chain_a_values(ctx):
    _compare_chain(ctx, "a")


@check(2, title="chain_b(q, d) = (x1, y1, gamma1, x2, y2, gamma2, xe, ye, gammae) on random q and d",
       stage=STAGE_RANDOM, group="chain_b")
def check_chain_b_values(ctx):
    _compare_chain(ctx, "b")


# ------------------------------------------------------------------------------------ the Jacobians


def assert_derivative(J, central, name, function, mistakes, hint, names=None):
    """``J`` equals the central differences ``central`` of the student's ``function``; without a recognised mistake
    the failure says ``hint``."""
    mistakes = [*mistakes, *swapped_columns(central, names),
                *sign_flips(J, central, CENTRAL_DIFFERENCES, JACOBIAN_SIGN_HINT)]
    try:
        return assert_close(J, central, name, CENTRAL_DIFFERENCES, mistakes,
                            context=f"(the central differences of your own {function})")
    except CheckFailure as exc:
        if exc.diagnosis:
            raise
        fail(exc.message, hint)


def _assert_derivative(ctx, case):
    from reference import planar

    joints, rows = SIZES[case]
    analytic = planar.jacobian_a if case == "a" else planar.jacobian_b
    for q in CONFIGURATIONS[case]:
        call = f"(q={list(q)}, d={FD_LINK})"
        got = ctx.student("problem_21.jacobian_and_steps", case, q, FD_LINK, H)
        J = as_array(got["J"], f"jacobian_{case}{call}", (rows, joints))
        plus, minus = ([as_array(x, f"chain_{case}", (rows,)) for x in got[side]] for side in ("plus", "minus"))
        central = np.column_stack([(p - m) / (2 * H) for p, m in zip(plus, minus)])
        mistakes = [
            Mistake("chain_wrong", analytic(q, FD_LINK), (
                f"Your jacobian_{case} is right, but it is not the derivative of your chain_{case}: chain_{case} is "
                f"wrong (see its check).")),
            Mistake("degrees", analytic(as_degrees(q), FD_LINK), DEGREES_HINT),
        ]
        assert_derivative(J, central, f"jacobian_{case}{call}", f"chain_{case}", mistakes, (
            f"Column j of J_{case} holds the derivatives of all coordinates of x_{case} with respect to q_j: "
            f"differentiate each entry of your chain_{case} again."))


def _compare_jacobian(ctx, case):
    def compare(got, expected, args):
        mistakes = _jacobian_reference_mistakes(case, args[1], args[2], expected)
        assert_close(got, expected, f"jacobian_{case}(q, d)", EXACT,
                     mistakes + sign_flips(got, expected, EXACT, JACOBIAN_SIGN_HINT))

    ctx.compare_random("problem_21.jacobian", _strategy(case), name=f"jacobian_{case}(q, d)", tol=EXACT,
                       compare=compare, describe=_describe(f"jacobian_{case}"))


@check(1, title="jacobian_a(q, d) is the derivative of your own chain_a (central differences)",
       stage=STAGE_STRUCTURE, group="jacobian_a")
def check_jacobian_a_derivative(ctx):
    _assert_derivative(ctx, "a")


@check(1, title="jacobian_a(q, d) = d f_a / d q_a on random q and d", stage=STAGE_RANDOM, group="jacobian_a")
def check_jacobian_a_values(ctx):
    _compare_jacobian(ctx, "a")


@check(1, title="jacobian_b(q, d) is the derivative of your own chain_b (central differences)",
       stage=STAGE_STRUCTURE, group="jacobian_b")
def check_jacobian_b_derivative(ctx):
    _assert_derivative(ctx, "b")


@check(1, title="jacobian_b(q, d) = d f_b / d q_b on random q and d", stage=STAGE_RANDOM, group="jacobian_b")
def check_jacobian_b_values(ctx):
    _compare_jacobian(ctx, "b")


# ------------------------------------------------------------------------------------ the sheet's numbers


@check(1, title="case (2), q_b: the end effector is at (-0.1799, 0.3616, 1.0472) as on the sheet",
       stage=STAGE_VALUES, group="sheet")
def check_sheet_target(ctx):
    from reference.problem_21 import CASES as SHEET_CASES
    from reference.problem_21 import D, TARGET_END_EFFECTOR_CASE_2

    q_b = SHEET_CASES[2][1]
    x_b = as_array(ctx.student("problem_21.chain", "b", q_b, D), "chain_b(q_b, 0.15)", (9,))
    mistakes = [Mistake(m.name, m.value[6:], m.hint) for m in _chain_mistakes(q_b, D)]
    mistakes += sign_flips(x_b[6:], TARGET_END_EFFECTOR_CASE_2, SHEET, SIGN_HINT)
    assert_close(x_b[6:], TARGET_END_EFFECTOR_CASE_2, "(xe, ye, gammae) of case (2) with q_b", SHEET, mistakes,
                 context="(the sheet's value)")
