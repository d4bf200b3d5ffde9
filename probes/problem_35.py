"""Probes of problem 35: the symbolic joint functions, evaluated here at the points the check sends."""

import numpy as np

from . import module, probe, remembered
from ._forms import Arr, Dict, Items, Seq, Text

#: the entries of a joint-function dict, vectors as 3 x 1 and S, R as 3 x nq
KEYS = ("A_DpDs", "Dp_r_DpDs", "r_rel_dot", "r_rel_ddot", "omega_rel", "omega_rel_dot", "S", "R")
_FUNCTIONS = {}


def _functions(pkg, kind):
    """``({key: numeric function of (q, qd, qdd[, r])}, {key: what is wrong with it})`` for the joint function
    ``<kind>_joint_function()`` of the package (computed once per package and kind)."""
    def make():
        import sympy as sp

        result = getattr(module(pkg, "problem_35"), f"{kind}_joint_function")()
        symbols = [s for name in ("q", "qd", "qdd") for s in sp.Matrix(result[name])]
        if kind == "rolling_contact":
            symbols.append(result["r"])
        functions, problems = {}, {}
        for name in KEYS:
            if name not in result:
                problems[name] = "missing"
                continue
            expr = sp.Matrix(result[name])
            free = expr.free_symbols - set(symbols)
            if free:
                problems[name] = "contains the symbols " + ", ".join(sorted(map(str, free)))
                continue
            functions[name] = sp.lambdify(symbols, expr, "numpy")
        return functions, problems

    return remembered(_FUNCTIONS, (pkg.__name__, kind), make)


@probe(
    returns=Dict({"problems": Items(Text()), "values": Seq(Items(Arr(any_shape=True)))}), says="{0}_joint_function()"
)
def joint_function(pkg, kind, points):
    """The entries of ``<kind>_joint_function()`` at every point ``{"q", "qd", "qdd", "r"}``."""
    functions, problems = _functions(pkg, kind)
    values = []
    for point in points:
        args = [*point["q"], *point["qd"], *point["qdd"], *([point["r"]] if kind == "rolling_contact" else [])]
        values.append({name: np.array(f(*args), dtype=float) for name, f in functions.items()})
    return {"problems": problems, "values": values}


@probe(reference_only=True)
def numeric_joint_function(pkg, kind, points):
    """The package's numeric joint function of ``kind`` (the joint class of its ``tree`` module) at every point, as
    dicts with the entries of ``KEYS`` (vectors as 3-vectors)."""
    from ._trees import CLASSES

    tree = module(pkg, "tree")
    values = []
    for point in points:
        nq = len(point["q"])
        extra = {"r": point["r"]} if kind == "rolling_contact" else {}
        joint = getattr(tree, CLASSES[kind])(tree.Body("P"), tree.Body("S"), q_index=list(range(nq)), **extra)
        A_DpDs, r_rel = joint.joint_pose(np.asarray(point["q"], dtype=float))
        rel = joint.joint_motion(*(np.asarray(point[key], dtype=float) for key in ("q", "qd", "qdd")))
        values.append({"A_DpDs": A_DpDs, "Dp_r_DpDs": r_rel, "r_rel_dot": rel.r_rel_dot, "r_rel_ddot": rel.r_rel_ddot,
                       "omega_rel": rel.omega_rel, "omega_rel_dot": rel.omega_rel_dot, "S": rel.S, "R": rel.R})
    return values
