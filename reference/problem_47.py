"""Problem 47: the bowling pin falling onto the greased (frictionless) lane, a plastic impact.

Problem data P47: ``q = (x, y, phi)``, the centre of gravity in inertial coordinates and the rotation ``phi`` from
vertical; mass ``m``, inertia ``theta``, ``M = diag(m, m, theta)``; the centre of gravity at ``(x_cog, y_cog)``
from the pin's lower left corner (in the pin's frame), the corner that touches the lane.  The constraint ``c`` is
the height of that corner above the lane, ``c_dot = J qd``.  A fully plastic impact keeps the position,
``q+ = q-``, and stops the contact, ``J qd+ = 0``, with the impulse ``Lam`` acting through ``+J.T Lam``.

(b) and (c) are free-text answers in answers.toml (``[problem_47.free_text] b``, ``c``): argue physically.
"""

import numpy as np

__all__ = ["constraint", "constraint_jacobian", "plastic_impact", "impulse", "angle_of_max_impulse", "max_impulse"]


def constraint(q, x_cog, y_cog):
    """(a) ``c``: the height of the pin's lower left corner above the lane (a float)."""
    # BEGIN SOLUTION problem 47
    x, y, phi = q
    return float(y - x_cog * np.sin(phi) - y_cog * np.cos(phi))
    # END SOLUTION


def constraint_jacobian(q, x_cog, y_cog):
    """(a) ``J``: the 1 x 3 Jacobian of the contact, ``c_dot = J qd``."""
    # BEGIN SOLUTION problem 47
    phi = q[2]
    return np.array([[0.0, 1.0, y_cog * np.sin(phi) - x_cog * np.cos(phi)]])
    # END SOLUTION


def plastic_impact(q_minus, qd_minus, m, theta, x_cog, y_cog):
    """``(q_plus, qd_plus, Lam)``: the state after a fully plastic impact of the corner on the lane and the impulse
    (a float), from the state ``(q_minus, qd_minus)`` just before it."""
    # BEGIN SOLUTION problem 47
    qd_minus = np.asarray(qd_minus, dtype=float)
    M_inv = np.diag([1.0 / m, 1.0 / m, 1.0 / theta])
    J = constraint_jacobian(q_minus, x_cog, y_cog)
    Lam = -(J @ qd_minus) / (J @ M_inv @ J.T)[0]
    return np.array(q_minus, dtype=float), qd_minus + M_inv @ J.T @ Lam, float(Lam[0])
    # END SOLUTION


def impulse(phi, yd_minus, m, theta, x_cog, y_cog):
    """(d) ``Lam``: the impulse for ``qd- = (xd-, yd-, 0)`` at the angle ``phi`` (a float)."""
    # BEGIN SOLUTION problem 47
    arm = x_cog * np.cos(phi) - y_cog * np.sin(phi)
    return float(-m * theta * yd_minus / (m * arm ** 2 + theta))
    # END SOLUTION


def angle_of_max_impulse(x_cog, y_cog):
    """(b) ``phi_hat``: the angle in ``(-pi/2, pi/2)`` at which ``impulse`` is largest."""
    # BEGIN SOLUTION problem 47
    return float(np.arctan2(x_cog, y_cog))
    # END SOLUTION


def max_impulse(yd_minus, m):
    """(d) ``Lam_max``: the largest impulse for ``qd- = (xd-, yd-, 0)``."""
    # BEGIN SOLUTION problem 47
    return float(-m * yd_minus)
    # END SOLUTION
