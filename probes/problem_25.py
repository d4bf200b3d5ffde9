"""Probes of problem 25: the passive dynamic walker (numeric and symbolic) and random trees with rolling
contacts."""

import numpy as np

from . import _trees, module, probe, remembered
from ._forms import Arr, Dict, Either, Seq, Text
from ._symbolic import lambdify
from ._trees import OUTLINE, POSES

_SYMBOLIC = {}
#: the lengths ``build_walker`` and ``cog_positions_symbolic`` read from the module: on the sheet the leg is twice
#: the foot's radius, so the engine draws them anew with the angles (each its own)
REBIND = {"module": "problem_25", "names": ("LEG_LENGTH", "FOOT_RADIUS", "DX", "DY")}


@probe(
    returns=Dict({**POSES.fields, "outline": OUTLINE, "x": Arr(any_shape=True)}),
    says="build_walker()",
    args=("angle", "angle"),
    rebind=REBIND,
)
def walker(pkg, alpha, gamma):
    """The walker of ``build_walker`` at ``q = (alpha, gamma)``: body states, outline and ``cog_positions``."""
    p25 = module(pkg, "problem_25")
    tree = p25.build_walker()
    x = p25.cog_positions(alpha, gamma, tree)
    tree.forward_kinematics(np.array([alpha, gamma], dtype=float))
    return {**_trees.state(tree, motion=False), "outline": _trees.outline(tree), "x": x}


@probe(returns=POSES, says="forward_kinematics of the tree")
def tree_poses(pkg, description, q):
    return _trees.tree_state(pkg, description, q)


def _symbolic(pkg):
    """``cog_positions_symbolic()`` as numeric functions of ``(alpha, gamma)`` (computed once per package), or the
    symbols other than ``q`` that the expressions contain."""
    def make():
        import sympy as sp

        q, x, J = module(pkg, "problem_25").cog_positions_symbolic()
        symbols = list(sp.Matrix(q))
        x, J = sp.Matrix(x), sp.Matrix(J)
        free = sorted(str(s) for s in (x.free_symbols | J.free_symbols) - set(symbols))
        functions = None if free else (lambdify(symbols, x, "numpy"), lambdify(symbols, J, "numpy"))
        return functions, free, [str(s) for s in symbols]

    return remembered(_SYMBOLIC, pkg.__name__, make)


@probe(
    returns=Either(
        Dict({"free_symbols": Seq(Text()), "symbols": Seq(Text())}),
        Dict(
            {
                "x": Seq(Arr(any_shape=True)),
                "J": Seq(Arr(any_shape=True)),
                "plus": Seq(Seq(Arr(any_shape=True))),
                "minus": Seq(Seq(Arr(any_shape=True))),
                "symbols": Seq(Text()),
            }
        ),
    ),
    says="cog_positions_symbolic()",
    rebind=REBIND,
)
def symbolic(pkg, points, h):
    """``x`` and ``J`` of ``cog_positions_symbolic`` at every point ``(alpha, gamma)``, and ``x`` at the points
    shifted by ``+-h`` in each coordinate."""
    functions, free, symbols = _symbolic(pkg)
    if functions is None:
        return {"free_symbols": free, "symbols": symbols}
    x_of, J_of = functions

    def x_at(point):
        return np.array(x_of(*point), dtype=float)

    result = {"x": [], "J": [], "plus": [], "minus": [], "symbols": symbols}
    for point in np.asarray(points, dtype=float):
        result["x"].append(x_at(point))
        result["J"].append(np.array(J_of(*point), dtype=float))
        result["plus"].append([x_at(point + h * e) for e in np.eye(2)])
        result["minus"].append([x_at(point - h * e) for e in np.eye(2)])
    return result


@probe(reference_only=True)
def walker_case(pkg):
    """The walker of ``build_walker`` as a plain-data description, and part (c)'s configuration."""
    p25 = module(pkg, "problem_25")
    return {"description": _trees.describe(module(pkg, "tree"), p25.build_walker()), "alpha_c": p25.ALPHA_C,
            "gamma_c": p25.GAMMA_C}


@probe(reference_only=True, args=("angle", "angle"))
def leg_jacobians(pkg, alpha, gamma):
    """Rows ``I_J_S[0:2]`` and ``I_J_R[2]`` of each leg's Jacobians at ``q = (alpha, gamma)`` (6 x 2), the
    Jacobian of ``x = (x_st, y_st, gamma_st, x_sw, y_sw, gamma_sw)``."""
    tree = module(pkg, "problem_25").build_walker()
    tree.forward_kinematics(np.array([alpha, gamma], dtype=float), np.zeros(2))
    rows = []
    for name in ("stance_leg", "swing_leg"):
        body = tree[name]
        A_IB = np.asarray(body.A_IB, dtype=float)
        rows += [(A_IB @ body.B_J_S)[:2], (A_IB @ body.B_J_R)[2:]]
    return np.vstack(rows)
