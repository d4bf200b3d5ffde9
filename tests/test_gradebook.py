"""The gradebook: its schema, one atomic transaction per student, resumption keys, manual scores."""

import os
import signal
import sqlite3
import subprocess
import sys
import time
from dataclasses import replace
from types import ModuleType

import pytest

from grader.gradebook import Gradebook, ManualScoreError
from grader.sources import grader_version

from .batch_fixtures import VERSIONS, synthetic_report
from .submissions import ROOT


@pytest.fixture
def book(tmp_path):
    with Gradebook(tmp_path / "gradebook.sqlite") as book:
        yield book


def count(book, table):
    return book.db.execute(f"SELECT count(*) FROM {table}").fetchone()[0]


def test_schema_wal_and_unique_key(book):
    tables = {r[0] for r in book.db.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
    assert {"students", "submissions", "check_results", "manual_scores", "runs"} <= tables
    assert book.db.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
    unique = [
        [c[2] for c in book.db.execute(f"PRAGMA index_info('{index[1]}')")]
        for index in book.db.execute("PRAGMA index_list('submissions')") if index[2]
    ]
    assert ["student_id", "content_hash", "grader_version", "problem"] in unique


def test_results_round_trip(book):
    run = book.start_run("subs", [6, 7], 2)
    reports = [synthetic_report(6, failed=(2,), hidden=(3,), figure=True, manual=True), synthetic_report(7)]
    book.record("alice", "h1", VERSIONS, run, reports)
    current = book.current()
    assert [(g.student, g.report.problem, g.content_hash, g.run_id, g.outcome) for g in current] == [
        ("alice", 6, "h1", run, "graded"), ("alice", 7, "h1", run, "graded")]
    # rebuilt exactly, with the grader version of the gradebook's key (package version and check digest)
    assert [g.report for g in current] == [replace(r, grader_version=VERSIONS[r.problem]) for r in reports]
    assert book.graded_problems("alice", "h1", VERSIONS) == {6, 7}
    assert book.graded_problems("alice", "h1", {6: "other", 7: VERSIONS[7]}) == {7}
    assert book.graded_problems("alice", "h2", VERSIONS) == set()
    # without the figures: the same reports, every figure left out (what the class's files read)
    lean = book.current(figures=False)
    assert any(r.figures for g in current for r in g.report.results)
    assert [replace(g, report=replace(g.report, results=tuple(replace(r, figures=()) for r in g.report.results)))
            for g in current] == lean


def test_a_key_is_graded_once_and_a_refused_student_leaves_nothing(book):
    run = book.start_run("subs", [6, 7], 1)
    book.record("alice", "h1", VERSIONS, run, [synthetic_report(6)])
    before = [count(book, t) for t in ("students", "submissions", "check_results")]
    # problem 7 is new, problem 6 is graded already: the whole student is refused, problem 7 included
    with pytest.raises(sqlite3.IntegrityError):
        book.record("alice", "h1", VERSIONS, run, [synthetic_report(7), synthetic_report(6)])
    assert [count(book, t) for t in ("students", "submissions", "check_results")] == before
    # a failure in the middle of a student's checks rolls back the student entirely
    broken = synthetic_report(7)
    broken = replace(broken, results=broken.results[:3] + (replace(broken.results[3], visibility="secret"),))
    with pytest.raises(sqlite3.IntegrityError):
        book.record("bob", "h2", VERSIONS, run, [synthetic_report(6), broken])
    assert [count(book, t) for t in ("students", "submissions", "check_results")] == before
    assert book.db.execute("SELECT graded FROM runs WHERE id = ?", (run,)).fetchone()[0] == 1


def test_forced_regrade_replaces_and_a_changed_submission_adds(book):
    first = book.start_run("subs", [6], 1)
    book.record("alice", "h1", VERSIONS, first, [synthetic_report(6, failed=(0,))])
    second = book.start_run("subs", [6], 1, force=True)
    book.record("alice", "h1", VERSIONS, second, [synthetic_report(6)], replace_existing=True)
    assert count(book, "submissions") == 1 and count(book, "check_results") == 7
    (current,) = book.current()
    assert current.run_id == second and current.report.score == 7
    book.record("alice", "h2", VERSIONS, second, [synthetic_report(6, failed=(1, 2))])
    (current,) = book.current()
    assert (current.content_hash, current.report.score) == ("h2", 5)
    assert count(book, "submissions") == 2  # the history is kept


def test_kill_9_while_writing_leaves_only_whole_students(tmp_path):
    path = tmp_path / "gradebook.sqlite"
    script = f"from tests.batch_fixtures import write_students; write_students({str(path)!r}, 100000)"
    writer = subprocess.Popen([sys.executable, "-c", script], cwd=ROOT)
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            time.sleep(0.1)
            if path.exists():
                with sqlite3.connect(path, timeout=10) as db:
                    try:
                        if db.execute("SELECT count(*) FROM students").fetchone()[0] >= 50:
                            break
                    except sqlite3.OperationalError:  # the file is there, its tables not yet
                        continue
        os.kill(writer.pid, signal.SIGKILL)
    finally:
        writer.wait()
    assert writer.returncode == -signal.SIGKILL
    with Gradebook(path) as book:
        students = count(book, "students")
        assert 50 <= students < 100000
        per_student = book.db.execute(
            "SELECT count(*) FROM submissions GROUP BY student_id").fetchall()
        assert len(per_student) == students and {n for (n,) in per_student} == {2}
        per_submission = dict(book.db.execute(
            "SELECT s.problem, count(*) FROM check_results c JOIN submissions s ON s.id = c.submission_id "
            "GROUP BY c.submission_id").fetchall())
        assert per_submission == {6: 7, 7: 12}
        assert book.db.execute("SELECT graded FROM runs").fetchone()[0] == students
        assert book.db.execute("PRAGMA integrity_check").fetchone()[0] == "ok"


def test_manual_scores_are_checked_then_merged(book):
    run = book.start_run("subs", [6], 1)
    for name in ("alice", "bob"):
        book.record(name, f"h-{name}", VERSIONS, run, [synthetic_report(6, manual=True)])
    header = "student,problem,key,score,comment\n"
    bad = header + "alice,6,why,3,\nbob,6,nope,1,\ncarol,6,why,1,\nbob,six,why,1,\n"
    with pytest.raises(ManualScoreError) as error:
        book.import_manual(bad)
    assert [line.split(":")[0] for line in str(error.value).splitlines()] == ["line 2", "line 3", "line 4", "line 5"]
    assert "outside 0..2" in str(error.value)
    assert count(book, "manual_scores") == 0
    with pytest.raises(ManualScoreError, match="no column score"):
        book.import_manual("student,problem,key\nalice,6,why\n")
    assert book.import_manual(header + "alice,6,why,1.5,clear\nbob,6,why,,\n") == 1
    scores = {g.student: g.report.manual[0].score for g in book.current()}
    assert scores == {"alice": 1.5, "bob": None}
    assert {g.student: g.report.score for g in book.current()} == {"alice": 8.5, "bob": 7}
    assert book.import_manual(header + "alice,6,why,2,better\n") == 1
    assert book.current()[0].report.manual[0].score == 2
    assert book.manual_comments()[("alice", 6, "why")] == "better"
    assert count(book, "manual_scores") == 1


def test_grader_version_follows_the_check_module(tmp_path, monkeypatch):
    from grader.problems import problem_module

    source = tmp_path / "problem_98.py"
    source.write_text("TITLE = 'x'\n")
    module = ModuleType("checks.problem_98")
    module.__file__ = str(source)
    monkeypatch.setitem(sys.modules, "checks.problem_98", module)
    problem_module.cache_clear()
    try:
        before = grader_version(98)
        assert before == grader_version(98) and before.startswith("0.1.0+")
        source.write_text("TITLE = 'y'\n")
        assert grader_version(98) != before
        assert grader_version(6) != before
    finally:
        problem_module.cache_clear()


def test_the_probes_a_check_module_imports_decide_its_verdicts(tmp_path, monkeypatch):
    """A check names a probe by its function (``from probes import problem_22 as p22``): the dependency analysis
    follows that import to the probe module and on to the reference module the probe reaches; a probe named only
    in a string is no dependency."""
    from grader.problems import problem_module
    from grader.sources import verdict_sources

    source = tmp_path / "problem_98.py"
    module = ModuleType("checks.problem_98")
    module.__file__ = str(source)
    monkeypatch.setitem(sys.modules, "checks.problem_98", module)
    problem_module.cache_clear()
    try:
        source.write_text("TITLE = 'x'\nPROBE = 'problem_22.loop'\n")
        named = {f"{path.parent.name}/{path.name}" for path in verdict_sources(98)}
        source.write_text("from probes import problem_22 as p22\n\nTITLE = 'x'\nPROBE = p22.loop\n")
        imported = {f"{path.parent.name}/{path.name}" for path in verdict_sources(98)}
    finally:
        problem_module.cache_clear()
    assert "probes/problem_22.py" not in named and "reference/problem_22.py" not in named
    assert {"probes/problem_22.py", "reference/problem_22.py", "student_template/problem_22.py"} <= imported
    assert named < imported


VERSIONS_SCRIPT = """
import json
from grader.sources import grader_version
print(json.dumps({n: grader_version(n) for n in (6, 12, 24, 31)}))
"""


def test_editing_shared_code_regrades_exactly_the_problems_that_use_it(tmp_path):
    """The version key covers every file that decides a verdict: shared check helpers, shared probes, the grader's
    machinery and the reference, not only the problem's own check and probe modules."""
    import json
    import shutil

    for package in ("grader", "checks", "probes", "reference", "student_template"):
        shutil.copytree(ROOT / package, tmp_path / package, ignore=shutil.ignore_patterns("__pycache__"))

    def versions():
        done = subprocess.run([sys.executable, "-c", VERSIONS_SCRIPT], cwd=tmp_path, capture_output=True, text=True,
                              env={**os.environ, "PYTHONPATH": str(tmp_path)}, timeout=120)
        assert done.returncode == 0, done.stderr
        return {int(k): v for k, v in json.loads(done.stdout).items()}

    def edit(relative):
        path = tmp_path / relative
        path.write_text(path.read_text() + "\n# edited\n")

    before = versions()
    assert versions() == before  # stable
    changes = {}
    for relative in ("checks/_trees.py", "probes/_trees.py", "checks/_rigid.py", "reference/rotations.py",
                     "reference/tree.py", "grader/checking.py"):
        edit(relative)
        after = versions()
        changes[relative] = {n for n in before if after[n] != before[n]}
        before = after
    assert changes["checks/_trees.py"] == {24, 31}
    assert changes["probes/_trees.py"] == {24, 31}
    assert changes["checks/_rigid.py"] == {12}
    assert changes["reference/rotations.py"] == {6, 12, 24, 31}
    assert changes["reference/tree.py"] == {24, 31}
    assert changes["grader/checking.py"] == {6, 12, 24, 31}
