"""Probes of problem 16: inertia of simple bodies, numerically and symbolically, and the inverse maps."""

import numpy as np

from . import module, probe
from ._forms import Arr, Dict, Either, Text
from ._symbolic import lambdify

BODIES = ("cuboid", "ellipsoid", "particles")
SYMBOLS = ("m", "a", "b", "c")


@probe(returns=Arr(3), says="centre_of_gravity(masses, points)", args=("vector", ""))
def centre_of_gravity(pkg, masses, points):
    return module(pkg, "inertia").centre_of_gravity(masses, points)


@probe(returns=Arr(3, 3), says="point_masses_inertia(masses, points)")
def point_masses(pkg, masses, points):
    return module(pkg, "inertia").point_masses_inertia(masses, points)


@probe(returns=Arr(3, 3), says="{0}_inertia({1}, {2}, {3}, {4})", args=("", "scalar", "scalar", "scalar", "scalar"))
def body(pkg, name, m, a, b, c):
    return getattr(module(pkg, "inertia"), f"{name}_inertia")(m, a, b, c)


@probe(returns=Either(Text(), Arr(None, 3, 3)), says="{0}_inertia_symbolic()")
def symbolic(pkg, name, points):
    """The symbolic inertia of body ``name`` evaluated at each ``(m, a, b, c)`` of ``points``; a string says why
    it cannot be evaluated."""
    matrix = getattr(module(pkg, "inertia"), f"{name}_inertia_symbolic")()
    import sympy as sp

    if not isinstance(matrix, sp.MatrixBase) or matrix.shape != (3, 3):
        return f"not a 3 x 3 sympy Matrix: {str(matrix)[:200]}"
    symbols = {s.name: s for s in matrix.free_symbols}
    unknown = sorted(set(symbols) - set(SYMBOLS))
    if unknown:
        return f"uses the symbols {unknown}; only m, a, b, c are allowed"
    f = lambdify([symbols.get(n, sp.Symbol(n)) for n in SYMBOLS], matrix, "numpy")
    values = [np.array(f(*p), dtype=float) for p in points]
    return np.array(values)


@probe(
    returns=Dict({"cuboid": Arr(3), "ellipsoid": Arr(3), "particles": Arr(3)}),
    says="part_b({0}, {1}, {2}, {3})",
    args=("scalar", "scalar", "scalar", "scalar"),
)
def dimensions(pkg, m, I1, I2, I3):
    return module(pkg, "problem_16").part_b(m, I1, I2, I3)
