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
    # BEGIN SOLUTION problem 42
    def apex(t, y, *args):
        return y[1]

    def landing(t, y, *args):
        return y[0]

    apex.terminal, apex.direction = False, -1
    landing.terminal, landing.direction = True, -1
    return apex, landing
    # END SOLUTION


def throw(v0=V0, drag=DRAG, g=GRAVITY, t_max=T_MAX):
    """The flight of the ball thrown up from the ground at ``v0``, integrated with ``solve_ivp`` and the events of
    ``make_events()`` until it lands (at most ``t_max``).  Returns ``{"t_apex", "height_apex", "t_land",
    "v_land"}`` (``t_land`` and ``v_land`` None if it does not land before ``t_max``) and the run, ``"t"`` and
    ``"y"`` (one row ``(height, velocity)`` per step of the solver, up to the landing)."""
    # BEGIN SOLUTION problem 42
    from scipy.integrate import solve_ivp

    result = solve_ivp(ball_ode, (0.0, t_max), [0.0, v0], args=(drag, g), events=make_events(), rtol=1e-10,
                       atol=1e-12)
    (t_apex, t_land), (y_apex, y_land) = result.t_events, result.y_events
    landed = len(t_land) > 0
    return {"t_apex": float(t_apex[0]), "height_apex": float(y_apex[0][0]),
            "t_land": float(t_land[0]) if landed else None, "v_land": float(y_land[0][1]) if landed else None,
            "t": result.t, "y": result.y.T}
    # END SOLUTION


# BEGIN REFERENCE ONLY
# The grader's computation of the key of question (b): not part of the student's package.

#: the options of (b): what happens to the flight when the landing event has direction 0
DIRECTION_OPTIONS = {
    1: "it ends at the landing, as with direction -1",
    2: "it ends at once, at t = 0",
    3: "it never ends: the ball falls through the ground until t_max",
    4: "it ends at the apex",
}


def flight_with_landing_direction(direction, v0=V0, drag=DRAG):
    """``(t_end, t_apex)``: where the flight of ``throw`` ends, and its apex time, when the landing event has the
    given ``direction`` (the apex is ``None`` if it is not reached)."""
    from scipy.integrate import solve_ivp

    apex, landing = make_events()
    landing.direction = direction
    result = solve_ivp(ball_ode, (0.0, T_MAX), [0.0, v0], args=(drag, GRAVITY), events=[apex, landing], rtol=1e-10,
                       atol=1e-12)
    return float(result.t[-1]), (float(result.t_events[0][0]) if len(result.t_events[0]) else None)


def answer_b():
    """The option of (b) that the integration shows for direction 0."""
    t_end, t_apex = flight_with_landing_direction(0)
    t_land, _ = flight_with_landing_direction(-1)
    outcomes = {1: abs(t_end - t_land) < 1e-6, 2: t_end < 1e-9, 3: t_end >= T_MAX - 1e-9,
                4: t_apex is not None and abs(t_end - t_apex) < 1e-6}
    found = [k for k, holds in outcomes.items() if holds]
    if len(found) != 1:
        raise ValueError(f"expected exactly one option to hold, found {found}")
    return found[0]
# END REFERENCE ONLY
