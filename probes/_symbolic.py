"""Symbolic answers as numeric functions: ``lambdify``, as sympy's, and a quick reading of the expression's tree.

A probe of a symbolic answer turns each expression into a function of its symbols (``lambdify(args, expr)``) and
calls it at the points the grader sends.  Sympy's ``lambdify`` prints the expression as code and compiles it, which
costs tens of milliseconds for a few matrices: nothing for one answer, much for the diagnosis engine, which
evaluates the reference's code under many slips (``grader.diagnosis.mutants``), each giving new expressions that
are called at a handful of points.  Within ``quick()`` (the engine's, never the student's or the oracle's)
``lambdify`` returns a function that reads the expression's tree instead: its distinct subexpressions once, in an
order where each comes after its operands, evaluated by numpy's functions on the values of the call.  The values
are those of sympy's function up to the rounding of the order of sums and products.  An expression with anything
else than numbers, the arguments' symbols, sums, products, powers and the common functions of one or two arguments
(a piecewise expression, an unknown symbol, a matrix inside a product), or a result that is neither an expression
nor a matrix, is given to sympy's ``lambdify``.

An answer whose symbols may carry assumptions (``real=True``, ``positive=True``) is read by the names of its symbols
(``named``): sympy's ``lambdify`` of the expression with every symbol replaced by the plain symbol of its name.  The
replacing (``subs``) walks and rebuilds every subexpression, and of an unsimplified answer costs more than the
reading itself; within ``quick()`` the reading matches the symbols by name instead, which gives the same values."""

import contextlib

from . import Flag

__all__ = ["lambdify", "named", "quick"]

_QUICK = Flag()

#: the functions read by name (sympy's class name: numpy's function)
_FUNCTIONS = {
    "sin": "sin", "cos": "cos", "tan": "tan", "asin": "arcsin", "acos": "arccos", "atan": "arctan",
    "atan2": "arctan2", "sinh": "sinh", "cosh": "cosh", "tanh": "tanh", "exp": "exp", "log": "log",
    "Abs": "abs", "sign": "sign",
}


@contextlib.contextmanager
def quick():
    """Within: ``lambdify`` of this thread reads the expression's tree (see the module's docstring)."""
    with _QUICK.within():
        yield


def lambdify(args, expr, modules="numpy"):
    """``sympy.lambdify(args, expr, modules)``; within ``quick()``, a function of the same values that reads the
    expression's tree, where it holds only what that reading knows."""
    import sympy as sp

    if _QUICK.on:
        try:
            return _read(list(args), expr)
        except _Unknown:
            pass
    return sp.lambdify(args, expr, modules)


def named(names, expr, modules="numpy"):
    """A function of the values of the symbols named ``names`` (in that order) that evaluates ``expr``, each of
    whose symbols is read as the plain symbol of its name: ``lambdify`` of ``expr.subs({s: Symbol(str(s))})`` in
    the plain symbols of ``names``; within ``quick()``, a reading of ``expr`` itself that matches its symbols by
    name (see the module's docstring)."""
    import sympy as sp

    names = [str(n) for n in names]
    if _QUICK.on:
        try:
            return _read(names, expr)
        except _Unknown:
            pass
    plain = expr.subs({s: sp.Symbol(str(s)) for s in expr.free_symbols})
    return sp.lambdify([sp.Symbol(n) for n in names], plain, modules)


class _Unknown(Exception):
    """Something the quick reading does not evaluate."""


def _read(args, expr):
    """A function of ``args``' values that evaluates ``expr`` (an expression or a matrix) as sympy's ``lambdify``
    does, by one pass over a program of its distinct subexpressions; ``args`` given as names (strings): every
    symbol of ``expr`` is the argument of its name, whatever its assumptions."""
    import numpy as np
    import sympy as sp

    by_name = all(isinstance(a, str) for a in args)
    if not by_name and not all(isinstance(a, sp.Symbol) for a in args):
        raise _Unknown
    if isinstance(expr, sp.MatrixBase):
        shape, entries = expr.shape, list(expr)
    elif isinstance(expr, sp.Expr):
        shape, entries = None, [expr]
    else:
        raise _Unknown
    positions = {a: i for i, a in enumerate(args)}
    index, program = {}, []

    def visit(node):
        if node in index:
            return index[node]
        key = node.name if by_name and node.is_Symbol else node
        if key in positions:
            step = ("arg", positions[key], ())
        elif node.is_Number or node.is_NumberSymbol:
            try:
                step = ("const", float(node), ())
            except (TypeError, ValueError):
                raise _Unknown from None
        elif node.is_Add:
            step = ("add", None, tuple(visit(a) for a in node.args))
        elif node.is_Mul:
            step = ("mul", None, tuple(visit(a) for a in node.args))
        elif node.is_Pow:
            step = ("pow", None, (visit(node.base), visit(node.exp)))
        elif isinstance(node, sp.Function) and type(node).__name__ in _FUNCTIONS:
            step = ("call", getattr(np, _FUNCTIONS[type(node).__name__]), tuple(visit(a) for a in node.args))
        else:
            raise _Unknown
        index[node] = len(program)
        program.append(step)
        return index[node]

    outputs = [visit(entry) for entry in entries]

    def function(*values):
        if len(values) != len(args):
            raise TypeError(f"expected {len(args)} arguments, got {len(values)}")
        results = []
        for kind, operand, operands in program:
            if kind == "arg":
                results.append(values[operand])
            elif kind == "const":
                results.append(operand)
            elif kind == "add":
                total = results[operands[0]]
                for k in operands[1:]:
                    total = total + results[k]
                results.append(total)
            elif kind == "mul":
                product = results[operands[0]]
                for k in operands[1:]:
                    product = product * results[k]
                results.append(product)
            elif kind == "pow":
                results.append(np.power(np.float64(results[operands[0]]), results[operands[1]]))
            else:
                results.append(operand(*(results[k] for k in operands)))
        if shape is None:
            return results[outputs[0]]
        return np.array([results[k] for k in outputs]).reshape(shape)

    return function
