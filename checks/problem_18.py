"""Checks of problem 18: the rotation rate and acceleration for which a body point Q does not accelerate.

omega is determined up to its sign (the direction of rotation does not matter): the check accepts both and tests
the defining property, I_a_Q = 0.
"""

import numpy as np

from checks._real import assert_real
from checks._rigid import FINITE
from grader import strategies as st
from grader.checking import EXACT, STAGE_RANDOM, STAGE_STRUCTURE, Mistake, assert_close, as_array, check, fail
from probes import problem_18 as p18

TITLE = "Acceleration of a Point on a Rigid Body"

COMPONENTS = st.floats(-3.0, 3.0, **FINITE)


@st.composite
def solvable(draw):
    """``(a_x, a_y, r_x, r_y)`` with ``a . r >= 0`` and Q away from B."""
    r = np.array([draw(COMPONENTS), draw(COMPONENTS)])
    if r @ r < 0.01:
        r = r + 0.2
    a = np.array([draw(COMPONENTS), draw(COMPONENTS)])
    if a @ r < 0:
        a = -a
    return (*a.tolist(), *r.tolist())


def acceleration_of_Q(omega, omega_dot, a_x, a_y, r_x, r_y):
    """``B_a_Q = B_a_B + (skew(omegaDot) + skew(omega)^2) B_r_BQ`` in the plane (its norm equals |I_a_Q|)."""
    r, a = np.array([r_x, r_y]), np.array([a_x, a_y])
    return a + omega_dot * np.array([-r[1], r[0]]) - omega**2 * r


def _describe(args):
    return "(a_x, a_y, r_x, r_y) = ({:.6g}, {:.6g}, {:.6g}, {:.6g})".format(*args)


@check(3, title="non_accelerating_point: with your (omega, omega_dot) the point Q does not accelerate (either sign "
       "of omega; random a and r)", stage=STAGE_RANDOM, group="values")
def check_zero_acceleration(ctx):
    def compare(got, expected, args):
        if isinstance(got, str):
            fail(f"non_accelerating_point{args} raised {got}, but a solution exists (a . r >= 0).")
        omega, omega_dot = as_array(got, "(omega, omega_dot)", (2,))
        residual = acceleration_of_Q(omega, omega_dot, *args)
        if np.all(np.abs(residual) <= 1e-8 * (1 + np.abs(args).max())):
            return
        w, wd = expected
        sign = -1.0 if omega < 0 else 1.0
        assert_close([omega, omega_dot], [sign * w, wd], "(omega, omega_dot)", EXACT, [
            Mistake("omega_dot_sign", [sign * w, -wd], "omega_dot has the wrong sign: the tangential term "
                    "omega_dot x r = omega_dot (-r_y, r_x) must cancel a, so omega_dot = (a_x r_y - a_y r_x) / |r|²."),
            Mistake("omega_squared", [w**2, wd], "You returned omega² = (a . r) / |r|²: omega is its square root "
                    "(either sign)."),
            Mistake("swapped", [wd, sign * w], "omega and omega_dot are swapped: return (omega, omega_dot)."),
        ], note=f"Q's acceleration with your values is {residual.round(6).tolist()} (body x-y components), not 0.")

    ctx.student(p18.non_accelerating, 1.0, 2.0, 0.5, 0.5)
    ctx.compare_random(p18.non_accelerating, solvable(), name="(omega, omega_dot)", tol=EXACT,
                       compare=compare, examples=15, describe=_describe)


@check(1, title="non_accelerating_point raises ValueError when no omega exists (a . r < 0) or Q coincides with B",
       stage=STAGE_STRUCTURE, group="no_solution")
def check_no_solution(ctx):
    solvable = (1.0, 2.0, 0.5, 0.5)
    expected = ctx.reference(p18.non_accelerating, *solvable)
    got = ctx.student(p18.non_accelerating, *solvable)
    if isinstance(got, str):
        fail(f"non_accelerating_point{solvable} raised {got}, but a solution exists (a . r = 1.5 >= 0): raising "
             "ValueError counts only where there is no solution.",
             "Raise ValueError only when a . r < 0 or r = 0; otherwise return (omega, omega_dot).", "always_raises")
    assert_real(got, f"non_accelerating_point{solvable}", (2,), expected)  # raising counts beside a computed answer
    for args, why in (((1.0, 0.0, -1.0, 0.5), "a . r < 0: omega² would be negative"),
                      ((1.0, 2.0, 0.0, 0.0), "Q coincides with B (r = 0)")):
        got = ctx.student(p18.non_accelerating, *args)
        if not isinstance(got, str):
            fail(f"non_accelerating_point{args} returned {got}; expected a ValueError ({why}).",
                 "The docstring asks for ValueError when there is no real solution: test the sign of a . r and "
                 "r = 0 before taking the square root or dividing.", "no_error")
