"""Problem 25: the passive dynamic walker, a rolling-contact joint and a hip joint.

Normalised to leg length and leg mass (problem data P25): ``l = 1``, foot radius ``r = 0.5``, centre of gravity
``dx = 0.05`` in front of and ``dy = 0.7`` below the hip; each leg ``m = 1``, ``B_I_B = diag(0.03, 0.01, 0.03)``.
Ground -> stance leg: rolling contact, ``P_r_PDp = (0, r, 0)`` (the foot centre at q = 0), ``A_PDp = E``,
``S_r_SDs = (-dx, dy - l + r, 0)``, ``A_SDs = E``.  Stance -> swing leg: rotational hip joint,
``P_r_PDp = (-dx, dy, 0)``, ``S_r_SDs = (-dx, dy, 0)``, ``A_PDp = A_SDs = E``.

``q = (alpha, gamma)``: stance leg angle from the vertical and angle between the legs, counter-clockwise positive.
The centres of gravity are collected as ``x = (x_st, y_st, gamma_st, x_sw, y_sw, gamma_sw)`` with the leg
orientations as signed angles about the 3-axis.  Part (c) uses ``alpha = -30 deg``, ``gamma = +60 deg``
(erratum: the sheet lost these values).
"""

import numpy as np

from .tree import Body, KinematicTree, RollingContactJoint, RotationalJoint

__all__ = [
    "LEG_LENGTH",
    "FOOT_RADIUS",
    "DX",
    "DY",
    "LEG_MASS",
    "LEG_INERTIA",
    "ALPHA_C",
    "GAMMA_C",
    "build_walker",
    "planar_angle",
    "cog_positions",
    "solve",
    "cog_positions_symbolic",
]

LEG_LENGTH = 1.0
FOOT_RADIUS = 0.5
DX = 0.05
DY = 0.7
LEG_MASS = 1.0
LEG_INERTIA = np.diag([0.03, 0.01, 0.03])
#: part (c): stance leg angle and inter-leg angle [rad]
ALPHA_C = np.deg2rad(-30.0)
GAMMA_C = np.deg2rad(60.0)


def build_walker(body_class=Body):
    """The walker as a ``KinematicTree`` of the bodies ``ground``, ``stance_leg``, ``swing_leg``, with
    ``q = (alpha, gamma)``.  ``body_class``: the class of the bodies (``dynamics.DynamicBody`` for a tree with
    equations of motion)."""
    ground = body_class("ground")
    stance = body_class("stance_leg", LEG_MASS, LEG_INERTIA)
    swing = body_class("swing_leg", LEG_MASS, LEG_INERTIA)
    # BEGIN SOLUTION problem 25
    l, r = LEG_LENGTH, FOOT_RADIUS
    RollingContactJoint(
        ground,
        stance,
        r=r,
        P_r_PDp=(0.0, r, 0.0),
        S_r_SDs=(-DX, DY - l + r, 0.0),
        q_index=[0],
    )
    RotationalJoint(stance, swing, P_r_PDp=(-DX, DY, 0.0), S_r_SDs=(-DX, DY, 0.0), q_index=[1])
    # END SOLUTION
    return KinematicTree(ground)


def planar_angle(A_IB):
    """The signed rotation angle about the 3-axis of a rotation ``R3(angle)`` (in ``(-pi, pi]``)."""
    return float(np.arctan2(A_IB[1, 0], A_IB[0, 0]))


def cog_positions(alpha, gamma, tree=None):
    """``x = (x_st, y_st, gamma_st, x_sw, y_sw, gamma_sw)``: inertial position and orientation of both legs'
    centres of gravity at ``q = (alpha, gamma)``."""
    tree = build_walker() if tree is None else tree
    tree.forward_kinematics([alpha, gamma])
    x = []
    for name in ("stance_leg", "swing_leg"):
        body = tree[name]
        x += [*body.I_r_IB[:2], planar_angle(body.A_IB)]
    return np.array(x)


def solve():
    """The values of part (c): ``cog_positions(-30 deg, +60 deg)``."""
    return cog_positions(ALPHA_C, GAMMA_C)


def cog_positions_symbolic():
    """Part (e): ``(q, x, J)`` with the sympy symbols ``q = (alpha, gamma)``, the analytic
    ``x = (x_st, y_st, gamma_st, x_sw, y_sw, gamma_sw)`` (6 x 1) and its Jacobian ``J = dx/dq`` (6 x 2).

    The same passes as the numeric tree, with sympy matrices; both joints rotate about the common 3-axis, so the
    leg orientations are ``alpha`` and ``alpha + gamma``.
    """
    import sympy as sp

    # BEGIN SOLUTION problem 25
    alpha, gamma = sp.symbols("alpha gamma", real=True)
    l, r, dx, dy = (sp.nsimplify(v) for v in (LEG_LENGTH, FOOT_RADIUS, DX, DY))

    def rot3(angle):
        c, s = sp.cos(angle), sp.sin(angle)
        return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])

    def across(A_IP, I_r_IP, P_r_PDp, A_DpDs, Dp_r_DpDs, S_r_SDs):
        """Inertial pose of the successor (``A_PDp = A_SDs = E``)."""
        A_IS = A_IP @ A_DpDs
        return A_IS, I_r_IP + A_IP @ (P_r_PDp + Dp_r_DpDs) - A_IS @ S_r_SDs

    hip = sp.Matrix([-dx, dy, 0])
    foot = sp.Matrix([-dx, dy - l + r, 0])
    rolling = sp.Matrix([-r * alpha, 0, 0])
    A_st, r_st = across(sp.eye(3), sp.zeros(3, 1), sp.Matrix([0, r, 0]), rot3(alpha), rolling, foot)
    A_sw, r_sw = across(A_st, r_st, hip, rot3(gamma), sp.zeros(3, 1), hip)
    x = sp.Matrix([r_st[0], r_st[1], alpha, r_sw[0], r_sw[1], alpha + gamma]).applyfunc(sp.simplify)
    q = sp.Matrix([alpha, gamma])
    return q, x, x.jacobian(q).applyfunc(sp.simplify)
    # END SOLUTION
