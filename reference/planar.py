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
    # BEGIN SOLUTION problem 21
    q1, q2 = np.asarray(q, dtype=float)
    return np.array([0.0, q1, 0.0, -d * np.sin(q2), q1 + d * np.cos(q2), q2])
    # END SOLUTION


def jacobian_a(q, d):
    """Analytic ``J_a = d f_a / d q_a`` (6 x 2) of case a."""
    # BEGIN SOLUTION problem 21
    _, q2 = np.asarray(q, dtype=float)
    c2, s2 = np.cos(q2), np.sin(q2)
    return np.array(
        [
            [0.0, 0.0],
            [1.0, 0.0],
            [0.0, 0.0],
            [0.0, -d * c2],
            [1.0, -d * s2],
            [0.0, 1.0],
        ]
    )
    # END SOLUTION


def chain_b(q, d):
    """``x_b = f_b(q_b) = (x1, y1, gamma1, x2, y2, gamma2, xe, ye, gammae)`` of case b for ``q = (q1, q2, q3, q4)``.

    ``gamma1 = 0`` and ``gamma2 = q2`` are the orientations of the segments that end at P1 and P2;
    the end effector's orientation is ``q2 + q4``.
    """
    # BEGIN SOLUTION problem 21
    q1, q2, q3, q4 = np.asarray(q, dtype=float)
    x2, y2 = -q3 * np.sin(q2), q1 + q3 * np.cos(q2)
    g_e = q2 + q4
    return np.array([0.0, q1, 0.0, x2, y2, q2, x2 - d * np.sin(g_e), y2 + d * np.cos(g_e), g_e])
    # END SOLUTION


def jacobian_b(q, d):
    """Analytic ``J_b = d f_b / d q_b`` (9 x 4) of case b."""
    # BEGIN SOLUTION problem 21
    _, q2, q3, q4 = np.asarray(q, dtype=float)
    c2, s2 = np.cos(q2), np.sin(q2)
    c24, s24 = np.cos(q2 + q4), np.sin(q2 + q4)
    return np.array(
        [
            [0.0, 0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0],
            [0.0, -q3 * c2, -s2, 0.0],
            [1.0, -q3 * s2, c2, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, -q3 * c2 - d * c24, -s2, -d * c24],
            [1.0, -q3 * s2 - d * s24, c2, -d * s24],
            [0.0, 1.0, 0.0, 1.0],
        ]
    )
    # END SOLUTION


def end_effector_loop(q, d):
    """End-effector pose ``(x, y, gamma)`` of the 2n-joint arm, walking the joints from the base in a for-loop.

    ``q`` alternates prismatic lengths and rotation angles, ``(q1, q2, ..., q_2n)``; ``d`` is the final link.
    """
    # BEGIN SOLUTION problem 22
    x = y = gamma = 0.0
    for length, angle in np.asarray(q, dtype=float).reshape(-1, 2):
        x -= length * np.sin(gamma)
        y += length * np.cos(gamma)
        gamma += angle
    return np.array([x - d * np.sin(gamma), y + d * np.cos(gamma), gamma])
    # END SOLUTION


def point_k(q, k):
    """Pose ``(x_k, y_k, g_k)`` of point ``P_k`` (``0 <= k <= n``), computed recursively from ``P_{k-1}``.

    ``g_k`` is the orientation of the segment leaving ``P_k``, i.e. after the rotational joint ``q_2k``;
    ``P_0`` is the origin with ``g_0 = 0``.  (Problem 21 lists the orientation of the segment arriving at a point
    instead: ``gamma1`` of ``chain_b`` is ``g_0``, ``gamma2`` is ``g_1``.)
    """
    # BEGIN SOLUTION problem 22
    if not 0 <= k <= len(q) // 2:
        raise ValueError(f"point index {k} outside 0..{len(q) // 2}")
    if k == 0:
        return np.zeros(3)
    x, y, gamma = point_k(q, k - 1)
    length, angle = q[2 * k - 2], q[2 * k - 1]
    return np.array([x - length * np.sin(gamma), y + length * np.cos(gamma), gamma + angle])
    # END SOLUTION


def end_effector_recursive(q, d):
    """End-effector pose ``(x, y, gamma)`` of the 2n-joint arm from ``point_k(q, n)`` (recursive)."""
    # BEGIN SOLUTION problem 22
    q = np.asarray(q, dtype=float)
    if q.size % 2:
        raise ValueError(f"expected an even number of joint variables, got {q.size}")
    x, y, gamma = point_k(q, q.size // 2)
    return np.array([x - d * np.sin(gamma), y + d * np.cos(gamma), gamma])
    # END SOLUTION
# BEGIN REFERENCE ONLY


# The arm with a known mistake switched on, for the grader's diagnoses only (reached through the probes of
# problems 21 and 22, never shipped to students).  Complex ``q`` is kept, for complex-step derivatives.

#: mistakes of ``mistaken_walk``
ARM_MISTAKES = ("degrees", "horizontal", "horizontal_all", "horizontal_offset", "joint_order", "no_final_link")


def _direction(gamma, mistake=None):
    """Unit vector of a segment of orientation ``gamma``, as the sheet defines it or as a mistake reads it."""
    if mistake in ("horizontal", "horizontal_all"):
        return np.array([np.cos(gamma), np.sin(gamma)])
    return np.array([-np.sin(gamma), np.cos(gamma)])


def mistaken_walk(q, d, mistake=None):
    """The 2n-joint arm with ``mistake`` applied: ``(points, end)``, ``points[k-1] = (x_k, y_k, g_{k-1}, g_k)``
    for ``k = 1..n`` and ``end = (xe, ye, g_n)``.

    Mistakes: ``degrees`` (radians read as degrees), ``horizontal`` (segments along (cos g, sin g) after the
    vertical first one), ``horizontal_all`` (every segment along (cos g, sin g)), ``horizontal_offset`` (right
    positions, orientations from the horizontal: +90 deg), ``joint_order`` (each segment after its own rotation),
    ``no_final_link`` (d left out).
    """
    pairs = np.asarray(q).reshape(-1, 2)
    if mistake == "degrees":
        pairs = pairs * np.array([1.0, np.pi / 180.0])
    offset = np.pi / 2 if mistake == "horizontal_offset" else 0.0
    point, gamma, points = np.zeros(2), 0.0, []
    for k, (length, turn) in enumerate(pairs):
        before = gamma
        if mistake == "joint_order":
            gamma = gamma + turn
        along = np.array([0.0, 1.0]) if k == 0 and mistake == "horizontal" else _direction(gamma, mistake)
        point = point + length * along
        if mistake != "joint_order":
            gamma = gamma + turn
        points.append(np.array([*point, before + offset, gamma + offset]))
    link = 0.0 if mistake == "no_final_link" else d
    return points, np.array([*(point + link * _direction(gamma, mistake)), gamma + offset])


def mistaken_layout(q, d, mistake=None):
    """``x_a`` / ``x_b`` of problem 21 with ``mistake`` applied: each point with the orientation of the segment
    arriving there, then the end effector."""
    points, end = mistaken_walk(q, d, mistake)
    return np.concatenate([*(p[:3] for p in points), end])
# END REFERENCE ONLY
