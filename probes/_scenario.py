"""Stateful scenarios: build objects of the package, drive them through method calls, read their state back.

A scenario is plain data, so the whole loop, however long, runs inside one probe call:

``objects``  ``[(name, "module.Class", {keyword: value}), ...]``, built in order; a value ``"@name"`` stands for an
             object built before (e.g. the coordinate system of a bound vector).
``steps``    ``[("name.method", [args]), ...]``, applied in order ``repeat`` times; ``"@name"`` args as above.
``read``     ``[(label, "name.attribute"), (label, "name.method", [args]), ...]``, read once at the end.
``trace``    the same as ``read``, recorded before the first repetition, after every ``every``-th one and after
             the last.

``run`` returns ``{"final": {label: value}, "trace": {label: array}, "step": array}``: ``step[i]`` is the number of
repetitions done when sample ``i`` of the traces was taken.  Lists of numbers are passed to methods as float
arrays; values read back are copied, never returned as the package's own objects.
"""

import numpy as np

from . import module, probe
from ._forms import ANY, Arr, Dict, Items

__all__ = ["run", "body_run", "BODY_ROLES"]

#: the roles of a rigid body's state (a probe's ``state`` argument) for the diagnosis engine's declarations
BODY_ROLES = {"A_IB": "rotation", "B_r_IB": "vector", "B_v_B": "vector", "B_a_B": "vector", "B_omega_B": "vector",
              "B_omegaDot_B": "vector"}


def _value(value, objects):
    if isinstance(value, str) and value.startswith("@"):
        return objects[value[1:]]
    if isinstance(value, list) and value and all(isinstance(x, (int, float)) for x in value):
        return np.asarray(value, dtype=float)
    return value


def _build(pkg, objects):
    built = {}
    for name, cls, kwargs in objects:
        module_name, _, class_name = cls.rpartition(".")
        factory = getattr(module(pkg, module_name), class_name)
        built[name] = factory(**{k: _value(v, built) for k, v in kwargs.items()})
    return built


def _bind(target, built):
    name, _, attribute = target.partition(".")
    return built[name], attribute


def _reader(spec, built):
    label, target, *args = spec
    obj, attribute = _bind(target, built)
    if not args:
        return label, lambda: getattr(obj, attribute)
    call_args = [_value(a, built) for a in args[0]]
    return label, lambda: getattr(obj, attribute)(*call_args)


def _plain(value):
    if isinstance(value, tuple):
        return [_plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return value.copy()
    return value


def _sample(label, value):
    try:
        return np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{label} must be numeric, got {str(value)[:200]}") from None


def _stack(label, values):
    shapes = {v.shape for v in values}
    if len(shapes) > 1:
        raise ValueError(f"{label} changed its shape during the run: {sorted(shapes)}")
    return np.array(values)


@probe(returns=Dict({"final": Items(ANY), "trace": Items(Arr(any_shape=True, finite=False)), "step": Arr(None)}))
def run(pkg, objects, steps=(), repeat=1, read=(), trace=(), every=1):
    """Build ``objects``, apply ``steps`` ``repeat`` times, and return the reads and traces (see the module)."""
    built = _build(pkg, objects)
    calls = []
    for target, args in steps:
        obj, method = _bind(target, built)
        calls.append((getattr(obj, method), [_value(a, built) for a in args]))
    tracers = [_reader(spec, built) for spec in trace]
    samples = {label: [] for label, _ in tracers}
    taken = []

    def record(done):
        taken.append(done)
        for label, get in tracers:
            samples[label].append(_sample(label, get()))

    if tracers:
        record(0)
    for i in range(1, repeat + 1):
        for method, args in calls:
            method(*args)
        if tracers and (i % every == 0 or i == repeat):
            record(i)
    final = {label: _plain(get()) for label, get in (_reader(spec, built) for spec in read)}
    traces = {label: _stack(label, values) for label, values in samples.items()}
    return {"final": final, "trace": traces, "step": np.array(taken, dtype=float)}


def body_run(pkg, cls, state, steps, repeat=1, read=(), trace=(), every=1):
    """``run`` for a single object named ``body`` of class ``cls`` built from the keyword arguments ``state``;
    ``steps`` are ``(method, [args])`` and ``read``/``trace`` are ``(label, attribute)`` or
    ``(label, method, [args])`` of that body."""
    return run(
        pkg,
        [("body", cls, state)],
        [(f"body.{method}", args) for method, args in steps],
        repeat,
        [(label, f"body.{target}", *rest) for label, target, *rest in read],
        [(label, f"body.{target}", *rest) for label, target, *rest in trace],
        every,
    )
