"""Checks of problem 33: the rolling contact's relative motion (``RollingContactJoint.joint_motion``) and the
passive dynamic walker with velocities, accelerations and Jacobians."""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    Mistake,
    Tol,
    as_array,
    assert_close,
    check,
    close,
)
from probes import _trees as probe_trees, problem_33 as p33

from ._real import real, require_real, rotation_flaw
from ._trees import (
    bodies_of,
    candidates,
    compare_fixed,
    compare_jacobian_differences,
    compare_path_differences,
    compare_states,
    compare_trees,
    configuration_figure,
    tree_comparison,
)
from ._upstream import held, judged
from .problem_25 import WALKER_MODELS

TITLE = "Rolling Contact Joint (velocities, accelerations, Jacobians)"

KINDS = ("rolling_contact", "rotational", "test")
#: the positions and orientations are problem 25's work (and 24's): the motion is judged on the student's own (error
#: carried forward; the finite-difference checks judge it on them)
POSES = ("p25.rolling_trees", "positions and orientations A_IB, B_r_IB (problems 24 and 25)")
NO_SLIP = Tol("rolling without slipping", 1e-9, 1e-9)
VALUES = st.lists(st.floats(-2.0, 2.0, allow_nan=False), min_size=6, max_size=6).map(
    lambda v: (np.array(v[:2]), np.array(v[2:4]), np.array(v[4:])))


def _walker(ctx):
    """``{"description", "q", "qd", "qdd", "foot_radius"}`` of the reference's walker at the sheet's test state."""
    return ctx.reference(p33.walker_case)


def _contact(bodies, names, q, radius):
    """Velocity and acceleration of the stance foot's material point that touches the ground, and the stance leg's
    angular velocity, all inertial (``bodies`` in the order of ``names``)."""
    body = bodies[names.index("stance_leg")]
    A = as_array(body.get("A_IB"), "A_IB of stance_leg", (3, 3))
    r, v, w, a, dw = (A @ as_array(body.get(name), f"{name} of stance_leg", (3,))
                      for name in ("B_r_IB", "B_v_B", "B_omega_B", "B_a_B", "B_omegaDot_B"))
    lever = np.array([-radius * q[0], 0.0, 0.0]) - r
    return v + np.cross(w, lever), a + np.cross(dw, lever) + np.cross(w, np.cross(w, lever)), w


def _same_pose(bodies, mine):
    return all(close(theirs[name], ours.get(name), EXACT) for theirs, ours in zip(bodies, mine)
               for name in ("A_IB", "B_r_IB"))


@check(2, title="the walker at the sheet's test state q = (-30 deg, +60 deg), qd = (-0.5, +1), qdd = 0: velocities, "
       "accelerations and Jacobians of both legs", stage=STAGE_VALUES, group="walker")
def check_sheet(ctx):
    case = _walker(ctx)
    values = case["q"], case["qd"], case["qdd"]
    mistakes = candidates(ctx, case["description"], *values, models=WALKER_MODELS)
    own = judged(ctx, p33.walker, *values)  # the reference's recursion with the student's R3 and skew
    got = ctx.student(p33.walker, *values)
    expected = ctx.reference(p33.walker, *values)
    drawing = configuration_figure("Problem 33: the walker at the test state", got, expected)
    if drawing is not None:
        ctx.add_figure(drawing)
    held(ctx, own, lambda: compare_states(got, expected, mistakes=mistakes, context="(the sheet's test state)",
                                          poses_from=(ctx, *POSES)),
         lambda value: compare_states(got, value, context="(the sheet's test state)"))


@check(1, title="the stance foot rolls without slipping: the foot's point on the ground is at rest and accelerates "
       "straight up by r omega^2", stage=STAGE_STRUCTURE, group="no_slip")
def check_no_slip(ctx):
    case = _walker(ctx)
    description, radius = case["description"], case["foot_radius"]

    def compare(got, expected, args):
        q, names = args[0], expected["names"]
        known = candidates(ctx, description, *args, models=WALKER_MODELS)
        mine = bodies_of(got, names)
        leg, ours = (bodies[names.index("stance_leg")] for bodies in (mine, bodies_of(expected, names)))
        require_real("the contact point's motion", "motion of the stance leg", [
            ("A_IB of stance_leg", rotation_flaw(leg.get("A_IB"), ours.get("A_IB"))),
            *(real(f"{quantity} of stance_leg", leg.get(quantity), (3,), ours.get(quantity))
              for quantity in ("B_r_IB", "B_v_B", "B_omega_B", "B_a_B", "B_omegaDot_B"))])
        v, a, w = _contact(mine, names, q, radius)
        expected_a = np.array([0.0, radius * w[2] ** 2, 0.0])
        if close(v, np.zeros(3), NO_SLIP) and close(a, expected_a, NO_SLIP):
            return
        mistaken = [(name, hint, _contact(bodies, names, q, radius)) for name, hint, bodies in known
                    if name == "rolling_sign" and _same_pose(bodies, mine)]
        assert_close(v, np.zeros(3), "the velocity of the stance foot's contact point", NO_SLIP,
                     [Mistake(name, c[0], hint) for name, hint, c in mistaken],
                     context="(rolling without slipping)",
                     note="The contact point is the foot's point right below its centre, I_r = (-r alpha, 0, 0).")
        assert_close(a, expected_a, "the acceleration of the stance foot's contact point",
                     NO_SLIP, [Mistake(name, c[1], hint) for name, hint, c in mistaken],
                     context="(rolling without slipping: r omega^2 towards the foot's centre)")

    def describe(args):
        return "q = {}, qd = {}, qdd = {}".format(*(np.asarray(v).tolist() for v in args))

    compare_fixed(ctx, p33.walker, (np.array([0.4, -0.9]), np.array([1.2, -0.7]), np.array([-0.8, 1.5])),
                  compare, describe)
    ctx.compare_random(p33.walker, VALUES, name="the contact point", tol=NO_SLIP, compare=compare,
                       examples=10, describe=describe)


@check(1, title="the Jacobians of random trees with rolling contacts are the derivatives of your own positions and "
       "orientations (finite differences)", stage=STAGE_STRUCTURE, group="jacobians")
def check_jacobians(ctx):
    compare_jacobian_differences(ctx, probe_trees.jacobian_differences, KINDS)


@check(1, title="along a path q(t), the velocities and accelerations of random trees with rolling contacts are the "
       "time derivatives of your own kinematics", stage=STAGE_STRUCTURE, group="path")
def check_path(ctx):
    compare_path_differences(ctx, probe_trees.path_differences, KINDS)


@check(2, title="random trees with rolling contacts: velocities, accelerations and Jacobians of every body",
       stage=STAGE_RANDOM, group="trees")
def check_random_trees(ctx):
    compare_trees(ctx, probe_trees.tree_state, KINDS, tree_comparison(ctx, poses_from=POSES), name="the bodies' motion")
