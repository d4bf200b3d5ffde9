"""Checks of problem 25: the rolling-contact joint (``RollingContactJoint.joint_pose``), the passive dynamic walker
(``build_walker``) and its symbolic positions and Jacobian (``cog_positions_symbolic``)."""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    SHEET,
    STAGE_RANDOM,
    STAGE_VALUES,
    Mistake,
    as_array,
    assert_close,
    check,
    close,
    fail,
)
from probes import problem_25 as p25

from ._trees import (
    KINEMATIC_DIFFERENCES,
    MODELS,
    H,
    Model,
    candidates,
    compare_fixed,
    compare_states,
    compare_trees,
    configuration_figure,
    judged_states,
    tree_comparison,
)
from ._upstream import held, judged, judging
from ._shapes import as_dict, as_list

TITLE = "Rolling Contact Joint"

KINDS = ("rolling_contact", "rotational", "test")
#: part (c) of the sheet (problem data: alpha = -30 deg, gamma = +60 deg), x = (x_st, y_st, gamma_st, x_sw, ...)
SHEET_X = np.array([0.2051, 0.3018, -0.5236, 0.9051, 0.3518, 0.5236])
ANGLES = (2, 5)
LEGS = ("stance_leg", "swing_leg")
ALPHA = st.floats(-1.2, 1.2, allow_nan=False)
GAMMA = st.floats(-2.5, 2.5, allow_nan=False)


def _without_contact_offset(description):
    joints = [dict(joint) for joint in description["joints"]]
    joints[0]["P_r_PDp"] = np.zeros(3)
    return {**description, "joints": joints}


def _foot_at_hip(description):
    joints = [dict(joint) for joint in description["joints"]]
    joints[0]["S_r_SDs"] = np.array(joints[1]["S_r_SDs"], dtype=float)
    return {**description, "joints": joints}


def _coordinates_swapped(description):
    joints = [dict(joint) for joint in description["joints"]]
    joints[0]["q_index"], joints[1]["q_index"] = joints[1]["q_index"], joints[0]["q_index"]
    return {**description, "joints": joints}


WALKER_MODELS = MODELS + (
    Model("contact_height", "The rolling joint's frame Dp sits at the foot's centre when q = 0, a radius above the "
          "ground: P_r_PDp = (0, r, 0) (build_walker).", edit=_without_contact_offset),
    Model("foot_offset", "Ds of the rolling joint is the foot's centre, l - r below the hip: S_r_SDs = (-dx, dy - l "
          "+ r, 0) for the stance leg; you used the hip's offset (-dx, dy, 0) (build_walker).", edit=_foot_at_hip),
    Model("coordinate_order", "q = (alpha, gamma): the rolling contact has q_index [0], the hip q_index [1] "
          "(build_walker).", edit=_coordinates_swapped),
)
BODY_HINT = ("x holds the legs' positions in inertial coordinates, I_r_IB = A_IB @ B_r_IB; yours are in the legs' "
             "body coordinates (B_r_IB).")


def _walker(ctx):
    """``{"description", "alpha_c", "gamma_c"}`` of the reference's walker."""
    return ctx.reference(p25.walker_case)


def _wrap(angle):
    return (np.asarray(angle) + np.pi) % (2 * np.pi) - np.pi


def _x_of(bodies, names, frame="inertial"):
    """``x = (x_st, y_st, gamma_st, x_sw, y_sw, gamma_sw)`` of the walker's bodies (in the order of ``names``);
    with ``frame="body"`` the positions are read in the legs' body coordinates (``B_r_IB``)."""
    x = []
    for name in LEGS:
        body = bodies[names.index(name)]
        A = np.asarray(body["A_IB"])
        position = A @ body["B_r_IB"] if frame == "inertial" else np.asarray(body["B_r_IB"])
        x += [*position[:2], np.arctan2(A[1, 0], A[0, 0])]
    return np.array(x)


def _on_branch(x, target):
    """``x`` with its leg angles moved by multiples of 2 pi next to ``target``'s."""
    x = np.array(x, dtype=float)
    x[list(ANGLES)] = target[list(ANGLES)] + _wrap(x[list(ANGLES)] - target[list(ANGLES)])
    return x


def _x_mistakes(ctx, alpha, gamma, target):
    """The known mistakes of ``x`` at ``(alpha, gamma)``, asked of the reference now (whatever the student's
    answer)."""
    description = _walker(ctx)["description"]
    names = [body["name"] for body in description["bodies"]]
    found = [Mistake(name, _on_branch(_x_of(bodies, names), target), hint)
             for name, hint, bodies in candidates(ctx, description, [alpha, gamma], models=WALKER_MODELS)]
    walker = ctx.reference(p25.walker, alpha, gamma)
    body = _x_of(walker["bodies"], walker["names"], frame="body")
    return [Mistake("wrong_frame", _on_branch(body, target), BODY_HINT), *found]


# ------------------------------------------------------------------------------------ part (c)


@check(2, title="part (c): at alpha = -30 deg, gamma = +60 deg the legs' centres of gravity are at x = (0.2051, "
       "0.3018, -0.5236, 0.9051, 0.3518, 0.5236), and at angles drawn anew", stage=STAGE_VALUES, group="sheet")
def check_sheet_values(ctx):
    case = _walker(ctx)
    alpha, gamma = case["alpha_c"], case["gamma_c"]
    mistakes = _x_mistakes(ctx, alpha, gamma, SHEET_X)
    own = judged(ctx, p25.walker, alpha, gamma)  # the reference's walker with the student's R3 (problem 6)
    got = ctx.student(p25.walker, alpha, gamma)
    expected = ctx.reference(p25.walker, alpha, gamma)
    drawing = configuration_figure("Problem 25: the walker at alpha = -30 deg, gamma = +60 deg", got, expected)
    if drawing is not None:
        ctx.add_figure(drawing)
    raw = as_array(as_dict(got, "the walker read back by the probe", ("x",))["x"], "cog_positions(alpha, gamma)",
                   (6,))

    def against(target, name, context, found=()):
        x = raw.copy()
        for i in ANGLES:  # signed angles; the course printed acos(A11), which loses the sign
            if abs(_wrap(x[i] - target[i])) <= SHEET.atol or abs(x[i] - abs(target[i])) <= SHEET.atol:
                x[i] = target[i]
        if not close(x, target, SHEET):
            assert_close(x, target, name, SHEET, found, context=context,
                         note="The leg angles may be signed (ours) or unsigned as the course printed them "
                              "(acos(A11)).")

    held(ctx, own, lambda: against(SHEET_X, "x = cog_positions(-30 deg, +60 deg)",
                                   "(the sheet's values with the erratum's angles)", mistakes),
         lambda value: against(np.asarray(value["x"], dtype=float), "x = cog_positions(-30 deg, +60 deg)", ""))
    # the walker at angles of its own, drawn anew at each grading (no key holds them)
    other = ctx.draw(lambda rng: [float(rng.uniform(-1.0, 1.0)), float(rng.uniform(-2.0, 2.0))])
    own = judged(ctx, p25.walker, *other)
    expected = ctx.reference(p25.walker, *other)
    got = ctx.student(p25.walker, *other)
    raw = as_array(as_dict(got, "the walker read back by the probe", ("x",))["x"], "cog_positions(alpha, gamma)",
                   (6,))
    name = "x = cog_positions(alpha, gamma)"
    where = f"(alpha, gamma) = ({other[0]:.4f}, {other[1]:.4f})"
    held(ctx, own, lambda: against(np.asarray(expected["x"], dtype=float), name, where),
         lambda value: against(np.asarray(value["x"], dtype=float), name, where))


@check(2, title="the walker of build_walker at random (alpha, gamma): A_IB and B_r_IB of every body",
       stage=STAGE_RANDOM, group="walker")
def check_walker_random(ctx):
    description = _walker(ctx)["description"]

    def compare(got, expected, args):
        compare_states(got, expected, mistakes=candidates(ctx, description, list(args), models=WALKER_MODELS))

    def describe(args):
        return f"q = (alpha, gamma) = ({args[0]!r}, {args[1]!r})"

    compare = judging(ctx, p25.walker, compare, judged_states)
    compare_fixed(ctx, p25.walker, (0.4, -0.9), compare, describe)
    ctx.compare_random(p25.walker, st.tuples(ALPHA, GAMMA), name="the walker", tol=EXACT, compare=compare,
                       examples=10, describe=describe)


@check(2, title="random trees with rolling contacts: A_IB and B_r_IB of every body, in recursion order",
       stage=STAGE_RANDOM, group="trees")
def check_rolling_trees(ctx):
    compare_trees(ctx, p25.tree_poses, KINDS, tree_comparison(ctx, motion=False), motion=False,
                  name="the bodies' poses")


# ------------------------------------------------------------------------------------ part (e): symbolic


def _points(ctx):
    case = _walker(ctx)
    drawn = ctx.draw(lambda rng: rng.uniform([-1.2, -2.5], [1.2, 2.5], (7, 2)))
    return np.vstack([[case["alpha_c"], case["gamma_c"]], np.asarray(drawn, dtype=float)])


def _symbolic(ctx, points):
    got = as_dict(ctx.student(p25.symbolic, points, H), "the reply of the symbolic probe")
    if "free_symbols" in got:
        fail(f"x and J of cog_positions_symbolic() contain symbols other than q = ({', '.join(got['symbols'])}): "
             f"{', '.join(got['free_symbols'])}, so they cannot be evaluated at a configuration.",
             "Build x and J from the symbols you return in q only; the geometry enters as numbers.", "free_symbols")
    as_dict(got, "the reply of the symbolic probe", ("x", "J", "plus", "minus"))
    return {key: as_list(got[key], f"{key} of cog_positions_symbolic() at the {len(points)} points", len(points))
            for key in ("x", "J", "plus", "minus")}


def _at(point, ctx):
    return f"at (alpha, gamma) = ({point[0]:.6g}, {point[1]:.6g}) (seed {ctx.seed})"


def _shifted(value, name):
    """The student's ``x`` at the two shifted points as a 2 x 6 array."""
    value = as_array(value, name)
    if value.size != 12:
        fail(f"{name} must hold x at 2 points (2 x 6 entries), got shape {value.shape}.", diagnosis="shape")
    return value.reshape(2, 6)


@check(2, title="part (e): the symbolic x(alpha, gamma) equals the legs' inertial positions and orientations at "
       "random configurations", stage=STAGE_VALUES, group="symbolic")
def check_symbolic_positions(ctx):
    points = _points(ctx)
    expected_x = [np.asarray(ctx.reference(p25.walker, *point)["x"]) for point in points]
    mistakes = [_x_mistakes(ctx, *point, expected) for point, expected in zip(points, expected_x)]
    got = _symbolic(ctx, points)
    for point, value, expected, known in zip(points, got["x"], expected_x, mistakes):
        value = as_array(value, f"x {_at(point, ctx)}")
        if value.size != 6:
            as_array(value, "x", (6, 1))
        value = _on_branch(value.reshape(6), expected)
        if not close(value, expected, EXACT):
            assert_close(value, expected, f"x {_at(point, ctx)}", EXACT, known, note="Angles are compared modulo 2 pi.")


@check(1, title="part (e): the symbolic Jacobian J is dx/dq (finite differences of your x) and matches the legs' "
       "Jacobians", stage=STAGE_VALUES, group="symbolic")
def check_symbolic_jacobian(ctx):
    points = _points(ctx)
    expected_J = [ctx.reference(p25.leg_jacobians, *point) for point in points]
    got = _symbolic(ctx, points)
    for point, J, plus, minus, expected in zip(points, got["J"], got["plus"], got["minus"], expected_J):
        J = as_array(J, "J", (6, 2))
        step = _shifted(plus, "x at q + h e_j") - _shifted(minus, "x at q - h e_j")
        step[:, list(ANGLES)] = _wrap(step[:, list(ANGLES)])
        fd = step.T / (2 * H)
        assert_close(J, fd, f"J {_at(point, ctx)}", KINEMATIC_DIFFERENCES, [
            Mistake("column_order", fd[:, ::-1], "J = dx/dq has one column per coordinate, in the order of "
                    "q = (alpha, gamma); yours are swapped."),
        ], context="(expected: the derivative of your own x)")
        assert_close(J, expected, f"J {_at(point, ctx)}", EXACT,
                     context="(the legs' Jacobians: rows I_J_S[0:2] and I_J_R[2] of each leg)")
