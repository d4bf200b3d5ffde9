"""Problem 39: the steam turbine, a rotor with a misaligned axis and the loads on its bearings.

Problem data P39: mass ``m = 1e5 kg``; inertia ``50 000 kg m^2`` about the axis of symmetry (the 1-axis) and
``450 000 kg m^2`` about every axis perpendicular to it through the centre of gravity.  The rotor turns at
1500 rpm about the fixed 1-axis, ``omega = (1500 rpm, 0, 0)``, ``omegaDot = 0``; with the sheet's approximation
``pi = sqrt(10)`` that is ``50 sqrt(10) rad/s``.  The misalignment is a small rotation by ``alpha = 1e-3`` about
the 3-axis (``sin alpha = alpha``, ``cos alpha = 1``).  The bearings sit on the rotation axis at ``x = -d/2``
(bearing 1) and ``x = +d/2`` (bearing 2) from the centre of gravity, ``d = 10 m``; gravity ``g = 10`` acts along
``-y``.  Model answers: ``I2 ~ [[50000.45, -400, 0], [-400, 450000.05, 0], [0, 0, 450000]]``,
``F1 = (0, 1.5e6, 0) N``, ``F2 = (0, -0.5e6, 0) N``.
"""

import numpy as np

__all__ = [
    "MASS",
    "I_AXIAL",
    "I_TRANSVERSE",
    "ALPHA",
    "OMEGA",
    "GRAVITY_39",
    "BEARING_DISTANCE",
    "inertia_aligned",
    "small_rotation",
    "inertia_misaligned",
    "bearing_forces",
    "solve",
]

MASS = 1e5
I_AXIAL = 5e4
I_TRANSVERSE = 4.5e5
ALPHA = 1e-3
#: 1500 rpm with the sheet's pi = sqrt(10): 1500 * 2 pi / 60 = 50 pi = 50 sqrt(10) rad/s
OMEGA = 50.0 * np.sqrt(10.0)
GRAVITY_39 = 10.0
BEARING_DISTANCE = 10.0


def inertia_aligned(I_axial=I_AXIAL, I_transverse=I_TRANSVERSE):
    """(a) ``I1``: the inertia of the rotor about its centre of gravity with its axis of symmetry along 1."""
    # TODO problem 39: write your solution here
    raise NotImplementedError("Problem 39: inertia_aligned is not implemented yet")


def small_rotation(alpha):
    """The rotation by the small angle ``alpha`` about the 3-axis with ``sin alpha = alpha``, ``cos alpha = 1``."""
    return np.array([[1.0, -alpha, 0.0], [alpha, 1.0, 0.0], [0.0, 0.0, 1.0]])


def inertia_misaligned(I1, alpha=ALPHA):
    """(b) ``I2``: the inertia ``I1`` of the rotor turned by the small angle ``alpha`` about the 3-axis, in the
    frame of the rotation axis: ``I2 = A I1 A.T`` with ``A = small_rotation(alpha)``."""
    # TODO problem 39: write your solution here
    raise NotImplementedError("Problem 39: inertia_misaligned is not implemented yet")


def bearing_forces(I2, omega=OMEGA, m=MASS, g=GRAVITY_39, d=BEARING_DISTANCE):
    """(c) ``(F1, F2)``: the forces (3-vectors, in the frame of the rotation axis) that bearing 1 at ``x = -d/2``
    and bearing 2 at ``x = +d/2`` exert on the rotor turning at the constant rate ``omega`` about the 1-axis,
    with gravity ``g`` along ``-y``.  Euler: their moment about the centre of gravity is
    ``omega x (I2 omega)`` (``omegaDot = 0``); Newton: they carry the weight, ``F1 + F2 = (0, m g, 0)``; no axial
    force."""
    # TODO problem 39: write your solution here
    raise NotImplementedError("Problem 39: bearing_forces is not implemented yet")


def solve():
    """``{"I1", "I2", "F1", "F2"}`` for the sheet's turbine."""
    I1 = inertia_aligned()
    I2 = inertia_misaligned(I1)
    F1, F2 = bearing_forces(I2)
    return {"I1": I1, "I2": I2, "F1": F1, "F2": F2}
