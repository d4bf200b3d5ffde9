"""One gate for every answer: each reply of the student's side is held to the form its probe declares
(``probes._forms``) before any check uses it.

A reply of the wrong form (a string where a number belongs, a list for a dict, a missing key, a matrix of the wrong
shape, NaN) is the student's error: the check fails with "cannot be graded: ..." and says where and what, never
with a crash of the check (an internal grader error, exit code 3).  A hostile worker can send any JSON at all; a
student's function can return anything; both meet the same gate.

Where the diagnosis engine is on, two shapes name a cause: a matrix of the transposed shape (a transpose), and a
list of values whose entries fit the form in one other order (``V, moments`` for ``moments, V``: two entries
exchanged).
"""

from __future__ import annotations

import itertools

from functools import lru_cache

import probes

from .checking import CheckFailure, engine_on, transposed_shape_hint
from .errors import GraderFault

__all__ = ["admit", "form_of", "describe_call", "probe_function", "GATE_PREFIX"]

#: how every failure of the gate begins
GATE_PREFIX = "cannot be graded: "


@lru_cache(maxsize=None)
def probe_function(probe):
    """The probe function of ``probe`` (its name, ``"problem_22.loop"``, or the function), on the grader's side; a
    name that is no probe is the grader's fault."""
    if callable(probe) and getattr(probe, "is_probe", False):
        return probe
    try:
        return probes.lookup(probe)
    except probes.ProbeLookupError as exc:
        raise GraderFault(f"the check names a probe that does not exist: {probe} ({exc})") from exc


def form_of(probe):
    """``(form, says)`` of a probe (its name or its function); a probe without a declared form, or one that reads
    the reference's own data, is the grader's defect when it is asked of a student."""
    func = probe_function(probe)
    name = probe if isinstance(probe, str) else f"{(func.__module__ or '').removeprefix('probes.')}.{func.__name__}"
    if getattr(func, "reference_only", False):
        raise GraderFault(f"the probe {name} reads the reference's own data and is never run on a submission")
    form = getattr(func, "returns", None)
    if form is None:
        raise GraderFault(f"the probe {name} declares no form for its reply (@probe(returns=...))")
    return form, getattr(func, "says", "") or ""


def _short(value) -> str:
    import numpy as np

    if isinstance(value, bool) or value is None:
        return repr(value)
    if isinstance(value, (int, float)):
        return f"{value:.6g}"
    if isinstance(value, str):
        return repr(value) if len(value) <= 40 else repr(value[:37] + "...")
    if isinstance(value, np.ndarray) and value.size <= 6 and value.dtype.kind in "iuf":
        return np.array2string(value.ravel(), precision=4, separator=", ") if value.ndim == 1 else f"array{value.shape}"
    if isinstance(value, np.ndarray):
        return f"array{value.shape}"
    if isinstance(value, (list, tuple)):
        return f"[{len(value)} entries]" if len(value) > 4 else "[" + ", ".join(_short(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{...}"
    return type(value).__name__


def describe_call(probe, args, says: str = "") -> str:
    """How a message names the call of ``probe``: its ``says`` with the arguments shown short, or the probe's own
    name with them."""
    shown = [_short(a) for a in args]
    if says:
        try:
            return says.format(*shown)
        except (IndexError, KeyError, ValueError):
            pass
    name = probe if isinstance(probe, str) else getattr(probe, "__name__", str(probe))
    return f"{name.rpartition('.')[2]}({', '.join(shown)})"


def admit(probe, args: tuple, value):
    """``value`` (the decoded reply of the student's side to ``probe(*args)``) if it has the probe's form; else a
    ``CheckFailure`` that says it cannot be graded, where and why."""
    form, says = form_of(probe)
    fault = form.fault(value, args)
    if fault is None:
        return value
    where = describe_call(probe, args, says)
    subject = f"{where}{fault.path}" if fault.path else where
    if fault.transposed and engine_on():  # the transposed shape: one of the diagnosis engine's slips
        raise CheckFailure(f"{GATE_PREFIX}{subject} {fault.text}: the transposed shape.",
                           transposed_shape_hint(fault.transposed), "transpose", None)
    order = in_another_order(form, value, args) if engine_on() else None
    if order is not None:  # ``V, moments`` returned where ``moments, V`` belongs
        moved = ", ".join(f"your entry {i + 1} has the form of entry {k + 1}" for k, i in enumerate(order) if i != k)
        raise CheckFailure(f"{GATE_PREFIX}{subject} {fault.text}: the values in another order.",
                           f"Looks like your function returns its values in another order ({moved}): "
                           "return them in the order asked.", "swapped", None)
    raise CheckFailure(f"{GATE_PREFIX}{subject} {fault.text}.", fault.hint, fault.diagnosis, None)


#: the entries of a sequence, at most, whose order is sought (a longer reply, a hostile one of millions, fails as a
#: shape alone: each entry costs up to 24 tries of its form)
ORDER_ENTRIES = 64


def in_another_order(form, value, args=()) -> tuple | None:
    """Where ``value`` fails ``form`` but its entries in another order fit it, that order (``order[k]``: the entry
    of ``value`` in place ``k``); else None.  The entries are those of a list of two to four (a ``Tup``) or the values
    of a dict under its two to four keys (a ``Dict``: ``qdd`` and ``lam`` given each other's values); in a ``Seq`` of
    such, the one order that mends every entry of it that fails.  One order only: where several fit (two entries of
    one form), the form cannot tell which was meant."""
    from probes._forms import Dict, Seq, Tup

    if isinstance(form, Seq) and isinstance(value, list) and 0 < len(value) <= ORDER_ENTRIES:
        orders = {in_another_order(form.item, item, args) for item in value if form.item.fault(item, args) is not None}
        return orders.pop() if len(orders) == 1 else None
    if isinstance(form, Tup) and isinstance(value, list) and 2 <= len(value) == len(form.forms) <= 4:
        entries, fits = value, lambda moved: form.fault(moved, args) is None
    elif isinstance(form, Dict) and isinstance(value, dict) and 2 <= len(value) <= 4 \
            and set(value) == set(form.fields):
        keys = list(form.fields)
        entries = [value[key] for key in keys]
        fits = lambda moved: form.fault(dict(zip(keys, moved)), args) is None  # noqa: E731
    else:
        return None
    own = tuple(range(len(entries)))
    fitting = [order for order in itertools.permutations(own) if order != own and fits([entries[k] for k in order])]
    return fitting[0] if len(fitting) == 1 else None
