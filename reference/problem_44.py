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
    # BEGIN SOLUTION problem 44
    def second_contact(t, y, *args):
        x, height, phi = y[:3]
        return float(height * np.cos(phi) - (x - s) * np.sin(phi) - d)

    second_contact.terminal = True
    second_contact.direction = -1
    return second_contact
    # END SOLUTION


def bar_ode(t, y, m=MASS, theta=THETA, g=GRAVITY):
    """The right-hand side ``dy/dt = (qd, qdd)`` of the bar on its support (problem 43), ``y = (q, qd)``."""
    # BEGIN SOLUTION problem 44
    qdd, _ = accelerations(y[:3], y[3:], m, theta, g)
    return np.concatenate([y[3:], qdd])
    # END SOLUTION


def simulate(q0=Q0, t_end=T_END, s=SUPPORT_DISTANCE, m=MASS, theta=THETA, g=GRAVITY, d=HALF_WIDTH):
    """The bar from ``q0`` at rest, output every ``T_STEP`` from 0, until it hits the second support (at most
    ``t_end``).  Returns ``{"t", "q", "qd"}`` (one row per output time up to the event), ``"t_event"``,
    ``"q_event"`` and ``"qd_event"`` (``t_event`` None if the bar does not reach the support by ``t_end``)."""
    # BEGIN SOLUTION problem 44
    from scipy.integrate import solve_ivp

    t_eval = np.arange(0.0, t_end + T_STEP / 2, T_STEP)
    y0 = np.concatenate([np.asarray(q0, dtype=float), np.zeros(3)])
    result = solve_ivp(bar_ode, (0.0, t_end), y0, t_eval=t_eval, args=(m, theta, g),
                       events=[make_contact_event(s, d)], rtol=1e-10, atol=1e-12)
    run = {"t": result.t, "q": result.y[:3].T, "qd": result.y[3:].T, "t_event": None}
    if len(result.t_events[0]):
        y_event = result.y_events[0][0]
        run.update(t_event=float(result.t_events[0][0]), q_event=y_event[:3], qd_event=y_event[3:])
    return run
    # END SOLUTION


def solve():
    """The sheet's run (``simulate()``)."""
    return simulate()
