"""Probes of problem 45: the symbolic answers of the falling bar's impact (the Jacobian of both contacts, the
impulses, the limit of s), evaluated at points the grader sends (the grader never sees the expressions)."""

import numpy as np

from . import module, probe, remembered
from ._forms import Arr, Dict, Either, Seq, Text
from ._symbolic import named

#: the symbols the answers may use
NAMES = ("s", "l", "d", "m", "theta", "phid")
SHAPES = {"J": (2, 3), "Lam": (2,), "s_limit": ()}
_ANSWERS = {}


_FUNCTIONS = {"J": "impact_jacobian", "Lam": "impulses", "s_limit": "opening_limit"}


def _answer(pkg, key):
    """The answer ``key`` (``"J"``, ``"Lam"`` or ``"s_limit"``) as a sympy matrix (1 x 1 for ``s_limit``),
    computed once per package and process."""
    import sympy as sp

    p45 = module(pkg, "problem_45")

    def make():
        value = getattr(p45, _FUNCTIONS[key])()
        return sp.Matrix([sp.sympify(value)]) if key == "s_limit" else sp.Matrix(value)

    return remembered(_ANSWERS, (pkg.__name__, id(p45), key), make)


def _problem(key, matrix):
    shape = SHAPES[key]
    size = int(np.prod(shape)) if shape else 1
    if matrix.shape != shape and not (len(shape) < 2 and size in matrix.shape and 1 in matrix.shape):
        return f"{key} has shape {matrix.shape}, expected {shape or 'a single expression'}"
    unknown = sorted({str(s) for s in matrix.free_symbols} - set(NAMES))
    if unknown:
        return f"{key} uses the symbols {unknown}, which are not among {list(NAMES)}"
    return None


def _each(key, points):
    return len(points)


@probe(
    returns=Either(Dict({"problem": Text(), "transposed": Seq(Arr(any_shape=True), length=_each)},
                        optional=("transposed",)),
                   Seq(Arr(any_shape=True), length=_each)),
    says="the answer {0}",
)
def evaluate(pkg, key, points):
    """``[value at every point {symbol name: value}]`` of the answer ``key`` (``"J"``: ``impact_jacobian()``,
    ``"Lam"``: ``impulses()``, ``"s_limit"``: ``opening_limit()``); or ``{"problem": text}`` if it has the wrong
    shape or uses symbols outside ``NAMES``, with ``"transposed"``, the values of its transpose, where its shape is
    the transposed one of a matrix that is not square (the check tells whether it is the transpose asked for)."""
    matrix = _answer(pkg, key)
    problem = _problem(key, matrix)
    shape = SHAPES[key]
    if problem and len(shape) == 2 and shape[0] != shape[1] and matrix.shape == shape[::-1] \
            and not _problem(key, matrix.T):  # the transpose kept beside the answer: its id keys its function
        transposed = remembered(_ANSWERS, ("transposed", pkg.__name__, id(matrix)), lambda: matrix.T)
        return {"problem": problem, "transposed": _values(pkg, key, transposed, points)}
    if problem:
        return {"problem": problem}
    return _values(pkg, key, matrix, points)


def _values(pkg, key, matrix, points):
    """The values of ``matrix`` (of the answer ``key``'s shape) at the points."""
    function = remembered(_ANSWERS, ("function", pkg.__name__, id(matrix)), lambda: named(NAMES, matrix, "numpy"))
    return [np.array(function(*(float(point[name]) for name in NAMES)), dtype=float).reshape(SHAPES[key])
            for point in points]
