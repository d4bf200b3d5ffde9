"""The problem index of ``docs/architecture.md``: for each problem with checks, its reference, check and probe modules.

    python -m tools.problem_index            # rewrite the index in docs/architecture.md
    python -m tools.problem_index --check    # exit 1 if the index there is out of date

The index is read from the source files alone (nothing is imported):

* checks: ``checks/problem_NN.py`` and the shared check modules it imports, and theirs in turn;
* probes: the probe modules those check modules import (a check names a probe by its function,
  ``from probes import _trees as probe_trees`` ... ``probe_trees.tree_state``);
* reference: ``reference/problem_NN.py`` (where the problem has one), the library modules it imports, and the
  library modules that those check and probe modules name (``module(pkg, "tree")``, or a module passed to a
  shared probe, ``"rotations"``).
"""

from __future__ import annotations

import argparse
import ast
import sys
from pathlib import Path

from grader.sources import parsed, project_imports, strings

ROOT = Path(__file__).resolve().parents[1]
DOCUMENT = ROOT / "docs" / "architecture.md"
BEGIN = "<!-- BEGIN problem index: python -m tools.problem_index -->"
END = "<!-- END problem index -->"


def _modules(package: str) -> set[str]:
    return {path.stem for path in (ROOT / package).glob("*.py") if path.stem != "__init__"}


def _parsed(package: str, name: str) -> ast.Module:
    return parsed(ROOT / package / f"{name}.py")


def _imports(tree: ast.Module, package: str) -> set[str]:
    """The modules of ``package`` that ``tree`` (a module of that package, or one that names it absolutely)
    imports, anywhere in the file."""
    return {name.split(".")[1] for name in project_imports(tree, package)
            if name.startswith(package + ".")}


def problem_row(number: int) -> dict[str, list[str]] | None:
    """The modules of problem ``number``, or None when it has no checks."""
    name = f"problem_{number:02d}"
    checks, probes, reference = _modules("checks"), _modules("probes"), _modules("reference")
    if name not in checks:
        return None
    check_modules, todo = set(), [name]
    while todo:
        current = todo.pop()
        if current in check_modules:
            continue
        check_modules.add(current)
        todo += sorted(_imports(_parsed("checks", current), "checks") & checks)
    probe_modules: set[str] = set()
    named: set[str] = set()
    for current in check_modules:
        tree = _parsed("checks", current)
        probe_modules |= _imports(tree, "probes") & probes
        named |= strings(tree)
    for current in probe_modules:
        named |= strings(_parsed("probes", current))
    library = {module for module in reference if not module.startswith("problem_")}
    reference_modules = named & library
    if name in reference:
        reference_modules |= {name} | (_imports(_parsed("reference", name), "reference") & library)
    reference_modules |= named & {m for m in reference if m.startswith("problem_")}
    title = next((node.value.value for node in _parsed("checks", name).body
                  if isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "TITLE" for t in node.targets)
                  and isinstance(node.value, ast.Constant)), "")
    return {"title": [title], "reference": _ordered(reference_modules, name),
            "checks": _ordered(check_modules, name), "probes": _ordered(probe_modules, name)}


def _ordered(modules: set[str], first: str) -> list[str]:
    """The problem's own module first, then the library's or the shared ones, then other problems' modules."""
    return sorted(modules, key=lambda m: (m != first, m.startswith("problem_"), m))


def render() -> str:
    """The index as a markdown table, between its markers."""
    lines = [BEGIN, "",
             "| problem | title | `reference/` | `checks/` | `probes/` |",
             "|---:|---|---|---|---|"]
    for number in range(1, 48):
        row = problem_row(number)
        if row is None:
            lines.append(f"| {number} | reading only: no checks | | | |")
            continue
        cells = [", ".join(f"`{m}`" for m in row[key]) for key in ("reference", "checks", "probes")]
        lines.append(f"| {number} | {row['title'][0]} | " + " | ".join(cells) + " |")
    lines += ["", END]
    return "\n".join(lines)


def current(text: str) -> str:
    """The index as ``text`` holds it (markers included), or "" when the markers are missing."""
    start, end = text.find(BEGIN), text.find(END)
    return text[start:end + len(END)] if 0 <= start < end else ""


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="only report whether the index is current")
    args = parser.parse_args(argv)
    text = DOCUMENT.read_text(encoding="utf-8")
    held, wanted = current(text), render()
    if args.check:
        if held != wanted:
            print("docs/architecture.md: the problem index is out of date\nrun: python -m tools.problem_index",
                  file=sys.stderr)
        return 0 if held == wanted else 1
    if not held:
        print(f"docs/architecture.md has no markers {BEGIN!r} ... {END!r}", file=sys.stderr)
        return 1
    DOCUMENT.write_text(text.replace(held, wanted), encoding="utf-8")
    print("docs/architecture.md: problem index " + ("unchanged" if held == wanted else "updated"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
