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
    # BEGIN SOLUTION problem 16
    masses, points = np.asarray(masses, dtype=float), np.asarray(points, dtype=float)
    return masses @ points / masses.sum()
    # END SOLUTION


def point_masses_inertia(masses, points):
    """Inertia of point masses about their centre of gravity:
    ``sum m_i (|d_i|^2 E - d_i d_i^T)`` with ``d_i = r_i - r_G``."""
    # BEGIN SOLUTION problem 16
    masses, points = np.asarray(masses, dtype=float), np.asarray(points, dtype=float)
    d = points - centre_of_gravity(masses, points)
    second_moments = (d.T * masses) @ d  # sum m_i d_i d_i^T
    return np.trace(second_moments) * np.eye(3) - second_moments
    # END SOLUTION


def cuboid_inertia(m, a, b, c):
    """Homogeneous cuboid of mass ``m`` with edges ``a``, ``b``, ``c``: ``m/12 diag(b²+c², a²+c², a²+b²)``."""
    # BEGIN SOLUTION problem 16
    return m / 12 * np.diag([b**2 + c**2, a**2 + c**2, a**2 + b**2])
    # END SOLUTION


def ellipsoid_inertia(m, a, b, c):
    """Homogeneous ellipsoid of mass ``m`` with *full* axes ``a``, ``b``, ``c`` (semi-axes a/2, b/2, c/2):
    ``m/5 diag((b/2)²+(c/2)², (a/2)²+(c/2)², (a/2)²+(b/2)²)``."""
    # BEGIN SOLUTION problem 16
    return m / 20 * np.diag([b**2 + c**2, a**2 + c**2, a**2 + b**2])
    # END SOLUTION


def face_centre_particles(m, a, b, c):
    """The six particles of mass ``m/6`` at the face centres of the cuboid with edges ``a``, ``b``, ``c``:
    ``(masses, points)`` with points ``(±a/2, 0, 0)``, ``(0, ±b/2, 0)``, ``(0, 0, ±c/2)``."""
    points = 0.5 * np.array([[a, 0, 0], [-a, 0, 0], [0, b, 0], [0, -b, 0], [0, 0, c], [0, 0, -c]], dtype=float)
    return np.full(6, m / 6), points


def particles_inertia(m, a, b, c):
    """Six particles of mass ``m/6`` at the face centres of the cuboid with edges ``a``, ``b``, ``c``
    (see ``face_centre_particles``); equals ``cuboid_inertia(m, a, b, c)``."""
    # BEGIN SOLUTION problem 16
    return point_masses_inertia(*face_centre_particles(m, a, b, c))
    # END SOLUTION


def cuboid_inertia_symbolic():
    """``cuboid_inertia`` as a ``sympy.Matrix`` in the positive symbols ``m, a, b, c``."""
    # BEGIN SOLUTION problem 16
    import sympy as sp

    m, a, b, c = sp.symbols("m a b c", positive=True)
    return m / 12 * sp.diag(b**2 + c**2, a**2 + c**2, a**2 + b**2)
    # END SOLUTION


def ellipsoid_inertia_symbolic():
    """``ellipsoid_inertia`` (full axes) as a ``sympy.Matrix`` in the positive symbols ``m, a, b, c``."""
    # BEGIN SOLUTION problem 16
    import sympy as sp

    m, a, b, c = sp.symbols("m a b c", positive=True)
    ha, hb, hc = a / 2, b / 2, c / 2
    return m / 5 * sp.diag(hb**2 + hc**2, ha**2 + hc**2, ha**2 + hb**2)
    # END SOLUTION


def particles_inertia_symbolic():
    """``particles_inertia`` as a ``sympy.Matrix`` in the positive symbols ``m, a, b, c``, summed over the six
    particles (their centre of gravity is the origin)."""
    # BEGIN SOLUTION problem 16
    import sympy as sp

    m, a, b, c = sp.symbols("m a b c", positive=True)
    half = [(a / 2, 0, 0), (0, b / 2, 0), (0, 0, c / 2)]
    points = [sp.Matrix(p) * s for p in half for s in (1, -1)]
    return sp.simplify(sum((m / 6 * (r.dot(r) * sp.eye(3) - r * r.T) for r in points), sp.zeros(3, 3)))
    # END SOLUTION


def principal_second_moments(I1, I2, I3):
    """Second moments ``(sum m x², sum m y², sum m z²)`` of a body with principal moments ``I1, I2, I3``:
    ``((-I1+I2+I3)/2, (I1-I2+I3)/2, (I1+I2-I3)/2)``.

    Raises ``ValueError`` if the moments violate the triangle inequality; rounding-level negatives become 0.
    """
    # BEGIN SOLUTION problem 16
    moments = np.array([I1, I2, I3], dtype=float)
    second = 0.5 * (moments.sum() - 2.0 * moments)
    if np.any(second < -1e-12 * np.abs(moments).sum()):
        raise ValueError(f"principal moments {moments} violate the triangle inequality")
    return np.clip(second, 0.0, None)
    # END SOLUTION


def cuboid_dimensions(m, I1, I2, I3):
    """Edges ``(a, b, c)`` of the homogeneous cuboid of mass ``m`` with ``diag(I1, I2, I3)``:
    ``a = sqrt(6/m (-I1+I2+I3))``, cyclic."""
    # BEGIN SOLUTION problem 16
    return tuple(np.sqrt(12.0 / m * principal_second_moments(I1, I2, I3)).tolist())
    # END SOLUTION


def ellipsoid_dimensions(m, I1, I2, I3):
    """Full axes ``(a, b, c)`` of the homogeneous ellipsoid of mass ``m`` with ``diag(I1, I2, I3)``:
    ``a = sqrt(10/m (-I1+I2+I3))``, cyclic."""
    # BEGIN SOLUTION problem 16
    return tuple(np.sqrt(20.0 / m * principal_second_moments(I1, I2, I3)).tolist())
    # END SOLUTION


def particles_dimensions(m, I1, I2, I3):
    """Cuboid edges ``(a, b, c)`` whose six face-centre particles (mass ``m/6`` each) have
    ``diag(I1, I2, I3)``: ``a = sqrt(6/m (-I1+I2+I3))``, cyclic (the same as ``cuboid_dimensions``)."""
    # BEGIN SOLUTION problem 16
    return tuple(np.sqrt(12.0 / m * principal_second_moments(I1, I2, I3)).tolist())
    # END SOLUTION


# --- problem 17: representations of an inertia matrix ---------------------------------------------------------


def principal_axes(B_I_G):
    """Eigen-decomposition ``B_I_G = V diag(I1, I2, I3) V^T`` with ``I1 <= I2 <= I3`` and ``V`` a proper
    rotation (``det V = +1``; its columns are the principal axes in B).  Returns ``(moments, V)``."""
    # BEGIN SOLUTION problem 17
    moments, V = np.linalg.eigh(as_matrix(B_I_G))
    if np.linalg.det(V) < 0:
        V[:, 2] = -V[:, 2]
    return moments, V
    # END SOLUTION


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
    # BEGIN SOLUTION problem 17
    moments, V = principal_axes(B_I_G)
    Sx, Sy, Sz = principal_second_moments(*moments)
    x, y, z = np.sqrt(3.0 * np.array([Sx, Sy, Sz]) / m)
    six = np.array([[x, 0, 0], [-x, 0, 0], [0, y, 0], [0, -y, 0], [0, 0, z], [0, 0, -z]])
    x, y, z = np.sqrt(np.array([2.0 * Sx, 2.0 * Sy, Sz]) / m)
    four = np.array([[x, 0, -z], [-x, 0, -z], [0, -y, z], [0, y, z]])
    return {
        "six_points": {"masses": np.full(6, m / 6), "points": six @ V.T},
        "four_points": {"masses": np.full(4, m / 4), "points": four @ V.T},
        "ellipsoid": {"mass": m, "axes": np.array(ellipsoid_dimensions(m, *moments)), "V": V},
        "cuboid": {"mass": m, "edges": np.array(cuboid_dimensions(m, *moments)), "V": V},
    }
    # END SOLUTION


# --- problem 18: a point without acceleration -----------------------------------------------------------------


def non_accelerating_point(a_x, a_y, r_x, r_y):
    """Rate ``omega`` and acceleration ``omega_dot`` about the 3-axis for which the body point Q at
    ``B_r_BQ = (r_x, r_y, 0)`` does not accelerate, given ``B_a_B = (a_x, a_y, 0)``.

    ``I_a_Q = 0`` requires ``omega² = (a_x r_x + a_y r_y)/(r_x² + r_y²)`` and
    ``omega_dot = (a_x r_y - a_y r_x)/(r_x² + r_y²)``.  Returns ``(omega, omega_dot)`` with ``omega >= 0``;
    ``(-omega, omega_dot)`` is the other solution (the direction of rotation does not matter).
    Raises ``ValueError`` if no solution exists (``a · r < 0``) or Q coincides with B (``r = 0``).
    """
    # BEGIN SOLUTION problem 18
    r2 = r_x**2 + r_y**2
    if r2 == 0.0:
        raise ValueError("Q coincides with B: its acceleration does not depend on omega")
    a_dot_r = a_x * r_x + a_y * r_y
    if a_dot_r < 0.0:
        raise ValueError("no real omega: the acceleration of B points away from Q (a · r < 0)")
    return float(np.sqrt(a_dot_r / r2)), float((a_x * r_y - a_y * r_x) / r2)
    # END SOLUTION


# --- problem 19: composite bodies -----------------------------------------------------------------------------


def parallel_axis(I_G, m, r):
    """Parallel-axis (Steiner) theorem: inertia about a point O of a body of mass ``m`` with inertia ``I_G``
    about its centre of gravity G, ``r`` the vector between O and G: ``I_O = I_G + m (|r|² E - r r^T)``."""
    # BEGIN SOLUTION problem 19
    r = as_vector(r)
    return as_matrix(I_G) + m * ((r @ r) * np.eye(3) - np.outer(r, r))
    # END SOLUTION


def composite_inertia(masses, centres, inertias):
    """Inertia of a composite body about its centre of gravity, from parts with masses ``m_k``, centres of
    gravity ``r_k`` (shape (n, 3)) and inertias ``I_k`` about their own centres (all in the same coordinates):
    ``sum_k parallel_axis(I_k, m_k, r_k - r_G)``."""
    # BEGIN SOLUTION problem 19
    r_G = centre_of_gravity(masses, centres)
    return sum(parallel_axis(I, m, r - r_G) for m, r, I in zip(masses, np.asarray(centres, dtype=float), inertias))
    # END SOLUTION


# --- problem 20: what makes an inertia matrix -----------------------------------------------------------------


def is_inertia_matrix(I, tol=1e-9):
    """Whether ``I`` can be the inertia matrix of a rigid body about its centre of gravity.

    Checks, in this order, with tolerance ``tol`` relative to the largest entry: shape 3 x 3, symmetry,
    positive definiteness, and the triangle inequality of the principal moments (``I3 <= I1 + I2``).
    Returns ``(ok, reason)``; ``reason`` names the first property that fails.
    """
    # BEGIN SOLUTION problem 20
    I = np.asarray(I, dtype=float)
    if I.shape != (3, 3):
        return False, f"not a 3 x 3 matrix (shape {I.shape})"
    scale = max(float(np.abs(I).max()), np.finfo(float).tiny)
    if np.abs(I - I.T).max() > tol * scale:
        return False, "not symmetric"
    I1, I2, I3 = np.linalg.eigvalsh(I)
    if I1 <= tol * scale:
        return False, f"not positive definite (smallest principal moment {I1:.4g})"
    if I3 > I1 + I2 + tol * scale:
        return False, f"principal moments ({I1:.4g}, {I2:.4g}, {I3:.4g}) violate the triangle inequality"
    return True, "symmetric, positive definite, principal moments satisfy the triangle inequality"
    # END SOLUTION
