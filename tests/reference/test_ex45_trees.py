"""Kinematic trees (problems 24, 25, 31-35): physics identities on random trees and the sheet's configurations."""

import functools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from reference import problem_24, problem_25, problem_31, problem_32, problem_33, problem_34, problem_35
from reference.rotations import R3, skew, unskew
from reference.tree import (
    Body,
    KinematicTree,
    RigidJoint,
    RotationalJoint,
    generalized_gravity,
    tree_lines,
)
from tests.strategies import JOINT_CLASSES, angles, make_joint, rotations, trees, vectors

EXAMPLES = settings(max_examples=40, deadline=None)
E3 = np.eye(3)


# ---------------------------------------------------------------- strategies: random trees and states


@st.composite
def tree_states(draw):
    """``(tree, q, qd, qdd)`` with coordinates, velocities and accelerations in [-2, 2]."""
    tree = draw(trees())
    q, qd, qdd = (draw(vectors(tree.nq, 2.0)) for _ in range(3))
    return tree, q, qd, qdd


def snapshot(tree, q, qd=None, qdd=None):
    """Inertial states of all bodies as a dict of stacked arrays (independent of later passes)."""
    tree.forward_kinematics(q, qd, qdd)
    names = ["A_IB", "I_r_IB"]
    if qd is not None:
        names += ["I_v_B", "I_omega_B", "I_a_B", "I_omegaDot_B", "I_J_S", "I_J_R"]
    return {name: np.array([getattr(body, name) for body in tree.bodies]) for name in names}


def central_difference(f, x, h=1e-6):
    """Derivative of the array-valued ``f`` at the scalar ``x``."""
    return (f(x + h) - f(x - h)) / (2.0 * h)


def potential_gradient(tree, q, I_grav):
    """Finite-difference gradient of the potential energy ``V(q) = -sum(m I_grav . I_r_IB)``."""

    def potential(x):
        tree.forward_kinematics(x)
        return -sum(body.m * I_grav @ body.I_r_IB for body in tree.bodies)

    return np.array([central_difference(lambda h: potential(q + h * e), 0.0) for e in np.eye(tree.nq)]).reshape(-1)


# ---------------------------------------------------------------- identities on random trees


@EXAMPLES
@given(tree_states())
def test_jacobians_are_derivatives_of_positions_and_orientations(state):
    tree, q, _, _ = state
    s = snapshot(tree, q, np.zeros(tree.nq))
    for i in range(tree.nq):
        e = np.eye(tree.nq)[i]
        dr = central_difference(lambda h: snapshot(tree, q + h * e)["I_r_IB"], 0.0)
        dA = central_difference(lambda h: snapshot(tree, q + h * e)["A_IB"], 0.0)
        np.testing.assert_allclose(s["I_J_S"][:, :, i], dr, atol=1e-6)
        # skew(I_omega) = dA_IB/dt A_IB.T, column i of I_J_R is the angular velocity for qd = e_i
        omegas = np.array([unskew(dA_k @ A_k.T) for dA_k, A_k in zip(dA, s["A_IB"])])
        np.testing.assert_allclose(s["I_J_R"][:, :, i], omegas, atol=1e-6)


@EXAMPLES
@given(tree_states())
def test_velocities_are_jacobian_times_qd(state):
    tree, q, qd, qdd = state
    tree.forward_kinematics(q, qd, qdd)
    for body in tree.bodies:
        np.testing.assert_allclose(body.B_v_B, body.B_J_S @ qd, atol=1e-10)
        np.testing.assert_allclose(body.B_omega_B, body.B_J_R @ qd, atol=1e-10)


@EXAMPLES
@given(tree_states())
def test_bias_accelerations_are_accelerations_minus_jacobian_times_qdd(state):
    tree, q, qd, qdd = state
    full = snapshot(tree, q, qd, qdd)
    bias = snapshot(tree, q, qd)  # qdd defaults to zero
    np.testing.assert_allclose(full["I_a_B"] - full["I_J_S"] @ qdd, bias["I_a_B"], atol=1e-9)
    np.testing.assert_allclose(full["I_omegaDot_B"] - full["I_J_R"] @ qdd, bias["I_omegaDot_B"], atol=1e-9)
    # the Jacobians do not depend on the velocities
    np.testing.assert_allclose(full["I_J_S"], snapshot(tree, q, np.zeros(tree.nq))["I_J_S"], atol=1e-12)


@EXAMPLES
@given(tree_states())
def test_velocities_and_accelerations_are_time_derivatives_along_a_path(state):
    tree, q, qd, qdd = state

    def at(t):
        """State on the path q(t) = q + qd t + qdd t^2 / 2."""
        return snapshot(tree, q + qd * t + 0.5 * qdd * t**2, qd + qdd * t, qdd)

    s = at(0.0)
    np.testing.assert_allclose(central_difference(lambda t: at(t)["I_r_IB"], 0.0), s["I_v_B"], atol=1e-6)
    np.testing.assert_allclose(central_difference(lambda t: at(t)["I_v_B"], 0.0), s["I_a_B"], atol=1e-5)
    np.testing.assert_allclose(central_difference(lambda t: at(t)["I_omega_B"], 0.0), s["I_omegaDot_B"], atol=1e-5)
    dA = central_difference(lambda t: at(t)["A_IB"], 0.0)
    np.testing.assert_allclose(
        [unskew(dA_k @ A_k.T) for dA_k, A_k in zip(dA, s["A_IB"])], s["I_omega_B"], atol=1e-6
    )


@EXAMPLES
@given(tree_states())
def test_orientations_stay_proper_rotations(state):
    tree, q, qd, qdd = state
    tree.forward_kinematics(q, qd, qdd)
    for body in tree.bodies:
        np.testing.assert_allclose(body.A_IB.T @ body.A_IB, E3, atol=1e-12)
        assert np.linalg.det(body.A_IB) == pytest.approx(1.0, abs=1e-12)
        assert body.B_J_S.shape == body.B_J_R.shape == (3, tree.nq)


@EXAMPLES
@given(tree_states(), st.data())
def test_rigid_joint_transports_the_predecessor_state(state, data):
    tree, q, qd, qdd = state
    parent = tree.bodies[data.draw(st.integers(0, len(tree.bodies) - 1))]
    child = Body("attached", 1.0)
    joint = RigidJoint(
        parent,
        child,
        P_r_PDp=data.draw(vectors(3, 1.0)),
        A_PDp=data.draw(rotations()),
        S_r_SDs=data.draw(vectors(3, 1.0)),
        A_SDs=data.draw(rotations()),
    )
    tree = KinematicTree(tree.root)
    tree.forward_kinematics(q, qd, qdd)
    A_IS = parent.A_IB @ joint.A_PDp @ joint.A_SDs.T
    d = parent.A_IB @ joint.P_r_PDp - A_IS @ joint.S_r_SDs
    w, dw = parent.I_omega_B, parent.I_omegaDot_B
    np.testing.assert_allclose(child.A_IB, A_IS, atol=1e-12)
    np.testing.assert_allclose(child.I_r_IB, parent.I_r_IB + d, atol=1e-12)
    np.testing.assert_allclose(child.I_omega_B, w, atol=1e-10)
    np.testing.assert_allclose(child.I_omegaDot_B, dw, atol=1e-10)
    np.testing.assert_allclose(child.I_v_B, parent.I_v_B + np.cross(w, d), atol=1e-10)
    np.testing.assert_allclose(child.I_a_B, parent.I_a_B + np.cross(dw, d) + np.cross(w, np.cross(w, d)), atol=1e-9)
    np.testing.assert_allclose(child.I_J_R, parent.I_J_R, atol=1e-10)
    np.testing.assert_allclose(child.I_J_S, parent.I_J_S - skew(d) @ parent.I_J_R, atol=1e-10)


@EXAMPLES
@given(tree_states())
def test_rigid_joint_without_offsets_copies_the_state(state):
    tree, q, qd, qdd = state
    parent = tree.bodies[-1]
    child = Body("copy")
    RigidJoint(parent, child)
    KinematicTree(tree.root).forward_kinematics(q, qd, qdd)
    for name in ("A_IB", "B_r_IB", "B_v_B", "B_omega_B", "B_a_B", "B_omegaDot_B", "B_J_S", "B_J_R"):
        np.testing.assert_allclose(getattr(child, name), getattr(parent, name), atol=1e-12)


@EXAMPLES
@given(st.lists(st.tuples(st.floats(0.1, 2.0), st.floats(0.0, 1.0), angles), min_size=1, max_size=5), st.data())
def test_chain_of_rotational_joints_matches_planar_closed_form(links, data):
    """Links of length L_k with the body frame at fraction c_k along the link: positions, orientations,
    velocities and Jacobians of the planar serial chain."""
    n = len(links)
    lengths, fractions, q = (np.array(column) for column in zip(*links))
    qd = data.draw(vectors(n, 2.0))
    ground = Body("ground")
    predecessor, previous_length = ground, 0.0
    for k, (length, c) in enumerate(zip(lengths, fractions)):
        link = Body(f"link_{k}")
        RotationalJoint(predecessor, link, P_r_PDp=(previous_length, 0, 0), S_r_SDs=(-c * length, 0, 0), q_index=[k])
        predecessor, previous_length = link, (1.0 - c) * length
    tree = KinematicTree(ground).forward_kinematics(q, qd)

    theta, theta_dot = np.cumsum(q), np.cumsum(qd)
    joints = np.zeros((n, 3))  # inertial joint positions
    for k in range(1, n):
        joints[k] = joints[k - 1] + lengths[k - 1] * np.array([np.cos(theta[k - 1]), np.sin(theta[k - 1]), 0.0])
    for k in range(n):
        link = tree[f"link_{k}"]
        axis = np.array([np.cos(theta[k]), np.sin(theta[k]), 0.0])
        r = joints[k] + fractions[k] * lengths[k] * axis
        np.testing.assert_allclose(link.A_IB, R3(theta[k]), atol=1e-12)
        np.testing.assert_allclose(link.I_r_IB, r, atol=1e-12)
        np.testing.assert_allclose(link.I_omega_B, [0.0, 0.0, theta_dot[k]], atol=1e-12)
        J_S = np.zeros((3, n))
        J_R = np.zeros((3, n))
        for i in range(k + 1):
            J_S[:, i] = np.cross([0.0, 0.0, 1.0], r - joints[i])
            J_R[2, i] = 1.0
        np.testing.assert_allclose(link.I_J_S, J_S, atol=1e-12)
        np.testing.assert_allclose(link.I_J_R, J_R, atol=1e-12)


@EXAMPLES
@given(tree_states())
def test_generalized_gravity_is_minus_gradient_of_potential(state):
    tree, q, _, _ = state
    I_grav = np.array([0.3, -9.81, 0.5])
    np.testing.assert_allclose(generalized_gravity(tree, q, I_grav), -potential_gradient(tree, q, I_grav), atol=1e-6)


def test_positions_only_pass_clears_motion():
    tree = problem_24.build_triple_pendulum()
    tree.forward_kinematics(problem_24.Q, np.ones(3))
    assert tree["link_3"].B_J_S is not None
    tree.forward_kinematics(problem_24.Q)
    assert all(body.B_v_B is None and body.B_J_S is None for body in tree.bodies)


def test_tree_checks_coordinates_and_lines():
    a, b = Body("a"), Body("b")
    RotationalJoint(a, b, q_index=[1])
    with pytest.raises(ValueError):
        KinematicTree(a)
    with pytest.raises(ValueError):
        RotationalJoint(a, Body("c"), q_index=[0, 1])
    tree = problem_24.build_triple_pendulum().forward_kinematics(problem_24.Q)
    lines = tree_lines(tree)
    assert lines.shape == (9, 2, 3)
    # consecutive segments join up: predecessor -> Dp -> Ds -> successor
    np.testing.assert_allclose(lines[1:, 0][[0, 1, 3, 4, 6, 7]], lines[:-1, 1][[0, 1, 3, 4, 6, 7]], atol=1e-12)
    np.testing.assert_allclose(lines[-1, 1], tree["link_3"].I_r_IB, atol=1e-12)


# ---------------------------------------------------------------- problems 24 and 31: triple pendulum


def pendulum_closed_form(q, qd, qdd):
    """Planar triple pendulum (links 1 m, centres of gravity in the middle, angles from the -y axis):
    ``(theta, joints, r, v, a)`` with the joint positions and the centres of gravity's motion (x, y)."""
    theta, w, dw = np.cumsum(q), np.cumsum(qd), np.cumsum(qdd)
    along = np.stack([np.sin(theta), -np.cos(theta)], axis=1)
    across = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    levers = np.tril(np.ones((3, 3)), -1) + 0.5 * np.eye(3)  # lever of link l for the centre of gravity of link k
    joints = np.tril(np.ones((3, 3)), -1) @ along
    r = levers @ along
    v = levers @ (across * w[:, None])
    a = levers @ (across * dw[:, None] - along * w[:, None] ** 2)
    return theta, joints, r, v, a


def test_problem_24_triple_pendulum_positions():
    result = problem_24.solve()
    theta, _, r, _, _ = pendulum_closed_form(problem_24.Q, np.zeros(3), np.zeros(3))
    np.testing.assert_allclose(result["ground"]["I_r_IB"], np.zeros(3), atol=1e-15)
    np.testing.assert_allclose(result["ground"]["A_IB"], E3, atol=1e-15)
    for k in range(3):
        link = result[f"link_{k + 1}"]
        np.testing.assert_allclose(link["I_r_IB"][:2], r[k], atol=1e-12)
        np.testing.assert_allclose(link["A_IB"], problem_24.A_PDP_FIRST @ R3(theta[k]), atol=1e-12)
    np.testing.assert_allclose(result["link_1"]["I_r_IB"], [0.25, -0.4330127, 0.0], atol=1e-7)
    np.testing.assert_allclose(result["link_3"]["I_r_IB"], [0.5947, -2.1855, 0.0], atol=1e-4)


def test_problem_31_link_3_jacobians_velocities_accelerations():
    result = problem_31.solve()
    _, joints, r, v, a = pendulum_closed_form(problem_31.Q, problem_31.QD, problem_31.QDD)
    J_S = np.array([[-(r[2] - p)[1], (r[2] - p)[0], 0.0] for p in joints]).T
    np.testing.assert_allclose(result["I_J_S"], J_S, atol=1e-12)
    expected = [[2.1855, 1.3195, 0.3536], [0.5947, 0.0947, 0.3536], [0, 0, 0]]
    np.testing.assert_allclose(result["I_J_S"], expected, atol=1e-4)
    np.testing.assert_allclose(result["I_J_R"], [[0, 0, 0], [0, 0, 0], [1, 1, 1]], atol=1e-15)
    np.testing.assert_allclose(result["I_v_B"][:2], v[2], atol=1e-12)
    np.testing.assert_allclose(result["I_a_B"][:2], a[2], atol=1e-12)
    np.testing.assert_allclose(result["I_omega_B"], [0, 0, 1], atol=1e-15)
    np.testing.assert_allclose(result["I_omegaDot_B"], [0, 0, 1], atol=1e-15)
    J_S_31, J_R_31 = problem_31.link3_jacobians()
    np.testing.assert_allclose(J_S_31, result["I_J_S"], atol=1e-15)
    np.testing.assert_allclose(J_R_31, result["I_J_R"], atol=1e-15)


# ---------------------------------------------------------------- problems 25 and 33: passive dynamic walker


@functools.lru_cache(maxsize=1)
def walker_symbolic():
    import sympy as sp

    q, x, J = problem_25.cog_positions_symbolic()
    return sp.lambdify(list(q), x, "numpy"), sp.lambdify(list(q), J, "numpy")


def test_problem_25_part_c_values():
    x = problem_25.solve()
    alpha, gamma = np.deg2rad([-30.0, 60.0])
    r, dx, dy, l = problem_25.FOOT_RADIUS, problem_25.DX, problem_25.DY, problem_25.LEG_LENGTH
    hip = np.array([-r * alpha, r]) + R3(alpha)[:2, :2] @ np.array([0.0, l - r])
    stance = hip + R3(alpha)[:2, :2] @ np.array([dx, -dy])
    swing = hip + R3(alpha + gamma)[:2, :2] @ np.array([dx, -dy])
    np.testing.assert_allclose(x, [*stance, alpha, *swing, alpha + gamma], atol=1e-12)
    np.testing.assert_allclose(x, [0.2051, 0.3018, -0.5236, 0.9051, 0.3518, 0.5236], atol=1e-4)
    # at q = 0 both centres of gravity sit 0.05 in front of and 0.3 above the contact point
    np.testing.assert_allclose(problem_25.cog_positions(0.0, 0.0), [0.05, 0.3, 0.0, 0.05, 0.3, 0.0], atol=1e-12)


@settings(max_examples=25, deadline=None)
@given(st.floats(-1.5, 1.5), st.floats(-2.5, 2.5))
def test_problem_25_symbolic_positions_and_jacobian_match_the_tree(alpha, gamma):
    x_of, J_of = walker_symbolic()
    tree = problem_25.build_walker()
    difference = np.ravel(x_of(alpha, gamma)) - problem_25.cog_positions(alpha, gamma, tree)
    difference[[2, 5]] = (difference[[2, 5]] + np.pi) % (2.0 * np.pi) - np.pi  # angles agree modulo 2 pi
    np.testing.assert_allclose(difference, 0.0, atol=1e-12)
    tree.forward_kinematics([alpha, gamma], np.zeros(2))
    J_tree = np.vstack([np.vstack([tree[n].I_J_S[:2], tree[n].I_J_R[2:]]) for n in ("stance_leg", "swing_leg")])
    np.testing.assert_allclose(np.asarray(J_of(alpha, gamma), dtype=float), J_tree, atol=1e-12)


def test_problem_33_walker_velocities():
    result = problem_33.solve()
    stance, swing = result["stance_leg"], result["swing_leg"]
    qd = problem_33.QD
    for leg in (stance, swing):
        np.testing.assert_allclose(leg["I_v_B"], leg["I_J_S"] @ qd, atol=1e-12)
        np.testing.assert_allclose(leg["I_omega_B"], leg["I_J_R"] @ qd, atol=1e-12)
    np.testing.assert_allclose(stance["I_omega_B"], [0, 0, -0.5], atol=1e-15)
    np.testing.assert_allclose(swing["I_omega_B"], [0, 0, 0.5], atol=1e-15)
    # rolling without slipping: the material point of the stance foot touching the ground is at rest
    r = problem_25.FOOT_RADIUS
    contact = np.array([-r * problem_33.Q[0], 0.0, 0.0])
    w = stance["I_omega_B"]
    np.testing.assert_allclose(stance["I_v_B"] + np.cross(w, contact - stance["I_r_IB"]), 0.0, atol=1e-12)
    # with qdd = 0 and a constant rolling rate, the contact point accelerates straight up (centripetal, r w^2)
    a_contact = stance["I_a_B"] + np.cross(w, np.cross(w, contact - stance["I_r_IB"]))
    np.testing.assert_allclose(a_contact, [0.0, r * w[2] ** 2, 0.0], atol=1e-12)


# ---------------------------------------------------------------- problem 32: robot arm


def test_problem_32_robot_geometry():
    tree = problem_32.build_robot()
    assert tree.nq == 3
    np.testing.assert_allclose(problem_32.end_effector_position(tree, np.zeros(3)), [0.0, -3.0, 0.0], atol=1e-15)
    tree.forward_kinematics(np.zeros(3), np.zeros(3))
    axes = [tree[f"link_{k}"].I_J_R[:, k - 1] for k in (1, 2, 3)]
    np.testing.assert_allclose(axes, [[0, 0, 1], [1, 0, 0], [0, 0, 1]], atol=1e-15)
    # hanging straight down, gravity needs no torque
    np.testing.assert_allclose(problem_32.gravity_compensation(tree, np.zeros(3)), 0.0, atol=1e-12)


def test_problem_32_time_grid_and_path():
    t = problem_32.time_grid()
    assert t.size == 209 and np.all(np.diff(t) > 0) and t[0] == 0.0 and t[-1] == 2.0
    x0, _, _ = problem_32.end_effector_path(0.0)
    x1, v1, a1 = problem_32.end_effector_path(1.0)
    np.testing.assert_allclose(x0, [-1.0, -2.0, 0.5])
    np.testing.assert_allclose(problem_32.end_effector_path(2.0)[0], [1.0, -2.0, 0.5])
    np.testing.assert_allclose([x1, v1, a1], [[0.0, -2.0, 0.5], [2.0, 0, 0], [0, 0, 0]], atol=1e-12)
    assert problem_32.ACCELERATION == 4.0
    np.testing.assert_allclose(problem_32.end_effector_path(0.25)[2], [4.0, 0, 0])  # boundary: later phase
    np.testing.assert_allclose(problem_32.end_effector_path(1.75)[2], [0.0, 0, 0])
    # the path's velocity and acceleration are its derivatives
    for tk in (0.4, 1.0, 1.5):
        _, v, a = problem_32.end_effector_path(tk)
        np.testing.assert_allclose(central_difference(lambda s: problem_32.end_effector_path(s)[0], tk), v, atol=1e-8)
        np.testing.assert_allclose(central_difference(lambda s: problem_32.end_effector_path(s)[1], tk), a, atol=1e-6)


def test_problem_32_inverse_kinematics_reproduces_the_path():
    trajectory = problem_32.desired_trajectory()
    np.testing.assert_allclose(trajectory["q"][0], [-0.00369, -0.46218, -1.44917], atol=5e-6)
    assert trajectory["q"].shape == (209, 3)
    assert np.abs(np.diff(trajectory["q"], axis=0)).max() < 0.05  # one continuous branch
    tree = problem_32.build_robot()
    for k in range(0, 209, 4):
        q, qd, qdd = trajectory["q"][k], trajectory["qd"][k], trajectory["qdd"][k]
        end_effector = tree.forward_kinematics(q, qd, qdd)["end_effector"]
        np.testing.assert_allclose(end_effector.I_r_IB, trajectory["x"][k], atol=1e-10)
        np.testing.assert_allclose(end_effector.I_v_B, trajectory["xd"][k], atol=1e-9)
        np.testing.assert_allclose(end_effector.I_a_B, trajectory["xdd"][k], atol=1e-8)
    # the cached table is not mutated through the returned copies
    trajectory["q"][0] = 0.0
    assert problem_32.desired_trajectory()["q"][0, 1] != 0.0


def test_problem_32_gravity_torques():
    result = problem_32.solve()
    tree = problem_32.build_robot()
    assert result["tau"].shape == (209, 3)
    for k in (0, 100, 208):
        q = result["q_des"][k]
        np.testing.assert_allclose(result["tau"][k], -generalized_gravity(tree, q, problem_32.I_GRAV), atol=1e-12)
        np.testing.assert_allclose(result["tau"][k], potential_gradient(tree, q, problem_32.I_GRAV), atol=1e-6)


# ---------------------------------------------------------------- problem 34: biped


def test_problem_34_gait_is_smooth_and_periodic():
    for t in (0.0, 0.37, 1.0):
        q, qd, qdd = problem_34.gait(t)
        np.testing.assert_allclose(central_difference(lambda s: problem_34.gait(s)[0], t), qd, atol=1e-8)
        np.testing.assert_allclose(central_difference(lambda s: problem_34.gait(s)[1], t), qdd, atol=1e-6)
        q_next = problem_34.gait(t + problem_34.PERIOD)[0]
        np.testing.assert_allclose(q_next[1:], q[1:], atol=1e-12)
        assert q_next[0] > q[0]


def test_problem_34_biped_kinematics():
    tree = problem_34.build_biped()
    assert tree.nq == 7 and [body.name for body in tree.bodies] == list(problem_34.BODY_NAMES)
    result = problem_34.solve(90)
    t = problem_34.frame_time(90)
    q, qd, qdd = problem_34.gait(t)
    main = result["main_body"]
    np.testing.assert_allclose(main["I_r_IB"], [q[0], q[1], 0.0], atol=1e-12)
    np.testing.assert_allclose(main["A_IB"], R3(q[2]), atol=1e-12)
    np.testing.assert_allclose(main["I_v_B"], [qd[0], qd[1], 0.0], atol=1e-12)
    np.testing.assert_allclose(main["I_a_B"], [qdd[0], qdd[1], 0.0], atol=1e-12)
    for side, z, hip, extension in (("left", 0.2, 3, 5), ("right", -0.2, 4, 6)):
        angle = q[2] + q[hip]
        down = np.array([np.sin(angle), -np.cos(angle), 0.0])
        hip_point = np.array([q[0], q[1], z])
        np.testing.assert_allclose(result[f"thigh_{side}"]["I_r_IB"], hip_point + 0.25 * down, atol=1e-12)
        shank = hip_point + (0.75 + q[extension]) * down
        np.testing.assert_allclose(result[f"shank_{side}"]["I_r_IB"], shank, atol=1e-12)
        for name in (f"thigh_{side}", f"shank_{side}"):
            body = result[name]
            np.testing.assert_allclose(body["I_v_B"], body["I_J_S"] @ qd, atol=1e-12)


# ---------------------------------------------------------------- problem 35: symbolic joint functions


@functools.lru_cache(maxsize=1)
def symbolic_joint_functions():
    import sympy as sp

    keys = ("A_DpDs", "Dp_r_DpDs", "r_rel_dot", "r_rel_ddot", "omega_rel", "omega_rel_dot", "S", "R")
    functions = {}
    for kind, d in problem_35.solve().items():
        symbols = [*d["q"], *d["qd"], *d["qdd"], *([d["r"]] if "r" in d else [])]
        functions[kind] = {key: sp.lambdify(symbols, d[key], "numpy") for key in keys}
    return functions


@settings(max_examples=25, deadline=None)
@given(st.sampled_from(problem_35.JOINT_TYPES), vectors(9, 3.0), st.floats(0.05, 2.0))
def test_problem_35_symbolic_joint_functions_match_numeric(kind, values, r):
    cls = JOINT_CLASSES[kind]
    nq = cls.nq
    q, qd, qdd = values[:nq], values[3 : 3 + nq], values[6 : 6 + nq]
    joint = make_joint(kind, Body("p"), Body("s"), 0, r=r)
    A_DpDs, Dp_r_DpDs = joint.joint_pose(q)
    motion = joint.joint_motion(q, qd, qdd)
    args = [*q, *qd, *qdd, *([r] if kind == "rolling_contact" else [])]
    symbolic = {key: np.asarray(f(*args), dtype=float) for key, f in symbolic_joint_functions()[kind].items()}
    np.testing.assert_allclose(symbolic["A_DpDs"], A_DpDs, atol=1e-12)
    np.testing.assert_allclose(symbolic["Dp_r_DpDs"].ravel(), Dp_r_DpDs, atol=1e-12)
    for key in ("r_rel_dot", "r_rel_ddot", "omega_rel", "omega_rel_dot"):
        np.testing.assert_allclose(symbolic[key].ravel(), getattr(motion, key), atol=1e-12)
    np.testing.assert_allclose(symbolic["S"].reshape(3, nq), motion.S, atol=1e-12)
    np.testing.assert_allclose(symbolic["R"].reshape(3, nq), motion.R, atol=1e-12)


def test_problem_35_covers_the_four_joint_types():
    result = problem_35.solve()
    assert set(result) == set(problem_35.JOINT_TYPES)
    rolling = result["rolling_contact"]
    gamma, r = rolling["q"][0], rolling["r"]
    assert rolling["S"].tolist() == [[-r], [0], [0]]
    assert rolling["Dp_r_DpDs"].tolist() == [[-r * gamma], [0], [0]]
