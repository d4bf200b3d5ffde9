"""Probes of problem 17: principal axes and the four bodies representing an inertia matrix."""

from . import module, probe


@probe
def principal_axes(pkg, B_I_G):
    return list(module(pkg, "inertia").principal_axes(B_I_G))


@probe
def representations(pkg, B_I_G, m):
    return module(pkg, "inertia").inertia_representations(B_I_G, m)
