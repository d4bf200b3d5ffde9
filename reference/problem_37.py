"""Problem 37: the robot arm of problem 32 with dynamics, and three joint-level controllers.

The equations of motion come from the projected Newton-Euler equations over the tree (``dynamics``:
``DynamicBody.mfg_contribution`` is this problem's part).  The controllers compute the motor torques from the
desired joint values at time ``t`` (linear interpolation in the 209-point table of problem 32) and the measured
state, with the gains ``P = 10``, ``D = 50`` on every joint (problem data P37):

* PD:                     ``tau = P (q_des - q) + D (qd_des - qd)`` (given, as in the course);
* gravity compensation:   ``tau = -g(q) + PD``;
* computed torques:       ``tau = M(q) qdd_des - f(q, qd) - g(q) + PD``.

The simulation starts on the desired trajectory at rest, ``y0 = (q_des(0), qd_des(0))``, and runs from 0 to 2 s.
The trajectory is passed in as a table (the course loads it from a file), ``{"t", "q", "qd", "qdd"}`` as returned
by ``problem_32.desired_trajectory()``.
"""

import numpy as np

from .dynamics import DynamicBody, equations_of_motion, forward_dynamics, integrate_piecewise
from .problem_32 import I_GRAV, T_END, build_robot, desired_trajectory

__all__ = [
    "P_GAIN",
    "D_GAIN",
    "CONTROLLERS",
    "build_dynamic_robot",
    "desired_state",
    "pd_torque",
    "gravity_compensation_torque",
    "computed_torque",
    "controller_torque",
    "robot_ode",
    "simulate",
    "solve",
]

P_GAIN = 10.0
D_GAIN = 50.0
#: the controllers, in the order of the sheet
CONTROLLERS = ("pd", "gravity_compensation", "computed_torques")


def build_dynamic_robot():
    """The arm of problem 32 with bodies that have equations of motion (``DynamicBody``)."""
    return build_robot(body_class=DynamicBody)


def desired_state(trajectory, t):
    """``(q_des, qd_des, qdd_des)`` at time ``t`` by linear interpolation between the rows of the table
    ``trajectory`` (its first or last row outside its times)."""
    times = np.asarray(trajectory["t"], dtype=float)
    k = int(np.clip(np.searchsorted(times, t, side="right") - 1, 0, times.size - 2))
    w = float(np.clip((t - times[k]) / (times[k + 1] - times[k]), 0.0, 1.0))
    return tuple((1.0 - w) * np.asarray(trajectory[key][k], dtype=float) + w * np.asarray(trajectory[key][k + 1])
                 for key in ("q", "qd", "qdd"))


def pd_torque(q, qd, q_des, qd_des):
    """Controller 1 (given): ``tau = P (q_des - q) + D (qd_des - qd)``."""
    return P_GAIN * (q_des - q) + D_GAIN * (qd_des - qd)


def gravity_compensation_torque(g, q, qd, q_des, qd_des):
    """Controller 2: the PD torques plus the torques that hold the arm against gravity, ``tau = -g + PD``, with
    ``g`` the generalized gravity forces at the measured state."""
    # BEGIN SOLUTION problem 37
    return -g + pd_torque(q, qd, q_des, qd_des)
    # END SOLUTION


def computed_torque(M, f, g, q, qd, q_des, qd_des, qdd_des):
    """Controller 3, computed torques: ``tau = M qdd_des - f - g + PD``, with ``M``, ``f``, ``g`` at the measured
    state ``(q, qd)``."""
    # BEGIN SOLUTION problem 37
    return M @ qdd_des - f - g + pd_torque(q, qd, q_des, qd_des)
    # END SOLUTION


def controller_torque(controller, M, f, g, q, qd, q_des, qd_des, qdd_des):
    """The torques of the named controller (one of ``CONTROLLERS``) at the measured state ``(q, qd)``, where the
    equations of motion are ``M``, ``f``, ``g``, and the desired state ``(q_des, qd_des, qdd_des)``."""
    if controller == "pd":
        return pd_torque(q, qd, q_des, qd_des)
    if controller == "gravity_compensation":
        return gravity_compensation_torque(g, q, qd, q_des, qd_des)
    if controller == "computed_torques":
        return computed_torque(M, f, g, q, qd, q_des, qd_des, qdd_des)
    raise ValueError(f"unknown controller {controller!r}, expected one of {CONTROLLERS}")


def robot_ode(t, y, tree, trajectory, controller):
    """The right-hand side ``dy/dt = (qd, qdd)`` of the robot under the named controller, ``y = (q, qd)``: the
    equations of motion at ``(q, qd)``, the controller's torques, then the forward dynamics."""
    # BEGIN SOLUTION problem 37
    q, qd = y[:3], y[3:]
    M, f, g = equations_of_motion(tree, q, qd, I_GRAV)
    tau = controller_torque(controller, M, f, g, q, qd, *desired_state(trajectory, t))
    return np.concatenate([qd, forward_dynamics(M, f, g, tau)])
    # END SOLUTION


def simulate(controller, trajectory, t_end=T_END):
    """Simulate the robot under the named controller from ``y0 = (q_des(0), qd_des(0))`` (the table's first row)
    to ``t_end``, with output at the table's times up to ``t_end``.  Returns ``{"t", "q", "qd"}`` (one row per
    time).  Any ``scipy.integrate.solve_ivp`` method at its default tolerances is accurate enough for the grader;
    a fixed-step Euler loop is not."""
    # BEGIN SOLUTION problem 37
    tree = build_dynamic_robot()
    times = np.asarray(trajectory["t"], dtype=float)
    y0 = np.concatenate([trajectory["q"][0], trajectory["qd"][0]])
    run = integrate_piecewise(robot_ode, (0.0, t_end), y0, times[times <= t_end], breaks=times,
                              args=(tree, trajectory, controller))
    return {"t": run["t"], "q": run["y"][:, :3], "qd": run["y"][:, 3:]}
    # END SOLUTION


def solve(t_end=T_END):
    """``{controller: simulate(controller, desired_trajectory(), t_end)}`` for the three controllers."""
    trajectory = desired_trajectory()
    return {controller: simulate(controller, trajectory, t_end) for controller in CONTROLLERS}
