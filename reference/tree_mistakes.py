# BEGIN REFERENCE ONLY
"""Mistaken copies of the tree's recursion, for the grader's diagnoses only (reached through the probe
``_trees.mistaken_states``; the student template leaves this module out whole, and no kit holds it).

The formulas of ``tree.Joint`` with one known mistake switched on.  ``mistaken_classes(spec)`` returns a stand-in
for the ``tree`` module whose joint classes carry it.
"""

import functools
import json
import types

import numpy as np

from .rotations import skew
from .tree import (
    Body,
    Joint,
    JointMotion,
    KinematicTree,
    RigidJoint,
    RollingContactJoint,
    RotationalJoint,
    TranslationalJoint,
    Virtual3DOFJoint,
)

__all__ = ["mistaken_classes"]


def _mistaken_pose(joint, A_DpDs, r_rel, transpose=False, ds_transpose=False, reverse="", offset_sign=-1.0,
                   offset_in_dp=False):
    """``Joint.successor_pose`` with a mistake (``reverse``: "all" products or the "joint" rotation's product in
    the wrong order)."""
    P = joint.predecessor
    A_PDp = joint.A_PDp.T if transpose else joint.A_PDp
    A_SDs = joint.A_SDs.T if ds_transpose else joint.A_SDs
    if reverse == "all":
        A_IS = A_SDs.T @ A_DpDs @ A_PDp @ P.A_IB
    elif reverse == "joint":
        A_IS = A_DpDs @ P.A_IB @ A_PDp @ A_SDs.T
    else:
        A_IS = P.A_IB @ A_PDp @ A_DpDs @ A_SDs.T
    Dp_r_IDp = A_PDp.T @ P.B_r_IB + joint.P_r_PDp if offset_in_dp else A_PDp.T @ (P.B_r_IB + joint.P_r_PDp)
    return A_IS, A_SDs @ (A_DpDs.T @ (Dp_r_IDp + r_rel)) + offset_sign * joint.S_r_SDs


def _mistaken_motion(joint, A_DpDs, r_rel, rel, transpose=False, coriolis=2.0, transport=1.0, centripetal_dp=1.0,
                     centripetal_ds=1.0, offset_sign=-1.0):
    """``Joint.successor_motion`` with a mistake."""
    P = joint.predecessor
    A_DpP = joint.A_PDp if transpose else joint.A_PDp.T
    P_Om, P_dOm = skew(P.B_omega_B), skew(P.B_omegaDot_B)
    Dp_omega, Dp_omegaDot = A_DpP @ P.B_omega_B, A_DpP @ P.B_omegaDot_B
    Dp_v = A_DpP @ (P.B_v_B + P_Om @ joint.P_r_PDp)
    Dp_a = A_DpP @ (P.B_a_B + (P_dOm + centripetal_dp * P_Om @ P_Om) @ joint.P_r_PDp)
    Om, dOm = skew(Dp_omega), skew(Dp_omegaDot)
    A_DsDp = A_DpDs.T
    Ds_omega = A_DsDp @ (Dp_omega + rel.omega_rel)
    Ds_v = A_DsDp @ (Dp_v + rel.r_rel_dot + Om @ r_rel)
    Ds_omegaDot = A_DsDp @ (Dp_omegaDot + rel.omega_rel_dot + transport * Om @ rel.omega_rel)
    Ds_a = A_DsDp @ (Dp_a + rel.r_rel_ddot + coriolis * Om @ rel.r_rel_dot + (dOm + Om @ Om) @ r_rel)
    S_omega, S_omegaDot = joint.A_SDs @ Ds_omega, joint.A_SDs @ Ds_omegaDot
    S_Om, S_dOm = skew(S_omega), skew(S_omegaDot)
    S_v = joint.A_SDs @ Ds_v + offset_sign * S_Om @ joint.S_r_SDs
    S_a = joint.A_SDs @ Ds_a + offset_sign * (S_dOm + centripetal_ds * S_Om @ S_Om) @ joint.S_r_SDs
    return S_v, S_omega, S_a, S_omegaDot


def _mistaken_jacobians(joint, A_DpDs, r_rel, rel, transpose=False, shift=0, lever=1.0, offset_sign=-1.0):
    """``Joint.successor_jacobians`` with a mistake (``shift``: the joint's columns moved by that many places)."""
    P = joint.predecessor
    nq = P.B_J_S.shape[1]
    columns = (joint.q_index + shift) % nq
    S, R = np.zeros((3, nq)), np.zeros((3, nq))
    S[:, columns], R[:, columns] = rel.S, rel.R
    A_PDp = joint.A_PDp.T if transpose else joint.A_PDp
    A_SP = (A_PDp @ A_DpDs @ joint.A_SDs.T).T
    S_J_R = A_SP @ (P.B_J_R + A_PDp @ R)
    arm = lever * skew(joint.P_r_PDp + A_PDp @ r_rel)
    S_J_S = A_SP @ (P.B_J_S + A_PDp @ S - arm @ P.B_J_R) - offset_sign * skew(joint.S_r_SDs) @ S_J_R
    return S_J_S, S_J_R


class _MistakenRecursion:
    """The generic recursion with the switches of a mistake (class attributes set by ``mistaken_classes``)."""

    mistake_pose = mistake_motion = mistake_jacobians = {}

    def successor_pose(self, A_DpDs, Dp_r_DpDs):
        return _mistaken_pose(self, A_DpDs, Dp_r_DpDs, **self.mistake_pose)

    def successor_motion(self, A_DpDs, Dp_r_DpDs, rel):
        return _mistaken_motion(self, A_DpDs, Dp_r_DpDs, rel, **self.mistake_motion)

    def successor_jacobians(self, A_DpDs, Dp_r_DpDs, rel):
        return _mistaken_jacobians(self, A_DpDs, Dp_r_DpDs, rel, **self.mistake_jacobians)


class _RotationalSign:
    """A rotational joint turning the wrong way: ``A_DpDs = R3(-gamma)``."""

    def joint_pose(self, q):
        A_DpDs, r_rel = super().joint_pose(q)
        return A_DpDs.T, r_rel

    def joint_motion(self, q, qd, qdd):
        rel = super().joint_motion(q, qd, qdd)
        return rel._replace(omega_rel=-rel.omega_rel, omega_rel_dot=-rel.omega_rel_dot, R=-rel.R)


class _RollingMotionSign:
    """A rolling contact whose relative motion has the wrong sign: ``S = (+r, 0, 0)``."""

    def joint_motion(self, q, qd, qdd):
        rel = super().joint_motion(q, qd, qdd)
        return rel._replace(r_rel_dot=-rel.r_rel_dot, r_rel_ddot=-rel.r_rel_ddot, S=-rel.S)


class _RollingWrongWay(_RollingMotionSign):
    """A rolling contact moving the wrong way: ``Dp_r_DpDs = (+r gamma, 0, 0)``."""

    def joint_pose(self, q):
        A_DpDs, r_rel = super().joint_pose(q)
        return A_DpDs, -r_rel


class _VirtualOrder:
    """A virtual 3-DOF joint read as ``q = (gamma, dx, dy)``."""

    def joint_pose(self, q):
        return super().joint_pose(np.asarray(q)[[1, 2, 0]])

    def joint_motion(self, q, qd, qdd):
        order = [1, 2, 0]
        rel = super().joint_motion(np.asarray(q)[order], np.asarray(qd)[order], np.asarray(qdd)[order])
        return rel._replace(S=rel.S[:, [2, 0, 1]], R=rel.R[:, [2, 0, 1]])


#: joint mistakes by name: (the joint type they change, the mixin)
_JOINT_MISTAKES = {
    "rotational_sign": (RotationalJoint, _RotationalSign),
    "rolling_motion_sign": (RollingContactJoint, _RollingMotionSign),
    "rolling_wrong_way": (RollingContactJoint, _RollingWrongWay),
    "virtual_order": (Virtual3DOFJoint, _VirtualOrder),
}
_JOINT_TYPES = (RotationalJoint, TranslationalJoint, RollingContactJoint, Virtual3DOFJoint, RigidJoint)


@functools.lru_cache(maxsize=None)
def _mistaken_namespace(spec_text):
    spec = json.loads(spec_text)
    generic = type("MistakenRecursion", (_MistakenRecursion,), {
        "mistake_pose": spec.get("pose", {}), "mistake_motion": spec.get("motion", {}),
        "mistake_jacobians": spec.get("jacobians", {})})
    special = dict([_JOINT_MISTAKES[spec["joint"]]]) if spec.get("joint") else {}
    classes = {cls.__name__: type(cls.__name__, tuple(b for b in (special.get(cls), generic) if b) + (cls,), {})
               for cls in _JOINT_TYPES}
    return types.SimpleNamespace(Body=Body, KinematicTree=KinematicTree, JointMotion=JointMotion,
                           Joint=type("Joint", (generic, Joint), {}), **classes)


def mistaken_classes(spec):
    """A stand-in for the ``tree`` module (``Body``, ``KinematicTree``, ``JointMotion``, ``Joint`` and the joint types)
    whose recursion carries the mistake ``spec``: ``{"pose": {...}, "motion": {...}, "jacobians": {...}}`` switches
    of ``_mistaken_pose``, ``_mistaken_motion``, ``_mistaken_jacobians``, and ``"joint"``: a name of
    ``_JOINT_MISTAKES``."""
    return _mistaken_namespace(json.dumps(spec, sort_keys=True))
# END REFERENCE ONLY
