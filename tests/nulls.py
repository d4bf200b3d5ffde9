"""Null submissions: the reference with every numeric result of its public API replaced by zeros, by ones or by a
constant, keeping shapes and container structure.

``build_null(dest, fill)`` copies the reference and appends to each of its modules a few lines that, once the
module has run, replace every public function (its ``__all__``) by a wrapper that maps the function's result to
``fill``: floats, float arrays and complex numbers become ``fill``; dicts, lists, tuples (named ones included)
keep their keys and lengths and have their entries mapped; symbolic expressions (sympy) become the constant;
a returned function is wrapped the same way.  Public classes of the module have every public attribute read
mapped likewise (``__getattribute__``), so that state a method stores (a tree's ``A_IB`` after forward
kinematics) reads as the constant and methods return it.  Integers, booleans, strings (MJCF text), ``None`` and
other objects are kept: they are structure (counts, indices, links, text), not computed numbers.  The package's
``answers.toml`` (multiple choice, predicted output) is the reference's.

Every numeric answer of such a submission is worth nothing; only checks that see no number of the student's
changed by the mapping (answers read from ``answers.toml``, a model built from unchanged MJCF text) may pass.
"""

from __future__ import annotations

from pathlib import Path

from .submissions import copy_reference

__all__ = ["FILLS", "build_null", "NULL_TAIL"]

#: the null families: every numeric result zero, one, or one constant
FILLS = {"zeros": 0.0, "ones": 1.0, "constant": 0.5}

#: appended to every module of the package copy; ``FILL`` is the constant
NULL_TAIL = '''

# ---- null submission: every public result of this module mapped to FILL (tests/nulls.py) ----
def _null_module(namespace, fill):
    import functools
    import inspect

    import numpy

    def null(value):
        if value is None or isinstance(value, (bool, numpy.bool_, str, bytes, int, numpy.integer)):
            return value
        if isinstance(value, (float, complex, numpy.floating, numpy.complexfloating)):
            return type(value)(fill)
        if isinstance(value, numpy.ndarray):
            if value.dtype.kind in "fc":
                return numpy.full_like(value, fill)
            if value.dtype == object:
                return numpy.array([null(v) for v in value.ravel()], dtype=object).reshape(value.shape)
            return value
        if isinstance(value, dict):
            mapped = {k: null(v) for k, v in value.items()}
            if all(mapped[k] is v for k, v in value.items()):
                return value  # nothing numeric in it: the same object (a list of joints the caller appends to, say)
            return type(value)(mapped.items())
        if isinstance(value, (list, tuple)):
            mapped = [null(v) for v in value]
            if all(m is v for m, v in zip(mapped, value)):
                return value
            return type(value)(*mapped) if hasattr(value, "_fields") else type(value)(mapped)
        if type(value).__module__.split(".")[0] == "sympy":
            import sympy

            constant = sympy.nsimplify(fill)
            if hasattr(value, "applyfunc"):
                return value.applyfunc(lambda entry: constant)
            return constant
        if callable(value) and not isinstance(value, type):
            return wrap(value)
        return value

    def wrap(func):
        if getattr(func, "_null_wrapped", False):
            return func

        @functools.wraps(func)
        def wrapper(*args, **kwargs):
            return null(func(*args, **kwargs))

        wrapper._null_wrapped = True
        return wrapper

    def null_class(cls):
        original = cls.__getattribute__

        def __getattribute__(self, name):
            value = original(self, name)
            return value if name.startswith("_") else null(value)

        cls.__getattribute__ = __getattribute__

    for name in namespace.get("__all__", ()):
        obj = namespace.get(name)
        if inspect.isclass(obj):
            if obj.__module__ == namespace["__name__"] and not issubclass(obj, BaseException):
                null_class(obj)
        elif inspect.isfunction(obj):
            namespace[name] = wrap(obj)


_null_module(globals(), FILL)
del _null_module
'''


def build_null(dest: Path, fill: float) -> Path:
    """A copy of the reference at ``dest`` whose public functions and classes give ``fill`` for every number."""
    copy_reference(dest)
    for path in sorted(dest.glob("*.py")):
        text = path.read_text()
        if "__all__" in text:
            path.write_text(text + NULL_TAIL.replace("FILL", repr(fill)))
    return dest
