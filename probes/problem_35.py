"""Probes of problem 35: the symbolic joint functions, evaluated here at the points the check sends."""

import numpy as np

from . import module, probe, remembered
from ._forms import Arr, Dict, Items, Seq, Text
from ._symbolic import lambdify

#: the entries of a joint-function dict, vectors as 3 x 1 and S, R as 3 x nq
KEYS = ("A_DpDs", "Dp_r_DpDs", "r_rel_dot", "r_rel_ddot", "omega_rel", "omega_rel_dot", "S", "R")
_FUNCTIONS = {}


def _lambdified(result, symbols):
    """``({key: numeric function of symbols}, {key: what is wrong with it})`` for the entries of a joint-function
    dict ``result``."""
    import sympy as sp

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
        functions[name] = lambdify(symbols, expr, "numpy")
    return functions, problems


def _functions(pkg, kind):
    """``({key: numeric function of (q, qd, qdd[, r])}, {key: what is wrong with it})`` for the joint function
    ``<kind>_joint_function()`` of the package (computed once per package and kind)."""
    def make():
        import sympy as sp

        result = getattr(module(pkg, "problem_35"), f"{kind}_joint_function")()
        symbols = [s for name in ("q", "qd", "qdd") for s in sp.Matrix(result[name])]
        if kind == "rolling_contact":
            symbols.append(result["r"])
        return _lambdified(result, symbols)

    return remembered(_FUNCTIONS, (pkg.__name__, kind), make)


def _at_points(functions, problems, points, with_r):
    """``{"problems", "values"}``: the lambdified entries at every point ``{"q", "qd", "qdd"[, "r"]}``."""
    values = []
    for point in points:
        args = [*point["q"], *point["qd"], *point["qdd"], *([point["r"]] if with_r else [])]
        values.append({name: np.array(f(*args), dtype=float) for name, f in functions.items()})
    return {"problems": problems, "values": values}


def _symbols(names):
    """Sympy column vectors ``(q, qd, qdd)`` of real symbols named ``names``, ``d_names``, ``dd_names``."""
    import sympy as sp

    q = sp.Matrix(sp.symbols(names, real=True))
    return (q, *(sp.Matrix([sp.Symbol(f"{prefix}{name}", real=True) for name in q]) for prefix in ("d_", "dd_")))


def _turned(angle):
    """``R3(angle)`` (sympy)."""
    import sympy as sp

    c, s = sp.cos(angle), sp.sin(angle)
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


#: poses that are not linear in q, for ``joint_function_from_pose``: a polar joint, ``q = (gamma, s)``, turned by
#: ``gamma`` about the Dp 3-axis and slid by ``s`` along the turned 1-axis (a hip and a leg extension in one joint);
#: a crank, ``q = (phi,)``, turned by ``phi`` about the Dp 3-axis with the Ds origin on the crank at 0.5 m
POSES = {"polar": "A_DpDs = R3(gamma), Dp_r_DpDs = R3(gamma) (s, 0, 0)",
         "crank": "A_DpDs = R3(phi), Dp_r_DpDs = R3(phi) (0.5, 0, 0)"}


def _pose(name):
    """``(q, qd, qdd, A_DpDs, Dp_r_DpDs)`` of one of ``POSES`` (sympy)."""
    import sympy as sp

    if name == "polar":
        q, qd, qdd = _symbols("gamma, s")
        return q, qd, qdd, _turned(q[0]), _turned(q[0]) @ sp.Matrix([q[1], 0, 0])
    if name == "crank":
        q, qd, qdd = _symbols("phi,")
        return q, qd, qdd, _turned(q[0]), _turned(q[0]) @ sp.Matrix([sp.Rational(1, 2), 0, 0])
    raise ValueError(f"no pose {name!r}: one of {sorted(POSES)}")


def _pose_functions(pkg, name):
    """``_lambdified`` of ``joint_function_from_pose`` of the package on the pose ``name`` (once per package)."""
    def make():
        q, qd, qdd, A_DpDs, Dp_r_DpDs = _pose(name)
        result = module(pkg, "problem_35").joint_function_from_pose(q, qd, qdd, A_DpDs, Dp_r_DpDs)
        if not isinstance(result, dict):
            raise ValueError(f"joint_function_from_pose must return a dict, got {str(result)[:200]}")
        return _lambdified(result, [*q, *qd, *qdd])

    return remembered(_FUNCTIONS, (pkg.__name__, "pose", name), make)


@probe(
    returns=Dict({"problems": Items(Text()), "values": Seq(Items(Arr(any_shape=True)))}), says="{0}_joint_function()"
)
def joint_function(pkg, kind, points):
    """The entries of ``<kind>_joint_function()`` at every point ``{"q", "qd", "qdd", "r"}``."""
    return _at_points(*_functions(pkg, kind), points, with_r=kind == "rolling_contact")


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


@probe(
    returns=Dict({"problems": Items(Text()), "values": Seq(Items(Arr(any_shape=True)))}),
    says="joint_function_from_pose(...) of the {0} joint",
)
def pose_joint_function(pkg, pose, points):
    """The entries of ``joint_function_from_pose`` on the pose ``pose`` (one of ``POSES``) at every point ``{"q",
    "qd", "qdd"}``."""
    return _at_points(*_pose_functions(pkg, pose), points, with_r=False)
