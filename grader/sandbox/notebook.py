"""Notebooks as submissions: which lines and statements of a notebook's code cells count, and (in the sandboxed
worker only) running them.  Standard library only: this module is copied next to the worker and imported by it;
the loader uses its text functions (``clean_cell``, ``definitions``), which read code and never run it.

What counts of a notebook (the same rule in the grader and in the worker):

* code cells only; IPython lines are dropped: magics (``%matplotlib inline``), shell lines (``!pip install``),
  ``get_ipython()`` calls, help (``x?``); a cell that starts with a cell magic (``%%time``) is dropped whole;
* of each cell, its *definitions*: ``import``, ``from ... import``, ``def``, ``class``, assignments to plain names
  (``GAMMA = np.deg2rad(30)``, ``a, b = ...``), and ``if``/``try`` blocks made only of these.  Everything else is
  the student trying things out and is left out: prints, plots (``plt.plot(...)``, ``plt.show()``), a value shown
  at the end of a cell, loops, ``assert``, assignments into items or attributes;
* the definitions run in the sandbox, cell by cell in the notebook's order, each on its own: one that raises
  is skipped (the report says which cell and why) and the others still run;
* cells out of order: a definition that failed because a name did not exist yet (``NameError``: it uses a
  function of a later cell) runs again after all the others, as long as that makes progress;
* an import of the submission's own modules (``from rotations import R1`` or ``from .rotations import R1``)
  never replaces a name the notebook defines itself, whichever cell comes first.
"""

from __future__ import annotations

import ast
import re

__all__ = ["clean_cell", "is_definition", "bound_names", "definitions", "first_line", "run_cells", "MAX_PASSES"]

#: how often the definitions that failed with a NameError run again (cells out of order)
MAX_PASSES = 5
_MAGIC = re.compile(r"^\s*(%|!)")
_HELP = re.compile(r"^\s*[\w.]+\s*\?\??\s*$|^\s*\?\??[\w.]+\s*$")


def clean_cell(source: str) -> tuple[str, int]:
    """The cell's code without IPython lines (each replaced by an empty line, so that line numbers stay those of
    the cell), and how many lines were dropped.  A cell magic drops the whole cell."""
    lines = source.splitlines()
    if lines and lines[0].lstrip().startswith("%%"):
        return "", len(lines)
    kept, dropped = [], 0
    for line in lines:
        if _MAGIC.match(line) or "get_ipython()" in line or _HELP.match(line):
            kept.append("")
            dropped += 1
        else:
            kept.append(line)
    return "\n".join(kept) + "\n", dropped


def _plain_targets(target: ast.expr) -> bool:
    if isinstance(target, ast.Name):
        return True
    if isinstance(target, (ast.Tuple, ast.List)):
        return all(_plain_targets(t) for t in target.elts)
    if isinstance(target, ast.Starred):
        return _plain_targets(target.value)
    return False


def is_definition(stmt: ast.stmt) -> bool:
    """Whether a top-level statement of a cell is kept (see the module's docstring)."""
    if isinstance(stmt, (ast.Import, ast.ImportFrom, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return True
    if isinstance(stmt, ast.Assign):
        return all(_plain_targets(t) for t in stmt.targets)
    if isinstance(stmt, ast.AnnAssign):
        return stmt.value is not None and isinstance(stmt.target, ast.Name)
    if isinstance(stmt, ast.If):
        return all(is_definition(s) for s in stmt.body + stmt.orelse)
    if isinstance(stmt, ast.Try):
        return all(is_definition(s) for s in stmt.body + stmt.orelse)
    return False


def _target_names(target: ast.expr) -> list[str]:
    if isinstance(target, ast.Name):
        return [target.id]
    if isinstance(target, (ast.Tuple, ast.List)):
        return [n for t in target.elts for n in _target_names(t)]
    if isinstance(target, ast.Starred):
        return _target_names(target.value)
    return []


def bound_names(stmt: ast.stmt) -> list[str]:
    """The names a kept statement defines (not those it imports)."""
    if isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return [stmt.name]
    if isinstance(stmt, ast.Assign):
        return [n for t in stmt.targets for n in _target_names(t)]
    if isinstance(stmt, ast.AnnAssign):
        return _target_names(stmt.target)
    if isinstance(stmt, (ast.If, ast.Try)):
        inner = stmt.body + stmt.orelse + [s for h in getattr(stmt, "handlers", []) for s in h.body]
        return [n for s in inner if is_definition(s) for n in bound_names(s)]
    return []


def definitions(code: str) -> list[str]:
    """The names that the kept statements of a cleaned cell define, in order (raises ``SyntaxError`` and the
    errors of ``ast.parse`` for code that does not parse)."""
    names: list[str] = []
    for stmt in ast.parse(code).body:
        if is_definition(stmt):
            names += [n for n in bound_names(stmt) if n not in names]
    return names


def first_line(code: str, width: int = 60) -> str:
    """How a report names a cell beside its number: its first line that holds code, shortened to ``width``."""
    line = next((line.strip() for line in code.splitlines() if line.strip()), "")
    return line if len(line) <= width else line[:width - 1] + "…"


# ---------------------------------------------------------------- running (in the sandboxed worker only)


def _without_own_names(stmt: ast.stmt, own: set[str], internal) -> ast.stmt | None:
    """``stmt`` without the names an import of the submission's own modules would put over the notebook's own
    definitions (None when nothing is left to import)."""
    if not isinstance(stmt, ast.ImportFrom) or not (stmt.level > 0 or internal(stmt.module or "")):
        return stmt
    names = [a for a in stmt.names if a.name == "*" or (a.asname or a.name) not in own]
    if not names:
        return None
    return ast.copy_location(ast.ImportFrom(module=stmt.module, names=names, level=stmt.level), stmt)


def run_cells(cells: list, namespace: dict, own: set[str], filename, internal) -> list[str]:
    """Run the kept statements of ``cells`` (pairs of the cell's number and its cleaned code) in ``namespace``;
    ``filename(number)`` names a cell in tracebacks, ``internal(module)`` says whether a top-level module name is
    one of the submission's.  Returns what the report says about the statements that were skipped."""
    import linecache

    todo = []
    notes: list[str] = []
    firsts: dict[int, str] = {}
    for number, code in cells:
        firsts[number] = first_line(code)
        # the cell's lines for tracebacks (a cell has no file of its own to read them from)
        linecache.cache[filename(number)] = (len(code), None, code.splitlines(True), filename(number))
        try:
            tree = ast.parse(code, filename(number))
        except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
            notes.append(f"cell {number} “{firsts[number]}” was left out: it does not parse "
                         f"({type(exc).__name__}: {exc})")
            continue
        for stmt in tree.body:
            if is_definition(stmt):
                stmt = _without_own_names(stmt, own, internal)
                if stmt is not None:
                    todo.append((number, stmt))
    failed: list = []
    for attempt in range(MAX_PASSES + 1):
        retry = []
        for number, stmt in todo:
            try:
                code = compile(ast.Module(body=[stmt], type_ignores=[]), filename(number), "exec")
                exec(code, namespace)  # noqa: S102 - the student's notebook, inside the sandbox
            except NameError as exc:  # perhaps defined by a later cell: tried again below
                retry.append((number, stmt, exc))
            except (Exception, SystemExit) as exc:  # noqa: BLE001 - one failing definition never stops the rest
                failed.append((number, stmt, exc))
        if not retry or len(retry) == len(todo) or attempt == MAX_PASSES:
            failed += retry
            break
        todo = [(number, stmt) for number, stmt, _ in retry]
    failed.sort(key=lambda item: (item[0], item[1].lineno))
    for number, stmt, exc in failed:
        names = bound_names(stmt) or [alias.asname or alias.name for alias in getattr(stmt, "names", [])]
        what = ", ".join(names[:6]) or "a statement"
        notes.append(f"cell {number} “{firsts[number]}”, line {stmt.lineno} ({what}) raised {type(exc).__name__}: "
                     f"{str(exc)[:300]}; it was skipped")
    return notes
