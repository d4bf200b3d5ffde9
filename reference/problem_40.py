"""Problem 40: equations of motion of a system of particles, the double pendulum of two point masses.

Problem data P40: ``x1 = (l1 sin q1, -l1 cos q1)``, ``x2 = x1 + (l2 sin(q1 + q2), -l2 cos(q1 + q2))``, masses
``m1``, ``m2``, gravity ``g`` along ``-y``.  The projected Newton-Euler equations of point masses,
``M = sum(J.T m J)``, ``f = -sum(J.T m sigma)``, ``g = sum(J.T m (0, -g))`` with ``J = dx/dq`` and the bias
acceleration ``sigma = d(J qd)/dq qd``, give the sheet's ``M qdd - f - g = 0``.

The answer is symbolic (sympy), in the symbols of ``symbols()``: ``q1 q2 dq1 dq2 l1 l2 m1 m2 g``.
"""

__all__ = ["SYMBOL_NAMES", "symbols", "particle_positions", "equations_of_motion_symbolic"]

#: the names of the symbols of the answer, in the order of ``symbols()``
SYMBOL_NAMES = ("q1", "q2", "dq1", "dq2", "l1", "l2", "m1", "m2", "g")


def symbols():
    """The sympy symbols ``(q1, q2, dq1, dq2, l1, l2, m1, m2, g)`` (real; lengths, masses and g positive)."""
    import sympy as sp

    q1, q2, dq1, dq2 = sp.symbols("q1 q2 dq1 dq2", real=True)
    l1, l2, m1, m2, g = sp.symbols("l1 l2 m1 m2 g", positive=True)
    return q1, q2, dq1, dq2, l1, l2, m1, m2, g


def particle_positions():
    """``(x1, x2)``: the positions of the two particles (sympy 2 x 1 matrices)."""
    import sympy as sp

    q1, q2, _, _, l1, l2, _, _, _ = symbols()
    x1 = sp.Matrix([l1 * sp.sin(q1), -l1 * sp.cos(q1)])
    x2 = x1 + sp.Matrix([l2 * sp.sin(q1 + q2), -l2 * sp.cos(q1 + q2)])
    return x1, x2


def equations_of_motion_symbolic():
    """``(M, f, g)`` of the double pendulum of point masses: the 2 x 2 mass matrix and the 2 x 1 vectors of
    ``M qdd = f + g`` (sympy matrices in the symbols of ``symbols()``)."""
    import sympy as sp

    # BEGIN SOLUTION problem 40
    q1, q2, dq1, dq2, _, _, m1, m2, g = symbols()
    q, qd = sp.Matrix([q1, q2]), sp.Matrix([dq1, dq2])
    M, f, G = sp.zeros(2, 2), sp.zeros(2, 1), sp.zeros(2, 1)
    for x, m in zip(particle_positions(), (m1, m2)):
        J = x.jacobian(q)
        sigma = (J @ qd).jacobian(q) @ qd
        M += m * J.T @ J
        f -= m * J.T @ sigma
        G += m * J.T @ sp.Matrix([0, -g])

    def tidy(expression):
        return sp.factor_terms(sp.trigsimp(sp.expand(expression), method="fu"))

    return M.applyfunc(tidy), f.applyfunc(tidy), G.applyfunc(tidy)
    # END SOLUTION
