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
    # BEGIN SOLUTION problem 6
    A_IC1 = R3(GAMMA)
    A_IC2 = A_IC1 @ R2(BETA)
    A_IC3 = A_IC2 @ R1(ALPHA)
    return {"A_IC1": A_IC1, "A_IC2": A_IC2, "A_IC3": A_IC3}
    # END SOLUTION


def vectors():
    """Return the coordinates of V in I, C1, C2 and C3: ``{"I_v": ..., "C1_v": ..., "C2_v": ..., "C3_v": ...}``."""
    # BEGIN SOLUTION problem 6
    A = frames()
    I_v = A["A_IC3"] @ C3_V
    return {
        "I_v": I_v,
        "C1_v": A["A_IC1"].T @ I_v,
        "C2_v": A["A_IC2"].T @ I_v,
        "C3_v": C3_V.copy(),
    }
    # END SOLUTION
