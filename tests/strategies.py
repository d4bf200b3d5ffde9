"""Hypothesis strategies shared by the tests: angles, vectors, rotations, inertia matrices."""

import numpy as np
from hypothesis import strategies as st

from reference.rotations import R1, R2, R3

finite = dict(allow_nan=False, allow_infinity=False)

angles = st.floats(-np.pi, np.pi, **finite)
small_angles = st.floats(-1.4, 1.4, **finite)


def vectors(n=3, bound=10.0):
    """Arrays of shape (n,) with entries in [-bound, bound]."""
    return st.lists(st.floats(-bound, bound, **finite), min_size=n, max_size=n).map(np.array)


@st.composite
def rotations(draw):
    """Proper rotation matrices, built from three Cardan angles (covers SO(3))."""
    a, b, g = draw(angles), draw(st.floats(-np.pi / 2, np.pi / 2, **finite)), draw(angles)
    return R3(g) @ R2(b) @ R1(a)


@st.composite
def principal_moments(draw, low=0.1, high=10.0):
    """Three principal moments that satisfy the triangle inequality (I_i <= I_j + I_k)."""
    # moments of a mass distribution: I1 = y2 + z2, I2 = x2 + z2, I3 = x2 + y2 with second moments >= 0
    x2, y2, z2 = (draw(st.floats(low / 2, high / 2, **finite)) for _ in range(3))
    return np.array([y2 + z2, x2 + z2, x2 + y2])


@st.composite
def inertia_matrices(draw):
    """Symmetric positive-definite inertia matrices that satisfy the triangle inequality."""
    A = draw(rotations())
    return A @ np.diag(draw(principal_moments())) @ A.T
