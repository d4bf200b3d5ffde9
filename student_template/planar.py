"""Planar kinematics of serial arms with prismatic and rotational joints (problems 21 and 22).

Conventions (problem data): poses are ``(x, y, gamma)`` in the inertial frame I at the robot's base; the
orientation ``gamma`` of a segment is measured from the vertical (the y-axis), counter-clockwise positive, so a
segment of orientation ``gamma`` and length ``s`` spans ``s * (-sin gamma, cos gamma)``.  Prismatic joints extend
along the current segment; the first segment is vertical.

Problem 21, case a: ``q_a = (q1, q2)``, q1 prismatic, q2 rotational at P1, final link of length d.
Case b stacks two such stages: ``q_b = (q1, q2, q3, q4)``.  Problem 22 stacks n stages:
``q = (q1, ..., q_2n)`` alternating prismatic (odd, lengths) and rotational (even, angles) joints, with
``P_k = P_{k-1} + q_{2k-1} (-sin g_{k-1}, cos g_{k-1})`` and ``g_k = g_{k-1} + q_{2k}`` from ``P_0 = 0``,
``g_0 = 0``; the end effector sits at ``P_n + d (-sin g_n, cos g_n)`` with orientation ``g_n``.
"""

import numpy as np

__all__ = [
    "chain_a",
    "jacobian_a",
    "chain_b",
    "jacobian_b",
    "end_effector_loop",
    "point_k",
    "end_effector_recursive",
]


def chain_a(q, d):
    """``x_a = f_a(q_a) = (x1, y1, gamma1, xe, ye, gammae)`` of case a for ``q = (q1, q2)`` and link length ``d``."""
    # TODO problem 21: write your solution here
    raise NotImplementedError("Problem 21: chain_a is not implemented yet")


def jacobian_a(q, d):
    """Analytic ``J_a = d f_a / d q_a`` (6 x 2) of case a."""
    # TODO problem 21: write your solution here
    raise NotImplementedError("Problem 21: jacobian_a is not implemented yet")


def chain_b(q, d):
    """``x_b = f_b(q_b) = (x1, y1, gamma1, x2, y2, gamma2, xe, ye, gammae)`` of case b for ``q = (q1, q2, q3, q4)``.

    ``gamma1 = 0`` and ``gamma2 = q2`` are the orientations of the segments that end at P1 and P2;
    the end effector's orientation is ``q2 + q4``.
    """
    # TODO problem 21: write your solution here
    raise NotImplementedError("Problem 21: chain_b is not implemented yet")


def jacobian_b(q, d):
    """Analytic ``J_b = d f_b / d q_b`` (9 x 4) of case b."""
    # TODO problem 21: write your solution here
    raise NotImplementedError("Problem 21: jacobian_b is not implemented yet")


def end_effector_loop(q, d):
    """End-effector pose ``(x, y, gamma)`` of the 2n-joint arm, walking the joints from the base in a for-loop.

    ``q`` alternates prismatic lengths and rotation angles, ``(q1, q2, ..., q_2n)``; ``d`` is the final link.
    """
    # TODO problem 22: write your solution here
    raise NotImplementedError("Problem 22: end_effector_loop is not implemented yet")


def point_k(q, k):
    """Pose ``(x_k, y_k, g_k)`` of point ``P_k`` (``0 <= k <= n``), computed recursively from ``P_{k-1}``.

    ``g_k`` is the orientation of the segment leaving ``P_k``, i.e. after the rotational joint ``q_2k``;
    ``P_0`` is the origin with ``g_0 = 0``.  (Problem 21 lists the orientation of the segment arriving at a point
    instead: ``gamma1`` of ``chain_b`` is ``g_0``, ``gamma2`` is ``g_1``.)
    """
    # TODO problem 22: write your solution here
    raise NotImplementedError("Problem 22: point_k is not implemented yet")


def end_effector_recursive(q, d):
    """End-effector pose ``(x, y, gamma)`` of the 2n-joint arm from ``point_k(q, n)`` (recursive)."""
    # TODO problem 22: write your solution here
    raise NotImplementedError("Problem 22: end_effector_recursive is not implemented yet")
