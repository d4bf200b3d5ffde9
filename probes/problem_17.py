"""Probes of problem 17: principal axes and the four bodies representing an inertia matrix."""

from . import module, probe
from ._forms import Arr, Dict, Num, Tup


@probe(returns=Tup(Arr(3), Arr(3, 3)), says="principal_axes(B_I_G)")
def principal_axes(pkg, B_I_G):
    return list(module(pkg, "inertia").principal_axes(B_I_G))


@probe(
    returns=Dict(
        {
            "cuboid": Dict({"V": Arr(3, 3), "edges": Arr(3), "mass": Num()}),
            "ellipsoid": Dict({"V": Arr(3, 3), "axes": Arr(3), "mass": Num()}),
            "four_points": Dict({"masses": Arr(4), "points": Arr(4, 3)}),
            "six_points": Dict({"masses": Arr(6), "points": Arr(6, 3)}),
        }
    ),
    says="inertia_representations(B_I_G, {1})",
)
def representations(pkg, B_I_G, m):
    return module(pkg, "inertia").inertia_representations(B_I_G, m)


@probe(reference_only=True)
def constants(pkg):
    """The sheet's four inertia matrices and the mass of problem 17."""
    p17 = module(pkg, "problem_17")
    return {"MATRICES": p17.MATRICES, "MASS": p17.MASS}
