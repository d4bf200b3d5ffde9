"""Problem 7: derivatives of the Cardan transformations, symbolically (sympy).

``derive()`` returns sympy expressions in the plain symbols ``alpha, beta, gamma, alpha_dot, beta_dot,
gamma_dot`` (use ``symbols()``): the time dependence is handled inside, the result contains no functions of t.
"""

import numpy as np

from .rotations import cardan

__all__ = ["symbols", "derive", "animate", "N_STEPS", "START_ANGLES"]

N_STEPS = 100
#: (alpha, beta, gamma) at the start of the animation
START_ANGLES = np.deg2rad([60.0, 45.0, 30.0])


def symbols():
    """The six real symbols ``(alpha, beta, gamma, alpha_dot, beta_dot, gamma_dot)``."""
    import sympy as sp

    return sp.symbols("alpha beta gamma alpha_dot beta_dot gamma_dot", real=True)


def derive():
    """Symbolic ``A_IC1, A_IC2, A_IC3, A_C3I`` and ``C3_omega_IC3`` (a 3 x 1 sympy Matrix), as a dict."""
    # BEGIN SOLUTION problem 7
    import sympy as sp

    alpha, beta, gamma, alpha_dot, beta_dot, gamma_dot = symbols()
    t = sp.Symbol("t", real=True)
    a, b, g = (sp.Function(name, real=True)(t) for name in ("a", "b", "g"))

    def rot(axis, x):
        c, s = sp.cos(x), sp.sin(x)
        return {
            1: sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]]),
            2: sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
            3: sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
        }[axis]

    A_IC1 = rot(3, g)
    A_IC2 = A_IC1 * rot(2, b)
    A_IC3 = A_IC2 * rot(1, a)
    A_C3I = A_IC3.T
    W = A_C3I * A_IC3.diff(t)
    omega = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
    to_symbols = {
        a.diff(t): alpha_dot, b.diff(t): beta_dot, g.diff(t): gamma_dot,
    }
    plain = {a: alpha, b: beta, g: gamma}

    def clean(expr):
        return expr.xreplace(to_symbols).xreplace(plain)

    return {
        "A_IC1": clean(A_IC1),
        "A_IC2": clean(A_IC2),
        "A_IC3": clean(A_IC3),
        "A_C3I": clean(A_C3I),
        "C3_omega_IC3": clean(omega).applyfunc(lambda e: sp.trigsimp(sp.expand(e))),
    }
    # END SOLUTION


def animate(n=N_STEPS):
    """Euler-integrate the Cardan angles from ``START_ANGLES`` with all rates 1 rad/s, ``dt = pi/n``, for ``n``
    steps; return ``{"angles": (alpha, beta, gamma), "A_IC3": ...}`` at the end."""
    # BEGIN SOLUTION problem 7
    angles = START_ANGLES.copy()
    dt = np.pi / n
    for _ in range(n):
        angles = angles + dt * np.ones(3)
    return {"angles": angles, "A_IC3": cardan(*angles)}
    # END SOLUTION
