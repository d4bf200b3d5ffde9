"""The one door to the oracle: no check module imports ``reference``.

Every value of the reference reaches a check through ``ctx.reference(probe, ...)``, so that the same checks run
against the live reference (instructor) or a recorded answer key (student kit, which holds no reference code).
The test parses every module under ``checks/`` and looks at every import anywhere in it, inside functions too.
"""

import ast
from pathlib import Path

import pytest

CHECKS = Path(__file__).resolve().parents[1] / "checks"

#: Modules allowed to import ``reference``: none. The test fails for an entry that no longer imports it, so a
#: stale entry cannot stay behind.
KNOWN_EXCEPTIONS: set[str] = set()

_IMPORTERS = {("importlib", "import_module"), (None, "import_module"), (None, "__import__"), ("resources", "files"),
              (None, "files")}


def _is_reference(name: str | None) -> bool:
    return bool(name) and name.split(".")[0] == "reference"


def reference_imports(source: str) -> list[str]:
    """``line: statement`` of every import of ``reference`` in ``source``: ``import reference...``, ``from
    reference... import ...`` and ``importlib.import_module("reference...")`` / ``__import__("reference...")``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            found += [f"{node.lineno}: import {alias.name}" for alias in node.names if _is_reference(alias.name)]
        elif isinstance(node, ast.ImportFrom):
            if node.level == 0 and _is_reference(node.module):
                found.append(f"{node.lineno}: from {node.module} import ...")
        elif isinstance(node, ast.Call) and node.args and isinstance(node.args[0], ast.Constant):
            func = node.func
            owner = func.value.id if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name) else None
            name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", None)
            target = node.args[0].value
            if (owner, name) in _IMPORTERS and isinstance(target, str) and _is_reference(target):
                found.append(f"{node.lineno}: {name}({target!r})")
    return found


MODULES = sorted(path.name for path in CHECKS.glob("*.py"))


def test_the_modules_are_found():
    assert "problem_22.py" in MODULES and "_trees.py" in MODULES


@pytest.mark.parametrize("name", MODULES)
def test_check_module_does_not_import_reference(name):
    found = reference_imports((CHECKS / name).read_text())
    if name in KNOWN_EXCEPTIONS:
        assert found, f"{name} no longer imports reference: remove it from KNOWN_EXCEPTIONS"
    else:
        assert not found, f"{name} imports reference (use ctx.reference with a probe):\n" + "\n".join(found)


@pytest.mark.parametrize("source, expected", [
    ("import reference\n", 1),
    ("import reference.tree as t\n", 1),
    ("def f():\n    from reference.problem_22 import D\n", 1),
    ("class C:\n    def m(self):\n        from reference import planar\n", 1),
    ("import importlib\nimportlib.import_module('reference.tree')\n", 1),
    ("__import__('reference')\n", 1),
    ("resources.files('reference').joinpath('answers.toml')\n", 1),
    ("from . import _trees\nfrom probes import _trees as p\nimport references_notes\n", 0),
])
def test_every_form_of_import_is_found(source, expected):
    assert len(reference_imports(source)) == expected
