"""The portable mode (issue 28): chosen for a student's own grading only, in the kit, by a grader that is not root
where bubblewrap cannot run, or when GRADER_SANDBOX=portable asks for it; instructor grading (a batch, Gradescope)
never uses it, whatever the environment says.  (Its behaviour under attack: ``test_hostile.py``'s portable cases;
on a platform without the POSIX-only calls: ``test_laptops.py``.)"""

from __future__ import annotations

import json

import pytest

import grader.sandbox.portable as portable
from grader.runner import grade_problem
from grader.workers import Fresh
from grader.sandbox import Limits, sandbox_mode, student_mode
from grader.sandbox.portable import PORTABLE, PORTABLE_NOTE

from .submissions import copy_reference

LIMITS = Limits(call_timeout=5.0, import_timeout=10.0)


@pytest.fixture
def laptop(monkeypatch):
    """A student's laptop as the mode selection sees it: not root, no bubblewrap, no GRADER_SANDBOX."""
    monkeypatch.delenv("GRADER_SANDBOX", raising=False)
    monkeypatch.setattr(portable, "is_root", lambda: False)
    monkeypatch.setattr(portable, "_bwrap_runs", lambda: False)


def test_the_kit_on_a_laptop_chooses_the_portable_mode(laptop):
    assert student_mode(kit=True).kind == PORTABLE
    assert student_mode(kit=True).note == PORTABLE_NOTE
    # the full project (an instructor's, even on a laptop) keeps the modes of instructor grading
    assert student_mode(kit=False).kind != PORTABLE


def test_root_never_gets_the_portable_mode_by_itself(laptop, monkeypatch):
    monkeypatch.setattr(portable, "is_root", lambda: True)
    assert student_mode(kit=True).kind != PORTABLE


def test_bubblewrap_wins_where_it_runs(monkeypatch):
    if not sandbox_mode().isolated:
        pytest.skip("bubblewrap is not available here")
    monkeypatch.delenv("GRADER_SANDBOX", raising=False)
    monkeypatch.setattr(portable, "is_root", lambda: False)
    assert student_mode(kit=True).kind == "bwrap"


def test_grader_sandbox_portable_forces_it_for_a_student_only(monkeypatch):
    monkeypatch.setenv("GRADER_SANDBOX", "portable")
    assert student_mode(kit=False).kind == PORTABLE
    assert student_mode(kit=True).kind == PORTABLE
    assert sandbox_mode().kind != PORTABLE  # the instructor's choice: bubblewrap or a plain process


def test_a_portable_grading_says_what_it_protects(tmp_path):
    report = grade_problem(6, copy_reference(tmp_path / "pkg"), seed=3, workers=Fresh(LIMITS, portable.portable_mode()))
    assert report.score == report.auto_max_score
    assert report.sandbox == PORTABLE_NOTE and not report.isolated
    assert "not your computer" in report.sandbox and "\n" not in report.sandbox


def test_instructor_grading_never_uses_the_portable_mode(tmp_path, monkeypatch):
    """A batch and Gradescope's grading, with GRADER_SANDBOX=portable in their environment."""
    from grader.batch import run_batch
    from grader.gradescope import run as run_gradescope

    monkeypatch.setenv("GRADER_SANDBOX", "portable")
    subs = tmp_path / "subs"
    copy_reference(subs / "alice")
    out = tmp_path / "results"
    run_batch(subs, out, problems=[6], jobs=1, limits=LIMITS, progress=False,
              no_sandbox=not sandbox_mode().isolated)
    exported = [p.read_text() for p in out.rglob("*") if p.suffix in (".json", ".html", ".csv")]
    assert exported and not [text for text in exported if "portable mode" in text]
    student = json.loads((out / "students" / "alice" / "results.json").read_text())
    assert student["score"] > 0

    root = tmp_path / "autograder"
    copy_reference(root / "submission")
    (root / "results").mkdir()
    run_gradescope(root, [6], seed=1)
    results = (root / "results" / "results.json").read_text()
    assert json.loads(results)["score"] > 0 and "portable mode" not in results


def test_a_portable_worker_reads_writes_and_prints_in_utf8(tmp_path):
    """The student's code runs in Python's UTF-8 mode: its files (``open("data.txt")``, a probe's ``read_text()``)
    and its prints are UTF-8 on every platform, as in ``C.UTF-8`` on Linux, not in the ANSI code page of Windows
    (cp1252, where ``print("ω")`` raises)."""
    from grader.sandbox import Child

    work = copy_reference(tmp_path / "pkg")
    (work / "problem_20.py").write_text("import locale\nimport sys\n\nprint('ω')\nMATRICES_A = [sys.flags.utf8_mode, "
                                        "locale.getpreferredencoding(False), sys.stdout.encoding]\n")
    with Child(work, LIMITS, portable.portable_mode()) as child:
        utf8_mode, files, prints = child.call("problem_20.sheet_matrices")
        assert "ω" in child.output()[0]
    assert utf8_mode == 1 and {files.lower(), prints.lower()} <= {"utf-8", "utf8"}
