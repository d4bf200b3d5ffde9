"""Models: a MuJoCo model of the student's compared with the reference's, element by element.

The checks of Exercise I compare what a student's compiled model declares (``probes._mjcf.describe``: gravity, the
bodies' masses, centres of mass and inertias, the joints' anchors and axes, the actuators, the initial state) with
numbers of the sheet or with the reference's analytic values, so the compared value has no reference call behind
it.  Its source is the student's call of a model probe; the reference's model comes from the same probe on the same
arguments.  The two descriptions are matched element by element (bodies and joints by their order in the tree,
which must be the same: the same parents, the same joint types) and the differences are told only where one story
holds them all, and the compared value is among them:

* a body and the bodies it carries moved by one translation, nothing else changed: the body's ``pos`` (an offset;
  where the body sits along the lever from its parent's joint at a factor of the grammar of the reference's
  distance, half the link's length for the whole, a scale as much; where it sits at the lever's opposite, behind
  its parent's joint, a sign as much; where its lever from the parent's joint has the reference's coordinates
  along other axes, its position's coordinates in the wrong order as much);
* a body and the bodies it carries turned about its joint by one angle (centres of mass, anchors, axes and
  inertias alike), nothing else changed but the joints' initial angles: where the reference's body starts
  unturned relative to its parent, the model built in another configuration (its ``euler`` or its keyframe);
  where it starts turned by an angle (a configuration the model is given), the slip of that angle's value that
  gives the student's turn (its sign, degrees, a factor), else nothing;
* two bodies or more, each turned about its own joint by one slip of its own start angle, every body keeping its own
  structure (in its frame and its parent's): the configuration's angles read as degrees (no ``<compiler
  angle="radian"/>``) or written in degrees, or each negated;
* joints placed elsewhere in their bodies, nothing else changed: every difference is a joint's anchor, each off by
  one vector in its body's frame (a joint's ``pos`` typed wrongly, or written so for every joint by one loop): an
  offset;
* one attribute alone differs (gravity, an axis, a damping, a gear, a site's position in its body): the grammar of
  values on it (a sign, entries exchanged, a factor).

Differences that no one story holds name nothing.  The world positions of sites and of a connect's points follow
from the attributes: they are not compared, but a compared value may be one of them (the point a connect holds,
moved with its site).  What the model does at rest (a four-bar's acceleration) is not compared.
"""

from __future__ import annotations

import numpy as np

from probes import ProbeLookupError, name_of

from ..errors import GraderFault
from ..values import Tol
from .evidence import array_of, at, distinct, Evidence, Hypothesis, within
from .grammar import output_slips

__all__ = ["SAME", "is_model", "model_call", "model_slips", "differences"]

#: two compiled models' numbers agree to this (MuJoCo compiles the same text to the same numbers; a slip moves them
#: far more)
SAME = Tol("a compiled model's numbers", 1e-9, 1e-7)
#: the attributes compared, by element
_BODY = ("mass", "com", "inertia")
_JOINT = ("anchor", "axis", "damping", "armature", "frictionloss", "stiffness")
_ACTUATOR = ("joint", "gear", "unit_torque")
_MODEL = ("gravity", "timestep", "qpos", "qvel")


def is_model(value) -> bool:
    """``value`` is a MuJoCo model's description (``probes._mjcf.describe``), not any result with bodies and joints
    (a tree's description of the course's own classes)."""
    if not isinstance(value, dict) or not {"gravity", "timestep"} <= set(value):
        return False
    bodies, joints = value.get("bodies"), value.get("joints")
    return isinstance(bodies, list) and isinstance(joints, list) \
        and all(isinstance(b, dict) and {"parent", "mass", "com", "inertia"} <= set(b) for b in bodies) \
        and all(isinstance(j, dict) and {"type", "body", "anchor", "axis"} <= set(j) for j in joints)


def model_call(log, student):
    """``(probe, args, description)``: the student's model a compared value came from (``student``: the call found
    behind it, else the check's latest call of the student's code that returned a model), or None."""
    if student is not None and is_model(student.root):
        return _named(student.probe), tuple(student.args), student.root
    for side, probe, args, value in reversed(list(log)):
        if side == "student" and is_model(value):
            return _named(probe), tuple(args), value
    return None


def _named(probe):
    """The probe's name (the log holds the function a check called)."""
    try:
        return name_of(probe)
    except ProbeLookupError:
        return probe


def _same(a, b) -> bool:
    a, b = array_of(a), array_of(b)
    return a is not None and b is not None and a.shape == b.shape and within(a, b, SAME)


def _paths(desc) -> list:
    paths = [(key,) for key in _MODEL if key in desc]
    paths += [("bodies", i, key) for i in range(len(desc["bodies"])) for key in _BODY]
    paths += [("joints", j, key) for j in range(len(desc["joints"])) for key in _JOINT]
    paths += [("actuators", u, key) for u in range(len(desc.get("actuators") or ())) for key in _ACTUATOR]
    paths += [("sites", k, "pos") for k in range(len(desc.get("sites") or ()))]
    return paths


def _derived_paths(desc) -> list:
    """The values that follow from the attributes (the world positions of sites and of a connect's points)."""
    paths = [("sites", k, "world") for k in range(len(desc.get("sites") or ()))]
    paths += [("equalities", i, key) for i in range(len(desc.get("equalities") or ())) for key in ("point1", "point2")]
    return paths


def _alike_trees(mine, theirs) -> bool:
    """The two models have the same tree: bodies with the same parents, joints of the same types on the same bodies,
    as many actuators."""
    if len(mine["bodies"]) != len(theirs["bodies"]) or len(mine["joints"]) != len(theirs["joints"]):
        return False
    if len(mine.get("actuators") or ()) != len(theirs.get("actuators") or ()):
        return False
    if any(int(a["parent"]) != int(b["parent"]) for a, b in zip(mine["bodies"], theirs["bodies"])):
        return False
    if len(mine.get("sites") or ()) != len(theirs.get("sites") or ()) or \
            len(mine.get("equalities") or ()) != len(theirs.get("equalities") or ()):
        return False
    if any(int(a["body"]) != int(b["body"]) for a, b in zip(mine.get("sites") or (), theirs.get("sites") or ())):
        return False
    return all(a["type"] == b["type"] and int(a["body"]) == int(b["body"])
               for a, b in zip(mine["joints"], theirs["joints"]))


def differences(mine, theirs, paths=None) -> list:
    """The paths of the attributes (or of ``paths``) where two models with the same tree differ."""
    return [path for path in (_paths(theirs) if paths is None else paths) if at(theirs, path) is not None
            and not _same(at(mine, path), at(theirs, path))]


def _carried(desc, body: int) -> set:
    """The body ids of ``body`` (an id, 1 for the first moving body) and the bodies it carries."""
    ids = {body}
    for i, entry in enumerate(desc["bodies"], start=1):
        chain, parent = set(), int(entry["parent"])
        while parent > 0 and parent not in chain:
            chain.add(parent)
            parent = int(desc["bodies"][parent - 1]["parent"])
        if body in chain:
            ids.add(i)
    return ids


def _moved_paths(desc, ids: set) -> set:
    """The positions (centres of mass, joint anchors) of the bodies ``ids``."""
    found = {("bodies", i - 1, "com") for i in ids}
    found |= {("joints", j, "anchor") for j, joint in enumerate(desc["joints"]) if int(joint["body"]) in ids}
    return found


def _name(desc, body: int) -> str:
    name = str(desc["bodies"][body - 1].get("name") or "")
    return f'the body "{name}"' if name else f"body {body}"


def _shifted(mine, theirs, body: int, differing: list):
    """The translation that moves ``body`` and the bodies it carries from the reference's model to the student's,
    when it holds every difference, else None."""
    ids = _carried(theirs, body)
    moved = _moved_paths(theirs, ids)
    if not set(differing) <= moved:
        return None
    shifts = [np.asarray(at(mine, p), dtype=float) - np.asarray(at(theirs, p), dtype=float) for p in sorted(moved)]
    d = shifts[0]
    if not np.any(np.abs(d) > SAME.atol) or not all(within(s, d, Tol("", 1e-9, 0.0)) for s in shifts):
        return None
    return d


def _rotation(axis, angle) -> np.ndarray:
    """The rotation by ``angle`` about the unit vector ``axis``."""
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(angle) * K + (1.0 - np.cos(angle)) * K @ K


def _turned(mine, theirs, body: int, differing: list):
    """The angle by which ``body`` and the bodies it carries are turned about its joint, from the reference's model
    to the student's, when that holds every difference (the joints' initial angles may differ too), else None."""
    joints = [j for j, joint in enumerate(theirs["joints"]) if int(joint["body"]) == body]
    if len(joints) != 1:
        return None
    pivot = np.asarray(theirs["joints"][joints[0]]["anchor"], dtype=float)
    axis = np.asarray(theirs["joints"][joints[0]]["axis"], dtype=float)
    if not _same(mine["joints"][joints[0]]["anchor"], pivot) or np.linalg.norm(axis) < 0.5:
        return None
    ids = _carried(theirs, body)
    points = sorted(_moved_paths(theirs, ids))
    turned = points + [("bodies", i - 1, "inertia") for i in ids]
    turned += [("joints", j, "axis") for j, joint in enumerate(theirs["joints"]) if int(joint["body"]) in ids]
    if not set(differing) <= set(turned) | {("qpos",), ("qvel",)}:
        return None
    angle = None
    for path in points:
        r = np.asarray(at(theirs, path), dtype=float) - pivot
        s = np.asarray(at(mine, path), dtype=float) - pivot
        r_perp, s_perp = r - axis * (axis @ r), s - axis * (axis @ s)
        if np.linalg.norm(r_perp) > 1e-6 and np.linalg.norm(s_perp) > 1e-6:
            angle = float(np.arctan2(axis @ np.cross(r_perp, s_perp), r_perp @ s_perp))
            break
    if angle is None or abs(angle) < 1e-6:
        return None
    R = _rotation(axis, angle)
    for path in turned:
        ours, theirs_value = np.asarray(at(mine, path), dtype=float), np.asarray(at(theirs, path), dtype=float)
        if path[-1] == "inertia":
            expected = R @ theirs_value @ R.T
        elif path[-1] == "axis":
            expected = R @ theirs_value
        else:
            expected = pivot + R @ (theirs_value - pivot)
        if not within(ours, expected, Tol("", 1e-8, 1e-6)):
            return None
    return angle


def _compared(mine, differing: list, got) -> bool:
    """The compared value is (the first entries of) one of the attributes that differ."""
    target = array_of(got)
    if target is None or target.size == 0:
        return False
    for path in differing:
        value = array_of(at(mine, path))
        if value is not None and value.size >= target.size \
                and within(value.ravel()[:target.size], target.ravel(), Tol("", 1e-12, 1e-12)):
            return True
    return False


def _vector(d) -> str:
    return "(" + ", ".join(f"{x:+.4g}" for x in d) + ")"


def model_slips(scene, evidence: Evidence) -> list[Hypothesis] | None:
    """The slips of the student's model that hold every difference from the reference's model on the same arguments,
    where the compared value is one of them (one story, or the grammar of values on a single attribute).  None in
    the student kit where its key does not hold the reference's model (it holds no reference's answer to a call
    asked of the student alone): the graded submission may say more."""
    found = model_call(getattr(scene.ctx, "calls", ()), evidence.student)
    if found is None or evidence.got is None:
        return []
    probe, args, mine = found
    try:
        theirs = scene.reference(probe, args)
    except GraderFault:
        return None if getattr(scene.ctx.oracle, "mode", "") == "kit" else []
    if not is_model(theirs) or not _alike_trees(mine, theirs):
        return []
    differing = differences(mine, theirs)
    derived = differences(mine, theirs, _derived_paths(theirs))
    if not differing or not _compared(mine, differing + derived, evidence.got):
        return []
    told = []
    for body in range(1, len(theirs["bodies"]) + 1):
        d = _shifted(mine, theirs, body, differing)
        if d is not None:
            told.append(Hypothesis(f"model:moved:{body}", "offset", 1,
                                   f"{_name(theirs, body)} and the bodies it carries sit {_vector(d)} m from where "
                                   "they belong: look at that body's pos"))
            told += _lever_slips(mine, theirs, body) + _axes_slips(mine, theirs, body)
            break
    for body in range(1, len(theirs["bodies"]) + 1):
        angle = _turned(mine, theirs, body, differing)
        if angle is not None:
            told += _angle_slips(theirs, body, angle)
            break
    else:
        told += _turned_each(mine, theirs, differing)
    told += _joints_moved(mine, theirs, differing)
    if len(differing) == 1:
        told += _attribute_slips(mine, theirs, differing[0])
    return told


def _joints_moved(mine, theirs, differing: list) -> list[Hypothesis]:
    """Joints placed elsewhere in their bodies: every difference is a joint's anchor (no body moved, no centre of
    mass), each off by one vector in the frame of the joint's body (a ``pos`` typed wrongly on one joint, or on every
    joint a loop writes): an offset.  Anchors moved each by another vector hold no one story: nothing."""
    if not differing or any(path[0] != "joints" or path[-1] != "anchor" for path in differing):
        return []
    offsets = [_frame(theirs, int(theirs["joints"][path[1]]["body"])).T
               @ (np.asarray(at(mine, path), dtype=float) - np.asarray(at(theirs, path), dtype=float))
               for path in differing]
    d = offsets[0]
    if not all(within(o, d, SAME) for o in offsets):
        return []
    names = [str(theirs["joints"][j].get("name") or f"joint {j + 1}") for _, j, _ in differing]
    which = f'the joint "{names[0]}" sits' if len(names) == 1 else f"the joints {', '.join(names)} each sit"
    return [Hypothesis("model:joints-moved", "offset", 1, f"{which} {_vector(d)} m (in its body's frame) from where "
                       "it belongs in its body, the body itself where it belongs: look at the joint's pos")]


def _pivot(desc, body: int):
    """The anchor of the first joint of ``body`` (the world's origin for the world, 0), or None."""
    if body == 0:
        return np.zeros(3)
    anchors = [joint["anchor"] for joint in desc["joints"] if int(joint["body"]) == body]
    return np.asarray(anchors[0], dtype=float) if anchors else None


def _lever_slips(mine, theirs, body: int) -> list[Hypothesis]:
    """A body moved along the lever from its parent's joint to its own, by a factor of the grammar (half the link's
    length where the whole belongs): a scale as much as an offset; or to the lever's opposite (the length typed
    with a minus, the body hung behind its parent's joint): a sign as much as an offset.  The body's offset is
    what the answer shows, the lever's slip where it was made: both are told."""
    parent = int(theirs["bodies"][body - 1]["parent"])
    ends = [_pivot(desc, b) for desc in (theirs, mine) for b in (parent, body)]
    if any(end is None for end in ends):
        return []
    r, s = ends[1] - ends[0], ends[3] - ends[2]
    if np.linalg.norm(r) < 1e-6:
        return []
    kept = []
    for hypothesis, value in output_slips(r, {}, None):
        if (hypothesis.key.startswith("scale") or hypothesis.key == "sign") \
                and within(s, np.asarray(value, dtype=float), SAME):
            kept.append(Hypothesis(f"model:lever:{body}:{hypothesis.key}", hypothesis.name, hypothesis.cost,
                                   f"{_name(theirs, body)} sits on its parent at {_vector(s)} m from the parent's "
                                   f"joint, where the reference's sits at {_vector(r)}: "
                                   f"{hypothesis.detail.removeprefix('your value is ')}"))
    return kept


def _axes_slips(mine, theirs, body: int) -> list[Hypothesis]:
    """A body placed on its parent along other axes (``pos="0 L 0"`` where ``"L 0 0"`` belongs): the lever from its
    parent's joint to its own has the reference's coordinates in the parent's frame, each where another belongs (a
    sign may change with it), not the reference's lever moved or stretched: its coordinates in the wrong order as
    much as an offset."""
    parent = int(theirs["bodies"][body - 1]["parent"])
    ends = [_pivot(desc, b) for desc in (theirs, mine) for b in (parent, body)]
    if any(end is None for end in ends):
        return []
    frame = _frame(theirs, parent)  # the parent is where it belongs: the levers in its frame
    r, s = frame.T @ (ends[1] - ends[0]), frame.T @ (ends[3] - ends[2])
    if np.linalg.norm(r) < 1e-6 or not _permuted(np.abs(r), np.abs(s)):
        return []
    return [Hypothesis(f"model:axes:{body}", "coordinate_order", 1,
                       f"{_name(theirs, body)} sits on its parent at {_vector(s)} m from the parent's joint (in "
                       f"the parent's frame), where the reference's sits at {_vector(r)}: the same lengths along "
                       "other axes (its position's coordinates in the wrong order)")]


def _frame(desc, body: int) -> np.ndarray:
    """The orientation of ``body`` in the world (the identity for the world, 0, and where the description holds
    none)."""
    frame = desc["bodies"][body - 1].get("frame") if body > 0 else None
    return np.eye(3) if frame is None else np.asarray(frame, dtype=float)


def _permuted(r: np.ndarray, s: np.ndarray) -> bool:
    """``s`` holds the entries of ``r`` in another order: the same entries, not each in its own place."""
    tol = Tol("", SAME.atol, SAME.rtol)
    return within(np.sort(s), np.sort(r), tol) and not within(s, r, tol)


def _angle(R, axis) -> float:
    """The angle of the rotation ``R`` about ``axis`` (a unit vector of its own)."""
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    sin = 0.5 * k @ np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    cos = 0.5 * (np.trace(R) - 1.0 - (1.0 - k @ R @ k))
    return float(np.arctan2(sin, cos))


def _wrapped(a: float) -> float:
    return float((a + np.pi) % (2 * np.pi) - np.pi)


def _start_angle(desc, body: int):
    """The angle by which ``body`` is turned about its joint relative to its parent at the start (from the bodies'
    orientations), or None where the description has none or the turn is not about the joint's axis."""
    entry = desc["bodies"][body - 1]
    parent = int(entry["parent"])
    frames = [np.eye(3) if b == 0 else array_of(desc["bodies"][b - 1].get("frame")) for b in (parent, body)]
    axes = [joint["axis"] for joint in desc["joints"] if int(joint["body"]) == body]
    if any(f is None or f.shape != (3, 3) for f in frames) or not axes:
        return None
    R = frames[0].T @ frames[1]
    axis = frames[0].T @ np.asarray(axes[0], dtype=float)
    angle = _angle(R, axis)
    if not within(R, _rotation(axis, angle), Tol("", 1e-6, 0.0)):
        return None
    return angle


#: the angles a body may start turned by where the reference's starts turned by ``q`` (a slip of the angle's value)
_ANGLE_SLIPS = (
    ("sign_flip", lambda q: -q, "the angle with the opposite sign"),
    ("degrees", lambda q: np.degrees(q), "the angle in degrees where MuJoCo reads radians"),
    ("degrees", lambda q: np.radians(q), "the angle converted to radians once too often"),
    ("factor_two", lambda q: 2 * q, "twice the angle"),
    ("factor_half", lambda q: q / 2, "half the angle"),
)


def _angle_slips(theirs, body: int, turn: float) -> list[Hypothesis]:
    """A body turned by ``turn`` about its joint: where the reference's body starts unturned relative to its parent,
    the model is built in another configuration; where it starts turned by an angle (a configuration given), the
    slip of that angle's value that gives the student's (none: nothing is told)."""
    q = _start_angle(theirs, body)
    if q is None:
        return []
    where = f"{_name(theirs, body)} and the bodies it carries start turned by {np.degrees(turn):+.1f} degrees about "
    if abs(_wrapped(q)) < 1e-6:
        return [Hypothesis(f"model:turned:{body}", "initial_pose", 1, where + "its joint: look at that body's "
                           "orientation (euler) and the keyframe's qpos")]
    mine = q + turn
    return [Hypothesis(f"model:angle:{body}:{name}:{words}", name, 1, where + f"its joint, as with {words} "
                       f"({mine:+.4g} rad where {q:+.4g} rad belongs)")
            for name, slip, words in _ANGLE_SLIPS if abs(_wrapped(slip(q) - mine)) < 1e-6]


#: the angles every body may start turned by where the reference's start turned by their configuration's angles
#: ``q``: one slip of every angle's value, in words
_ANGLES_SLIPS = (
    ("degrees", np.radians, "the angles read as degrees (MuJoCo's default where the model declares no <compiler "
                            "angle=\"radian\"/>), or converted to radians once too often"),
    ("degrees", np.degrees, "the angles written in degrees where the model declares them in radians"),
    ("sign_flip", np.negative, "every angle with the opposite sign"),
)


def _turned_each(mine, theirs, differing: list) -> list[Hypothesis]:
    """Two bodies or more, each turned about its own joint relative to its parent by one slip of its own start angle
    (the configuration's angles read as degrees, say), where the reference's bodies start turned by the
    configuration's angles, and nothing else changed: every body keeps its own structure (mass, centre of mass,
    inertia and joint axis in its own frame, and its joint where it sits in its parent's frame).  One body turned
    alone (and the bodies it carries) is ``_turned``'s."""
    n = len(theirs["bodies"])
    allowed = {("qpos",), ("qvel",)}
    if n < 2 or not differing or not all(path in allowed or (path[0] == "bodies" and path[-1] in _BODY)
                                         or (path[0] == "joints" and path[-1] in ("anchor", "axis"))
                                         for path in differing):
        return []
    ours = [_start_angle(mine, body) for body in range(1, n + 1)]
    refs = [_start_angle(theirs, body) for body in range(1, n + 1)]
    if any(a is None for a in ours + refs) or not all(_kept_structure(mine, theirs, b) for b in range(1, n + 1)):
        return []
    if sum(abs(_wrapped(a - b)) > 1e-6 for a, b in zip(ours, refs)) < 2:
        return []
    return [Hypothesis(f"model:angles:{name}", name, 1, f"every body starts turned about its joint by another angle "
                       f"than its own ({', '.join(f'{a:+.4g}' for a in ours)} rad where "
                       f"{', '.join(f'{b:+.4g}' for b in refs)} rad belong), as with {words}")
            for name, slip, words in _ANGLES_SLIPS
            if all(abs(_wrapped(float(slip(b)) - a)) < 1e-6 for a, b in zip(ours, refs))]


def _kept_structure(mine, theirs, body: int) -> bool:
    """``body`` has the same mass, centre of mass, inertia and joint axis in its own frame in both models, and its
    joint sits where it does in its parent's frame (relative to the parent's joint, or the world's origin)."""
    def local(desc):
        F, P = _frame(desc, body), _frame(desc, int(desc["bodies"][body - 1]["parent"]))
        entry, anchor = desc["bodies"][body - 1], _pivot(desc, body)
        parent = _pivot(desc, int(entry["parent"]))
        axes = [joint["axis"] for joint in desc["joints"] if int(joint["body"]) == body]
        if anchor is None or parent is None or len(axes) != 1:
            return None
        return [np.atleast_1d(np.asarray(entry["mass"], dtype=float)),
                F.T @ (np.asarray(entry["com"], dtype=float) - anchor),
                F.T @ np.asarray(entry["inertia"], dtype=float) @ F,
                F.T @ np.asarray(axes[0], dtype=float), P.T @ (anchor - parent)]

    a, b = local(mine), local(theirs)
    return a is not None and b is not None and all(within(x, y, SAME) for x, y in zip(a, b))


def _attribute_slips(mine, theirs, path) -> list[Hypothesis]:
    """The grammar of values on the one attribute that differs."""
    ours, expected = array_of(at(mine, path)), array_of(at(theirs, path))
    if ours is None or expected is None or ours.shape != expected.shape:
        return []
    what = " ".join(str(k if isinstance(k, str) else k + 1) for k in path)
    kept = []
    for hypothesis, value in output_slips(expected, {}, None):
        value = array_of(value)
        if value is not None and value.shape == ours.shape and within(ours, value, SAME) \
                and distinct(value, expected, SAME):
            kept.append(Hypothesis(f"model:{'/'.join(map(str, path))}:{hypothesis.key}", hypothesis.name,
                                   hypothesis.cost, f"{hypothesis.detail} (the model's {what})", hypothesis.twin))
    return kept

