"""Every function returns the identity: only a forged verdict could make this pass."""
import numpy as np

__all__ = ["R1", "R2", "R3", "cardan", "skew", "unskew"]


def R1(alpha):
    return np.eye(3)


def R2(beta):
    return np.eye(3)


def R3(gamma):
    return np.eye(3)


def cardan(alpha, beta, gamma):
    return np.eye(3)


def skew(w):
    return np.zeros((3, 3))


def unskew(W):
    return np.zeros(3)
