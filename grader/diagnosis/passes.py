"""Passes of state that the calls of many mutants repeat alike, computed once.

A kinematic tree's forward kinematics sets every body's pose, velocities, accelerations and Jacobians; a mutant of
a function the pass does not run (a body's share of ``M, f, g``, a constraint's terms read from the end effector)
runs it again on a tree built alike at the same coordinates, and it is most of what the mutant's call costs.
Within ``Shared.around(holder)``, for the mutants of one explanation's pass (``mutants._evaluate``), each declared
pass (``PASSES``) on a tree and arguments seen before sets the attributes it set then (copies of its arrays), where
none of the code it ran then has another code now (a mutant's, in its function's place); else it runs as it is,
and what it did is kept where it ran only the reference's code.

The effect kept is exact: the pass is keyed by the pickled tree (its structure, data and the state it holds before
the pass) and arguments, the code it ran is traced, and a pass that changes anything beyond the attributes of the
tree, its bodies and its joints, or that returns anything but the tree, is not kept.  Nothing is kept from one
explanation to the next: a grading's cost is its own."""

from __future__ import annotations

import contextlib
import pickle
import sys
from dataclasses import dataclass

import numpy as np

__all__ = ["PASSES", "MAX_KEPT", "MISSES_TRIED", "Shared"]

#: the passes kept: ``(module, class, method)`` of the private package; the method's ``self`` holds the objects it
#: updates (``bodies``, ``joints``) and it returns ``self``
PASSES = (("tree", "KinematicTree", "forward_kinematics"),)
#: the most passes kept for one explanation
MAX_KEPT = 256
#: the passes run as they are (keyed, traced, none set again) before sharing is weighed by what it saved
MISSES_TRIED = 16
#: the attribute values a kept pass may set: copied where they are arrays
_PLAIN = (type(None), bool, int, float, str, np.ndarray, np.floating, np.integer)


@dataclass(frozen=True)
class _Kept:
    ran: frozenset  # the code objects the pass ran
    effects: tuple  # ``(index of the object, attribute, value)``


class Shared:
    """The passes kept for one explanation's mutants; ``originals`` (``mutants._evaluate``'s) holds the original
    code of every function whose code a mutant changes."""

    def __init__(self, package, originals: dict, root: str):
        self.package, self.originals, self.root = package, originals, root
        self.kept: dict = {}
        self.hits = self.misses = 0
        self.reaching: set = set()  # the original codes a pass has been seen to run

    def _classes(self) -> list:
        found = []
        for module_name, class_name, method in PASSES:
            module = sys.modules.get(f"{self.package.__name__}.{module_name}")
            cls = getattr(module, class_name, None) if module is not None else None
            function = vars(cls).get(method) if isinstance(cls, type) else None
            if callable(function):
                found.append((cls, method, function))
        return found

    @contextlib.contextmanager
    def around(self, holder):
        """Within: the passes shared, unless ``holder`` (the function whose code the mutant changes) is one of
        them or a pass has been seen to run its code (its mutants run the pass as it is, without the cost of keying
        and tracing it), or the passes are seldom met alike (``_worth``)."""
        installed = []
        original = self.originals.get(id(holder), (None, None))[1] if holder is not None else None
        try:
            for cls, method, function in self._classes() if original not in self.reaching and self._worth() else ():
                if function is not holder:
                    # kept as a constant's binding is: ``mutants._restore`` puts it back after the deadline, where
                    # the deadline's interruption cut this block's own restoring short
                    self.originals.setdefault((id(cls), method), (cls, method, function))
                    setattr(cls, method, self._wrapped(function))
                    installed.append((cls, method, function))
            yield
        finally:
            for cls, method, function in installed:
                setattr(cls, method, function)

    def _worth(self) -> bool:
        """Whether keying and tracing the passes pays: after ``MISSES_TRIED`` passes run as they are, only where
        at least as many were set again."""
        return self.misses < MISSES_TRIED or self.hits >= self.misses

    def _changed(self) -> set:
        """The original codes of the functions that run another code now."""
        return {kept[1] for kept in self.originals.values() if len(kept) == 2 and kept[0].__code__ is not kept[1]}

    def _wrapped(self, function):
        shared = self

        def kept_pass(tree, *args, **kwargs):
            return shared._run(function, tree, args, kwargs)

        kept_pass.__wrapped__ = function
        return kept_pass

    def _run(self, function, tree, args, kwargs):
        try:
            key = pickle.dumps((tree, args, sorted(kwargs.items())), protocol=pickle.HIGHEST_PROTOCOL)
        except Exception:  # noqa: BLE001 - a tree or arguments that cannot be pickled: the pass as it is
            return function(tree, *args, **kwargs)
        kept = self.kept.get(key)
        if kept is not None and not (kept.ran & self._changed()):
            objects = _objects(tree)
            if objects is not None:
                self.hits += 1
                copies: dict = {}  # an array set on two attributes is one array again
                for index, attribute, value in kept.effects:
                    if isinstance(value, np.ndarray):
                        value = copies.setdefault(id(value), value.copy())
                    setattr(objects[index], attribute, value)
                return tree
        return self._measured(function, tree, args, kwargs, key)

    def _measured(self, function, tree, args, kwargs, key):
        """The pass run as it is, traced, and kept where it ran only the reference's code and did what a kept pass
        may do."""
        objects = _objects(tree)
        before = None if objects is None else [_state(obj) for obj in objects]
        seen: set = set()
        prefix = self.root
        previous = sys.getprofile()

        def profile(frame, event, arg):
            if event == "call" and frame.f_code.co_filename.startswith(prefix):
                seen.add(frame.f_code)
            if previous is not None:
                previous(frame, event, arg)

        sys.setprofile(profile)
        try:
            result = function(tree, *args, **kwargs)
        finally:
            sys.setprofile(previous)
        self.misses += 1
        swapped = {kept[0].__code__: kept[1] for kept in self.originals.values()
                   if len(kept) == 2 and kept[0].__code__ is not kept[1]}
        self.reaching |= {swapped.get(code, code) for code in seen}
        if before is None or result is not tree or seen & set(swapped) or len(self.kept) >= MAX_KEPT:
            return result
        effects = _effects(objects, before)
        after = _objects(tree)
        if effects is not None and after is not None and len(after) == len(objects) \
                and all(a is b for a, b in zip(after, objects)):
            self.kept[key] = _Kept(frozenset(seen), effects)
        return result


def _objects(tree) -> list | None:
    """The tree, its bodies and its joints, in their order, or None where it holds no such lists."""
    bodies, joints = getattr(tree, "bodies", None), getattr(tree, "joints", None)
    if not isinstance(bodies, list) or not isinstance(joints, list):
        return None
    return [tree, *bodies, *joints]


def _state(obj) -> dict:
    """An object's attributes, each with a copy of it where it is an array or a container (a pass may write into
    one in place)."""
    return {k: (v, v.copy() if isinstance(v, (np.ndarray, list, dict, set)) else None) for k, v in vars(obj).items()}


def _same(copy, value) -> bool:
    """An array or container as it was (``copy``): equal entries, the same items."""
    if isinstance(value, np.ndarray):
        try:
            return copy.shape == value.shape and np.array_equal(copy, value, equal_nan=value.dtype.kind in "fc")
        except TypeError:  # entries that do not compare: taken as changed
            return False
    if isinstance(value, dict):
        return copy.keys() == value.keys() and all(copy[k] is value[k] for k in value)
    if isinstance(value, set):
        return copy == value
    return len(copy) == len(value) and all(a is b for a, b in zip(copy, value))


def _effects(objects: list, before: list) -> tuple | None:
    """``(index, attribute, value)`` of every attribute the pass set or wrote into, copied; None where it removed
    one or set a value that is not plain (``_PLAIN``)."""
    effects, copies = [], {}
    for index, (obj, was) in enumerate(zip(objects, before)):
        now = vars(obj)
        if set(was) - set(now):
            return None
        for attribute, value in now.items():
            old = was.get(attribute)
            if old is not None and value is old[0] and (old[1] is None or _same(old[1], value)):
                continue
            if not isinstance(value, _PLAIN):  # an object, or a container set or written into: not kept
                return None
            if isinstance(value, np.ndarray):
                value = copies.setdefault(id(value), value.copy())
            effects.append((index, attribute, value))
    return tuple(effects)
