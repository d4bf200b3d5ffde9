"""Probes of problem 17: principal axes and the four bodies representing an inertia matrix."""

from . import module, probe


@probe
def principal_axes(pkg, B_I_G):
    return list(module(pkg, "inertia").principal_axes(B_I_G))


@probe
def representations(pkg, B_I_G, m):
    return module(pkg, "inertia").inertia_representations(B_I_G, m)


@probe
def constants(pkg):
    """The sheet's four inertia matrices and the mass of problem 17."""
    p17 = module(pkg, "problem_17")
    return {"MATRICES": p17.MATRICES, "MASS": p17.MASS}
