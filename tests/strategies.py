"""Hypothesis strategies shared by the tests: angles, vectors, rotations, inertia matrices, kinematic trees."""

import numpy as np
from hypothesis import strategies as st

from reference.rotations import R1, R2, R3
from reference.tree import (
    Body,
    KinematicTree,
    RigidJoint,
    RollingContactJoint,
    RotationalJoint,
    TranslationalJoint,
    Virtual3DOFJoint,
)

finite = dict(allow_nan=False, allow_infinity=False)

angles = st.floats(-np.pi, np.pi, **finite)
small_angles = st.floats(-1.4, 1.4, **finite)


def vectors(n=3, bound=10.0):
    """Arrays of shape (n,) with entries in [-bound, bound]."""
    return st.lists(st.floats(-bound, bound, **finite), min_size=n, max_size=n).map(np.array)


@st.composite
def rotations(draw):
    """Proper rotation matrices, built from three Cardan angles (covers SO(3))."""
    a, b, g = draw(angles), draw(st.floats(-np.pi / 2, np.pi / 2, **finite)), draw(angles)
    return R3(g) @ R2(b) @ R1(a)


@st.composite
def principal_moments(draw, low=0.1, high=10.0):
    """Three principal moments that satisfy the triangle inequality (I_i <= I_j + I_k)."""
    # moments of a mass distribution: I1 = y2 + z2, I2 = x2 + z2, I3 = x2 + y2 with second moments >= 0
    x2, y2, z2 = (draw(st.floats(low / 2, high / 2, **finite)) for _ in range(3))
    return np.array([y2 + z2, x2 + z2, x2 + y2])


@st.composite
def inertia_matrices(draw):
    """Symmetric positive-definite inertia matrices that satisfy the triangle inequality."""
    A = draw(rotations())
    return A @ np.diag(draw(principal_moments())) @ A.T


JOINT_CLASSES = {
    "rotational": RotationalJoint,
    "translational": TranslationalJoint,
    "rolling_contact": RollingContactJoint,
    "virtual_3dof": Virtual3DOFJoint,
    "rigid": RigidJoint,
}
MOVING_KINDS = ("rotational", "translational", "rolling_contact", "virtual_3dof")


def make_joint(kind, predecessor, successor, first_index, r=0.3, **geometry):
    """A joint of type ``kind`` (a key of ``JOINT_CLASSES``) on the coordinates from ``first_index`` on."""
    cls = JOINT_CLASSES[kind]
    index = list(range(first_index, first_index + cls.nq))
    if cls is RollingContactJoint:
        return cls(predecessor, successor, r=r, q_index=index, **geometry)
    return cls(predecessor, successor, q_index=index, **geometry)


def massive_body(draw, name):
    """A ``Body`` with a random mass (kinematics only)."""
    return Body(name, m=draw(st.floats(0.1, 5.0)))


@st.composite
def trees(draw, max_bodies=5, body=massive_body):
    """Random trees: each new body (made by ``body(draw, name)``) hangs at a random earlier body through a random
    joint type with random offsets and joint-frame orientations; coordinates are numbered in creation order.  The
    first joint moves, so ``nq >= 1``."""
    n = draw(st.integers(1, max_bodies))
    bodies = [body(draw, "body_0")]
    nq = 0
    for k in range(1, n + 1):
        predecessor = bodies[draw(st.integers(0, k - 1))]
        successor = body(draw, f"body_{k}")
        kind = draw(st.sampled_from(MOVING_KINDS if k == 1 else tuple(JOINT_CLASSES)))
        geometry = {
            "P_r_PDp": draw(vectors(3, 1.0)),
            "A_PDp": draw(rotations()),
            "S_r_SDs": draw(vectors(3, 1.0)),
            "A_SDs": draw(rotations()),
        }
        joint = make_joint(kind, predecessor, successor, nq, r=draw(st.floats(0.05, 1.0)), **geometry)
        nq += joint.nq
        bodies.append(successor)
    return KinematicTree(bodies[0])
