"""Problem 11: bound vectors and coordinate systems, with the test values of the course's test file."""

import numpy as np

from .bound import BoundCoSys, BoundVector
from .rotations import R3

__all__ = ["make_test_objects", "solve"]


def make_test_objects():
    """The test file's objects: C with ``A_IC = R3(30°)`` drawn at ``I_r_IC = (1, 2, 0)``, and the vector
    ``C_v = (0, -2, 0)`` drawn from ``C_r_CO = (1, 0, 0)``.  Returns ``(C, v)``."""
    C = BoundCoSys(R3(np.deg2rad(30.0)), [1.0, 2.0, 0.0])
    v = BoundVector(C, [0.0, -2.0, 0.0], [1.0, 0.0, 0.0])
    return C, v


def solve():
    """The test vector in inertial components, its start point, and its components in I and in C."""
    C, v = make_test_objects()
    inertial = BoundCoSys()
    return {"I_v": v.I_v, "I_r_IO": v.I_r_IO, "I_coords": v.get_coords(inertial), "C_coords": v.get_coords(C)}
