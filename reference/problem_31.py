"""Problem 31: velocities, accelerations and Jacobians of the triple pendulum of problem 24.

Test case (problem data P31): ``q = (pi/6, -pi/4, pi/3)``, ``qd = (1, 0, 0)``, ``qdd = (0, 0, 1)``; the course
printed ``A_IB @ B_J_S`` and ``A_IB @ B_J_R`` of link 3.
"""

import numpy as np

from .problem_24 import build_triple_pendulum
from .tree import inertial_state

__all__ = ["Q", "QD", "QDD", "link3_jacobians", "body_motion", "solve"]

Q = np.array([np.pi / 6, -np.pi / 4, np.pi / 3])
QD = np.array([1.0, 0.0, 0.0])
QDD = np.array([0.0, 0.0, 1.0])


def body_motion(q=Q, qd=QD, qdd=QDD):
    """``{body name: inertial state}`` (positions, velocities, accelerations, Jacobians in I-coordinates,
    see ``tree.inertial_state``) of the triple pendulum."""
    tree = build_triple_pendulum().forward_kinematics(q, qd, qdd)
    return {body.name: inertial_state(body) for body in tree.bodies}


def link3_jacobians(q=Q):
    """``(A_IB @ B_J_S, A_IB @ B_J_R)`` of link 3, each 3 x 3."""
    link_3 = body_motion(q, np.zeros(3), np.zeros(3))["link_3"]
    return link_3["I_J_S"], link_3["I_J_R"]


def solve():
    """The sheet's output for link 3: ``{"I_J_S", "I_J_R", "I_v_B", "I_omega_B", "I_a_B", "I_omegaDot_B"}``."""
    link_3 = body_motion()["link_3"]
    keys = ("I_J_S", "I_J_R", "I_v_B", "I_omega_B", "I_a_B", "I_omegaDot_B")
    return {key: link_3[key] for key in keys}
