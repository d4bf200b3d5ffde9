"""Problem 10: understanding rotation matrices.

The keys of (a) and (b) are computed from the printed matrices' properties (in a reference-only block: the
student answers in answers.toml); (c) is read off a figure, so any proper rotation close to the course's
approximate matrix is accepted.  The printed matrices carry three decimals,
so their properties hold to ``PRINT_TOL`` only.
"""

import numpy as np

__all__ = ["PRINT_TOL", "MATRICES_A", "MATRICES_B", "COURSE_C"]

#: tolerance for properties of matrices printed with three decimals
PRINT_TOL = 5e-3

MATRICES_A = (
    np.array([[0.354, -0.573, 0.739], [0.612, 0.739, 0.280], [-0.707, 0.354, 0.612]]),
    np.array([[0.500, -0.750, 0.433], [0.866, 0.433, -0.250], [0.0, 0.500, 0.866]]),
    np.array([[0.354, 0.612, -0.707], [-0.573, 0.739, 0.354], [0.739, 0.280, 0.612]]),
    np.array([[0.354, 0.612, -0.707], [-0.573, 0.739, 1.354], [0.739, 0.280, 0.612]]),
)

MATRICES_B = (
    np.array([[0.866, -0.500, 0.433], [-0.500, 0.433, 0.750], [0.433, 0.750, 0.500]]),
    np.array([[0.866, -0.250, 0.433], [0.500, 0.433, -0.750], [0.0, 0.866, 0.500]]),
    np.array([[0.866, 0.250, 0.433], [0.500, -0.433, -0.750], [0.0, -0.866, 0.500]]),
    np.array([[0.866, 0.500, 0.433], [0.500, -0.433, -0.750], [0.433, -0.750, 0.500]]),
)

#: the course's approximate A_IC for (c) (columns: the axes of C in I); itself not orthonormal
COURSE_C = np.array([[0.15, -0.6, -0.9], [-0.1, 0.9, 0.6], [0.95, 0.2, 0.1]])


