"""Problem 34: a planar biped on a virtual 3-DOF joint, with translational leg extensions.

Model (problem data P34, normalised).  Bodies: ``main_body`` m = 0.7, ``B_I_B = diag(0.004, 0.04, 0.04)``;
thighs m = 0.1, ``diag(0.0002, 0.002, 0.002)``; shanks m = 0.05, ``diag(0.0001, 0.001, 0.001)``.  Joints:
virtual 3-DOF ground -> main body (``q = (x, y, phi)``); hips (rotational) main body -> thigh at
``P_r_PDp = (0, 0, +-0.2)`` (+0.2 is the left side, z points to the left of a walker moving along +x),
``A_PDp = [[0,1,0],[-1,0,0],[0,0,1]]`` (the thigh's 1-axis points down at q = 0), ``S_r_SDs = (-0.25, 0, 0)``;
leg extensions (translational along Dp x) thigh -> shank at ``P_r_PDp = (0.25, 0, 0)``,
``S_r_SDs = (-0.25, 0, 0)``.  ``q = (x, y, phi, hip_left, hip_right, ext_left, ext_right)``.  Thigh and shank are
0.5 long, so a leg measures ``1 + extension`` from the hip to the end of the shank.

Gait.  The course's recorded walking data is replaced by a smooth periodic gait of period ``T``
(``w = 2 pi / T``), every coordinate a trigonometric polynomial plus a linear drift, so velocities and
accelerations are exact derivatives::

    x         = v t,                    v = 4 sin(A) / T   (two steps of length 2 sin(A) per period)
    y         = Y0 + H cos(2 w t)       (the hip bobs twice per period)
    phi       = P sin(2 w t)            (pitch of the main body)
    hip_left  = +A sin(w t),            hip_right = -A sin(w t)
    ext_left  = -C (1 + cos(w t))^2 / 4 = -C (3/8 + cos(w t)/2 + cos(2 w t)/8)
    ext_right = -C (1 - cos(w t))^2 / 4 = -C (3/8 - cos(w t)/2 + cos(2 w t)/8)

A leg shortens by up to ``C`` while it swings forward (hip angle increasing) and is fully extended in mid stance;
the hip height follows the stance leg roughly (``Y0 + H = 1`` in mid stance).  The gait is kinematic: ground
contact is not enforced, the stance foot slides a little.
Frames of the animation are ``FRAME_DT`` apart, frame 1 at t = 0.
"""

import numpy as np

from .tree import Body, KinematicTree, RotationalJoint, TranslationalJoint, Virtual3DOFJoint, inertial_state

__all__ = [
    "MAIN_MASS",
    "MAIN_INERTIA",
    "THIGH_MASS",
    "THIGH_INERTIA",
    "SHANK_MASS",
    "SHANK_INERTIA",
    "PERIOD",
    "HIP_AMPLITUDE",
    "RETRACTION",
    "HIP_HEIGHT",
    "BOB",
    "PITCH",
    "FRAME_DT",
    "BODY_NAMES",
    "build_biped",
    "gait_coefficients",
    "gait",
    "frame_time",
    "kinematics_at",
    "solve",
]

MAIN_MASS, MAIN_INERTIA = 0.7, np.diag([0.004, 0.04, 0.04])
THIGH_MASS, THIGH_INERTIA = 0.1, np.diag([0.0002, 0.002, 0.002])
SHANK_MASS, SHANK_INERTIA = 0.05, np.diag([0.0001, 0.001, 0.001])
#: gait parameters: period [s], hip amplitude [rad], leg retraction, mean hip height, bobbing, pitch [rad]
PERIOD = 1.2
HIP_AMPLITUDE = 0.35
RETRACTION = 0.12
HIP_HEIGHT = 0.955
BOB = 0.045
PITCH = 0.03
FRAME_DT = 0.02
BODY_NAMES = ("ground", "main_body", "thigh_left", "shank_left", "thigh_right", "shank_right")

_A_HIP = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])


def build_biped():
    """The biped as a ``KinematicTree`` with the bodies ``BODY_NAMES`` and the coordinate order
    ``(x, y, phi, hip_left, hip_right, ext_left, ext_right)``."""
    ground = Body("ground")
    main = Body("main_body", MAIN_MASS, MAIN_INERTIA)
    Virtual3DOFJoint(ground, main, q_index=[0, 1, 2])
    for side, z, hip, extension in (("left", 0.2, 3, 5), ("right", -0.2, 4, 6)):
        thigh = Body(f"thigh_{side}", THIGH_MASS, THIGH_INERTIA)
        shank = Body(f"shank_{side}", SHANK_MASS, SHANK_INERTIA)
        RotationalJoint(main, thigh, P_r_PDp=(0.0, 0.0, z), A_PDp=_A_HIP, S_r_SDs=(-0.25, 0.0, 0.0), q_index=[hip])
        TranslationalJoint(thigh, shank, P_r_PDp=(0.25, 0.0, 0.0), S_r_SDs=(-0.25, 0.0, 0.0), q_index=[extension])
    return KinematicTree(ground)


def gait_coefficients():
    """``(drift, cos_coeffs, sin_coeffs)`` of the gait: ``q_i(t) = drift[i] t + sum_k cos_coeffs[i, k] cos(k w t)
    + sin_coeffs[i, k] sin(k w t)`` for the harmonics k = 0, 1, 2 (``w = 2 pi / PERIOD``)."""
    A, C = HIP_AMPLITUDE, RETRACTION
    drift = np.array([4.0 * np.sin(A) / PERIOD, 0, 0, 0, 0, 0, 0])
    cos_coeffs = np.zeros((7, 3))
    sin_coeffs = np.zeros((7, 3))
    cos_coeffs[1] = [HIP_HEIGHT, 0.0, BOB]
    sin_coeffs[2, 2] = PITCH
    sin_coeffs[3, 1], sin_coeffs[4, 1] = A, -A
    cos_coeffs[5] = [-3 * C / 8, -C / 2, -C / 8]
    cos_coeffs[6] = [-3 * C / 8, +C / 2, -C / 8]
    return drift, cos_coeffs, sin_coeffs


def gait(t):
    """``(q, qd, qdd)`` of the gait at time ``t`` (exact derivatives of the trigonometric polynomials)."""
    drift, a, b = gait_coefficients()
    w = 2.0 * np.pi / PERIOD * np.arange(a.shape[1])
    c, s = np.cos(w * t), np.sin(w * t)
    q = drift * t + a @ c + b @ s
    qd = drift + (b * w) @ c - (a * w) @ s
    qdd = -(a * w**2) @ c - (b * w**2) @ s
    return q, qd, qdd


def frame_time(frame):
    """Time of animation frame ``frame`` (1-based, ``FRAME_DT`` apart)."""
    return (frame - 1) * FRAME_DT


def kinematics_at(t, tree=None):
    """``{body name: inertial state}`` (``tree.inertial_state``) of the biped following the gait at time ``t``."""
    tree = build_biped() if tree is None else tree
    tree.forward_kinematics(*gait(t))
    return {body.name: inertial_state(body) for body in tree.bodies}


def solve(frame=90):
    """The biped at animation frame ``frame`` (default: the sheet's 90th frame), see ``kinematics_at``."""
    return kinematics_at(frame_time(frame))
