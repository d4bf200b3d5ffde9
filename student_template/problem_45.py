"""Problem 45: the falling bar of problem 43 hits the second support: does the first contact open?

Problem data P45: at the impact ``q- = (l-, d, 0)`` (the bar lies flat, its centre of gravity at ``l-`` from the
first support); the second support is at the distance ``s`` from the first, at the same height, with the
constraint ``c2 = y cos phi - (x - s) sin phi - d`` (``c1`` is the constraint of problem 43).  Assume both contacts
closed after the impact, the left one closed before it (its part of ``c_dot-`` is 0), the right one closing
(``phid- < 0``), and a fully plastic impact (restitution 0)::

    Lam = -M_lam c_dot-,    M_lam = (J M^-1 J.T)^-1,    M = diag(m, m, theta)

The left contact opens during the impact when its impulse would have to pull, ``Lam1 < 0``.

The answers are symbolic (sympy) in the symbols of ``symbols()``: ``s l d m theta phid`` (``l`` for ``l-``,
``phid`` for ``phid-``).
"""

__all__ = ["SYMBOL_NAMES", "symbols", "impact_jacobian", "impulses", "opening_limit"]

#: the names of the symbols of the answers, in the order of ``symbols()``
SYMBOL_NAMES = ("s", "l", "d", "m", "theta", "phid")


def symbols():
    """The sympy symbols ``(s, l, d, m, theta, phid)`` (``phid`` real, the others positive)."""
    import sympy as sp

    s, l, d, m, theta = sp.symbols("s l d m theta", positive=True)
    return s, l, d, m, theta, sp.Symbol("phid", real=True)


def impact_jacobian():
    """``J``: the 2 x 3 Jacobian of both contacts ``(c1, c2)`` at ``q- = (l, d, 0)`` (a sympy matrix)."""
    import sympy as sp

    # TODO problem 45: write your solution here
    raise NotImplementedError("Problem 45: impact_jacobian is not implemented yet")


def impulses():
    """``Lam``: the impulses ``(Lam1, Lam2)`` of both contacts in a plastic impact with ``c_dot- = (0, s phid)``
    (a sympy 2 x 1 matrix in ``s, l, m, theta, phid``)."""
    import sympy as sp

    # TODO problem 45: write your solution here
    raise NotImplementedError("Problem 45: impulses is not implemented yet")


def opening_limit():
    """``s_limit``: the left contact opens during the impact (``Lam1 < 0``) iff ``s < s_limit`` (a sympy
    expression in ``l, d, m, theta``)."""
    import sympy as sp

    # TODO problem 45: write your solution here
    raise NotImplementedError("Problem 45: opening_limit is not implemented yet")
