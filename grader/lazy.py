"""Names of a package imported when first used, so that ``grade`` starts without importing the machinery (numpy,
the checks, the batch grader) that the command at hand does not need."""

from __future__ import annotations

import importlib
from typing import Any, Callable

__all__ = ["lazy_names"]


def lazy_names(package: str, where: dict[str, str], namespace: dict[str, Any]) -> Callable[[str], Any]:
    """A module ``__getattr__`` for ``package``: the name ``n`` is read from the submodule ``where[n]`` when first
    used, then kept in ``namespace`` (the package's globals) so that it is looked up only once."""

    def __getattr__(name: str):
        module = where.get(name)
        if module is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(f"{package}.{module}"), name)
        namespace[name] = value
        return value

    return __getattr__
