"""Every check is proven: the reference passes it, and each planted mistake is caught by the intended check with
the intended diagnosis and message.

Each submission is also graded with the student kit's answer key (kit mode): every public check must give the
same status and diagnosis as with the live reference (parity), and the secret and hidden checks are deferred.

Two ways of starting the student's worker are covered: the planted mistakes and correct variants are graded on
workers forked from a batch slot's warm process (``grade batch``'s path, ``grader.sandbox.zygote``); the reference
and the untouched template are graded live on a fresh worker (``grade problem-N``'s path) and in kit mode on a
forked one, and the two must agree.
"""

import pytest

from grader import grade_problem, grade_submission
from grader.workers import Forked
from grader.problems import problems
from grader.results import Status

from .kit_support import (  # noqa: F401 (fixtures)
    SEED,
    assert_same_verdicts,
    grade_live_and_kit,
    warm_slot,
)
from .submissions import (
    ROOT,
    build_planted,
    build_variant,
    copy_reference,
    correct_variants,
    planted_mistakes,
)

PROBLEMS = [p.number for p in problems()]


@pytest.fixture(scope="module")
def reference_copy(tmp_path_factory):
    return copy_reference(tmp_path_factory.mktemp("ref") / "pkg")


@pytest.fixture(scope="module")
def slot():
    """A batch slot's warm process with every problem's modules imported, as ``grade batch`` starts one."""
    yield from warm_slot(PROBLEMS)


@pytest.mark.parametrize("problem", PROBLEMS)
def test_reference_scores_full_marks(problem, reference_copy, kit_oracle, deferred_ids, slot):
    report = grade_problem(problem, reference_copy, seed=SEED)
    kit = grade_problem(problem, reference_copy, seed=SEED, oracle=kit_oracle, workers=Forked(slot))
    failed = [(r.check_id, r.status.value, r.message[:300]) for r in report.results if not r.passed]
    assert not failed
    assert report.score == report.auto_max_score > 0
    assert_same_verdicts(f"reference p{problem:02d}", report, kit, deferred_ids)


def test_untouched_template_parity(kit_oracle, deferred_ids, slot):
    live = grade_submission(ROOT / "student_template", PROBLEMS, seed=SEED)
    kit = grade_submission(ROOT / "student_template", PROBLEMS, seed=SEED, oracle=kit_oracle, workers=Forked(slot))
    for one, other in zip(live, kit):
        assert_same_verdicts(f"template p{one.problem:02d}", one, other, deferred_ids)


@pytest.mark.parametrize("mistake", planted_mistakes(), ids=lambda m: m.name)
def test_planted_mistake_is_caught(mistake, tmp_path, kit_oracle, deferred_ids, slot):
    submission = build_planted(mistake, tmp_path / "pkg")
    report, kit = grade_live_and_kit(mistake.problem, submission, kit_oracle, zygote=slot)
    by_id = {r.check_id: r for r in report.results}
    target = by_id[mistake.check]
    assert target.status is Status(mistake.status), target.message
    assert target.diagnosis == mistake.diagnosis, (target.diagnosis, target.message, target.hint)
    assert mistake.message in target.message + "\n" + target.hint
    unexpected = [r.check_id for r in report.results
                  if r.status not in (Status.PASSED, Status.SKIPPED) and r.check_id not in (mistake.check, *mistake.also)]
    assert not unexpected, f"checks failed that the mistake should not touch: {unexpected}"
    assert report.score < report.auto_max_score
    assert_same_verdicts(mistake.name, report, kit, deferred_ids)


@pytest.mark.parametrize("variant", correct_variants(), ids=lambda v: v["name"])
def test_correct_variant_scores_full_marks(variant, tmp_path, kit_oracle, deferred_ids, slot):
    """Fairness: another valid answer, or a sound alternative computation, loses nothing."""
    report, kit = grade_live_and_kit(variant["problem"], build_variant(variant, tmp_path / "pkg"), kit_oracle,
                                     zygote=slot)
    failed = [(r.check_id, r.status.value, r.message[:300]) for r in report.results if not r.passed]
    assert not failed
    assert_same_verdicts(variant["name"], report, kit, deferred_ids)
