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
        # BEGIN SOLUTION problem 11
        self.A_IC = as_matrix(A_IC).copy()
        # END SOLUTION

    def set_offset(self, I_r_IC):
        """Set the offset ``I_r_IC`` (inertial components)."""
        # BEGIN SOLUTION problem 11
        self.I_r_IC = as_vector(I_r_IC).copy()
        # END SOLUTION


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
        # BEGIN SOLUTION problem 11
        v = as_vector(v)
        self.C_v = v.copy() if X is None else self.C.A_IC.T @ (X.A_IC @ v)
        # END SOLUTION

    def set_offset(self, r, X=None):
        """Set the start point offset from its components ``r`` in ``X`` (``None`` means C):
        ``C_r_CO = A_IC.T @ A_IX @ X_r_CO``."""
        # BEGIN SOLUTION problem 11
        r = as_vector(r)
        self.C_r_CO = r.copy() if X is None else self.C.A_IC.T @ (X.A_IC @ r)
        # END SOLUTION

    def get_coords(self, X=None):
        """The vector in the components of the coordinate system ``X`` (``None`` means C):
        ``X_v = A_IX.T @ I_v``."""
        # BEGIN SOLUTION problem 11
        X = self.C if X is None else X
        return X.A_IC.T @ self.I_v
        # END SOLUTION

    @property
    def I_v(self):
        """The vector in inertial components: ``I_v = A_IC @ C_v``."""
        # BEGIN SOLUTION problem 11
        return self.C.A_IC @ self.C_v
        # END SOLUTION

    @property
    def I_r_IO(self):
        """The start point in inertial components: ``I_r_IO = I_r_IC + A_IC @ C_r_CO``."""
        # BEGIN SOLUTION problem 11
        return self.C.I_r_IC + self.C.A_IC @ self.C_r_CO
        # END SOLUTION

