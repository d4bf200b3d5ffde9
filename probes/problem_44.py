"""Probes of problem 44: the event function of the second support, and the bar's run up to it (with the package's
own constraint of problem 43 along the run)."""

import numpy as np

from . import module, probe
from ._dynamics import fixed_run, fixed_step, trace
from ._forms import Arr, Dict, Flag, Maybe, Num

#: an event function's values at the states, and its ``terminal`` and ``direction`` attributes (None when missing)
EVENT = Dict({"values": Arr(None), "terminal": Maybe(Flag()), "direction": Maybe(Num())})

@probe(returns=EVENT, says="make_contact_event({1}, {2})", args=("", "scalar", "scalar"))
def event(pkg, states, s, d):
    """The values of ``make_contact_event(s, d)`` at every state ``y = (q, qd)``, and its ``terminal`` and
    ``direction`` attributes (``None`` when missing)."""
    function = module(pkg, "problem_44").make_contact_event(s, d)
    values = [float(function(0.0, np.asarray(y, dtype=float))) for y in states]
    terminal, direction = getattr(function, "terminal", None), getattr(function, "direction", None)
    return {"values": values, "terminal": None if terminal is None else bool(terminal),
            "direction": None if direction is None else float(direction)}


@probe(
    returns=Dict(
        {
            "t": Arr(None),
            "q": Arr(None, 3),
            "qd": Arr(None, 3),
            "c": Arr(None),
            "t_event": Maybe(Num()),
            "q_event": Arr(3),
            "qd_event": Arr(3),
        },
        optional=("q_event", "qd_event"),
    ),
    says="simulate(q0, {1}, {2})",
    motion={"time": "t", "states": ("q", "qd"), "events": ("t_event",), "fixed_step": "problem_44.simulate_fixed",
               "schemes": ("euler", "symplectic")},
)
def simulate(pkg, q0, t_end, s, bar=None, d=None):
    """``simulate(q0, t_end, s)`` (the sheet's bar, or ``bar = (m, theta, g)`` and the half-width ``d`` where given):
    the run, the event, and ``c`` of the package's own ``problem_43.constraint`` at every output time (the first
    support, at ``d``, 0 unless given)."""
    other = {} if bar is None else dict(zip(("m", "theta", "g"), (float(x) for x in bar)))
    if d is not None:
        other["d"] = float(d)
    run = module(pkg, "problem_44").simulate(np.asarray(q0, dtype=float), float(t_end), float(s), **other)
    t, q, qd = trace(run, 3, "problem_44.simulate")
    constraint = module(pkg, "problem_43").constraint
    width = 0.0 if d is None else float(d)
    out = {"t": t, "q": q, "qd": qd, "c": np.array([float(constraint(row, width)) for row in q]),
           "t_event": run.get("t_event")}
    if out["t_event"] is not None:
        out["t_event"] = float(out["t_event"])
        for key in ("q_event", "qd_event"):
            out[key] = np.asarray(run[key], dtype=float).reshape(3)
    return out


@probe(reference_only=True)
def simulate_fixed(pkg, q0, t_end, s, *rest):
    """The bar of ``simulate`` run by a fixed-step ``scheme`` at step ``h`` with the package's own ``bar_ode``,
    until it hits the second support (the diagnosis engine calls it on the reference, with the arguments of
    ``simulate`` followed by ``h, scheme``: ``rest`` is ``(h, scheme)``, ``(bar, h, scheme)`` or
    ``(bar, d, h, scheme)``)."""
    *extra, h, scheme = rest
    bar, d = (list(extra) + [None, None])[:2]
    other = {} if bar is None else dict(zip(("m", "theta", "g"), (float(x) for x in bar)))
    p44 = module(pkg, "problem_44")
    event = p44.make_contact_event(float(s)) if d is None else p44.make_contact_event(float(s), float(d))
    at_rest = np.append(np.asarray(q0, dtype=float), [0.0, 0.0, 0.0])
    return fixed_run(fixed_step(lambda t, y: p44.bar_ode(t, y, **other), at_rest, float(t_end), h, scheme, event=event,
                                direction=-1.0), 3)
