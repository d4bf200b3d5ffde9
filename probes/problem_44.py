"""Probes of problem 44: the event function of the second support, and the bar's run up to it (with the package's
own constraint of problem 43 along the run)."""

from contextlib import nullcontext

import numpy as np

from . import module, probe
from ._dynamics import fixed_run, fixed_step, solver_variant, trace
from ._forms import Arr, Dict, Flag, Maybe, Num, Seq

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
               "schemes": ("euler", "symplectic"), "rhs": "problem_44.bar_ode", "rhs_args": (3,),
               "parameters": {"arg": 3, "names": ("m", "theta", "g"), "sheet": "problem_44.sheet_bar"},
               "start": {"arg": 0, "name": "q0", "sheet": "problem_44.sheet_start"},
               "variants": {"arg": 5, "tolerances": True},
               "at_events": {"q_event": ("t_event", "q"), "qd_event": ("t_event", "qd")}},
)
def simulate(pkg, q0, t_end, s, bar=None, d=None, variant=None):
    """``simulate(q0, t_end, s)`` (the sheet's bar, or ``bar = (m, theta, g)`` and the half-width ``d`` where given):
    the run, the event, and ``c`` of the package's own ``problem_43.constraint`` at every output time (the first
    support, at ``d``, 0 unless given).  ``variant`` (the diagnosis engine's, on the reference): the package's run
    with ``solve_ivp`` called as a slip would call it (``_dynamics.solver_variant``: at looser tolerances)."""
    other = {} if bar is None else dict(zip(("m", "theta", "g"), (float(x) for x in bar)))
    if d is not None:
        other["d"] = float(d)
    p44 = module(pkg, "problem_44")
    with solver_variant(variant, p44) if variant is not None else nullcontext():
        run = p44.simulate(np.asarray(q0, dtype=float), float(t_end), float(s), **other)
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


@probe(returns=Seq(Arr(6), length=lambda bar, cases: len(cases)), says="bar_ode", terms="problem_44.bar_ode_terms")
def bar_ode(pkg, bar, cases):
    """``bar_ode(t, y)`` (or ``bar_ode(t, y, m, theta, g)`` with ``bar = (m, theta, g)`` where given) for every
    ``(t, y)`` of ``cases`` (the diagnosis engine compares it with the reference's at states along a run of
    ``simulate``)."""
    other = {} if bar is None else dict(zip(("m", "theta", "g"), (float(x) for x in bar)))
    p44 = module(pkg, "problem_44")
    return [np.array(p44.bar_ode(float(t), np.asarray(y, dtype=float), **other), dtype=float) for t, y in cases]


@probe(reference_only=True)
def bar_ode_terms(pkg, bar, cases):
    """``bar_ode`` of every case split into named terms (the diagnosis engine calls it on the reference):
    ``dy/dt = (qd, 0) + (0, qdd without gravity) + (0, what gravity adds)`` (the accelerations of the bar on its
    support are affine in ``g``)."""
    m, theta, g = (None, None, None) if bar is None else (float(x) for x in bar)
    p44 = module(pkg, "problem_44")
    other = {} if bar is None else {"m": m, "theta": theta}
    gravity = p44.GRAVITY if g is None else g
    terms = {"velocity": [], "f": [], "gravity": []}
    for t, y in cases:
        y = np.asarray(y, dtype=float)
        full = np.asarray(p44.bar_ode(float(t), y.copy(), **other, g=gravity), dtype=float)
        bias = np.asarray(p44.bar_ode(float(t), y.copy(), **other, g=0.0), dtype=float)
        zero = np.zeros(3)
        terms["velocity"].append(np.concatenate([y[3:], zero]))
        terms["f"].append(np.concatenate([zero, bias[3:]]))
        terms["gravity"].append(np.concatenate([zero, full[3:] - bias[3:]]))
    return {"terms": terms, "extra": {}}


@probe(reference_only=True)
def sheet_start(pkg):
    """The sheet's start ``Q0``: the positions ``simulate`` starts from where it is given no ``q0`` (the diagnosis
    engine calls it on the reference)."""
    return [float(x) for x in module(pkg, "problem_44").Q0]


@probe(reference_only=True)
def sheet_bar(pkg):
    """The sheet's bar ``(m, theta, g)``: the values ``simulate`` runs with where it is given no ``bar`` (the
    diagnosis engine calls it on the reference)."""
    p44 = module(pkg, "problem_44")
    return [float(p44.MASS), float(p44.THETA), float(p44.GRAVITY)]
