"""Generate ``student_template/`` from ``reference/``.

    python -m tools.make_template            # rewrite student_template/
    python -m tools.make_template --check    # exit 1 if student_template/ is out of date

Every region between ``# BEGIN SOLUTION problem N`` and ``# END SOLUTION`` is replaced by a stub that raises
``NotImplementedError("Problem N: <name> is not implemented yet")``, where <name> is the enclosing function or
method.  A top-level block between ``# BEGIN REFERENCE ONLY`` and ``# END REFERENCE ONLY`` (the grader's own
computations, e.g. of multiple-choice keys) is left out of the template entirely; its names stay out of
``__all__``.  A module that is one such block from its first line to its last (``tree_mistakes.py``: the
deliberately wrong recursions the diagnoses compute) is left out whole.  ``reference/answers.toml`` becomes ``answers.toml`` with every answer blank ("") and a comment saying
what kind of value is expected.  The package's docstring is the template's own (``PACKAGE_DOCSTRING``).
Everything else is copied verbatim.
"""

from __future__ import annotations

import argparse
import ast
import re
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
REFERENCE = ROOT / "reference"
TEMPLATE = ROOT / "student_template"

BEGIN = re.compile(r"^(?P<indent>\s*)# BEGIN SOLUTION problem (?P<problem>\d+)\s*$")
END = re.compile(r"^\s*# END SOLUTION\s*$")
REF_BEGIN = re.compile(r"^# BEGIN REFERENCE ONLY\s*$")
REF_END = re.compile(r"^# END REFERENCE ONLY\s*$")
DEF = re.compile(r"^(?P<indent>\s*)(?:async\s+)?def\s+(?P<name>\w+)")
CLASS = re.compile(r"^(?P<indent>\s*)class\s+(?P<name>\w+)")

STUDENT_README = """\
# Your multibody-dynamics package

Fill in every function that raises `NotImplementedError("Problem N: ...")`, and the answers in
`answers.toml`.  Keep the names and signatures: the grader calls them.  Inside the package, import with relative
imports (`from .rotations import skew`).

Grade one problem with `grade problem-6` (from this folder), or `grade problem-6 --html report.html` for a report
with plots.  `grade list` shows every problem and its points.
"""


#: the template package's own docstring, in place of the reference's (which says it is the solution)
PACKAGE_DOCSTRING = '''"""Your multibody-dynamics package: the student template of the course.

The package is a small multibody library (rotations, coordinate systems, rigid bodies, inertia, kinematic trees)
plus one ``problem_NN`` module per problem of the exercise sheet.  Fill in every function that raises
``NotImplementedError("Problem N: ...")``, and the answers in ``answers.toml``; keep the names and signatures, which
the grader calls.  ``grade problem-6`` in this folder grades problem 6.

Notation (see ``conventions``): ``A_XY`` maps Y-coordinates to X-coordinates, ``B_r_IB`` is the position of B
from I expressed in B, adjacent frame letters cancel (``A_IB @ A_BC == A_IC``).  SI units, radians.

Import inside the package with relative imports (``from .rotations import skew``): the grader imports the package
under another name.
"""
'''


class TemplateError(ValueError):
    """A marker region that cannot be turned into a stub."""


def _enclosing_name(lines: list[str], index: int, indent: int) -> str:
    """The qualified name of the function or method that contains line ``index``."""
    names: list[str] = []
    limit = indent
    for line in reversed(lines[:index]):
        match = DEF.match(line) or CLASS.match(line)
        if match and len(match["indent"]) < limit:
            names.append(match["name"])
            limit = len(match["indent"])
            if limit == 0:
                break
    if not names:
        raise TemplateError("a solution region must sit inside a function or method")
    return ".".join(reversed(names))


def strip_reference_only(source: str, filename: str = "<source>") -> str:
    """Remove the top-level ``REFERENCE ONLY`` blocks of ``source``."""
    out: list[str] = []
    inside = None
    for number, line in enumerate(source.splitlines(keepends=True), 1):
        if REF_BEGIN.match(line):
            if inside is not None:
                raise TemplateError(f"{filename}:{number}: nested BEGIN REFERENCE ONLY")
            inside = number
        elif REF_END.match(line):
            if inside is None:
                raise TemplateError(f"{filename}:{number}: END REFERENCE ONLY without BEGIN")
            inside = None
        elif inside is None:
            out.append(line)
    if inside is not None:
        raise TemplateError(f"{filename}:{inside}: BEGIN REFERENCE ONLY without END")
    return "".join(out)


def reference_only(source: str, filename: str = "<source>") -> bool:
    """True if the module ``source`` is reference-only as a whole: nothing is left once its ``REFERENCE ONLY``
    blocks are dropped (the template leaves it out)."""
    return not strip_reference_only(source, filename).strip()


def stub_source(source: str, filename: str = "<source>") -> str:
    """Drop the reference-only blocks of ``source`` and replace every solution region by a
    ``NotImplementedError`` stub."""
    lines = strip_reference_only(source, filename).splitlines(keepends=True)
    out: list[str] = []
    i = 0
    while i < len(lines):
        begin = BEGIN.match(lines[i])
        if END.match(lines[i]):
            raise TemplateError(f"{filename}:{i + 1}: END SOLUTION without BEGIN")
        if not begin:
            out.append(lines[i])
            i += 1
            continue
        indent = begin["indent"]
        name = _enclosing_name(lines, i, len(indent))
        j = i + 1
        while j < len(lines) and not END.match(lines[j]):
            if BEGIN.match(lines[j]):
                raise TemplateError(f"{filename}:{j + 1}: nested BEGIN SOLUTION")
            j += 1
        if j == len(lines):
            raise TemplateError(f"{filename}:{i + 1}: BEGIN SOLUTION without END")
        message = f"Problem {int(begin['problem'])}: {name} is not implemented yet"
        out.append(f"{indent}# TODO problem {int(begin['problem'])}: write your solution here\n")
        out.append(f'{indent}raise NotImplementedError("{message}")\n')
        i = j + 1
    return "".join(out)


def with_docstring(source: str, docstring: str, filename: str = "<source>") -> str:
    """``source`` with its module docstring replaced by ``docstring`` (a string literal and its newline)."""
    tree = ast.parse(source, filename)
    first = tree.body[0] if tree.body else None
    if not (isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant)
            and isinstance(first.value.value, str)):
        raise TemplateError(f"{filename}: the package has no docstring to replace")
    lines = source.splitlines(keepends=True)
    return "".join(lines[: first.lineno - 1]) + docstring + "".join(lines[first.end_lineno:])


def _describe(value) -> str:
    if isinstance(value, bool):
        return "true or false"
    if isinstance(value, int):
        return "an integer (the number of the option you choose)"
    if isinstance(value, float):
        return "a number"
    if isinstance(value, list):
        if value and isinstance(value[0], list):
            return f"a {len(value)} x {len(value[0])} matrix, e.g. [[1, 0, 0], [0, 1, 0], [0, 0, 1]]"
        return f"a list of {len(value)} numbers"
    if isinstance(value, str) and "\n" in value:
        return 'text over several lines, in triple quotes """..."""'
    return "text"


def _blank_answers(tables: dict, prefix: str = "") -> list[str]:
    lines: list[str] = []
    scalars = {k: v for k, v in tables.items() if not isinstance(v, dict)}
    if prefix and scalars:
        lines.append(f"[{prefix}]")
        for key, value in scalars.items():
            lines.append(f'{key} = ""  # {_describe(value)}')
        lines.append("")
    for key, value in tables.items():
        if isinstance(value, dict):
            lines.extend(_blank_answers(value, f"{prefix}.{key}" if prefix else key))
    return lines


def answers_template(reference_answers: str) -> str:
    """The template's answers.toml: the reference's keys, every value blank."""
    data = tomllib.loads(reference_answers)
    head = [
        "# Your answers to the questions that are not code.",
        '# Replace each "" by your answer; the comment says what kind of value is expected.',
        "# Questions under a .free_text table are read and scored by a person.",
        "",
    ]
    return "\n".join(head + _blank_answers(data)).rstrip("\n") + "\n"


def render() -> dict[str, str]:
    """Every file of the template, by relative path."""
    files: dict[str, str] = {}
    for path in sorted(REFERENCE.glob("*.py")):
        source = path.read_text()
        if not reference_only(source, str(path)):
            files[path.name] = stub_source(source, str(path))
    files["__init__.py"] = with_docstring(files["__init__.py"], PACKAGE_DOCSTRING, str(REFERENCE / "__init__.py"))
    answers = REFERENCE / "answers.toml"
    if answers.exists():
        files["answers.toml"] = answers_template(answers.read_text())
    files["README.md"] = STUDENT_README
    return files


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="only report whether student_template/ is current")
    args = parser.parse_args(argv)
    files = render()
    existing = {p.name: p.read_text() for p in TEMPLATE.glob("*") if p.is_file()}
    stale = sorted(name for name in files.keys() | existing.keys() if files.get(name) != existing.get(name))
    if args.check:
        for name in stale:
            print(f"student_template/{name} is out of date", file=sys.stderr)
        if stale:
            print("run: python -m tools.make_template", file=sys.stderr)
        return 1 if stale else 0
    TEMPLATE.mkdir(exist_ok=True)
    for name in stale:
        target = TEMPLATE / name
        if name in files:
            target.write_text(files[name])
        else:
            target.unlink()
    print(f"student_template/: {len(files)} files, {len(stale)} updated")
    return 0


if __name__ == "__main__":
    sys.exit(main())
