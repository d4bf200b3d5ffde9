"""Probes of problem 11: bound coordinate systems and bound vectors driven through their setters."""

from . import module, probe
from ._forms import Arr, Dict
from ._scenario import run

COSYS, VECTOR = "bound.BoundCoSys", "bound.BoundVector"


def _objects(A_IC, I_r_IC, C_v, C_r_CO, A_IX=None):
    objects = [("C", COSYS, {"A_IC": A_IC, "I_r_IC": I_r_IC}),
               ("v", VECTOR, {"C": "@C", "C_v": C_v, "C_r_CO": C_r_CO})]
    if A_IX is not None:
        objects.append(("X", COSYS, {"A_IC": A_IX}))
    return objects


@probe(
    returns=Dict({"I_v": Arr(3), "I_r_IO": Arr(3), "I_coords": Arr(3), "C_coords": Arr(3)}),
    says="the bound vector",
    args=("rotation", "vector", "vector", "vector"),
    rotation=0,
)
def vector(pkg, A_IC, I_r_IC, C_v, C_r_CO):
    """The vector in inertial components, its start point, and its components in I and in C."""
    objects = [*_objects(A_IC, I_r_IC, C_v, C_r_CO), ("I", COSYS, {})]
    read = [("I_v", "v.I_v"), ("I_r_IO", "v.I_r_IO"), ("I_coords", "v.get_coords", ["@I"]),
            ("C_coords", "v.get_coords", [])]
    return run(pkg, objects, read=read)["final"]


@probe(
    returns=Dict({"A_IC": Arr(3, 3), "I_r_IC": Arr(3), "I_v": Arr(3), "I_r_IO": Arr(3)}),
    says="the bound vector after moving its system",
    args=("rotation", "vector", "vector", "vector", "rotation", "vector"),
    rotation=0,
)
def moved(pkg, A_IC, I_r_IC, C_v, C_r_CO, A_new, I_r_new):
    """The vector after its coordinate system was turned to ``A_new`` and moved to ``I_r_new``."""
    steps = [("C.set_transform", [A_new]), ("C.set_offset", [I_r_new])]
    read = [("A_IC", "C.A_IC"), ("I_r_IC", "C.I_r_IC"), ("I_v", "v.I_v"), ("I_r_IO", "v.I_r_IO")]
    return run(pkg, _objects(A_IC, I_r_IC, C_v, C_r_CO), steps, read=read)["final"]


@probe(
    returns=Dict({"C_v": Arr(3), "C_r_CO": Arr(3), "I_v": Arr(3), "I_r_IO": Arr(3), "C_v_own": Arr(3),
                  "C_r_CO_own": Arr(3)}),
    says="the bound vector after set_vector and set_offset",
    args=("rotation", "vector", "rotation", "vector", "vector"),
    rotation=0,
)
def set_in(pkg, A_IC, I_r_IC, A_IX, X_v, X_r):
    """The vector after ``set_vector(X_v, X)`` and ``set_offset(X_r, X)`` with another coordinate system X, and
    a second vector ``w`` on C after ``set_vector(X_v)`` and ``set_offset(X_r)`` without one (components in C
    itself: ``C_v_own``, ``C_r_CO_own``)."""
    objects = [*_objects(A_IC, I_r_IC, [0, 0, 0], [0, 0, 0], A_IX), ("w", VECTOR, {"C": "@C"})]
    steps = [("v.set_vector", [X_v, "@X"]), ("v.set_offset", [X_r, "@X"]), ("w.set_vector", [X_v]),
             ("w.set_offset", [X_r])]
    read = [("C_v", "v.C_v"), ("C_r_CO", "v.C_r_CO"), ("I_v", "v.I_v"), ("I_r_IO", "v.I_r_IO"),
            ("C_v_own", "w.C_v"), ("C_r_CO_own", "w.C_r_CO")]
    return run(pkg, objects, steps, read=read)["final"]


@probe(
    returns=Dict({"X_v": Arr(3), "C_v": Arr(3)}),
    says="get_coords",
    args=("rotation", "vector", "rotation"),
    rotation=0,
)
def coords(pkg, A_IC, C_v, A_IX):
    """``get_coords(X)`` and ``get_coords()`` of a vector on C."""
    read = [("X_v", "v.get_coords", ["@X"]), ("C_v", "v.get_coords", [])]
    return run(pkg, _objects(A_IC, [0, 0, 0], C_v, [0, 0, 0], A_IX), read=read)["final"]


@probe(reference_only=True)
def test_objects(pkg):
    """The course's test objects (``make_test_objects()``) as plain data: C's ``A_IC``, ``I_r_IC`` and the
    vector's ``C_v``, ``C_r_CO``."""
    C, v = module(pkg, "problem_11").make_test_objects()
    return {"A_IC": C.A_IC, "I_r_IC": C.I_r_IC, "C_v": v.C_v, "C_r_CO": v.C_r_CO}
