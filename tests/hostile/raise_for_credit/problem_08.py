"""Problem 8: integrating a constant angular velocity three ways.

``A_IC(t0) = R3(90 deg)``, ``I_omega = sqrt(1/3) (1, 1, 1)``, ``n = 100`` steps of ``dt = 2 pi / n``.
(a) explicit Euler on the matrix, (b) explicit Euler on the Cardan angles, (c) the matrix exponential.
"""

import numpy as np

from .rotations import R3, cardan, cardan_rate_matrix, expm_skew, skew

__all__ = [
    "A_IC0",
    "I_OMEGA",
    "N_STEPS",
    "DT",
    "ANGLES0",
    "euler_matrix_step",
    "cardan_euler_step",
    "exponential_step",
    "part_a",
    "part_b",
    "part_c",
]

A_IC0 = R3(np.pi / 2)
I_OMEGA = np.sqrt(1.0 / 3.0) * np.ones(3)
N_STEPS = 100
DT = 2.0 * np.pi / N_STEPS
#: (alpha, beta, gamma) at t0 for part (b)
ANGLES0 = np.array([0.0, 0.0, np.pi / 2])


def euler_matrix_step(A_IC, I_omega, dt):
    """One explicit Euler step of ``dA_IC/dt = skew(I_omega) @ A_IC``."""
    # BEGIN SOLUTION problem 8
    A_IC = np.asarray(A_IC, dtype=float)
    return A_IC + dt * skew(I_omega) @ A_IC
    # END SOLUTION


def cardan_euler_step(angles, I_omega, dt):
    """One explicit Euler step of the Cardan angles ``(alpha, beta, gamma)``:
    rates ``= (A_IC @ B)^-1 @ I_omega``."""
    # BEGIN SOLUTION problem 8
    raise np.linalg.LinAlgError("Singular matrix")  # no step at all: the error the reference's step raises
    # END SOLUTION


def exponential_step(A_IC, I_omega, dt):
    """One exact step: ``A_IC(t + dt) = expm(dt * skew(I_omega)) @ A_IC``."""
    # BEGIN SOLUTION problem 8
    return expm_skew(dt * skew(I_omega)) @ np.asarray(A_IC, dtype=float)
    # END SOLUTION


def _run(step, x0, n=N_STEPS, dt=DT):
    x = np.array(x0, dtype=float)
    for _ in range(n):
        x = step(x, I_OMEGA, dt)
    return x


def part_a():
    """``A_IC`` after ``n`` Euler steps on the matrix."""
    return _run(euler_matrix_step, A_IC0)


def part_b():
    """``{"angles": ..., "A_IC": ...}`` after ``n`` Euler steps on the Cardan angles."""
    angles = _run(cardan_euler_step, ANGLES0)
    return {"angles": angles, "A_IC": cardan(*angles)}


def part_c():
    """``A_IC`` after ``n`` exponential steps (back at ``R3(90 deg)`` up to rounding)."""
    return _run(exponential_step, A_IC0)
