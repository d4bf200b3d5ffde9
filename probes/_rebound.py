"""A call with some of a problem module's named constants bound to other values for its duration.

A function that reads its problem's constants (the sheet's angles, lengths, masses) rather than taking them as
arguments has one input only; ``rebound`` runs a probe while ``bindings`` (``[[module, name, value], ...]``: a
float constant of a module of the package and its value) hold, and puts the constants back afterwards, so that the
same call gives the value at other constants.  It runs the same way on the reference and on a student's package;
a constant the package's module does not define is set for the call and removed afterwards.
"""

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
    ``probes.fresh``, so that nothing computed at the sheet's constants is reused)."""
    inner = lookup(name)
    kept = []
    try:
        for module_name, constant, value in bindings:
            target = module(pkg, module_name)
            kept.append((target, constant, getattr(target, constant, _MISSING)))
            setattr(target, constant, float(value))
        with fresh():
            return inner(pkg, *args)
    finally:
        for target, constant, before in reversed(kept):
            if before is _MISSING:
                delattr(target, constant)
            else:
                setattr(target, constant, before)


@probe(returns=None, reference_only=True)
def constants(pkg, module_name, names):
    """The reference's values of the named float constants of a module (``{name: value}``; one not a number is
    left out)."""
    target = module(pkg, module_name)
    found = {}
    for name in names:
        value = getattr(target, name, None)
        try:
            found[name] = float(value)
        except (TypeError, ValueError):
            continue
    return found
