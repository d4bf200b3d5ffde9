"""Checks of problem 32: the rigid joint (``RigidJoint``), generalized gravity (``generalized_gravity``) and the
robot arm's gravity-compensating torques (``gravity_compensation``) along the desired trajectory."""

import numpy as np

from grader.checking import (
    EXACT,
    SHEET,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    Mistake,
    as_array,
    assert_close,
    check,
    close,
    fail,
    figure,
)
from probes import _trees as probe_trees, problem_32 as p32

from ._real import rank_flaw, require_real, rotation_flaw
from ._shapes import as_dict, as_list
from ._trees import (
    KINEMATIC_DIFFERENCES,
    H,
    bodies_list,
    candidates,
    cases,
    compare_fixed,
    compare_states,
    compare_trees,
    configuration_figure,
    describe_case,
    rich_case,
    tree_comparison,
)
from ._upstream import held, judged, judging

TITLE = "Robotic Arm. 1 - Gravity compensation"

KINDS = ("rotational", "rigid", "test")
#: gravity of the random trees, off the axes so that a frame mix-up shows
I_GRAV = np.array([0.3, -9.81, 0.5])
#: the sheet's first point of the desired trajectory, and where it puts the end effector
Q_DES_0 = np.array([-0.00369, -0.46218, -1.44917])

SIGN_HINT = "The torque that holds the arm against gravity is tau = -g(q): with M qdd = f + g + tau, qdd = 0 at rest."
FRAME_HINT = ("I_grav is given in inertial coordinates: bring it into the body first, g = sum(B_J_S.T @ (A_IB.T @ "
              "I_grav) * m) (generalized_gravity, problem 32).")
MASS_HINT = "Each body's gravity force is m * I_grav: g = sum(B_J_S.T @ (A_IB.T @ I_grav) * m)."


def _gravity_mistakes(ctx, description, q, I_grav, expected):
    """``generalized_gravity`` without the frame change, and without the masses, from the reference's Jacobians and
    orientations at ``q`` (asked of the reference now, whatever the student's answer)."""
    nq = len(q)
    state = ctx.reference(probe_trees.tree_state, description, q, np.zeros(nq), np.zeros(nq))
    masses = {body["name"]: float(body.get("m", 0.0)) for body in description["bodies"]}
    bodies = [(body, masses[name]) for name, body in zip(state["names"], state["bodies"])]
    I_grav = np.asarray(I_grav, dtype=float)
    return [
        Mistake("sign_flip", -np.asarray(expected), "g(q) is the generalized gravity force, sum(B_J_S.T @ (A_IB.T @ "
                "I_grav) * m); yours has the opposite sign."),
        Mistake("wrong_frame", sum(body["B_J_S"].T @ I_grav * m for body, m in bodies), FRAME_HINT),
        Mistake("missing_mass", sum(body["B_J_S"].T @ (body["A_IB"].T @ I_grav) for body, _ in bodies), MASS_HINT),
    ]


def _robot(ctx):
    return ctx.reference(p32.robot_case)


@check(2, title="random trees with rigid joints: the state of every body, in recursion order",
       stage=STAGE_RANDOM, group="trees")
def check_rigid_trees(ctx):
    compare_trees(ctx, probe_trees.tree_state, KINDS, tree_comparison(ctx), name="the bodies' motion")


@check(2, title="the robot hangs with its end effector at (0, -3, 0) at q = 0, and at the sheet's q_des(0) = "
       "(-0.00369, -0.46218, -1.44917) it is at the path's start (-1, -2, 0.5)", stage=STAGE_VALUES, group="robot")
def check_end_effector(ctx):
    robot = _robot(ctx)
    for q, target, title in ((np.zeros(3), np.array([0.0, -3.0, 0.0]), ""),
                             (Q_DES_0, robot["x_start"], "Problem 32: the robot at q_des(0), front view")):
        mistakes = candidates(ctx, robot["description"], q)
        own = judged(ctx, p32.robot, q)  # the reference's robot with the student's R3 (problem 6)
        got = ctx.student(p32.robot, q)
        expected = ctx.reference(p32.robot, q)
        drawing = configuration_figure(title, got, expected) if title else None
        if drawing is not None:
            ctx.add_figure(drawing)
        where = f"(the robot at q = {q.tolist()})"

        def robot_at(value, found=(), target=target, where=where, q=q):
            compare_states(got, value, mistakes=found, context=where)
            end = target if value is expected else np.asarray(value["end_effector"], dtype=float)
            assert_close(got.get("end_effector"), end, f"end_effector_position(tree, {q.tolist()})", SHEET,
                         context="(the sheet's value)" if value is expected else where)

        held(ctx, own, lambda: robot_at(expected, mistakes), robot_at)


@check(1, title="generalized_gravity is minus the gradient of your own potential energy V(q) = -sum(m I_grav . "
       "I_r_IB) (finite differences)", stage=STAGE_STRUCTURE, group="potential")
def check_gravity_potential(ctx):
    def compare(got, expected, args):
        description, names, nq = args[0], expected["names"], len(args[1])
        masses = {body["name"]: body["m"] for body in description["bodies"]}
        got = as_dict(got, "the reply of the potential probe", ("g", "names", "shifted"))
        if got["names"] != names:
            fail(f"your tree lists its bodies as {str(got['names'])[:200]}, expected {names} (depth first from the "
                 "root).", "Create the joints in the order of the template: KinematicTree lists the bodies in "
                 "recursion order.")
        shifted = [[bodies_list(side, names, f"at q {sign} h e_{i + 1}")
                    for side, sign in zip(as_list(pair, f"the poses at q +- h e_{i + 1}", 2), "+-")]
                   for i, pair in enumerate(as_list(got["shifted"], "the poses at q +- h e_i, one pair per coordinate",
                                                    nq))]

        def potential(bodies):
            return -sum(masses[name] * I_GRAV @ (as_array(body.get("A_IB"), f"A_IB of {name}", (3, 3))
                                                 @ as_array(body.get("B_r_IB"), f"B_r_IB of {name}", (3,)))
                        for name, body in zip(names, bodies))

        fd = -np.array([(potential(plus) - potential(minus)) / (2 * H) for plus, minus in shifted])
        require_real("generalized_gravity(tree, q, I_grav)", "positions and orientations", [
            *((f"A_IB of {name} at q + h e_1", rotation_flaw(body.get("A_IB"), ours.get("A_IB")))
              for name, body, ours in zip(names, shifted[0][0], expected["shifted"][0][0])),
            ("-dV/dq of your own potential energy", rank_flaw(fd, expected["g"]))])
        assert_close(got["g"], fd, "generalized_gravity(tree, q, I_grav)", KINEMATIC_DIFFERENCES, [
            Mistake("sign_flip", -fd, "g(q) = -dV/dq points downhill, it is the generalized force of gravity."),
        ], context=f"(expected: -dV/dq of your own positions, I_grav = {I_GRAV.tolist()})")

    extra = (I_GRAV, H)
    name = "generalized_gravity(tree, q, I_grav)"
    compare = judging(ctx, p32.potential, compare,
                      lambda got, value, args: assert_close(got["g"], value["g"], name, EXACT,
                                                            context=f"(I_grav = {I_GRAV.tolist()})"))
    compare_fixed(ctx, p32.potential, rich_case(KINDS, motion=False, masses=True, extra=extra), compare)
    ctx.compare_random(p32.potential, cases(KINDS, motion=False, masses=True, extra=extra),
                       name="generalized_gravity", tol=KINEMATIC_DIFFERENCES, compare=compare, examples=10,
                       describe=describe_case)


@check(2, title="generalized_gravity(tree, q, I_grav) on random trees with random masses", stage=STAGE_RANDOM,
       group="gravity")
def check_gravity_random(ctx):
    def compare(got, expected, args):
        mistakes = _gravity_mistakes(ctx, *args, expected)
        if not close(got, expected, EXACT):
            assert_close(got, expected, "generalized_gravity(tree, q, I_grav)", EXACT, mistakes,
                         context=f"(I_grav = {I_GRAV.tolist()})")

    compare = judging(ctx, p32.gravity, compare,
                      lambda got, value, args: assert_close(got, value, "generalized_gravity(tree, q, I_grav)", EXACT,
                                                            context=f"(I_grav = {I_GRAV.tolist()})"))
    compare_fixed(ctx, p32.gravity, rich_case(KINDS, motion=False, masses=True, extra=(I_GRAV,)), compare)
    ctx.compare_random(p32.gravity, cases(KINDS, motion=False, masses=True, extra=(I_GRAV,)),
                       name="generalized_gravity", tol=EXACT, compare=compare, examples=15, describe=describe_case)


@check(2, title="the gravity-compensating torques tau = -g(q) along the desired trajectory (209 points)",
       stage=STAGE_VALUES, group="torques")
def check_gravity_trajectory(ctx):
    trajectory = ctx.reference(p32.trajectory, persist=True)
    t, q = trajectory["t"], trajectory["q"]
    own = judged(ctx, p32.torques, q)  # the reference's torques with the student's R3 (problem 6)
    got = as_array(ctx.student(p32.torques, q), "the torques along the trajectory", (t.size, 3))
    expected = np.asarray(ctx.reference(p32.torques, q, persist=True))
    ctx.add_figure(figure("Problem 32: gravity-compensating torques", "t [s]", "tau [Nm]",
                          student=[(f"tau_{k + 1}", t, got[:, k]) for k in range(3)],
                          reference=[(f"tau_{k + 1}", t, expected[:, k]) for k in range(3)]))

    def along(values, signs=True):
        for k in range(t.size):
            assert_close(got[k], values[k], f"gravity_compensation(tree, q_des(t = {t[k]:.6g}))", EXACT,
                         [Mistake("sign_flip", -values[k], SIGN_HINT)] if signs else [],
                         context=f"(q_des = {np.round(q[k], 5).tolist()}, the first time that differs)")

    held(ctx, own, lambda: along(expected), lambda value: along(np.asarray(value, dtype=float), signs=False))
