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
