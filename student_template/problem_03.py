"""Problem 3: a double pendulum in MuJoCo.

Two identical HDPE links (the link of problem 2b): joint 1 at the world origin, joint 2 at the free end of link 1,
both hinges about z, both angles 0 at the start (straight, horizontal along +x, at rest), no damping, no torque.
(a) The model, with mass and inertia computed by MuJoCo from the geometry.  (b) The same model with the inertia
given by hand (Simscape's "Custom" inertia): mass, centre of mass, moments and products of inertia from L, W, H
and rho; the motion must not change.  (c) Joint 1 driven kinematically at a constant rate, ``q1 = rate t``.

The sheet compared only the first five seconds: why?  (answers.toml, [problem_03.free_text] why_five_seconds)
"""

import numpy as np

from .mjcf import HEIGHT, LENGTH, WIDTH, number, vector

__all__ = ["double_pendulum", "link_inertia", "double_pendulum_custom_inertia", "driven_double_pendulum"]


def double_pendulum(density, gravity):
    """MJCF text of the double pendulum (3a): body ``link1`` with hinge ``joint1`` at the origin, and inside it body
    ``link2`` with hinge ``joint2`` at the free end of link 1 (``pos`` = the link's length along link 1's x).
    Inertia from the geometry (``density``); gravity ``(0, -gravity, 0)``; RK4 with a 1 ms step."""
    # TODO problem 3: write your solution here
    raise NotImplementedError("Problem 3: double_pendulum is not implemented yet")


def link_inertia(length, width, height, density):
    """The custom inertia of a brick link (3b), in the link's body frame (origin at the joint, x along the link):
    ``{"mass": m, "com": (3,), "inertia": (3, 3)}``, the inertia about the centre of mass.

    ``m = L W H rho``; the centre of mass is the middle of the brick; the moments are
    ``m/12 (W^2 + H^2)``, ``m/12 (L^2 + H^2)``, ``m/12 (L^2 + W^2)``; the products are 0.
    """
    # TODO problem 3: write your solution here
    raise NotImplementedError("Problem 3: link_inertia is not implemented yet")


def double_pendulum_custom_inertia(density, gravity):
    """MJCF text of the double pendulum with custom inertia (3b): each body declares
    ``<inertial pos="..." mass="..." fullinertia="Ixx Iyy Izz Ixy Ixz Iyz"/>`` from ``link_inertia`` (an explicit
    ``<inertial>`` replaces the inertia MuJoCo would compute from the geoms); otherwise as ``double_pendulum``."""
    # TODO problem 3: write your solution here
    raise NotImplementedError("Problem 3: double_pendulum_custom_inertia is not implemented yet")


def driven_double_pendulum(density, gravity, rate):
    """MJCF text of the double pendulum of 3a with joint 1 driven kinematically (3c): ``q1 = rate t``.

    The MuJoCo idiom for a prescribed joint motion is a stiff servo: an ``<intvelocity>`` actuator on joint 1
    (``kp="1000"``, no ``kv``) integrates its control, the velocity setpoint, into a position setpoint and pulls
    the joint onto it.  The model starts from a keyframe in which the drive already runs:
    ``<keyframe><key qvel="rate 0" ctrl="rate"/></keyframe>`` (joint 1 turns at ``rate`` from t = 0, joint 2 at
    rest relative to link 1).  The grader resets the model to its first keyframe and never changes the control.
    """
    # TODO problem 3: write your solution here
    raise NotImplementedError("Problem 3: driven_double_pendulum is not implemented yet")


