"""Checks of problem 43: the bar on a frictionless support (``mass_matrix``, ``forces``, ``constraint``,
``constraint_jacobian``, ``constraint_bias``, ``constrained_system``, ``accelerations``).

Physics decides where it can: ``M`` symmetric positive-definite; ``J`` the gradient and ``sigma`` the second
derivative along ``qd`` of the student's own constraint (finite differences); the solution of the constrained
system meets the constraint (``J qdd + sigma = 0``) and the equations of motion with the student's own pieces.
Where it cannot (the sign conventions of the sheet, the values), against the reference at random states with a
catalogue of known mistakes, and at the sheet's state with the erratum of lambda (the sheet prints 1.742 for
1.7342).
"""

import numpy as np
from grader import strategies as st

from grader.checking import (
    EXACT,
    SHEET,
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
from probes import problem_43 as p43

from ._answers import typed_or_ignored

TITLE = "Equations of Motion for a System with Implicit Constraints"

#: problem data P43
MASS, THETA, GRAVITY, HALF_WIDTH = 0.5, 1.0, 9.81, 0.0
Q0 = np.array([1.0, 1.0, np.pi / 4])
SHEET_QDD = np.array([-2.4525, -7.3575, -2.4525])
SHEET_LAMBDA = 1.742
ERRATUM = ("Erratum: the sheet prints lambda = 1.742; the correct value is 9.81 * 0.7071 / 4 = 1.7342 (graded "
           "against the correct value).")
#: finite differences of the student's own constraint: first derivatives (central, h = 1e-6) and the second
#: derivative along qd (h = 1e-4)
H_GRADIENT, H_PATH = 1e-6, 1e-4
GRADIENT = Tol("finite differences, h = 1e-6", 1e-6, 1e-6)
CURVATURE = Tol("second differences, h = 1e-4", 1e-5, 1e-5)
PHYSICS = Tol("constrained dynamics", 1e-8, 1e-8)
SPD = 1e-9
_SEEDS = st.integers(0, 2**32 - 1)

HINTS = {
    "constraint_force_sign": "The support pushes through +J.T lam: M qdd = f + g + J.T lam, so the system is "
                             "[[M, -J.T], [J, 0]] [qdd; lam] = [f + g; -sigma] and lam > 0 while the bar rests on "
                             "the support.",
    "missing_sigma": "The constraint holds at the level of accelerations: c_ddot = J qdd + sigma = 0, so the lower "
                     "row is J qdd = -sigma; without sigma the bar leaves its support as soon as it turns.",
    "sigma_sign": "c_ddot = J qdd + sigma = 0: the lower row is J qdd = -sigma.",
    "gravity_sign": "Gravity acts along -y: g = (0, -m g, 0).",
}


def _state(rng):
    return (np.concatenate([rng.uniform(-2.0, 2.0, 2), rng.uniform(-np.pi, np.pi, 1)]), rng.uniform(-2.0, 2.0, 3))


def _parameters(rng):
    return float(rng.uniform(0.2, 3.0)), float(rng.uniform(0.2, 3.0)), float(rng.uniform(1.0, 20.0))


@st.composite
def _dynamic_cases(draw):
    """``(q, qd, m, theta, g)``."""
    rng = np.random.default_rng(draw(_SEEDS))
    return (*_state(rng), *_parameters(rng))


def _describe(args):
    """``q, qd`` and the parameters that follow them: ``m, theta, g`` (dynamics) or ``d`` (the constraint)."""
    q, qd, *rest = args
    names = ("m", "theta", "g") if len(rest) == 3 else ("d",)
    values = [f"{name} = {value:.4g}" for name, value in zip(names, rest)]
    return ", ".join([f"q = {np.round(q, 4).tolist()}", f"qd = {np.round(qd, 4).tolist()}", *values])


# ------------------------------------------------------------------------------------------ the free bar


@st.composite
def _masses(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    return float(rng.uniform(0.2, 3.0)), float(rng.uniform(0.2, 3.0))


@check(1, title="(a) mass_matrix(m, theta) is symmetric positive-definite and equals diag(m, m, theta) at random "
       "masses", stage=STAGE_STRUCTURE, group="bar")
def check_mass_matrix(ctx):
    def compare(got, expected, args):
        m, theta = args
        M = as_array(got, "M", (3, 3))
        if np.abs(M - M.T).max() > SPD or np.linalg.eigvalsh(0.5 * (M + M.T)).min() <= SPD:
            fail(f"M is not symmetric positive-definite (m = {m:.4g}, theta = {theta:.4g}):\n{format_array(M)}",
                 "The kinetic energy (m xd^2 + m yd^2 + theta phid^2) / 2 is positive for every motion.",
                 "not_positive_definite")
        assert_close(M, expected, "M", EXACT, [
            Mistake("inertia_position", np.diag([theta, theta, m]), "q = (x, y, phi): the mass belongs to the two "
                    "translations, the inertia theta to the rotation, M = diag(m, m, theta)."),
        ], context=f"(m = {m:.4g}, theta = {theta:.4g})")

    ctx.compare_random(p43.mass_matrix, _masses(), name="M", tol=EXACT, compare=compare, examples=5)


@check(1, title="(a) forces(m, g): f = 0 and gravity g = (0, -m g, 0) at random masses", stage=STAGE_STRUCTURE,
       group="bar")
def check_forces(ctx):
    def compare(got, expected, args):
        m, g = args
        assert_close(got["f"], expected["f"], "f", EXACT, context="(the free bar has no velocity terms)")
        assert_close(got["g"], expected["g"], "g", EXACT, [
            Mistake("gravity_sign", -np.asarray(expected["g"]), HINTS["gravity_sign"]),
            Mistake("missing_mass", np.asarray(expected["g"]) / m, "g is a force: the weight m g, not the acceleration "
                    "of gravity."),
        ], context=f"(m = {m:.4g}, g = {g:.4g})")

    ctx.compare_random(p43.forces, _masses(), name="f, g", tol=EXACT, compare=compare, examples=5)


# ------------------------------------------------------------------------------------------ the constraint


@st.composite
def _constraint_cases(draw):
    """``(q, qd, d, h)``."""
    rng = np.random.default_rng(draw(_SEEDS))
    return (*_state(rng), float(rng.uniform(-0.5, 0.5)), H_GRADIENT)


def _terms(ctx, name, tol, examples=8):
    """Compare ``constraint_terms`` at random states with ``compare(got, expected, args)``."""

    def run(compare):
        ctx.compare_random(p43.constraint_terms, _constraint_cases(), name=name, tol=tol, compare=compare,
                           examples=examples, describe=_describe)

    return run


@check(1, title="(b) constraint(q, d) = y cos phi - x sin phi - d at random states", stage=STAGE_STRUCTURE,
       group="bar")
def check_constraint(ctx):
    def compare(got, expected, args):
        q, _, d, _ = args
        x, y, phi = q
        c = float(expected["c"])
        assert_close(got["c"], c, "c", EXACT, [
            Mistake("constraint_sign", -c, "c is the height of the bar's lower edge over O, positive when the "
                    "support is below the bar: c = y cos phi - x sin phi - d."),
            Mistake("d_sign", c + 2 * d, "The lower edge lies d below the centre line of the bar: subtract d."),
            Mistake("sin_cos_swapped", y * np.sin(phi) - x * np.cos(phi) - d, "The normal of the bar turned by "
                    "phi is (-sin phi, cos phi): c = (x, y) . (-sin phi, cos phi) - d."),
        ], context=f"at {_describe(args[:3])}")

    _terms(ctx, "c", EXACT)(compare)


@check(2, title="(b) constraint_jacobian(q) is the 1 x 3 gradient of your own constraint (finite differences) and "
       "the reference's at random states", stage=STAGE_STRUCTURE, group="bar")
def check_constraint_jacobian(ctx):
    def compare(got, expected, args):
        if np.shape(got["J"]) == (3, 1):
            fail(f"J has shape (3, 1): the transpose of the constraint Jacobian.\ngot:\n{format_array(got['J'])}",
                 "J is a row, 1 x 3: c_dot = J qd (a 1 x 1 result); J.T is the column through which the force "
                 "acts, J.T lam.", "transpose")
        J = as_array(got["J"], "J", (1, 3))
        fd = np.array([[(plus - minus) / (2 * H_GRADIENT) for plus, minus in got["c_coordinates"]]])
        assert_close(J, fd, "J", GRADIENT, [
            Mistake("jacobian_sign", -fd, "J = dc/dq: with c = y cos phi - x sin phi - d, J = (-sin phi, cos phi, "
                    "-x cos phi - y sin phi)."),
        ], context=f"at {_describe(args[:3])} (expected: dc/dq of your own constraint)")
        assert_close(J, expected["J"], "J", EXACT, context=f"at {_describe(args[:3])}")

    _terms(ctx, "J", GRADIENT)(compare)


@check(2, title="(b) constraint_bias(q, qd) is the second derivative of your own constraint along qd (c_ddot = "
       "J qdd + sigma) and the reference's at random states", stage=STAGE_STRUCTURE, group="bar")
def check_constraint_bias(ctx):
    def compare(got, expected, args):
        q, qd, _, _ = args
        x, y, phi = q
        xd, yd, phid = qd
        sigma = as_array(got["sigma"], "sigma", (1,))
        before, at, after = got["c_path"]
        curvature = np.array([(after - 2 * at + before) / H_PATH ** 2])
        coriolis = -2 * phid * (xd * np.cos(phi) + yd * np.sin(phi))
        centripetal = phid ** 2 * (x * np.sin(phi) - y * np.cos(phi))
        mistakes = [
            Mistake("sigma_sign", -curvature, "sigma is what c_ddot is when qdd = 0: c_ddot = J qdd + sigma = "
                    "Jdot qd + J qdd, so sigma = +Jdot qd."),
            Mistake("coriolis_factor", curvature - coriolis / 2, "Both J's x- and y-entries and its phi-entry change "
                    "with phi: the cross terms add up to -2 phid (xd cos phi + yd sin phi) (factor 2)."),
            Mistake("centripetal_sign", curvature - 2 * centripetal, "The centripetal part is +phid^2 (x sin phi - "
                    "y cos phi): d/dt of -x cos phi - y sin phi at fixed x, y is +phid (x sin phi - y cos phi)."),
        ]
        assert_close(sigma, curvature, "sigma", CURVATURE, mistakes,
                     context=f"at {_describe(args[:2])} (expected: d^2/dt^2 c(q + t qd) at t = 0 of your own "
                             f"constraint)")
        assert_close(sigma, expected["sigma"], "sigma", EXACT, context=f"at {_describe(args[:2])}")

    ctx.compare_random(p43.constraint_terms, _constraint_cases().map(lambda a: (*a[:3], H_PATH)),
                       name="sigma", tol=CURVATURE, compare=compare, examples=8, describe=_describe)


# ------------------------------------------------------------------------------------------ the constrained system


def _mistakes(ctx, args, key):
    found = ctx.reference(p43.system_mistakes, *args)
    return [Mistake(name, np.asarray(value[key]), HINTS[name]) for name, value in found.items()]


@check(2, title="(b) constrained_system: [[M, -J.T], [J, 0]] [qdd; lam] = [f + g; -sigma] at random states (any "
       "system with the same solution)", stage=STAGE_VALUES, group="bar")
def check_constrained_system(ctx):
    def compare(got, expected, args):
        mistakes = {key: _mistakes(ctx, args, key) for key in ("A", "b", "qdd", "lam")}
        A, b = as_array(got["A"], "A", (4, 4)), as_array(got["b"], "b", (4,))
        A_ref, b_ref = np.asarray(expected["A"]), np.asarray(expected["b"])
        solution = np.linalg.solve(A_ref, b_ref)
        if abs(np.linalg.det(A)) > 1e-12 and close(np.linalg.solve(A, b), solution, EXACT):
            return
        where = f"at {_describe(args)}"
        assert_close(A, A_ref, "A", EXACT, mistakes["A"], context=where)
        assert_close(b, b_ref, "b", EXACT, mistakes["b"], context=where)

    ctx.compare_random(p43.constrained_system, _dynamic_cases(), name="A, b", tol=EXACT, compare=compare,
                       examples=8, describe=_describe)


@check(2, title="(c) accelerations: the constraint holds (J qdd + sigma = 0) and M qdd = f + g + J.T lam with your "
       "own M, g, J and sigma at random states", stage=STAGE_VALUES, group="bar")
def check_accelerations_physics(ctx):
    def compare(got, expected, args):
        qdd, lam = as_array(got["qdd"], "qdd", (3,)), as_array(got["lam"], "lam", (1,))
        M, J = as_array(got["M"], "M", (3, 3)), as_array(got["J"], "J", (1, 3))
        f, G, sigma = as_array(got["f"], "f", (3,)), as_array(got["g"], "g", (3,)), as_array(got["sigma"], "sigma",
                                                                                                  (1,))
        where = f"at {_describe(args)}"
        assert_close(J @ qdd, -sigma, "J qdd", PHYSICS, [
            Mistake("missing_sigma", np.zeros(1), HINTS["missing_sigma"]),
            Mistake("sigma_sign", sigma, HINTS["sigma_sign"]),
        ], context=f"{where} (the contact stays closed: J qdd + sigma = 0, with your own J and sigma)")
        assert_close(M @ qdd - f - G, J.T @ lam, "M qdd - f - g", PHYSICS, [
            Mistake("constraint_force_sign", -J.T @ lam, HINTS["constraint_force_sign"]),
        ], context=f"{where} (expected: J.T lam, the support's force, with your own M, f, g, J)")

    ctx.compare_random(p43.accelerations, _dynamic_cases(), name="qdd, lam", tol=PHYSICS, compare=compare,
                       examples=8, describe=_describe)


@check(2, title="(c) accelerations: qdd and lam of the reference at random states", stage=STAGE_VALUES, group="bar")
def check_accelerations_values(ctx):
    def compare(got, expected, args):
        mistakes = {key: _mistakes(ctx, args, key) for key in ("qdd", "lam")}
        where = f"at {_describe(args)}"
        assert_close(got["lam"], expected["lam"], "lam", EXACT, mistakes["lam"], context=where)
        assert_close(got["qdd"], expected["qdd"], "qdd", EXACT, mistakes["qdd"], context=where)

    ctx.compare_random(p43.accelerations, _dynamic_cases(), name="qdd, lam", tol=EXACT, compare=compare,
                       examples=8, describe=_describe)


#: a state and a bar the sheet does not print: the sheet's qdd and lam typed in earn nothing there
OTHER_CASE = (np.array([0.8, 1.3, np.pi / 6]), np.zeros(3), 0.7, 1.4, GRAVITY)
TYPED_HINT = ("These are the sheet's numbers whatever the state: compute qdd and lam from the arguments (the checks "
              "also ask states the sheet does not print).")


@check(2, title="(c) at q = (1, 1, 45 deg) at rest (m = 0.5, theta = 1, g = 9.81): qdd = (-2.4525, -7.3575, "
       "-2.4525) and lam = 1.7342 (the sheet's 1.742 is a misprint); the reference's at a state the sheet does not "
       "print", stage=STAGE_VALUES, group="bar")
def check_sheet(ctx):
    args = (Q0, np.zeros(3), MASS, THETA, GRAVITY)
    expected = ctx.reference(p43.accelerations, *args)
    mistakes = {key: _mistakes(ctx, args, key) for key in ("qdd", "lam")}
    got = ctx.student(p43.accelerations, *args)
    lam = float(np.asarray(expected["lam"]).reshape(-1)[0])
    lam_mistakes = [*mistakes["lam"], Mistake("sheet_misprint", np.array([SHEET_LAMBDA]), ERRATUM)]
    assert_close(got["qdd"], SHEET_QDD, "qdd", SHEET, mistakes["qdd"], context="(the sheet's state)")
    assert_close(got["lam"], np.array([lam]), "lam", SHEET, lam_mistakes, context="(the sheet's state)", note=ERRATUM)
    expected = ctx.reference(p43.accelerations, *OTHER_CASE)
    mistakes = {key: _mistakes(ctx, OTHER_CASE, key) for key in ("qdd", "lam")}
    got = ctx.student(p43.accelerations, *OTHER_CASE)
    where = f"at {_describe(OTHER_CASE)} (a state the sheet does not print)"
    assert_close(got["qdd"], expected["qdd"], "qdd", EXACT, [*typed_or_ignored(SHEET_QDD, TYPED_HINT, "state"),
                                                             *mistakes["qdd"]], context=where)
    assert_close(got["lam"], expected["lam"], "lam", EXACT, [*typed_or_ignored(np.array([lam]), TYPED_HINT, "state"),
                                                             Mistake("typed_numbers", np.array([SHEET_LAMBDA]),
                                                                     TYPED_HINT), *mistakes["lam"]], context=where)
