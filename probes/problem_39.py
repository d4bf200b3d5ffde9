"""Probes of problem 39: the turbine's inertias and the forces on its bearings."""

import numpy as np

from . import module, probe
from ._forms import Arr, Tup


@probe(returns=Arr(3, 3), says="inertia_aligned({0}, {1})", args=("scalar", "scalar"))
def inertia_aligned(pkg, I_axial, I_transverse):
    return np.array(module(pkg, "problem_39").inertia_aligned(I_axial, I_transverse), dtype=float)


@probe(returns=Arr(3, 3), says="inertia_misaligned(I1, {1})", args=("", "angle"))
def inertia_misaligned(pkg, I1, alpha):
    return np.array(module(pkg, "problem_39").inertia_misaligned(np.asarray(I1, dtype=float), alpha), dtype=float)


@probe(
    returns=Tup(Arr(3), Arr(3)),
    says="bearing_forces(I2, {1}, {2}, {3}, {4})",
    args=("inertia", "scalar", "scalar", "scalar", "scalar"),
)
def bearing_forces(pkg, I2, omega, m, g, d):
    """``[F1, F2]`` of ``bearing_forces(I2, omega, m, g, d)``."""
    F1, F2 = module(pkg, "problem_39").bearing_forces(np.asarray(I2, dtype=float), omega, m, g, d)
    return [np.array(F1, dtype=float), np.array(F2, dtype=float)]
