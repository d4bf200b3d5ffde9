"""Probes of side effects: what one call's outputs cannot show.

A function later problems reuse must leave its caller's arrays alone and must not keep state between calls.  These
probes call a function of the package on copies of the arguments, on a second input, and on the first input again,
and return what they saw as plain data; ``checks/_effects.py`` judges it.
"""

import copy

import numpy as np

from . import module, probe
from ._forms import ANY, Dict, Seq

__all__ = ["calls", "snapshot", "fresh_copies"]


def snapshot(value):
    """A deep copy of a call's result, as plain data where it is numeric (an unusable result is left to the
    check of the function's values)."""
    try:
        return copy.deepcopy(value)
    except Exception:  # noqa: BLE001
        return None


def fresh_copies(args):
    """Fresh copies of the arguments (lists as numpy arrays where the function is given arrays)."""
    return [np.array(a, dtype=float) if isinstance(a, (list, np.ndarray)) else copy.deepcopy(a) for a in args]


@probe(returns=Dict({"first": ANY, "first_later": ANY, "again": ANY, "args_after": Seq(ANY)}), says="{0}.{1}")
def calls(pkg, module_name, function, first, second):
    """``module.function(*first)``, then ``(*second)``, then ``(*first)`` again, each on fresh copies:

    ``{"first": the first result (copied at once), "first_later": the first result object after the second call,
    "again": the result of the repeated call, "args_after": the first call's arguments after it returned}``."""
    func = getattr(module(pkg, module_name), function)
    args = fresh_copies(first)
    result = func(*args)
    at_first = snapshot(result)
    args_after = snapshot(args)
    func(*fresh_copies(second))
    first_later = snapshot(result)
    again = func(*fresh_copies(first))
    return {"first": at_first, "first_later": first_later, "again": snapshot(again), "args_after": args_after}
