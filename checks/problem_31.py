"""Checks of problem 31: velocities, accelerations and Jacobians across a joint (``Joint.successor_motion``,
``Joint.successor_jacobians``, ``RotationalJoint.joint_motion``)."""

from grader.checking import STAGE_RANDOM, STAGE_STRUCTURE, STAGE_VALUES, check
from probes import _trees as probe_trees, problem_31 as p31

from ._trees import (
    assert_tree_no_side_effects,
    candidates,
    compare_jacobian_differences,
    compare_path_differences,
    compare_states,
    compare_trees,
    rich_case,
    tree_comparison,
)
from ._upstream import held, judged

TITLE = "Kinematics with Velocities, Accelerations, and Jacobians"

#: rotational joints and the probe's test joint (relative translations exercise the Coriolis term)
KINDS = ("rotational", "test")
#: the positions and orientations are problem 24's work: the motion is judged on the student's own (error carried
#: forward; the finite-difference checks judge it on them)
POSES = ("p24.random_trees", "positions and orientations A_IB, B_r_IB (problem 24)")


@check(2, title="the triple pendulum at the sheet's test case q = (pi/6, -pi/4, pi/3), qd = (1, 0, 0), qdd = "
       "(0, 0, 1): velocities, accelerations and Jacobians of every body", stage=STAGE_VALUES, group="pendulum")
def check_pendulum(ctx):
    case = ctx.reference(p31.pendulum_case)
    values = case["q"], case["qd"], case["qdd"]
    mistakes = candidates(ctx, case["description"], *values)
    own = judged(ctx, p31.pendulum, *values)  # the reference's recursion with the student's R3 and skew
    got = ctx.student(p31.pendulum, *values)
    expected = ctx.reference(p31.pendulum, *values)
    held(ctx, own, lambda: compare_states(got, expected, mistakes=mistakes, context="(the sheet's test case)",
                                          poses_from=(ctx, *POSES)),
         lambda value: compare_states(got, value, context="(the sheet's test case)"))


@check(2, title="the Jacobians B_J_S, B_J_R of random trees are the derivatives of your own positions and "
       "orientations (finite differences)", stage=STAGE_STRUCTURE, group="jacobians")
def check_jacobians(ctx):
    compare_jacobian_differences(ctx, probe_trees.jacobian_differences, KINDS)


@check(2, title="along a path q(t), your velocities are the time derivatives of your positions and orientations, "
       "and your accelerations those of your velocities", stage=STAGE_STRUCTURE, group="path")
def check_path(ctx):
    compare_path_differences(ctx, probe_trees.path_differences, KINDS)


@check(3, title="random trees: velocities, accelerations and Jacobians of every body, in recursion order",
       stage=STAGE_RANDOM, group="trees")
def check_random_trees(ctx):
    compare_trees(ctx, probe_trees.tree_state, KINDS, tree_comparison(ctx, poses_from=POSES), name="the bodies' motion")


@check(1, title="forward_kinematics with velocities leaves q, qd, qdd unchanged, and a tree used again gives what a "
       "fresh tree gives (no state kept between calls)", stage=STAGE_RANDOM + 1, group="trees")
def check_side_effects(ctx):
    description, q, qd, qdd = rich_case(KINDS)
    assert_tree_no_side_effects(ctx, description, (q, qd, qdd), (q - 0.4, -qd, 0.5 * qdd))
