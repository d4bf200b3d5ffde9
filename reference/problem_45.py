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

    # BEGIN SOLUTION problem 45
    s, l, d, _, _, _ = symbols()
    x, y, phi = sp.symbols("x y phi", real=True)
    c = sp.Matrix([y * sp.cos(phi) - x * sp.sin(phi) - d, y * sp.cos(phi) - (x - s) * sp.sin(phi) - d])
    return c.jacobian([x, y, phi]).subs({x: l, y: d, phi: 0})
    # END SOLUTION


def impulses():
    """``Lam``: the impulses ``(Lam1, Lam2)`` of both contacts in a plastic impact with ``c_dot- = (0, s phid)``
    (a sympy 2 x 1 matrix in ``s, l, m, theta, phid``)."""
    import sympy as sp

    # BEGIN SOLUTION problem 45
    s, _, _, m, theta, phid = symbols()
    J = impact_jacobian()
    M_lam = (J * sp.diag(m, m, theta).inv() * J.T).inv()
    return sp.factor(-M_lam * sp.Matrix([0, s * phid]))
    # END SOLUTION


def opening_limit():
    """``s_limit``: the left contact opens during the impact (``Lam1 < 0``) iff ``s < s_limit`` (a sympy
    expression in ``l, d, m, theta``)."""
    import sympy as sp

    # BEGIN SOLUTION problem 45
    s, l, _, m, theta, phid = symbols()
    # Lam1 / phid is positive for a small s and changes sign at s_limit; phid < 0, so Lam1 < 0 below it
    ratio = sp.together(impulses()[0] / phid)
    return sp.solve(sp.numer(ratio), s)[0]
    # END SOLUTION
