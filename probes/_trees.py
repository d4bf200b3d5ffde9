"""Shared probe helpers of the kinematic-tree problems (24, 25, 31-35).

A tree travels as plain data::

    {"bodies": [{"name": "body_0", "m": 1.0}, ...],
     "joints": [{"kind": "rotational", "parent": 0, "q_index": [2], "P_r_PDp": ..., "A_PDp": ...,
                 "S_r_SDs": ..., "A_SDs": ..., "r": 0.3 (rolling_contact), "c": ..., "U": ... (test)}, ...]}

Joint ``k`` connects ``bodies[parent]`` to ``bodies[k + 1]``.  ``build`` turns it into a tree with the classes of
the ``tree`` module it is given (the student's, the reference's, or a mistaken copy); ``state`` reads every body's
state back in recursion order.  The joint kind ``"test"`` is defined here, on the given module's generic ``Joint``:
a rotation by ``c @ q`` about the Dp 3-axis combined with the translation ``U @ q`` (``c``: nq, ``U``: 3 x nq), so
the generic recursion meets relative translations without any joint type the student writes.
"""

import sys

import numpy as np

from . import module, probe
from ._forms import ANY, Arr, Dict, Items, Maybe, Seq, Text, Tup
from ._effects import fresh_copies, snapshot

__all__ = [
    "QUANTITY",
    "BODIES",
    "STATE",
    "POSES",
    "OUTLINE",
    "POSE",
    "MOTION",
    "CLASSES",
    "build",
    "state",
    "outline",
    "describe",
    "tree_state",
    "mistaken_states",
    "jacobian_differences",
    "path_differences",
    "tree_calls",
]

#: body quantities, in the order the recursion computes them
POSE = ("A_IB", "B_r_IB")
MOTION = ("B_v_B", "B_omega_B", "B_a_B", "B_omegaDot_B", "B_J_S", "B_J_R")
CLASSES = {
    "rotational": "RotationalJoint",
    "translational": "TranslationalJoint",
    "rolling_contact": "RollingContactJoint",
    "virtual_3dof": "Virtual3DOFJoint",
    "rigid": "RigidJoint",
}
_E3 = np.array([0.0, 0.0, 1.0])

#: a body's quantity as the probe reads it back from the student's body (None where not set): numeric, of any shape
#: (the checks compare it with the reference's and say what is wrong with its shape or values)
QUANTITY = Maybe(Arr(any_shape=True, finite=False))
#: the bodies' states (one dict of quantities per body)
BODIES = Seq(Items(QUANTITY))
#: ``state(tree)``: the names, the joints leading to the bodies, the bodies' states
STATE = Dict({"names": Seq(Text()), "bodies": BODIES,
              "joints": Seq(Maybe(Dict({"type": Text(), "predecessor": Text(), "q_index": Arr(None)})))})
#: ``state(tree, motion=False)``: the same, poses only
POSES = STATE
#: the points of a tree's outline (a figure only), or None
OUTLINE = Maybe(Arr(any_shape=True, finite=False))
_TEST_JOINTS = {}


def _rot3(angle):
    """The rotation about the 3-axis by ``angle``, written out here (scipy's ``Rotation`` takes a third of a second
    to import and a tenth of a millisecond a call, in the grader and in every worker)."""
    cos_a, sin_a = float(np.cos(angle)), float(np.sin(angle))
    return np.array([[cos_a, -sin_a, 0.0], [sin_a, cos_a, 0.0], [0.0, 0.0, 1.0]])


def _test_joint(tree):
    """The joint type ``"test"`` on the generic ``Joint`` of ``tree`` (one per class; those of modules no longer
    imported, such as the grader's passing imports of the reference, are let go)."""
    if tree.Joint not in _TEST_JOINTS:
        for joint in [j for j in _TEST_JOINTS if j.__module__ not in sys.modules]:
            del _TEST_JOINTS[joint]

        class TestJoint(tree.Joint):
            def __init__(self, predecessor, successor, *, c, U, **geometry):
                self.c = np.asarray(c, dtype=float).reshape(-1)
                self.nq = self.c.size
                self.U = np.asarray(U, dtype=float).reshape(3, self.nq)
                super().__init__(predecessor, successor, **geometry)

            def joint_pose(self, q):
                return _rot3(self.c @ q), self.U @ q

            def joint_motion(self, q, qd, qdd):
                return tree.JointMotion(self.U @ qd, self.U @ qdd, _E3 * (self.c @ qd), _E3 * (self.c @ qdd),
                                        self.U.copy(), np.outer(_E3, self.c))

        _TEST_JOINTS[tree.Joint] = TestJoint
    return _TEST_JOINTS[tree.Joint]


def build(tree, description):
    """A ``KinematicTree`` of the classes of ``tree`` (a module or namespace) from a plain-data description."""
    bodies = [tree.Body(body["name"], float(body.get("m", 0.0))) for body in description["bodies"]]
    for k, joint in enumerate(description["joints"]):
        geometry = {key: np.asarray(joint[key], dtype=float) for key in ("P_r_PDp", "A_PDp", "S_r_SDs", "A_SDs")}
        kind = joint["kind"]
        if kind == "test":
            cls, extra = _test_joint(tree), {"c": joint["c"], "U": joint["U"]}
        else:
            cls = getattr(tree, CLASSES[kind])
            extra = {"r": float(joint["r"])} if kind == "rolling_contact" else {}
        cls(bodies[int(joint["parent"])], bodies[k + 1], q_index=[int(i) for i in joint["q_index"]], **geometry,
            **extra)
    return tree.KinematicTree(bodies[0])


def describe(tree_module, tree):
    """The plain-data description of a built tree (the inverse of ``build``) whose joints are of the joint types of
    ``tree_module``."""
    kinds = {getattr(tree_module, name): kind for kind, name in CLASSES.items()}
    index = {id(body): k for k, body in enumerate(tree.bodies)}
    joints = []
    for body in tree.bodies[1:]:
        joint = body.parent_joint
        entry = {"kind": kinds[type(joint)], "parent": index[id(joint.predecessor)],
                 "q_index": [int(i) for i in np.reshape(joint.q_index, -1)]}
        entry.update({key: np.array(getattr(joint, key), dtype=float)
                      for key in ("P_r_PDp", "A_PDp", "S_r_SDs", "A_SDs")})
        if entry["kind"] == "rolling_contact":
            entry["r"] = float(joint.r)
        joints.append(entry)
    return {"bodies": [{"name": body.name, "m": float(body.m)} for body in tree.bodies], "joints": joints}


def _plain(value):
    return None if value is None else np.array(value, dtype=float)


def state(tree, motion=True):
    """``{"names", "joints", "bodies"}``: per body (recursion order) its quantities as arrays (``None`` where not
    set) and a short description of the joint leading to it."""
    names = POSE + MOTION if motion else POSE
    joints = []
    for body in tree.bodies:
        joint = body.parent_joint
        joints.append(None if joint is None else {
            "type": type(joint).__name__,
            "predecessor": joint.predecessor.name,
            "q_index": [int(i) for i in np.reshape(joint.q_index, -1)],
        })
    return {
        "names": [body.name for body in tree.bodies],
        "joints": joints,
        "bodies": [{name: _plain(getattr(body, name)) for name in names} for body in tree.bodies],
    }


def outline(tree, start=None):
    """Inertial points of one line through the tree below ``start`` (default: the root), depth first and back: for
    every joint predecessor -> Dp -> Ds -> successor (the segments of ``tree_lines``); ``None`` if the bodies'
    states cannot be drawn."""
    points = []

    def visit(body):
        A_IB = np.asarray(body.A_IB, dtype=float)
        here = A_IB @ np.asarray(body.B_r_IB, dtype=float).reshape(3)
        points.append(here)
        for joint in body.child_joints:
            child = joint.successor
            A_IS = np.asarray(child.A_IB, dtype=float)
            Dp = here + A_IB @ joint.P_r_PDp
            Ds = A_IS @ np.asarray(child.B_r_IB, dtype=float).reshape(3) + A_IS @ joint.S_r_SDs
            points.extend([Dp, Ds])
            visit(child)
            points.extend([Ds, Dp, here])

    try:
        visit(tree.root if start is None else start)
    except (TypeError, ValueError):
        return None
    return np.array(points)


@probe(returns=STATE, says="forward_kinematics of the tree")
def tree_state(pkg, description, q, qd=None, qdd=None):
    """The state of the described tree, built with the package's classes, after ``forward_kinematics``."""
    tree = build(module(pkg, "tree"), description)
    tree.forward_kinematics(np.asarray(q, dtype=float), *(() if qd is None else (qd, qdd)))
    return state(tree, motion=qd is not None)


def _same_bodies(bodies, others):
    """True if two lists of body states hold the same quantities, equal to 1e-12."""
    mine = [value for body in bodies for value in body.values()]
    theirs = [value for body in others for value in body.values()]
    if len(mine) != len(theirs) or any((a is None) != (b is None) for a, b in zip(mine, theirs)):
        return False
    a = np.concatenate([np.ravel(value) for value in mine if value is not None] or [np.zeros(0)])
    b = np.concatenate([np.ravel(value) for value in theirs if value is not None] or [np.zeros(0)])
    return a.shape == b.shape and (a.size == 0 or float(np.max(np.abs(a - b))) <= 1e-12)


@probe(reference_only=True)
def mistaken_states(pkg, specs, description, q, qd=None, qdd=None):
    """The bodies' states (``state(...)["bodies"]``) of the described tree as a recursion with a known mistake
    computes them, one per mistake ``spec`` (see ``mistaken_classes`` of the package's ``tree_mistakes`` module,
    which only the reference has); ``None`` where the mistake cannot be computed or changes nothing on this tree."""
    mistakes = module(pkg, "tree_mistakes")
    correct = tree_state(pkg, description, q, qd, qdd)["bodies"]
    found = []
    for spec in specs:
        try:
            tree = build(mistakes.mistaken_classes(spec), description)
            tree.forward_kinematics(np.asarray(q, dtype=float), *(() if qd is None else (qd, qdd)))
        except (ValueError, IndexError, np.linalg.LinAlgError):
            found.append(None)
            continue
        bodies = state(tree, motion=qd is not None)["bodies"]
        found.append(None if _same_bodies(bodies, correct) else bodies)
    return found


@probe(returns=Dict({"state": STATE, "shifted": Seq(Tup(BODIES, BODIES))}), says="forward_kinematics of the tree")
def jacobian_differences(pkg, description, q, h):
    """The full state at ``q`` (at rest) and the poses at ``q +- h e_i`` for every coordinate ``i``."""
    tree = build(module(pkg, "tree"), description)
    q = np.asarray(q, dtype=float)
    zero = np.zeros(q.size)
    tree.forward_kinematics(q, zero, zero)
    at = state(tree)
    shifted = []
    for i in range(q.size):
        pair = []
        for sign in (1.0, -1.0):
            tree.forward_kinematics(q + sign * h * np.eye(q.size)[i])
            pair.append(state(tree, motion=False)["bodies"])
        shifted.append(pair)
    return {"state": at, "shifted": shifted}


@probe(returns=Tup(STATE, STATE, STATE), says="forward_kinematics of the tree")
def path_differences(pkg, description, q, qd, qdd, h):
    """Full states at ``t = -h, 0, +h`` along ``q(t) = q + qd t + qdd t^2 / 2``."""
    tree = build(module(pkg, "tree"), description)
    q, qd, qdd = (np.asarray(v, dtype=float) for v in (q, qd, qdd))
    states = []
    for t in (-h, 0.0, h):
        tree.forward_kinematics(q + qd * t + 0.5 * qdd * t * t, qd + qdd * t, qdd)
        states.append(state(tree))
    return states


@probe(
    returns=Dict({"first": STATE, "second": STATE, "fresh_second": STATE, "again": STATE, "args_after": Seq(ANY)}),
    says="forward_kinematics of the tree",
)
def tree_calls(pkg, description, first, second):
    """One tree of the described bodies, built once: ``forward_kinematics(*first)``, then ``(*second)``, then
    ``(*first)`` again (each a tuple ``(q[, qd, qdd])`` on fresh copies), and a fresh tree at ``second``:

    ``{"first", "second", "fresh_second", "again"}`` (the states, see ``_trees.state``) and ``"args_after"`` (the
    first call's arguments after it returned)."""
    tree_module = module(pkg, "tree")
    tree = build(tree_module, description)
    motion = len(first) > 1
    args = fresh_copies(first)
    tree.forward_kinematics(*args)
    at_first = state(tree, motion)
    args_after = snapshot(args)
    tree.forward_kinematics(*fresh_copies(second))
    at_second = state(tree, motion)
    fresh = build(tree_module, description)
    fresh.forward_kinematics(*fresh_copies(second))
    tree.forward_kinematics(*fresh_copies(first))
    return {"first": at_first, "second": at_second, "fresh_second": state(fresh, motion), "again": state(tree, motion),
            "args_after": args_after}
