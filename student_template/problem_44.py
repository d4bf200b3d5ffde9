"""Problem 44: the bar of problem 43 until it hits a second support (event detection).

Problem data P44: from ``t = 0`` to ``1`` s, output every 0.01 s, ``q0 = (1, 1, pi/4)`` at rest, ``m = 0.5``,
``theta = 1``, ``g = 9.81``, ``d = 0``.  A second frictionless support sits at the height of the first, at the
distance ``s = 0.5`` m from it.  The event is the height of the bar's lower edge above it,
``y cos phi - (x - s) sin phi - d``: it falls through zero as the bar hits the support (terminal, direction -1).
"""

import numpy as np

from .problem_43 import GRAVITY, HALF_WIDTH, MASS, Q0, THETA, accelerations

__all__ = ["SUPPORT_DISTANCE", "T_END", "T_STEP", "make_contact_event", "bar_ode", "simulate", "solve"]

#: s, the distance of the second support from the first [m]
SUPPORT_DISTANCE = 0.5
T_END = 1.0
T_STEP = 0.01


def make_contact_event(s=SUPPORT_DISTANCE, d=HALF_WIDTH):
    """The event function ``second_contact(t, y, *args)`` for ``solve_ivp`` (``y = (q, qd)``; the ``args`` that
    solve_ivp also passes are ignored): the height ``y cos phi - (x - s) sin phi - d`` of the bar's lower edge above
    the second support, with the attributes ``terminal`` (stop there) and ``direction`` (-1: it falls through
    zero)."""
    # TODO problem 44: write your solution here
    raise NotImplementedError("Problem 44: make_contact_event is not implemented yet")


def bar_ode(t, y, m=MASS, theta=THETA, g=GRAVITY):
    """The right-hand side ``dy/dt = (qd, qdd)`` of the bar on its support (problem 43), ``y = (q, qd)``."""
    # TODO problem 44: write your solution here
    raise NotImplementedError("Problem 44: bar_ode is not implemented yet")


def simulate(q0=Q0, t_end=T_END, s=SUPPORT_DISTANCE, m=MASS, theta=THETA, g=GRAVITY, d=HALF_WIDTH):
    """The bar from ``q0`` at rest, output every ``T_STEP`` from 0, until it hits the second support (at most
    ``t_end``).  Returns ``{"t", "q", "qd"}`` (one row per output time up to the event), ``"t_event"``,
    ``"q_event"`` and ``"qd_event"`` (``t_event`` None if the bar does not reach the support by ``t_end``)."""
    # TODO problem 44: write your solution here
    raise NotImplementedError("Problem 44: simulate is not implemented yet")


def solve():
    """The sheet's run (``simulate()``)."""
    return simulate()
