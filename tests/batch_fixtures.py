"""A generated class of submissions for the batch tests and the batch benchmark.

``build_class(dest)`` writes one entry per student into ``dest`` — correct work, the template, every planted
mistake, hostile submissions and one that is merely slow — as folders, zip archives and notebooks, and returns
what each student's grade of problem 6 must be.
"""

from __future__ import annotations

import tempfile
import zipfile
from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

from grader.results import ProblemReport

from .submissions import (
    ROOT,
    build_hostile,
    build_planted,
    copy_reference,
    copy_template,
    hostile_expectation,
    hostile_names,
    planted_mistakes,
)

__all__ = ["Expected", "BATCH_LIMITS", "HOSTILE", "HIDDEN_PROBLEM", "VERSIONS", "build_class", "build_slow",
           "zip_folder", "notebook_submission", "hidden_check_module", "synthetic_report", "write_students"]

PROBLEM = 6
FULL = 10.0
#: limits of the test batches: a hostile submission costs at most these
BATCH_LIMITS = {"call_timeout": 2.0, "import_timeout": 3.0, "student_timeout": 10.0}
#: hostile submissions of tests/hostile/ included in the class (those present)
HOSTILE = ("infinite_loop_call", "infinite_loop_import", "memory_bomb", "fork_bomb", "syntax_error",
           "import_exception", "os_exit", "sys_exit", "print_flood", "fake_json")
#: a submission whose every call is slow but within the call limit: only the per-student bound stops it
SLOW_R1 = ("    c, s = np.cos(alpha), np.sin(alpha)\n",
           "    import time\n    time.sleep(0.5)\n    c, s = np.cos(alpha), np.sin(alpha)\n")


@dataclass(frozen=True)
class Expected:
    """What a student's grade of problem 6 must be."""

    student: str
    kind: str  # "reference", "template", "planted", "hostile", "slow"
    score: float | None = None  # the exact score, when known
    max_score: float = FULL  # an upper bound
    statuses: dict = field(default_factory=dict)  # check id ("*": every check) -> its statuses (empty: any)
    others: tuple = ()  # the statuses every other check may have (empty: any)
    diagnoses: dict = field(default_factory=dict)  # check id -> its diagnosis
    message: str = ""  # in the message or hint of a check whose status is one of ``message_in``
    message_in: tuple = ()
    outcome: str = "graded"  # how the batch recorded it


def zip_folder(folder: Path, archive: Path, top: str = "") -> Path:
    """Zip ``folder``'s files, under the folder ``top`` inside the archive when given."""
    with zipfile.ZipFile(archive, "w", zipfile.ZIP_DEFLATED) as out:
        for path in sorted(folder.rglob("*")):
            if path.is_file() and "__pycache__" not in path.parts:
                out.write(path, str(Path(top) / path.relative_to(folder)))
    return archive


def notebook_submission(dest: Path) -> Path:
    """A folder of notebooks, one per module, as a student working in Jupyter hands in."""
    dest.mkdir(parents=True)
    for module in ("rotations", "problem_06"):
        source = (ROOT / "reference" / f"{module}.py").read_text()
        notebook = new_notebook(cells=[
            new_markdown_cell(f"# {module}\nMy solution."),
            new_code_cell("%matplotlib inline"),
            new_code_cell(source),
        ])
        nbformat.write(notebook, dest / f"{module}.ipynb")
    return dest


def _mark(folder: Path, student: str) -> Path:
    """Make each copy's content (hence its hash and seed) its own."""
    with open(folder / "problem_06.py", "a") as handle:
        handle.write(f"\n# {student}\n")
    return folder


def build_slow(dest: Path) -> Path:
    """Correct work whose R1 sleeps half a second: within the call limit, far beyond the per-student bound."""
    copy_reference(dest)
    rotations = dest / "rotations.py"
    rotations.write_text(rotations.read_text().replace(*SLOW_R1, 1))
    return dest


def _hostile_expected(name: str, student: str) -> Expected:
    """tests/hostile/NAME/expect.toml, with one allowance: the batch's call limit is shorter than the default
    that the expectation assumes, so a check may also stop at that limit (a memory bomb filling memory)."""
    spec = hostile_expectation(name)
    statuses = tuple(spec["status"] if isinstance(spec["status"], list) else [spec["status"]])
    checks = spec.get("checks")
    allowed = statuses + ("timeout",)
    return Expected(
        student, "hostile",
        max_score=float(spec.get("max_score", FULL)),
        score=0.0 if checks is None else None,
        statuses={c: allowed for c in checks} if checks else {"*": allowed + ("skipped",)},
        message=spec.get("message", ""),
        message_in=statuses,
    )


def build_class(dest: Path, references: int = 10, zips: int = 5, templates: int = 3,
                hostile: bool = True, slow: bool = True) -> dict[str, Expected]:
    """Write the class into ``dest`` (created) and return each student's expected grade."""
    dest.mkdir(parents=True, exist_ok=True)
    expected: dict[str, Expected] = {}
    passed = ("passed",)
    with tempfile.TemporaryDirectory() as scratch:
        scratch = Path(scratch)
        for i in range(1, references + 1):
            name = f"ref_dir_{i:02d}"
            _mark(copy_reference(dest / name), name)
            expected[name] = Expected(name, "reference", FULL, others=passed)
        for i in range(1, zips + 1):
            name = f"ref_zip_{i:02d}"
            folder = _mark(copy_reference(scratch / name), name)
            zip_folder(folder, dest / f"{name}.zip", top=name if i % 2 else "")
            expected[name] = Expected(name, "reference", FULL, others=passed)
        notebook_submission(dest / "nb_dir")
        expected["nb_dir"] = Expected("nb_dir", "reference", FULL, others=passed)
        zip_folder(notebook_submission(scratch / "nb_zip"), dest / "nb_zip.zip")
        expected["nb_zip"] = Expected("nb_zip", "reference", FULL, others=passed)
        for i in range(1, templates + 1):
            name = f"template_{i:02d}"
            copy_template(dest / name)
            if i > 1:
                _mark(dest / name, name)
            expected[name] = Expected(name, "template", 0.0, others=("not_implemented", "skipped"))
        for mistake in planted_mistakes(PROBLEM):
            for kind in ("dir", "zip"):
                name = f"planted_{kind}_{mistake.name}"
                folder = build_planted(mistake, (dest if kind == "dir" else scratch) / name)
                if kind == "zip":
                    zip_folder(folder, dest / f"{name}.zip")
                expected[name] = Expected(
                    name, "planted", max_score=FULL - 1,
                    statuses={mistake.check: (mistake.status,), **{also: () for also in mistake.also}},
                    others=("passed", "skipped"), diagnoses={mistake.check: mistake.diagnosis},
                    message=mistake.message, message_in=(mistake.status,),
                )
        if hostile:
            for name in (n for n in HOSTILE if n in hostile_names()):
                student = f"hostile_{name}"
                build_hostile(name, dest / student)
                expected[student] = _hostile_expected(name, student)
        if slow:
            build_slow(dest / "slow_student")
            expected["slow_student"] = Expected("slow_student", "slow", 0.0, statuses={"*": ("timeout",)},
                                                message="limit of", message_in=("timeout",), outcome="timeout")
    (dest / "README.txt").write_text("not a submission: ignored by the batch\n")
    return expected


# ------------------------------------------------------------------------------------------ a hidden check

HIDDEN_PROBLEM = 99


def hidden_check_module() -> ModuleType:
    """A check module for tests only (problem 99): one visible check, one hidden check, one free-text question."""
    import numpy as np

    from grader.checking import SHEET, STAGE_STRUCTURE, assert_close, assert_rotation, check

    module = ModuleType(f"checks.problem_{HIDDEN_PROBLEM}")
    module.TITLE = "Hidden checks (test only)"
    module.MANUAL = {"why": ("Why is a rotation matrix orthonormal?", 2.0)}

    @check(1, title="cardan(...) is a proper rotation", stage=STAGE_STRUCTURE)
    def check_visible_rotation(ctx):
        assert_rotation(ctx.student("problem_06.cardan", 0.4, -0.3, 1.1), "cardan(0.4, -0.3, 1.1)")

    @check(3, title="SECRET: the coordinates of V in I", visibility="hidden")
    def check_secret_vector(ctx):
        got = ctx.student("problem_06.vectors")
        expected = ctx.reference("problem_06.vectors")
        assert_close(np.asarray(got["I_v"]), expected["I_v"], "I_v (SECRET-MESSAGE)", SHEET)

    for func in (check_visible_rotation, check_secret_vector):
        setattr(module, func.__name__, func)
    return module


# ------------------------------------------------------------------------------------------ synthetic results

VERSIONS = {6: "test+6", 7: "test+7"}


def synthetic_report(problem: int = 6, failed: tuple = (), hidden: tuple = (), checks: int = 7,
                     manual: bool = False, figure: bool = False) -> ProblemReport:
    """A report with ``checks`` one-point checks named c0, c1, ...; those in ``failed`` fail with a diagnosis."""
    from grader.results import CheckResult, Figure, ManualItem, Series, Status

    plot = Figure("q(t)", "t [s]", "q [rad]", (Series("yours", (0.0, 1.0), (0.0, 0.5), "student"),
                                                Series("reference", (0.0, 1.0), (0.0, 0.4), "reference")))
    results = tuple(
        CheckResult(
            f"p{problem:02d}.c{i}", problem, f"property {i}", Status.FAILED if i in failed else Status.PASSED,
            0.0 if i in failed else 1.0, 1.0,
            message=f"got 1, expected 2 (check {i})" if i in failed else "",
            diagnosis="transpose" if i in failed else "",
            visibility="hidden" if i in hidden else "visible",
            seed=1234 if i == 0 else None,
            figures=(plot,) if figure and i == 0 else (),
        )
        for i in range(checks)
    )
    items = (ManualItem(problem, "why", "Why?", "Because A_IB is orthonormal.", "model", 2.0),) if manual else ()
    return ProblemReport(problem, f"Problem {problem}", results, items, sandbox="test", isolated=True, seed=42,
                         duration=0.1, stdout="printed <b>\n", submission="/tmp/x", grader_version="0.1.0",
                         notes=("a note",))


def write_students(path: str, count: int) -> None:
    """Commit ``count`` students of two problems each, one transaction per student (for the kill -9 test)."""
    from grader.gradebook import Gradebook

    with Gradebook(path) as book:
        run = book.start_run("synthetic", [6, 7], 1)
        for i in range(count):
            book.record(f"student_{i:05d}", f"hash{i}", VERSIONS, run,
                        [synthetic_report(6, failed=(1,)), synthetic_report(7, checks=12)])
