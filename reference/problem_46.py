"""Problem 46: the robot arm of problem 37, under computed torques, caught by a wire.

Problem data P46: the wire hangs at ``anchor = (-1, -1, -1)`` and is ``wire_length = 2`` long (``ANCHOR``,
``WIRE_LENGTH``; the functions below take them as arguments with these defaults, and the grader also hangs the wire
elsewhere).  It becomes taut
when the end effector E reaches the distance ``wire_length`` from the anchor: the event residual
``|anchor - I_r_E| - wire_length`` crosses zero upwards (terminal, direction +1).  The wire does not stretch: a
fully plastic impact, then motion under the unilateral constraint ``c = wire_length - |anchor - I_r_E| = 0`` with
``dir = (I_r_E - anchor) / |I_r_E - anchor|``::

    J_lam = -dir.T A_IE B_J_S,E                                     (1 x 3)
    sigma_lam = -dir.T A_IE B_a_E - |dir x I_v_E|^2 / wire_length   (B_a_E the bias acceleration, qdd = 0)

so that ``J_lam qdd + sigma_lam = c_ddot``.  Baumgarte stabilisation adds ``P_B c + D_B c_dot`` to ``sigma_lam``
(``P_B = 25``, ``D_B = 10``; ``c_dot = -dir.T I_v_E``).  Constrained dynamics (the constraint force acts through
``+J.T lam``)::

    [[M, -J.T], [J, 0]] [qdd; lam] = [f + g + tau; -sigma]

Plastic impact: ``Lam = -(J M^-1 J.T)^-1 J qd_minus``, ``qd_plus = qd_minus + M^-1 J.T Lam``, ``q_plus = q_minus``.

*Erratum* (problem data): the sheet's event time 0.93313 and its ``q_PLUS``, ``d_q_PLUS`` come from MATLAB's
loose ode45 (RelTol 1e-3).  A tight integration gives ``q_PLUS`` to about 1e-5 and the event time to about 2e-4,
but ``d_q_PLUS`` differs by up to 0.04 per component; the grader compares with a tight run within the bands of
problem data.
"""

import numpy as np

from .dynamics import equations_of_motion, integrate_piecewise
from .problem_32 import I_GRAV, T_END
from .problem_37 import build_dynamic_robot, computed_torque, desired_state, robot_ode

__all__ = [
    "ANCHOR",
    "WIRE_LENGTH",
    "P_BAUMGARTE",
    "D_BAUMGARTE",
    "SHEET_EVENT_TIME",
    "SHEET_Q_PLUS",
    "SHEET_QD_PLUS",
    "make_wire_event",
    "constraint_terms",
    "plastic_impact",
    "constrained_dynamics",
    "constrained_ode",
    "simulate",
    "solve",
]

ANCHOR = np.array([-1.0, -1.0, -1.0])
WIRE_LENGTH = 2.0
P_BAUMGARTE = 25.0
D_BAUMGARTE = 10.0
#: the sheet's values (MATLAB ode45 at RelTol 1e-3, see the erratum)
SHEET_EVENT_TIME = 0.93313
SHEET_Q_PLUS = np.array([0.45214, -0.59389, -1.6775])
SHEET_QD_PLUS = np.array([0.98849, 0.01024, -0.99379])


def make_wire_event(tree, anchor=ANCHOR, wire_length=WIRE_LENGTH):
    """The event function ``wire_stretched(t, y, *args)`` for ``scipy.integrate.solve_ivp`` (``y = (q, qd)``; the
    ``args`` that solve_ivp also passes to events are ignored): the residual ``|anchor - I_r_E| - wire_length`` of
    the end effector of ``tree``, with the attributes ``terminal`` (stop the integration) and ``direction`` (+1:
    detect the crossing from - to +)."""
    # BEGIN SOLUTION problem 46
    def wire_stretched(t, y, *args):
        I_r_E = tree.forward_kinematics(y[:3])["end_effector"].I_r_IB
        return float(np.linalg.norm(anchor - I_r_E) - wire_length)

    wire_stretched.terminal = True
    wire_stretched.direction = 1
    return wire_stretched
    # END SOLUTION


def constraint_terms(end_effector, baumgarte=True, anchor=ANCHOR, wire_length=WIRE_LENGTH):
    """``(J_lam, sigma_lam)`` of the taut wire from the current state of the ``end_effector`` body (after a pass of
    ``forward_kinematics(q, qd, 0)``, so that its ``B_a_B`` is the bias acceleration): the 1 x 3 constraint
    Jacobian and the 1-vector of its bias acceleration (see the module), with the Baumgarte terms
    ``P_B c + D_B c_dot`` if ``baumgarte``."""
    # BEGIN SOLUTION problem 46
    E = end_effector
    I_r_E, I_v_E = E.I_r_IB, E.I_v_B
    distance = np.linalg.norm(I_r_E - anchor)
    direction = (I_r_E - anchor) / distance
    J = -(direction @ E.A_IB @ E.B_J_S).reshape(1, -1)
    sigma = -direction @ E.A_IB @ E.B_a_B - np.linalg.norm(np.cross(direction, I_v_E)) ** 2 / wire_length
    if baumgarte:
        sigma += P_BAUMGARTE * (wire_length - distance) + D_BAUMGARTE * (0.0 - direction @ I_v_E)
    return J, np.array([sigma])
    # END SOLUTION


def plastic_impact(M, J, qd_minus):
    """``(qd_plus, Lam)``: the velocities after a fully plastic impact on the constraints ``J`` (k x n) and the
    impulses (k): ``Lam = -(J M^-1 J.T)^-1 J qd_minus``, ``qd_plus = qd_minus + M^-1 J.T Lam``."""
    # BEGIN SOLUTION problem 46
    Minv_JT = np.linalg.solve(M, J.T)
    Lam = -np.linalg.solve(J @ Minv_JT, J @ qd_minus)
    return qd_minus + Minv_JT @ Lam, Lam
    # END SOLUTION


def constrained_dynamics(M, f, g, tau, J, sigma):
    """``(qdd, lam)`` of the constrained system ``[[M, -J.T], [J, 0]] [qdd; lam] = [f + g + tau; -sigma]``
    (``J``: k x n, ``sigma``: k)."""
    # BEGIN SOLUTION problem 46
    n, k = M.shape[0], J.shape[0]
    A = np.block([[M, -J.T], [J, np.zeros((k, k))]])
    x = np.linalg.solve(A, np.concatenate([f + g + tau, -np.asarray(sigma, dtype=float)]))
    return x[:n], x[n:]
    # END SOLUTION


def constrained_ode(t, y, tree, trajectory, baumgarte, anchor=ANCHOR, wire_length=WIRE_LENGTH):
    """The right-hand side ``dy/dt = (qd, qdd)`` of the robot on the taut wire under computed torques,
    ``y = (q, qd)``."""
    # BEGIN SOLUTION problem 46
    q, qd = y[:3], y[3:]
    M, f, g = equations_of_motion(tree, q, qd, I_GRAV)
    tau = computed_torque(M, f, g, q, qd, *desired_state(trajectory, t))
    J, sigma = constraint_terms(tree["end_effector"], baumgarte, anchor, wire_length)
    qdd, _ = constrained_dynamics(M, f, g, tau, J, sigma)
    return np.concatenate([qd, qdd])
    # END SOLUTION


def simulate(trajectory, baumgarte=True, t_end=T_END, anchor=ANCHOR, wire_length=WIRE_LENGTH):
    """The robot under computed torques (problem 37) from the start of ``trajectory`` until the wire (hung at
    ``anchor``, ``wire_length`` long) is taut, the plastic impact, then the constrained motion to ``t_end``; output
    at the table's times.  Returns ``{"t", "q",
    "qd"}`` (both phases; the row at the event time is the state after the impact), ``"t_event"``,
    ``"q_minus"``, ``"qd_minus"``, ``"q_plus"``, ``"qd_plus"``, ``"Lam"`` (``t_event`` None and no impact values if
    the wire never becomes taut)."""
    # BEGIN SOLUTION problem 46
    tree = build_dynamic_robot()
    times = np.asarray(trajectory["t"], dtype=float)
    t_eval = times[times <= t_end]
    y0 = np.concatenate([trajectory["q"][0], trajectory["qd"][0]])
    free = integrate_piecewise(robot_ode, (0.0, t_end), y0, t_eval, breaks=times,
                               events=[make_wire_event(tree, anchor, wire_length)],
                               args=(tree, trajectory, "computed_torques"))
    if free["t_event"] is None:
        return {"t": free["t"], "q": free["y"][:, :3], "qd": free["y"][:, 3:], "t_event": None}
    t_event, q_minus, qd_minus = free["t_event"], free["y_event"][:3], free["y_event"][3:]
    M, _, _ = equations_of_motion(tree, q_minus, qd_minus, I_GRAV)
    J, _ = constraint_terms(tree["end_effector"], False, anchor, wire_length)
    qd_plus, Lam = plastic_impact(M, J, qd_minus)
    after = integrate_piecewise(constrained_ode, (t_event, t_end), np.concatenate([q_minus, qd_plus]),
                                np.concatenate([[t_event], t_eval[t_eval > t_event]]), breaks=times,
                                args=(tree, trajectory, baumgarte, anchor, wire_length))
    y = np.vstack([free["y"], after["y"]])
    return {"t": np.concatenate([free["t"], after["t"]]), "q": y[:, :3], "qd": y[:, 3:], "t_event": t_event,
            "q_minus": q_minus, "qd_minus": qd_minus, "q_plus": q_minus.copy(), "qd_plus": qd_plus, "Lam": Lam}
    # END SOLUTION


def solve():
    """``{"baumgarte": simulate(...), "plain": simulate(..., baumgarte=False)}`` on the desired trajectory of
    problem 32."""
    from .problem_32 import desired_trajectory

    trajectory = desired_trajectory()
    return {"baumgarte": simulate(trajectory), "plain": simulate(trajectory, baumgarte=False)}
