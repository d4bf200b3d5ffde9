"""Problem 27 (Understanding Jacobians): the multiple-choice keys, computed.

The sheet's figures are missing, so (a) and (d) are restated with explicit geometry (problem data); the options
are typed from the sheet.

(a) Planar arm, ``x = (xe, ye, gammae)``: revolute joint 1 at the origin, prismatic joint 2 sliding along
    ``(0.26, 0.97)``, revolute joint 3 at ``(1.82, 6.61)``, end effector at ``(5.17, 2.83)`` [m].  The Jacobian's
    columns are ``(-(ye - py), xe - px, 1)`` for a revolute joint at ``p`` and ``(ux, uy, 0)`` for a prismatic
    joint along ``u``.
(b) Explicit equality constraints ``x = f(q, t)``: each option's velocity formula is evaluated on an example
    constraint of the option's type.  The types are classified by definition, not computed: an explicit equality
    is holonomic (rheonomic when ``f`` depends on ``t``, scleronomic when not) and cannot describe a non-holonomic
    constraint, so option 3 is excluded on that ground.  The frame subscripts (option 4 uses C) are not modelled.
(c) Bias acceleration ``sigma`` of an explicit rheonomic constraint, defined by ``x_ddot = J q_ddot + sigma``: it
    is the acceleration of ``x`` along a motion with the same ``q``, ``q_dot`` and ``q_ddot = 0``.  Each option is
    evaluated symbolically on an example constraint and trajectory.  The sheet's fourth option is garbled in
    extraction; it is read as ``sigma = d^2 f_c / dt^2 - J_c q_ddot``.
(d) Flyball governor: the spindle is the vertical I y-axis (x to the right, z towards the viewer), ``phi`` turns
    the spindle about +y, and the right ball hangs at distance ``l`` from a pivot on the spindle on a linkage at
    ``gamma`` from the downward vertical: ``I_r = R2(phi) (l sin gamma, -l cos gamma, 0)`` (plus the constant pivot
    position).  The configuration is ``phi = 0``, ``gamma = 30 deg``; options are in units of ``l``.
(e) Transport of time derivatives between frames.  The operators between the terms were lost in extraction; they
    are restored as minus signs (the only reading under which exactly one statement fails), and the subscripts of
    statement 4 are read as B.  Each statement is evaluated numerically on a random rigid motion.

Course keys (problem data): (a) 4, (b) 1, (c) 1, (d) 3, (e) 2.
"""

import numpy as np

from .rotations import cardan, cardan_rate_matrix, skew

__all__ = [
    "PRINT_TOL",
    "JOINT_1",
    "AXIS_2",
    "JOINT_3",
    "END_EFFECTOR",
    "OPTIONS_A",
    "OPTIONS_B",
    "OPTIONS_D",
    "revolute_column",
    "prismatic_column",
    "jacobian_a",
    "governor_jacobian",
    "frame_derivative_residuals",
]

#: tolerance for matrices printed with two decimals
PRINT_TOL = 5e-3

JOINT_1 = (0.0, 0.0)
AXIS_2 = (0.26, 0.97)
JOINT_3 = (1.82, 6.61)
END_EFFECTOR = (5.17, 2.83)

OPTIONS_A = {
    1: np.array([[5.17, 0.97, 3.35], [-2.83, 0.26, 3.78], [0.0, 0.0, 1.0]]),
    2: np.array([[1.82, 0.97, 3.35], [-6.76, 0.26, 3.78], [1.0, 0.0, 1.0]]),
    3: np.array([[-6.76, 0.26, 3.78], [1.82, 0.97, 3.35], [1.0, 0.0, 1.0]]),
    4: np.array([[-2.83, 0.26, 3.78], [5.17, 0.97, 3.35], [1.0, 0.0, 1.0]]),
}

#: option -> (time derivative added to ``J q_dot``, constraint type)
OPTIONS_B = {
    1: ("partial", "holonomic"),
    2: ("total", "rheonomic"),
    3: ("partial", "non-holonomic"),
    4: ("total", "scleronomic"),
}

_H = np.sqrt(3.0) / 2.0
OPTIONS_D = {
    1: np.array([[_H, _H], [0.5, 0.0], [0.0, -0.5]]),
    2: np.array([[_H, 0.0], [0.0, 0.5], [-0.5, 0.0]]),
    3: np.array([[0.0, _H], [0.0, 0.5], [-0.5, 0.0]]),
    4: np.array([[0.0, _H], [0.5, 0.0], [0.0, -0.5]]),
}


def revolute_column(p, p_e):
    """Column ``(x, y, gamma)`` of the planar Jacobian of the end effector at ``p_e`` for a revolute joint at ``p``."""
    # BEGIN SOLUTION problem 27
    (px, py), (xe, ye) = p, p_e
    return np.array([-(ye - py), xe - px, 1.0])
    # END SOLUTION


def prismatic_column(u):
    """Column ``(x, y, gamma)`` of the planar Jacobian for a prismatic joint sliding along ``u``."""
    # BEGIN SOLUTION problem 27
    ux, uy = u
    return np.array([ux, uy, 0.0])
    # END SOLUTION


def jacobian_a():
    """``J_f`` of (a) from the restated geometry."""
    # BEGIN SOLUTION problem 27
    return np.column_stack(
        [
            revolute_column(JOINT_1, END_EFFECTOR),
            prismatic_column(AXIS_2),
            revolute_column(JOINT_3, END_EFFECTOR),
        ]
    )
    # END SOLUTION


# BEGIN REFERENCE ONLY
def _constraint(rheonomic):
    """Example explicit constraint ``x = f(q, t)``: a two-link arm, on a turning, moving base when rheonomic."""
    import sympy as sp

    t = sp.Symbol("t", real=True)
    q = sp.symbols("q1 q2", real=True)
    arm = sp.Matrix(
        [
            sp.cos(q[0]) + sp.Rational(7, 10) * sp.cos(q[0] + q[1]),
            sp.sin(q[0]) + sp.Rational(7, 10) * sp.sin(q[0] + q[1]),
        ]
    )
    if not rheonomic:
        return t, q, arm
    turn = sp.Matrix([[sp.cos(3 * t / 2), -sp.sin(3 * t / 2)], [sp.sin(3 * t / 2), sp.cos(3 * t / 2)]])
    return t, q, turn * arm + sp.Matrix([sp.sin(2 * t) / 3, t**2 / 10])


def _trajectory(t, t0, q0, qd0, qdd0):
    """``q(t)`` with the given value, velocity and acceleration at ``t0``."""
    tau = t - t0
    return [a + b * tau + c * tau**2 / 2 for a, b, c in zip(q0, qd0, qdd0)]


# example state at which (b) and (c) are evaluated: t0, q(t0), q_dot(t0), q_ddot(t0) as exact fractions
_T0 = (2, 5)
_Q0, _QD0, _QDD0 = ((1, 3), (-1, 2)), ((1, 2), (3, 4)), ((-2, 3), (5, 4))


def _rationals(pairs):
    import sympy as sp

    return [sp.Rational(*pair) for pair in pairs]


def _float_vector(expr, t, t0):
    return np.array(expr.subs(t, t0).evalf(), dtype=float).reshape(-1)


def velocity_residuals():
    """``{option: |x_dot - (J q_dot + df)|}`` of (b), ``None`` when the option's type admits no explicit equality."""
    import sympy as sp

    t0, q0, qd0, qdd0 = sp.Rational(*_T0), _rationals(_Q0), _rationals(_QD0), _rationals(_QDD0)
    residuals = {}
    for option, (derivative, kind) in OPTIONS_B.items():
        if kind == "non-holonomic":
            residuals[option] = None
            continue
        t, q, f = _constraint(rheonomic=kind != "scleronomic")
        along = dict(zip(q, _trajectory(t, t0, q0, qd0, qdd0)))
        x_dot = f.subs(along).diff(t)
        df = f.diff(t).subs(along) if derivative == "partial" else x_dot
        predicted = f.jacobian(q).subs(along) * sp.Matrix(qd0) + df
        residuals[option] = float(np.linalg.norm(_float_vector(x_dot - predicted, t, t0)))
    return residuals


def bias_acceleration_residuals():
    """``{option: |sigma_option - sigma|}`` of (c) on the rheonomic example constraint."""
    import sympy as sp

    t0, q0, qd0, qdd0 = sp.Rational(*_T0), _rationals(_Q0), _rationals(_QD0), _rationals(_QDD0)
    t, q, f = _constraint(rheonomic=True)
    along = dict(zip(q, _trajectory(t, t0, q0, qd0, qdd0)))
    coasting = dict(zip(q, _trajectory(t, t0, q0, qd0, [0, 0])))
    sigma = f.subs(coasting).diff(t, 2)
    x_ddot = f.subs(along).diff(t, 2)
    J = f.jacobian(q).subs(along)
    J_dot_qd = J.diff(t) * sp.Matrix(qd0)
    J_qdd = J * sp.Matrix(qdd0)
    options = {
        1: J_dot_qd + x_ddot,
        2: x_ddot - J_qdd,
        3: J_dot_qd + f.diff(t).subs(along).diff(t),
        4: f.subs(along).diff(t, 2) - J_qdd,
    }
    return {k: float(np.linalg.norm(_float_vector(v - sigma, t, t0))) for k, v in options.items()}
# END REFERENCE ONLY


def governor_jacobian():
    """``J / l`` of the right ball of (d) at ``phi = 0``, ``gamma = 30 deg`` (columns ``phi``, ``gamma``)."""
    # BEGIN SOLUTION problem 27
    import sympy as sp

    phi, gamma, l = sp.symbols("phi gamma l", positive=True)
    c, s = sp.cos(phi), sp.sin(phi)
    A_I_spindle = sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    I_r_ball = A_I_spindle * sp.Matrix([l * sp.sin(gamma), -l * sp.cos(gamma), 0])
    J = I_r_ball.jacobian([phi, gamma]).subs({phi: 0, gamma: sp.pi / 6}) / l
    return np.array(sp.simplify(J).evalf(), dtype=float)
    # END SOLUTION


def _rigid_motion(seed):
    """Random smooth rigid motion: Cardan angles and position are polynomials in t with random coefficients."""
    rng = np.random.default_rng(seed)
    angles = [np.polynomial.Polynomial(c) for c in rng.uniform(-1.0, 1.0, (3, 3))]
    position = [np.polynomial.Polynomial(c) for c in rng.uniform(-1.0, 1.0, (3, 4))]
    B_I_B = np.diag(rng.uniform(0.5, 2.0, 3))
    mass = rng.uniform(0.5, 2.0)

    def at(t, order=0):
        return np.array([p.deriv(order)(t) if order else p(t) for p in angles])

    def A_IB(t):
        return cardan(*at(t))

    def B_omega(t):
        return cardan_rate_matrix(*at(t)) @ at(t, 1)

    def I_r(t, order=0):
        return np.array([p.deriv(order)(t) if order else p(t) for p in position])

    return A_IB, B_omega, I_r, B_I_B, mass


def _derivative(f, t, h=1e-5):
    return (f(t + h) - f(t - h)) / (2.0 * h)


def frame_derivative_residuals(seed=0, t=0.3):
    """``{statement: |lhs - rhs|}`` of the four statements of (e) on a random rigid motion at time ``t``."""
    # BEGIN SOLUTION problem 27
    A_IB, B_omega, I_r, B_I_B, m = _rigid_motion(seed)
    A, w = A_IB(t), B_omega(t)
    I_w = A @ w
    B_r, B_v = A.T @ I_r(t), A.T @ I_r(t, 1)
    B_a = _derivative(lambda s: A_IB(s).T @ I_r(s, 1), t) + np.cross(w, B_v)

    def I_L(s):
        return A_IB(s) @ B_I_B @ B_omega(s)

    B_L, B_P = A.T @ I_L(t), m * B_v
    statements = {
        1: (_derivative(lambda s: A_IB(s).T @ I_r(s), t), B_v - skew(w) @ B_r),
        2: (I_r(t, 2), A @ B_a - np.cross(I_w, A @ B_v)),
        3: (_derivative(lambda s: A_IB(s).T @ I_L(s), t), A.T @ _derivative(I_L, t) - np.cross(w, B_L)),
        4: (_derivative(lambda s: m * A_IB(s).T @ I_r(s, 1), t), A.T @ (m * I_r(t, 2)) - skew(w) @ B_P),
    }
    return {k: float(np.linalg.norm(lhs - rhs)) for k, (lhs, rhs) in statements.items()}
    # END SOLUTION


# BEGIN REFERENCE ONLY
def _only(options, what):
    if len(options) != 1:
        raise ValueError(f"expected exactly one option that {what}, found {options}")
    return options[0]


def answer_a():
    """Key of (a): the option equal to the computed Jacobian."""
    J = jacobian_a()
    return _only([k for k, option in OPTIONS_A.items() if np.allclose(option, J, atol=PRINT_TOL)], "matches J")


def answer_b(tol=1e-9):
    """Key of (b): the option whose formula reproduces ``x_dot`` for its constraint type."""
    residuals = velocity_residuals()
    return _only([k for k, r in residuals.items() if r is not None and r < tol], "gives x_dot")


def answer_c(tol=1e-9):
    """Key of (c): the option that does NOT give the bias acceleration."""
    return _only([k for k, r in bias_acceleration_residuals().items() if r > tol], "fails")


def answer_d():
    """Key of (d): the option equal to the computed Jacobian of the ball."""
    J = governor_jacobian()
    return _only([k for k, option in OPTIONS_D.items() if np.allclose(option, J, atol=1e-12)], "matches J")


def answer_e(tol=1e-6):
    """Key of (e): the statement that is NOT correct on a random rigid motion."""
    return _only([k for k, r in frame_derivative_residuals().items() if r > tol], "fails")


def answers():
    """``{"a": ..., "e": ...}``: all five keys."""
    return {
        "a": answer_a(),
        "b": answer_b(),
        "c": answer_c(),
        "d": answer_d(),
        "e": answer_e(),
    }
# END REFERENCE ONLY
