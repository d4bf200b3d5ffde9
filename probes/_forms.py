"""The forms of probe replies: what the answer of a probe must look like before a check may use it.

Every probe declares the form of its reply (``@probe(returns=Arr(3, 3))``).  The grader holds each reply of the
student's side to that form before any check sees it (``grader.gate``): the types, the keys of a dict, the shapes
of arrays, finite numbers.  A reply of the wrong form is the student's error ("cannot be graded: ..."), never a
crash of the check.  A form only describes; it runs in the grader and imports nothing of it.

``fault(value, args)`` returns ``None`` when ``value`` has the form, else a ``Fault`` naming where (a path into the
reply such as ``["bodies"][2]["A_IB"]``) and what is wrong.  ``args`` are the probe's arguments, for dimensions that
depend on them (``Arr(3, lambda q, *_: len(q))``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["Fault", "Form", "Num", "Arr", "Text", "Flag", "Dict", "Items", "Seq", "Tup", "Maybe", "Either", "ByArgs",
           "ANY"]


@dataclass(frozen=True)
class Fault:
    """What is wrong with a reply: ``path`` into it ("" for the whole reply), ``text`` (completes "... must be"
    or "... is"), the ``diagnosis`` ("shape", "none", "not_finite" or "") and a ``hint``; ``transposed``: a
    matrix of the transposed shape of a fixed one that is not square (the gate may tell it as a transpose)."""

    path: str
    text: str
    diagnosis: str = ""
    hint: str = ""
    transposed: tuple = ()

    def within(self, step: str) -> "Fault":
        return Fault(step + self.path, self.text, self.diagnosis, self.hint, self.transposed)


def _shown(value) -> str:
    """A short description of a value that has the wrong form (its text as the student's code made it: a report
    shows its control characters escaped)."""
    kind = type(value).__name__
    text = str(value)
    return f"a value of type {kind}: {text[:120]}{'...' if len(text) > 120 else ''}"


def _dim(dim, args):
    return dim(*args) if callable(dim) else dim


class Form:
    """The form of a reply (or a part of one)."""

    def fault(self, value, args=()) -> Fault | None:
        raise NotImplementedError

    def describe(self) -> str:
        raise NotImplementedError


def _is_number(x) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


class Num(Form):
    """A real number (an int or a float, not a bool; a 0-d array too).  ``finite``: NaN and infinities fail."""

    def __init__(self, finite: bool = True):
        self.finite = finite

    def describe(self) -> str:
        return "a finite number" if self.finite else "a number"

    def fault(self, value, args=()):
        if value is None:
            return Fault("", "is None: the function returned nothing", "none", "Did you forget a return statement?")
        if type(value).__module__ == "numpy" and getattr(value, "shape", None) == () and value.dtype.kind in "iuf":
            value = value.item()
        if not _is_number(value):
            return Fault("", f"must be a number, got {_shown(value)}")
        if self.finite and not math.isfinite(value):
            return Fault("", f"must be a finite number, got {value!r}", "not_finite")
        return None


def _numeric_leaves(value, depth=0) -> bool:
    """True when ``value`` is a number or nested lists of numbers (no bools, no text, no None)."""
    if _is_number(value):
        return True
    if isinstance(value, list) and depth < 8:
        return all(_numeric_leaves(x, depth + 1) for x in value)
    return False


class Arr(Form):
    """A numeric array of the given shape: a float array as the codec returns it, nested lists of numbers or, for
    shape ``()``, a number.  A dimension is an int, ``None`` (any length) or a function of the probe's arguments.
    ``Arr()`` with no dimensions at all: any shape (``ndim`` fixes only the number of dimensions).  ``finite``:
    NaN and infinities fail."""

    def __init__(self, *dims, ndim: int | None = None, finite: bool = True, any_shape: bool = False):
        self.dims = dims
        self.ndim = ndim
        self.finite = finite
        self.any_shape = any_shape or (not dims and ndim is None)

    def describe(self) -> str:
        if self.any_shape:
            return "a numeric array"
        if not self.dims:
            return f"a numeric array of {self.ndim} dimensions"
        dims = ", ".join("n" if d is None or callable(d) else str(d) for d in self.dims)
        return f"a numeric array of shape ({dims}{',' if len(self.dims) == 1 else ''})"

    def fault(self, value, args=()):
        import numpy as np

        if value is None:
            return Fault("", "is None: the function returned nothing", "none", "Did you forget a return statement?")
        if isinstance(value, np.ndarray):
            if value.dtype.kind not in "iuf":
                return Fault("", f"must be numeric, got an array with entries that are not numbers: "
                                 f"{str(value.ravel()[:6].tolist())[:120]}")
            array = value
        elif _numeric_leaves(value):
            try:
                array = np.asarray(value, dtype=float)
            except ValueError:  # ragged lists
                return Fault("", f"must be {self.describe()}, got lists of unequal lengths: {str(value)[:120]}",
                             "shape")
        else:
            return Fault("", f"must be numeric, got {_shown(value)}")
        if not self.any_shape:
            if self.dims:
                expected = tuple(_dim(d, args) for d in self.dims)
                same = len(expected) == array.ndim and all(d is None or d == n for d, n in zip(expected, array.shape))
                if not same:
                    shown = tuple("n" if d is None else d for d in expected)
                    hint = ""
                    if None not in expected and array.size == math.prod(expected):
                        hint = f"Reshape it, e.g. np.reshape(x, {expected})."
                    transposed = (expected if len(expected) == 2 and None not in expected
                                  and expected[0] != expected[1] and array.shape == expected[::-1] else ())
                    return Fault("", f"must have shape {shown}, got shape {array.shape}", "shape", hint, transposed)
            elif array.ndim != self.ndim:
                return Fault("", f"must be an array of {self.ndim} dimensions, got shape {array.shape}", "shape")
        if self.finite and not bool(np.all(np.isfinite(array))):
            return Fault("", "contains NaN or infinite entries", "not_finite")
        return None


class Text(Form):
    """A string."""

    def describe(self) -> str:
        return "text"

    def fault(self, value, args=()):
        return None if isinstance(value, str) else Fault("", f"must be text, got {_shown(value)}")


class Flag(Form):
    """``True`` or ``False``."""

    def describe(self) -> str:
        return "True or False"

    def fault(self, value, args=()):
        return None if isinstance(value, bool) else Fault("", f"must be True or False, got {_shown(value)}")


class Dict(Form):
    """A dict holding at least ``fields`` (key → form); keys in ``optional`` may be absent.  Other keys are not
    looked at (no check reads them)."""

    def __init__(self, fields: dict, optional=()):
        self.fields = dict(fields)
        self.optional = frozenset(optional)

    def describe(self) -> str:
        return f"a dict with the keys {sorted(k for k in self.fields if k not in self.optional)}"

    def fault(self, value, args=()):
        if not isinstance(value, dict):
            return Fault("", f"must be {self.describe()}, got {_shown(value)}", "shape")
        missing = [k for k in self.fields if k not in value and k not in self.optional]
        if missing:
            return Fault("", f"has no entries {missing} (it has {sorted(map(str, value))[:20]})", "shape")
        for key, form in self.fields.items():
            if key in value:
                found = form.fault(value[key], args)
                if found is not None:
                    return found.within(f"[{key!r}]")
        return None


class Items(Form):
    """A dict of any number of entries, each of ``form`` (keys are text: the codec sends them so)."""

    def __init__(self, form: Form):
        self.form = form

    def describe(self) -> str:
        return f"a dict of {self.form.describe()}"

    def fault(self, value, args=()):
        if not isinstance(value, dict):
            return Fault("", f"must be {self.describe()}, got {_shown(value)}", "shape")
        for key, item in value.items():
            found = self.form.fault(item, args)
            if found is not None:
                return found.within(f"[{key!r}]")
        return None


class Seq(Form):
    """A list of entries of ``item``'s form; ``length``: exactly that many (an int or a function of the probe's
    arguments), ``None`` any number (the check says how many it needs)."""

    def __init__(self, item: Form, length=None):
        self.item = item
        self.length = length

    def describe(self) -> str:
        return "a list" if self.length is None or callable(self.length) else f"a list of {self.length} entries"

    def fault(self, value, args=()):
        if not isinstance(value, list):
            return Fault("", f"must be {self.describe()}, got {_shown(value)}", "shape")
        length = _dim(self.length, args)
        if length is not None and len(value) != length:
            return Fault("", f"must have {length} entries, got {len(value)}", "shape")
        for index, item in enumerate(value):
            found = self.item.fault(item, args)
            if found is not None:
                return found.within(f"[{index}]")
        return None


class Tup(Form):
    """A list of exactly ``len(forms)`` entries, each of its own form (a tuple comes back from the child as a
    list)."""

    def __init__(self, *forms: Form):
        self.forms = forms

    def describe(self) -> str:
        return f"a list of {len(self.forms)} entries"

    def fault(self, value, args=()):
        if not isinstance(value, list):
            return Fault("", f"must be {self.describe()}, got {_shown(value)}", "shape")
        if len(value) != len(self.forms):
            return Fault("", f"must have {len(self.forms)} entries, got {len(value)}", "shape")
        for index, (item, form) in enumerate(zip(value, self.forms)):
            found = form.fault(item, args)
            if found is not None:
                return found.within(f"[{index}]")
        return None


class Maybe(Form):
    """``None`` or ``form`` (a value the probe leaves out when the student's function cannot give it)."""

    def __init__(self, form: Form):
        self.form = form

    def describe(self) -> str:
        return f"None or {self.form.describe()}"

    def fault(self, value, args=()):
        return None if value is None else self.form.fault(value, args)


class Either(Form):
    """One of ``forms``; when none fits, the fault of the last (write the answer's own form last, after the
    replies that say why there is none, such as ``{"error": ...}``)."""

    def __init__(self, *forms: Form):
        self.forms = forms

    def describe(self) -> str:
        return " or ".join(form.describe() for form in self.forms)

    def fault(self, value, args=()):
        faults = [form.fault(value, args) for form in self.forms]
        return None if any(f is None for f in faults) else faults[-1]


class ByArgs(Form):
    """The form that ``choose(*args)`` gives for the probe's arguments (a probe whose reply depends on which
    function it calls)."""

    def __init__(self, choose):
        self.choose = choose

    def describe(self) -> str:
        return "the form its arguments call for"

    def fault(self, value, args=()):
        return self.choose(*args).fault(value, args)


class _Anything(Form):
    """Any plain data: the check itself looks at it (text answers, values compared by the check's own rules)."""

    def describe(self) -> str:
        return "any value"

    def fault(self, value, args=()):
        return None


#: any plain data (use where the check itself holds the value to its form)
ANY = _Anything()
