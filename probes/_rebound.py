"""A call with some of a problem module's named constants bound to other values for its duration.

A function that reads its problem's constants (the sheet's angles, lengths, masses) rather than taking them as
arguments has one input only; ``rebound`` runs a probe while ``bindings`` (``[[module, name, value], ...]``: a
constant of a module of the package, a number or a row of numbers, and its value) hold, and puts the constants back
afterwards, so that the same call gives the value at other constants.  A row is bound in the kind it had (a tuple, a
list or an array).  It runs the same way on the reference and on a student's package;
a constant the package's module does not define is set for the call and removed afterwards.
"""

import numpy as np

from . import fresh, lookup, module, probe
from ._forms import ByArgs

__all__ = ["rebound", "constants"]

_MISSING = object()


def _form(name, bindings, args):
    """The form of the reply of the probe ``name`` (``rebound``'s reply is that probe's)."""
    return lookup(name).returns


@probe(returns=ByArgs(_form), says="{0} at other constants")
def rebound(pkg, name, bindings, args):
    """``name(*args)`` on the package with the constants of ``bindings`` bound to their values (made anew:
    ``probes.fresh``, alone: nothing computed at the sheet's constants is reused, not even for one code of the
    package on several inputs)."""
    inner = lookup(name)
    kept = []
    try:
        for module_name, constant, value in bindings:
            target = module(pkg, module_name)
            before = getattr(target, constant, _MISSING)
            kept.append((target, constant, before))
            setattr(target, constant, _like(before, value))
        with fresh(alone=True):
            return inner(pkg, *args)
    finally:
        for target, constant, before in reversed(kept):
            if before is _MISSING:
                delattr(target, constant)
            else:
                setattr(target, constant, before)


def _like(before, value):
    """``value`` (a number or a list of numbers) in the kind of the constant it replaces."""
    if not isinstance(value, (list, tuple)):
        return float(value)
    row = [float(x) for x in value]
    if isinstance(before, tuple):
        return tuple(row)
    if isinstance(before, list):
        return row
    return np.array(row, dtype=float)


@probe(returns=None, reference_only=True)
def constants(pkg, module_name, names):
    """The reference's values of the named constants of a module (``{name: value}``): a number as a float, a row
    of numbers (a tuple, a list, an array of one dimension) as a list of floats; any other is left out."""
    target = module(pkg, module_name)
    found = {}
    for name in names:
        value = getattr(target, name, None)
        if isinstance(value, (bool, str)) or value is None:
            continue
        try:
            array = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            continue
        if array.ndim == 0:
            found[name] = float(array)
        elif array.ndim == 1 and array.size:
            found[name] = [float(x) for x in array]
    return found
