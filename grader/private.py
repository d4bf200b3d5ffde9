"""A private import of the reference: the reference package imported afresh under a name of its own (``_carried_*``
for error carried forward, ``grader.upstream``; ``_mutated_reference`` for the diagnosis of formulas,
``grader.diagnosis.mutants``), so that its functions can be changed without touching the ``reference`` every
other check uses.  A finder on ``sys.meta_path`` finds the private package's modules in the reference's folder;
the package's owner may patch each module once its code has run."""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import importlib.util
import sys
import threading
from pathlib import Path

from .errors import GraderFault

__all__ = ["reference_root", "private_import", "drop_private", "close_private"]


class _Loader(importlib.abc.Loader):
    """The source loader of a module of a private package, which hands the module to its owner's ``patch`` once its
    code has run (a hybrid replaces the module's shared functions there, before any module that imports them from
    it continues)."""

    def __init__(self, loader, patch, name: str):
        self._loader = loader
        self._patch = patch
        self._name = name

    def create_module(self, spec):
        return self._loader.create_module(spec)

    def exec_module(self, module):
        self._loader.exec_module(module)
        if self._patch is not None:
            self._patch(self._name, module)

    def __getattr__(self, name):  # get_source, get_filename, ... for tracebacks
        return getattr(self._loader, name)


class _Finder(importlib.abc.MetaPathFinder):
    """Finds the modules of the private packages (a hybrid's ``_carried_*``) in the reference's folder."""

    def __init__(self):
        #: the private package's name -> ``(the reference's folder, patch(module_name, module) or None)``
        self.hybrids: dict[str, tuple] = {}
        self.lock = threading.Lock()

    def find_spec(self, fullname, path=None, target=None):
        prefix, dot, rest = fullname.partition(".")
        owner = self.hybrids.get(prefix)
        if owner is None or not dot or "." in rest:
            return None
        root, patch = owner
        spec = importlib.machinery.PathFinder.find_spec(fullname, [str(root)])
        if spec is None:
            return None
        spec.loader = _Loader(spec.loader, patch, rest)
        return spec


_FINDER = _Finder()


def _install() -> None:
    with _FINDER.lock:
        if _FINDER not in sys.meta_path:
            sys.meta_path.insert(0, _FINDER)


def reference_root(purpose: str) -> Path:
    """The folder of the installed reference package; its absence is the grader's fault (``purpose`` says what
    needs it)."""
    spec = importlib.util.find_spec("reference")
    if spec is None or not spec.submodule_search_locations:
        raise GraderFault(f"the reference solution is not installed: {purpose} needs it")
    return Path(list(spec.submodule_search_locations)[0])


def private_import(name: str, root: Path, patch=None):
    """A fresh import of the reference package in ``root`` under the private name ``name`` (a top-level name no
    other module uses); ``patch(module_name, module)`` sees each of its modules once its code has run."""
    _install()
    with _FINDER.lock:
        _FINDER.hybrids[name] = (root, patch)
    spec = importlib.util.spec_from_file_location(name, root / "__init__.py", submodule_search_locations=[str(root)])
    package = importlib.util.module_from_spec(spec)
    sys.modules[name] = package
    try:
        spec.loader.exec_module(package)
    except BaseException:
        drop_private(package)
        raise
    return package


def drop_private(package) -> None:
    """Forget a private import of the reference (its modules leave ``sys.modules``)."""
    name = package.__name__
    with _FINDER.lock:
        _FINDER.hybrids.pop(name, None)
    # a copy (one step under the interpreter's lock): other threads import while a problem graded beside them drops
    for module in [n for n in sys.modules.copy() if n == name or n.startswith(name + ".")]:
        sys.modules.pop(module, None)


def close_private(owner) -> None:
    """Forget the private packages whose ``patch`` is a method of ``owner`` (their modules stay where imported)."""
    with _FINDER.lock:
        for name in [n for n, (_, patch) in _FINDER.hybrids.items() if getattr(patch, "__self__", None) is owner]:
            _FINDER.hybrids.pop(name, None)
