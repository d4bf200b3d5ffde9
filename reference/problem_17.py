"""Problem 17: four bodies representing each of the sheet's inertia matrices (m = 10 kg)."""

import numpy as np

from .inertia import inertia_representations

__all__ = ["MASS", "MATRICES", "run_case"]

MASS = 10.0
#: The sheet's inertia matrices, cases 1-4 [kg m²].
MATRICES = {
    1: np.eye(3),
    2: np.diag([1.5, 2.0, 2.5]),
    3: np.array([[1.56, -0.16, 0.23], [-0.16, 1.95, -0.50], [0.23, -0.50, 2.5]]),
    4: np.diag([1.0, 3.0, 3.0]),
}


def run_case(k):
    """The four representations (see ``inertia.inertia_representations``) of matrix ``k`` (1-4)."""
    return inertia_representations(MATRICES[k], MASS)
