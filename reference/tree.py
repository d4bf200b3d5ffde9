"""Kinematic trees: rigid bodies linked by joints, recursive forward kinematics (problems 24, 25, 31-35).

Conventions (problem data, P24 and P31).  Every body B stores body-frame quantities:

``A_IB``                          orientation, maps B-coordinates to I-coordinates;
``B_r_IB``                        position of B, in B-coordinates (inertial position ``A_IB @ B_r_IB``);
``B_v_B``, ``B_a_B``              absolute velocity and acceleration of B, in B-coordinates;
``B_omega_B``, ``B_omegaDot_B``   absolute angular velocity and acceleration, in B-coordinates;
``B_J_S``, ``B_J_R``              3 x nq translational and rotational Jacobians in B-coordinates,
                                  ``B_v_B = B_J_S @ qd``, ``B_omega_B = B_J_R @ qd``;
``m``, ``B_I_B``                  mass and inertia about the centre of gravity (B is the centre of gravity).

A joint connects a predecessor P and a successor S.  It carries the frame Dp fixed on P (``P_r_PDp``, ``A_PDp``)
and the frame Ds fixed on S (``S_r_SDs``, ``A_SDs``).  Its *joint function* gives the relative pose
``A_DpDs(q)``, ``Dp_r_DpDs(q)`` and the relative motion in Dp-coordinates: ``r_rel_dot``, ``r_rel_ddot``
(derivatives of ``Dp_r_DpDs`` as seen from Dp), ``omega_rel``, ``omega_rel_dot`` (angular velocity and
acceleration of Ds relative to Dp) and the motion subspaces ``S = d r_rel_dot / d qd`` and
``R = d omega_rel / d qd`` (3 x nq of the joint).  The recursion across a joint is generic and lives in ``Joint``;
each joint type only supplies its joint function.

The root body sits at ``A_IB = E``, ``B_r_IB = 0`` and at rest.
"""

from typing import NamedTuple

import numpy as np

from .conventions import E3, as_matrix, as_vector
from .rotations import R3, skew

__all__ = [
    "JointMotion",
    "Body",
    "Joint",
    "RotationalJoint",
    "TranslationalJoint",
    "RollingContactJoint",
    "Virtual3DOFJoint",
    "RigidJoint",
    "KinematicTree",
    "inertial_state",
    "generalized_gravity",
    "tree_lines",
]


class JointMotion(NamedTuple):
    """Relative motion across a joint, all in Dp-coordinates.

    ``r_rel_dot``, ``r_rel_ddot``, ``omega_rel``, ``omega_rel_dot``: 3-vectors; ``S``, ``R``: 3 x nq of the joint
    with ``r_rel_dot = S @ qd`` and ``omega_rel = R @ qd``.
    """

    r_rel_dot: np.ndarray
    r_rel_ddot: np.ndarray
    omega_rel: np.ndarray
    omega_rel_dot: np.ndarray
    S: np.ndarray
    R: np.ndarray


class Body:
    """A rigid body in a kinematic tree: mass properties, links to its joints, and its kinematic state.

    ``parent_joint`` is the joint that has this body as successor (``None`` for the root), ``child_joints`` the
    joints that have it as predecessor.  State attributes (body coordinates, see the module docstring):
    ``A_IB``, ``B_r_IB``, ``B_v_B``, ``B_omega_B``, ``B_a_B``, ``B_omegaDot_B``, ``B_J_S``, ``B_J_R``.  A
    positions-only pass leaves the velocity, acceleration and Jacobian attributes at ``None``.
    """

    def __init__(self, name, m=0.0, B_I_B=None):
        self.name = str(name)
        self.m = float(m)
        self.B_I_B = np.zeros((3, 3)) if B_I_B is None else as_matrix(B_I_B).copy()
        self.parent_joint = None
        self.child_joints = []
        self.A_IB = np.eye(3)
        self.B_r_IB = np.zeros(3)
        self.clear_motion()

    def __repr__(self):
        return f"Body({self.name!r}, m={self.m})"

    @property
    def is_root(self):
        """True if no joint leads to this body."""
        return self.parent_joint is None

    def clear_motion(self):
        """Set velocities, accelerations and Jacobians to ``None`` (not computed)."""
        self.B_v_B = self.B_omega_B = self.B_a_B = self.B_omegaDot_B = None
        self.B_J_S = self.B_J_R = None

    def set_at_rest(self, nq, with_motion=True):
        """Put the body at the origin, ``A_IB = E``, at rest; with ``with_motion`` also zero velocities,
        accelerations and ``3 x nq`` Jacobians, otherwise those are cleared."""
        self.A_IB = np.eye(3)
        self.B_r_IB = np.zeros(3)
        if not with_motion:
            self.clear_motion()
            return
        self.B_v_B, self.B_omega_B = np.zeros(3), np.zeros(3)
        self.B_a_B, self.B_omegaDot_B = np.zeros(3), np.zeros(3)
        self.B_J_S, self.B_J_R = np.zeros((3, nq)), np.zeros((3, nq))

    def forward_kinematics(self, q, qd=None, qdd=None):
        """Recursively compute the state of every body below this one.

        ``q``, ``qd``, ``qdd`` are float arrays of the whole tree's coordinates.  With ``qd = None`` only positions
        and orientations are computed; otherwise ``qdd`` must be an array as well.  A root body first puts itself
        at rest at the origin (``set_at_rest``), then every child joint updates its successor, which recurses.
        """
        # BEGIN SOLUTION problem 24
        if self.is_root:
            self.set_at_rest(len(q), with_motion=qd is not None)
        for joint in self.child_joints:
            joint.forward_kinematics(q, qd, qdd)
        # END SOLUTION

    def subtree(self):
        """This body and all bodies below it, depth first, children in the order their joints were created."""
        yield self
        for joint in self.child_joints:
            yield from joint.successor.subtree()

    # inertial-frame views of the state
    @property
    def I_r_IB(self):
        return self.A_IB @ self.B_r_IB

    @property
    def I_v_B(self):
        return self.A_IB @ self.B_v_B

    @property
    def I_a_B(self):
        return self.A_IB @ self.B_a_B

    @property
    def I_omega_B(self):
        return self.A_IB @ self.B_omega_B

    @property
    def I_omegaDot_B(self):
        return self.A_IB @ self.B_omegaDot_B

    @property
    def I_J_S(self):
        return self.A_IB @ self.B_J_S

    @property
    def I_J_R(self):
        return self.A_IB @ self.B_J_R


class Joint:
    """Generic joint between ``predecessor`` P and ``successor`` S; subclasses supply the joint function.

    ``P_r_PDp``, ``A_PDp``: the frame Dp in P (default at P, aligned); ``S_r_SDs``, ``A_SDs``: the frame Ds in S.
    ``q_index``: the indices of the joint's ``nq`` coordinates in the tree's ``q``.  Creating a joint links it
    into its bodies (``predecessor.child_joints``, ``successor.parent_joint``).
    """

    #: number of coordinates of this joint type
    nq = 0

    def __init__(
        self,
        predecessor,
        successor,
        *,
        P_r_PDp=(0.0, 0.0, 0.0),
        A_PDp=E3,
        S_r_SDs=(0.0, 0.0, 0.0),
        A_SDs=E3,
        q_index=(),
    ):
        self.predecessor = predecessor
        self.successor = successor
        self.P_r_PDp = as_vector(P_r_PDp).copy()
        self.A_PDp = as_matrix(A_PDp).copy()
        self.S_r_SDs = as_vector(S_r_SDs).copy()
        self.A_SDs = as_matrix(A_SDs).copy()
        self.q_index = np.array(q_index, dtype=int).reshape(-1)
        if self.q_index.size != self.nq:
            raise ValueError(f"{type(self).__name__} has {self.nq} coordinates, got q_index {list(self.q_index)}")
        if successor.parent_joint is not None:
            raise ValueError(f"body {successor.name!r} already has a parent joint")
        if successor is predecessor:
            raise ValueError("a joint needs two different bodies")
        predecessor.child_joints.append(self)
        successor.parent_joint = self

    def __repr__(self):
        return f"{type(self).__name__}({self.predecessor.name!r} -> {self.successor.name!r})"

    # ---- joint function (supplied by each joint type) ----
    def joint_pose(self, q):
        """``(A_DpDs, Dp_r_DpDs)`` for the joint's coordinates ``q`` (array of length ``nq``)."""
        raise NotImplementedError(f"{type(self).__name__} does not define a joint function")

    def joint_motion(self, q, qd, qdd):
        """``JointMotion`` (relative velocities, accelerations, motion subspaces; in Dp) for the joint's
        coordinates and their derivatives (arrays of length ``nq``)."""
        raise NotImplementedError(f"{type(self).__name__} does not define a joint function")

    # ---- generic recursion across the joint ----
    def successor_pose(self, A_DpDs, Dp_r_DpDs):
        """Pose ``(A_IS, S_r_IS)`` of the successor from the predecessor's pose (problem data P24)::

            A_IDp = A_IP A_PDp          Dp_r_IDp = A_PDp.T (P_r_IP + P_r_PDp)
            A_IDs = A_IDp A_DpDs        Ds_r_IDs = A_DpDs.T (Dp_r_IDp + Dp_r_DpDs)
            A_IS  = A_IDs A_SDs.T       S_r_IS   = A_SDs Ds_r_IDs - S_r_SDs
        """
        # BEGIN SOLUTION problem 24
        P = self.predecessor
        A_IDp = P.A_IB @ self.A_PDp
        Dp_r_IDp = self.A_PDp.T @ (P.B_r_IB + self.P_r_PDp)
        A_IDs = A_IDp @ A_DpDs
        Ds_r_IDs = A_DpDs.T @ (Dp_r_IDp + Dp_r_DpDs)
        return A_IDs @ self.A_SDs.T, self.A_SDs @ Ds_r_IDs - self.S_r_SDs
        # END SOLUTION

    def successor_motion(self, A_DpDs, Dp_r_DpDs, rel):
        """Velocities and accelerations ``(S_v_S, S_omega_S, S_a_S, S_omegaDot_S)`` of the successor from the
        predecessor's (problem data P31), with ``r_rel = Dp_r_DpDs`` and ``rel`` the ``JointMotion``::

            Dp_omega = A_PDp.T P_omega              Dp_v = A_PDp.T (P_v + skew(P_omega) P_r_PDp)
            Dp_omegaDot = A_PDp.T P_omegaDot        Dp_a = A_PDp.T (P_a + (skew(P_omegaDot) + skew(P_omega)^2) P_r_PDp)
            Ds_omega = A_DpDs.T (Dp_omega + omega_rel)
            Ds_v = A_DpDs.T (Dp_v + r_rel_dot + skew(Dp_omega) r_rel)
            Ds_omegaDot = A_DpDs.T (Dp_omegaDot + omega_rel_dot + skew(Dp_omega) omega_rel)
            Ds_a = A_DpDs.T (Dp_a + r_rel_ddot + 2 skew(Dp_omega) r_rel_dot
                             + (skew(Dp_omegaDot) + skew(Dp_omega)^2) r_rel)
            S_omega = A_SDs Ds_omega                S_v = A_SDs Ds_v - skew(S_omega) S_r_SDs
            S_omegaDot = A_SDs Ds_omegaDot          S_a = A_SDs Ds_a - (skew(S_omegaDot) + skew(S_omega)^2) S_r_SDs
        """
        # BEGIN SOLUTION problem 31
        P = self.predecessor
        A_DpP = self.A_PDp.T
        P_Om, P_dOm = skew(P.B_omega_B), skew(P.B_omegaDot_B)
        Dp_omega = A_DpP @ P.B_omega_B
        Dp_omegaDot = A_DpP @ P.B_omegaDot_B
        Dp_v = A_DpP @ (P.B_v_B + P_Om @ self.P_r_PDp)
        Dp_a = A_DpP @ (P.B_a_B + (P_dOm + P_Om @ P_Om) @ self.P_r_PDp)

        Dp_Om, Dp_dOm = skew(Dp_omega), skew(Dp_omegaDot)
        A_DsDp = A_DpDs.T
        Ds_omega = A_DsDp @ (Dp_omega + rel.omega_rel)
        Ds_v = A_DsDp @ (Dp_v + rel.r_rel_dot + Dp_Om @ Dp_r_DpDs)
        Ds_omegaDot = A_DsDp @ (Dp_omegaDot + rel.omega_rel_dot + Dp_Om @ rel.omega_rel)
        Ds_a = A_DsDp @ (
            Dp_a + rel.r_rel_ddot + 2.0 * Dp_Om @ rel.r_rel_dot + (Dp_dOm + Dp_Om @ Dp_Om) @ Dp_r_DpDs
        )

        S_omega = self.A_SDs @ Ds_omega
        S_omegaDot = self.A_SDs @ Ds_omegaDot
        S_Om, S_dOm = skew(S_omega), skew(S_omegaDot)
        S_v = self.A_SDs @ Ds_v - S_Om @ self.S_r_SDs
        S_a = self.A_SDs @ Ds_a - (S_dOm + S_Om @ S_Om) @ self.S_r_SDs
        return S_v, S_omega, S_a, S_omegaDot
        # END SOLUTION

    def successor_jacobians(self, A_DpDs, Dp_r_DpDs, rel):
        """Jacobians ``(S_J_S, S_J_R)`` of the successor (3 x nq, problem data P31), with ``A_SP = (A_PDp A_DpDs
        A_SDs.T).T`` and the joint's ``S``, ``R`` placed at the columns ``q_index`` of 3 x nq zero matrices::

            S_J_R = A_SP (P_J_R + A_PDp R)
            S_J_S = A_SP (P_J_S + A_PDp S - skew(P_r_PDp + A_PDp r_rel) P_J_R) + skew(S_r_SDs) S_J_R
        """
        # BEGIN SOLUTION problem 31
        P = self.predecessor
        nq = P.B_J_S.shape[1]
        S = np.zeros((3, nq))
        R = np.zeros((3, nq))
        S[:, self.q_index] = rel.S
        R[:, self.q_index] = rel.R
        A_SP = (self.A_PDp @ A_DpDs @ self.A_SDs.T).T
        S_J_R = A_SP @ (P.B_J_R + self.A_PDp @ R)
        lever = skew(self.P_r_PDp + self.A_PDp @ Dp_r_DpDs)
        S_J_S = A_SP @ (P.B_J_S + self.A_PDp @ S - lever @ P.B_J_R) + skew(self.S_r_SDs) @ S_J_R
        return S_J_S, S_J_R
        # END SOLUTION

    def forward_kinematics(self, q, qd=None, qdd=None):
        """Update the successor from the predecessor across this joint, then recurse into the successor.

        Arguments as in ``Body.forward_kinematics``; the joint reads its own coordinates at ``q_index``.
        """
        i = self.q_index
        A_DpDs, Dp_r_DpDs = self.joint_pose(q[i])
        body = self.successor
        body.A_IB, body.B_r_IB = self.successor_pose(A_DpDs, Dp_r_DpDs)
        if qd is None:
            body.clear_motion()
        else:
            rel = self.joint_motion(q[i], qd[i], qdd[i])
            body.B_v_B, body.B_omega_B, body.B_a_B, body.B_omegaDot_B = self.successor_motion(
                A_DpDs, Dp_r_DpDs, rel
            )
            body.B_J_S, body.B_J_R = self.successor_jacobians(A_DpDs, Dp_r_DpDs, rel)
        body.forward_kinematics(q, qd, qdd)


def _zeros_motion(nq):
    zero = np.zeros(3)
    return JointMotion(zero, zero, zero, zero, np.zeros((3, nq)), np.zeros((3, nq)))


class RotationalJoint(Joint):
    """Rotation by ``gamma = q[0]`` about the 3-axis of Dp (problems 24, 31)."""

    nq = 1

    def joint_pose(self, q):
        """``A_DpDs = R3(gamma)``, ``Dp_r_DpDs = 0``."""
        # BEGIN SOLUTION problem 24
        return R3(q[0]), np.zeros(3)
        # END SOLUTION

    def joint_motion(self, q, qd, qdd):
        """``omega_rel = (0, 0, gamma_dot)``, ``omega_rel_dot = (0, 0, gamma_ddot)``, no relative translation;
        ``S = 0``, ``R = e3``."""
        # BEGIN SOLUTION problem 31
        e3 = np.array([0.0, 0.0, 1.0])
        zero = np.zeros(3)
        return JointMotion(zero, zero, e3 * qd[0], e3 * qdd[0], np.zeros((3, 1)), e3.reshape(3, 1))
        # END SOLUTION


class TranslationalJoint(Joint):
    """Translation by ``dx = q[0]`` along the 1-axis of Dp (problem 34)."""

    nq = 1

    def joint_pose(self, q):
        """``A_DpDs = E``, ``Dp_r_DpDs = (dx, 0, 0)``."""
        # BEGIN SOLUTION problem 34
        return np.eye(3), np.array([q[0], 0.0, 0.0])
        # END SOLUTION

    def joint_motion(self, q, qd, qdd):
        """``r_rel_dot = (dx_dot, 0, 0)``, ``r_rel_ddot = (dx_ddot, 0, 0)``, no relative rotation;
        ``S = e1``, ``R = 0``."""
        # BEGIN SOLUTION problem 34
        e1 = np.array([1.0, 0.0, 0.0])
        zero = np.zeros(3)
        return JointMotion(e1 * qd[0], e1 * qdd[0], zero, zero, e1.reshape(3, 1), np.zeros((3, 1)))
        # END SOLUTION


class RollingContactJoint(Joint):
    """A circle of radius ``r`` on the successor rolling without slipping on the flat predecessor, rotated by
    ``gamma = q[0]`` about the 3-axis of Dp; Dp and Ds sit at the circle's centre (problems 25, 33)."""

    nq = 1

    def __init__(self, predecessor, successor, *, r, **geometry):
        super().__init__(predecessor, successor, **geometry)
        self.r = float(r)

    def joint_pose(self, q):
        """``A_DpDs = R3(gamma)``, ``Dp_r_DpDs = (-r gamma, 0, 0)``."""
        # BEGIN SOLUTION problem 25
        return R3(q[0]), np.array([-self.r * q[0], 0.0, 0.0])
        # END SOLUTION

    def joint_motion(self, q, qd, qdd):
        """``r_rel_dot = (-r gamma_dot, 0, 0)``, ``r_rel_ddot = (-r gamma_ddot, 0, 0)``,
        ``omega_rel = (0, 0, gamma_dot)``, ``omega_rel_dot = (0, 0, gamma_ddot)``; ``S = (-r, 0, 0)``, ``R = e3``."""
        # BEGIN SOLUTION problem 33
        s = np.array([-self.r, 0.0, 0.0])
        e3 = np.array([0.0, 0.0, 1.0])
        return JointMotion(s * qd[0], s * qdd[0], e3 * qd[0], e3 * qdd[0], s.reshape(3, 1), e3.reshape(3, 1))
        # END SOLUTION


class Virtual3DOFJoint(Joint):
    """Planar floating joint, ``q = (dx, dy, gamma)``: translation in the 1-2 plane of Dp, rotation about its
    3-axis (problem 34)."""

    nq = 3

    def joint_pose(self, q):
        """``A_DpDs = R3(gamma)``, ``Dp_r_DpDs = (dx, dy, 0)``."""
        # BEGIN SOLUTION problem 34
        return R3(q[2]), np.array([q[0], q[1], 0.0])
        # END SOLUTION

    def joint_motion(self, q, qd, qdd):
        """``r_rel_dot = (dx_dot, dy_dot, 0)``, ``r_rel_ddot = (dx_ddot, dy_ddot, 0)``,
        ``omega_rel = (0, 0, gamma_dot)``, ``omega_rel_dot = (0, 0, gamma_ddot)``;
        ``S = [e1 e2 0]``, ``R = [0 0 e3]``."""
        # BEGIN SOLUTION problem 34
        S = np.diag([1.0, 1.0, 0.0])
        R = np.diag([0.0, 0.0, 1.0])
        return JointMotion(S @ qd, S @ qdd, R @ qd, R @ qdd, S, R)
        # END SOLUTION


class RigidJoint(Joint):
    """A joint without coordinates: the successor is rigidly attached, Ds coincides with Dp (problem 32)."""

    nq = 0

    def joint_pose(self, q):
        """``A_DpDs = E``, ``Dp_r_DpDs = 0``."""
        # BEGIN SOLUTION problem 32
        return np.eye(3), np.zeros(3)
        # END SOLUTION

    def joint_motion(self, q, qd, qdd):
        """No relative motion; ``S``, ``R`` are 3 x 0."""
        # BEGIN SOLUTION problem 32
        return _zeros_motion(0)
        # END SOLUTION


class KinematicTree:
    """The bodies and joints below ``root``, collected depth first, and the number of coordinates ``nq``.

    The joints' ``q_index`` must together cover ``0 .. nq-1`` exactly once.  Bodies are looked up by name with
    ``tree["link_1"]``.
    """

    def __init__(self, root):
        if not root.is_root:
            raise ValueError(f"body {root.name!r} has a parent joint and cannot be the root")
        self.root = root
        self.bodies = list(root.subtree())
        self.joints = [body.parent_joint for body in self.bodies[1:]]
        self.nq = sum(joint.nq for joint in self.joints)
        indices = sorted(int(i) for joint in self.joints for i in joint.q_index)
        if indices != list(range(self.nq)):
            raise ValueError(f"the joints' q_index must cover 0..{self.nq - 1} exactly once, got {indices}")
        names = [body.name for body in self.bodies]
        if len(set(names)) != len(names):
            raise ValueError(f"body names must be unique, got {names}")
        self._by_name = {body.name: body for body in self.bodies}

    def __getitem__(self, name):
        return self._by_name[name]

    def __iter__(self):
        return iter(self.bodies)

    def forward_kinematics(self, q, qd=None, qdd=None):
        """Positions (and with ``qd`` velocities, accelerations and Jacobians) of all bodies; ``qdd`` defaults to
        zeros, which gives the bias accelerations.  Returns the tree."""
        q = as_vector(q, self.nq)
        if qd is None:
            if qdd is not None:
                raise ValueError("qdd needs qd")
        else:
            qd = as_vector(qd, self.nq)
            qdd = np.zeros(self.nq) if qdd is None else as_vector(qdd, self.nq)
        self.root.forward_kinematics(q, qd, qdd)
        return self


def inertial_state(body):
    """The body's current state in inertial coordinates: ``A_IB``, ``I_r_IB`` and, if computed, ``I_v_B``,
    ``I_omega_B``, ``I_a_B``, ``I_omegaDot_B``, ``I_J_S``, ``I_J_R``."""
    state = {"A_IB": body.A_IB.copy(), "I_r_IB": body.I_r_IB}
    if body.B_v_B is not None:
        for name in ("I_v_B", "I_omega_B", "I_a_B", "I_omegaDot_B", "I_J_S", "I_J_R"):
            state[name] = getattr(body, name)
    return state


def generalized_gravity(tree, q, I_grav):
    """Generalized gravity forces ``g(q) = sum(B_J_S.T @ A_IB.T @ I_grav * m)`` over all bodies, with the
    gravitational acceleration ``I_grav`` in inertial coordinates (``M qdd = f + g + tau``)."""
    # BEGIN SOLUTION problem 32
    tree.forward_kinematics(q, np.zeros(tree.nq))
    I_grav = as_vector(I_grav)
    g = np.zeros(tree.nq)
    for body in tree.bodies:
        g += body.B_J_S.T @ (body.A_IB.T @ I_grav) * body.m
    return g
    # END SOLUTION


def tree_lines(tree):
    """Line segments for a drawing of the tree in its current state, as an array ``(n, 2, 3)`` of inertial
    start and end points: for every joint, predecessor -> Dp, Dp -> Ds and Ds -> successor."""
    segments = []
    for joint in tree.joints:
        P, S = joint.predecessor, joint.successor
        I_r_P, I_r_S = P.I_r_IB, S.I_r_IB
        I_r_Dp = I_r_P + P.A_IB @ joint.P_r_PDp
        I_r_Ds = I_r_S + S.A_IB @ joint.S_r_SDs
        segments += [(I_r_P, I_r_Dp), (I_r_Dp, I_r_Ds), (I_r_Ds, I_r_S)]
    return np.array(segments, dtype=float).reshape(-1, 2, 3)
