"""Problem 26: the chairoplane.

Generalised coordinates ``q = (beta, phi)``: ``beta`` turns the carousel about the vertical axis, ``phi`` swings
the chain of length ``l3`` outward from the vertical.  The chain hangs from the end of an arm of length ``l2`` at
height ``l1`` (problem data):
``x = ((l2 + l3 sin phi) sin beta, l1 - l3 cos phi, (l2 + l3 sin phi) cos beta)``.
"""

import numpy as np

__all__ = ["position", "jacobian"]


def position(beta, phi, l1, l2, l3):
    """Position ``x = f(q)`` of the point P (the seat) for ``q = (beta, phi)``."""
    # TODO problem 26: write your solution here
    raise NotImplementedError("Problem 26: position is not implemented yet")


def jacobian(beta, phi, l1, l2, l3):
    """Analytic constraint Jacobian ``J_f = d f / d q`` (3 x 2, columns beta, phi): ``x_dot = J_f q_dot``."""
    # TODO problem 26: write your solution here
    raise NotImplementedError("Problem 26: jacobian is not implemented yet")
