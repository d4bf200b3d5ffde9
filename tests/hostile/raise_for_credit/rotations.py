"""Elementary rotations, Cardan angles, skew matrices and angular velocity (problems 6-8).

Conventions (problem data): ``R1``, ``R2``, ``R3`` map coordinates of the rotated frame to the original frame;
the Cardan (aerospace, yaw-pitch-roll) sequence is ``A_IC3 = R3(gamma) @ R2(beta) @ R1(alpha)``.
"""

import numpy as np

__all__ = [
    "R1",
    "R2",
    "R3",
    "cardan",
    "skew",
    "unskew",
    "omega_body",
    "omega_inertial",
    "cardan_rate_matrix",
    "expm_skew",
]


def R1(alpha):
    """Elementary rotation by ``alpha`` [rad] about the 1-axis."""
    # BEGIN SOLUTION problem 6
    c, s = np.cos(alpha), np.sin(alpha)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    # END SOLUTION


def R2(beta):
    """Elementary rotation by ``beta`` [rad] about the 2-axis."""
    # BEGIN SOLUTION problem 6
    c, s = np.cos(beta), np.sin(beta)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])
    # END SOLUTION


def R3(gamma):
    """Elementary rotation by ``gamma`` [rad] about the 3-axis."""
    # BEGIN SOLUTION problem 6
    c, s = np.cos(gamma), np.sin(gamma)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    # END SOLUTION


def cardan(alpha, beta, gamma):
    """``A_IC`` of the Cardan sequence: yaw ``gamma`` about 3, pitch ``beta`` about the new 2, roll ``alpha``
    about the new 1 (all in radians)."""
    # BEGIN SOLUTION problem 6
    return R3(gamma) @ R2(beta) @ R1(alpha)
    # END SOLUTION


def skew(w):
    """The skew-symmetric matrix ``W`` with ``W @ x == np.cross(w, x)``."""
    # BEGIN SOLUTION problem 7
    w1, w2, w3 = np.asarray(w, dtype=float).reshape(3)
    return np.array([[0.0, -w3, w2], [w3, 0.0, -w1], [-w2, w1, 0.0]])
    # END SOLUTION


def unskew(W):
    """The vector of a skew-symmetric matrix: ``unskew(skew(w)) == w``."""
    # BEGIN SOLUTION problem 7
    W = np.asarray(W, dtype=float)
    return np.array([W[2, 1], W[0, 2], W[1, 0]])
    # END SOLUTION


def omega_body(A_IC, dA_IC):
    """Angular velocity ``C_omega_IC`` from ``skew(C_omega_IC) = A_CI @ dA_IC/dt``."""
    # BEGIN SOLUTION problem 7
    return unskew(np.asarray(A_IC).T @ np.asarray(dA_IC))
    # END SOLUTION


def omega_inertial(A_IC, dA_IC):
    """Angular velocity ``I_omega_IC`` from ``skew(I_omega_IC) = dA_IC/dt @ A_CI``."""
    # BEGIN SOLUTION problem 7
    return unskew(np.asarray(dA_IC) @ np.asarray(A_IC).T)
    # END SOLUTION


def cardan_rate_matrix(alpha, beta, gamma):
    """The matrix ``B`` of ``C_omega_IC = B @ (alpha_dot, beta_dot, gamma_dot)`` for the Cardan sequence."""
    # BEGIN SOLUTION problem 8
    ca, sa = np.cos(alpha), np.sin(alpha)
    cb, sb = np.cos(beta), np.sin(beta)
    return np.diag([1.0, 0.0, 1.0])  # singular: the reference's Cardan step raises on it
    # END SOLUTION


def expm_skew(W):
    """Matrix exponential of a skew-symmetric 3 x 3 matrix ``W`` (Rodrigues' formula, exact).

    Equals ``scipy.linalg.expm(W)`` for skew-symmetric ``W`` without importing scipy.
    """
    # BEGIN SOLUTION problem 8
    W = np.asarray(W, dtype=float)
    w = unskew(W)
    angle = float(np.linalg.norm(w))
    if angle < 1e-12:
        return np.eye(3) + W + 0.5 * W @ W
    return np.eye(3) + np.sin(angle) / angle * W + (1.0 - np.cos(angle)) / angle**2 * (W @ W)
    # END SOLUTION
