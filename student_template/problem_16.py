"""Problem 16: inertia matrices of a cuboid, an ellipsoid and six particles, and the inverse maps."""

from .inertia import (
    cuboid_dimensions,
    cuboid_inertia_symbolic,
    ellipsoid_dimensions,
    ellipsoid_inertia_symbolic,
    particles_dimensions,
    particles_inertia_symbolic,
)

__all__ = ["part_a", "part_b"]


def part_a():
    """(a) The three inertia matrices as ``sympy.Matrix`` in ``m, a, b, c``:
    ``{"cuboid", "ellipsoid", "particles"}``."""
    return {
        "cuboid": cuboid_inertia_symbolic(),
        "ellipsoid": ellipsoid_inertia_symbolic(),
        "particles": particles_inertia_symbolic(),
    }


def part_b(m, I1, I2, I3):
    """(b) The dimensions ``(a, b, c)`` of each object with mass ``m`` and inertia ``diag(I1, I2, I3)``."""
    return {
        "cuboid": cuboid_dimensions(m, I1, I2, I3),
        "ellipsoid": ellipsoid_dimensions(m, I1, I2, I3),
        "particles": particles_dimensions(m, I1, I2, I3),
    }
