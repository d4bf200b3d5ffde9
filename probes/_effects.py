"""Probes of side effects: what one call's outputs cannot show.

A function later problems reuse must leave its caller's arrays alone and must not keep state between calls.  These
probes call a function of the package on copies of the arguments, on a second input, and on the first input again,
and return what they saw as plain data; ``checks/_effects.py`` judges it.
"""

import copy

import numpy as np

from . import module, probe

__all__ = ["calls", "tree_calls"]


def _snapshot(value):
    """A deep copy of a call's result, as plain data where it is numeric (an unusable result is left to the
    check of the function's values)."""
    try:
        return copy.deepcopy(value)
    except Exception:  # noqa: BLE001
        return None


def _arrays(args):
    """Fresh copies of the arguments (lists as numpy arrays where the function is given arrays)."""
    return [np.array(a, dtype=float) if isinstance(a, (list, np.ndarray)) else copy.deepcopy(a) for a in args]


@probe
def calls(pkg, module_name, function, first, second):
    """``module.function(*first)``, then ``(*second)``, then ``(*first)`` again, each on fresh copies:

    ``{"first": the first result (copied at once), "first_later": the first result object after the second call,
    "again": the result of the repeated call, "args_after": the first call's arguments after it returned}``."""
    func = getattr(module(pkg, module_name), function)
    args = _arrays(first)
    result = func(*args)
    snapshot = _snapshot(result)
    args_after = _snapshot(args)
    func(*_arrays(second))
    first_later = _snapshot(result)
    again = func(*_arrays(first))
    return {"first": snapshot, "first_later": first_later, "again": _snapshot(again), "args_after": args_after}


@probe
def tree_calls(pkg, description, first, second):
    """One tree of the described bodies, built once: ``forward_kinematics(*first)``, then ``(*second)``, then
    ``(*first)`` again (each a tuple ``(q[, qd, qdd])`` on fresh copies), and a fresh tree at ``second``:

    ``{"first", "second", "fresh_second", "again"}`` (the states, see ``_trees.state``) and ``"args_after"`` (the
    first call's arguments after it returned)."""
    from ._trees import build, state

    tree_module = module(pkg, "tree")
    tree = build(tree_module, description)
    motion = len(first) > 1
    args = _arrays(first)
    tree.forward_kinematics(*args)
    at_first = state(tree, motion)
    args_after = _snapshot(args)
    tree.forward_kinematics(*_arrays(second))
    at_second = state(tree, motion)
    fresh = build(tree_module, description)
    fresh.forward_kinematics(*_arrays(second))
    tree.forward_kinematics(*_arrays(first))
    return {"first": at_first, "second": at_second, "fresh_second": state(fresh, motion), "again": state(tree, motion),
            "args_after": args_after}
