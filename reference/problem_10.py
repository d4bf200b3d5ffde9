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


# BEGIN REFERENCE ONLY
# The grader's computation of the keys: not part of the student's package.


def orthonormality_defect(A):
    """Largest entry of ``|A.T @ A - E|``."""
    A = np.asarray(A, dtype=float)
    return float(np.max(np.abs(A.T @ A - np.eye(3))))


def is_orthonormal(A, tol=PRINT_TOL):
    """True when ``A.T @ A == E`` to ``tol``."""
    return orthonormality_defect(A) <= tol


def is_rotation(A, tol=PRINT_TOL):
    """True for a proper rotation: orthonormal with determinant +1 (a reflection has -1)."""
    return is_orthonormal(A, tol) and abs(np.linalg.det(A) - 1.0) <= 3 * tol


def _only(indices, what):
    if len(indices) != 1:
        raise ValueError(f"expected exactly one matrix that {what}, found options {indices}")
    return indices[0]


def answer_a():
    """1-based index of the matrix in (a) that is NOT orthonormal."""
    return _only([k + 1 for k, A in enumerate(MATRICES_A) if not is_orthonormal(A)], "is not orthonormal")


def answer_b():
    """1-based index of the matrix in (b) that IS a rotation."""
    return _only([k + 1 for k, A in enumerate(MATRICES_B) if is_rotation(A)], "is a rotation")


def nearest_rotation(A):
    """The proper rotation closest to ``A`` in the Frobenius norm (SVD projection)."""
    U, _, Vt = np.linalg.svd(np.asarray(A, dtype=float))
    D = np.diag([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))])
    return U @ D @ Vt
# END REFERENCE ONLY
