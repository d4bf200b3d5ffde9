"""Problem 19: inertia about the 3-axis of the object of Figure 21, as a multiple of m/120.

The object (grid 1 m, total mass m): a central block 4 x 2 of mass 0.8 m centred at the origin, and two 1 x 1
blocks of mass 0.1 m each centred at (1.5, 1.5) and (-1.5, -1.5).  The figure is planar; the depth along the
3-axis does not change the inertia about the 3-axis.
"""

import numpy as np

from .inertia import composite_inertia, cuboid_inertia

__all__ = ["blocks", "inertia", "answer"]


def blocks(m=1.0, depth=0.0):
    """The blocks as ``(masses, centres, inertias)``, each inertia about the block's own centre."""
    masses = np.array([0.8, 0.1, 0.1]) * m
    centres = np.array([[0.0, 0.0, 0.0], [1.5, 1.5, 0.0], [-1.5, -1.5, 0.0]])
    edges = [(4.0, 2.0, depth), (1.0, 1.0, depth), (1.0, 1.0, depth)]
    return masses, centres, [cuboid_inertia(mk, *e) for mk, e in zip(masses, edges)]


def inertia(m=1.0, depth=0.0):
    """The object's inertia matrix about its centre of gravity (parallel-axis theorem over the blocks)."""
    return composite_inertia(*blocks(m, depth))


def answer(m=1.0):
    """``I3 / (m/120)``; the course's answer is 272."""
    return float(inertia(m)[2, 2] / (m / 120))
