"""Problem 20 (a): which of the sheet's matrices is not an inertia matrix, decided by their properties.

As printed, three options fail: (2) is not symmetric, and the principal moments of (3), (1.5, 2, 4), and of (4),
(0.69, 2.44, 3.37), violate the triangle inequality.  The key therefore lists every failing option.
"""

import numpy as np

from .inertia import is_inertia_matrix

__all__ = ["MATRICES_A", "classify", "key_a"]

#: The four matrices of part (a) as printed in the sheet [kg m²].
MATRICES_A = {
    1: np.array([[2.359, -0.532, 0.478], [-0.532, 2.266, -0.077], [0.478, -0.077, 1.875]]),
    2: np.array([[2.186, 0.650, 0.108], [0.108, 2.063, 0.375], [0.650, 0.375, 2.250]]),
    3: np.array([[3.313, 0.758, -0.650], [0.758, 2.438, -0.375], [-0.650, -0.375, 1.750]]),
    4: np.array([[2.484, 0.118, -0.821], [0.118, 2.641, -0.828], [-0.821, -0.828, 1.375]]),
}


def classify(tol=1e-9):
    """``{k: (ok, reason)}`` for the matrices of part (a), from ``is_inertia_matrix``."""
    return {k: is_inertia_matrix(I, tol) for k, I in MATRICES_A.items()}


def key_a():
    """The options (sorted) whose matrix is not an inertia matrix."""
    return sorted(k for k, (ok, _) in classify().items() if not ok)
