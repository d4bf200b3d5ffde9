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
    # TODO problem 7: write your solution here
    raise NotImplementedError("Problem 7: derive is not implemented yet")


def animate(n=N_STEPS):
    """Euler-integrate the Cardan angles from ``START_ANGLES`` with all rates 1 rad/s, ``dt = pi/n``, for ``n``
    steps; return ``{"angles": (alpha, beta, gamma), "A_IC3": ...}`` at the end."""
    # TODO problem 7: write your solution here
    raise NotImplementedError("Problem 7: animate is not implemented yet")
