"""Several problems of one submission graded by two sandboxed workers side by side (``grade problem-6 problem-7
...`` on two cores): the same verdicts as one worker, the reports in the order asked, failures shrunk in both
workers at once, and Ctrl-C ending both workers and everything they started."""

import signal
import subprocess
import sys
import time

import pytest

from grader.cli import default_workers, main
from grader.runner import grade_submission
from grader.workers import Fresh

from .processes import default_ctrl_c, descendants
from .submissions import ROOT, build_hostile, build_with_mistakes, copy_reference, planted_mistakes
from .test_batch import assert_gone

#: heavy problems (7's sympy, 15's simulations) and the trees of 31 that reuse 24 and 25
PROBLEMS = [6, 7, 9, 15, 22, 24, 25, 31]
#: one mistake in each of two problems, both found by randomized comparisons (hypothesis shrinks each)
MISTAKES = ("p09-reversed-product", "p22-loop-sign-flip")


def _verdicts(reports) -> list:
    return [(r.problem, [(c.check_id, c.status, c.score, c.message, c.hint, c.diagnosis) for c in r.results])
            for r in reports]


def _with_mistakes(dest):
    mistakes = {m.name: m for m in planted_mistakes()}
    build_with_mistakes(dest, [mistakes[name] for name in MISTAKES])
    return dest


@pytest.mark.parametrize("kind", ["reference", "two mistakes"])
def test_two_workers_give_the_verdicts_of_one(kind, tmp_path):
    submission = copy_reference(tmp_path / "s") if kind == "reference" else _with_mistakes(tmp_path / "s")
    alone = grade_submission(submission, PROBLEMS, seed=5)
    together = grade_submission(submission, PROBLEMS, seed=5, workers=Fresh(count=2))
    assert [r.problem for r in together] == PROBLEMS
    assert _verdicts(together) == _verdicts(alone)
    failed = {c.check_id for r in together for c in r.results if not c.passed}
    if kind == "reference":
        assert not failed and sum(r.score for r in together) == sum(r.auto_max_score for r in together)
    else:  # both mistakes found, each by its own check: the comparison is not between two empty results
        mistakes = {m.name: m for m in planted_mistakes()}
        assert {mistakes[name].check for name in MISTAKES} <= failed


def test_a_single_problem_or_a_single_core_uses_one_worker(monkeypatch):
    monkeypatch.setattr("os.sched_getaffinity", lambda pid: {0, 1})
    assert default_workers(1) == 1 and default_workers(29) == 2
    monkeypatch.setattr("os.sched_getaffinity", lambda pid: {0})
    assert default_workers(29) == 1


def test_workers_must_be_a_positive_number(tmp_path, capsys):
    copy_reference(tmp_path / "s")
    assert main(["problem-6", "problem-8", "--submission", str(tmp_path / "s"), "--workers", "0"]) == 2
    assert "not a whole number of at least 1" in capsys.readouterr().err


def test_an_unloadable_submission_is_said_once_for_each_problem(tmp_path):
    broken = tmp_path / "broken.zip"
    broken.write_bytes(b"not a zip archive")
    reports = grade_submission(broken, [6, 8, 9], seed=1, workers=Fresh(count=2))
    assert [r.problem for r in reports] == [6, 8, 9]
    assert all(r.load_error for r in reports) and all(r.score == 0 for r in reports)


def test_ctrl_c_ends_both_workers(tmp_path):
    """Problem 6 hangs in the student's code (a call allowed a minute), 7 and 8 are graded beside it; Ctrl-C
    ends the command at once, with every worker and every process they started."""
    submission = build_hostile("infinite_loop_call", tmp_path / "s")
    command = [sys.executable, "-m", "grader.cli", "problem-6", "problem-7", "problem-8", "--submission",
               str(submission), "--workers", "2", "--timeout", "60"]
    grading = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               preexec_fn=default_ctrl_c)
    try:
        seen: set = set()
        settle = time.monotonic() + 6  # both workers started, 7 and 8 graded, 6's call under way
        while time.monotonic() < settle and grading.poll() is None:
            seen |= set(descendants(grading.pid))
            time.sleep(0.1)
        assert grading.poll() is None, grading.communicate()
        workers = sorted(seen | set(descendants(grading.pid)))
        asked = time.monotonic()
        grading.send_signal(signal.SIGINT)
        _, stderr = grading.communicate(timeout=45)
        took = time.monotonic() - asked
    finally:
        grading.kill()
    assert grading.returncode == 130 and "interrupted" in stderr, stderr
    assert took < 30, f"Ctrl-C took {took:.1f} s to end the grading (a call was allowed 60 s)"
    assert len(workers) >= 2, workers  # the two workers' sandboxes, at least
    assert_gone(workers)


def test_an_interruption_of_the_caller_ends_both_workers_at_once(tmp_path):
    """In the caller's own process (``grade_submission`` from a long-lived program): Ctrl-C while the workers
    grade ends the call within seconds, though a worker is in a call allowed a minute, and leaves no process
    behind."""
    import os
    import threading

    from grader.sandbox import Limits

    submission = build_hostile("infinite_loop_call", tmp_path / "s")
    before = set(descendants(os.getpid()))
    main_thread = threading.main_thread().ident
    timer = threading.Timer(6.0, signal.pthread_kill, (main_thread, signal.SIGINT))  # Ctrl-C, to this thread
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)  # however pytest was started
    began = time.monotonic()
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            grade_submission(submission, [6, 7, 8], seed=1, workers=Fresh(Limits(call_timeout=60.0), count=2))
        took = time.monotonic() - began
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    assert took < 25, f"the interruption took {took - 6:.1f} s to end the grading"
    assert_gone(sorted(set(descendants(os.getpid())) - before))


def test_workers_are_asked_of_one_place(tmp_path):
    """A grading gets its workers from ``grader.workers`` only: a count or a warm process handed over as before is
    refused, before anything is copied or started."""
    submission = copy_reference(tmp_path / "s")
    for workers in (2, object()):
        with pytest.raises(TypeError, match="Fresh, Forked or Started"):
            grade_submission(submission, [6], seed=1, workers=workers)
    assert Fresh(count=3).side_by_side(2) == 2 and Fresh(count=3).side_by_side(0) == 1
