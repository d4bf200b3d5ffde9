"""Checks of problem 24: the rotational joint and the recursive forward kinematics of positions and orientations
(``Body.forward_kinematics``, ``Joint.successor_pose``, ``RotationalJoint.joint_pose``)."""

from grader.checking import STAGE_RANDOM, STAGE_STRUCTURE, STAGE_VALUES, STRUCTURE, assert_rotation, check

from ._trees import (
    bodies_of,
    candidates,
    cases,
    compare_states,
    compare_trees,
    configuration_figure,
    describe_case,
    rich_case,
    tree_comparison,
)

TITLE = "Rotational Joint and Recursive Forward Kinematics"

#: rotational joints and the probe's test joint (a relative translation for the generic pass)
KINDS = ("rotational", "test")


def _pendulum(ctx):
    case = ctx.reference("problem_24.pendulum_case")
    return case["description"], case["q"]


@check(1, title="the orientations A_IB of every body of random trees are proper rotations", stage=STAGE_STRUCTURE,
       group="trees")
def check_orientations(ctx):
    def compare(got, expected, args):
        for name, body in zip(expected["names"], bodies_of(got, expected["names"])):
            assert_rotation(body["A_IB"], f"A_IB of {name}", STRUCTURE)

    args = rich_case(KINDS, motion=False)
    compare(ctx.student("problem_24.tree_poses", *args), ctx.reference("problem_24.tree_poses", *args), args)
    ctx.compare_random("problem_24.tree_poses", cases(KINDS, motion=False), name="A_IB", tol=STRUCTURE,
                       compare=compare, examples=10, describe=describe_case)


@check(2, title="the triple pendulum at q = (pi/6, -pi/4, pi/3): A_IB and B_r_IB of every body",
       stage=STAGE_VALUES, group="pendulum")
def check_pendulum(ctx):
    description, q = _pendulum(ctx)
    mistakes = candidates(ctx, description, q)
    got = ctx.student("problem_24.pendulum", q)
    expected = ctx.reference("problem_24.pendulum", q)
    drawing = configuration_figure("Problem 24: the triple pendulum at q = (pi/6, -pi/4, pi/3)", got, expected)
    if drawing is not None:
        ctx.add_figure(drawing)
    compare_states(got, expected, mistakes=mistakes, context="(the sheet's configuration)")


@check(3, title="random trees of rotational joints: A_IB and B_r_IB of every body, in recursion order",
       stage=STAGE_RANDOM, group="trees")
def check_random_trees(ctx):
    compare_trees(ctx, "problem_24.tree_poses", KINDS, tree_comparison(ctx, motion=False), motion=False,
                  name="the bodies' poses")
