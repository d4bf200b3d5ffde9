"""Problem 6: Euler angles in the Cardan (yaw-pitch-roll) convention.

I -> C1: gamma = 30 deg about 3;  C1 -> C2: beta = 45 deg about the new 2;  C2 -> C3: alpha = 60 deg about the
new 1.  The vector V has ``C3_v = (1, 1, 1)``.
"""

import numpy as np

from .rotations import R1, R2, R3

__all__ = ["GAMMA", "BETA", "ALPHA", "C3_V", "frames", "vectors"]

GAMMA = np.deg2rad(30.0)
BETA = np.deg2rad(45.0)
ALPHA = np.deg2rad(60.0)
C3_V = np.array([1.0, 1.0, 1.0])


def frames():
    """Return ``{"A_IC1": ..., "A_IC2": ..., "A_IC3": ...}`` for the sheet's angles."""
    # TODO problem 6: write your solution here
    raise NotImplementedError("Problem 6: frames is not implemented yet")


def vectors():
    """Return the coordinates of V in I, C1, C2 and C3: ``{"I_v": ..., "C1_v": ..., "C2_v": ..., "C3_v": ...}``."""
    # TODO problem 6: write your solution here
    raise NotImplementedError("Problem 6: vectors is not implemented yet")
