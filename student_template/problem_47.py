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
    """(b) ``phi_hat``: the angle in ``(-pi/2, pi/2)`` at which ``impulse`` is largest."""
    # TODO problem 47: write your solution here
    raise NotImplementedError("Problem 47: angle_of_max_impulse is not implemented yet")


def max_impulse(yd_minus, m):
    """(d) ``Lam_max``: the largest impulse for ``qd- = (xd-, yd-, 0)``."""
    # TODO problem 47: write your solution here
    raise NotImplementedError("Problem 47: max_impulse is not implemented yet")
