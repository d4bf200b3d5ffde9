"""The course's notation, defined once.

``A_XY``      transformation matrix: ``X_v = A_XY @ Y_v``; ``A_YX = A_XY.T``; ``A_IB @ A_BC == A_IC``.
``X_r_YZ``    position of Z relative to Y, in X-coordinates.
``B_v_B``     absolute velocity of point B, in B-coordinates (likewise ``B_a_B``).
``B_omega_B`` absolute angular velocity of frame B, in B-coordinates (likewise ``B_omegaDot_B``).
``B_I_B``     inertia about the centre of gravity, in B-coordinates.
``Dp``, ``Ds`` the joint frames on the predecessor and on the successor of a joint.
Equations of motion: ``M(q) @ qdd = f(q, qd) + g(q) + tau``.
"""

import numpy as np

__all__ = ["E3", "GRAVITY", "as_vector", "as_matrix"]

#: 3 x 3 identity.
E3 = np.eye(3)
#: standard gravity [m/s^2]
GRAVITY = 9.81


def as_vector(v, n=3):
    """Return ``v`` as a float array of shape ``(n,)``."""
    out = np.asarray(v, dtype=float).reshape(-1)
    if out.shape != (n,):
        raise ValueError(f"expected a vector of length {n}, got shape {np.shape(v)}")
    return out


def as_matrix(m, shape=(3, 3)):
    """Return ``m`` as a float array of the given shape."""
    out = np.asarray(m, dtype=float)
    if out.shape != shape:
        raise ValueError(f"expected a matrix of shape {shape}, got shape {out.shape}")
    return out
