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
    # TODO problem 46: write your solution here
    raise NotImplementedError("Problem 46: make_wire_event is not implemented yet")


def constraint_terms(end_effector, baumgarte=True, anchor=ANCHOR, wire_length=WIRE_LENGTH):
    """``(J_lam, sigma_lam)`` of the taut wire from the current state of the ``end_effector`` body (after a pass of
    ``forward_kinematics(q, qd, 0)``, so that its ``B_a_B`` is the bias acceleration): the 1 x 3 constraint
    Jacobian and the 1-vector of its bias acceleration (see the module), with the Baumgarte terms
    ``P_B c + D_B c_dot`` if ``baumgarte``."""
    # TODO problem 46: write your solution here
    raise NotImplementedError("Problem 46: constraint_terms is not implemented yet")


def plastic_impact(M, J, qd_minus):
    """``(qd_plus, Lam)``: the velocities after a fully plastic impact on the constraints ``J`` (k x n) and the
    impulses (k): ``Lam = -(J M^-1 J.T)^-1 J qd_minus``, ``qd_plus = qd_minus + M^-1 J.T Lam``."""
    # TODO problem 46: write your solution here
    raise NotImplementedError("Problem 46: plastic_impact is not implemented yet")


def constrained_dynamics(M, f, g, tau, J, sigma):
    """``(qdd, lam)`` of the constrained system ``[[M, -J.T], [J, 0]] [qdd; lam] = [f + g + tau; -sigma]``
    (``J``: k x n, ``sigma``: k)."""
    # TODO problem 46: write your solution here
    raise NotImplementedError("Problem 46: constrained_dynamics is not implemented yet")


def constrained_ode(t, y, tree, trajectory, baumgarte, anchor=ANCHOR, wire_length=WIRE_LENGTH):
    """The right-hand side ``dy/dt = (qd, qdd)`` of the robot on the taut wire under computed torques,
    ``y = (q, qd)``."""
    # TODO problem 46: write your solution here
    raise NotImplementedError("Problem 46: constrained_ode is not implemented yet")


def simulate(trajectory, baumgarte=True, t_end=T_END, anchor=ANCHOR, wire_length=WIRE_LENGTH):
    """The robot under computed torques (problem 37) from the start of ``trajectory`` until the wire (hung at
    ``anchor``, ``wire_length`` long) is taut, the plastic impact, then the constrained motion to ``t_end``; output
    at the table's times.  Returns ``{"t", "q",
    "qd"}`` (both phases; the row at the event time is the state after the impact), ``"t_event"``,
    ``"q_minus"``, ``"qd_minus"``, ``"q_plus"``, ``"qd_plus"``, ``"Lam"`` (``t_event`` None and no impact values if
    the wire never becomes taut)."""
    # TODO problem 46: write your solution here
    raise NotImplementedError("Problem 46: simulate is not implemented yet")


def solve():
    """``{"baumgarte": simulate(...), "plain": simulate(..., baumgarte=False)}`` on the desired trajectory of
    problem 32."""
    from .problem_32 import desired_trajectory

    trajectory = desired_trajectory()
    return {"baumgarte": simulate(trajectory), "plain": simulate(trajectory, baumgarte=False)}
