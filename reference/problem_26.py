"""Problem 26: the chairoplane.

Generalised coordinates ``q = (beta, phi)``: ``beta`` turns the carousel about the vertical axis, ``phi`` swings
the chain of length ``l3`` outward from the vertical.  The chain hangs from the end of an arm of length ``l2`` at
height ``l1`` (problem data):
``x = ((l2 + l3 sin phi) sin beta, l1 - l3 cos phi, (l2 + l3 sin phi) cos beta)``.
"""

import numpy as np

__all__ = ["position", "jacobian"]


def position(beta, phi, l1, l2, l3):
    """Position ``x = f(q)`` of the point P (the seat) for ``q = (beta, phi)``."""
    # BEGIN SOLUTION problem 26
    radius = l2 + l3 * np.sin(phi)
    return np.array([radius * np.sin(beta), l1 - l3 * np.cos(phi), radius * np.cos(beta)])
    # END SOLUTION


def jacobian(beta, phi, l1, l2, l3):
    """Analytic constraint Jacobian ``J_f = d f / d q`` (3 x 2, columns beta, phi): ``x_dot = J_f q_dot``."""
    # BEGIN SOLUTION problem 26
    radius = l2 + l3 * np.sin(phi)
    cb, sb = np.cos(beta), np.sin(beta)
    cp = np.cos(phi)
    return np.array(
        [
            [radius * cb, l3 * cp * sb],
            [0.0, l3 * np.sin(phi)],
            [-radius * sb, l3 * cp * cb],
        ]
    )
    # END SOLUTION
# BEGIN REFERENCE ONLY


#: mistakes of ``mistaken_position``
POSITION_MISTAKES = ("beta_sin_cos", "phi_sin_cos", "sign_flip", "radius", "degrees")


def mistaken_position(beta, phi, l1, l2, l3, mistake=None):
    """The seat's position with ``mistake`` applied, for the grader's diagnoses only (complex arguments are kept,
    for complex-step derivatives): ``beta_sin_cos``, ``phi_sin_cos`` (sin and cos swapped), ``sign_flip`` (the
    chain hanging up), ``radius`` (the arm l2 left out), ``degrees`` (the angles read as degrees)."""
    if mistake == "degrees":
        beta, phi = beta * np.pi / 180.0, phi * np.pi / 180.0
    reach, drop = (l3 * np.cos(phi), l3 * np.sin(phi)) if mistake == "phi_sin_cos" else (
        l3 * np.sin(phi), l3 * np.cos(phi))
    radius = reach if mistake == "radius" else l2 + reach
    height = l1 + drop if mistake == "sign_flip" else l1 - drop
    across, along = (np.cos(beta), np.sin(beta)) if mistake == "beta_sin_cos" else (np.sin(beta), np.cos(beta))
    return np.array([radius * across, height, radius * along])
# END REFERENCE ONLY
