"""Checks of problem 47: the bowling pin's plastic impact on the lane (``constraint``, ``constraint_jacobian``,
``plastic_impact``, ``impulse``, ``angle_of_max_impulse``, ``max_impulse``) and the free-text arguments (b), (c).

Physics decides where it can: the Jacobian is the gradient of the student's own constraint (finite differences);
after the plastic impact ``q+ = q-``, the contact is stopped (``J qd+ = 0`` with the student's own ``J``) and the
lane pushes (``Lam > 0``); a failure of the angle of the maximum shows the student's own impulse around it.  The
values (the sheet's conventions) against the reference at random pins and states, with known mistakes.
"""

import numpy as np

from checks._effects import assert_no_side_effects
from grader import strategies as st
from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    Mistake,
    Tol,
    as_array,
    assert_close,
    check,
    close,
    fail,
    format_array,
)
from probes import problem_47 as p47

TITLE = "Bowling Pin"
MANUAL = {
    "b": ("47(b): argue physically at which angle the impulse is largest (no spin before the impact).", 1),
    "c": ("47(c): argue physically why the answer changes when the pin also spins.", 1),
}

H = 1e-6
GRADIENT = Tol("finite differences, h = 1e-6", 1e-6, 1e-6)
IMPACT = Tol("after a plastic impact", 1e-8, 1e-8)
#: the impulse at phi_hat -+ DELTA is not larger than at phi_hat
DELTA = 0.05
_SEEDS = st.integers(0, 2**32 - 1)


def _pin(rng):
    """``(m, theta, x_cog, y_cog)``."""
    return (float(rng.uniform(0.5, 3.0)), float(rng.uniform(0.01, 0.2)), float(rng.uniform(0.03, 0.3)),
            float(rng.uniform(0.1, 0.6)))


def _q(rng):
    return np.concatenate([rng.uniform(-1.0, 1.0, 2), rng.uniform(-1.2, 1.2, 1)])


@st.composite
def _contacts(draw):
    """``(q, x_cog, y_cog, h)``."""
    rng = np.random.default_rng(draw(_SEEDS))
    _, _, x_cog, y_cog = _pin(rng)
    return _q(rng), x_cog, y_cog, H


def _describe_contact(args):
    return f"q = {np.round(args[0], 4).tolist()}, x_cog = {args[1]:.4g}, y_cog = {args[2]:.4g}"


@check(1, title="(a) constraint(q, x_cog, y_cog): the height of the lower left corner above the lane at random "
       "states", stage=STAGE_STRUCTURE, group="contact")
def check_constraint(ctx):
    def compare(got, expected, args):
        q, x_cog, y_cog, _ = args
        phi = q[2]
        c = float(expected["c"])
        assert_close(got["c"], c, "c", EXACT, [
            Mistake("sin_cos_swapped", c + x_cog * (np.sin(phi) - np.cos(phi)) + y_cog * (np.cos(phi) - np.sin(phi)),
                    "phi is the rotation from vertical: the height of the corner below the centre of gravity is the "
                    "vertical component of (x_cog, y_cog) turned by phi."),
            Mistake("rotation_sense", c + 2 * x_cog * np.sin(phi), "A positive phi turns the pin counter-clockwise: "
                    "the corner, at -x_cog from the centre of gravity, rises by x_cog sin phi."),
        ], context=f"at {_describe_contact(args)}")

    ctx.compare_random(p47.contact, _contacts(), name="c", tol=EXACT, compare=compare, examples=8,
                       describe=_describe_contact)


@check(2, title="(a) constraint_jacobian(q, x_cog, y_cog) is the 1 x 3 gradient of your own constraint (finite "
       "differences) and the reference's at random states", stage=STAGE_STRUCTURE, group="contact")
def check_jacobian(ctx):
    def compare(got, expected, args):
        if np.shape(got["J"]) == (3, 1):
            fail(f"J has shape (3, 1): the transpose of the constraint Jacobian.\ngot:\n{format_array(got['J'])}",
                 "J is a row, 1 x 3: c_dot = J qd; the impulse acts through the column J.T.", "transpose")
        J = as_array(got["J"], "J", (1, 3))
        fd = np.array([[(plus - minus) / (2 * H) for plus, minus in got["c_coordinates"]]])
        assert_close(J, fd, "J", GRADIENT, [
            Mistake("jacobian_sign", -fd, "J = dc/dq of the corner's height c."),
        ], context=f"at {_describe_contact(args)} (expected: dc/dq of your own constraint)")
        assert_close(J, expected["J"], "J", EXACT, context=f"at {_describe_contact(args)}")

    ctx.compare_random(p47.contact, _contacts(), name="J", tol=GRADIENT, compare=compare, examples=8,
                       describe=_describe_contact)


@st.composite
def _impacts(draw):
    """``(q_minus, qd_minus, m, theta, x_cog, y_cog)`` with the corner closing fast (``yd- <= -1``, small spin)."""
    rng = np.random.default_rng(draw(_SEEDS))
    m, theta, x_cog, y_cog = _pin(rng)
    qd = np.array([rng.uniform(-2.0, 2.0), rng.uniform(-5.0, -1.0), rng.uniform(-0.5, 0.5)])
    return _q(rng), qd, m, theta, x_cog, y_cog


def _describe_impact(args):
    q, qd, m, theta, x_cog, y_cog = args
    return (f"q- = {np.round(q, 4).tolist()}, qd- = {np.round(qd, 4).tolist()}, m = {m:.4g}, theta = {theta:.4g}, "
            f"x_cog = {x_cog:.4g}, y_cog = {y_cog:.4g}")


#: two closing impacts ``(q_minus, qd_minus, m, theta, x_cog, y_cog)`` for the side-effect check of plastic_impact
SIDE_IMPACTS = (
    (np.array([0.3, 0.05, 0.4]), np.array([0.7, -2.1, 0.3]), 2.0, 0.15, 0.25, 0.4),
    (np.array([-0.2, 0.02, -0.3]), np.array([-0.4, -1.6, -0.2]), 1.5, 0.1, 0.3, 0.35),
)


@check(3, title="plastic_impact: q+ = q-, J qd+ = 0 with your own J and Lam > 0 on random closing impacts, and the "
       "values of the reference; q_minus and qd_minus are left as they were", stage=STAGE_VALUES, group="contact")
def check_plastic_impact(ctx):
    def compare(got, expected, args):
        q_minus, qd_minus = args[:2]
        q_plus, qd_plus = as_array(got["q_plus"], "q_plus", (3,)), as_array(got["qd_plus"], "qd_plus", (3,))
        Lam, J = as_array(got["Lam"], "Lam", (1,)), as_array(got["J"], "J", (1, 3))
        expected_plus, expected_Lam = np.asarray(expected["qd_plus"]), np.asarray(expected["Lam"])
        where = f"at {_describe_impact(args)}"
        assert_close(q_plus, q_minus, "q_plus", EXACT, context=f"{where} (an impact changes velocities only)")
        # an elastic impact is told only where every velocity after it is the elastic law's (2 qd+ - qd- of the
        # reference's), not merely the corner's reversed velocity
        assert_close(J @ qd_plus, np.zeros(1), "J qd_plus", IMPACT, [
            *([Mistake("elastic", -J @ qd_minus, "A fully plastic impact stops the corner: Lam = -(J M^-1 J.T)^-1 "
                       "J qd- gives J qd+ = 0; yours reverses its velocity (restitution 1, elastic).")]
              if close(qd_plus, 2 * expected_plus - np.asarray(qd_minus, dtype=float), IMPACT) else []),
            Mistake("unchanged", J @ qd_minus, "The impact changes the velocities: qd+ = qd- + M^-1 J.T Lam."),
        ], context=f"{where} (with your own J: after a plastic impact the corner does not move into the lane)")
        if Lam[0] <= 0:
            assert_close(Lam, expected_Lam, "Lam", EXACT, [
                Mistake("impulse_sign", -expected_Lam, "The lane pushes the corner up: Lam = -(J M^-1 J.T)^-1 J qd- "
                        "> 0 for a closing corner (J qd- < 0), acting through +J.T Lam."),
            ], context=f"{where} (the lane can only push: Lam > 0)")
        assert_close(qd_plus, expected_plus, "qd_plus", EXACT, context=where)
        assert_close(Lam, expected_Lam, "Lam", EXACT, context=where)

    ctx.compare_random(p47.impact, _impacts(), name="the impact", tol=EXACT, compare=compare, examples=10,
                       describe=_describe_impact)
    assert_no_side_effects(ctx, "problem_47", "plastic_impact", *SIDE_IMPACTS,
                           ("q_minus", "qd_minus", "m", "theta", "x_cog", "y_cog"))


@st.composite
def _impulse_cases(draw):
    """``(phi, yd_minus, m, theta, x_cog, y_cog)``."""
    rng = np.random.default_rng(draw(_SEEDS))
    return (float(rng.uniform(-1.2, 1.2)), float(rng.uniform(-5.0, -0.5)), *_pin(rng))


def _describe_impulse(args):
    names = ("phi", "yd-", "m", "theta", "x_cog", "y_cog")
    return ", ".join(f"{name} = {value:.4g}" for name, value in zip(names, args))


@check(2, title="(d) impulse(phi, yd-, ...) for qd- = (xd-, yd-, 0) equals the reference's at random pins and "
       "angles", stage=STAGE_RANDOM, group="contact")
def check_impulse(ctx):
    def mistakes(args, expected):
        _, yd, m = args[:3]
        return [
            Mistake("elastic", 2 * expected, "A plastic impact stops the corner (restitution 0); twice the "
                    "impulse reverses its velocity (elastic)."),
            Mistake("impulse_sign", -expected, "The lane pushes: Lam > 0 for a falling pin (yd- < 0)."),
            Mistake("no_rotation", -m * yd, "The impulse depends on the angle: away from the maximum it also starts "
                    "a rotation, and the corner gives way (J M^-1 J.T includes the lever arm over theta)."),
        ]

    ctx.compare_random(p47.impulse, _impulse_cases(), name="Lam", tol=EXACT, mistakes=mistakes,
                       examples=10, describe=_describe_impulse)


@st.composite
def _maximum_cases(draw):
    """``(yd_minus, m, theta, x_cog, y_cog, delta)``."""
    rng = np.random.default_rng(draw(_SEEDS))
    return (float(rng.uniform(-5.0, -0.5)), *_pin(rng), DELTA)


def _describe_maximum(args):
    names = ("yd-", "m", "theta", "x_cog", "y_cog")
    return ", ".join(f"{name} = {value:.4g}" for name, value in zip(names, args))


@check(2, title="(b, d) angle_of_max_impulse and max_impulse equal the reference's at random pins (your own "
       "impulse is shown around phi_hat)", stage=STAGE_RANDOM, group="contact")
def check_maximum(ctx):
    def compare(got, expected, args):
        _, m = args[:2]
        where = f"at {_describe_maximum(args)}"
        phi_hat, Lam_max = as_array(got["phi_hat"], "phi_hat", ()), as_array(got["Lam_max"], "Lam_max", ())
        expected_phi, expected_max = float(expected["phi_hat"]), float(expected["Lam_max"])
        before, at, after = (float(x) for x in got["impulses"])
        note = (f"Your own impulse is larger at phi_hat -+ {DELTA} ({before:.6g}, {after:.6g}) than at phi_hat "
                f"({at:.6g}): phi_hat is not its maximum." if max(before, after) > at * (1 + 1e-12) else "")
        assert_close(phi_hat, expected_phi, "phi_hat", EXACT, [
            Mistake("swapped", np.pi / 2 - expected_phi, "The corner is straight below the centre of gravity when "
                    "(x_cog, y_cog) turned by phi points straight up: check which of x_cog and y_cog is the "
                    "opposite side of the angle."),
            Mistake("degrees", np.rad2deg(expected_phi), "Angles in radians."),
        ], context=where, note=note)
        assert_close(Lam_max, expected_max, "Lam_max", EXACT, [
            Mistake("impulse_sign", -expected_max, "The lane pushes: Lam_max > 0 for a falling pin (yd- < 0)."),
            Mistake("missing_mass", expected_max / m, "An impulse stops a momentum: m yd-, not the velocity alone."),
        ], context=where)

    ctx.compare_random(p47.maximum, _maximum_cases(), name="phi_hat, Lam_max", tol=EXACT, compare=compare,
                       examples=8, describe=_describe_maximum)
