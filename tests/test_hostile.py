"""Hostile submissions: each yields a clear student-facing error or a 0 for the attacked checks, within its
limits, and the grader itself carries on."""

import time

import pytest

from grader import grade_problem
from grader.results import Status
from grader.sandbox import Limits, SandboxMode, sandbox_mode

from .submissions import build_hostile, hostile_expectation, hostile_names

LIMITS = Limits(call_timeout=3.0, import_timeout=5.0, memory_mb=1024)
MODES = [pytest.param("bwrap", id="bwrap"), pytest.param("process", id="process")]


def _mode(kind):
    if kind == "bwrap" and not sandbox_mode().isolated:
        pytest.skip("bubblewrap is not available here")
    return SandboxMode(kind, f"{kind} (test)")


@pytest.mark.parametrize("kind", MODES)
@pytest.mark.parametrize("name", hostile_names())
def test_hostile_submission(name, kind, tmp_path):
    expect = hostile_expectation(name)
    if expect.get("isolated_only") and kind != "bwrap":
        pytest.skip("only a file-system sandbox can hide the reference's files; reports flag plain processes")
    submission = build_hostile(name, tmp_path / "pkg")
    start = time.monotonic()
    report = grade_problem(expect.get("problem", 6), submission, seed=7, limits=LIMITS, mode=_mode(kind))
    elapsed = time.monotonic() - start
    by_id = {r.check_id: r for r in report.results}
    statuses = expect["status"] if isinstance(expect["status"], list) else [expect["status"]]
    targets = expect.get("checks") or [r.check_id for r in report.results if r.status is not Status.SKIPPED]
    for check_id in targets:
        result = by_id[check_id]
        assert result.status.value in statuses, (check_id, result.status, result.message)
        assert result.score == 0
        if "message" in expect:
            assert expect["message"] in result.message, result.message
    assert not any(r.status is Status.GRADER_ERROR for r in report.results), report.results
    if "max_score" in expect:
        assert report.score <= expect["max_score"]
    if "stdout" in expect:
        assert expect["stdout"] in report.stdout
    # every call is bounded: import and call time-outs, plus process start-up, per attacked check
    assert elapsed < len(report.results) * (LIMITS.call_timeout + 2) + LIMITS.import_timeout


def test_fallback_is_reported(tmp_path):
    from .submissions import copy_reference

    report = grade_problem(6, copy_reference(tmp_path / "pkg"), seed=1,
                           mode=SandboxMode("process", "bubblewrap is not available: plain process"))
    assert report.score == report.auto_max_score
    assert not report.isolated and "bubblewrap" in report.sandbox
