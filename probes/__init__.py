"""Probes: small functions that drive a package's API with plain inputs and return plain data.

A probe runs twice with the same arguments: in the sandboxed child on the student's package, and in the grader
on the reference.  Probes import nothing from ``reference``, ``checks`` or ``grader``; they receive the package
as their first argument.  Arguments and results are JSON-able data (numpy arrays are encoded by ``_codec``).
"""

import importlib

__all__ = ["probe", "module"]


def probe(func):
    """Mark ``func(package, *args)`` as callable from the grader."""
    func.is_probe = True
    return func


def module(package, name):
    """The submodule ``name`` of ``package`` (e.g. ``module(pkg, "rotations")``)."""
    return importlib.import_module(f"{package.__name__}.{name}")
