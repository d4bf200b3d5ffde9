"""Reference of problems 21, 22, 26, 27, 28, 30 and 36: sheet targets, Jacobians, recursion, answer keys."""

import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reference import planar, problem_21, problem_22, problem_26, problem_27, problem_28, problem_30, problem_36
from reference.rotations import R2
from tests.strategies import angles, finite

ANSWERS = tomllib.loads((Path(planar.__file__).parent / "answers.toml").read_text())

lengths = st.floats(-1.0, 1.0, **finite)
link = st.floats(0.01, 1.0, **finite)
q_a = st.tuples(lengths, angles).map(np.array)
q_b = st.tuples(lengths, angles, lengths, angles).map(np.array)
joint_vectors = st.lists(st.tuples(lengths, angles), min_size=1, max_size=12).map(lambda pairs: np.array(pairs).ravel())


def central_jacobian(f, q, h=1e-6):
    q = np.asarray(q, dtype=float)
    columns = [(f(q + h * e) - f(q - h * e)) / (2 * h) for e in np.eye(q.size)]
    return np.column_stack(columns)


# --- problem 21 -----------------------------------------------------------------------------------------------


def test_p21_case_2_end_effector_matches_sheet():
    x_b = problem_21.solve(2)["x_b"]
    np.testing.assert_allclose(x_b[6:], problem_21.TARGET_END_EFFECTOR_CASE_2, atol=5e-5)


def test_p21_case_1_is_the_figure():
    # figure: P1 = (0, q1, 0), q2 = -45 deg, q4 = +45 deg, so the end effector points straight up again
    x = problem_21.solve(1)
    np.testing.assert_allclose(x["x_a"][:3], [0.0, 0.1, 0.0])
    np.testing.assert_allclose(x["x_b"][6:], [0.2 * np.sqrt(0.5), 0.1 + 0.2 * np.sqrt(0.5) + 0.15, 0.0], atol=1e-12)
    assert x["J_a"].shape == (6, 2) and x["J_b"].shape == (9, 4)


@settings(max_examples=60, deadline=None)
@given(q_a, link)
def test_p21_jacobian_a_is_derivative(q, d):
    np.testing.assert_allclose(planar.jacobian_a(q, d), central_jacobian(lambda p: planar.chain_a(p, d), q), atol=1e-7)


@settings(max_examples=60, deadline=None)
@given(q_b, link)
def test_p21_jacobian_b_is_derivative(q, d):
    np.testing.assert_allclose(planar.jacobian_b(q, d), central_jacobian(lambda p: planar.chain_b(p, d), q), atol=1e-7)


@settings(max_examples=60, deadline=None)
@given(lengths, angles, link)
def test_p21_case_b_with_q3_q4_zero_reduces_to_case_a(q1, q2, d):
    x_a, J_a = planar.chain_a([q1, q2], d), planar.jacobian_a([q1, q2], d)
    x_b, J_b = planar.chain_b([q1, q2, 0.0, 0.0], d), planar.jacobian_b([q1, q2, 0.0, 0.0], d)
    a_rows, b_rows = [0, 1, 2, 3, 4, 5], [0, 1, 2, 6, 7, 8]
    np.testing.assert_allclose(x_b[b_rows], x_a[a_rows], atol=1e-12)
    np.testing.assert_allclose(J_b[b_rows][:, :2], J_a, atol=1e-12)
    # P2 coincides with P1 but carries the orientation q2 of the second segment
    np.testing.assert_allclose(x_b[3:6], [0.0, q1, q2], atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(q_b, link)
def test_p21_case_b_with_final_link_shrunk_to_zero_ends_at_p2(q, d):
    x_b = planar.chain_b(q, 0.0)
    np.testing.assert_allclose(x_b[6:8], x_b[3:5], atol=1e-12)
    np.testing.assert_allclose(np.hypot(*(planar.chain_b(q, d)[6:8] - x_b[3:5])), d, rtol=1e-12)


# --- problem 22 -----------------------------------------------------------------------------------------------


def test_p22_q3_matches_sheet_target_both_ways():
    for recursive in (False, True):
        np.testing.assert_allclose(problem_22.solve(recursive)["q3"], problem_22.TARGET_Q3, atol=5e-5)


def test_p22_q1_is_p21_case_1():
    np.testing.assert_allclose(problem_22.solve()["q1"], problem_21.solve(1)["x_b"][6:], atol=1e-12)


@settings(max_examples=80, deadline=None)
@given(joint_vectors, link)
def test_p22_loop_and_recursion_agree(q, d):
    np.testing.assert_allclose(planar.end_effector_recursive(q, d), planar.end_effector_loop(q, d), atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(q_b, link)
def test_p22_two_stages_are_p21_case_b(q, d):
    x_b = planar.chain_b(q, d)
    np.testing.assert_allclose(planar.end_effector_loop(q, d), x_b[6:], atol=1e-12)
    np.testing.assert_allclose(planar.point_k(q, 1), [*x_b[0:2], x_b[5]], atol=1e-12)
    np.testing.assert_allclose(planar.point_k(q, 2)[:2], x_b[3:5], atol=1e-12)


@settings(max_examples=40, deadline=None)
@given(joint_vectors, link)
def test_p22_end_effector_is_last_point_plus_final_link(q, d):
    n = q.size // 2
    x, y, gamma = planar.point_k(q, n)
    expected = [x - d * np.sin(gamma), y + d * np.cos(gamma), gamma]
    np.testing.assert_allclose(planar.end_effector_loop(q, d), expected, atol=1e-12)
    np.testing.assert_allclose(gamma, np.sum(q[1::2]), atol=1e-12)


def test_p22_point_k_recurses_down_to_the_origin(monkeypatch):
    calls = []
    recurse = planar.point_k

    def counting(q, k):
        calls.append(k)
        return recurse(q, k)

    monkeypatch.setattr(planar, "point_k", counting)
    q = problem_22.joint_vector("q3")
    planar.end_effector_recursive(q, problem_22.D)
    assert calls == [6, 5, 4, 3, 2, 1, 0]


def test_p22_rejects_odd_joint_vectors():
    with pytest.raises(ValueError):
        planar.end_effector_recursive([0.1, 0.2, 0.3], 0.1)
    with pytest.raises(ValueError):
        planar.end_effector_loop([0.1, 0.2, 0.3], 0.1)


# --- problem 26 -----------------------------------------------------------------------------------------------


@settings(max_examples=60, deadline=None)
@given(angles, angles, link, link, link)
def test_p26_jacobian_is_derivative(beta, phi, l1, l2, l3):
    def f(q):
        return problem_26.position(q[0], q[1], l1, l2, l3)

    J = problem_26.jacobian(beta, phi, l1, l2, l3)
    np.testing.assert_allclose(J, central_jacobian(f, [beta, phi]), atol=1e-7)


@settings(max_examples=40, deadline=None)
@given(angles, angles, link, link, link)
def test_p26_seat_stays_on_its_sphere_and_circle(beta, phi, l1, l2, l3):
    x = problem_26.position(beta, phi, l1, l2, l3)
    # the seat is l3 from the chain's suspension point, which circles the axis at radius l2, height l1
    suspension = np.array([l2 * np.sin(beta), l1, l2 * np.cos(beta)])
    np.testing.assert_allclose(np.linalg.norm(x - suspension), l3, rtol=1e-12)
    np.testing.assert_allclose(problem_26.position(0.0, 0.0, l1, l2, l3), [0.0, l1 - l3, l2], atol=1e-15)


# --- problem 27 -----------------------------------------------------------------------------------------------

COURSE_KEYS_27 = {"a": 4, "b": 1, "c": 1, "d": 3, "e": 2}


def test_p27_computed_keys_are_the_course_keys():
    assert problem_27.answers() == COURSE_KEYS_27


def test_p27_a_jacobian_from_geometry():
    np.testing.assert_allclose(
        problem_27.jacobian_a(), [[-2.83, 0.26, 3.78], [5.17, 0.97, 3.35], [1.0, 0.0, 1.0]], atol=1e-12
    )


def test_p27_d_matches_finite_differences_of_the_ball():
    def ball(q):
        phi, gamma = q
        return R2(phi) @ np.array([np.sin(gamma), -np.cos(gamma), 0.0])

    np.testing.assert_allclose(problem_27.governor_jacobian(), central_jacobian(ball, [0.0, np.pi / 6]), atol=1e-8)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_p27_e_only_statement_2_fails_on_any_motion(seed):
    residuals = problem_27.frame_derivative_residuals(seed=seed, t=0.1 * seed)
    assert residuals[2] > 1e-2
    assert all(residuals[k] < 1e-6 for k in (1, 3, 4))


def test_p27_c_only_option_1_is_wrong():
    residuals = problem_27.bias_acceleration_residuals()
    assert residuals[1] > 1e-2 and max(residuals[k] for k in (2, 3, 4)) < 1e-12


# --- problems 28, 30, 36: ports and answers -------------------------------------------------------------------


def test_p28_port_walks_the_list_from_red():
    assert problem_28.expected_output().splitlines() == ["Rainbow:", "red", "yellow", "blue", "Sandwich"]


def test_p36_ports():
    assert problem_36.part1_output().splitlines() == [
        "Alice is figthing The Red Queen",
        "The Red Queen is fighting Alice",
    ]
    assert problem_36.part2_output().splitlines() == [
        "TweedleDum and TweedleDee",
        "    Agreed to have a battle",
        "For TweedleDee said TweedleDum",
        "    Had spoiled his nice new rattle",
    ]


def test_p36_tweedles_are_each_others_foes():
    dum = problem_36.TweedleDum()
    assert isinstance(dum.foe, problem_36.TweedleDee) and dum.foe.foe is dum


def test_p30_diagram_has_the_two_chains_of_the_problem_data():
    assert problem_30.base_classes("LinkedRigidBodyDynamicsCLASS_v2") == {
        "RigidBodyDynamicsCLASS_v2",
        "RigidBodyKinematicsCLASS_v2",
        "LinkedBodyObjectCLASS_v2",
    }
    assert problem_30.base_classes("LinkedRotationalJointCLASS_v2") == {
        "LinkedGenericJointCLASS_v2",
        "LinkedJointObjectCLASS_v2",
    }


def test_answers_file_agrees_with_the_computations():
    assert ANSWERS["problem_27"] == problem_27.answers()
    assert ANSWERS["problem_28"]["output"] == problem_28.expected_output()
    assert ANSWERS["problem_36"]["part1"] == problem_36.part1_output()
    assert ANSWERS["problem_36"]["part2"] == problem_36.part2_output()
    assert [tuple(pair) for pair in ANSWERS["problem_36"]["hierarchy"]] == problem_36.class_hierarchy()
    assert [tuple(pair) for pair in ANSWERS["problem_30"]["diagram"]] == problem_30.class_diagram()


def test_answers_file_free_text_is_the_model_answers():
    assert ANSWERS["problem_36"]["free_text"]["c"] == problem_36.ANSWER_C
    assert ANSWERS["problem_30"]["free_text"] == {
        "c": problem_30.ANSWER_C,
        "d": problem_30.ANSWER_D,
        "e": problem_30.ANSWER_E,
    }
