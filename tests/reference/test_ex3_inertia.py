"""Exercise III, problems 16-20: inertia of simple bodies, representations, a non-accelerating point, composite
bodies and the properties of inertia matrices; the answers file of Exercise III."""

import functools
import tomllib
from importlib import resources

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from reference import problem_16, problem_17, problem_18, problem_19, problem_20
from reference.inertia import (
    centre_of_gravity,
    composite_inertia,
    cuboid_dimensions,
    cuboid_inertia,
    cuboid_inertia_symbolic,
    ellipsoid_dimensions,
    ellipsoid_inertia,
    ellipsoid_inertia_symbolic,
    inertia_representations,
    is_inertia_matrix,
    non_accelerating_point,
    parallel_axis,
    particles_dimensions,
    particles_inertia,
    particles_inertia_symbolic,
    point_masses_inertia,
    principal_axes,
)
from reference.rigid_body import RigidBodyKinematics
from tests.strategies import finite, inertia_matrices, principal_moments, rotations, vectors

SETTINGS = settings(max_examples=40, deadline=None)

positive = st.floats(0.1, 10.0, **finite)
masses = st.floats(0.1, 100.0, **finite)


def assert_valid_inertia(I):
    ok, reason = is_inertia_matrix(I, tol=1e-9)
    assert ok, reason


@functools.cache
def answers():
    return tomllib.loads(resources.files("reference").joinpath("answers.toml").read_text())


# --- problem 16 ----------------------------------------------------------------------------------------------


@SETTINGS
@given(masses, positive, positive, positive)
def test_p16_simple_bodies(m, a, b, c):
    cuboid = cuboid_inertia(m, a, b, c)
    ellipsoid = ellipsoid_inertia(m, a, b, c)
    particles = particles_inertia(m, a, b, c)
    for I in (cuboid, ellipsoid, particles):
        assert_valid_inertia(I)
    # six particles at the face centres have the cuboid's inertia; the ellipsoid's is 12/20 of it
    np.testing.assert_allclose(particles, cuboid, rtol=1e-12, atol=1e-12 * np.abs(cuboid).max())
    np.testing.assert_allclose(ellipsoid, 0.6 * cuboid, rtol=1e-12)


@SETTINGS
@given(masses, positive)
def test_p16_classic_formulas(m, d):
    # cube of edge d: m d²/6; sphere of diameter d (radius R = d/2): 2/5 m R²
    np.testing.assert_allclose(cuboid_inertia(m, d, d, d), m * d**2 / 6 * np.eye(3), rtol=1e-12)
    np.testing.assert_allclose(ellipsoid_inertia(m, d, d, d), 0.4 * m * (d / 2) ** 2 * np.eye(3), rtol=1e-12)


@functools.cache
def _lambdified():
    import sympy as sp

    def numeric(M):
        symbols = {s.name: s for s in M.free_symbols}
        return sp.lambdify([symbols[name] for name in "mabc"], M, "numpy")

    return {
        "cuboid": numeric(cuboid_inertia_symbolic()),
        "ellipsoid": numeric(ellipsoid_inertia_symbolic()),
        "particles": numeric(particles_inertia_symbolic()),
    }


def test_p16_symbolic_matrices_use_m_a_b_c():
    for M in problem_16.part_a().values():
        assert M.shape == (3, 3)
        assert {s.name for s in M.free_symbols} == {"m", "a", "b", "c"}
        assert M.is_symmetric()


@SETTINGS
@given(masses, positive, positive, positive)
def test_p16_symbolic_agrees_with_numeric(m, a, b, c):
    numeric = {"cuboid": cuboid_inertia, "ellipsoid": ellipsoid_inertia, "particles": particles_inertia}
    for name, f in _lambdified().items():
        expected = numeric[name](m, a, b, c)
        np.testing.assert_allclose(np.array(f(m, a, b, c), dtype=float), expected, rtol=1e-12,
                                   atol=1e-12 * np.abs(expected).max())


@SETTINGS
@given(masses, positive, positive, positive)
def test_p16_inverse_maps_round_trip(m, a, b, c):
    pairs = [(cuboid_inertia, cuboid_dimensions), (ellipsoid_inertia, ellipsoid_dimensions),
             (particles_inertia, particles_dimensions)]
    for forward, inverse in pairs:
        np.testing.assert_allclose(inverse(m, *np.diag(forward(m, a, b, c))), (a, b, c), rtol=1e-9)
    dims = problem_16.part_b(m, *np.diag(cuboid_inertia(m, a, b, c)))
    np.testing.assert_allclose(dims["cuboid"], (a, b, c), rtol=1e-9)
    np.testing.assert_allclose(dims["particles"], (a, b, c), rtol=1e-9)


@SETTINGS
@given(masses, principal_moments())
def test_p16_dimensions_reproduce_the_moments(m, moments):
    for forward, inverse in [(cuboid_inertia, cuboid_dimensions), (ellipsoid_inertia, ellipsoid_dimensions),
                             (particles_inertia, particles_dimensions)]:
        np.testing.assert_allclose(np.diag(forward(m, *inverse(m, *moments))), moments, rtol=1e-9)


def test_p16_inverse_rejects_impossible_moments():
    for inverse in (cuboid_dimensions, ellipsoid_dimensions, particles_dimensions):
        with pytest.raises(ValueError, match="triangle"):
            inverse(1.0, 1.0, 1.0, 3.0)


@SETTINGS
@given(st.lists(masses, min_size=1, max_size=6), st.data(), vectors())
def test_point_masses_inertia_definition(ms, data, shift):
    points = np.array([data.draw(vectors()) for _ in ms])
    I = point_masses_inertia(ms, points)
    r_G = centre_of_gravity(ms, points)
    expected = sum(m * ((r - r_G) @ (r - r_G) * np.eye(3) - np.outer(r - r_G, r - r_G)) for m, r in zip(ms, points))
    scale = 1e-9 * max(1.0, np.abs(expected).max())
    np.testing.assert_allclose(I, expected, atol=scale)
    # about the centre of gravity: independent of where the points are
    np.testing.assert_allclose(point_masses_inertia(ms, points + shift), I, atol=scale)
    np.testing.assert_allclose(I, I.T, atol=scale)


# --- problem 17 ----------------------------------------------------------------------------------------------


def _check_representations(B_I_G, m):
    reps = inertia_representations(B_I_G, m)
    tol = dict(rtol=1e-9, atol=1e-9 * np.abs(B_I_G).max())
    for name in ("six_points", "four_points"):
        ms, points = reps[name]["masses"], reps[name]["points"]
        assert ms.sum() == pytest.approx(m)
        np.testing.assert_allclose(ms @ points, 0.0, atol=1e-9 * m * max(1.0, np.abs(points).max()))
        I = point_masses_inertia(ms, points)
        np.testing.assert_allclose(I, B_I_G, **tol)
        assert_valid_inertia(I)
    for name, body in (("ellipsoid", ellipsoid_inertia), ("cuboid", cuboid_inertia)):
        rep = reps[name]
        V = rep["V"]
        np.testing.assert_allclose(V.T @ V, np.eye(3), atol=1e-12)
        assert np.linalg.det(V) == pytest.approx(1.0)
        dims = rep["axes"] if name == "ellipsoid" else rep["edges"]
        I = V @ body(rep["mass"], *dims) @ V.T
        np.testing.assert_allclose(I, B_I_G, **tol)
        assert_valid_inertia(I)


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_p17_sheet_matrices(k):
    _check_representations(problem_17.MATRICES[k], problem_17.MASS)
    assert set(problem_17.run_case(k)) == {"six_points", "four_points", "ellipsoid", "cuboid"}


@SETTINGS
@given(inertia_matrices(), masses)
def test_p17_representations_reproduce_random_inertias(B_I_G, m):
    _check_representations(B_I_G, m)


@SETTINGS
@given(rotations(), principal_moments())
def test_p17_principal_axes(A, moments):
    moments_out, V = principal_axes(A @ np.diag(moments) @ A.T)
    np.testing.assert_allclose(moments_out, np.sort(moments), rtol=1e-9)
    assert np.linalg.det(V) == pytest.approx(1.0)
    np.testing.assert_allclose(V @ np.diag(moments_out) @ V.T, A @ np.diag(moments) @ A.T, atol=1e-9)


# --- problem 18 ----------------------------------------------------------------------------------------------


@SETTINGS
@given(vectors(2, bound=5.0), vectors(2, bound=5.0), rotations())
def test_p18_point_does_not_accelerate(a, r, A_IB):
    assume(np.linalg.norm(r) > 1e-2 and a @ r >= 0.0)
    solutions = problem_18.solutions(a[0], a[1], r[0], r[1])
    assert solutions[0] == non_accelerating_point(a[0], a[1], r[0], r[1])
    assert solutions[0][0] >= 0.0
    for omega, omega_dot in solutions:
        body = RigidBodyKinematics(A_IB=A_IB, B_a_B=[a[0], a[1], 0.0], B_omega_B=[0.0, 0.0, omega],
                                   B_omegaDot_B=[0.0, 0.0, omega_dot])
        np.testing.assert_allclose(body.acceleration_of_point([r[0], r[1], 0.0]), 0.0, atol=1e-9)


def test_p18_no_solution():
    with pytest.raises(ValueError):
        non_accelerating_point(-1.0, 0.0, 1.0, 0.0)  # B accelerates away from Q
    with pytest.raises(ValueError):
        non_accelerating_point(1.0, 0.0, 0.0, 0.0)  # Q is B


# --- problem 19 ----------------------------------------------------------------------------------------------


def test_p19_answer():
    assert problem_19.answer() == pytest.approx(272.0, rel=1e-12)
    assert answers()["problem_19"]["I3_in_m_over_120"] == round(problem_19.answer())
    masses_, centres, _ = problem_19.blocks()
    assert masses_.sum() == pytest.approx(1.0)
    np.testing.assert_allclose(centre_of_gravity(masses_, centres), 0.0, atol=1e-15)


@SETTINGS
@given(masses, st.floats(0.0, 5.0, **finite))
def test_p19_inertia_is_valid_and_scales_with_mass(m, depth):
    I = problem_19.inertia(m, depth)
    assert_valid_inertia(I)
    assert I[2, 2] == pytest.approx(272 / 120 * m, rel=1e-12)  # independent of the depth


@SETTINGS
@given(masses, positive, positive, positive, st.floats(0.05, 0.95, **finite))
def test_p19_composite_of_a_split_cuboid(m, a, b, c, split):
    # cut the cuboid across the 1-axis at a fraction `split` of its length; the parts recombine to the whole
    a1, a2 = split * a, (1 - split) * a
    parts_m = [m * split, m * (1 - split)]
    centres = [[-a / 2 + a1 / 2, 0.0, 0.0], [a / 2 - a2 / 2, 0.0, 0.0]]
    inertias = [cuboid_inertia(parts_m[0], a1, b, c), cuboid_inertia(parts_m[1], a2, b, c)]
    np.testing.assert_allclose(composite_inertia(parts_m, centres, inertias), cuboid_inertia(m, a, b, c),
                               rtol=1e-9, atol=1e-12 * m * (a * a + b * b + c * c))


@SETTINGS
@given(inertia_matrices(), masses, vectors())
def test_p19_parallel_axis_adds_the_point_mass(I_G, m, r):
    I_O = parallel_axis(I_G, m, r)
    np.testing.assert_allclose(I_O - I_G, m * (r @ r * np.eye(3) - np.outer(r, r)), atol=1e-9 * max(1.0, m * r @ r))
    # moving away from the centre of gravity never decreases the moment about any axis
    assert np.linalg.eigvalsh(I_O - I_G).min() >= -1e-9 * max(1.0, m * r @ r)


# --- problem 20 ----------------------------------------------------------------------------------------------


@SETTINGS
@given(inertia_matrices())
def test_p20_accepts_inertia_matrices(I):
    assert is_inertia_matrix(I)[0]


@SETTINGS
@given(inertia_matrices(), st.floats(0.05, 1.0, **finite))
def test_p20_rejects_asymmetric(I, eps):
    J = I.copy()
    J[0, 1] += eps
    ok, reason = is_inertia_matrix(J)
    assert not ok and "symmetric" in reason


@SETTINGS
@given(rotations(), st.floats(0.1, 5.0, **finite), st.floats(0.1, 5.0, **finite), st.floats(0.01, 5.0, **finite))
def test_p20_rejects_indefinite_and_triangle_violations(A, I1, I2, excess):
    ok, reason = is_inertia_matrix(A @ np.diag([-I1, I2, I2]) @ A.T)
    assert not ok and "positive definite" in reason
    ok, reason = is_inertia_matrix(A @ np.diag([I1, I2, I1 + I2 + excess]) @ A.T)
    assert not ok and "triangle" in reason


def test_p20_planar_body_is_on_the_boundary():
    # a thin plate: I3 = I1 + I2 exactly
    assert is_inertia_matrix(cuboid_inertia(1.0, 2.0, 1.0, 0.0))[0]


def test_p20_key_a_is_computed_and_recorded():
    verdicts = problem_20.classify()
    assert verdicts[1][0]
    assert "symmetric" in verdicts[2][1]
    assert "triangle" in verdicts[3][1] and "triangle" in verdicts[4][1]
    assert problem_20.key_a() == [2, 3, 4]
    # the sheet asks for one option; as printed three qualify, and any of them is a correct answer
    assert answers()["problem_20"]["a"] in problem_20.key_a()
    assert answers()["problem_20"]["b"] == 4


def test_answers_file_free_text():
    data = answers()
    for problem, part in [("problem_12", "b"), ("problem_13", "choice_of_T"), ("problem_15", "a"),
                          ("problem_20", "a")]:
        text = data[problem]["free_text"][part]
        assert isinstance(text, str) and len(text) > 40
    assert "wheel" in data["problem_12"]["free_text"]["b"]
    assert "unstable" in data["problem_15"]["free_text"]["a"]
