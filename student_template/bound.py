"""Bound coordinate systems and bound vectors (problem 11).

A *bound* coordinate system or vector carries, besides its value, a point where it is drawn. The point does not
change the value: a transformation or a free vector has no origin.

``BoundCoSys``   ``A_IC`` (maps C-coordinates to I-coordinates) and the offset ``I_r_IC`` in *inertial*
                 components.
``BoundVector``  the vector ``C_v`` and its start point offset ``C_r_CO``, both in the components of its
                 coordinate system C; it is drawn from ``I_r_IO = I_r_IC + A_IC @ C_r_CO`` along
                 ``I_v = A_IC @ C_v``.
"""

import numpy as np

from .conventions import as_matrix, as_vector

__all__ = ["BoundCoSys", "BoundVector"]


class BoundCoSys:
    """Coordinate system C given by ``A_IC``, drawn at ``I_r_IC`` (inertial components).

    Defaults: ``A_IC`` the identity, ``I_r_IC`` zero.
    """

    def __init__(self, A_IC=None, I_r_IC=None):
        self.A_IC = np.eye(3) if A_IC is None else as_matrix(A_IC).copy()
        self.I_r_IC = np.zeros(3) if I_r_IC is None else as_vector(I_r_IC).copy()

    def set_transform(self, A_IC):
        """Set the orientation ``A_IC`` (a 3 x 3 rotation matrix)."""
        # TODO problem 11: write your solution here
        raise NotImplementedError("Problem 11: BoundCoSys.set_transform is not implemented yet")

    def set_offset(self, I_r_IC):
        """Set the offset ``I_r_IC`` (inertial components)."""
        # TODO problem 11: write your solution here
        raise NotImplementedError("Problem 11: BoundCoSys.set_offset is not implemented yet")


class BoundVector:
    """Vector ``C_v`` drawn from the offset ``C_r_CO`` of its coordinate system ``C`` (a ``BoundCoSys``).

    Both are stored in C-components, so the vector moves with C when C is changed.
    Defaults: ``C_v`` and ``C_r_CO`` zero.
    """

    def __init__(self, C, C_v=None, C_r_CO=None):
        self.C = C
        self.C_v = np.zeros(3) if C_v is None else as_vector(C_v).copy()
        self.C_r_CO = np.zeros(3) if C_r_CO is None else as_vector(C_r_CO).copy()

    def set_vector(self, v, X=None):
        """Set the vector from its components ``v`` in the coordinate system ``X`` (a ``BoundCoSys``;
        ``None`` means C itself): ``C_v = A_IC.T @ A_IX @ X_v``."""
        # TODO problem 11: write your solution here
        raise NotImplementedError("Problem 11: BoundVector.set_vector is not implemented yet")

    def set_offset(self, r, X=None):
        """Set the start point offset from its components ``r`` in ``X`` (``None`` means C):
        ``C_r_CO = A_IC.T @ A_IX @ X_r_CO``."""
        # TODO problem 11: write your solution here
        raise NotImplementedError("Problem 11: BoundVector.set_offset is not implemented yet")

    def get_coords(self, X=None):
        """The vector in the components of the coordinate system ``X`` (``None`` means C):
        ``X_v = A_IX.T @ I_v``."""
        # TODO problem 11: write your solution here
        raise NotImplementedError("Problem 11: BoundVector.get_coords is not implemented yet")

    @property
    def I_v(self):
        """The vector in inertial components: ``I_v = A_IC @ C_v``."""
        # TODO problem 11: write your solution here
        raise NotImplementedError("Problem 11: BoundVector.I_v is not implemented yet")

    @property
    def I_r_IO(self):
        """The start point in inertial components: ``I_r_IO = I_r_IC + A_IC @ C_r_CO``."""
        # TODO problem 11: write your solution here
        raise NotImplementedError("Problem 11: BoundVector.I_r_IO is not implemented yet")

