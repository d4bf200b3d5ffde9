"""Probes of problem 19: the parallel-axis theorem and composite bodies."""

from . import module, probe


@probe
def parallel_axis(pkg, I_G, m, r):
    return module(pkg, "inertia").parallel_axis(I_G, m, r)


@probe
def composite(pkg, masses, centres, inertias):
    return module(pkg, "inertia").composite_inertia(masses, centres, list(inertias))
