"""Which arguments of the student's functions the checks vary.

A grading of the reference records every call a check sends to the student's package (probe and arguments).  Each
call is then run again, in this process, on a copy of the reference whose functions and methods are wrapped: a
wrapper called directly from a probe (not from the package's own code) records the value each parameter took,
defaults filled in.  A parameter that took one value only over the whole grading is one no check varies: an
answer that ignores it loses nothing.
"""

from __future__ import annotations

import functools
import hashlib
import importlib
import inspect
import pkgutil
import shutil
import sys
from collections import defaultdict
from pathlib import Path

import numpy as np

from grader.gate import probe_function
from probes import call_key, name_of
from probes._codec import decode, encode

from .submissions import ROOT
from .wrapped import grade_wrapped

__all__ = ["ProbeCalls", "Recorder", "probe_calls", "instrumented", "parameter_values", "gaps"]

#: the package name of the instrumented copy of the reference
PACKAGE = "argument_audit"
#: digits a float keeps in a value's fingerprint
DIGITS = 9


class ProbeCalls:
    """A sandboxed child that passes every call on and remembers ``(probe, args)`` of each."""

    def __init__(self, child):
        self.child = child
        self.calls: list[tuple[str, tuple]] = []

    def call(self, probe, *args, timeout=None):
        self.calls.append((name_of(probe), args))
        return self.child.call(probe, *args, timeout=timeout)

    def output(self):
        return self.child.output()


def probe_calls(problem: int, reference: Path, zygote) -> list[tuple[str, tuple]]:
    """Every ``(probe, args)`` the checks of ``problem`` send to the student's package while ``reference`` (a copy
    of the reference) is graded (live reference, the suite's seed)."""
    results, recorder = grade_wrapped(problem, reference, zygote, ProbeCalls)
    failed = [r.check_id for r in results if not r.passed]
    assert not failed, f"the reference fails {failed}: its calls are no measure"
    return recorder.calls


def fingerprint(value, depth: int = 0) -> str:
    """A short text that is equal for equal values: numbers to ``DIGITS`` digits, containers by their items, a
    function by its name, a symbolic (sympy) value by its text, an object by its class, its ``name`` and (called
    with it directly) its public attributes, the objects among them by their class and name."""
    if value is None or isinstance(value, (bool, str)):
        return repr(value)
    if isinstance(value, (int, float, np.integer, np.floating)):
        return f"{float(value):.{DIGITS}g}"
    if isinstance(value, dict):
        return "{" + ",".join(f"{k!r}:{fingerprint(v, depth + 1)}" for k, v in sorted(value.items(), key=repr)) + "}"
    if isinstance(value, (list, tuple, np.ndarray)):
        try:
            array = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            return "[" + ",".join(fingerprint(v, depth + 1) for v in value) + "]"
        rounded = np.round(array, DIGITS) + 0.0
        return f"array{array.shape}:" + hashlib.sha256(rounded.tobytes()).hexdigest()[:16]
    if callable(value) and hasattr(value, "__qualname__"):
        return f"function {value.__qualname__}"
    if type(value).__module__.split(".")[0] == "sympy":
        return f"{type(value).__name__}:{value}"
    name = getattr(value, "name", None)
    label = f"{type(value).__name__}({name!r})" if isinstance(name, str) else type(value).__name__
    if depth > 0 or not hasattr(value, "__dict__"):
        return label
    attributes = {key: item for key, item in vars(value).items() if not key.startswith("_") and not callable(item)}
    return label + fingerprint(attributes, depth + 1)


class Recorder:
    """``values[function][parameter]``: the fingerprints of the values each parameter took in calls from a probe."""

    def __init__(self):
        self.values: dict[str, dict[str, set]] = defaultdict(lambda: defaultdict(set))

    def wrap(self, func, qualified: str, method: bool):
        try:
            signature = inspect.signature(func)
        except (TypeError, ValueError):
            return func
        skip = 1 if method else 0

        @functools.wraps(func)
        def recorded(*args, **kwargs):
            caller = sys._getframe(1).f_globals.get("__name__", "")
            if caller.split(".")[0] == "probes":
                try:
                    bound = signature.bind(*args, **kwargs)
                except TypeError:
                    bound = None
                if bound is not None:
                    bound.apply_defaults()
                    for name, value in list(bound.arguments.items())[skip:]:
                        self.values[qualified][name].add(fingerprint(value))
            return func(*args, **kwargs)

        return recorded


def _own(obj, module) -> bool:
    return getattr(obj, "__module__", None) == module.__name__


def instrumented(folder: Path, recorder: Recorder):
    """A copy of the reference imported as ``PACKAGE`` from ``folder``, every function and method of its modules
    wrapped by ``recorder`` (a name a module imports from another is wrapped there too)."""
    shutil.copytree(ROOT / "reference", folder / PACKAGE, ignore=shutil.ignore_patterns("__pycache__"))
    sys.path.insert(0, str(folder))
    package = importlib.import_module(PACKAGE)
    modules = [importlib.import_module(f"{PACKAGE}.{info.name}") for info in pkgutil.iter_modules(package.__path__)]
    wrapped = {}
    for module in modules:
        short = module.__name__.removeprefix(PACKAGE + ".")
        for name, obj in list(vars(module).items()):
            if inspect.isfunction(obj) and _own(obj, module):
                wrapped[id(obj)] = recorder.wrap(obj, f"{short}.{name}", method=False)
            elif inspect.isclass(obj) and _own(obj, module):
                for attr, member in list(vars(obj).items()):
                    if inspect.isfunction(member) and (not attr.startswith("__") or attr == "__init__"):
                        setattr(obj, attr, recorder.wrap(member, f"{short}.{name}.{attr}", method=True))
    for module in modules:
        for name, obj in list(vars(module).items()):
            if id(obj) in wrapped:
                setattr(module, name, wrapped[id(obj)])
    return package


def release(folder: Path) -> None:
    for name in [name for name in sys.modules if name.split(".")[0] == PACKAGE]:
        del sys.modules[name]
    if str(folder) in sys.path:
        sys.path.remove(str(folder))


def parameter_values(calls, folder: Path) -> dict[str, dict[str, set]]:
    """The values each parameter of the package's functions took when ``calls`` (``(probe, args)``, each distinct
    one once) run on an instrumented copy of the reference."""
    recorder = Recorder()
    package = instrumented(folder, recorder)
    try:
        seen = set()
        for probe, args in calls:
            key = call_key(probe, args)
            if key in seen:
                continue
            seen.add(key)
            try:
                probe_function(probe)(package, *decode(encode(list(args))))
            except Exception:  # noqa: BLE001 - a call meant to raise (an invalid input) still records its arguments
                pass
    finally:
        release(folder)
    return {function: dict(params) for function, params in recorder.values.items()}


def gaps(values: dict[str, dict[str, set]]) -> list[str]:
    """``"function:parameter"`` for every parameter that took one value only."""
    return sorted(f"{function}:{name}" for function, params in values.items() for name, seen in params.items()
                  if len(seen) < 2)
