"""Exercise III, problems 11-15: bound vectors, rigid body kinematics, screw axis, torque-free dynamics."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reference import problem_11, problem_12, problem_14, problem_15
from reference.bound import BoundCoSys, BoundVector
from reference.rigid_body import RigidBodyDynamics, RigidBodyKinematics, fixed_step_count
from reference.rotations import R1, R2, R3, expm_skew, skew
from tests.strategies import finite, principal_moments, rotations, vectors

SETTINGS = settings(max_examples=40, deadline=None)

step_sizes = st.floats(1e-4, 0.1, **finite)
omegas = vectors(bound=1.5)


@st.composite
def bodies(draw):
    """Kinematic states with a random orientation and bounded velocities and accelerations."""
    return RigidBodyKinematics(
        A_IB=draw(rotations()),
        B_r_IB=draw(vectors()),
        B_v_B=draw(vectors(bound=3.0)),
        B_a_B=draw(vectors(bound=3.0)),
        B_omega_B=draw(vectors(bound=3.0)),
        B_omegaDot_B=draw(vectors(bound=3.0)),
    )


@st.composite
def well_conditioned_inertias(draw):
    """Inertia matrices with principal moments in [1, 3], in a random orientation."""
    A = draw(rotations())
    return A @ np.diag(draw(principal_moments(low=1.0, high=3.0))) @ A.T


def assert_rotation(A, atol=1e-12):
    np.testing.assert_allclose(A.T @ A, np.eye(3), atol=atol)
    assert np.linalg.det(A) == pytest.approx(1.0, abs=atol)


# --- problem 11 ----------------------------------------------------------------------------------------------


def test_p11_test_values():
    out = problem_11.solve()
    s3 = np.sqrt(3.0)
    np.testing.assert_allclose(out["I_v"], [1.0, -s3, 0.0], atol=1e-12)
    np.testing.assert_allclose(out["I_coords"], out["I_v"], atol=1e-12)
    np.testing.assert_allclose(out["I_r_IO"], [1.0 + s3 / 2, 2.5, 0.0], atol=1e-12)
    np.testing.assert_allclose(out["C_coords"], [0.0, -2.0, 0.0], atol=1e-12)


@SETTINGS
@given(rotations(), vectors(), rotations(), vectors(), vectors())
def test_p11_set_in_other_frame_and_read_back(A_IC, I_r_IC, A_IX, X_v, X_r):
    C, X = BoundCoSys(A_IC, I_r_IC), BoundCoSys(A_IX)
    v = BoundVector(C)
    v.set_vector(X_v, X)
    v.set_offset(X_r, X)
    np.testing.assert_allclose(v.get_coords(X), X_v, atol=1e-9)
    np.testing.assert_allclose(v.I_v, A_IX @ X_v, atol=1e-9)
    np.testing.assert_allclose(v.I_r_IO, I_r_IC + A_IX @ X_r, atol=1e-9)
    np.testing.assert_allclose(v.get_coords(), A_IC.T @ A_IX @ X_v, atol=1e-9)


@SETTINGS
@given(rotations(), rotations(), vectors(), vectors(), vectors())
def test_p11_vector_moves_with_its_cosys(A_IC, A_new, I_r_new, C_v, C_r_CO):
    C = BoundCoSys(A_IC)
    v = BoundVector(C, C_v, C_r_CO)
    C.set_transform(A_new)
    C.set_offset(I_r_new)
    np.testing.assert_allclose(v.get_coords(C), C_v, atol=1e-9)
    np.testing.assert_allclose(v.I_v, A_new @ C_v, atol=1e-9)
    np.testing.assert_allclose(v.I_r_IO, I_r_new + A_new @ C_r_CO, atol=1e-9)
    # the value of a vector does not depend on where it is drawn
    np.testing.assert_allclose(np.linalg.norm(v.I_v), np.linalg.norm(C_v), atol=1e-9)


# --- problem 12 ----------------------------------------------------------------------------------------------


def test_course_loop_step_counts():
    assert fixed_step_count(0.01, 1.0) == 100
    assert fixed_step_count(0.001, 3.0) == 3001
    assert fixed_step_count(0.001, 30.0) == 30000


P12_TARGETS = {
    1: ([[0.0707, 0, 0.9975], [0, 1, 0], [-0.9975, 0, 0.0707]], [0, 0, 0]),
    2: ([[0.0707, 0, 0.9975], [0, 1, 0], [-0.9975, 0, 0.0707]], [0.1301, 0, 1.5112]),
    3: ([[0.7368, 0, 0.6761], [0, 1, 0], [-0.6761, 0, 0.7368]], [0.6041, 0, 0.4219]),
}


@pytest.mark.parametrize("k", [1, 2, 3])
def test_p12_sheet_targets(k):
    A_IB, B_r_IB = problem_12.run_case(k)
    A_target, r_target = P12_TARGETS[k]
    np.testing.assert_allclose(A_IB, A_target, atol=5e-5)  # the sheet prints 4 decimals
    np.testing.assert_allclose(B_r_IB, r_target, atol=5e-5)


def test_p12_constant_rotation_is_exact():
    # constant omega: the exponential update is exact, A_IB = R2(1.5 rad) after 1 s
    A_IB, _ = problem_12.run_case(1)
    np.testing.assert_allclose(A_IB, R2(1.5), atol=1e-12)


@SETTINGS
@given(bodies(), step_sizes)
def test_p12_one_step_uses_old_values(body, dt):
    old = {k: np.copy(v) for k, v in vars(body).items()}
    body.integration_step(dt)
    Om = skew(old["B_omega_B"])
    np.testing.assert_allclose(body.B_r_IB, old["B_r_IB"] + dt * (old["B_v_B"] - Om @ old["B_r_IB"]), atol=1e-12)
    np.testing.assert_allclose(body.B_v_B, old["B_v_B"] + dt * (old["B_a_B"] - Om @ old["B_v_B"]), atol=1e-12)
    np.testing.assert_allclose(body.A_IB, old["A_IB"] @ expm_skew(dt * Om), atol=1e-12)
    np.testing.assert_allclose(body.B_omega_B, old["B_omega_B"] + dt * old["B_omegaDot_B"], atol=1e-12)


@SETTINGS
@given(bodies(), step_sizes, st.integers(1, 20))
def test_p12_integration_keeps_A_IB_orthonormal(body, dt, n):
    for _ in range(n):
        body.integration_step(dt)
    assert_rotation(body.A_IB, atol=1e-11)


@SETTINGS
@given(bodies(), vectors(bound=2.0))
def test_p12_point_velocity_and_acceleration_are_derivatives(body, B_r_BQ):
    # one step of +-h agrees with the motion to first order in h, so central differences of the point's position
    # and velocity reproduce its velocity and acceleration up to O(h^2)
    h = 1e-5

    def after(dt):
        b = RigidBodyKinematics(**{k: np.copy(v) for k, v in vars(body).items()})
        b.integration_step(dt)
        return b

    fwd, bwd = after(h), after(-h)
    v_fd = (fwd.position_of_point(B_r_BQ) - bwd.position_of_point(B_r_BQ)) / (2 * h)
    a_fd = (fwd.velocity_of_point(B_r_BQ) - bwd.velocity_of_point(B_r_BQ)) / (2 * h)
    np.testing.assert_allclose(v_fd, body.velocity_of_point(B_r_BQ), atol=1e-6)
    np.testing.assert_allclose(a_fd, body.acceleration_of_point(B_r_BQ), atol=1e-6)


def test_p12_position_of_point():
    body = RigidBodyKinematics(A_IB=R3(np.pi / 2), B_r_IB=[1.0, 0.0, 0.0])
    np.testing.assert_allclose(body.position_of_point([0.0, 2.0, 0.0]), [-2.0, 1.0, 0.0], atol=1e-12)


def test_p12_part_b_rolling_wheel():
    traces = problem_12.run_part_b()
    I_r_IB, I_r_IQ = traces["I_r_IB"], traces["I_r_IQ"]
    assert I_r_IB.shape == I_r_IQ.shape == (3002, 3)
    radius = 3 / 16
    # Q is body-fixed at distance 3/16 from B
    np.testing.assert_allclose(np.linalg.norm(I_r_IQ - I_r_IB, axis=1), radius, atol=1e-12)
    # B starts at the contact point; the wheel rolls towards -x: the centre moves straight at |v| = omega r = 0.75
    np.testing.assert_allclose(I_r_IB[0], 0.0, atol=1e-15)
    np.testing.assert_allclose(I_r_IQ[:, 1], radius, atol=0.01)  # Euler: a few per cent over 3 s
    assert I_r_IQ[-1, 0] == pytest.approx(-0.75 * 3.001, rel=0.05)
    # B stays on or above the ground and never higher than the top of the wheel
    assert I_r_IB[:, 1].min() > -0.01 and I_r_IB[:, 1].max() < 2 * radius + 0.01


# --- problems 13/14 ------------------------------------------------------------------------------------------


@SETTINGS
@given(bodies())
def test_p14_screw_axis(body):
    w = body.B_omega_B
    B_r_BT, B_v_T = body.screw_axis()
    if np.linalg.norm(w) < 1e-6:
        return
    # T moves along the axis: v_T is parallel to omega and is the velocity of the body point T
    np.testing.assert_allclose(np.cross(B_v_T, w), 0.0, atol=1e-9)
    np.testing.assert_allclose(body.A_IB @ B_v_T, body.velocity_of_point(B_r_BT), atol=1e-9)
    # the closest point of the axis to B, and the translation along the axis is the projection of v_B
    assert B_r_BT @ w == pytest.approx(0.0, abs=1e-9)
    np.testing.assert_allclose(B_v_T, (body.B_v_B @ w) / (w @ w) * w, atol=1e-9)


def test_p14_screw_axis_without_rotation():
    B_r_BT, B_v_T = RigidBodyKinematics(B_v_B=[1.0, 2.0, 3.0]).screw_axis()
    np.testing.assert_array_equal(B_r_BT, 0.0)
    np.testing.assert_array_equal(B_v_T, 0.0)


def test_p14_run():
    out = problem_14.run()
    assert out["I_r_IT"].shape == out["I_v_T"].shape == (101, 3)
    assert_rotation(out["A_IB"])
    I_omega = out["A_IB"] @ np.array([0.0, 1.5, 1.5])
    np.testing.assert_allclose(np.cross(out["I_v_T"][-1], I_omega), 0.0, atol=1e-9)
    np.testing.assert_allclose(out["I_v_T"][0], 0.0, atol=1e-15)  # at rest at t = 0


# --- problem 15 ----------------------------------------------------------------------------------------------


def test_p15_case_6_sheet_target():
    A_IB, B_r_IB = problem_15.run_case(6)
    target = [[0.1564, 0.9877, 0.0004], [-0.9876, 0.1564, 0.0145], [0.0142, -0.0026, 0.9999]]
    np.testing.assert_allclose(A_IB, target, atol=5e-5)  # the sheet prints 4 decimals
    np.testing.assert_allclose(B_r_IB, 0.0, atol=1e-12)


def test_p15_pure_translation_and_principal_rotation():
    # case 1: no rotation, in 1 s the body drifts by (1, 1, 1)
    body = problem_15.make_body(1)
    for _ in range(1000):
        body.compute_natural_dynamics()
        body.integration_step(0.001)
    np.testing.assert_allclose(body.A_IB, np.eye(3), atol=1e-15)
    np.testing.assert_allclose(body.B_r_IB, 1.0, atol=1e-9)
    # case 2: steady rotation about a principal axis, omega stays constant
    body = problem_15.make_body(2)
    for _ in range(1000):
        body.compute_natural_dynamics()
        body.integration_step(0.001)
    np.testing.assert_allclose(body.B_omega_B, [1.0, 0.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(body.A_IB, R1(1.0), atol=1e-9)


def _max_axis_deviation(k, dt=0.01, t_end=30.0):
    """Largest angle between omega and the principal axis it starts close to."""
    body = problem_15.make_body(k)
    axis = np.eye(3)[k - 4]
    worst = 0.0
    for _ in range(fixed_step_count(dt, t_end)):
        body.compute_natural_dynamics()
        body.integration_step(dt)
        w = body.B_omega_B
        worst = max(worst, np.arccos(min(1.0, abs(w @ axis) / np.linalg.norm(w))))
    return worst


def test_p15_stability_of_principal_axes():
    # model answer: rotation about the smallest (4) and the largest (6) principal axis is stable, the middle (5)
    # one is unstable (coarser steps suffice for the qualitative picture)
    assert _max_axis_deviation(4) < 0.1
    assert _max_axis_deviation(6) < 0.1
    assert _max_axis_deviation(5) > 1.0


def test_p15_accelerations_of_the_free_body():
    body = RigidBodyDynamics(2.0, np.diag([1.5, 2.0, 2.5]), B_a_B=[1.0, 2.0, 3.0], B_omega_B=[1.0, 1.0, 1.0])
    body.compute_natural_dynamics()
    np.testing.assert_array_equal(body.B_a_B, 0.0)
    # Euler's equations for principal axes: I1 w1' = (I2 - I3) w2 w3, cyclic
    np.testing.assert_allclose(body.B_omegaDot_B, [(2.0 - 2.5) / 1.5, (2.5 - 1.5) / 2.0, (1.5 - 2.0) / 2.5])
    np.testing.assert_allclose(body.angular_momentum(), [1.5, 2.0, 2.5])


def _simulate(body, dt, n):
    for _ in range(n):
        body.compute_natural_dynamics()
        body.integration_step(dt)
    return body


def _kinetic_energy(body):
    return 0.5 * body.m * body.B_v_B @ body.B_v_B + 0.5 * body.B_omega_B @ body.B_I_B @ body.B_omega_B


@SETTINGS
@given(well_conditioned_inertias(), omegas, vectors(bound=1.0), st.floats(0.5, 2.0, **finite))
def test_p15_energy_and_momentum_conserved_to_first_order(B_I_B, w0, v0, m):
    dt, n = 2e-3, 250  # T = 0.5 s
    body = RigidBodyDynamics(m, B_I_B, B_v_B=v0, B_omega_B=w0)
    E0, L0 = _kinetic_energy(body), body.A_IB @ body.angular_momentum()
    _simulate(body, dt, n)
    # Local errors per step: kinetic energy grows by dt^2/2 (m |w x v|^2 + wd^T I wd) with |wd| <= kappa |w|^2;
    # inertial angular momentum changes by -dt^2/2 A_IB w x (w x I w).  Summed over the run, the drift is
    # O(dt T); the tolerances are these leading-order bounds with a factor of 2.
    moments = np.linalg.eigvalsh(B_I_B)
    kappa, I_max = moments[-1] / moments[0], moments[-1]
    w = max(np.linalg.norm(w0), np.linalg.norm(body.B_omega_B))
    T = n * dt
    energy_tol = dt * T * (m * w**2 * (v0 @ v0) + I_max * kappa**2 * w**4)
    momentum_tol = dt * T * I_max * w**3
    assert abs(_kinetic_energy(body) - E0) <= energy_tol + 1e-12
    assert np.linalg.norm(body.A_IB @ body.angular_momentum() - L0) <= momentum_tol + 1e-12
    assert_rotation(body.A_IB, atol=1e-11)


def test_p15_conservation_errors_are_first_order():
    def errors(dt, t_end=2.0):
        body = problem_15.make_body(3)
        E0, L0 = _kinetic_energy(body), body.A_IB @ body.angular_momentum()
        _simulate(body, dt, round(t_end / dt))
        return abs(_kinetic_energy(body) - E0), np.linalg.norm(body.A_IB @ body.angular_momentum() - L0)

    coarse, fine = errors(0.004), errors(0.002)
    for e_coarse, e_fine in zip(coarse, fine):
        assert e_coarse / e_fine == pytest.approx(2.0, rel=0.1)
