"""Shared checks of the kinematic-tree problems (24, 25, 31-35).

* Random trees as plain data (``trees``, ``cases``, from the case factory ``checks._cases``): random joint types,
  parents, offsets, joint-frame orientations (rotations from random unit quaternions), coordinate numbering, ``q``,
  ``qd``, ``qdd``.  The probe builds the same description with the student's classes and, in the grader, with the
  reference's.
* Known mistakes (``Model``, ``MODELS``): switches of the reference's recursion, joint types with a mistake, or an
  edit of the tree's description.  ``candidates`` asks the reference (probe ``_trees.mistaken_states``) for the
  state a student with each mistake computes on a case, eagerly, from the case alone.
* ``compare_states`` names the first body, in recursion order from the root, and the first quantity where the
  student's kinematics depart from the reference; ``compare_jacobians`` and ``compare_path`` check the student's
  Jacobians, velocities and accelerations against finite differences of the student's own kinematics.
"""

from dataclasses import dataclass

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    CheckFailure,
    Mistake,
    Tol,
    as_array,
    assert_close,
    assert_rotation,
    close,
    fail,
    figure,
    format_array,
)
from probes import _trees as probe_trees

from ._cases import (
    NQ,
    SEEDS,
    case_strategy,
    coordinate_count,
    draw_tree,
    joint_lines,
    random_frames,
    rich_joints,
    rich_values,
)
from ._effects import MUTATION_HINT, same, shown
from ._shapes import as_dict, as_list
from ._upstream import judging

__all__ = [
    "H",
    "KINEMATIC_DIFFERENCES",
    "ORDER",
    "trees",
    "cases",
    "rich_case",
    "compare_fixed",
    "compare_trees",
    "describe_case",
    "Model",
    "MODELS",
    "candidates",
    "bodies_of",
    "bodies_list",
    "assert_visited",
    "compare_states",
    "tree_comparison",
    "compare_jacobians",
    "compare_path",
    "compare_jacobian_differences",
    "compare_path_differences",
    "judged_states",
    "configuration_figure",
    "assert_tree_no_side_effects",
]

#: step of the finite differences (central differences: error ~ h^2)
H = 1e-5
#: a derivative of the student's own kinematics (a Jacobian, velocities and accelerations, the gradient of a
#: potential) against central differences of their own positions and orientations, of order one
KINEMATIC_DIFFERENCES = Tol("finite differences, h = 1e-5", 1e-6, 1e-6)
#: the body quantities in the order the recursion computes them
ORDER = probe_trees.POSE + probe_trees.MOTION

# ------------------------------------------------------------------------------------------ random trees


def _geometry(seed, kind, nq):
    """A joint's offsets and frames (with ``r``, or ``c`` and ``U``, for its kind) and its successor's mass from
    ``seed``; seed 0 gives the plainest joint: no offsets, aligned frames."""
    if seed == 0:
        joint = {"P_r_PDp": np.zeros(3), "A_PDp": np.eye(3), "S_r_SDs": np.zeros(3), "A_SDs": np.eye(3)}
        r, c, U, m = 0.5, np.eye(1, nq).ravel(), np.eye(3, nq, 1), 1.0
    else:
        rng = np.random.default_rng(seed)
        joint = random_frames(rng)
        r, c, U, m = rng.uniform(0.1, 1.0), rng.uniform(-1.5, 1.5, nq), rng.uniform(-1, 1, (3, nq)), rng.uniform(0.1, 5)
    if kind == "rolling_contact":
        joint["r"] = float(r)
    if kind == "test":
        joint.update(c=c, U=U)
    return joint, float(m)


@st.composite
def trees(draw, kinds, max_joints=4, masses=False):
    """Tree descriptions: two to ``max_joints`` joints of the given ``kinds`` (``"test"`` is the probe's own joint),
    each hanging at a random earlier body (shrinking towards a chain) with random offsets and joint frames (drawn
    from a seed per joint, shrinking towards aligned frames without offsets); the coordinates are numbered in a
    random order.  The first joint moves, so ``nq >= 1``."""

    def member(draw, k, kind):
        nq = draw(st.integers(1, 2)) if kind == "test" else NQ[kind]
        geometry, mass = _geometry(draw(SEEDS), kind, nq)
        return geometry, {"name": f"body_{k + 1}", "m": mass if masses else 1.0}, nq

    return draw_tree(draw, kinds, st.integers(min(2, max_joints), max_joints),
                     lambda draw: {"name": "body_0", "m": 1.0}, member)


def cases(kinds, motion=True, masses=False, extra=()):
    """``(description, q[, qd, qdd], *extra)`` with coordinates, velocities and accelerations in [-2, 2] (each
    drawn from a seed, shrinking towards zero)."""
    return case_strategy(trees(kinds, masses=masses), 3 if motion else 1, extra)


def _rich_geometry(rng, kind):
    joint = random_frames(rng)
    if kind == "rolling_contact":
        joint["r"] = 0.4
    if kind == "test":
        joint["c"], joint["U"] = rng.uniform(0.5, 1.5, 2) * [1, -1], rng.uniform(-1, 1, (3, 2))
    return joint


def rich_case(kinds, motion=True, masses=False, extra=(), seed=24):
    """A fixed case in the format of ``cases`` that exercises every term: a chain through all ``kinds`` (after a
    first joint of ``kinds[0]``) plus a branch at body 1, random geometry, coordinates numbered in random order and
    values bounded away from zero."""
    rng = np.random.default_rng(seed)
    joints = rich_joints(rng, kinds, _rich_geometry, lambda kind: NQ.get(kind, 2))
    bodies = [{"name": f"body_{k}", "m": float(rng.uniform(0.5, 3.0)) if masses else 1.0}
              for k in range(len(joints) + 1)]
    n = coordinate_count({"joints": joints})
    return ({"bodies": bodies, "joints": joints}, *rich_values(rng, n, 3 if motion else 1), *extra)


def compare_fixed(ctx, probe, args, compare, describe=None):
    """``compare`` the student's and the reference's ``probe`` on one fixed case; a failure names the case."""
    got = ctx.student(probe, *args)
    expected = ctx.reference(probe, *args)
    try:
        compare(got, expected, args)
    except CheckFailure as exc:
        first, _, rest = exc.message.partition("\n")
        shown = (describe or describe_case)(args)
        raise CheckFailure(f"{first}\non the fixed case {shown}\n{rest}", exc.hint, exc.diagnosis, exc.candidates,
                           exc.evidence) from None


def compare_trees(ctx, probe, kinds, compare, motion=True, masses=False, extra=(), examples=15, name="the tree"):
    """``compare`` on the fixed rich case, then on random trees of the given ``kinds``; where it fails on the
    student's own shared functions of earlier problems (their ``R3`` inside every rotational joint), the states are
    judged on what the reference's recursion makes of them (error carried forward, ``checks._upstream``)."""
    compare = judging(ctx, probe, compare, judged_states)
    compare_fixed(ctx, probe, rich_case(kinds, motion, masses, extra), compare)
    ctx.compare_random(probe, cases(kinds, motion, masses, extra), name=name, tol=EXACT, compare=compare,
                       examples=examples, describe=describe_case)


def _compact(a):
    """Short text of a vector or matrix; a rotation as ``cardan(alpha, beta, gamma)`` (``R3 R2 R1``)."""
    a = np.asarray(a, dtype=float)
    if a.shape == (3, 3) and np.allclose(a, np.eye(3)):
        return "E"
    if a.shape == (3, 3) and np.allclose(a.T @ a, np.eye(3)) and np.linalg.det(a) > 0 and abs(a[2, 0]) < 1.0:
        # a proper rotation with cos(beta) != 0 has exactly these Cardan angles
        angles = np.arctan2(a[2, 1], a[2, 2]), -np.arcsin(a[2, 0]), np.arctan2(a[1, 0], a[0, 0])
        return "cardan({:.4f}, {:.4f}, {:.4f})".format(*angles)
    return " ".join(format_array(a).split())


def describe_case(args):
    """A readable description of ``(description, q, ...)``."""
    description, *values = args
    lines = [f"a tree of {len(description['bodies'])} bodies (joint k leads to body_k):",
             *joint_lines(description, _compact)]
    for label, value in zip(("q", "qd", "qdd"), values):
        if isinstance(value, np.ndarray):
            lines.append(f"  {label} = {_compact(value)}")
    return "\n".join(lines)


# ------------------------------------------------------------------------------------------ known mistakes


@dataclass(frozen=True)
class Model:
    """A known mistake: switches of the reference's generic recursion (``pose``, ``motion``, ``jacobians``: pairs
    of keyword arguments of its mistaken ``successor_pose``, ``successor_motion``, ``successor_jacobians``), a joint
    type with a mistake (``joint``: a name of the reference's joint mistakes), or an ``edit`` of the tree's
    description (computed with the correct recursion)."""

    name: str
    hint: str
    pose: tuple = ()
    motion: tuple = ()
    jacobians: tuple = ()
    joint: str = ""
    edit: object = None


#: the joint type each joint mistake changes, and whether it changes positions (or only the motion)
_JOINT_KINDS = {"rotational_sign": ("rotational", True), "rolling_motion_sign": ("rolling_contact", False),
                "rolling_wrong_way": ("rolling_contact", True), "virtual_order": ("virtual_3dof", True)}


def _spec(model):
    """The model's mistake as plain data for the probe ``_trees.mistaken_states``."""
    spec = {key: dict(value) for key, value in (("pose", model.pose), ("motion", model.motion),
                                                 ("jacobians", model.jacobians)) if value}
    return {**spec, "joint": model.joint} if model.joint else spec


def _relevant(model, description, motion):
    """False when the mistake cannot change this case (a joint type the tree does not have, or a mistake of the
    velocities on a positions-only pass)."""
    if model.joint:
        kind, in_pose = _JOINT_KINDS[model.joint]
        return any(joint["kind"] == kind for joint in description["joints"]) and (motion or in_pose)
    return motion or bool(model.pose) or model.edit is not None


_RECURSION = ("A_IS = A_IP A_PDp A_DpDs A_SDs.T, S_r_IS = A_SDs A_DpDs.T (A_PDp.T (P_r_IP + P_r_PDp) + Dp_r_DpDs) "
              "- S_r_SDs")
_DS_A = ("Ds_a = A_DpDs.T (Dp_a + r_rel_ddot + 2 skew(Dp_omega) r_rel_dot + (skew(Dp_omegaDot) + skew(Dp_omega)^2) "
         "r_rel)")
MODELS = (
    Model("transpose", "The joint frame Dp is applied the wrong way round: A_PDp maps Dp- to P-coordinates, so "
          "A_IDp = A_IP @ A_PDp and Dp_r_IDp = A_PDp.T @ (P_r_IP + P_r_PDp). You used its transpose A_DpP where "
          "A_PDp belongs (Joint.successor_pose, problem 24).", pose=(("transpose", True),)),
    Model("transpose", "The joint frame Ds is applied the wrong way round: A_SDs maps Ds- to S-coordinates, so "
          "A_IS = A_IDs @ A_SDs.T and S_r_IS = A_SDs @ Ds_r_IDs - S_r_SDs (Joint.successor_pose, problem 24).",
          pose=(("ds_transpose", True),)),
    *(Model("rotation_order", "The rotations are multiplied in the wrong order: adjacent frame letters cancel, "
            "A_IDs = A_IDp @ A_DpDs and A_IS = A_IP @ A_PDp @ A_DpDs @ A_SDs.T; each new rotation multiplies from "
            "the right (Joint.successor_pose, problem 24).", pose=(("reverse", which),)) for which in ("joint", "all")),
    Model("offset_sign", "S_r_SDs is added where it must be subtracted: it points from the body's origin S to Ds, "
          "so S_r_IS = A_SDs @ Ds_r_IDs - S_r_SDs (Joint.successor_pose, problem 24).", pose=(("offset_sign", 1.0),)),
    Model("offset_frame", "P_r_PDp is given in P-coordinates: add it to P_r_IP before rotating into Dp, "
          "Dp_r_IDp = A_PDp.T @ (P_r_IP + P_r_PDp); you added it after the rotation (Joint.successor_pose, "
          "problem 24).", pose=(("offset_in_dp", True),)),
    Model("sign_flip", "The rotational joint turns the wrong way: A_DpDs = R3(gamma), a counter-clockwise rotation "
          "about the Dp 3-axis; you have R3(-gamma) = R3(gamma).T (RotationalJoint.joint_pose, problem 24).",
          joint="rotational_sign"),
    Model("rolling_sign", "The rolling contact's relative motion has the wrong sign: r_rel_dot = (-r gamma_dot, 0, "
          "0), r_rel_ddot = (-r gamma_ddot, 0, 0), S = (-r, 0, 0), the derivatives of Dp_r_DpDs = (-r gamma, 0, 0) "
          "(RollingContactJoint.joint_motion, problem 33).", joint="rolling_motion_sign"),
    Model("rolling_sign", "The rolling contact moves the wrong way: a circle turning counter-clockwise by gamma "
          "without slipping rolls towards -x, Dp_r_DpDs = (-r gamma, 0, 0) (RollingContactJoint.joint_pose, "
          "problem 25).", joint="rolling_wrong_way"),
    Model("coordinate_order", "The virtual 3-DOF joint's coordinates are q = (dx, dy, gamma): A_DpDs = R3(q[2]), "
          "Dp_r_DpDs = (q[0], q[1], 0), S = [e1 e2 0], R = [0 0 e3] (Virtual3DOFJoint, problem 34).",
          joint="virtual_order"),
    Model("missing_coriolis", f"The Coriolis term 2 skew(Dp_omega) r_rel_dot is missing: {_DS_A} "
          "(Joint.successor_motion, problem 31).", motion=(("coriolis", 0.0),)),
    Model("coriolis_factor", f"The Coriolis term needs the factor 2: {_DS_A}. One skew(Dp_omega) r_rel_dot comes from "
          "differentiating r_rel in the rotating frame Dp, the other from differentiating skew(Dp_omega) r_rel "
          "(Joint.successor_motion, problem 31).", motion=(("coriolis", 1.0),)),
    Model("transport", "The angular acceleration misses skew(Dp_omega) omega_rel: the relative angular velocity "
          "turns with Dp, Ds_omegaDot = A_DpDs.T (Dp_omegaDot + omega_rel_dot + skew(Dp_omega) omega_rel) "
          "(Joint.successor_motion, problem 31).", motion=(("transport", 0.0),)),
    Model("missing_centripetal", "Moving the predecessor's acceleration to Dp misses the centripetal term: "
          "Dp_a = A_PDp.T (P_a + (skew(P_omegaDot) + skew(P_omega)^2) P_r_PDp) (Joint.successor_motion, problem 31).",
          motion=(("centripetal_dp", 0.0),)),
    Model("missing_centripetal", "Moving the acceleration from Ds to the body misses the centripetal term: "
          "S_a = A_SDs Ds_a - (skew(S_omegaDot) + skew(S_omega)^2) S_r_SDs (Joint.successor_motion, problem 31).",
          motion=(("centripetal_ds", 0.0),)),
    Model("offset_sign", "S_r_SDs enters the velocities with a minus sign (it points from S to Ds): S_v = A_SDs Ds_v "
          "- skew(S_omega) S_r_SDs, S_a = A_SDs Ds_a - (skew(S_omegaDot) + skew(S_omega)^2) S_r_SDs and S_J_S = ... "
          "+ skew(S_r_SDs) S_J_R (Joint.successor_motion and successor_jacobians, problem 31).",
          motion=(("offset_sign", 1.0),), jacobians=(("offset_sign", 1.0),)),
    Model("transpose", "The predecessor's motion is brought into Dp with A_DpP = A_PDp.T (Dp_omega = A_PDp.T "
          "P_omega, Dp_v = A_PDp.T (P_v + skew(P_omega) P_r_PDp), ...); you used A_PDp (Joint.successor_motion, "
          "problem 31).", motion=(("transpose", True),), jacobians=(("transpose", True),)),
    Model("column_offset", "The joint's columns of the Jacobians are in the wrong place: S and R go into the columns "
          "q_index of the 3 x nq matrices (S_full[:, q_index] = S); yours are shifted by one, and q_index is "
          "0-based (Joint.successor_jacobians, problem 31).", jacobians=(("shift", -1),)),
    Model("column_offset", "The joint's columns of the Jacobians are in the wrong place: S and R go into the columns "
          "q_index of the 3 x nq matrices; yours are shifted by one (Joint.successor_jacobians, problem 31).",
          jacobians=(("shift", 1),)),
    Model("lever", "The translational Jacobian misses the lever of the predecessor's rotation: S_J_S = A_SP (P_J_S "
          "+ A_PDp S - skew(P_r_PDp + A_PDp r_rel) P_J_R) + skew(S_r_SDs) S_J_R (Joint.successor_jacobians, "
          "problem 31).", jacobians=(("lever", 0.0),)),
)

INERTIAL_HINT = ("B_r_IB holds the body's position in B-coordinates (its inertial position is A_IB @ B_r_IB); you "
                 "stored the inertial position. Keep every body quantity in body coordinates "
                 "(Joint.successor_pose, problem 24).")
_GENERIC_HINTS = {
    "A_IB": f"The orientation comes from the pass across the body's parent joint: {_RECURSION}.",
    "B_r_IB": f"The position comes from the pass across the body's parent joint: {_RECURSION}.",
    "B_v_B": "Velocities (problem 31, steps 1, 3, 6): Dp_v = A_PDp.T (P_v + skew(P_omega) P_r_PDp), Ds_v = A_DpDs.T "
             "(Dp_v + r_rel_dot + skew(Dp_omega) r_rel), S_v = A_SDs Ds_v - skew(S_omega) S_r_SDs.",
    "B_omega_B": "Angular velocities (problem 31): Ds_omega = A_DpDs.T (A_PDp.T P_omega + omega_rel), "
                 "S_omega = A_SDs Ds_omega.",
    "B_a_B": f"Accelerations (problem 31, steps 1, 5, 6): Dp_a = A_PDp.T (P_a + (skew(P_omegaDot) + skew(P_omega)^2) "
             f"P_r_PDp), {_DS_A}, S_a = A_SDs Ds_a - (skew(S_omegaDot) + skew(S_omega)^2) S_r_SDs.",
    "B_omegaDot_B": "Angular accelerations (problem 31, step 4): Ds_omegaDot = A_DpDs.T (Dp_omegaDot + omega_rel_dot "
                    "+ skew(Dp_omega) omega_rel), S_omegaDot = A_SDs Ds_omegaDot.",
    "B_J_S": "S_J_S = A_SP (P_J_S + A_PDp S - skew(P_r_PDp + A_PDp r_rel) P_J_R) + skew(S_r_SDs) S_J_R with A_SP = "
             "(A_PDp A_DpDs A_SDs.T).T and the joint's S in the columns q_index (problem 31).",
    "B_J_R": "S_J_R = A_SP (P_J_R + A_PDp R) with A_SP = (A_PDp A_DpDs A_SDs.T).T and the joint's R in the columns "
             "q_index (problem 31).",
}


def candidates(ctx, description, q, qd=None, qdd=None, models=MODELS):
    """``[(name, hint, bodies)]``: the bodies' states that the mistaken recursions compute for this case, asked of
    the reference from the case alone (whatever the student's answer) when a comparison first consults them (see
    ``Context.catalogue``), mistakes that change nothing left out."""
    return ctx.catalogue(lambda: _candidates(ctx, description, q, qd, qdd, models))


def _candidates(ctx, description, q, qd, qdd, models):
    motion = qd is not None
    values = (q,) if qd is None else (q, qd, qdd)
    relevant = [model for model in models if _relevant(model, description, motion)]
    switched = [model for model in relevant if model.edit is None]
    states = ctx.reference(probe_trees.mistaken_states, [_spec(model) for model in switched], description, *values)
    found = list(zip(switched, states))
    found += [(model, ctx.reference(probe_trees.tree_state, model.edit(description), *values)["bodies"])
              for model in relevant if model.edit is not None]
    return [(model.name, model.hint, bodies) for model, bodies in found if bodies is not None]


# ------------------------------------------------------------------------------------------ comparisons


def bodies_of(got, names):
    """The student's body states (dicts) in the order of ``names``; the reply must list exactly these bodies."""
    unreadable = "the probe could not read the tree's bodies back."
    if not isinstance(got, dict) or not isinstance(got.get("bodies"), list) or not isinstance(got.get("names"), list):
        fail(unreadable)
    theirs = got["names"]
    if len(theirs) != len(got["bodies"]) or not all(isinstance(name, str) for name in theirs):
        fail(unreadable)
    mine = dict(zip(theirs, got["bodies"]))
    missing = [name for name in names if name not in mine]
    if missing:
        fail(f"your tree has no bodies named {missing} (it has {list(mine)}).",
             "Keep the body names of the template.")
    if list(theirs) != list(names):
        fail(f"your tree lists its bodies as {list(theirs)}, expected {list(names)} (depth first from the root).",
             "Create the joints in the order of the template: KinematicTree lists the bodies in recursion order.")
    bodies = [mine[name] for name in names]
    if not all(isinstance(body, dict) for body in bodies):
        fail(unreadable)
    return bodies


def bodies_list(value, names, what):
    """A list of body states (dicts) with one entry per body of ``names`` (the probe's states at shifted
    configurations, which carry no names)."""
    bodies = as_list(value, f"the bodies' states {what}", len(names))
    if not all(isinstance(body, dict) for body in bodies):
        fail(f"the bodies' states {what} must be dicts of the bodies' quantities.", diagnosis="shape")
    return bodies


def _with_hint(value, expected, name, tol, mistakes, hint, **kwargs):
    """``assert_close`` that falls back to ``hint`` when no known mistake matches."""
    try:
        return assert_close(value, expected, name, tol, mistakes, **kwargs)
    except CheckFailure as exc:
        if exc.diagnosis or exc.hint or not hint:
            raise
        raise CheckFailure(exc.message, hint, "", exc.candidates, exc.evidence) from None


def _where(expected, k, quantity):
    names = expected["names"]
    joint = expected["joints"][k]
    if joint is None:
        place = f"{names[k]} is the root: it sits at the origin, A_IB = E, at rest"
    else:
        place = (f"{names[k]} hangs at {joint['predecessor']} by a {joint['type']} with q_index "
                 f"{joint['q_index']}")
    before = f"the bodies before it ({', '.join(names[:k])}) agree with the reference" if k else "it is the first body"
    return (f"First departure in recursion order from the root: {quantity} of {names[k]} (body {k + 1} of "
            f"{len(names)}); {before}.\n{place}.")


def _agrees_before(bodies, expected, k, quantity, tol):
    """True if the mistaken ``bodies`` agree with ``expected`` on everything computed before ``quantity`` of body
    ``k`` (where the student's state agrees with the reference too)."""
    for j in range(k + 1):
        for name in ORDER[:ORDER.index(quantity)] if j == k else ORDER:
            value = expected["bodies"][j].get(name)
            if value is not None and not close(bodies[j][name], value, tol):
                return False
    return True


#: the quantities one function of a joint computes (its pose, its motion, its Jacobians): a mistaken recursion
#: whose value vanishes where the student's does is named only where it gives the student's every quantity of that
#: group, in every body
GROUPS = (probe_trees.POSE, probe_trees.MOTION[:4], probe_trees.MOTION[4:])


def _vanishes(value, tol):
    """A mistaken value of zeros: the test case makes the slip's term vanish, and many slips give it alike."""
    try:
        return close(value, np.zeros_like(np.asarray(value, dtype=float)), tol)
    except Exception:  # noqa: BLE001 - a value that cannot be compared is no zero
        return False


def _reproduces(bodies, theirs, quantity, tol):
    """True when the mistaken ``bodies`` give the student's bodies ``theirs`` in every quantity of the group of
    ``quantity`` (``GROUPS``), not only in the one compared: a slip that gives a zero of the student's by the test
    case's chance (a term that vanishes there) and another value elsewhere is not the student's slip."""
    group = next(g for g in GROUPS if quantity in g)
    for mine, body in zip(bodies, theirs):
        for name in group:
            value = mine.get(name)
            if value is None:
                continue
            try:
                if not close(body.get(name), value, tol):
                    return False
            except Exception:  # noqa: BLE001 - a quantity that cannot be compared is not reproduced
                return False
    return True


UNVISITED_HINT = (
    "The recursion must visit every child joint of every body: Body.forward_kinematics loops over ALL of "
    "self.child_joints and each joint recurses into its successor (Joint.forward_kinematics, problem 24). A return "
    "inside that loop, a loop over the first child only, or a walk along one chain leaves the other branches at "
    "their initial state."
)


def _initial(body, motion: bool) -> bool:
    """True when a body's state is still what it is before any pass: no pose (None) or ``A_IB = E, B_r_IB = 0``, and
    no motion (None) or none at all."""
    A, r = body.get("A_IB"), body.get("B_r_IB")
    untouched = (A is None and r is None) or (close(A, np.eye(3), EXACT) and close(r, np.zeros(3), EXACT))
    if not untouched or not motion:
        return untouched
    return all(body.get(q) is None or close(body.get(q), np.zeros_like(np.asarray(body.get(q), dtype=float)), EXACT)
               for q in probe_trees.MOTION)


def assert_visited(bodies, expected_bodies, names, motion=True):
    """Fail when the recursion never reached some bodies: their state is still the initial one where the
    reference's is not (diagnosis ``unvisited_branch``), rather than naming a wrong value or a missing return."""
    unvisited = [k for k in range(1, len(names))
                 if _initial(bodies[k], motion) and not _initial(expected_bodies[k], motion)]
    if unvisited:
        listed = ", ".join(names[k] for k in unvisited)
        fail(f"forward_kinematics never reached {listed}: {'its' if len(unvisited) == 1 else 'their'} state is "
             f"still the initial one (A_IB = E, B_r_IB = 0{', no motion' if motion else ''}), although "
             f"{'its' if len(unvisited) == 1 else 'their'} joints moved the bodies elsewhere.\n"
             f"the bodies in recursion order: {', '.join(names)}", UNVISITED_HINT, "unvisited_branch")


def compare_states(got, expected, tol=EXACT, mistakes=(), context="", poses_from=None, known=True):
    """Fail at the first body (recursion order) and quantity where ``got`` departs from ``expected``; ``mistakes``
    are the mistaken states ``[(name, hint, bodies)]`` of ``candidates`` to diagnose with, beside a position stored
    in inertial coordinates (``known``: False names no known mistake at all).

    ``poses_from = (ctx, check id, what)`` says that the positions and orientations are an earlier problem's work,
    graded by that check: they are not compared here (error carried forward), only the motion is; when the poses
    depart, the check records it (``ctx.carry_forward``)."""
    names = expected["names"]
    bodies = bodies_of(got, names)
    assert_visited(bodies, expected["bodies"], names, motion=any(
        body.get("B_v_B") is not None for body in expected["bodies"]))
    departed = False
    for k, name in enumerate(names):
        ref = expected["bodies"][k]
        for quantity in ORDER:
            if ref.get(quantity) is None:
                continue
            value = bodies[k].get(quantity)
            if value is None:
                fail(f"{quantity} of {name} is not set after forward_kinematics.",
                     "Every pass sets the successor's state from the joint's results (Joint.forward_kinematics).",
                     "none")
            if close(value, ref[quantity], tol):
                continue
            if poses_from is not None and quantity in probe_trees.POSE:
                departed = True
                continue
            found = [Mistake(m_name, state[k][quantity], m_hint)
                     for m_name, m_hint, state in mistakes
                     if _agrees_before(state, expected, k, quantity, tol)
                     and (not _vanishes(state[k][quantity], tol) or _reproduces(state, bodies, quantity, tol))]
            if quantity == "B_r_IB" and known:
                found.append(Mistake("wrong_frame", ref["A_IB"] @ ref["B_r_IB"], INERTIAL_HINT))
            _with_hint(value, ref[quantity], f"{quantity} of {name}", tol, found, _GENERIC_HINTS[quantity],
                       context=context, note=_where(expected, k, quantity))
    if departed:
        ctx, upstream, what = poses_from
        ctx.carry_forward(upstream, what)


def tree_comparison(ctx, motion=True, models=MODELS, poses_from=None):
    """A ``compare`` for ``ctx.compare_random`` on ``(description, q[, qd, qdd])`` cases; the mistaken states of
    each case are asked of the reference before the comparison.  ``poses_from = (check id, what)``: the poses are
    an earlier problem's, judged there (see ``compare_states``)."""
    carried = None if poses_from is None else (ctx, *poses_from)

    def compare(got, expected, args):
        compare_states(got, expected, mistakes=candidates(ctx, *args[:4 if motion else 2], models=models),
                       poses_from=carried)

    return compare


def _same_as(bodies, reference, quantities, tol=EXACT):
    """True when every body's ``quantities`` equal the reference's (the motion is right, whatever the poses)."""
    return all(close(body.get(quantity), ref[quantity], tol) for body, ref in zip(bodies, reference)
               for quantity in quantities if ref.get(quantity) is not None)


def _unskew(W):
    return 0.5 * np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]])


def _pose_of(body, name):
    A = as_array(body.get("A_IB"), f"A_IB of {name}", (3, 3))
    return A, A @ as_array(body.get("B_r_IB"), f"B_r_IB of {name}", (3,))


COLUMN_HINT = ("Your Jacobian's columns are shifted by one against the coordinates: the joint's S and R go into the "
               "columns q_index (0-based) of the 3 x nq matrices (Joint.successor_jacobians, problem 31).")
JACOBIAN_FRAME_HINT = ("Your Jacobian is in inertial coordinates: B_J_S and B_J_R are in body coordinates, "
                       "B_v_B = B_J_S qd (the inertial Jacobian is A_IB @ B_J_S).")


def compare_jacobians(got, expected, h=H, tol=KINEMATIC_DIFFERENCES):
    """Every body's ``B_J_S``, ``B_J_R`` are the derivatives of its own position ``A_IB @ B_r_IB`` and orientation
    ``A_IB`` (``skew(B_J_R[:, i]) = A_IB.T dA_IB/dq_i``), from ``jacobian_differences``; ``expected`` (the
    reference's reply) gives the bodies and the number of coordinates the reply must cover."""
    names = expected["state"]["names"]
    nq = len(expected["shifted"])
    got = as_dict(got, "the reply of the Jacobian probe", ("state", "shifted"))
    bodies = bodies_of(got["state"], names)
    pairs = as_list(got["shifted"], "the poses at q +- h e_i, one pair per coordinate", nq)
    shifted = [[bodies_list(side, names, f"at q {sign} h e_{i + 1}") for side, sign in
                zip(as_list(pair, f"the poses at q +- h e_{i + 1}", 2), "+-")] for i, pair in enumerate(pairs)]
    if _same_as(bodies, expected["state"]["bodies"], ("B_J_S", "B_J_R")):
        return  # the reference's Jacobians: right on their own merit, whatever the poses (judged elsewhere)
    assert_visited(bodies, expected["state"]["bodies"], names)
    for k, name in enumerate(names):
        body = bodies[k]
        A = assert_rotation(body.get("A_IB"), f"A_IB of {name}")
        plus = [_pose_of(pair[0][k], name) for pair in shifted]
        minus = [_pose_of(pair[1][k], name) for pair in shifted]
        J_S = A.T @ np.column_stack([(p[1] - m[1]) / (2 * h) for p, m in zip(plus, minus)]).reshape(3, nq)
        J_R = np.column_stack([_unskew(A.T @ (p[0] - m[0]) / (2 * h)) for p, m in zip(plus, minus)]).reshape(3, nq)
        for quantity, fd, of in (("B_J_S", J_S, "position A_IB @ B_r_IB"), ("B_J_R", J_R, "orientation A_IB")):
            before = f"the bodies before it ({', '.join(names[:k])}) are consistent" if k else "the root"
            _with_hint(body.get(quantity), fd, f"{quantity} of {name}", tol, [
                Mistake("column_offset", np.roll(fd, -1, axis=1), COLUMN_HINT),
                Mistake("column_offset", np.roll(fd, 1, axis=1), COLUMN_HINT),
                Mistake("wrong_frame", A @ fd, JACOBIAN_FRAME_HINT),
            ], _GENERIC_HINTS[quantity], context=f"(expected: the derivative of your own {of} by q, 3 x {nq})",
                note=f"{name} is the first body, in recursion order, whose {quantity} is not the derivative of "
                     f"its own kinematics ({before}).")


_PATH_HINTS = {
    "B_v_B": "Your velocity is not the time derivative of your own position A_IB @ B_r_IB. " + _GENERIC_HINTS["B_v_B"],
    "B_omega_B": "Your angular velocity does not match how your own A_IB turns: skew(B_omega_B) = A_IB.T dA_IB/dt. "
                 + _GENERIC_HINTS["B_omega_B"],
    "B_a_B": "Your acceleration is not the time derivative of your own velocity (in I: d/dt (A_IB B_v_B)). "
             + _GENERIC_HINTS["B_a_B"],
    "B_omegaDot_B": "Your angular acceleration is not the time derivative of your own angular velocity. "
                    + _GENERIC_HINTS["B_omegaDot_B"],
}


def compare_path(got, expected, h=H, tol=KINEMATIC_DIFFERENCES):
    """Along ``q(t)`` (states at ``-h, 0, +h`` from ``path_differences``) every body's velocities are the time
    derivatives of its own pose, and its accelerations those of its own velocities; ``expected`` (the reference's
    reply) gives the bodies the reply must cover."""
    names = expected[1]["names"]
    minus, at, plus = (bodies_of(state, names) for state in as_list(got, "the states at t = -h, 0, +h", 3))
    if _same_as(at, expected[1]["bodies"], tuple(_PATH_HINTS)):
        return  # the reference's motion: right on its own merit, whatever the poses (judged elsewhere)
    assert_visited(at, expected[1]["bodies"], names)
    for k, name in enumerate(names):
        A = assert_rotation(at[k].get("A_IB"), f"A_IB of {name}")

        def rate(quantity):
            def inertial(body):
                A_b = as_array(body.get("A_IB"), f"A_IB of {name}", (3, 3))
                return A_b if quantity is None else A_b @ as_array(body.get(quantity), f"{quantity} of {name}", (3,))

            return (inertial(plus[k]) - inertial(minus[k])) / (2 * h)

        expected_rates = {"B_v_B": A.T @ rate("B_r_IB"), "B_omega_B": _unskew(A.T @ rate(None)),
                          "B_a_B": A.T @ rate("B_v_B"), "B_omegaDot_B": A.T @ rate("B_omega_B")}
        for quantity, fd in expected_rates.items():
            before = f"the bodies before it ({', '.join(names[:k])}) are consistent" if k else "the root"
            _with_hint(at[k].get(quantity), fd, f"{quantity} of {name}", tol, [], _PATH_HINTS[quantity],
                       context="(expected: the time derivative of your own kinematics along q(t) = q + qd t + "
                               "qdd t^2/2)",
                       note=f"{name} is the first body, in recursion order, whose {quantity} is not the time "
                            f"derivative of its own kinematics ({before}).")


def judged_states(got, value, args):
    """The student's tree states against the reference's recursion on the student's own shared functions (see
    ``checks._upstream.judging``): every body's quantities, as ``compare_states`` reads them."""
    compare_states(got, value)


def compare_jacobian_differences(ctx, probe, kinds, examples=10):
    """Jacobians of random trees against finite differences of the student's own positions and orientations."""

    def jacobians(got, expected, args):
        compare_jacobians(got, expected)

    compare = judging(ctx, probe, jacobians, lambda got, value, args: compare_states(got["state"], value["state"]))

    compare_fixed(ctx, probe, rich_case(kinds, motion=False, extra=(H,)), compare)
    ctx.compare_random(probe, cases(kinds, motion=False, extra=(H,)), name="B_J_S, B_J_R", tol=KINEMATIC_DIFFERENCES,
                       compare=compare, examples=examples, describe=describe_case)


def compare_path_differences(ctx, probe, kinds, examples=10):
    """Velocities and accelerations of random trees against time derivatives of the student's own kinematics."""

    def path(got, expected, args):
        compare_path(got, expected)

    compare = judging(ctx, probe, path, lambda got, value, args: [compare_states(a, b) for a, b in zip(got, value)])

    compare_fixed(ctx, probe, rich_case(kinds, extra=(H,)), compare)
    ctx.compare_random(probe, cases(kinds, extra=(H,)), name="velocities and accelerations", tol=KINEMATIC_DIFFERENCES,
                       compare=compare, examples=examples, describe=describe_case)


def configuration_figure(title, got, expected, axes=(0, 1)):
    """The student's tree drawn over the reference's (``outline`` of the probe, projected on two inertial axes), or
    ``None`` if the student's outline cannot be drawn."""
    try:
        mine = np.asarray(got["outline"], dtype=float)
    except (TypeError, ValueError, KeyError):
        return None
    if mine.ndim != 2 or mine.shape[1] != 3 or not np.all(np.isfinite(mine)):
        return None
    ours = np.asarray(expected["outline"], dtype=float)
    i, j = axes
    label = "xyz"
    return figure(title, f"{label[i]} [m]", f"{label[j]} [m]", student=[("configuration", mine[:, i], mine[:, j])],
                  reference=[("configuration", ours[:, i], ours[:, j])], equal_axes=True)


# ------------------------------------------------------------------------------------ side effects


def assert_tree_no_side_effects(ctx, description, first, second):
    """Fail unless ``forward_kinematics`` of a tree leaves its arguments unchanged and a tree used again gives what
    a fresh tree gives (``first``, then ``second``, then ``first``; each ``(q[, qd, qdd])``)."""
    first, second = [np.asarray(v, dtype=float) for v in first], [np.asarray(v, dtype=float) for v in second]
    got = as_dict(ctx.student(probe_trees.tree_calls, description, first, second),
                  "the reply of the side-effect probe (forward_kinematics)",
                  ("first", "second", "fresh_second", "again", "args_after"))
    after = as_list(got["args_after"], "the arguments of forward_kinematics after the call", len(first))
    for name, sent, left in zip(("q", "qd", "qdd"), first, after):
        if not same(sent, left):
            fail(f"forward_kinematics changes its argument {name} in place: the caller's array is not the same after "
                 f"the call.\npassed:\n{shown(sent)}\nafter the call:\n{shown(left)}", MUTATION_HINT,
                 "mutates_argument")
    for label, mine, fresh in (("used again at a second configuration", got["second"], got["fresh_second"]),
                               ("used again at the first configuration", got["again"], got["first"])):
        if not same(mine, fresh):
            fail(f"a tree {label} does not give what a fresh tree gives: forward_kinematics keeps state between "
                 f"calls.\n{_first_difference(mine, fresh)}", TREE_STATE_HINT, "state_between_calls")


TREE_STATE_HINT = (
    "Every call of forward_kinematics computes every body's state from q (and qd, qdd) afresh: nothing may be kept "
    "from an earlier call (a pose computed once and reused, a cache keyed on the wrong thing, a sum that is not "
    "reset). Later problems call it at every step of a simulation on the same tree."
)


def _first_difference(mine, fresh) -> str:
    """Which body and quantity differ first (or why the states cannot be compared)."""
    if not isinstance(mine, dict) or not isinstance(fresh, dict):
        return "the states could not be read back."
    for name, a, b in zip(fresh.get("names", []), mine.get("bodies", []), fresh.get("bodies", [])):
        for quantity in b:
            if not same(a.get(quantity) if isinstance(a, dict) else None, b[quantity]):
                return (f"{quantity} of {name}:\nthe tree used again:\n{shown(a.get(quantity))}\na fresh tree:\n"
                        f"{shown(b[quantity])}")
    return "the bodies differ."
