"""Feedback a student can act on: one mistake is counted once and named at its root (error carried forward).

A later check is judged on the student's own earlier results: a planted mistake in an upstream function costs only
the checks of that function; the checks built on it pass (full follow-through credit), point at the root, and the
root's hint names them once.
"""

import pytest

from grader import grade_problem
from grader.results import Status

from .kit_support import SEED
from .submissions import build_planted, planted_mistakes


def planted(name):
    return next(m for m in planted_mistakes() if m.name == name)


def graded(name, tmp_path):
    mistake = planted(name)
    return mistake, grade_problem(mistake.problem, build_planted(mistake, tmp_path / "pkg"), seed=SEED)


def assert_carried(report, root: str, followers: list[str], what: str, skipped=()):
    """Only ``root`` (and the later stages of its own group, ``skipped``) loses points; every follower passes with
    a pointer to the root; the root's hint names the followers once."""
    by_id = {r.check_id: r for r in report.results}
    lost = {r.check_id for r in report.results if r.score < r.max_score}
    assert lost == {root, *skipped}, lost
    assert all(by_id[s].status is Status.SKIPPED for s in skipped)
    assert report.score == report.auto_max_score - sum(by_id[c].max_score for c in lost)
    root_hint = by_id[root].hint
    assert root_hint.count("Later checks use your") == 1, root_hint
    assert f"judged on your {what}" in root_hint
    for follower in followers:
        result = by_id[follower]
        assert result.status is Status.PASSED
        assert f"Judged on your own {what}" in result.hint, result.hint
        assert by_id[root].title in result.hint
        assert root_hint.count(f"“{result.title}”") == 1, root_hint
    # no diagnosis is counted but the root's: the class summary counts the mistake once
    assert [r.check_id for r in report.results if r.diagnosis] == [root]


def test_transposed_R3_costs_only_the_elementary_rotations(tmp_path):
    _, report = graded("p06-R3-transpose", tmp_path)
    assert_carried(report, "p06.elementary_values", ["p06.cardan_values", "p06.frames", "p06.vectors"],
                   "R1, R2, R3", skipped=["p06.side_effects"])
    root = next(r for r in report.results if r.check_id == "p06.elementary_values")
    assert root.diagnosis == "transpose or angle_sign" and "A_CI instead of A_IC" in root.hint


def test_reflection_in_R2_is_carried_from_the_structure_check(tmp_path):
    """The values check of R1..R3 is skipped after the structure check fails: the root is the structure check."""
    _, report = graded("p06-R2-sign-flip-reflection", tmp_path)
    assert_carried(report, "p06.elementary_rotation",
                   ["p06.cardan_rotation", "p06.cardan_values", "p06.frames", "p06.vectors"], "R1, R2, R3",
                   skipped=["p06.elementary_values", "p06.side_effects"])


def test_an_upstream_answer_that_does_nothing_is_not_carried(tmp_path):
    """R1 returns the identity: the checks built on it are not judged on it (an answer that does nothing earns
    nothing downstream either)."""
    _, report = graded("p06-R1-identity", tmp_path)
    by_id = {r.check_id: r for r in report.results}
    assert by_id["p06.cardan_values"].status is Status.FAILED
    assert not any("Judged on your own R1, R2, R3" in r.hint for r in report.results)


def test_a_downstream_mistake_of_its_own_is_still_caught(tmp_path):
    """cardan multiplies the student's own (transposed) R3 in the wrong order: judged on their R3, it fails for
    its own reason, with its own diagnosis."""
    _, report = graded("p06-R3-transpose-and-cardan-order", tmp_path)
    by_id = {r.check_id: r for r in report.results}
    assert by_id["p06.cardan_values"].status is Status.FAILED
    assert by_id["p06.cardan_values"].diagnosis == "rotation_order"
    assert by_id["p06.elementary_values"].diagnosis == "transpose or angle_sign"


@pytest.mark.parametrize("name", ["p06-vectors-typed-from-sheet"])
def test_typed_sheet_numbers_do_not_pass(name, tmp_path):
    mistake, report = graded(name, tmp_path)
    target = next(r for r in report.results if r.check_id == mistake.check)
    assert target.score == 0 and target.diagnosis == "typed_numbers"


def test_a_wrong_step_of_point_k_costs_only_point_k(tmp_path):
    """Problem 22: the recursion's step is wrong; end_effector_recursive is judged on the student's own point_k."""
    _, report = graded("p22-point-k-orientation-before", tmp_path)
    assert_carried(report, "p22.points_values", ["p22.recursive_values"], "point_k", skipped=["p22.recursion"])


def test_a_wrong_position_pass_costs_only_the_positions(tmp_path):
    """A tree's position pass is wrong (problem 24's successor_pose adds S_r_SDs): problem 24 loses its pose
    checks; problem 31 judges the velocities, accelerations and Jacobians on their own merit (they are right) and
    its checks that met the student's poses point at problem 24's check."""
    from grader import grade_submission

    mistake = planted("p24-offset-added")
    p24, p31 = grade_submission(build_planted(mistake, tmp_path / "pkg"), [24, 31], seed=SEED)
    assert p24.score < p24.auto_max_score
    assert {r.check_id: r.diagnosis for r in p24.results if not r.passed}["p24.random_trees"] == "offset_sign"
    assert p31.score == p31.auto_max_score, [(r.check_id, r.message[:200]) for r in p31.results if not r.passed]
    carried = [r for r in p31.results if "Judged on your own positions and orientations" in r.hint]
    assert {r.check_id for r in carried} == {"p31.pendulum", "p31.random_trees"}
    assert all("problem 24's check “random trees of rotational joints" in r.hint for r in carried)
    assert not any(r.diagnosis for r in p31.results)


def test_a_wrong_gravity_costs_only_the_equations_of_motion(tmp_path):
    """Problem 37: g has the wrong sign; robot_ode and the three runs are judged on the student's own M, f, g."""
    _, report = graded("p37-gravity-sign", tmp_path)
    by_id = {r.check_id: r for r in report.results}
    lost = {r.check_id for r in report.results if r.score < r.max_score}
    assert lost <= {"p37.robot_mfg", "p37.tree_mfg", "p37.gravity_is_potential"} and "p37.robot_mfg" in lost, lost
    followers = ["p37.robot_ode", "p37.computed_torques_run", "p37.gravity_compensation_run", "p37.pd_run"]
    for follower in followers:
        assert by_id[follower].status is Status.PASSED
        assert "Judged on your own M, f, g" in by_id[follower].hint
    assert by_id["p37.robot_mfg"].hint.count("Later checks use your M, f, g") == 1


def test_the_class_summary_counts_the_root_mistake_once(tmp_path):
    """Two students with a transposed R3: the class summary names the root check, never the checks judged on it."""
    from grader.report.summary import class_summary
    from grader.batch.gradebook import Graded

    _, report = graded("p06-R3-transpose", tmp_path)
    html = class_summary([Graded(student, "hash", "v", 1, "now", "graded", report) for student in ("ann", "bob")])
    assert "p06.elementary_values" in html
    for follower in ("p06.cardan_values", "p06.frames", "p06.vectors"):
        assert follower not in html
