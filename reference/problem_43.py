"""Problem 43: a bar on a frictionless support, equations of motion with an implicit constraint.

Problem data P43: ``q = (x, y, phi)``, the position and orientation of the bar's centre of gravity in inertial
coordinates; mass ``m``, inertia ``theta``, width ``2 d``; gravity ``g`` along ``-y``.  The bar rests with its
lower edge on a frictionless point support at the origin O.  The constraint ``c`` is the distance of O below the
bar's lower edge, measured along the bar's normal ``(-sin phi, cos phi)``: zero while the edge runs through O,
positive when the bar is above it.  ``c_dot = J qd``, ``c_ddot = J qdd + sigma``.  The support pushes with the
force ``lam`` through ``+J.T lam``::

    M qdd = f + g + J.T lam,    J qdd + sigma = 0

At ``q = (1, 1, 45 deg)`` at rest with ``m = 0.5``, ``theta = 1``, ``d = 0``, ``g = 9.81`` the sheet gives
``qdd = (-2.4525, -7.3575, -2.4525)`` and ``lambda = 1.742``.  *Erratum* (problem data): the correct value is
``lambda = 9.81 * 0.7071 / 4 = 1.7342``.
"""

import numpy as np

__all__ = [
    "MASS",
    "THETA",
    "HALF_WIDTH",
    "GRAVITY",
    "Q0",
    "SHEET_QDD",
    "SHEET_LAMBDA",
    "mass_matrix",
    "forces",
    "constraint",
    "constraint_jacobian",
    "constraint_bias",
    "constrained_system",
    "accelerations",
    "solve",
]

MASS = 0.5
THETA = 1.0
#: d, half the width of the bar
HALF_WIDTH = 0.0
GRAVITY = 9.81
Q0 = np.array([1.0, 1.0, np.pi / 4])
#: the sheet's values at Q0, at rest (its lambda 1.742 is a misprint of 1.7342, see the erratum)
SHEET_QDD = np.array([-2.4525, -7.3575, -2.4525])
SHEET_LAMBDA = 1.742


def mass_matrix(m=MASS, theta=THETA):
    """(a) ``M``, the 3 x 3 mass matrix of the free bar."""
    # BEGIN SOLUTION problem 43
    return np.diag([m, m, theta])
    # END SOLUTION


def forces(m=MASS, g=GRAVITY):
    """(a) ``(f, g)``: the generalized forces of the free bar, ``f`` (3, no velocity terms) and gravity ``g`` (3),
    acting along ``-y``."""
    # BEGIN SOLUTION problem 43
    return np.zeros(3), np.array([0.0, -m * g, 0.0])
    # END SOLUTION


def constraint(q, d=HALF_WIDTH):
    """(b) ``c``: the violation of the contact at O (a float), zero when the bar's lower edge runs through O."""
    # BEGIN SOLUTION problem 43
    x, y, phi = q
    return float(y * np.cos(phi) - x * np.sin(phi) - d)
    # END SOLUTION


def constraint_jacobian(q):
    """(b) ``J``: the 1 x 3 constraint Jacobian, ``c_dot = J qd``."""
    # BEGIN SOLUTION problem 43
    x, y, phi = q
    return np.array([[-np.sin(phi), np.cos(phi), -x * np.cos(phi) - y * np.sin(phi)]])
    # END SOLUTION


def constraint_bias(q, qd):
    """(b) ``sigma``: the bias acceleration of the constraint (a 1-vector), ``c_ddot = J qdd + sigma``."""
    # BEGIN SOLUTION problem 43
    x, y, phi = q
    xd, yd, phid = qd
    return np.array([-2 * phid * (xd * np.cos(phi) + yd * np.sin(phi))
                     + phid ** 2 * (x * np.sin(phi) - y * np.cos(phi))])
    # END SOLUTION


def constrained_system(q, qd, m=MASS, theta=THETA, g=GRAVITY):
    """(b) ``(A, b)``: the equations of motion of the constrained bar as one linear system in ``(qdd, lam)``,
    ``A = [[M, -J.T], [J, 0]]`` (4 x 4) and ``b = [f + g; -sigma]`` (4)."""
    # BEGIN SOLUTION problem 43
    M = mass_matrix(m, theta)
    f, G = forces(m, g)
    J = constraint_jacobian(q)
    A = np.block([[M, -J.T], [J, np.zeros((1, 1))]])
    return A, np.concatenate([f + G, -constraint_bias(q, qd)])
    # END SOLUTION


def accelerations(q, qd, m=MASS, theta=THETA, g=GRAVITY):
    """(c) ``(qdd, lam)``: the accelerations (3) and the contact force (a float) of the constrained bar at
    ``(q, qd)``."""
    # BEGIN SOLUTION problem 43
    A, b = constrained_system(q, qd, m, theta, g)
    x = np.linalg.solve(A, b)
    return x[:3], float(x[3])
    # END SOLUTION


def solve():
    """``{"qdd", "lam"}`` at the sheet's state: ``Q0`` at rest."""
    qdd, lam = accelerations(Q0, np.zeros(3))
    return {"qdd": qdd, "lam": lam}
