"""Checks of problem 34: the translational and the virtual 3-DOF joint (``TranslationalJoint``,
``Virtual3DOFJoint``) and the biped that uses them."""

from grader.checking import STAGE_RANDOM, STAGE_STRUCTURE, STAGE_VALUES, check
from probes import _trees as probe_trees, problem_34 as p34

from ._trees import (
    candidates,
    compare_jacobian_differences,
    compare_path_differences,
    compare_states,
    compare_trees,
    configuration_figure,
    tree_comparison,
)
from ._upstream import held, judged

TITLE = "Biped"

KINDS = ("virtual_3dof", "translational", "rotational", "test")
FRAME = 90


@check(2, title="the biped at the 90th frame of its gait: positions, velocities, accelerations and Jacobians of every "
       "body", stage=STAGE_VALUES, group="biped")
def check_biped(ctx):
    case = ctx.reference(p34.biped_case, FRAME)
    t = case["t"]
    mistakes = candidates(ctx, case["description"], case["q"], case["qd"], case["qdd"])
    own = judged(ctx, p34.biped, t)  # the reference's recursion with the student's R3 and skew
    got = ctx.student(p34.biped, t)
    expected = ctx.reference(p34.biped, t)
    drawing = configuration_figure(f"Problem 34: the biped at frame {FRAME} (t = {t:g} s)", got, expected)
    if drawing is not None:
        ctx.add_figure(drawing)
    held(ctx, own, lambda: compare_states(got, expected, mistakes=mistakes, context=f"(frame {FRAME}, t = {t:g} s)"),
         lambda value: compare_states(got, value, context=f"(frame {FRAME}, t = {t:g} s)"))


@check(1, title="the Jacobians of random trees with translational and virtual 3-DOF joints are the derivatives of "
       "your own positions and orientations (finite differences)", stage=STAGE_STRUCTURE, group="jacobians")
def check_jacobians(ctx):
    compare_jacobian_differences(ctx, probe_trees.jacobian_differences, KINDS)


@check(1, title="along a path q(t), the velocities and accelerations of random trees with translational and "
       "virtual 3-DOF joints are the time derivatives of your own kinematics", stage=STAGE_STRUCTURE, group="path")
def check_path(ctx):
    compare_path_differences(ctx, probe_trees.path_differences, KINDS)


@check(3, title="random trees with translational and virtual 3-DOF joints: the state of every body, in recursion "
       "order", stage=STAGE_RANDOM, group="trees")
def check_random_trees(ctx):
    compare_trees(ctx, probe_trees.tree_state, KINDS, tree_comparison(ctx), name="the bodies' motion")
