"""One mistake counts once across problems (error carried forward across problems).

A shared function found wrong in one problem (a transposed ``R3`` of problem 6) costs its points there; every later
problem that uses it judges its own code on the student's function (``grader.upstream``: the reference's code of the
later problem composed with the student's ``R3``), keeps its points and points at the check that finds the mistake.
Credit is carried only on real upstream results; a later mistake of its own is still caught; the student kit, which
holds no reference code, leaves such a check to the graded submission and names the function and its check.
"""

from __future__ import annotations

import ast
import re

import numpy as np
import pytest

from checks._upstream import SHARED, flaw
from grader import grade_submission
from grader.workers import Fresh
from grader.checking import checks_of
from grader.problems import problem_module
from grader.results import Status

from .kit_support import (  # noqa: F401 (fixtures)
    SEED,
    assert_same_verdicts,
    grade_live_and_kit,
)
from .submissions import ROOT, build_planted, copy_reference, planted_mistakes

#: where problem 6's check of R1, R2, R3 is named
ROOT_TITLE = "problem 6's check “R1, R2, R3 equal the elementary rotations on random angles”"
#: the problems after 6 that a transposed R3 reaches, and the checks it made fail before (points lost on main: 80)
REACHED = {7: ["p07.animation"],
           8: ["p08.cardan_step", "p08.part_a", "p08.part_b", "p08.part_c"],
           24: ["p24.pendulum", "p24.random_trees"],
           25: ["p25.sheet_values", "p25.walker_random", "p25.rolling_trees"],
           27: ["p27.frame_residuals"],
           31: ["p31.pendulum", "p31.jacobians", "p31.path", "p31.random_trees"],
           32: ["p32.rigid_trees", "p32.end_effector", "p32.gravity_potential", "p32.gravity_random",
                "p32.gravity_trajectory"],
           33: ["p33.sheet", "p33.jacobians", "p33.path", "p33.random_trees"],
           34: ["p34.biped", "p34.jacobians", "p34.path", "p34.random_trees"],
           37: ["p37.gravity_is_potential", "p37.lagrange_equations", "p37.robot_mfg", "p37.tree_mfg"],
           38: ["p38.walker_ode"],
           46: ["p46.event_function", "p46.constraint_jacobian", "p46.constraint_terms"]}


def _planted(name):
    return next(m for m in planted_mistakes() if m.name == name)


def _with(tmp_path, replacements):
    """A reference copy with text replacements ``[(file, old, new)]``, each made exactly once."""
    submission = copy_reference(tmp_path / "pkg")
    for file, old, new in replacements:
        text = (submission / file).read_text()
        assert text.count(old) == 1, (file, old)
        (submission / file).write_text(text.replace(old, new))
    return submission


R3_TRANSPOSED = ("rotations.py", "return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])",
                 "return np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])")


@pytest.fixture(scope="module")
def transposed(tmp_path_factory):
    return build_planted(_planted("p06-R3-transpose"), tmp_path_factory.mktemp("r3") / "pkg")


def test_a_transposed_R3_costs_problem_6s_R_checks_only(transposed):
    """The issue's case: a transposed R3 cost 3 points in problem 6, 1 in problem 7 and 6 in problem 8; now problem
    6's checks of R1, R2, R3 alone, and problems 7 and 8 keep their points and say where the mistake is."""
    p6, p7, p8 = grade_submission(transposed, [6, 7, 8], seed=SEED)
    lost = {r.check_id for r in p6.results if not r.passed}
    assert lost == {"p06.elementary_values", "p06.side_effects"}, lost
    assert {r.check_id: r.diagnosis for r in p6.results if r.diagnosis} == {"p06.elementary_values": "transpose or angle_sign"}
    for report in (p7, p8):
        assert report.score == report.auto_max_score, [(r.check_id, r.message[:300]) for r in report.results
                                                       if not r.passed]
        assert not any(r.diagnosis for r in report.results)
    for check_id in REACHED[7] + REACHED[8]:
        result = next(r for r in (*p7.results, *p8.results) if r.check_id == check_id)
        assert "Judged on your own R3, which differs from the reference's" in result.hint, result.hint
        assert ROOT_TITLE in result.hint, result.hint


@pytest.mark.slow
def test_a_transposed_R3_reaches_no_later_problem(transposed):
    """Every later problem that builds on R3 (trees, equations of motion, the wire's event) judges its own code on
    the student's R3: the checks it made fail keep their points, each pointing at problem 6's check.  Left out:
    simulations whose model is built on R3 (problem 24's and 38's runs, problem 46's run), where the reference's run
    on the student's R3 would take tens of seconds of calls into the sandbox."""
    numbers = sorted(n for n in REACHED if n > 8)
    for report in grade_submission(transposed, numbers, seed=SEED, workers=Fresh(count=2)):
        by_id = {r.check_id: r for r in report.results}
        for check_id in REACHED[report.problem]:
            result = by_id[check_id]
            assert result.status is Status.PASSED, (check_id, result.message[:500])
            assert ROOT_TITLE in result.hint, (check_id, result.hint)
        assert not any(r.diagnosis for r in report.results if not r.passed and r.check_id in REACHED[report.problem])


def test_a_later_mistake_of_its_own_is_judged_on_the_students_R3(tmp_path):
    """With R3 transposed and the Euler step of problem 8 wrong as well, part (a) fails: judged on the student's
    own R3 (the reference's run with it), it is still wrong, and the message says on what it was judged."""
    euler = ("problem_08.py", "return A_IC + dt * skew(I_omega) @ A_IC", "return A_IC - dt * skew(I_omega) @ A_IC")
    report = grade_submission(_with(tmp_path, [R3_TRANSPOSED, euler]), [8], seed=SEED)[0]
    by_id = {r.check_id: r for r in report.results}
    part_a = by_id["p08.part_a"]
    assert part_a.status is Status.FAILED, part_a.message
    assert "judged on your own R3" in part_a.message and ROOT_TITLE in part_a.message, part_a.message
    assert by_id["p08.euler_step"].status is Status.FAILED
    assert by_id["p08.part_b"].status is Status.PASSED and ROOT_TITLE in by_id["p08.part_b"].hint


#: where problem 8's check of its rate matrix is named, within problem 8's own report
RATE_MATRIX_TITLE = "see “cardan_rate_matrix(alpha, beta, gamma) gives C_omega = B @ (alpha_dot, beta_dot, gamma_dot)”"


def test_a_wrong_rate_matrix_costs_its_own_check_only_within_its_problem(tmp_path):
    """One mistake counts once within a problem too: problem 8's Cardan step and its part (b) use the student's own
    cardan_rate_matrix, which problem 8's check of it grades; they are judged on it, keep their points and point at
    that check, whose hint lists them (they had each cost their points as well)."""
    report = grade_submission(build_planted(_planted("p08-rate-matrix-transposed"), tmp_path / "pkg"), [8],
                              seed=SEED)[0]
    by_id = {r.check_id: r for r in report.results}
    assert {r.check_id for r in report.results if not r.passed} == {"p08.rate_matrix"}, \
        [(r.check_id, r.message[:300]) for r in report.results if not r.passed]
    assert by_id["p08.rate_matrix"].diagnosis == "transpose"
    for check_id in ("p08.cardan_step", "p08.part_b"):
        hint = by_id[check_id].hint
        assert "Judged on your own cardan_rate_matrix (error carried forward: full credit)" in hint, hint
        assert RATE_MATRIX_TITLE in hint, hint
    root = by_id["p08.rate_matrix"].hint
    assert "Later checks use your cardan_rate_matrix" in root and by_id["p08.part_b"].title in root, root


def test_an_error_the_students_own_rate_matrix_makes_the_reference_raise_too_is_carried(tmp_path):
    """A rate matrix with its cos(alpha) left out is singular at alpha = 0: the student's Cardan step raises there,
    and so does the reference's step on their rate matrix.  On random inputs, where the step is judged by its value
    elsewhere, the error is carried forward as a value would be: the step keeps its points (it had erred, costing
    them).  Part (b) is one run, judged on nothing else: its error stays the student's (``raise_for_credit`` of the
    hostile suite shows why).  The reference's rate matrix is the identity at zero angles; the student's is judged
    there as any value, not as a rotation (``ROTATION_VALUED``)."""
    singular = ("rotations.py", "[0.0, ca, cb * sa]", "[0.0, 0.0, cb * sa]")
    report = grade_submission(_with(tmp_path, [singular]), [8], seed=SEED)[0]
    by_id = {r.check_id: r for r in report.results}
    assert {r.check_id for r in report.results if not r.passed} == {"p08.rate_matrix", "p08.part_b"}, \
        [(r.check_id, r.message[:300]) for r in report.results if not r.passed]
    assert by_id["p08.part_b"].status is Status.ERROR and "LinAlgError" in by_id["p08.part_b"].message
    assert RATE_MATRIX_TITLE in by_id["p08.cardan_step"].hint, by_id["p08.cardan_step"].hint


def test_only_the_rotations_are_judged_as_rotations():
    """A value equal to the identity in the reference (problem 8's rate matrix at zero angles) is a rotation to be
    judged as one only where the function returns rotations."""
    mine, identity = np.diag([1.0, 0.0, 1.0]) + np.eye(3) * 0.1, np.eye(3)
    assert "not orthonormal" in flaw(mine, identity, "rotations.R3")
    assert "not orthonormal" in flaw(mine, identity)
    assert flaw(mine, identity, "rotations.cardan_rate_matrix") == ""


def test_a_shared_function_is_never_carried_into_the_check_that_grades_it(tmp_path):
    """Problem 8's exponential step is graded on random inputs through the reference's step, which calls the
    student's expm_skew: that check grades expm_skew itself, so it is judged against the reference and fails, where
    carrying the student's expm_skew into it would have passed it and left the mistake costing nothing."""
    sign = ("rotations.py", "return np.eye(3) + np.sin(angle) / angle * W + (1.0 - np.cos(angle)) / angle**2 * (W @ W)",
            "return np.eye(3) - np.sin(angle) / angle * W + (1.0 - np.cos(angle)) / angle**2 * (W @ W)")
    report = grade_submission(_with(tmp_path, [sign]), [8], seed=SEED)[0]
    by_id = {r.check_id: r for r in report.results}
    assert by_id["p08.exponential_step"].status is Status.FAILED, by_id["p08.exponential_step"].hint
    assert "Judged on your own" not in by_id["p08.exponential_step"].hint
    assert report.score < report.auto_max_score


def test_nothing_is_carried_on_an_R3_that_does_nothing(tmp_path):
    """An R3 of zeros is not a real result: problem 8's checks built on it fail against the reference, saying that
    nothing is carried forward on it."""
    zeros = ("rotations.py", "return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])", "return np.zeros((3, 3))")
    report = grade_submission(_with(tmp_path, [zeros]), [8], seed=SEED)[0]
    by_id = {r.check_id: r for r in report.results}
    for check_id in ("p08.part_a", "p08.part_c"):
        result = by_id[check_id]
        assert result.status is Status.FAILED, result.message
        assert "is all zeros: nothing is carried forward" in result.message, result.message
    assert not any("Judged on your own" in r.hint for r in report.results)


@pytest.mark.parametrize("returned, says", [("None", "is None"), ('"R3"', "is not numeric")])
def test_an_R3_that_returns_no_matrix_is_the_students_fault_where_a_later_answer_is_judged_on_it(tmp_path, returned,
                                                                                                 says):
    """An R3 left returning None (or text), with problem 8's own matrix typed in and its Euler step wrong: part (a)
    fails, and judging it on the student's R3 finds nothing to carry forward.  The comparison of that R3's value with
    the reference's must not be the grader's error (``None == array`` is an array, not a truth value)."""
    typed = ("problem_08.py", "A_IC0 = R3(np.pi / 2)",
             "A_IC0 = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])")
    euler = ("problem_08.py", "return A_IC + dt * skew(I_omega) @ A_IC", "return A_IC - dt * skew(I_omega) @ A_IC")
    stub = ("rotations.py", "return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])", f"return {returned}")
    report = grade_submission(_with(tmp_path, [stub, typed, euler]), [8], seed=SEED)[0]
    assert not [r.check_id for r in report.results if r.status is Status.GRADER_ERROR], [
        (r.check_id, r.message[:300]) for r in report.results if r.status is Status.GRADER_ERROR]
    part_a = next(r for r in report.results if r.check_id == "p08.part_a")
    assert part_a.status is Status.FAILED, part_a.message
    assert f"{says}: nothing is carried forward" in part_a.message, part_a.message


def test_the_kit_leaves_the_judgement_to_the_submission_and_names_the_function(transposed, kit_oracle,
                                                                             deferred_ids):
    """The kit cannot compose the reference's code with the student's R3: problems 7 and 8's checks built on it are
    deferred (not failed), naming R3 and problem 6's check; the parity of live and kit verdicts holds."""
    for problem in (7, 8):
        live, kit = grade_live_and_kit(problem, transposed, kit_oracle)
        assert_same_verdicts(f"transposed R3, p{problem:02d}", live, kit, deferred_ids)
        judged = {r.check_id: r for r in kit.results if r.status is Status.DEFERRED and r.check_id not in deferred_ids}
        assert set(judged) == set(REACHED[problem]), sorted(judged)
        for result in judged.values():
            assert result.message.startswith("judged on your own R3 when you submit"), result.message
            assert ROOT_TITLE in result.message and result.score == 0
        assert not [r.check_id for r in kit.results if r.status is Status.FAILED]


# ---------------------------------------------------------------------------------------------- the table


def _regions() -> dict:
    """``{"module.function": problem}`` of every module-level function of the reference with a solution region."""
    found = {}
    for path in sorted((ROOT / "reference").glob("*.py")):
        source = path.read_text()
        lines = source.splitlines()
        for node in ast.parse(source).body:
            if isinstance(node, ast.FunctionDef):
                body = "\n".join(lines[node.lineno - 1:node.end_lineno])
                match = re.search(r"# BEGIN SOLUTION problem (\d+)", body)
                if match:
                    found[f"{path.stem}.{node.name}"] = int(match.group(1))
    return found


def test_the_shared_functions_are_the_references_own():
    """Each shared function is a module-level function of the reference whose solution region belongs to the
    problem the table names, and is graded by a check of that problem."""
    regions = _regions()
    for function, (owner, check_id) in SHARED.items():
        assert regions.get(function) == owner, (function, regions.get(function), owner)
        assert check_id.startswith(f"p{owner:02d}.")
        assert check_id[4:] in {spec.name for spec in checks_of(problem_module(owner))}, check_id


def test_every_shared_function_a_later_problem_uses_is_listed():
    """A function with a solution region that another module of the reference imports (a later problem's module,
    or a module of the library that later problems use) is a shared function, unless it takes or gives objects
    that cannot travel to the sandbox (a tree, a function)."""
    regions = _regions()
    objects = {"tree.generalized_gravity", "problem_25.build_walker", "problem_37.robot_ode", "problem_37.simulate",
               "problem_44.make_contact_event", "problem_44.bar_ode"}
    missing = []
    for path in sorted((ROOT / "reference").glob("*.py")):
        later = int(path.stem[-2:]) if path.stem.startswith("problem_") else 99
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level == 1 and node.module:
                for alias in node.names:
                    function = f"{node.module}.{alias.name}"
                    if regions.get(function, later) < later and function not in SHARED and function not in objects:
                        missing.append((path.stem, function))
    assert not missing, missing


@pytest.mark.parametrize("mine, reference, says", [
    ([[0.0, 1, 0], [-1, 0, 0], [0, 0, 1]], [[0.0, -1, 0], [1, 0, 0], [0, 0, 1]], ""),
    ([[0.0, -1, 0], [1, 0, 0], [0, 0, -1]], [[0.0, -1, 0], [1, 0, 0], [0, 0, 1]], ""),
    ([[1.0, 0, 0], [0, 1, 0], [0, 0, 1]], [[1.0, 0, 0], [0, 1, 0], [0, 0, 1]], ""),
    ([[1.0, 0, 0], [0, 1, 0], [0, 0, 1]], [[0.0, -1, 0], [1, 0, 0], [0, 0, 1]], "is the identity"),
    ([[0.0, 0, 0], [0, 0, 0], [0, 0, 0]], [[0.0, -1, 0], [1, 0, 0], [0, 0, 1]], "is all zeros"),
    ([[0.5, 0.5, 0.5]] * 3, [[0.0, -1, 0], [1, 0, 0], [0, 0, 1]], "is one constant in every entry"),
    ([[2.0, 0, 0], [0, 1, 0], [0, 0, 1]], [[0.0, -1, 0], [1, 0, 0], [0, 0, 1]], "is not orthonormal"),
    ([1.0, float("nan"), 0.0], [1.0, 2.0, 3.0], "has NaN or infinite entries"),
    ([1.0, 2.0], [1.0, 2.0, 3.0], "has shape (2,), not (3,)"),
    ("x", [1.0, 2.0, 3.0], "is not numeric"),
    (None, [1.0, 2.0, 3.0], "is None"),
    ([[1.0, 2.0], 3.0], [[1.0, 2.0], 4.0], ""),
    ({"q": [0.0, 0.0]}, {"q": [1.0, 2.0]}, "['q'] is all zeros"),
])
def test_only_real_upstream_results_are_carried(mine, reference, says):
    found = flaw(mine, reference)
    assert (says in found) if says else found == "", found
