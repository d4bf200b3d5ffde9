"""Checks of problem 35: the symbolic joint functions of the four joint types, evaluated in the sandbox at the
points the check sends and compared with the reference's numeric joint functions; and ``joint_function_from_pose``
on poses that are not linear in q (a polar joint, a crank), where the part of a time derivative that depends on q
shows."""

import numpy as np

from grader.checking import (EXACT, STAGE_RANDOM, STAGE_STRUCTURE, CheckFailure, Mistake, as_array, assert_close, check,
                             close, fail)
from probes import problem_35 as p35

from ._shapes import as_dict, as_list

TITLE = "Specific Joint Functions"

NQ = {"rotational": 1, "translational": 1, "virtual_3dof": 3, "rolling_contact": 1, "polar": 2, "crank": 1}
NAMES = {"rotational": "(a) rotational", "translational": "(b) translational", "virtual_3dof": "(c) 3-DOF",
         "rolling_contact": "(d) rolling contact"}
VECTORS = ("Dp_r_DpDs", "r_rel_dot", "r_rel_ddot", "omega_rel", "omega_rel_dot")
KEYS = ("A_DpDs", *VECTORS, "S", "R")
#: the entries that change sign when the circle rolls the wrong way (Dp_r_DpDs = (+r gamma, 0, 0))
ROLLING_WRONG_WAY = ("Dp_r_DpDs", "r_rel_dot", "r_rel_ddot", "S")
POINTS = 6

SIGN_HINT = ("omega_rel comes from skew(omega_rel) = dA_DpDs/dt @ A_DpDs.T, read back as (W[2,1], W[0,2], W[1,0]); "
             "yours has the opposite sign (the other off-diagonal entries, or A_DpDs @ dA_DpDs/dt.T).")
QDD_HINT = ("The time derivative of an expression in q and qd has two parts: d/dt f(q, qd) = (df/dq) qd + (df/dqd) "
            "qdd; yours misses the second.")
ROLLING_HINT = ("The circle rolls the wrong way: turning counter-clockwise by gamma it rolls towards -x, "
                "Dp_r_DpDs = (-r gamma, 0, 0), S = (-r, 0, 0).")
BIAS_HINT = ("The time derivative of an expression in q and qd has two parts: d/dt f(q, qd) = (df/dq) qd + (df/dqd) "
             "qdd; yours misses the first. It vanishes where the pose is linear in q, as for the sheet's four joints, "
             "but not on a crank or a polar joint: there r_rel_ddot holds a centripetal term (and on the polar joint a "
             "Coriolis term).")
TRANSPOSE_HINT = "A_DpDs maps Ds- to Dp-coordinates: R3(gamma); you have its transpose R3(-gamma)."


def _points(ctx, kind):
    nq = NQ[kind]
    return ctx.draw(lambda rng: [{"q": rng.uniform(-2, 2, nq), "qd": rng.uniform(-2, 2, nq),
                                  "qdd": rng.uniform(-2, 2, nq), "r": float(rng.uniform(0.1, 2.0))}
                                 for _ in range(POINTS)])


def _evaluate(ctx, kind, points):
    return _read(ctx.student(p35.joint_function, kind, points), f"{kind}_joint_function()", points,
                 " and r" if kind == "rolling_contact" else "")


def _read(got, function, points, extra=""):
    """The student's entries at each point, from the reply of a probe of ``function`` (its ``problems`` fail)."""
    got = as_dict(got, f"the reply for {function}", ("problems", "values"))
    for name, problem in as_dict(got["problems"], f"the problems of {function}").items():
        what = f"{function} has no entry {name!r}" if problem == "missing" else (
            f"{name} of {function} {problem}: it must depend on q, qd, qdd{extra} only")
        fail(f"{what}, so it cannot be evaluated.",
             "Use the symbols of the dict's q, qd, qdd (and r): derivatives d_<name>, dd_<name> are in qd, qdd.",
             "free_symbols" if problem != "missing" else "format")
    values = as_list(got["values"], f"the values of {function} at the {len(points)} points", len(points))
    return [as_dict(value, f"{function} at a point", KEYS) for value in values]


def _entries(values, kind):
    """The student's entries in the reference's shapes: 3-vectors, 3 x 3, 3 x nq."""
    nq = NQ[kind]
    shaped = {"A_DpDs": as_array(values["A_DpDs"], "A_DpDs", (3, 3))}
    for name in VECTORS:
        value = np.asarray(values[name], dtype=float)
        shaped[name] = as_array(value.reshape(3) if value.size == 3 else value, name, (3,))
    for name in ("S", "R"):
        value = np.asarray(values[name], dtype=float)
        shaped[name] = as_array(value.reshape(3, nq) if value.size == 3 * nq else value, name, (3, nq))
    return shaped


def _at(point, kind):
    shown = ", ".join(f"{key} = {np.round(point[key], 6).tolist()}" for key in ("q", "qd", "qdd"))
    return f"at {shown}" + (f", r = {point['r']:.6g}" if kind == "rolling_contact" else "")


#: each velocity, its subspace, and what the check says of the two
SUBSPACES = (
    ("r_rel_dot", "S", "S is the motion subspace of the translation: r_rel_dot = S qd, S = d r_rel_dot / d qd."),
    ("omega_rel", "R", "R is the motion subspace of the rotation: omega_rel = R qd, R = d omega_rel / d qd."),
)


def _subspaces(ctx, kind):
    points = _points(ctx, kind)
    numeric = ctx.reference(p35.numeric_joint_function, kind, points)
    for point, values, expected in zip(points, _evaluate(ctx, kind, points), numeric):
        entries = _entries(values, kind)
        where = f"{_at(point, kind)} (seed {ctx.seed})"
        for velocity, subspace, note in SUBSPACES:
            try:
                assert_close(entries[velocity], entries[subspace] @ point["qd"], f"{velocity} {where}", EXACT,
                             context=f"(expected: your {subspace} @ qd)", note=note)
            except CheckFailure as failure:
                raise _caused(failure, entries, expected, (velocity, subspace), kind, point) from None


def _caused(failure, entries, expected, names, kind, point):
    """The failure of a velocity and its subspace that disagree, with the comparison of the first of the two that
    differs from the reference's at the point: its catalogue's name and hint, and the evidence the diagnosis engine
    explains (the check itself compares the student's two values with each other, which no reference call gives)."""
    for name in names:
        target = np.asarray(expected[name], dtype=float)
        try:
            assert_close(entries[name], target, f"{name} {_at(point, kind)}", EXACT, _mistakes(kind, name, target),
                         context=f"(the reference's {kind} joint function)")
        except CheckFailure as cause:
            return CheckFailure(f"{failure.message}\nYour {name} differs from the reference's: {cause.message}",
                                cause.hint or failure.hint, cause.diagnosis, evidence=cause.evidence)
    return failure


def _mistakes(kind, name, target):
    found = []
    if kind == "rolling_contact":
        found.append(Mistake("rolling_sign", -target if name in ROLLING_WRONG_WAY else target, ROLLING_HINT))
    if name in ("omega_rel", "omega_rel_dot", "R"):
        found.append(Mistake("sign_flip", -target, SIGN_HINT))
    if name in ("r_rel_ddot", "omega_rel_dot"):
        found.append(Mistake("missing_qdd", np.zeros(3), QDD_HINT))
    if name == "A_DpDs":
        found.append(Mistake("transpose", target.T, TRANSPOSE_HINT))
    return found


def _values(ctx, kind):
    points = _points(ctx, kind)
    numeric = ctx.reference(p35.numeric_joint_function, kind, points)
    for point, values, expected in zip(points, _evaluate(ctx, kind, points), numeric):
        for name, value in _entries(values, kind).items():
            target = np.asarray(expected[name], dtype=float)
            if not close(value, target, EXACT):
                assert_close(value, target, f"{name} {_at(point, kind)}", EXACT, _mistakes(kind, name, target),
                             context=f"(the reference's {kind} joint function; seed {ctx.seed})")


def _checks(kind):
    label = NAMES[kind]

    def subspaces(ctx):
        _subspaces(ctx, kind)

    def values(ctx):
        _values(ctx, kind)

    subspaces.__name__, values.__name__ = f"check_{kind}_subspaces", f"check_{kind}_values"
    return (
        check(1, title=f"{label} joint: r_rel_dot = S qd and omega_rel = R qd for your own S and R",
              stage=STAGE_STRUCTURE, group=kind)(subspaces),
        check(1, title=f"{label} joint: A_DpDs, Dp_r_DpDs, velocities, accelerations, S and R at random points",
              stage=STAGE_RANDOM, group=kind)(values),
    )


check_rotational_subspaces, check_rotational_values = _checks("rotational")
check_translational_subspaces, check_translational_values = _checks("translational")
check_virtual_3dof_subspaces, check_virtual_3dof_values = _checks("virtual_3dof")
check_rolling_contact_subspaces, check_rolling_contact_values = _checks("rolling_contact")


# ------------------------------------------------------------------------------------------ poses not linear in q

#: the accelerations: their part (df/dq) qd (the bias, their value at qdd = 0) vanishes on every joint of the sheet,
#: whose relative pose is linear in q, and shows on a pose that is not
ACCELERATIONS = ("r_rel_ddot", "omega_rel_dot")


def _pose_mistakes(name, target, without_bias, without_qdd):
    """The catalogue on a pose not linear in q: the sheet's joints' mistakes, with the accelerations' two parts each
    left out as the reference gives them (at qd = 0 the bias is gone, at qdd = 0 the qdd part is)."""
    found = [mistake for mistake in _mistakes("pose", name, target) if mistake.name != "missing_qdd"]
    if name in ACCELERATIONS:
        found += [Mistake(diagnosis, value, hint) for diagnosis, value, hint in (
            ("missing_bias", without_bias, BIAS_HINT), ("missing_qdd", without_qdd, QDD_HINT))
            if not close(value, target, EXACT)]
    return found


def _pose_values(ctx, pose):
    nq = NQ[pose]
    points = ctx.draw(lambda rng: [{"q": rng.uniform(-2, 2, nq), "qd": rng.uniform(-2, 2, nq),
                                    "qdd": rng.uniform(-2, 2, nq)} for _ in range(POINTS)])
    still = [point | {"qd": np.zeros(nq)} for point in points]
    steady = [point | {"qdd": np.zeros(nq)} for point in points]
    expected, without_bias, without_qdd = (ctx.reference(p35.pose_joint_function, pose, rows)["values"]
                                           for rows in (points, still, steady))
    what = f"joint_function_from_pose(...) of the {pose} joint ({p35.POSES[pose]})"
    got = _read(ctx.student(p35.pose_joint_function, pose, points), what, points)
    for i, (point, values) in enumerate(zip(points, got)):
        ours, bias_free, qdd_free = (_entries(reply[i], pose) for reply in (expected, without_bias, without_qdd))
        for name, value in _entries(values, pose).items():
            if not close(value, ours[name], EXACT):
                assert_close(value, ours[name], f"{name} {_at(point, pose)}", EXACT,
                             _pose_mistakes(name, ours[name], bias_free[name], qdd_free[name]),
                             context=f"({what}, against the reference's; seed {ctx.seed})")


@check(1, title="joint_function_from_pose on poses not linear in q (a polar joint: turned by gamma about the "
       "3-axis, slid by s along the turned 1-axis; a crank of 0.5 m): every entry at random points",
       stage=STAGE_RANDOM, group="poses")
def check_poses_values(ctx):
    for pose in p35.POSES:
        _pose_values(ctx, pose)
