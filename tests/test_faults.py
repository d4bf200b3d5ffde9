"""Whose fault each failure is (``grader.faults``), row by row: each failure of the table produced for real (a
submission that cannot be loaded, a worker that cannot start, a student's code that raises, ends its process,
answers what cannot be read or never answers, a probe the worker cannot run, a check that crashes), and what
``grade problem-6``, Gradescope's ``run_autograder`` and ``grade batch`` make of it: the student's faults are graded
and recorded, the grader's never (exit code 3, nothing stored, results that say so)."""

from __future__ import annotations

import csv
import json
import multiprocessing
import shutil
import sqlite3
import zipfile
from dataclasses import dataclass
from functools import partial
from pathlib import Path

import pytest

from grader.cli import main
from grader.errors import (GraderFault, ProbeFault, SandboxError, StudentCodeError, StudentTimeout, SubmissionError,
                           WorkerCrash)
from grader.faults import FAULTS, exit_code, fault_of, faults_in, stored
from grader.gradescope import run as run_autograder
from grader.sandbox import Limits, sandbox_mode
import probes

from .submissions import ROOT, build_hostile, copy_reference

pytestmark = pytest.mark.skipif(not sandbox_mode().isolated, reason="grading here needs bubblewrap")


def test_every_exception_of_the_grader_has_its_row():
    rows = {
        SubmissionError("a broken zip"): "loader",
        SandboxError("no bwrap"): "worker start",
        StudentCodeError("exception", "ValueError", "boom"): "student code",
        StudentCodeError("not_implemented", "NotImplementedError", "Problem 6"): "student code",
        StudentCodeError("exit", "SystemExit", "1", phase="import"): "student code",
        WorkerCrash("the process running your code was killed"): "student process",
        StudentCodeError("bad_value", "TypeError", "an object of no known type"): "codec",
        StudentTimeout(10.0): "timeout",
        ProbeFault("no such probe"): "probe",
        GraderFault("the reference raised"): "grader exception",
        RuntimeError("a defect of a check"): "grader exception",
        KeyError("A_IC3"): "grader exception",
    }
    for exc, failure in rows.items():
        assert fault_of(exc) is FAULTS[failure], (exc, fault_of(exc))
    assert {f.failure for f in FAULTS.values() if f.student} == {
        "loader", "student code", "student process", "codec", "timeout"}
    assert {f.exit_code for f in FAULTS.values() if not f.student} == {3}
    assert {f.autograder_exit for f in FAULTS.values()} == {0, 3}


# ------------------------------------------------------------------------------------------ the failures


def _crash_shape_zip(tmp: Path) -> Path:
    """A zip of the reference that also holds ``foo.py`` and ``foo.py/bar.py`` (it crashed the loader)."""
    path = tmp / "work.zip"
    with zipfile.ZipFile(path, "w") as archive:
        for name in ("rotations.py", "problem_06.py", "__init__.py"):
            archive.write(ROOT / "reference" / name, name)
        archive.writestr("foo.py", "x = 1\n")
        archive.writestr("foo.py/bar.py", "")
    return path


def _worker_cannot_start(monkeypatch) -> None:
    from grader.sandbox import child

    def refuse(self):
        raise self._setup_fault("it ended (exit code 1) before it was ready")

    def canary(*args, **options):
        raise SandboxError("grader installation fault: the worker that runs submissions cannot start: it ended "
                           "(exit code 1) before it was ready")

    monkeypatch.setattr(child.Child, "_await_ready", refuse)
    monkeypatch.setattr("grader.batch.run.canary", canary)


def _asks_for(probe: str, instead: str, monkeypatch) -> None:
    """The checks ask for the probe ``instead`` where they ask for ``probe`` (a typo of a check)."""
    from grader.context import Context

    real = Context.student
    monkeypatch.setattr(Context, "student", lambda self, name, *args, **options: real(
        self, instead if probes.name_of(name) == probe else name, *args, **options))


def _reference_raises(monkeypatch) -> None:
    from grader.context import Context

    real = Context.reference

    def reference(self, name, *args, **options):
        if probes.name_of(name) == "problem_06.frames_with_factors":
            raise RuntimeError("a defect of the reference")
        return real(self, name, *args, **options)

    monkeypatch.setattr(Context, "reference", reference)


def _short_calls(monkeypatch) -> None:
    """Each call of a student's code may take 1 s (Gradescope's run has no option for it)."""
    monkeypatch.setattr("grader.sandbox.child.Limits", partial(Limits, call_timeout=1.0))


@dataclass(frozen=True)
class Scenario:
    build: object  # tmp folder -> the submission
    patch: object = None  # monkeypatch -> None: what makes the grader fail
    shows: str = ""  # a text the student's report shows
    checks: tuple = ()  # checks it stops (default: every check)


SCENARIOS = {
    "loader": Scenario(_crash_shape_zip, shows="both a file and a folder named foo.py"),
    "worker start": Scenario(lambda tmp: copy_reference(tmp / "work"), _worker_cannot_start,
                             shows="before it was ready"),
    "student code": Scenario(lambda tmp: build_hostile("import_exception", tmp / "work"),
                             shows="RuntimeError: boom at import"),
    "student process": Scenario(lambda tmp: build_hostile("os_exit", tmp / "work"),
                                shows="ended unexpectedly with exit code 0"),
    "codec": Scenario(lambda tmp: build_hostile("forged_deep_reply", tmp / "work"),
                      shows="the answer could not be read", checks=("p06.frames", "p06.vectors")),
    "timeout": Scenario(lambda tmp: build_hostile("infinite_loop_call", tmp / "work"), _short_calls,
                        shows="did not finish within 1 s", checks=("p06.frames", "p06.vectors")),
    "probe": Scenario(lambda tmp: copy_reference(tmp / "work"),
                      partial(_asks_for, "problem_06.frames", "problem_06.no_such_probe"),
                      shows="no_such_probe", checks=("p06.frames",)),
    "grader exception": Scenario(lambda tmp: copy_reference(tmp / "work"), _reference_raises,
                                 shows="a defect of the reference", checks=("p06.frames",)),
}


def test_every_row_has_its_scenario():
    assert set(SCENARIOS) == set(FAULTS)


def _autograder_root(tmp: Path, submission: Path) -> Path:
    root = tmp / "autograder"
    (root / "submission").mkdir(parents=True)
    if submission.is_dir():
        shutil.copytree(submission, root / "submission", dirs_exist_ok=True)
    else:
        shutil.copy2(submission, root / "submission" / submission.name)
    return root


@pytest.mark.parametrize("failure", list(SCENARIOS))
def test_a_failure_ends_as_its_row_says_in_grade_and_on_gradescope(failure, tmp_path, monkeypatch, capsys):
    fault, scenario = FAULTS[failure], SCENARIOS[failure]
    (tmp_path / "in").mkdir()
    source = scenario.build(tmp_path / "in")
    if scenario.patch:
        scenario.patch(monkeypatch)
    # grade problem-6: its exit code, and what the student reads
    code = main(["problem-6", "--submission", str(source), "--seed", "1", "--timeout", "1"])
    captured = capsys.readouterr()
    assert code == fault.exit_code, (failure, code, captured.out, captured.err)
    assert scenario.shows in captured.out + captured.err, captured.out + captured.err
    assert "Traceback (most recent call last)" not in captured.err
    # Gradescope's run: the student's fault is graded (exit 0), the grader's said to be the grader's (exit 3)
    root = _autograder_root(tmp_path, source)
    assert run_autograder(root, [6], seed=1) == fault.autograder_exit, capsys.readouterr().out
    data = json.loads((root / "results" / "results.json").read_text())
    extra = data["extra_data"]
    assert bool(extra["grader_fault"] or extra["grader_errors"]) is (not fault.student), extra
    shown = data["output"] + "".join(t["output"] for t in data["tests"])
    assert scenario.shows in shown, shown
    if fault.student:
        assert extra["grader_fault"] is False and extra["grader_errors"] == []
        stopped = [t for t in data["tests"] if t["extra_data"].get("check_id") in scenario.checks] \
            if scenario.checks else data["tests"]
        assert stopped and all(t["score"] == 0 for t in stopped)


# ------------------------------------------------------------------------------------------ a batch

LIMITS = ["--timeout", "1", "--import-timeout", "10"]


def _batch(subs: Path, out: Path, capsys) -> tuple[int, str]:
    code = main(["batch", str(subs), "--out", str(out), "--problems", "6", "--jobs", "2", *LIMITS])
    return code, capsys.readouterr().err


def _stored(out: Path) -> dict:
    with sqlite3.connect(out / "gradebook.sqlite") as db:
        return {name: (score, outcome, load_error) for name, score, outcome, load_error in db.execute(
            "SELECT st.name, s.score, s.outcome, s.load_error FROM submissions s JOIN students st "
            "ON st.id = s.student_id")}


def test_a_batch_records_the_students_faults_once_and_its_exit_code_stays_0(tmp_path, capsys):
    """Every row of the student's: graded 0 with the reason and recorded once (an unloadable submission among them:
    in grades.csv, never "not graded, retried on the next run"), the batch's exit code unchanged by them."""
    subs = tmp_path / "subs"
    subs.mkdir()
    copy_reference(subs / "honest")
    students = {f: f.replace(" ", "_") for f, fault in FAULTS.items() if fault.student}
    for failure, name in students.items():
        folder = tmp_path / "in" / name
        folder.mkdir(parents=True)
        built = SCENARIOS[failure].build(folder)
        built.rename(subs / (name + built.suffix))
    out = tmp_path / "out"
    code, err = _batch(subs, out, capsys)
    assert code == 0, err
    assert " 0 not graded" in err and "retried" not in err, err
    recorded = _stored(out)
    assert set(recorded) == {"honest", *students.values()}
    assert recorded["honest"][0] == 10 and recorded["loader"] == (0, "graded", recorded["loader"][2])
    assert "both a file and a folder named foo.py" in recorded["loader"][2]
    assert recorded["timeout"][1] == "graded"  # each call stopped at 1 s: graded within the batch's bound
    with open(out / "grades.csv", newline="") as handle:
        grades = {row["student"]: row for row in csv.DictReader(handle)}
    assert grades["loader"]["problem_6"] == "0" and grades["honest"]["problem_6"] == "10"
    assert grades["loader"]["status"] == f"unloadable: {recorded['loader'][2]}"
    # recorded once: the next run grades nobody again
    code, err = _batch(subs, out, capsys)
    assert code == 0 and f"{len(students) + 1} unchanged" in err, err


@pytest.mark.parametrize("failure", ["probe", "grader exception"])
def test_a_batch_stores_nothing_of_the_graders_fault_and_exits_3(failure, tmp_path, monkeypatch, capsys):
    """The grader's faults in a check: the student is not graded (retried on the next run), the batch exits 3.  The
    batch's grading processes are forked here (not spawned) so that they carry the fault this test plants."""
    SCENARIOS[failure].patch(monkeypatch)
    fork = multiprocessing.get_context("fork")
    monkeypatch.setattr("grader.batch.pool.multiprocessing.get_context", lambda method=None: fork)
    subs = tmp_path / "subs"
    copy_reference(subs / "alice")
    code, err = _batch(subs, tmp_path / "out", capsys)
    assert code == 3, err
    assert "not graded: alice: internal grader error (not your fault)" in err, err
    assert _stored(tmp_path / "out") == {}


def test_a_batch_whose_workers_cannot_start_grades_nobody_and_exits_3(tmp_path, monkeypatch, capsys):
    _worker_cannot_start(monkeypatch)
    subs = tmp_path / "subs"
    copy_reference(subs / "alice")
    code, err = _batch(subs, tmp_path / "out", capsys)
    assert code == 3 and "before it was ready" in err, err
    assert _stored(tmp_path / "out") == {}


def test_the_reports_of_each_row_are_stored_or_not_as_the_table_says(tmp_path, monkeypatch):
    """What ``grade batch`` and Gradescope decide from a student's graded reports (``stored``, ``exit_code``): the
    decision of the table for each failure that is found while the checks run."""
    from grader.runner import grade_submission
    from grader.workers import Fresh

    for failure in ("student code", "student process", "codec", "timeout", "probe", "grader exception"):
        scenario, fault = SCENARIOS[failure], FAULTS[failure]
        with monkeypatch.context() as patched:
            if scenario.patch:
                scenario.patch(patched)
            reports = grade_submission(scenario.build(tmp_path / failure.replace(" ", "_")), [6], seed=1,
                                       workers=Fresh(Limits(call_timeout=1.0, import_timeout=10.0)))
        assert stored(reports) is fault.student, failure
        assert exit_code(reports) == fault.exit_code, failure
        assert {found.student for found in faults_in(reports)} == {fault.student}, (failure, faults_in(reports))
