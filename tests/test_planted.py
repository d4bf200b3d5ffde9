"""Every check is proven: the reference passes it, and each planted mistake is caught by the intended check with
the intended diagnosis and message."""

import pytest

from grader import grade_problem, problems
from grader.results import Status

from .submissions import build_planted, build_variant, copy_reference, correct_variants, planted_mistakes

PROBLEMS = [p.number for p in problems()]


@pytest.fixture(scope="module")
def reference_copy(tmp_path_factory):
    return copy_reference(tmp_path_factory.mktemp("ref") / "pkg")


@pytest.mark.parametrize("problem", PROBLEMS)
def test_reference_scores_full_marks(problem, reference_copy):
    report = grade_problem(problem, reference_copy, seed=12345)
    failed = [(r.check_id, r.status.value, r.message[:300]) for r in report.results if not r.passed]
    assert not failed
    assert report.score == report.auto_max_score > 0


@pytest.mark.parametrize("mistake", planted_mistakes(), ids=lambda m: m.name)
def test_planted_mistake_is_caught(mistake, tmp_path):
    submission = build_planted(mistake, tmp_path / "pkg")
    report = grade_problem(mistake.problem, submission, seed=12345)
    by_id = {r.check_id: r for r in report.results}
    target = by_id[mistake.check]
    assert target.status is Status(mistake.status), target.message
    assert target.diagnosis == mistake.diagnosis, (target.diagnosis, target.message, target.hint)
    assert mistake.message in target.message + "\n" + target.hint
    unexpected = [r.check_id for r in report.results
                  if r.status not in (Status.PASSED, Status.SKIPPED) and r.check_id not in (mistake.check, *mistake.also)]
    assert not unexpected, f"checks failed that the mistake should not touch: {unexpected}"
    assert report.score < report.auto_max_score


@pytest.mark.parametrize("variant", correct_variants(), ids=lambda v: v["name"])
def test_correct_variant_scores_full_marks(variant, tmp_path):
    """Fairness: another valid answer, or a sound alternative computation, loses nothing."""
    report = grade_problem(variant["problem"], build_variant(variant, tmp_path / "pkg"), seed=12345)
    failed = [(r.check_id, r.status.value, r.message[:300]) for r in report.results if not r.passed]
    assert not failed
