"""The reference of problems 6-10 against the sheet and against the properties of rotations."""

import tomllib
from pathlib import Path

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from reference import problem_06, problem_07, problem_08, problem_09, problem_10
from reference.cosys import CoSys
from reference.rotations import (
    R1,
    R2,
    R3,
    cardan,
    cardan_rate_matrix,
    expm_skew,
    omega_body,
    omega_inertial,
    skew,
    unskew,
)

from ..strategies import angles, rotations, vectors

ROOT = Path(__file__).resolve().parents[2]
SHEET = {"I_v": (1.6319, 0.5195, 0.2588), "C1_v": (1.6730, -0.3660, 0.2588),
         "C2_v": (1.0, -0.3660, 1.3660), "C3_v": (1.0, 1.0, 1.0)}


def is_rotation(A, tol=1e-12):
    return np.allclose(A.T @ A, np.eye(3), atol=tol) and abs(np.linalg.det(A) - 1) < tol


@given(angles)
def test_elementary_rotations_are_rotations_about_their_axis(a):
    for k, R in enumerate((R1, R2, R3)):
        A = R(a)
        assert is_rotation(A)
        axis = np.eye(3)[k]
        assert np.allclose(A @ axis, axis)  # the axis stays fixed
        assert np.allclose(A @ R(-a), np.eye(3))  # the inverse is the rotation back


@given(angles, angles)
def test_elementary_rotations_compose_by_adding_angles(a, b):
    for R in (R1, R2, R3):
        assert np.allclose(R(a) @ R(b), R(a + b))


@given(angles, angles, angles)
def test_cardan_is_the_product_in_yaw_pitch_roll_order(a, b, g):
    A = cardan(a, b, g)
    assert is_rotation(A, 1e-12)
    assert np.allclose(A, R3(g) @ R2(b) @ R1(a))


@given(vectors(), vectors())
def test_skew_is_the_cross_product_and_unskew_inverts_it(w, x):
    assert np.allclose(skew(w) @ x, np.cross(w, x))
    assert np.allclose(unskew(skew(w)), w)
    assert np.allclose(skew(w), -skew(w).T)


@given(rotations(), vectors())
def test_angular_velocity_from_a_known_rotation(A, w):
    dA = skew(w) @ A  # rotating with the inertial angular velocity w
    assert np.allclose(omega_inertial(A, dA), w)
    assert np.allclose(omega_body(A, dA), A.T @ w)


@given(angles, st.floats(-1.4, 1.4), angles, vectors(bound=2.0))
@settings(max_examples=30)
def test_cardan_rate_matrix_matches_the_derivative_of_the_matrix(a, b, g, rates):
    h = 1e-6
    angles_ = np.array([a, b, g])
    dA = (cardan(*(angles_ + h * rates)) - cardan(*(angles_ - h * rates))) / (2 * h)
    assert np.allclose(omega_body(cardan(*angles_), dA), cardan_rate_matrix(a, b, g) @ rates, atol=1e-6)


@given(rotations(), vectors(bound=3.0), st.floats(0.0, 2.0))
def test_exponential_update_stays_orthonormal_and_is_exact(A, w, dt):
    step = problem_08.exponential_step(A, w, dt)
    assert is_rotation(step, 1e-10)
    assert np.allclose(expm_skew(dt * skew(w)) @ expm_skew(-dt * skew(w)), np.eye(3))
    # a constant angular velocity about a fixed axis: the rotation angle is |w| dt about w
    if np.linalg.norm(w) > 1e-6:
        axis = w / np.linalg.norm(w)
        assert np.allclose(step @ A.T @ axis, axis, atol=1e-9)


def test_problem_06_matches_the_sheet():
    got = problem_06.vectors()
    for key, target in SHEET.items():
        assert np.allclose(got[key], target, atol=5e-5), key


def test_problem_07_symbolic_omega_matches_the_sheet():
    import sympy as sp

    a, b, g, ad, bd, gd = problem_07.symbols()
    expected = sp.Matrix([ad - gd * sp.sin(b), bd * sp.cos(a) + gd * sp.cos(b) * sp.sin(a),
                          gd * sp.cos(a) * sp.cos(b) - bd * sp.sin(a)])
    assert sp.simplify(problem_07.derive()["C3_omega_IC3"] - expected) == sp.zeros(3, 1)


def test_problem_08_schemes():
    grown = problem_08.part_a()
    # each Euler step scales the plane normal to omega by sqrt(1 + dt^2 |omega|^2): det grows by (1 + dt^2)
    assert np.isclose(np.linalg.det(grown), (1 + problem_08.DT**2) ** problem_08.N_STEPS, rtol=1e-12)
    drifted = problem_08.part_b()["A_IC"]
    assert is_rotation(drifted, 1e-12) and not np.allclose(drifted, problem_08.A_IC0, atol=1e-2)
    assert np.allclose(problem_08.part_c(), R3(np.pi / 2), atol=1e-12)


@given(st.lists(rotations(), min_size=1, max_size=4))
def test_problem_09_relative_transforms_round_trip(relatives):
    frames = []
    for A_BC in relatives:
        frames.append(CoSys(A_BC, frames[-1]) if frames else CoSys(A_BC))
    for C in frames:
        for B in frames:
            A_BC = C.get_transform(B)
            assert np.allclose(A_BC, C.get_transform(B))
            assert np.allclose(B.get_transform() @ A_BC, C.get_transform())  # A_IB A_BC = A_IC
            moved = CoSys()
            moved.set_transform(A_BC, B)
            assert np.allclose(moved.get_transform(), C.get_transform())
    for parent, child, A in zip(frames, frames[1:], relatives[1:]):
        assert np.allclose(child.get_transform(parent), A)


def test_problem_09_reproduces_problem_06():
    for key, value in problem_09.vectors().items():
        assert np.allclose(value, problem_06.vectors()[key])


def test_problem_10_keys_are_computed_and_recorded():
    answers = tomllib.loads((ROOT / "reference" / "answers.toml").read_text())["problem_10"]
    assert (problem_10.answer_a(), problem_10.answer_b()) == (4, 2)
    assert (answers["a"], answers["b"]) == (problem_10.answer_a(), problem_10.answer_b())
    recorded = np.array(answers["c"])
    assert np.allclose(recorded, problem_10.nearest_rotation(problem_10.COURSE_C), atol=0.01)
    assert problem_10.orthonormality_defect(problem_10.COURSE_C) > 0.5  # the printed (c) is not a rotation
