"""Probes of problem 19: the parallel-axis theorem and composite bodies."""

from . import module, probe
from ._forms import Arr


@probe(returns=Arr(3, 3), says="parallel_axis(I_G, {1}, r)", args=("", "scalar", "vector"))
def parallel_axis(pkg, I_G, m, r):
    return module(pkg, "inertia").parallel_axis(I_G, m, r)


@probe(returns=Arr(3, 3), says="composite_inertia(masses, centres, inertias)")
def composite(pkg, masses, centres, inertias):
    return module(pkg, "inertia").composite_inertia(masses, centres, list(inertias))


@probe(reference_only=True)
def blocks(pkg):
    """The blocks of the object of Figure 21 (mass m = 1): ``[masses, centres, inertias]``."""
    masses, centres, inertias = module(pkg, "problem_19").blocks()
    return [masses, centres, list(inertias)]


@probe(reference_only=True)
def answer(pkg):
    """I3 of the object of Figure 21 as a multiple of m/120."""
    return module(pkg, "problem_19").answer()
