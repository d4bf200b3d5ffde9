"""Problem 47: the bowling pin falling onto the greased (frictionless) lane, a plastic impact.

Problem data P47: ``q = (x, y, phi)``, the centre of gravity in inertial coordinates and the rotation ``phi`` from
vertical; mass ``m``, inertia ``theta``; the centre of gravity at ``(x_cog, y_cog)`` from the pin's lower left
corner, which touches the lane.  The constraint is the height of that corner::

    c = y - x_cog sin phi - y_cog cos phi
    J = (0, 1, y_cog sin phi - x_cog cos phi)

A fully plastic impact with ``M = diag(m, m, theta)``: ``Lam = -(J M^-1 J.T)^-1 J qd-``, ``qd+ = qd- + M^-1 J.T
Lam``, ``q+ = q-``.  For ``qd- = (xd-, yd-, 0)``::

    Lam = -m theta yd- / (m (x_cog cos phi - y_cog sin phi)^2 + theta)

maximal when the corner is straight below the centre of gravity, ``phi = arctan(x_cog / y_cog)``, where
``Lam_max = -m yd-`` (the whole vertical momentum is stopped, no rotation is started).
"""

import numpy as np

__all__ = ["constraint", "constraint_jacobian", "plastic_impact", "impulse", "angle_of_max_impulse", "max_impulse"]


def constraint(q, x_cog, y_cog):
    """(a) ``c``: the height of the pin's lower left corner above the lane (a float)."""
    # TODO problem 47: write your solution here
    raise NotImplementedError("Problem 47: constraint is not implemented yet")


def constraint_jacobian(q, x_cog, y_cog):
    """(a) ``J``: the 1 x 3 Jacobian of the contact, ``c_dot = J qd``."""
    # TODO problem 47: write your solution here
    raise NotImplementedError("Problem 47: constraint_jacobian is not implemented yet")


def plastic_impact(q_minus, qd_minus, m, theta, x_cog, y_cog):
    """``(q_plus, qd_plus, Lam)``: the state after a fully plastic impact of the corner on the lane and the impulse
    (a float), from the state ``(q_minus, qd_minus)`` just before it."""
    # TODO problem 47: write your solution here
    raise NotImplementedError("Problem 47: plastic_impact is not implemented yet")


def impulse(phi, yd_minus, m, theta, x_cog, y_cog):
    """(d) ``Lam``: the impulse for ``qd- = (xd-, yd-, 0)`` at the angle ``phi`` (a float)."""
    # TODO problem 47: write your solution here
    raise NotImplementedError("Problem 47: impulse is not implemented yet")


def angle_of_max_impulse(x_cog, y_cog):
    """(b) ``phi_hat``: the angle at which ``impulse`` is largest (the corner straight below the centre of
    gravity)."""
    # TODO problem 47: write your solution here
    raise NotImplementedError("Problem 47: angle_of_max_impulse is not implemented yet")


def max_impulse(yd_minus, m):
    """(d) ``Lam_max``: the largest impulse for ``qd- = (xd-, yd-, 0)``."""
    # TODO problem 47: write your solution here
    raise NotImplementedError("Problem 47: max_impulse is not implemented yet")
