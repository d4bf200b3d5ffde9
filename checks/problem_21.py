"""Checks of problem 21: the constraint functions f_a, f_b of the planar arms and their Jacobians.

The known mistakes of the arm (probe ``problem_21.mistakes``) and the diagnoses of Jacobians (``swapped_columns``,
``sign_flips``) are shared with problems 22 and 26.
"""


import numpy as np

from grader.checking import (
    EXACT,
    SHEET,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    CheckFailure,
    Mistake,
    as_array,
    assert_close,
    check,
    fail,
)
from probes import problem_21 as p21

from ._figures import add_planar_arm
from ._real import rank_flaw, require_real
from ._planar import (
    CENTRAL_DIFFERENCES,
    CONFIGURATIONS,
    DEGREES_HINT,
    FD_LINK,
    H,
    JACOBIAN_SIGN_HINT,
    SIGN_HINT,
    SIZES,
    _chain_mistakes,
    _compare_chain,
    _describe,
    _jacobian_reference_mistakes,
    _strategy,
    as_degrees,
    sign_flips,
    swapped_columns,
)
from ._shapes import as_dict, as_list

TITLE = "2D Kinematics"


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
        fail(exc.message, hint, evidence=exc.evidence)


def _assert_derivative(ctx, case):
    joints, rows = SIZES[case]
    for q in CONFIGURATIONS[case]:
        call = f"(q={list(q)}, d={FD_LINK})"
        ours = ctx.reference(p21.jacobian, case, q, FD_LINK)
        mistakes = [
            Mistake("chain_wrong", ours, (
                f"Your jacobian_{case} is right, but it is not the derivative of your chain_{case}: chain_{case} is "
                f"wrong (see its check).")),
            Mistake("degrees", ctx.reference(p21.jacobian, case, as_degrees(q), FD_LINK), DEGREES_HINT),
        ]
        got = as_dict(ctx.student(p21.jacobian_and_steps, case, q, FD_LINK, H), f"the reply for {call}",
                      ("J", "plus", "minus"))
        J = as_array(got["J"], f"jacobian_{case}{call}", (rows, joints))
        plus, minus = ([as_array(x, f"chain_{case}", (rows,))
                        for x in as_list(got[side], f"chain_{case} at q {sign} h e_j, one per joint", joints)]
                       for side, sign in (("plus", "+"), ("minus", "-")))
        central = np.column_stack([(p - m) / (2 * H) for p, m in zip(plus, minus)])
        require_real(f"jacobian_{case}{call}", f"chain_{case}", [
            (f"the central-difference Jacobian of your chain_{case} at q = {list(q)}", rank_flaw(central, ours))])
        assert_derivative(J, central, f"jacobian_{case}{call}", f"chain_{case}", mistakes, (
            f"Column j of J_{case} holds the derivatives of all coordinates of x_{case} with respect to q_j: "
            f"differentiate each entry of your chain_{case} again."))


def _compare_jacobian(ctx, case):
    def compare(got, expected, args):
        mistakes = _jacobian_reference_mistakes(ctx, case, args[1], args[2], expected)
        assert_close(got, expected, f"jacobian_{case}(q, d)", EXACT,
                     mistakes + sign_flips(got, expected, EXACT, JACOBIAN_SIGN_HINT))

    ctx.compare_random(p21.jacobian, _strategy(case), name=f"jacobian_{case}(q, d)", tol=EXACT,
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


#: added to the sheet's q_b: a configuration the sheet does not print, where the printed pose typed in earns nothing
UNPRINTED_SHIFT = np.array([0.15, -0.3, 0.1, 0.4])
TYPED_HINT = ("These are the sheet's printed numbers for q_b, whatever q is given: compute the pose from q and d "
              "(the checks also ask configurations the sheet does not print).")


@check(1, title="case (2), q_b: the end effector is at (-0.1799, 0.3616, 1.0472) as on the sheet (and where the "
       "reference's is at a configuration the sheet does not print)", stage=STAGE_VALUES, group="sheet")
def check_sheet_target(ctx):
    case = ctx.reference(p21.sheet_case)
    q_b, d, target = case["q_b"], case["d"], np.asarray(case["target"], dtype=float)
    mistakes = [Mistake(m.name, m.value[6:], m.hint) for m in _chain_mistakes(ctx, q_b, d)]
    got = ctx.student(p21.chain, "b", q_b, d)
    add_planar_arm(ctx, "Problem 21: the arm of case (2) with q_b", got, ctx.reference(p21.chain, "b", q_b, d))
    x_b = as_array(got, f"chain_b(q_b, {d:g})", (9,))
    mistakes += sign_flips(x_b[6:], target, SHEET, SIGN_HINT)
    assert_close(x_b[6:], target, "(xe, ye, gammae) of case (2) with q_b", SHEET, mistakes,
                 context="(the sheet's value)")
    other = [float(x) for x in np.asarray(q_b, dtype=float) + UNPRINTED_SHIFT]
    expected = np.asarray(ctx.reference(p21.chain, "b", other, d), dtype=float)[6:]
    x_other = as_array(ctx.student(p21.chain, "b", other, d), f"chain_b({np.round(other, 4).tolist()}, {d:g})",
                       (9,))
    assert_close(x_other[6:], expected, f"(xe, ye, gammae) at q = {np.round(other, 4).tolist()}", EXACT,
                 [Mistake("typed_numbers", target, TYPED_HINT)],
                 context="(a configuration the sheet does not print, against the reference)")
    q = ctx.draw(lambda rng: [float(x) for x in rng.uniform(-1.5, 1.5, len(q_b))])  # no key holds it: drawn anew
    expected = ctx.reference(p21.chain, "b", q, d)
    assert_close(ctx.student(p21.chain, "b", q, d), expected, f"chain_b(q, {d:g})", EXACT,
                 context=f"(the arm of case (2) at other angles, q = {np.round(q, 4).tolist()})")
