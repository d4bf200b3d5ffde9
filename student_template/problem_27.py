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
    # TODO problem 27: write your solution here
    raise NotImplementedError("Problem 27: revolute_column is not implemented yet")


def prismatic_column(u):
    """Column ``(x, y, gamma)`` of the planar Jacobian for a prismatic joint sliding along ``u``."""
    # TODO problem 27: write your solution here
    raise NotImplementedError("Problem 27: prismatic_column is not implemented yet")


def jacobian_a():
    """``J_f`` of (a) from the restated geometry."""
    # TODO problem 27: write your solution here
    raise NotImplementedError("Problem 27: jacobian_a is not implemented yet")




def governor_jacobian():
    """``J / l`` of the right ball of (d) at ``phi = 0``, ``gamma = 30 deg`` (columns ``phi``, ``gamma``)."""
    # TODO problem 27: write your solution here
    raise NotImplementedError("Problem 27: governor_jacobian is not implemented yet")


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
    # TODO problem 27: write your solution here
    raise NotImplementedError("Problem 27: frame_derivative_residuals is not implemented yet")


