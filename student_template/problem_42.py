"""Problem 42: event detection with ``scipy.integrate.solve_ivp`` (a warm-up; the sheet's problem is reading only).

Problem data P42: an event stops or marks the integration at a zero crossing of a residual ``value(t, y)``; the
attribute ``direction`` of the event function says which crossings count (+1: from - to +, -1: from + to -, 0:
both) and ``terminal`` whether the integration stops there.  In Python: ``solve_ivp(fun, t_span, y0,
events=[...])`` with ``event.terminal`` and ``event.direction``; the result holds ``t_events`` and ``y_events``,
one array per event function.

The warm-up: a ball thrown straight up from the ground, ``y = (height, velocity)``, with quadratic air drag (no
closed form)::

    height_dot = velocity
    velocity_dot = -g - k |velocity| velocity

with ``g = 9.81`` and the drag per unit mass ``k = 0.1 1/m``, thrown at ``v0 = 10 m/s``.  Two events: the apex
(the velocity crosses zero from + to -, marked, the integration goes on) and the landing (the height crosses zero
from + to -, the integration stops).  The ball starts on the ground, where the height is zero: only the direction
-1 keeps the launch from counting as a landing.

(a) ``make_events`` and ``throw``.  (b) In answers.toml, ``[problem_42] b``: with the landing event's direction 0
instead of -1, the flight of ``throw`` (1) ends at the landing, as with direction -1; (2) ends at once, at
``t = 0``; (3) never ends: the ball falls through the ground until ``t_max``; (4) ends at the apex.  Write the
number of the option.
"""

import numpy as np

__all__ = ["GRAVITY", "DRAG", "V0", "T_MAX", "ball_ode", "make_events", "throw"]

GRAVITY = 9.81
DRAG = 0.1
V0 = 10.0
#: the integration runs at most this long [s]; the landing ends it earlier
T_MAX = 10.0


def ball_ode(t, y, drag=DRAG, g=GRAVITY):
    """The right-hand side ``dy/dt`` of the thrown ball, ``y = (height, velocity)`` (given)."""
    height, velocity = y
    return np.array([velocity, -g - drag * abs(velocity) * velocity])


def make_events():
    """``(apex, landing)``: the two event functions ``apex(t, y, *args)`` (residual: the velocity; it marks the
    apex: direction -1, not terminal) and ``landing(t, y, *args)`` (residual: the height; it ends the flight:
    direction -1, terminal).  The ``args`` that ``solve_ivp`` also passes to the events are ignored."""
    # TODO problem 42: write your solution here
    raise NotImplementedError("Problem 42: make_events is not implemented yet")


def throw(v0=V0, drag=DRAG, g=GRAVITY, t_max=T_MAX):
    """The flight of the ball thrown up from the ground at ``v0``, integrated with ``solve_ivp`` and the events of
    ``make_events()`` until it lands (at most ``t_max``).  Returns ``{"t_apex", "height_apex", "t_land",
    "v_land"}`` (``t_land`` and ``v_land`` None if it does not land before ``t_max``) and the run, ``"t"`` and
    ``"y"`` (one row ``(height, velocity)`` per step of the solver, up to the landing)."""
    # TODO problem 42: write your solution here
    raise NotImplementedError("Problem 42: throw is not implemented yet")


