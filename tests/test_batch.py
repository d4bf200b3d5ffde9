"""Batch grading: a class of 45 graded in parallel, killed with SIGKILL and resumed (every student graded once,
with the right grade); Ctrl-C and a killed worker; regrading of changed work only; the per-student time bound;
exports and the class summary; hidden checks; manual scores."""

import base64
import csv
import io
import json
import multiprocessing
import os
import re
import signal
import sqlite3
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

import pytest

from grader.batch import BatchLocked, Progress, _locked, discover, export_results, run_batch
from grader.batch.run import NotInstructorInstallation
from grader.batch.pool import Slot
from grader.cli import main
from grader.errors import SubmissionError
from grader.gradebook import GRADEBOOK_NAME, Gradebook
from grader.sources import grader_version
from grader.report.gradescope_results import WITHHELD
from grader.results import student_view
from grader.checking import checks_of
from grader.runner import grade_submission
from grader.workers import Fresh
from grader.problems import problem_module, problems as all_problems
from grader.sandbox import Limits, sandbox_mode

from .batch_fixtures import (
    BATCH_LIMITS,
    HIDDEN_PROBLEM,
    VERSIONS,
    build_class,
    build_slow,
    hidden_check_module,
    notebook_submission,
    synthetic_report,
    zip_folder,
)
from .submissions import ROOT, build_hostile, build_planted, copy_reference, copy_template, planted_mistakes
from .processes import alive, cmdline, default_ctrl_c, descendants
from .test_gradescope import validate, visible_text

LIMITS = Limits(call_timeout=BATCH_LIMITS["call_timeout"], import_timeout=BATCH_LIMITS["import_timeout"])
CLI_LIMITS = ["--timeout", str(BATCH_LIMITS["call_timeout"]), "--import-timeout", str(BATCH_LIMITS["import_timeout"]),
              "--student-timeout", str(BATCH_LIMITS["student_timeout"])]
MISTAKES = {m.name: m for m in planted_mistakes(6)}


def batch_command(submissions, out, *extra):
    return [sys.executable, "-m", "grader.cli", "batch", str(submissions), "--out", str(out), "--problems", "6",
            "--jobs", "2", *CLI_LIMITS, *extra]


def rows(path, query, *args):
    with sqlite3.connect(path, timeout=30) as db:
        return db.execute(query, args).fetchall()


def committed(path):
    """How many problem results the gradebook holds (0 while it is being created)."""
    try:
        return rows(path, "SELECT count(*) FROM submissions")[0][0] if path.exists() else 0
    except sqlite3.OperationalError:
        return 0


def graded_rows(path):
    """(student, problem) -> (submission id, run id, graded at) of every graded row."""
    return {(name, problem): rest for name, problem, *rest in rows(
        path, "SELECT st.name, s.problem, s.id, s.run_id, s.graded_at FROM submissions s "
              "JOIN students st ON st.id = s.student_id")}





def assert_gone(pids, seconds=15):
    """The processes end (workers, their sandboxes and the students' processes)."""
    deadline = time.monotonic() + seconds
    while any(alive(pid) for pid in pids) and time.monotonic() < deadline:
        time.sleep(0.1)
    left = {pid: cmdline(pid)[:200] for pid in pids if alive(pid)}
    assert not left, f"processes outlived the batch: {left}"


def assert_grade(expected, submission, checks):
    """One student's result against what the fixture says it must be."""
    score, outcome = submission
    name = expected.student
    assert outcome == expected.outcome, name
    assert score == sum(c["score"] for c in checks.values()) == sum(
        c["max_score"] for c in checks.values() if c["status"] == "passed"), name
    if expected.score is not None:
        assert score == expected.score, (name, {k: c["status"] for k, c in checks.items()})
    assert score <= expected.max_score, name
    for check_id, check in checks.items():
        allowed = expected.statuses.get(check_id, expected.statuses.get("*", expected.others))
        assert not allowed or check["status"] in allowed, (name, check_id, check["status"], check["message"][:300])
    for check_id, diagnosis in expected.diagnoses.items():
        assert checks[check_id]["diagnosis"] == diagnosis, (name, check_id)
    texts = [c["message"] + c["hint"] for c in checks.values() if c["status"] in expected.message_in]
    if expected.message and texts:
        assert any(expected.message in text for text in texts), (name, texts)


# ------------------------------------------------------------------------------------------ the class


@pytest.mark.slow
def test_class_batch_killed_midway_resumes_with_every_student_graded_once(tmp_path):
    """45 students (correct, template, planted mistakes, hostile, slow; folders, zips, notebooks) on 2 workers:
    kill -9 the batch once some students are committed, rerun it, and check the gradebook and the grades."""
    expected = build_class(tmp_path / "class")
    assert len(expected) >= 40
    out = tmp_path / "results"
    db = out / GRADEBOOK_NAME
    with open(tmp_path / "first.log", "w") as log:
        first = subprocess.Popen(batch_command(tmp_path / "class", out), cwd=ROOT, stderr=log, stdout=log)
        try:
            deadline = time.monotonic() + 120
            while committed(db) < 8 and first.poll() is None and time.monotonic() < deadline:
                time.sleep(0.05)
            workers = descendants(first.pid)
            first.send_signal(signal.SIGKILL)
        finally:
            first.wait()
    assert first.returncode == -signal.SIGKILL, "the batch finished before it could be killed"
    assert workers, "no worker processes were seen"
    assert_gone(workers)

    before = graded_rows(db)
    assert 8 <= len(before) < len(expected)
    ((state, graded),) = rows(db, "SELECT state, graded FROM runs")
    assert state == "running" and graded == len(before)  # killed: never finished, nothing half-written

    second = subprocess.run(batch_command(tmp_path / "class", out), cwd=ROOT, capture_output=True, text=True,
                            timeout=300)
    assert second.returncode == 0, second.stderr[-3000:]
    progress = [line for line in second.stderr.splitlines() if line.startswith("[")]
    assert len(progress) == len(expected) - len(before)
    assert all(re.search(r"\d+/\d+ done .* ETA", line) for line in progress)

    after = graded_rows(db)
    assert sorted(name for name, _ in after) == sorted(expected)  # every student, once (problem 6 only)
    assert rows(db, "SELECT count(*) FROM submissions GROUP BY student_id, problem HAVING count(*) > 1") == []
    assert {k: after[k] for k in before} == before  # the first run's rows were not regraded
    runs = rows(db, "SELECT id, state, graded, skipped FROM runs ORDER BY id")
    assert [r[1:] for r in runs] == [("running", len(before), 0),
                                     ("finished", len(expected) - len(before), len(before))]
    assert {run for _, run, _ in after.values()} == {runs[0][0], runs[1][0]}

    # the grades
    submissions = {name: (score, outcome) for name, score, outcome in rows(
        db, "SELECT st.name, s.score, s.outcome FROM submissions s JOIN students st ON st.id = s.student_id")}
    checks = {}
    for name, *values in rows(db, "SELECT st.name, c.check_id, c.status, c.score, c.max_score, c.diagnosis, "
                                  "c.message, c.hint, c.duration FROM check_results c JOIN submissions s "
                                  "ON s.id = c.submission_id JOIN students st ON st.id = s.student_id"):
        keys = ("check_id", "status", "score", "max_score", "diagnosis", "message", "hint", "duration")
        check = dict(zip(keys, values))
        checks.setdefault(name, {})[check["check_id"]] = check
    assert {len(c) for c in checks.values()} == {len(checks_of(problem_module(6)))}
    for name, exp in expected.items():
        assert_grade(exp, submissions[name], checks[name])
    with open(out / "grades.csv") as handle:
        grades = {row["student"]: row for row in csv.DictReader(handle)}
    assert {name: float(row["total"]) for name, row in grades.items()} == {
        name: score for name, (score, _) in submissions.items()}

    # a hostile submission costs at most its limits
    slowest = max(c["duration"] for c in checks["hostile_infinite_loop_call"].values())
    assert slowest <= BATCH_LIMITS["call_timeout"] + BATCH_LIMITS["import_timeout"] + 2
    durations = dict(rows(db, "SELECT st.name, s.duration FROM submissions s JOIN students st ON st.id = s.student_id"))
    assert max(durations.values()) <= BATCH_LIMITS["student_timeout"] + 5

    # unchanged submissions are not graded again
    third = subprocess.run(batch_command(tmp_path / "class", out), cwd=ROOT, capture_output=True, text=True,
                           timeout=120)
    assert third.returncode == 0 and f"0 graded, {len(expected)} unchanged" in third.stderr
    assert graded_rows(db) == after


# ------------------------------------------------------------------------------------------ a small class


@pytest.fixture(scope="module")
def small_class(tmp_path_factory):
    """Seven students graded in-process with the batch API: the exports and the class summary."""
    root = tmp_path_factory.mktemp("small")
    subs = root / "subs"
    subs.mkdir()
    copy_reference(subs / "alice")
    zip_folder(copy_reference(root / "bob"), subs / "bob.zip", top="bob")
    notebook_submission(subs / "carol")
    build_planted(MISTAKES["p06-vectors-transpose"], subs / "dave")
    build_planted(MISTAKES["p06-R1-degrees"], subs / "erin")
    copy_template(subs / "frank")
    (subs / "gina.zip").write_bytes(b"this is not a zip archive")
    out = root / "results"
    report = run_batch(subs, out, problems=[6], jobs=2, limits=LIMITS, progress=False)
    return subs, out, report


def test_small_class_grades_and_exports(small_class):
    subs, out, report = small_class
    assert (report.students, report.graded, report.skipped, report.interrupted) == (7, 7, 0, False)
    with open(out / "grades.csv") as handle:
        table = list(csv.reader(handle))
    assert table[0] == ["student", "problem_6", "total", "possible", "status"]
    assert {row[0]: float(row[2]) for row in table[1:]} == {
        # dave: only the vectors check (1 point); erin: R1 in degrees costs the elementary values (2) and the side
        # effects of that group (not run after them); cardan, frames and vectors are judged on her own R1
        # (error carried forward, full credit)
        "alice": 10, "bob": 10, "carol": 10, "dave": 9, "erin": 7, "frank": 0, "gina": 0}
    assert {row[3] for row in table[1:]} == {"10"}  # the same possible points for everyone, gina included
    status = {row[0]: row[4] for row in table[1:]}
    assert status.pop("gina").startswith("unloadable: gina.zip is not a readable zip archive")
    assert set(status.values()) == {"graded"}
    for name in ("alice", "bob", "carol", "dave", "erin", "frank", "gina"):
        results = validate(json.loads((out / "students" / name / "results.json").read_text()))
        assert len(results["tests"]) == len(checks_of(problem_module(6)))
        assert results["score"] == float(next(r[2] for r in table if r[0] == name))
        html = (out / "students" / name / "report.html").read_text()
        assert f"Grading report: {name}" in html and "Problem 6" in html
    gina = (out / "students" / "gina" / "report.html").read_text()
    assert "could not be loaded" in gina and "not a readable zip archive" in gina
    with Gradebook.in_folder(out) as book:
        stored = {g.student: g.report for g in book.current()}
    assert stored["alice"].seed == stored["bob"].seed != stored["dave"].seed  # the seed follows the content
    # the seed reproduces the randomized checks: the same minimal failing input, the same messages
    (again,) = grade_submission(subs / "erin", [6], seed=stored["erin"].seed, workers=Fresh(LIMITS))
    assert [(r.status, r.message) for r in again.results] == [(r.status, r.message) for r in stored["erin"].results]
    assert "(minimal failing input found by hypothesis" in again.results[2].message


def test_small_class_results_json_follow_gradescopes_specification(small_class):
    """Each student's results.json is the autograder's format (one builder): the specification's JSON Schema, the
    score of grades.csv, and an unloadable submission said once at the top, never as the student's wrong answers."""
    _, out, _ = small_class
    with open(out / "grades.csv") as handle:
        totals = {row["student"]: float(row["total"]) for row in csv.DictReader(handle)}
    for name, total in totals.items():
        results = validate(json.loads((out / "students" / name / "results.json").read_text()))
        assert results["score"] == total and results["extra_data"]["problems"] == [6]
        assert {t["visibility"] for t in results["tests"]} == {"visible"}  # problem 6: no secret or hidden check
    gina = validate(json.loads((out / "students" / "gina" / "results.json").read_text()))
    assert gina["output"].count("not a readable zip archive") == 1
    assert gina["output"].startswith("Your submission could not be loaded (problem 6): ")
    assert "not a readable zip archive" in gina["extra_data"]["load_errors"]["6"]
    assert gina["score"] == 0 and gina["tests"]
    for test in gina["tests"]:
        assert test["status"] == "failed" and test["score"] == 0, test
        assert test["output"] == "Not run: your submission could not be loaded (the reason is at the top).", test
    dave = validate(json.loads((out / "students" / "dave" / "results.json").read_text()))
    vectors = next(t for t in dave["tests"] if t["extra_data"]["check_id"] == "p06.vectors")
    assert (vectors["status"], vectors["visibility"]) == ("failed", "visible")
    assert "likely mistake: transpose" in vectors["output"] and "A_C3I instead of A_IC3" in vectors["output"]


def test_class_summary_has_every_plot_and_table(small_class):
    _, out, _ = small_class
    html = (out / "summary.html").read_text()
    images = re.findall(r'<img alt="([^"]+)" src="data:image/png;base64,([^"]+)"', html)
    assert [alt for alt, _ in images] == ["Total score distribution", "Problem 6: score distribution",
                                          "Checks failed most often"]
    for _, data in images:
        png = base64.b64decode(data)
        assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 2000
    for table in ("problems", "failing-checks", "diagnoses", "trouble-table", "students"):
        assert re.search(rf'<table id="{table}">.*?<tr>.*?</table>', html, re.S), table
    gradebook = re.search(r'<table id="students">(.*?)</table>', html, re.S).group(1)
    assert gradebook.count("<tr>") == 1 + 7
    assert "14% of students</strong> transposed a matrix (A_BI for A_IB) in problem 6" in html
    assert "14% of students</strong> used degrees where radians are expected in problem 6" in html
    trouble = re.search(r'<table id="trouble-table">(.*?)</table>', html, re.S).group(1)
    assert "gina" in trouble and "alice" not in trouble and "frank" not in trouble


def test_an_unchanged_class_is_skipped_a_changed_student_regraded_and_force_regrades_all(tmp_path):
    subs = tmp_path / "subs"
    build_planted(MISTAKES["p06-vectors-transpose"], subs / "dave")
    copy_reference(subs / "alice")
    out = tmp_path / "results"
    first = run_batch(subs, out, problems=[6], jobs=1, limits=LIMITS, progress=False)
    assert (first.graded, first.skipped) == (2, 0)
    rows_first = graded_rows(out / GRADEBOOK_NAME)

    copy_reference(tmp_path / "fixed")
    (subs / "dave" / "problem_06.py").write_text((tmp_path / "fixed" / "problem_06.py").read_text())
    second = run_batch(subs, out, problems=[6], jobs=1, limits=LIMITS, progress=False)
    assert (second.graded, second.skipped) == (1, 1)
    with Gradebook.in_folder(out) as book:
        current = {g.student: g for g in book.current()}
        assert book.db.execute("SELECT count(*) FROM submissions").fetchone()[0] == 3  # dave's first kept
    assert current["dave"].report.score == 10 and current["dave"].run_id == second.run_id
    assert current["alice"].run_id == first.run_id
    assert "dave,10,10,10" in (out / "grades.csv").read_text()

    forced = run_batch(subs, out, problems=[6], jobs=1, limits=LIMITS, progress=False, force=True)
    assert (forced.graded, forced.skipped) == (2, 0)
    rows_forced = graded_rows(out / GRADEBOOK_NAME)
    assert len(rows_forced) == 2 and {run for _, run, _ in rows_forced.values()} == {forced.run_id}
    assert rows_forced.keys() == rows_first.keys()


def test_a_student_over_the_time_bound_is_stopped_and_recorded(tmp_path):
    subs = tmp_path / "subs"
    build_slow(subs / "slow_student")
    copy_reference(subs / "ref_dir_01")
    start = time.monotonic()
    report = run_batch(subs, tmp_path / "out", problems=[6], jobs=2, limits=LIMITS, student_timeout=3,
                       progress=False, export=False)
    assert time.monotonic() - start < 20
    assert report.timed_out == ["slow_student"] and report.graded == 2
    with Gradebook.in_folder(tmp_path / "out") as book:
        outcomes = {g.student: (g.outcome, g.report.score, {r.status.value for r in g.report.results})
                    for g in book.current()}
    assert outcomes == {"slow_student": ("timeout", 0, {"timeout"}), "ref_dir_01": ("graded", 10, {"passed"})}


def test_the_end_line_counts_each_student_once(tmp_path):
    """The line `grade batch` ends with sorts every student into one kind: a student stopped at the time limit is
    not also counted as graded, and on a rerun the unchanged students say how many of them were stopped."""
    subs = tmp_path / "subs"
    build_slow(subs / "slow_student")
    copy_reference(subs / "alice")
    out = tmp_path / "out"
    first = subprocess.run(batch_command(subs, out, "--student-timeout", "3"), cwd=ROOT, capture_output=True,
                           text=True, timeout=120)
    assert ("2 students: 1 graded, 0 unchanged (skipped), 1 stopped at the time limit, 0 not graded"
            in first.stderr), first.stderr
    again = subprocess.run(batch_command(subs, out, "--student-timeout", "3"), cwd=ROOT, capture_output=True,
                           text=True, timeout=120)
    assert ("2 students: 0 graded, 2 unchanged (skipped; 1 of them was stopped at the time limit when graded: "
            "--force grades it again), 0 stopped at the time limit, 0 not graded" in again.stderr), again.stderr


def test_ctrl_c_stops_the_batch_cleanly_keeping_what_was_graded(tmp_path):
    subs = tmp_path / "subs"
    copy_reference(subs / "alice")
    build_slow(subs / "slow_student")
    copy_reference(subs / "zoe")
    out = tmp_path / "results"
    batch = subprocess.Popen(batch_command(subs, out), cwd=ROOT, stderr=subprocess.PIPE, text=True,
                             preexec_fn=default_ctrl_c)  # Ctrl-C reaches it however pytest was started
    try:
        deadline = time.monotonic() + 60
        while not committed(out / GRADEBOOK_NAME) and time.monotonic() < deadline and batch.poll() is None:
            time.sleep(0.05)
        workers = descendants(batch.pid)
        batch.send_signal(signal.SIGINT)
        _, stderr = batch.communicate(timeout=30)
    finally:
        batch.kill()
    assert batch.returncode == 130 and "rerun the same command to finish" in stderr
    assert_gone(workers)
    ((state, graded),) = rows(out / GRADEBOOK_NAME, "SELECT state, graded FROM runs")
    assert state == "interrupted" and 1 <= graded < 3 and len(graded_rows(out / GRADEBOOK_NAME)) == graded
    assert not (out / "grades.csv").exists()  # exports wait for a finished batch


def test_sigterm_repeated_stops_the_batch_once_and_its_clean_up_runs_to_the_end(tmp_path):
    """A supervisor or an impatient operator may send SIGTERM more than once.  The first stops the batch as Ctrl-C
    does; the others must not cut its clean-up short (the workers' stop, the run's state in the gradebook, the
    temporary folders)."""
    subs = tmp_path / "subs"
    copy_reference(subs / "alice")
    build_slow(subs / "slow_student")
    copy_reference(subs / "zoe")
    out, temporary = tmp_path / "results", tmp_path / "tmp"
    temporary.mkdir()
    batch = subprocess.Popen(batch_command(subs, out), cwd=ROOT, stderr=subprocess.PIPE, text=True,
                             env=dict(os.environ, TMPDIR=str(temporary)))
    try:
        deadline = time.monotonic() + 60
        while not committed(out / GRADEBOOK_NAME) and time.monotonic() < deadline and batch.poll() is None:
            time.sleep(0.05)
        workers = descendants(batch.pid)
        signals = 0
        while batch.poll() is None and signals < 400:  # every 5 ms until it has ended
            batch.send_signal(signal.SIGTERM)
            signals += 1
            time.sleep(0.005)
        _, stderr = batch.communicate(timeout=30)
    finally:
        batch.kill()
    assert signals > 1, "the batch ended before a second signal"
    assert batch.returncode == 130 and "rerun the same command to finish" in stderr, (batch.returncode, stderr)
    assert_gone(workers)
    ((state, graded),) = rows(out / GRADEBOOK_NAME, "SELECT state, graded FROM runs")
    assert state == "interrupted" and 1 <= graded < 3 and len(graded_rows(out / GRADEBOOK_NAME)) == graded

    def left():  # jinja2 keeps its compiled templates in the temporary directory on purpose (grader/report/environment.py)
        return sorted(p.name for p in temporary.iterdir() if not p.name.startswith("_jinja2-cache"))

    deadline = time.monotonic() + 20
    while left() and time.monotonic() < deadline:
        time.sleep(0.1)
    assert left() == []


def test_a_worker_stopped_while_its_warm_process_starts_leaves_no_folder(tmp_path, monkeypatch):
    """A batch stopped early (Ctrl-C, SIGTERM) stops its workers while they may still be starting their warm
    process: the folder that process was being prepared in must be removed all the same (it stayed in /tmp).  The
    whole course's warm process, the longest to start, leaves the widest window."""
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    monkeypatch.setenv("TMPDIR", str(temporary))  # the worker's, started below
    course = tuple(p.number for p in all_problems())
    slot = Slot(multiprocessing.get_context("spawn"), 1, LIMITS, sandbox_mode(), course)
    try:
        deadline = time.monotonic() + 60
        while not list(temporary.glob("grader-slot-*")):
            assert time.monotonic() < deadline and slot.process.is_alive(), "the worker did not start"
            time.sleep(0.005)
        assert not slot.conn.poll(), "the worker was ready already: nothing was stopped while it started"
    finally:
        slot.stop()
    deadline = time.monotonic() + 20
    while list(temporary.glob("grader-slot-*")) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert list(temporary.glob("grader-slot-*")) == [], f"the worker's exit code: {slot.process.exitcode}"


SIGINT_ACTION = "import signal; print(signal.getsignal(signal.SIGINT) is signal.default_int_handler)"


def test_a_process_the_tests_interrupt_takes_ctrl_c_even_when_pytest_runs_as_a_background_job():
    """``pytest ... &`` in a script starts pytest with SIGINT ignored, and so every process it starts: the
    Ctrl-C test then saw its batch finish (exit 0) instead of stop.  Its batch is started with SIGINT's default
    action, which Python turns into KeyboardInterrupt."""
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)  # as a background job of a non-interactive shell
    try:
        inherited, reset = [subprocess.run([sys.executable, "-c", SIGINT_ACTION], capture_output=True, text=True,
                                           timeout=60, **extra).stdout.strip()
                            for extra in ({}, {"preexec_fn": default_ctrl_c})]
    finally:
        signal.signal(signal.SIGINT, previous)
    assert inherited == "False"  # the cause: an ignored SIGINT stays ignored in a Python child
    assert reset == "True"


def test_a_worker_killed_while_it_starts_is_started_again(tmp_path):
    """A worker killed from outside before it is ready (the OOM killer on a loaded machine) is not a broken
    installation: the batch starts another and grades everyone."""
    subs = tmp_path / "subs"
    names = [f"student_{i}" for i in range(3)]
    for name in names:
        copy_reference(subs / name)
    out = tmp_path / "results"
    batch = subprocess.Popen(batch_command(subs, out), cwd=ROOT, stderr=subprocess.PIPE, text=True)
    killed = set()
    try:
        deadline = time.monotonic() + 60
        while not killed and time.monotonic() < deadline and batch.poll() is None:
            for pid in descendants(batch.pid):
                if b"spawn_main" in cmdline(pid):
                    os.kill(pid, signal.SIGKILL)
                    killed.add(pid)
            time.sleep(0.01)
        _, stderr = batch.communicate(timeout=300)
    finally:
        batch.kill()
    assert killed, "no worker was seen starting"
    assert batch.returncode == 0, stderr
    assert sorted(name for name, _ in graded_rows(out / GRADEBOOK_NAME)) == names


def test_a_worker_killed_midway_costs_only_its_student_who_is_graded_on_the_rerun(tmp_path):
    subs = tmp_path / "subs"
    names = [f"student_{i}" for i in range(8)]
    for name in names:
        copy_reference(subs / name)
    out = tmp_path / "results"
    command = batch_command(subs, out)
    (tmp_path / "tmp").mkdir()  # what the killed workers leave behind (their private copies) stays in here
    env = {**os.environ, "TMPDIR": str(tmp_path / "tmp")}
    batch = subprocess.Popen(command, cwd=ROOT, stderr=subprocess.PIPE, text=True, env=env)
    try:
        deadline = time.monotonic() + 60
        while not committed(out / GRADEBOOK_NAME) and time.monotonic() < deadline and batch.poll() is None:
            time.sleep(0.05)
        for pid in descendants(batch.pid):
            if b"spawn_main" in cmdline(pid):
                os.kill(pid, signal.SIGKILL)  # as the kernel's OOM killer would
        _, stderr = batch.communicate(timeout=60)
    finally:
        batch.kill()
    assert batch.returncode == 3 and "not graded:" in stderr and "exit code -9" in stderr
    first = graded_rows(out / GRADEBOOK_NAME)
    lost = stderr.count("not graded:")
    assert len(first) == 8 - lost  # the others went on with fresh workers; the lost ones are not recorded
    rerun = subprocess.run(command, cwd=ROOT, capture_output=True, text=True, timeout=120, env=env)
    assert rerun.returncode == 0 and f"{lost} graded, {8 - lost} unchanged" in rerun.stderr
    assert sorted(name for name, _ in graded_rows(out / GRADEBOOK_NAME)) == names


# ------------------------------------------------------------------------------------------ visibility, manual


@pytest.fixture
def hidden_problem(monkeypatch):
    """Problem 99: a visible check, a hidden check and a free-text question (a test-only check module)."""
    monkeypatch.setitem(sys.modules, f"checks.problem_{HIDDEN_PROBLEM}", hidden_check_module())
    problem_module.cache_clear()
    yield HIDDEN_PROBLEM
    problem_module.cache_clear()


def grade_into(book, run, name, source):
    versions = {HIDDEN_PROBLEM: grader_version(HIDDEN_PROBLEM)}
    reports = grade_submission(source, [HIDDEN_PROBLEM], seed=7, workers=Fresh(LIMITS))
    book.record(name, name, versions, run, reports)
    return reports


def test_hidden_checks_count_for_the_instructor_and_stay_hidden_from_the_student(hidden_problem, tmp_path):
    good = copy_reference(tmp_path / "good")
    bad = build_planted(MISTAKES["p06-vectors-transpose"], tmp_path / "bad")
    for folder, answer in ((good, "Its columns are unit vectors, orthogonal to each other."), (bad, "")):
        with open(folder / "answers.toml", "a") as handle:
            handle.write(f'\n[problem_{HIDDEN_PROBLEM}.free_text]\nwhy = "{answer}"\n')
    out = tmp_path / "results"
    with Gradebook.in_folder(out) as book:
        run = book.start_run("subs", [HIDDEN_PROBLEM], 1)
        (good_report,) = grade_into(book, run, "good", good)
        (bad_report,) = grade_into(book, run, "bad", bad)
        export_results(out, book)
    assert [r.status.value for r in good_report.results] == ["passed", "passed"]
    assert [r.status.value for r in bad_report.results] == ["passed", "failed"]

    with open(out / "grades.csv") as handle:
        totals = {row["student"]: (row["total"], row["possible"]) for row in csv.DictReader(handle)}
    # hidden points count for the instructor; the free-text answer's 2 points once a person scores it
    assert totals == {"bad": ("1", "4"), "good": ("4", "4")}

    for name, visible in (("good", "1 / 4"), ("bad", "1 / 4")):
        html = (out / "students" / name / "report.html").read_text()
        assert f"<strong>{visible}</strong>" in html  # the visible score only
        assert "1 hidden check worth 3 points" in html
        assert "SECRET" not in html and "all passed" not in html.lower()
        assert "transpose" not in html
    # results.json: Gradescope's specification, the autograder's visibility (shown when grades are published)
    results = validate(json.loads((out / "students" / "bad" / "results.json").read_text()))
    secret = [t for t in results["tests"] if t["extra_data"].get("check_id") == f"p{HIDDEN_PROBLEM}.secret_vector"]
    assert [(t["visibility"], t["status"], t["score"], t["max_score"]) for t in secret] == [(WITHHELD, "failed", 0, 3)]
    seen = visible_text(results)
    assert "SECRET" not in seen and "transpose" not in seen and "1 hidden check worth 3 points" in seen
    assert results["score"] == 1.0 and results["extra_data"]["max_score"] == 4.0
    (why,) = [t for t in results["tests"] if t["extra_data"].get("free_text") == "why"]
    assert "score" not in why and "(blank)" in why["output"]  # informational until a person scores it

    summary = (out / "summary.html").read_text()
    assert "SECRET: the coordinates of V in I" in summary  # the instructor sees the hidden check fail
    assert "Its columns are unit vectors" in summary  # and the free-text answers to score

    view = student_view(bad_report)
    hidden = [r for r in view.results if r.visibility == "hidden"]
    assert [(r.title, r.message, r.score, r.diagnosis) for r in hidden] == [("hidden check", "", 0.0, "")]
    assert view.auto_max_score == bad_report.auto_max_score


def test_manual_scores_import_updates_the_gradebook_and_exports(hidden_problem, tmp_path, capsys):
    good = copy_reference(tmp_path / "good")
    with open(good / "answers.toml", "a") as handle:
        handle.write(f'\n[problem_{HIDDEN_PROBLEM}.free_text]\nwhy = "Orthogonal unit columns."\n')
    out = tmp_path / "results"
    with Gradebook.in_folder(out) as book:
        run = book.start_run("subs", [HIDDEN_PROBLEM], 1)
        grade_into(book, run, "good", good)
    assert main(["export", str(out)]) == 0
    assert "good,4,4,4,graded" in (out / "grades.csv").read_text()  # not scored yet: not possible yet
    listed = list(csv.DictReader(io.StringIO((out / "manual_answers.csv").read_text())))
    assert [(r["student"], r["key"], r["answer"], r["score"], r["max_score"]) for r in listed] == [
        ("good", "why", "Orthogonal unit columns.", "", "2")]

    scores = tmp_path / "scores.csv"
    scores.write_text((out / "manual_answers.csv").read_text().replace(",why,,2,", ",why,9,2,"))
    assert main(["import-manual", str(out), str(scores)]) == 2
    assert "outside 0..2" in capsys.readouterr().err
    comment = "Right, but say why the columns are orthogonal: <A_IB^T A_IB = E>."
    scores.write_text(_csv_text([dict(row, score="1.5", comment=comment) for row in listed]))
    assert main(["import-manual", str(out), str(scores)]) == 0
    assert "good,5.5,5.5,6,graded" in (out / "grades.csv").read_text()
    results = validate(json.loads((out / "students" / "good" / "results.json").read_text()))
    assert results["score"] == sum(t["score"] for t in results["tests"]) == 5.5
    (why,) = [t for t in results["tests"] if t["extra_data"].get("free_text") == "why"]
    assert (why["score"], why["max_score"], why["status"]) == (1.5, 2.0, "failed")
    assert "1.5 of 2 points" in why["output"] and "Orthogonal unit columns." in why["output"]
    assert why["output"].endswith(f"Comment from your course staff:\n{comment}")  # the comment reaches the student
    assert ",why,1.5,2," in (out / "manual_answers.csv").read_text()
    # the student's HTML report: the score and the comment (escaped), under the answer
    html = (out / "students" / "good" / "report.html").read_text()
    block = re.search(rf'<div class="manual" id="free-text-{HIDDEN_PROBLEM}-why">(.*?)</div>', html, re.S).group(1)
    assert "1.5 of 2 points" in block and "0 until a person scores it" not in block
    assert "Comment from your course staff" in block
    assert "say why the columns are orthogonal: &lt;A_IB^T A_IB = E&gt;." in block and "<A_IB" not in block
    # the JSON report (as `grade problem-N --json` writes it) and the terminal's
    from grader.report.data import render_json
    from grader.report.text import render_terminal

    with Gradebook.in_folder(out) as book:
        reports = [g.report for g in book.current(student="good")]
    (item,) = json.loads(render_json(reports, show_hidden=False))["reports"][0]["manual"]
    assert (item["score"], item["comment"]) == (1.5, comment) and "model_answer" not in item
    assert f"comment from your course staff: {comment}" in render_terminal(reports)


def _csv_text(rows: list[dict]) -> str:
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)
    return buffer.getvalue()


def export_hostile_text(tmp_path):
    """Exports of a student whose free-text answer and printed output are markup."""
    report = synthetic_report(6, failed=(1,), manual=True)
    report = replace(report, stdout="<script>alert('out')</script>",
                     manual=(replace(report.manual[0], answer="<script>alert('answer')</script>"),))
    with Gradebook.in_folder(tmp_path) as book:
        book.record("mallory", "h", VERSIONS, book.start_run("subs", [6], 1), [report])
        export_results(tmp_path, book)
    return tmp_path


def test_the_class_summary_escapes_student_text(tmp_path):
    summary = (export_hostile_text(tmp_path) / "summary.html").read_text()
    assert "&lt;script&gt;alert(&#39;answer&#39;)&lt;/script&gt;" in summary and "<script>" not in summary


def test_the_student_report_escapes_student_text(tmp_path):
    report = (export_hostile_text(tmp_path) / "students" / "mallory" / "report.html").read_text()
    assert "<script>" not in report


# ------------------------------------------------------------------------------------------ pieces


def test_discover_names_students_and_refuses_ambiguity(tmp_path):
    subs = tmp_path / "subs"
    (subs / "alice").mkdir(parents=True)
    (subs / "alice" / "problem_06.py").write_text("x = 1\n")
    (subs / "bob.zip").write_bytes(b"not a zip")
    (subs / "carol.ipynb").write_text("{}")
    (subs / "notes.txt").write_text("hello")
    (subs / ".DS_Store").write_text("")
    (subs / "results").mkdir()
    entries, ignored = discover(subs, exclude=subs / "results")
    assert [e.name for e in entries] == ["alice", "bob", "carol"] and ignored == ["notes.txt"]
    assert entries[1].content_hash.startswith("unloadable-")
    (subs / "alice.zip").write_bytes(b"")
    with pytest.raises(SubmissionError, match="both be the student 'alice'"):
        discover(subs)


def test_one_writer_per_results_folder(tmp_path):
    copy_template(tmp_path / "subs" / "alice")
    Gradebook.in_folder(tmp_path / "out").close()
    with _locked(tmp_path / "out"):
        with pytest.raises(BatchLocked):
            run_batch(tmp_path / "subs", tmp_path / "out", problems=[6], progress=False)
        assert main(["export", str(tmp_path / "out")]) == 2


def test_progress_redraws_on_a_terminal_and_writes_lines_otherwise():
    class Terminal(io.StringIO):
        def isatty(self):
            return True

    terminal, log = Terminal(), io.StringIO()
    for stream in (terminal, log):
        bar = Progress(4, skipped=1, stream=stream)
        bar.advance("alice", "10/10 (0.3 s)")
        bar.advance("bob", "0/10 (0.1 s)")
        bar.close()
    assert terminal.getvalue().count("\r\033[K") == 2 and "2/4 done (1 unchanged, skipped)" in terminal.getvalue()
    assert "ETA" in terminal.getvalue() and "█" in terminal.getvalue()
    lines = log.getvalue().splitlines()
    assert lines[0].startswith("[1/4] alice: 10/10 (0.3 s) · 1/4 done") and lines[1].startswith("[2/4] bob")


def test_the_class_files_read_no_figures_and_each_student_file_keeps_them(tmp_path, monkeypatch):
    """The figures are most of a gradebook's bytes: the files about the whole class are written without reading
    any (their memory grows with the class by scores and verdicts only), and each student's report still has its
    own plots."""
    import grader.batch.gradebook as gradebook_module

    out = tmp_path / "results"
    real, read = gradebook_module._figure, []
    monkeypatch.setattr(gradebook_module, "_figure", lambda data: read.append(data) or real(data))
    with Gradebook.in_folder(out) as book:
        run = book.start_run("subs", [6, 7], 1)
        for name in ("alice", "bob"):
            book.record(name, name, VERSIONS, run, [synthetic_report(6, figure=True), synthetic_report(7)])
        export_results(out, book, students=False)
        assert read == [] and (out / "summary.html").is_file() and not (out / "students").exists()
        export_results(out, book)
    assert len(read) == 2  # one figure per student, read for that student's own files
    for name in ("alice", "bob"):
        assert '<img alt="q(t)" src="data:image/png;base64,' in (out / "students" / name / "report.html").read_text()


def test_exports_neutralise_spreadsheet_formulas_and_imports_read_them_back(tmp_path):
    """A free-text answer or a student's name that begins with =, +, -, @ (or a tab or carriage return) would be a
    formula in the instructor's spreadsheet: every such cell is written with a leading apostrophe, and the manual
    scores file still imports with the names it was written with."""
    formulas = ['=HYPERLINK("http://x","y")', "+1+2", "-2+3", "@SUM(A1)", "\t=1", "\r=1"]
    out = tmp_path / "results"
    with Gradebook.in_folder(out) as book:
        run = book.start_run("subs", [6], 1)
        for index, text in enumerate(formulas):
            report = synthetic_report(6, manual=True)
            report = replace(report, manual=(replace(report.manual[0], answer=text),))
            book.record(f"={index}+student" if index % 2 == 0 else f"student{index}", f"h{index}", VERSIONS, run,
                        [report])
        export_results(out, book)
    def read(name):
        with open(out / name, newline="", encoding="utf-8") as handle:
            return handle.read()

    for name in ("grades.csv", "manual_answers.csv"):
        rows = list(csv.reader(io.StringIO(read(name))))
        cells = [cell for row in rows[1:] for cell in row]
        assert not [c for c in cells if c[:1] in ("=", "+", "-", "@", "\t", "\r")], name
    listed = list(csv.DictReader(io.StringIO(read("manual_answers.csv"))))
    assert sorted(r["answer"] for r in listed) == sorted("'" + text for text in formulas)
    scored = io.StringIO()
    writer = csv.DictWriter(scored, fieldnames=list(listed[0]))
    writer.writeheader()
    writer.writerows([dict(row, score="1", comment="=ok") for row in listed])
    with Gradebook.in_folder(out) as book:
        assert book.import_manual(scored.getvalue()) == len(formulas)
        graded = book.current()
        assert sorted(g.student for g in graded if g.report.manual[0].score == 1.0) == sorted(
            f"={i}+student" if i % 2 == 0 else f"student{i}" for i in range(len(formulas)))
        assert set(book.manual_comments().values()) == {"=ok"}


# ------------------------------------------------------------------------------------------ an instructor's errors


def test_the_student_kit_refuses_to_grade_a_class(tmp_path, monkeypatch, capsys):
    """Run from the student kit, a batch graded every multiple-choice and hidden check 0 and called the students'
    results graded (a correct problem 10 got 2/5): it stops before anything is looked at, and says why, once."""
    from grader.oracle import AnswerKey, KeyOracle, set_current

    subs, out = tmp_path / "subs", tmp_path / "out"
    copy_reference(subs / "alice")
    command = ["batch", str(subs), "--out", str(out), "--problems", "10", "--jobs", "1", "-q"]
    monkeypatch.setattr("grader.oracle.reference_available", lambda: False)  # the kit: no reference installed
    assert main(command) == 2
    err = capsys.readouterr().err
    assert err.count("grade batch needs the instructor's installation") == 1, err
    assert "student kit" in err and "`grade problem-N`" in err and "Traceback" not in err
    assert not out.exists()  # nothing graded, no gradebook made
    with pytest.raises(NotInstructorInstallation):
        run_batch(subs, out, problems=[10], jobs=1, progress=False)
    monkeypatch.undo()
    previous = set_current(KeyOracle(AnswerKey(seed=0, fingerprint=""), check_fingerprint=False))
    try:  # the reference importable, but the kit's answer key installed: it would stand in for the reference
        assert main(command) == 2
    finally:
        set_current(previous)
    err = capsys.readouterr().err
    assert err.count("needs the instructor's installation") == 1 and "answer key" in err, err
    assert not out.exists()


def test_a_batch_over_a_folder_without_submissions_stops_and_says_what_to_put_there(tmp_path, capsys):
    subs, out = tmp_path / "subs", tmp_path / "out"
    subs.mkdir()
    assert main(["batch", str(subs), "--out", str(out), "--problems", "6", "-q"]) == 2
    err = capsys.readouterr().err
    assert err.count(f"{subs} holds no submission") == 1 and "one entry per student" in err, err
    assert "0 students" not in err and not out.exists()
    (subs / "notes.txt").write_text("not a submission")
    assert main(["batch", str(subs), "--out", str(out), "--problems", "6", "-q"]) == 2
    assert "holds no submission (it holds only notes.txt)" in capsys.readouterr().err


def test_jobs_must_be_at_least_one(tmp_path, capsys):
    subs = tmp_path / "subs"
    copy_reference(subs / "alice")
    for jobs in ("0", "-2", "two"):
        assert main(["batch", str(subs), "--out", str(tmp_path / "out"), "--problems", "6", "--jobs", jobs]) == 2
        err = capsys.readouterr().err
        assert f"argument --jobs/-j: {jobs!r} is not a whole number of at least 1" in err, err
    assert not (tmp_path / "out").exists()


def unloadable_report(problem: int, reason: str):
    """What the batch records for a problem of a submission that could not be loaded."""
    from grader.results import Status

    report = synthetic_report(problem, checks=7 if problem == 6 else 12)
    results = tuple(replace(r, status=Status.ERROR, score=0.0) for r in report.results)
    return replace(report, results=results, manual=(), load_error=reason)


def test_possible_points_are_the_same_for_every_student_and_count_free_text_once_scored(tmp_path):
    """Possible points were the checks' plus every free-text answer's, scored or not, for a student whose answers
    were read, and the checks' alone for one whose zip was corrupt (19 and 21 in one class).  They are now the
    checks' until a person scores a free-text answer, then both, for everyone; grades.csv says why a student got
    0, and the class summary lists a corrupt zip once."""
    out = tmp_path / "results"
    reason = "gina.zip is not a readable zip archive: File is not a zip file. Make the archive again."
    with Gradebook.in_folder(out) as book:
        run = book.start_run("subs", [6, 7], 1)
        for name in ("alice", "bob"):
            book.record(name, name, VERSIONS, run, [synthetic_report(6, manual=True), synthetic_report(7, checks=12)])
        book.record("gina", "gina", VERSIONS, run, [unloadable_report(6, reason), unloadable_report(7, reason)])
        export_results(out, book, students=False)

        def grades():
            with open(out / "grades.csv", newline="") as handle:
                return {row["student"]: row for row in csv.DictReader(handle)}

        before = grades()
        assert {name: row["possible"] for name, row in before.items()} == {"alice": "19", "bob": "19", "gina": "19"}
        assert before["gina"]["status"] == f"unloadable: {reason}" and before["gina"]["total"] == "0"
        assert before["alice"]["status"] == "graded"
        summary = (out / "summary.html").read_text()
        assert "19 points possible" in summary
        trouble = re.search(r'<table id="trouble-table">(.*?)</table>', summary, re.S).group(1)
        assert trouble.count("<td>gina</td>") == 1 and trouble.count("not a readable zip archive") == 1
        assert "<td>6, 7</td>" in trouble

        book.import_manual("student,problem,key,score\nalice,6,why,1.5\n")
        export_results(out, book, students=False)
        after = grades()
        assert {name: row["possible"] for name, row in after.items()} == {"alice": "21", "bob": "21", "gina": "21"}
        assert {name: row["total"] for name, row in after.items()} == {"alice": "20.5", "bob": "19", "gina": "0"}
        assert "21 points possible" in (out / "summary.html").read_text()


def test_progress_shows_a_students_name_and_what_became_of_them_inert():
    """A student's name (a folder or file name) and the reason a student was not graded come from the submission:
    the progress lines show their control characters escaped, on a terminal and in a log alike."""
    class Terminal(io.StringIO):
        def isatty(self):
            return True

    terminal, log = Terminal(), io.StringIO()
    for stream in (terminal, log):
        bar = Progress(2, stream=stream)
        bar.advance("mallory\x1b]0;owned\x07\u202e", "0/10 (0.3 s)")
        bar.advance("eve\x9b2J", "not graded (\x1b[2J\x1b[H10 / 10 points)")
        bar.close()
    assert "mallory\\x1b]0;owned\\x07\\u202e: 0/10" in log.getvalue()
    assert "eve\\x9b2J: not graded (\\x1b[2J\\x1b[H10 / 10 points)" in log.getvalue()
    for text in (terminal.getvalue(), log.getvalue()):
        escapes = re.sub("\r\x1b\\[K", "", text)  # the terminal's redrawn line: the grader's own sequence
        assert not re.search("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e]", escapes), repr(text)


# ------------------------------------------------------------------------------------------ seeds


def test_a_submission_cannot_predict_its_seed_from_its_own_files(tmp_path):
    """The hostile ``predict_seed`` computes, from its own files, the content hash of its submission and the seed
    a batch derived from that alone, and prints both: its content hash is right, but the seed the batch gives it
    comes from the results folder's secret as well, which it cannot know."""
    subs = tmp_path / "subs"
    build_hostile("predict_seed", subs / "mallory")
    out = tmp_path / "results"
    report = run_batch(subs, out, problems=[6], jobs=1, limits=LIMITS, progress=False, export=False)
    assert report.graded == 1
    with Gradebook.in_folder(out) as book:
        (graded,) = book.current()
    printed = re.search(r"content hash (\w+); predicted seed (\d+)", graded.report.stdout)
    assert printed, graded.report.stdout
    assert printed[1] == graded.content_hash  # the attack works out what it can...
    assert int(printed[2]) != graded.report.seed  # ...but not its seed
    assert graded.report.score == 10


def test_seeds_come_from_the_folders_secret_made_once_and_reproduce_with_seed(tmp_path, capsys):
    """Each results folder has a secret of its own, made once and kept in its gradebook (readable by its owner
    alone): a student's seed is the same in every run of a folder, differs between folders, and the seed recorded
    reproduces the student's random inputs with `grade problem-N --seed`."""
    subs = tmp_path / "subs"
    build_planted(MISTAKES["p06-cardan-rotation-order"], subs / "ann")
    seeds = {}
    for folder in ("first", "second"):
        out = tmp_path / folder
        run_batch(subs, out, problems=[6], jobs=1, limits=LIMITS, progress=False, export=False)
        assert (out / GRADEBOOK_NAME).stat().st_mode & 0o077 == 0
        with Gradebook.in_folder(out) as book:
            secret = book.seed_secret()
            assert book.seed_secret() == secret and len(secret) == 32
            (graded,) = book.current()
        seeds[folder] = graded
        run_batch(subs, out, problems=[6], jobs=1, limits=LIMITS, progress=False, export=False, force=True)
        with Gradebook.in_folder(out) as book:
            assert book.seed_secret() == secret and book.current()[0].report.seed == graded.report.seed
    assert seeds["first"].report.seed != seeds["second"].report.seed
    # the instructor reproduces the student's random inputs: the same failing input, the same message
    graded = seeds["first"].report
    failed = [r for r in graded.results if r.status.value == "failed"]
    assert failed
    messages = {}
    for seed in (graded.seed, graded.seed + 1):
        js = tmp_path / f"again-{seed}.json"
        main(["problem-6", "--submission", str(subs / "ann"), "--seed", str(seed), "--json", str(js)])
        messages[seed] = {r["check_id"]: r["message"] for r in json.loads(js.read_text())["reports"][0]["results"]}
    assert all(messages[graded.seed][r.check_id] == r.message for r in failed)
    assert any(messages[graded.seed + 1][r.check_id] != r.message for r in failed)  # the inputs follow the seed


def test_a_worker_killed_before_its_clean_up_leaves_no_folder_after_the_batch(tmp_path, monkeypatch):
    """A grading slot ended by SIGKILL (an operator, the OOM killer, a supervisor's last resort) runs no clean-up: its
    warm process's staging folder stays.  The next warm process, and the end of each batch, remove the folders of
    slots that are gone; a folder of a slot still running is left to it."""
    from grader.batch.run import _sweep_slots
    from grader.sandbox.zygote import SLOT_PREFIX

    temporary = tmp_path / "tmp"
    temporary.mkdir()
    monkeypatch.setenv("TMPDIR", str(temporary))  # the worker's, started below
    slot = Slot(multiprocessing.get_context("spawn"), 1, LIMITS, sandbox_mode(), (6,))
    slot.wait_ready()
    made = list(temporary.glob(f"{SLOT_PREFIX}*"))
    assert [_owner_of(p) for p in made] == [slot.process.pid]
    slot.process.kill()
    slot.process.join()
    slot.conn.close()
    assert list(temporary.glob(f"{SLOT_PREFIX}*")) == made  # no clean-up ran
    running = temporary / f"{SLOT_PREFIX}{os.getpid()}-0123456789abcdef"
    running.mkdir()
    unknown = temporary / f"{SLOT_PREFIX}not-a-slot"
    unknown.mkdir()
    _sweep_slots()
    assert sorted(temporary.glob(f"{SLOT_PREFIX}*")) == sorted([running, unknown])


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="zombies are told from /proc")
def test_a_slot_killed_and_not_yet_collected_by_its_parent_leaves_no_folder_after_the_batch(tmp_path, monkeypatch):
    """A slot's process that has ended but whose exit its parent has not collected yet (a zombie) runs no clean-up
    any more: its folder is swept as a gone process's is.  A process of this batch still running is waited for, up
    to a bound, then left to itself."""
    from grader.batch import run
    from grader.sandbox.zygote import SLOT_PREFIX

    temporary = tmp_path / "tmp"
    temporary.mkdir()
    monkeypatch.setenv("TMPDIR", str(temporary))
    ended = subprocess.Popen([sys.executable, "-c", "pass"])
    running = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    try:
        deadline = time.monotonic() + 30
        while Path(f"/proc/{ended.pid}/stat").read_text().split(")")[-1].split()[0] != "Z":
            assert time.monotonic() < deadline, "the child did not end"
            time.sleep(0.05)
        zombie = temporary / f"{SLOT_PREFIX}{ended.pid}-0123456789abcdef"
        alive = temporary / f"{SLOT_PREFIX}{running.pid}-0123456789abcdef"
        zombie.mkdir()
        alive.mkdir()
        monkeypatch.setattr(run, "SLOTS_ENDING", 0.5, raising=False)
        run._sweep_slots()
        assert sorted(temporary.glob(f"{SLOT_PREFIX}*")) == [alive]
    finally:
        running.kill()
        running.wait()
        ended.wait()


def _owner_of(folder):
    from grader.sandbox.zygote import SLOT_PREFIX

    return int(folder.name[len(SLOT_PREFIX):].split("-")[0])
