"""Checks name probes by object: ``from probes import problem_22 as p22`` ... ``ctx.student(p22.loop, ...)``.

A probe named by a string (``ctx.student("problem_22.loop", ...)``) cannot be followed by a reader, an editor or the
dependency analysis (``grader.sources``), and a typo in it shows only when the check runs.  The test parses every
module under ``checks/`` and finds two forms of a string probe:

* a call of one of the context's doors (``student``, ``student_later``, ``reference``, ``compare_random``,
  ``upstream``) whose probe argument is a string constant, whatever the string;
* a string constant anywhere in the module (docstrings aside) of the form ``"problem_NN.name"`` or
  ``"_module.name"`` that names a probe: held in a constant, a table, or passed to a helper that calls a door.

The keys of the table of the student's own functions that error carried forward replaces (``SHARED`` of
``checks/_upstream.py``, ``"problem_43.accelerations"``) name functions of the student's package, not probes.
"""

import ast
import re
from pathlib import Path

import pytest

import probes

CHECKS = Path(__file__).resolve().parents[1] / "checks"

#: the context's methods that take a probe as their first argument
DOORS = ("student", "student_later", "reference", "compare_random", "upstream")
#: the form of a probe's name
PROBE_NAME = re.compile(r"(problem_\d\d|_[a-z][a-z0-9_]*)\.[A-Za-z_][A-Za-z0-9_]*")
#: tables whose keys name the student's own functions ``module.function``: (module, table). The test fails for an
#: entry that no longer exists, so a stale entry cannot stay behind.
STUDENT_FUNCTION_TABLES = {("_upstream.py", "SHARED")}


def _names_a_probe(text: str) -> bool:
    if not PROBE_NAME.fullmatch(text):
        return False
    try:
        probes.lookup(text)
    except probes.ProbeLookupError:
        return False
    return True


def _docstrings(tree: ast.Module) -> set[int]:
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                found.add(id(first.value))
    return found


def _table_keys(tree: ast.Module, tables: set[str]) -> set[int]:
    keys = set()
    for node in tree.body:
        if (isinstance(node, ast.Assign) and isinstance(node.value, ast.Dict)
                and any(isinstance(t, ast.Name) and t.id in tables for t in node.targets)):
            keys |= {id(key) for key in node.value.keys}
    return keys


def tables_of(tree: ast.Module) -> set[str]:
    """The module-level names assigned in ``tree``."""
    return {t.id for node in tree.body if isinstance(node, ast.Assign) for t in node.targets
            if isinstance(t, ast.Name)}


def string_probes(source: str, tables: set[str] = frozenset()) -> list[str]:
    """``line: text`` of every string probe in ``source``: a door's probe argument that is a string constant, and
    any string constant (not a docstring, not a key of one of ``tables``) that names a probe."""
    tree = ast.parse(source)
    found, door_args = set(), set()
    for node in ast.walk(tree):
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr in DOORS
                and node.args and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str)):
            found.add((node.args[0].lineno, f"{node.func.attr}({node.args[0].value!r}, ...)"))
            door_args.add(id(node.args[0]))
    skipped = _docstrings(tree) | _table_keys(tree, set(tables)) | door_args
    for node in ast.walk(tree):
        if (isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in skipped
                and _names_a_probe(node.value)):
            found.add((node.lineno, repr(node.value)))
    return [f"{line}: {text}" for line, text in sorted(found)]


MODULES = sorted(path.name for path in CHECKS.glob("*.py"))


def test_the_modules_are_found():
    assert "problem_22.py" in MODULES and "_trees.py" in MODULES


@pytest.mark.parametrize("name", MODULES)
def test_check_module_names_probes_by_object(name):
    tables = {table for module, table in STUDENT_FUNCTION_TABLES if module == name}
    found = string_probes((CHECKS / name).read_text(), tables)
    assert not found, (f"{name} names probes by string (import the probe module, `from probes import problem_22 "
                       f"as p22`, and pass the probe, `ctx.student(p22.loop, ...)`):\n" + "\n".join(found))


@pytest.mark.parametrize("module, table", sorted(STUDENT_FUNCTION_TABLES))
def test_the_tables_of_the_students_functions_exist(module, table):
    tree = ast.parse((CHECKS / module).read_text())
    assert table in tables_of(tree), f"{module} has no table {table}: remove it from STUDENT_FUNCTION_TABLES"
    assert string_probes(ast.unparse(tree)) != string_probes(ast.unparse(tree), {table}), (
        f"{module}'s {table} names no probe: remove it from STUDENT_FUNCTION_TABLES")


@pytest.mark.parametrize("source, expected", [
    ("ctx.student('problem_22.loop', q)\n", 1),
    ("got = ctx.student_later('problem_06.framez')\n", 1),  # a typo is found too
    ("def f(ctx):\n    return ctx.reference('_trees.tree_state', d, q)\n", 1),
    ("ctx.compare_random('problem_07.skew', S, name='skew', tol=T)\n", 1),
    ("ctx.upstream('problem_08.part', ('a',), SHARED, flaw)\n", 1),
    ("PROBE = 'problem_22.loop'\n", 1),
    ("CASES = {'a': ('problem_06.cardan', 1)}\n", 1),
    ("judged(ctx, 'problem_08.part', 'a')\n", 1),
    ("SHARED = {'problem_43.accelerations': (43, 'p43.accelerations_values')}\n", 1),
    ("from probes import problem_22 as p22\nctx.student(p22.loop, q)\nctx.reference(p22.loop, q)\n", 0),
    ('"""Calls "problem_22.loop"."""\nctx.answer("a")\nx = "rotations.R3"\ny = f"problem_24.simulate({t})"\n', 0),
])
def test_every_form_of_a_string_probe_is_found(source, expected):
    assert len(string_probes(source)) == expected


def test_the_keys_of_a_table_of_the_students_functions_are_no_probes():
    source = "SHARED = {'problem_43.accelerations': (43, 'p43.accelerations_values')}\n"
    assert string_probes(source, {"SHARED"}) == []
    assert string_probes(source.replace("SHARED", "PROBES"), {"SHARED"}) != []
