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
        # TODO problem 9: write your solution here
        raise NotImplementedError("Problem 9: CoSys.set_transform is not implemented yet")

    def get_transform(self, B=None):
        """Return ``A_BC``, the transformation from this frame C to ``B`` (to I when ``B`` is None)."""
        # TODO problem 9: write your solution here
        raise NotImplementedError("Problem 9: CoSys.get_transform is not implemented yet")
