"""Problem 32: the three-link robot arm, its desired trajectory and the gravity-compensating torques.

Robot (problem data P32, also P37 and P46): ground m = 0; three links, m = 3 kg, ``B_I_B = diag(0.2, 0.02, 0.2)``,
1 m long along their 2-axis with the centre of gravity in the middle; every joint rotates about its Dp 3-axis.
Joint 1 (ground -> link 1): ``P_r_PDp = 0``, ``A_PDp = E``; joint 2: ``P_r_PDp = (0, -0.5, 0)``,
``A_PDp = [[0,0,1],[0,1,0],[-1,0,0]]``; joint 3: ``P_r_PDp = (0, -0.5, 0)``, ``A_PDp = [[0,0,-1],[0,1,0],[1,0,0]]``;
all ``S_r_SDs = (0, 0.5, 0)``, ``A_SDs = E``.  The massless end effector sits rigidly at ``(0, -0.5, 0)`` of link 3.
At q = 0 the arm hangs along -y with the end effector at (0, -3, 0).  Gravity ``I_grav = (0, -9.81, 0)``.

Trajectory: the end effector moves along x from (-1, -2, 0.5) to (+1, -2, 0.5): at rest until ``t_rest``, then
``+a`` for ``t_acc``, constant speed, ``-a`` for ``t_acc``, at rest from ``t_end - t_rest`` on, with
``a = 2 / ((t_end - t_acc - 2 t_rest) t_acc)``; a phase boundary belongs to the later phase.  The joint trajectory
comes from inverse kinematics on the 209-point time grid (least squares from q = 0, then continuing from the
previous point); ``qd_des = J^-1 xd_des``, ``qdd_des = J^-1 (xdd_des - bias)`` with ``J`` the end effector's
inertial translational Jacobian and ``bias`` its acceleration at ``qdd = 0``.
"""

import functools

import numpy as np

from .conventions import GRAVITY
from .tree import Body, KinematicTree, RigidJoint, RotationalJoint, generalized_gravity

__all__ = [
    "LINK_MASS",
    "LINK_INERTIA",
    "I_GRAV",
    "T_END",
    "T_REST",
    "T_ACC",
    "ACCELERATION",
    "X_START",
    "X_END",
    "build_robot",
    "end_effector_position",
    "end_effector_path",
    "time_grid",
    "inverse_kinematics",
    "desired_trajectory",
    "gravity_compensation",
    "gravity_torques",
    "solve",
]

LINK_MASS = 3.0
LINK_INERTIA = np.diag([0.2, 0.02, 0.2])
I_GRAV = np.array([0.0, -GRAVITY, 0.0])
T_END, T_REST, T_ACC = 2.0, 0.25, 0.5
ACCELERATION = 2.0 / ((T_END - T_ACC - 2.0 * T_REST) * T_ACC)
X_START = np.array([-1.0, -2.0, 0.5])
X_END = np.array([1.0, -2.0, 0.5])

_A_PDP = (
    np.eye(3),
    np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]),
    np.array([[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]),
)


def build_robot(body_class=Body):
    """The arm as a ``KinematicTree``: ``ground``, ``link_1``, ``link_2``, ``link_3``, ``end_effector``;
    joint k has coordinate ``q[k-1]``.  ``body_class``: the class of the bodies (``dynamics.DynamicBody`` for a
    tree with equations of motion)."""
    ground = body_class("ground", 0.0)
    predecessor = ground
    for k, A_PDp in enumerate(_A_PDP):
        link = body_class(f"link_{k + 1}", LINK_MASS, LINK_INERTIA)
        P_r_PDp = (0.0, 0.0, 0.0) if k == 0 else (0.0, -0.5, 0.0)
        RotationalJoint(predecessor, link, P_r_PDp=P_r_PDp, A_PDp=A_PDp, S_r_SDs=(0.0, 0.5, 0.0), q_index=[k])
        predecessor = link
    RigidJoint(predecessor, body_class("end_effector", 0.0), P_r_PDp=(0.0, -0.5, 0.0))
    return KinematicTree(ground)


def end_effector_position(tree, q):
    """Inertial position of the end effector at ``q``."""
    return tree.forward_kinematics(q)["end_effector"].I_r_IB


def end_effector_path(t):
    """Desired end-effector position, velocity and acceleration ``(x, xd, xdd)`` (inertial) at time ``t``."""
    a, t1, t2 = ACCELERATION, T_REST + T_ACC, T_END - T_REST - T_ACC
    if t < T_REST:
        s, v, acc = 0.0, 0.0, 0.0
    elif t < t1:
        tau = t - T_REST
        s, v, acc = 0.5 * a * tau**2, a * tau, a
    elif t < t2:
        tau = t - t1
        s, v, acc = 0.5 * a * T_ACC**2 + a * T_ACC * tau, a * T_ACC, 0.0
    elif t < T_END - T_REST:
        tau = t - t2
        v_max = a * T_ACC
        s = 0.5 * a * T_ACC**2 + v_max * (t2 - t1) + v_max * tau - 0.5 * a * tau**2
        v, acc = v_max - a * tau, -a
    else:
        s, v, acc = float(np.linalg.norm(X_END - X_START)), 0.0, 0.0
    e = (X_END - X_START) / np.linalg.norm(X_END - X_START)
    return X_START + s * e, v * e, acc * e


def time_grid():
    """``0:0.01:2`` plus the phase boundaries 0.25, 0.75, 1.25, 1.75 shifted by +-1e-6 (209 points, sorted)."""
    base = np.round(np.linspace(0.0, T_END, 201), 12)
    boundaries = np.array([T_REST, T_REST + T_ACC, T_END - T_REST - T_ACC, T_END - T_REST])
    return np.sort(np.concatenate([base, boundaries - 1e-6, boundaries + 1e-6]))


def inverse_kinematics(tree, x_des, q0):
    """Joint angles that put the end effector at ``x_des``, by least squares started at ``q0``."""
    from scipy.optimize import least_squares

    def residual(q):
        return end_effector_position(tree, q) - x_des

    def jacobian(q):
        return tree.forward_kinematics(q, np.zeros(tree.nq))["end_effector"].I_J_S

    result = least_squares(residual, np.asarray(q0, dtype=float), jac=jacobian, xtol=1e-14, ftol=1e-14, gtol=1e-14)
    return result.x


@functools.lru_cache(maxsize=1)
def _trajectory():
    tree = build_robot()
    t = time_grid()
    n = t.size
    x, xd, xdd = (np.zeros((n, 3)) for _ in range(3))
    q, qd, qdd = (np.zeros((n, tree.nq)) for _ in range(3))
    q_prev = np.zeros(tree.nq)
    for k, tk in enumerate(t):
        x[k], xd[k], xdd[k] = end_effector_path(tk)
        q[k] = q_prev = inverse_kinematics(tree, x[k], q_prev)
        end_effector = tree.forward_kinematics(q[k], np.zeros(tree.nq))["end_effector"]
        J = end_effector.I_J_S
        qd[k] = np.linalg.solve(J, xd[k])
        bias = tree.forward_kinematics(q[k], qd[k])["end_effector"].I_a_B
        qdd[k] = np.linalg.solve(J, xdd[k] - bias)
    table = {"t": t, "x": x, "xd": xd, "xdd": xdd, "q": q, "qd": qd, "qdd": qdd}
    for value in table.values():
        value.flags.writeable = False
    return table


def desired_trajectory():
    """The desired motion on ``time_grid()``: ``{"t", "x", "xd", "xdd", "q", "qd", "qdd"}`` (rows per time; x in
    inertial coordinates).  Computed once per process; the arrays returned are copies."""
    return {key: value.copy() for key, value in _trajectory().items()}


def gravity_compensation(tree, q):
    """Joint torques that hold the arm at ``q`` against gravity: ``tau = -g(q)``."""
    # TODO problem 32: write your solution here
    raise NotImplementedError("Problem 32: gravity_compensation is not implemented yet")


def gravity_torques():
    """``(t, tau)``: the gravity-compensating torques (209 x 3) along the desired trajectory."""
    trajectory = _trajectory()
    tree = build_robot()
    return trajectory["t"].copy(), np.array([gravity_compensation(tree, q) for q in trajectory["q"]])


def solve():
    """``{"t", "q_des", "qd_des", "qdd_des", "tau"}`` along the desired trajectory."""
    trajectory = desired_trajectory()
    t, tau = gravity_torques()
    return {"t": t, "q_des": trajectory["q"], "qd_des": trajectory["qd"], "qdd_des": trajectory["qdd"], "tau": tau}
