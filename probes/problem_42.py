"""Probes of problem 42: the two event functions of the thrown ball, the flight, and the computation behind the key
of question (b)."""

import numpy as np

from . import module, probe


def _attribute(function, name):
    value = getattr(function, name, None)
    if value is None:
        return None
    return bool(value) if name == "terminal" else float(value)


@probe
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


@probe
def throw(pkg, v0, drag):
    """``throw(v0, drag)``: the apex and the landing, and the run ``t``, ``y`` (rows ``(height, velocity)``)."""
    run = module(pkg, "problem_42").throw(float(v0), float(drag))
    if not isinstance(run, dict):
        raise ValueError(f"throw must return a dict, got {str(run)[:200]}")
    t = np.asarray(run.get("t"), dtype=float).reshape(-1)
    y = np.asarray(run.get("y"), dtype=float)
    if y.shape != (t.size, 2):
        raise ValueError(f"throw: 'y' must have one row (height, velocity) per time ({t.size} x 2), got shape "
                         f"{y.shape}")
    return {key: _optional(run.get(key)) for key in ("t_apex", "height_apex", "t_land", "v_land")} | {"t": t, "y": y}


@probe
def key(pkg):
    """``{"b"}``: the key of (b), computed by the package's reference-only function (called on the reference
    only)."""
    return {"b": int(module(pkg, "problem_42").answer_b())}
