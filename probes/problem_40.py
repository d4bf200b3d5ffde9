"""Probes of problem 40: the symbolic equations of motion of the particle double pendulum, evaluated at points the
grader sends (the grader never sees the expressions themselves)."""

import numpy as np

from . import module, probe, remembered
from ._forms import Arr, Dict, Either, Seq, Text
from ._symbolic import named

#: the symbols the answer may use
NAMES = ("q1", "q2", "dq1", "dq2", "l1", "l2", "m1", "m2", "g")
SHAPES = {"M": (2, 2), "f": (2,), "g": (2,)}
_ANSWERS = {}


def _each(points):
    """One value per point."""
    return len(points)


def _answer(pkg):
    """``{"M", "f", "g"}`` as sympy matrices (computed once per package and process: simplifying takes a while)."""
    import sympy as sp

    p40 = module(pkg, "problem_40")

    def make():
        M, f, g = p40.equations_of_motion_symbolic()
        return {"M": sp.Matrix(M), "f": sp.Matrix(f), "g": sp.Matrix(g)}

    return remembered(_ANSWERS, (pkg.__name__, id(p40)), make)


def _functions(pkg):
    """``{"M", "f", "g"}`` as numeric functions of ``NAMES``, or ``{"problem": text}`` (lambdified once per answer:
    a call of ``evaluate`` is then only the arithmetic)."""
    answer = _answer(pkg)
    for key, matrix in answer.items():
        if matrix.shape not in (SHAPES[key], (SHAPES[key][0], 1), (1, SHAPES[key][0])) or (
                key == "M" and matrix.shape != (2, 2)):
            return {"problem": f"{key} has shape {matrix.shape}, expected {SHAPES[key]}"}
        unknown = sorted({str(s) for s in matrix.free_symbols} - set(NAMES))
        if unknown:
            return {"problem": f"{key} uses the symbols {unknown}, which are not among {list(NAMES)}"}
    return remembered(_ANSWERS, ("functions", id(answer)),
                      lambda: {key: named(NAMES, matrix, "numpy") for key, matrix in answer.items()})


@probe(
    returns=Either(
        Dict({"problem": Text()}),
        Dict({"M": Seq(Arr(2, 2), length=_each), "f": Seq(Arr(2), length=_each), "g": Seq(Arr(2), length=_each)}),
    ),
    says="equations_of_motion_symbolic()",
)
def evaluate(pkg, points):
    """``{"M": [...], "f": [...], "g": [...]}``: the answer at every point ``{symbol name: value}``; or
    ``{"problem": text}`` if an expression has the wrong shape or uses symbols outside ``NAMES``."""
    functions = _functions(pkg)
    if "problem" in functions:
        return functions
    out = {key: [] for key in functions}
    for point in points:
        values = [float(point[name]) for name in NAMES]
        for key, function in functions.items():
            out[key].append(np.array(function(*values), dtype=float).reshape(SHAPES[key]))
    return out
