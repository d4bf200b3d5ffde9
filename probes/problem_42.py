"""Probes of problem 42: the two event functions of the thrown ball, the flight, and the computation behind the key
of question (b)."""

from contextlib import nullcontext

import numpy as np

from . import module, probe
from ._dynamics import fixed_step, solver_variant
from ._forms import Arr, Dict, Either, Flag, Maybe, Num, Seq, Text

#: an event function's values at the states, and its ``terminal`` and ``direction`` attributes (None when missing)
EVENT = Dict({"values": Arr(None), "terminal": Maybe(Flag()), "direction": Maybe(Num())})


def _attribute(function, name):
    value = getattr(function, name, None)
    if value is None:
        return None
    return bool(value) if name == "terminal" else float(value)


@probe(returns=Either(Dict({"problem": Text()}), Dict({"apex": EVENT, "landing": EVENT})), says="make_events()")
def events(pkg, states):
    """``{"apex", "landing"}``: each event function's values at every state ``y = (height, velocity)`` and its
    ``terminal`` and ``direction`` attributes (``None`` when missing); ``{"problem": text}`` when
    ``make_events()`` does not return two functions."""
    functions = module(pkg, "problem_42").make_events()
    if not isinstance(functions, (tuple, list)) or len(functions) != 2 or not all(map(callable, functions)):
        return {"problem": f"make_events() must return the two functions (apex, landing), got {str(functions)[:200]}"}
    out = {}
    for name, function in zip(("apex", "landing"), functions):
        out[name] = {"values": [float(function(0.0, np.asarray(y, dtype=float))) for y in states],
                     "terminal": _attribute(function, "terminal"), "direction": _attribute(function, "direction")}
    return out


def _optional(value):
    return None if value is None else float(value)


@probe(
    returns=Dict(
        {
            "t_apex": Maybe(Num()),
            "height_apex": Maybe(Num()),
            "t_land": Maybe(Num()),
            "v_land": Maybe(Num()),
            "t": Arr(None),
            "y": Arr(None, 2),
        }
    ),
    says="throw({0}, {1})",
    args=("scalar", "scalar", "scalar"),
    draw=False,
    motion={"time": "t", "states": ("y",), "events": ("t_apex", "t_land"), "fixed_step": "problem_42.throw_fixed",
               "schemes": ("euler",), "rhs": "problem_42.ball_ode", "rhs_args": (1, 2), "rhs_through": ("t_apex",),
               "parameters": {"args": (0, 1, 2), "names": ("v0", "drag", "g"), "sheet": "problem_42.sheet_ball"},
               "variants": {"arg": 3, "starts": ((0, 1),), "tolerances": True},
               "at_events": {"height_apex": ("t_apex", "y", 0), "v_land": ("t_land", "y", 1)}},
)
def throw(pkg, v0, drag, g=None, variant=None):
    """``throw(v0, drag)`` (and ``g`` where given): the apex and the landing, and the run ``t``, ``y`` (rows
    ``(height, velocity)``).  ``variant`` (the diagnosis engine's, on the reference): the package's flight with
    ``solve_ivp`` called as a slip would call it (``_dynamics.solver_variant``: from the start with two entries
    exchanged, or at looser tolerances)."""
    gravity = {} if g is None else {"g": float(g)}
    p42 = module(pkg, "problem_42")
    with solver_variant(variant, p42) if variant is not None else nullcontext():
        run = p42.throw(float(v0), float(drag), **gravity)
    if not isinstance(run, dict):
        raise ValueError(f"throw must return a dict, got {str(run)[:200]}")
    t = np.asarray(run.get("t"), dtype=float).reshape(-1)
    y = np.asarray(run.get("y"), dtype=float)
    if y.shape != (t.size, 2):
        raise ValueError(f"throw: 'y' must have one row (height, velocity) per time ({t.size} x 2), got shape "
                         f"{y.shape}")
    return {key: _optional(run.get(key)) for key in ("t_apex", "height_apex", "t_land", "v_land")} | {"t": t, "y": y}


@probe(returns=Dict({"t_land": Maybe(Num()), "t_end": Num()}), says="throw({0}, {1}, t_max={2})")
def cut_short(pkg, v0, drag, t_max):
    """``throw(v0, drag, t_max=t_max)`` with a ``t_max`` before the landing: the landing time (None where the
    ball has not landed) and the run's last time."""
    run = module(pkg, "problem_42").throw(float(v0), float(drag), t_max=float(t_max))
    if not isinstance(run, dict):
        raise ValueError(f"throw must return a dict, got {str(run)[:200]}")
    t = np.asarray(run.get("t"), dtype=float).reshape(-1)
    if not t.size:
        raise ValueError("throw: 't' holds no time")
    return {"t_land": _optional(run.get("t_land")), "t_end": float(t[-1])}


@probe(reference_only=True)
def sheet_ball(pkg):
    """The sheet's ball ``(v0, drag, g)``: the values ``throw`` runs with where it is not given them (the diagnosis
    engine calls it on the reference)."""
    p42 = module(pkg, "problem_42")
    return [float(p42.V0), float(p42.DRAG), float(p42.GRAVITY)]


@probe(reference_only=True)
def key(pkg):
    """``{"b"}``: the key of (b), computed by the package's reference-only function (called on the reference
    only)."""
    return {"b": int(module(pkg, "problem_42").answer_b())}


@probe(reference_only=True)
def throw_fixed(pkg, v0, drag, *rest):
    """The ball of ``throw`` run by a fixed-step ``scheme`` at step ``h`` with the package's own ``ball_ode``, until
    the height falls through zero (the diagnosis engine calls it on the reference, with the arguments of ``throw``
    followed by ``h, scheme``: ``rest`` is ``(h, scheme)`` or ``(g, h, scheme)``)."""
    *g, h, scheme = rest
    p42 = module(pkg, "problem_42")
    gravity = float(g[0]) if g and g[0] is not None else p42.GRAVITY
    run = fixed_step(lambda t, y: p42.ball_ode(t, y, float(drag), gravity), [0.0, float(v0)], p42.T_MAX, h,
                     scheme, event=lambda t, y: y[0] if t > 0 else 1.0)
    return {"t": run["t"], "y": run["y"], "t_land": run["t_event"]}


@probe(returns=Seq(Arr(2), length=lambda drag, g, cases: len(cases)), says="ball_ode")
def ball_ode(pkg, drag, g, cases):
    """``ball_ode(t, y, drag, g)`` (the package's ``GRAVITY`` where ``g`` is None) for every ``(t, y)`` of
    ``cases`` (the diagnosis engine compares it with the reference's at states along a run of ``throw``)."""
    p42 = module(pkg, "problem_42")
    gravity = p42.GRAVITY if g is None else float(g)
    return [np.array(p42.ball_ode(float(t), np.asarray(y, dtype=float), float(drag), gravity), dtype=float)
            for t, y in cases]
