"""Checks of problem 26: position of the chairoplane's seat and its constraint Jacobian."""

import numpy as np

from grader import strategies as st
from grader.checking import EXACT, STAGE_RANDOM, STAGE_STRUCTURE, Mistake, as_array, assert_close, check, close, fail
from probes import problem_26 as p26

from ._figures import add_chairoplane, seat_between
from ._real import rank_flaw, require_real
from ._planar import (
    ANGLES,
    CENTRAL_DIFFERENCES,
    DEGREES_HINT,
    FINITE,
    H,
    JACOBIAN_SIGN_HINT,
    sign_flips,
    swapped_columns,
)
from ._shapes import as_dict, as_list
from .problem_21 import assert_derivative

TITLE = "Chairoplane: position and constraint Jacobian"

LENGTHS = st.floats(0.1, 3.0, **FINITE)
#: angles shrink towards 0.5 rad, where no sine or cosine vanishes and none equals another
GENERIC_ANGLES = ANGLES.map(lambda angle: angle + 0.5)
ARGUMENTS = st.tuples(GENERIC_ANGLES, GENERIC_ANGLES, LENGTHS, LENGTHS, LENGTHS)
COLUMNS = ["beta", "phi"]
#: configurations (beta, phi, l1, l2, l3) at which the Jacobian is differentiated
CONFIGURATIONS = [(0.7, 0.4, 2.0, 1.5, 1.2), (-2.3, -1.1, 3.0, 0.8, 1.7)]

MODELS = {
    "beta_sin_cos": "sin and cos of beta are swapped: at beta = 0 the arm points along the 3-axis, so "
                    "x1 = r sin(beta) and x3 = r cos(beta), with r = l2 + l3 sin(phi).",
    "phi_sin_cos": "sin and cos of phi are swapped: phi swings the chain out of the vertical, so it reaches out "
                   "by l3 sin(phi) and hangs down by l3 cos(phi).",
    "sign_flip": "The chain hangs DOWN from the arm at height l1: x2 = l1 - l3 cos(phi).",
    "radius": "The seat circles the axis at the radius l2 + l3 sin(phi): the arm l2 plus the chain's reach.",
    "degrees": DEGREES_HINT,
}
POSITION_SIGN_HINT = "Check the directions: x1 = r sin(beta), x2 = l1 - l3 cos(phi), x3 = r cos(beta)."


def _position_mistakes(ctx, args):
    found = ctx.reference(p26.mistakes, *args)["position"]
    return [Mistake(name, found[name], hint) for name, hint in MODELS.items()]


def _jacobian_mistakes(ctx, args, expected):
    beta, phi, *lengths = args
    found = ctx.reference(p26.mistakes, *args)["jacobian"]
    return [
        *[Mistake(name, found[name], hint) for name, hint in MODELS.items()],
        Mistake("degrees", ctx.reference(p26.jacobian, np.deg2rad(beta), np.deg2rad(phi), *lengths),
                DEGREES_HINT),
        *swapped_columns(expected, COLUMNS),
    ]


def _describe(function):
    return lambda args: "{}(beta={!r}, phi={!r}, l1={!r}, l2={!r}, l3={!r})".format(function, *args)


def _assert_not_transposed(J, expected, name, tol):
    if np.shape(J) == np.shape(expected)[::-1] and close(J, np.transpose(expected), tol):
        fail(f"{name} must be 3 x 2 (rows x1, x2, x3; columns beta, phi), got its transpose (2 x 3).",
             "Row i of J_f holds the derivatives of x_i, column j the derivatives with respect to q_j.",
             "transpose")


@check(2, title="position(beta, phi, l1, l2, l3) = x = f(q) on random angles and lengths", stage=STAGE_RANDOM,
       group="position")
def check_position_values(ctx):
    def compare(got, expected, args):
        mistakes = _position_mistakes(ctx, args) + sign_flips(got, expected, EXACT, POSITION_SIGN_HINT)
        assert_close(got, expected, "position(beta, phi, l1, l2, l3)", EXACT, mistakes)

    ctx.compare_random(p26.position, ARGUMENTS, name="position", tol=EXACT, compare=compare,
                       describe=_describe("position"))


@check(1, title="jacobian(beta, phi, l1, l2, l3) is the derivative of your own position (central differences)",
       stage=STAGE_STRUCTURE, group="jacobian")
def check_jacobian_derivative(ctx):
    for args in CONFIGURATIONS:
        call = _describe("jacobian")(args)
        ours = ctx.reference(p26.jacobian, *args)
        known = [
            Mistake("position_wrong", ours, "Your jacobian is right, but it is "
                    "not the derivative of your position: position is wrong (see its check)."),
            Mistake("degrees", ctx.reference(p26.jacobian, *np.deg2rad(args[:2]), *args[2:]), DEGREES_HINT),
        ]
        got = as_dict(ctx.student(p26.jacobian_and_steps, *args, H), f"the reply for {call}",
                      ("J", "plus", "minus"))
        if args == CONFIGURATIONS[0]:
            add_chairoplane(ctx, f"Problem 26: the chairoplane at beta = {args[0]:g}, phi = {args[1]:g}",
                            seat_between(got), ctx.reference(p26.position, *args), args[0], args[2], args[3])
        plus, minus = ([as_array(x, "position", (3,)) for x in as_list(got[side], f"position at q {sign} h e_j", 2)]
                       for side, sign in (("plus", "+"), ("minus", "-")))
        central = np.column_stack([(p - m) / (2 * H) for p, m in zip(plus, minus)])
        require_real(call, "position", [(f"the central-difference Jacobian of your position at (beta, phi) = "
                                          f"{args[:2]}", rank_flaw(central, ours))])
        _assert_not_transposed(got["J"], central, call, CENTRAL_DIFFERENCES)
        J = as_array(got["J"], call, (3, 2))
        assert_derivative(J, central, call, "position", known, "Column 1 of J_f is d x / d beta, column 2 is d x / d "
                          "phi: differentiate each entry of your position again.", COLUMNS)


@check(2, title="jacobian(beta, phi, l1, l2, l3) = d f / d q on random angles and lengths", stage=STAGE_RANDOM,
       group="jacobian")
def check_jacobian_values(ctx):
    def compare(got, expected, args):
        known = _jacobian_mistakes(ctx, args, expected)
        _assert_not_transposed(got, expected, "jacobian(beta, phi, l1, l2, l3)", EXACT)
        mistakes = known + sign_flips(got, expected, EXACT, JACOBIAN_SIGN_HINT)
        assert_close(got, expected, "jacobian(beta, phi, l1, l2, l3)", EXACT, mistakes)

    ctx.compare_random(p26.jacobian, ARGUMENTS, name="jacobian", tol=EXACT, compare=compare,
                       describe=_describe("jacobian"))
