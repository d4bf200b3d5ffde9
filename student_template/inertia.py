"""Inertia matrices: simple bodies, point masses, representations, composition and validity (problems 16-20).

Conventions (problem data): ``B_I_G`` is the inertia about the centre of gravity G in body coordinates,
``I = sum m_i (|r_i|^2 E - r_i r_i^T)`` with ``r_i`` measured from G.  Bodies are centred at G and aligned with
the body axes; ``a``, ``b``, ``c`` are the *full* extents along the 1-, 2- and 3-axis (cuboid edges, ellipsoid
full axes, distances between opposite face centres).  Principal moments are sorted ``I1 <= I2 <= I3`` where
an order matters.  The symbolic versions return ``sympy.Matrix`` objects in the positive symbols ``m, a, b, c``.
"""

import numpy as np

from .conventions import as_matrix, as_vector

__all__ = [
    "centre_of_gravity",
    "point_masses_inertia",
    "cuboid_inertia",
    "ellipsoid_inertia",
    "particles_inertia",
    "face_centre_particles",
    "cuboid_inertia_symbolic",
    "ellipsoid_inertia_symbolic",
    "particles_inertia_symbolic",
    "principal_second_moments",
    "cuboid_dimensions",
    "ellipsoid_dimensions",
    "particles_dimensions",
    "principal_axes",
    "inertia_representations",
    "non_accelerating_point",
    "parallel_axis",
    "composite_inertia",
    "is_inertia_matrix",
]


# --- problem 16: inertia of simple bodies ---------------------------------------------------------------------


def centre_of_gravity(masses, points):
    """Centre of gravity ``sum m_i r_i / sum m_i`` of point masses (``points`` has shape (n, 3))."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: centre_of_gravity is not implemented yet")


def point_masses_inertia(masses, points):
    """Inertia of point masses about their centre of gravity:
    ``sum m_i (|d_i|^2 E - d_i d_i^T)`` with ``d_i = r_i - r_G``."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: point_masses_inertia is not implemented yet")


def cuboid_inertia(m, a, b, c):
    """Homogeneous cuboid of mass ``m`` with edges ``a``, ``b``, ``c``: ``m/12 diag(b²+c², a²+c², a²+b²)``."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: cuboid_inertia is not implemented yet")


def ellipsoid_inertia(m, a, b, c):
    """Homogeneous ellipsoid of mass ``m`` with *full* axes ``a``, ``b``, ``c`` (semi-axes a/2, b/2, c/2):
    ``m/5 diag((b/2)²+(c/2)², (a/2)²+(c/2)², (a/2)²+(b/2)²)``."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: ellipsoid_inertia is not implemented yet")


def face_centre_particles(m, a, b, c):
    """The six particles of mass ``m/6`` at the face centres of the cuboid with edges ``a``, ``b``, ``c``:
    ``(masses, points)`` with points ``(±a/2, 0, 0)``, ``(0, ±b/2, 0)``, ``(0, 0, ±c/2)``."""
    points = 0.5 * np.array([[a, 0, 0], [-a, 0, 0], [0, b, 0], [0, -b, 0], [0, 0, c], [0, 0, -c]], dtype=float)
    return np.full(6, m / 6), points


def particles_inertia(m, a, b, c):
    """Six particles of mass ``m/6`` at the face centres of the cuboid with edges ``a``, ``b``, ``c``
    (see ``face_centre_particles``); equals ``cuboid_inertia(m, a, b, c)``."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: particles_inertia is not implemented yet")


def cuboid_inertia_symbolic():
    """``cuboid_inertia`` as a ``sympy.Matrix`` in the positive symbols ``m, a, b, c``."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: cuboid_inertia_symbolic is not implemented yet")


def ellipsoid_inertia_symbolic():
    """``ellipsoid_inertia`` (full axes) as a ``sympy.Matrix`` in the positive symbols ``m, a, b, c``."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: ellipsoid_inertia_symbolic is not implemented yet")


def particles_inertia_symbolic():
    """``particles_inertia`` as a ``sympy.Matrix`` in the positive symbols ``m, a, b, c``, summed over the six
    particles (their centre of gravity is the origin)."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: particles_inertia_symbolic is not implemented yet")


def principal_second_moments(I1, I2, I3):
    """Second moments ``(sum m x², sum m y², sum m z²)`` of a body with principal moments ``I1, I2, I3``:
    ``((-I1+I2+I3)/2, (I1-I2+I3)/2, (I1+I2-I3)/2)``.

    Raises ``ValueError`` if the moments violate the triangle inequality; rounding-level negatives become 0.
    """
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: principal_second_moments is not implemented yet")


def cuboid_dimensions(m, I1, I2, I3):
    """Edges ``(a, b, c)`` of the homogeneous cuboid of mass ``m`` with ``diag(I1, I2, I3)``:
    ``a = sqrt(6/m (-I1+I2+I3))``, cyclic."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: cuboid_dimensions is not implemented yet")


def ellipsoid_dimensions(m, I1, I2, I3):
    """Full axes ``(a, b, c)`` of the homogeneous ellipsoid of mass ``m`` with ``diag(I1, I2, I3)``:
    ``a = sqrt(10/m (-I1+I2+I3))``, cyclic."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: ellipsoid_dimensions is not implemented yet")


def particles_dimensions(m, I1, I2, I3):
    """Cuboid edges ``(a, b, c)`` whose six face-centre particles (mass ``m/6`` each) have
    ``diag(I1, I2, I3)``: ``a = sqrt(6/m (-I1+I2+I3))``, cyclic (the same as ``cuboid_dimensions``)."""
    # TODO problem 16: write your solution here
    raise NotImplementedError("Problem 16: particles_dimensions is not implemented yet")


# --- problem 17: representations of an inertia matrix ---------------------------------------------------------


def principal_axes(B_I_G):
    """Eigen-decomposition ``B_I_G = V diag(I1, I2, I3) V^T`` with ``I1 <= I2 <= I3`` and ``V`` a proper
    rotation (``det V = +1``; its columns are the principal axes in B).  Returns ``(moments, V)``."""
    # TODO problem 17: write your solution here
    raise NotImplementedError("Problem 17: principal_axes is not implemented yet")


def inertia_representations(B_I_G, m):
    """Four bodies of mass ``m`` that have the inertia ``B_I_G`` about their centre of gravity at the origin.

    Built from ``principal_axes``: ``B_I_G = V diag(I1, I2, I3) V^T``; points are given in B (mapped by V).
    Returns a dict (the switch cases of the course's template):

    - ``"six_points"`` (case 1): ``{"masses", "points"}``, six masses m/6 at ``V @ (±x,0,0), (0,±y,0), (0,0,±z)``,
      ``x = sqrt(1.5/m (-I1+I2+I3))``, cyclic;
    - ``"four_points"`` (case 2): ``{"masses", "points"}``, four masses m/4 at ``V @`` ``(+x,0,-z)``, ``(-x,0,-z)``,
      ``(0,-y,+z)``, ``(0,+y,+z)``, ``x = sqrt((-I1+I2+I3)/m)``, ``y = sqrt((I1-I2+I3)/m)``,
      ``z = sqrt((I1+I2-I3)/(2m))``;
    - ``"ellipsoid"`` (case 3): ``{"mass", "axes", "V"}``, full axes along the columns of V;
    - ``"cuboid"`` (case 4): ``{"mass", "edges", "V"}``, edges along the columns of V.

    ``B_I_G`` must be a valid inertia matrix (see ``is_inertia_matrix``).
    """
    # TODO problem 17: write your solution here
    raise NotImplementedError("Problem 17: inertia_representations is not implemented yet")


# --- problem 18: a point without acceleration -----------------------------------------------------------------


def non_accelerating_point(a_x, a_y, r_x, r_y):
    """Rate ``omega`` and acceleration ``omega_dot`` about the 3-axis for which the body point Q at
    ``B_r_BQ = (r_x, r_y, 0)`` does not accelerate, given ``B_a_B = (a_x, a_y, 0)``.

    ``I_a_Q = 0`` requires ``omega² = (a_x r_x + a_y r_y)/(r_x² + r_y²)`` and
    ``omega_dot = (a_x r_y - a_y r_x)/(r_x² + r_y²)``.  Returns ``(omega, omega_dot)`` with ``omega >= 0``;
    ``(-omega, omega_dot)`` is the other solution (the direction of rotation does not matter).
    Raises ``ValueError`` if no solution exists (``a · r < 0``) or Q coincides with B (``r = 0``).
    """
    # TODO problem 18: write your solution here
    raise NotImplementedError("Problem 18: non_accelerating_point is not implemented yet")


# --- problem 19: composite bodies -----------------------------------------------------------------------------


def parallel_axis(I_G, m, r):
    """Parallel-axis (Steiner) theorem: inertia about a point O of a body of mass ``m`` with inertia ``I_G``
    about its centre of gravity G, ``r`` the vector between O and G: ``I_O = I_G + m (|r|² E - r r^T)``."""
    # TODO problem 19: write your solution here
    raise NotImplementedError("Problem 19: parallel_axis is not implemented yet")


def composite_inertia(masses, centres, inertias):
    """Inertia of a composite body about its centre of gravity, from parts with masses ``m_k``, centres of
    gravity ``r_k`` (shape (n, 3)) and inertias ``I_k`` about their own centres (all in the same coordinates):
    ``sum_k parallel_axis(I_k, m_k, r_k - r_G)``."""
    # TODO problem 19: write your solution here
    raise NotImplementedError("Problem 19: composite_inertia is not implemented yet")


# --- problem 20: what makes an inertia matrix -----------------------------------------------------------------


def is_inertia_matrix(I, tol=1e-9):
    """Whether ``I`` can be the inertia matrix of a rigid body about its centre of gravity.

    Checks, in this order, with tolerance ``tol`` relative to the largest entry: shape 3 x 3, symmetry,
    positive definiteness, and the triangle inequality of the principal moments (``I3 <= I1 + I2``).
    Returns ``(ok, reason)``; ``reason`` names the first property that fails.
    """
    # TODO problem 20: write your solution here
    raise NotImplementedError("Problem 20: is_inertia_matrix is not implemented yet")
