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
    # TODO problem 6: write your solution here
    raise NotImplementedError("Problem 6: R1 is not implemented yet")


def R2(beta):
    """Elementary rotation by ``beta`` [rad] about the 2-axis."""
    # TODO problem 6: write your solution here
    raise NotImplementedError("Problem 6: R2 is not implemented yet")


def R3(gamma):
    """Elementary rotation by ``gamma`` [rad] about the 3-axis."""
    # TODO problem 6: write your solution here
    raise NotImplementedError("Problem 6: R3 is not implemented yet")


def cardan(alpha, beta, gamma):
    """``A_IC`` of the Cardan sequence: yaw ``gamma`` about 3, pitch ``beta`` about the new 2, roll ``alpha``
    about the new 1 (all in radians)."""
    # TODO problem 6: write your solution here
    raise NotImplementedError("Problem 6: cardan is not implemented yet")


def skew(w):
    """The skew-symmetric matrix ``W`` with ``W @ x == np.cross(w, x)``."""
    # TODO problem 7: write your solution here
    raise NotImplementedError("Problem 7: skew is not implemented yet")


def unskew(W):
    """The vector of a skew-symmetric matrix: ``unskew(skew(w)) == w``."""
    # TODO problem 7: write your solution here
    raise NotImplementedError("Problem 7: unskew is not implemented yet")


def omega_body(A_IC, dA_IC):
    """Angular velocity ``C_omega_IC`` from ``skew(C_omega_IC) = A_CI @ dA_IC/dt``."""
    # TODO problem 7: write your solution here
    raise NotImplementedError("Problem 7: omega_body is not implemented yet")


def omega_inertial(A_IC, dA_IC):
    """Angular velocity ``I_omega_IC`` from ``skew(I_omega_IC) = dA_IC/dt @ A_CI``."""
    # TODO problem 7: write your solution here
    raise NotImplementedError("Problem 7: omega_inertial is not implemented yet")


def cardan_rate_matrix(alpha, beta, gamma):
    """The matrix ``B`` of ``C_omega_IC = B @ (alpha_dot, beta_dot, gamma_dot)`` for the Cardan sequence."""
    # TODO problem 8: write your solution here
    raise NotImplementedError("Problem 8: cardan_rate_matrix is not implemented yet")


def expm_skew(W):
    """Matrix exponential of a skew-symmetric 3 x 3 matrix ``W`` (Rodrigues' formula, exact).

    Equals ``scipy.linalg.expm(W)`` for skew-symmetric ``W`` without importing scipy.
    """
    # TODO problem 8: write your solution here
    raise NotImplementedError("Problem 8: expm_skew is not implemented yet")
