"""Collision and contact (problems 42-45, 47): the sheet's targets (with the erratum of 43) and physics identities on
random states and parameters."""

import functools
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reference import problem_42, problem_43, problem_44, problem_45, problem_47

EXAMPLES = settings(max_examples=30, deadline=None)
ANSWERS = Path(__file__).resolve().parents[2] / "reference" / "answers.toml"
H = 1e-6

finite = st.floats(-2.0, 2.0)
positive = st.floats(0.2, 3.0)
angles = st.floats(-1.5, 1.5)
states = st.tuples(finite, finite, angles).map(np.array)
velocities = st.tuples(finite, finite, finite).map(np.array)


def gradient(function, q, h=H):
    return np.array([(function(q + h * e) - function(q - h * e)) / (2 * h) for e in np.eye(q.size)])


# ---------------------------------------------------------------- problem 42: the thrown ball


def test_thrown_ball_events_agree_with_a_fine_explicit_integration():
    """The apex and the landing of the tight solve_ivp run against a fourth-order Runge-Kutta loop at 1e-4 s with
    the crossings interpolated linearly."""
    run = problem_42.throw()
    dt, t, y = 1e-4, 0.0, np.array([0.0, problem_42.V0])
    crossings = {}
    while "land" not in crossings:
        k1 = problem_42.ball_ode(t, y)
        k2 = problem_42.ball_ode(t + dt / 2, y + dt / 2 * k1)
        k3 = problem_42.ball_ode(t + dt / 2, y + dt / 2 * k2)
        k4 = problem_42.ball_ode(t + dt, y + dt * k3)
        new = y + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        for key, k in (("apex", 1), ("land", 0)):
            if key not in crossings and y[k] > 0 >= new[k] and t > 0:
                crossings[key] = t + dt * y[k] / (y[k] - new[k])
        t, y = t + dt, new
    assert run["t_apex"] == pytest.approx(crossings["apex"], abs=1e-6)
    assert run["t_land"] == pytest.approx(crossings["land"], abs=1e-6)
    assert run["t"][-1] == pytest.approx(run["t_land"])
    assert run["v_land"] < 0 and run["height_apex"] > 0


def test_thrown_ball_without_drag_follows_the_parabola():
    run = problem_42.throw(v0=8.0, drag=0.0)
    g = problem_42.GRAVITY
    assert run["t_apex"] == pytest.approx(8.0 / g, abs=1e-8)
    assert run["height_apex"] == pytest.approx(64.0 / (2 * g), abs=1e-8)
    assert run["t_land"] == pytest.approx(16.0 / g, abs=1e-8)
    assert run["v_land"] == pytest.approx(-8.0, abs=1e-7)


def test_direction_key_is_computed_and_in_answers_toml():
    answers = tomllib.loads(ANSWERS.read_text())
    assert problem_42.answer_b() == answers["problem_42"]["b"] == 2
    assert problem_42.flight_with_landing_direction(0)[0] == 0.0
    assert problem_42.flight_with_landing_direction(-1)[0] == pytest.approx(problem_42.throw()["t_land"], abs=1e-9)


# ---------------------------------------------------------------- problem 43: the bar on its support


def test_sheet_accelerations_and_the_corrected_lambda():
    qdd, lam = problem_43.accelerations(problem_43.Q0, np.zeros(3))
    np.testing.assert_allclose(qdd, problem_43.SHEET_QDD, atol=5e-5)
    # erratum: the sheet prints 1.742, the correct value is 9.81 * 0.7071 / 4 = 1.7342
    assert lam == pytest.approx(9.81 * np.sqrt(0.5) / 4, abs=1e-12)
    assert lam == pytest.approx(1.7342, abs=5e-5)
    assert abs(lam - problem_43.SHEET_LAMBDA) > 5e-3


@EXAMPLES
@given(states, st.floats(-0.5, 0.5))
def test_jacobian_is_the_gradient_of_the_constraint(q, d):
    fd = gradient(lambda x: problem_43.constraint(x, d), q)
    np.testing.assert_allclose(problem_43.constraint_jacobian(q)[0], fd, atol=1e-7)


@EXAMPLES
@given(states, velocities)
def test_bias_is_the_second_derivative_along_qd(q, qd):
    h = 1e-4
    path = [problem_43.constraint(q + k * h * qd) for k in (-1, 0, 1)]
    curvature = (path[0] - 2 * path[1] + path[2]) / h ** 2
    assert problem_43.constraint_bias(q, qd)[0] == pytest.approx(curvature, abs=1e-5)


@EXAMPLES
@given(states, velocities, positive, positive, st.floats(1.0, 20.0))
def test_constrained_accelerations_meet_the_constraint_and_the_equations(q, qd, m, theta, g):
    qdd, lam = problem_43.accelerations(q, qd, m, theta, g)
    J, sigma = problem_43.constraint_jacobian(q), problem_43.constraint_bias(q, qd)
    M = problem_43.mass_matrix(m, theta)
    f, G = problem_43.forces(m, g)
    np.testing.assert_allclose(J @ qdd + sigma, 0.0, atol=1e-9)
    np.testing.assert_allclose(M @ qdd, f + G + J.T[:, 0] * lam, atol=1e-9)
    assert np.all(np.linalg.eigvalsh(M) > 0)


def test_the_bar_stays_on_its_support_in_the_run():
    run = problem_44.simulate()
    c = np.array([problem_43.constraint(q) for q in run["q"]])
    assert np.abs(c).max() < 1e-8


# ---------------------------------------------------------------- problem 44: the event


def test_the_bar_lands_flat_on_the_second_support():
    run = problem_44.simulate()
    event = problem_44.make_contact_event()
    assert event.terminal and event.direction == -1
    assert 0.6 < run["t_event"] < 0.75
    # on the first support the second contact's height is s sin phi: it closes as the bar lies flat (q- = (l-, d, 0))
    np.testing.assert_allclose(run["q_event"][1:], 0.0, atol=1e-8)
    assert 0.0 < run["q_event"][0] < problem_44.SUPPORT_DISTANCE
    assert run["qd_event"][2] < 0
    np.testing.assert_allclose(run["t"], np.arange(run["t"].size) * problem_44.T_STEP, atol=1e-12)
    assert run["t"][-1] <= run["t_event"]


def test_the_event_time_agrees_with_a_looser_method():
    from scipy.integrate import solve_ivp

    y0 = np.concatenate([problem_43.Q0, np.zeros(3)])
    other = solve_ivp(problem_44.bar_ode, (0, 1), y0, method="Radau", rtol=1e-9, atol=1e-11,
                      events=[problem_44.make_contact_event()])
    assert other.t_events[0][0] == pytest.approx(problem_44.simulate()["t_event"], abs=1e-7)


# ---------------------------------------------------------------- problem 45: the impact on the second support


@functools.cache
def answers_45():
    """The symbolic answers of problem 45, as functions of ``(s, l, d, m, theta, phid)`` (computed once)."""
    import sympy as sp

    expressions = {"J": problem_45.impact_jacobian(), "Lam": problem_45.impulses(),
                   "s_limit": sp.Matrix([problem_45.opening_limit()])}
    return {key: sp.lambdify(problem_45.symbols(), expression, "numpy") for key, expression in expressions.items()}


def evaluate(key, s, l, m, theta, phid, d=0.1):
    return np.array(answers_45()[key](s, l, d, m, theta, phid), dtype=float)


@settings(max_examples=15, deadline=None)
@given(st.floats(0.1, 2.0), st.floats(0.1, 1.5), positive, positive, st.floats(-3.0, -0.1))
def test_plastic_impulses_stop_both_contacts(s, l, m, theta, phid):
    J = evaluate("J", s, l, m, theta, phid)
    np.testing.assert_allclose(J, [[0, 1, -l], [0, 1, s - l]], atol=1e-12)
    Lam = evaluate("Lam", s, l, m, theta, phid)[:, 0]
    M_inv = np.diag([1 / m, 1 / m, 1 / theta])
    qd_minus = np.array([0.3, l * phid, phid])  # the left contact closed: c_dot- = (0, s phid)
    np.testing.assert_allclose(J @ qd_minus, [0.0, s * phid], atol=1e-12)
    qd_plus = qd_minus + M_inv @ J.T @ Lam
    np.testing.assert_allclose(J @ qd_plus, 0.0, atol=1e-9)


@settings(max_examples=15, deadline=None)
@given(st.floats(0.1, 1.5), positive, positive, st.floats(-3.0, -0.1), st.floats(0.05, 0.5))
def test_the_left_contact_opens_below_the_limit(l, m, theta, phid, margin):
    limit = float(evaluate("s_limit", 1.0, l, m, theta, phid)[0, 0])
    assert limit == pytest.approx(l + theta / (m * l), rel=1e-12)  # the model answer of problem data
    below, above = limit * (1 - margin), limit * (1 + margin)
    assert evaluate("Lam", below, l, m, theta, phid)[0, 0] < 0
    assert evaluate("Lam", above, l, m, theta, phid)[0, 0] > 0


# ---------------------------------------------------------------- problem 47: the bowling pin

pins = st.tuples(st.floats(0.5, 3.0), st.floats(0.01, 0.2), st.floats(0.03, 0.3), st.floats(0.1, 0.6))


@EXAMPLES
@given(states, pins)
def test_pin_jacobian_is_the_gradient_of_the_corner_height(q, pin):
    _, _, x_cog, y_cog = pin
    fd = gradient(lambda x: problem_47.constraint(x, x_cog, y_cog), q)
    np.testing.assert_allclose(problem_47.constraint_jacobian(q, x_cog, y_cog)[0], fd, atol=1e-7)


@EXAMPLES
@given(states, pins, st.floats(-2.0, 2.0), st.floats(-5.0, -1.0), st.floats(-0.5, 0.5))
def test_plastic_impact_of_the_pin(q, pin, xd, yd, phid):
    m, theta, x_cog, y_cog = pin
    qd_minus = np.array([xd, yd, phid])
    q_plus, qd_plus, Lam = problem_47.plastic_impact(q, qd_minus, m, theta, x_cog, y_cog)
    J = problem_47.constraint_jacobian(q, x_cog, y_cog)
    np.testing.assert_array_equal(q_plus, q)
    np.testing.assert_allclose(J @ qd_plus, 0.0, atol=1e-9)
    assert Lam > 0
    M = np.diag([m, m, theta])
    assert qd_plus @ M @ qd_plus <= qd_minus @ M @ qd_minus * (1 + 1e-12)
    if phid == 0.0:
        assert Lam == pytest.approx(problem_47.impulse(q[2], yd, m, theta, x_cog, y_cog), rel=1e-12)


@EXAMPLES
@given(pins, st.floats(-5.0, -0.5), st.floats(-1.2, 1.2))
def test_the_impulse_is_largest_with_the_corner_below_the_centre_of_gravity(pin, yd, phi):
    m, theta, x_cog, y_cog = pin
    phi_hat = problem_47.angle_of_max_impulse(x_cog, y_cog)
    assert phi_hat == pytest.approx(np.arctan(x_cog / y_cog))
    Lam_max = problem_47.max_impulse(yd, m)
    assert problem_47.impulse(phi_hat, yd, m, theta, x_cog, y_cog) == pytest.approx(Lam_max, rel=1e-12)
    assert problem_47.impulse(phi, yd, m, theta, x_cog, y_cog) <= Lam_max * (1 + 1e-12)
    # the closed form of problem data equals the general plastic impact with qd- = (0, yd-, 0)
    _, _, Lam = problem_47.plastic_impact(np.array([0.0, 0.0, phi]), np.array([0.0, yd, 0.0]), m, theta, x_cog, y_cog)
    assert problem_47.impulse(phi, yd, m, theta, x_cog, y_cog) == pytest.approx(Lam, rel=1e-12)
