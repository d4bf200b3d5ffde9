"""Problem 33: the passive dynamic walker of problem 25 with velocities, accelerations and Jacobians.

Test case (problem data P33): ``q = (-30 deg, +60 deg)``, ``qd = (-0.5, +1)``, ``qdd = 0``.  The rolling contact
has ``r_rel = (-r q, 0, 0)``, ``omega_rel = (0, 0, qd)``, ``S = (-r, 0, 0)``, ``R = e3``.
"""

import numpy as np

from .problem_25 import build_walker
from .tree import inertial_state

__all__ = ["Q", "QD", "QDD", "leg_motion", "solve"]

Q = np.deg2rad([-30.0, 60.0])
QD = np.array([-0.5, 1.0])
QDD = np.zeros(2)


def leg_motion(q=Q, qd=QD, qdd=QDD):
    """``{"stance_leg": ..., "swing_leg": ...}``: each leg's inertial state (``tree.inertial_state``) at
    ``(q, qd, qdd)``."""
    tree = build_walker().forward_kinematics(q, qd, qdd)
    return {name: inertial_state(tree[name]) for name in ("stance_leg", "swing_leg")}


def solve():
    """The walker's legs at the sheet's test state, see ``leg_motion``."""
    return leg_motion()
