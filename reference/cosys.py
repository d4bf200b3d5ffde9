"""Coordinate systems with relative transformations (problem 9)."""

import numpy as np

__all__ = ["CoSys"]


class CoSys:
    """A coordinate system C, stored by its transformation ``A_IC`` to the inertial frame I.

    ``CoSys(A_BC, B)`` places C relative to an existing coordinate system B (``A_IC = B.A_IC @ A_BC``);
    ``CoSys(A_IC)`` places it relative to I.
    """

    def __init__(self, A_BC=None, B=None):
        self.A_IC = np.eye(3)
        self.set_transform(np.eye(3) if A_BC is None else A_BC, B)

    def set_transform(self, A_BC, B=None):
        """Set the orientation of this frame C from ``A_BC``, relative to ``B`` (or to I when ``B`` is None)."""
        # BEGIN SOLUTION problem 9
        A_BC = np.asarray(A_BC, dtype=float)
        self.A_IC = A_BC.copy() if B is None else B.A_IC @ A_BC
        # END SOLUTION

    def get_transform(self, B=None):
        """Return ``A_BC``, the transformation from this frame C to ``B`` (to I when ``B`` is None)."""
        # BEGIN SOLUTION problem 9
        return self.A_IC.copy() if B is None else B.A_IC.T @ self.A_IC
        # END SOLUTION
