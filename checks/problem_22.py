"""Checks of problem 22: the end effector of the 2n-joint arm by a loop and by recursion, and that the recursion
really recurses (credited only once point_k's values are right, and when the recursive calls return the right
poses)."""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_VALUES,
    CheckFailure,
    Mistake,
    as_array,
    assert_close,
    check,
    close,
    fail,
)
from probes import problem_22 as p22

from ._figures import add_planar_arm
from ._planar import ANGLES, DEGREES_HINT, HORIZONTAL_HINT, LENGTHS, LINKS, SIGN_HINT, sign_flips
from ._real import is_real, real, require_real
from ._shapes import as_dict, as_list

TITLE = "Recursive Kinematics"

#: the recursion is credited after the randomized values of point_k (same group): a recursion that computes wrong
#: poses earns nothing for recursing
STAGE_AFTER_VALUES = STAGE_RANDOM + 1

JOINT_VECTORS = st.lists(st.tuples(LENGTHS, ANGLES), min_size=1, max_size=8).map(
    lambda pairs: np.array(pairs, dtype=float).ravel()
)

JOINT_ORDER_HINT = (
    "The joints act in their order: the prismatic joint q_(2k-1) extends along the orientation g_(k-1) of the "
    "segment so far, and only then the rotational joint q_(2k) turns it: g_k = g_(k-1) + q_(2k). You turned first."
)
FINAL_LINK_HINT = "The end effector sits d beyond P_n along g_n: (x_n - d sin g_n, y_n + d cos g_n, g_n)."
ORIENTATION_HINT = (
    "point_k(q, k) returns g_k, the orientation AFTER the rotational joint q_(2k) (of the segment leaving P_k); "
    "you returned g_(k-1), the orientation of the segment arriving at P_k."
)
MODELS = {
    "degrees": DEGREES_HINT,
    "horizontal_offset": HORIZONTAL_HINT + " Your positions are right but every orientation is 90 deg too large.",
    "horizontal": HORIZONTAL_HINT,
    "horizontal_all": HORIZONTAL_HINT,
    "joint_order": JOINT_ORDER_HINT,
    "no_final_link": FINAL_LINK_HINT,
}


def _name(model):
    return model.removesuffix("_offset").removesuffix("_all")


def _end_mistakes(ctx, q, d):
    found = ctx.reference(p22.mistakes, q, d)
    return [Mistake(_name(model), found[model]["end"], hint) for model, hint in MODELS.items()]


def _point_mistakes(found, expected, k):
    """Modelled mistakes of ``point_k(q, k)``: the pose ``(x_k, y_k, g_k)`` of the mistaken arms ``found`` (the
    probe ``problem_22.mistakes``), and the orientation before the joint read off the reference's poses."""
    if k == 0:
        return []
    models = [model for model in MODELS if model != "no_final_link"]
    x, y, before = *np.asarray(expected[k], dtype=float)[:2], float(np.asarray(expected[k - 1])[2])
    return [Mistake(_name(model), np.asarray(found[model]["points"][k - 1])[[0, 1, 3]], MODELS[model])
            for model in models] + [Mistake("orientation_before", (x, y, before), ORIENTATION_HINT)]


def _describe(function):
    def describe(args):
        shown = f"{function}(q={np.asarray(args[0]).tolist()!r}"
        return shown + (f", d={args[1]!r})" if len(args) > 1 else ")")

    return describe


def _compare_end(ctx, probe, function):
    def compare(got, expected, args):
        mistakes = _end_mistakes(ctx, *args) + sign_flips(got, expected, EXACT, SIGN_HINT)
        assert_close(got, expected, f"{function}(q, d)", EXACT, mistakes)

    ctx.compare_random(probe, st.tuples(JOINT_VECTORS, LINKS), name=f"{function}(q, d)", tol=EXACT, compare=compare,
                       describe=_describe(function))


# ------------------------------------------------------------------------------------ the sheet's case q3


@check(1, title="q3 (12 joints, corrected in the problem data), d = 0.15: the end effector is at "
       "(0.8243, 0.3914, 0) as on the sheet", stage=STAGE_VALUES, group="sheet")
def check_sheet_target(ctx):
    case = ctx.reference(p22.sheet_case)
    q3, d, target = case["q"], case["d"], np.asarray(case["target"], dtype=float)
    mistakes = _end_mistakes(ctx, q3, d)
    expected = ctx.reference(p22.loop, q3, d)
    got = ctx.student(p22.loop, q3, d)
    arm = [*ctx.reference(p22.points, q3)[1:], expected]
    add_planar_arm(ctx, "Problem 22: the arm at q3 (reference) and your end effector", got, arm, end_only=True)
    typed = Mistake("typed_numbers", target, "These are the sheet's printed numbers (four decimals), not computed "
                    "ones: compute the pose from q3 and d; it is compared at full precision.")
    assert_close(got, expected, f"end_effector_loop(q3, {d:g})", EXACT,
                 [typed] + mistakes + sign_flips(got, expected, EXACT, SIGN_HINT),
                 context="(the sheet's value at full precision)",
                 note="q3 has 12 entries: the sheet lost two of them (problem data).")


# ------------------------------------------------------------------------------------ the loop


@check(2, title="end_effector_loop(q, d) on random 2n-joint arms (n = 1..8)", stage=STAGE_RANDOM, group="loop")
def check_loop_values(ctx):
    _compare_end(ctx, p22.loop, "end_effector_loop")


# ------------------------------------------------------------------------------------ the recursion


@check(2, title="point_k(q, k) is the pose (x_k, y_k, g_k) of P_k for every k = 0..n on random arms",
       stage=STAGE_RANDOM, group="points")
def check_points_values(ctx):
    def compare(got, expected, args):
        (q,) = args
        found = ctx.reference(p22.mistakes, q, 0.0)
        got = as_list(got, f"[point_k(q, k) for k = 0..{len(expected) - 1}]", len(expected))
        for k, (pose, target) in enumerate(zip(got, expected)):
            right = {0: "", 1: "P_0 is right: "}.get(k, f"P_0 .. P_{k - 1} are right: ")
            where = f"{right}the step from P_{k - 1} to P_{k} is wrong." if k else "P_0 is the origin with g_0 = 0."
            assert_close(pose, target, f"point_k(q, {k})", EXACT,
                         _point_mistakes(found, expected, k) + sign_flips(pose, target, EXACT, SIGN_HINT), note=where)

    ctx.compare_random(p22.points, st.tuples(JOINT_VECTORS), name="point_k(q, k)", tol=EXACT,
                       compare=compare, describe=_describe("point_k"))


#: the check that grades the poses end_effector_recursive is judged on
POINTS = "p22.points_values"


def _with_final_link(pose, d):
    """The end effector a distance ``d`` beyond the pose ``(x, y, g)`` along its orientation."""
    x, y, g = np.asarray(pose, dtype=float)
    return np.array([x, y, g]) + d * np.array([-np.sin(g), np.cos(g), 0.0])


@check(1, title="end_effector_recursive(q, d) on random 2n-joint arms (n = 1..8)", stage=STAGE_RANDOM,
       group="recursive")
def check_recursive_values(ctx):
    name = "end_effector_recursive(q, d)"

    def compare(got, expected, args):
        mistakes = _end_mistakes(ctx, *args)  # the reference's calls, made eagerly
        end = as_array(got["end"], name, (3,))
        if close(end, expected["end"], EXACT):
            return
        own = got["point"]
        findings = [real(f"point_k(q, {len(args[0]) // 2})", own, (3,), expected["point"])]
        if own is None or close(own, expected["point"], EXACT) or (
                not is_real(findings) and not close(end, _with_final_link(own, args[1]), EXACT)):
            assert_close(end, expected["end"], name, EXACT,
                         mistakes + sign_flips(end, expected["end"], EXACT, SIGN_HINT))
            return
        own_end = _with_final_link(own, args[1])
        if close(end, own_end, EXACT):
            require_real(name, "point_k", findings)
            ctx.carry_forward(POINTS, "point_k")
            return
        assert_close(end, own_end, name, EXACT,
                     [Mistake("no_final_link", np.asarray(own, dtype=float), FINAL_LINK_HINT)] + mistakes,
                     context="(judged on your own point_k(q, n) and the final link)",
                     note="Your point_k differs from the reference's (its own check says how); the end effector is "
                          "judged on it.")

    ctx.compare_random(p22.recursive_with_point, st.tuples(JOINT_VECTORS, LINKS), name=name, tol=EXACT,
                       compare=compare, describe=_describe("end_effector_recursive"))


def _nesting(ctx, call, q, d):
    got = as_dict(ctx.student(p22.nesting, call, q, d), f"the reply of the recursion probe ({call})",
                  ("depth", "function", "value"))
    if isinstance(got["depth"], bool) or not isinstance(got["depth"], (int, float)):
        fail(f"the recursion probe ({call}) must report a depth, got {str(got['depth'])[:100]}.", diagnosis="shape")
    return got


def _assert_recursion_value(value, expected, name):
    """The value a recursive call returned is the reference's: recursing alone earns nothing."""
    try:
        assert_close(value, expected, name, EXACT, context="(the value your recursion returned)")
    except CheckFailure as exc:
        fail(exc.message, "The recursion earns its points only when it computes the poses: point_k(q, k) returns "
             "P_k = P_(k-1) + q_(2k-1) (-sin g_(k-1), cos g_(k-1)) with g_k = g_(k-1) + q_(2k), and "
             "end_effector_recursive adds the final link to point_k(q, n).", "wrong_values", evidence=exc.evidence)


@check(2, title="point_k calls itself, from P_n down to the origin, and end_effector_recursive uses it; both return "
       "the right poses", stage=STAGE_AFTER_VALUES, group="points")
def check_recursion(ctx):
    case = ctx.reference(p22.sheet_case)
    q, d = case["q"], case["d"]
    n = q.size // 2
    expected_point = ctx.reference(p22.points, q)[n]
    expected_end = ctx.reference(p22.recursive, q, d)
    got = _nesting(ctx, "point_k", q, d)
    if got["depth"] < 2:
        fail(
            f"point_k(q3, {n}) does not call itself: no function of your package ran more than once at a time.",
            "Recursion: point_k(q, k) gets (x, y, g) of P_(k-1) from point_k(q, k - 1) and adds one stage; "
            "point_k(q, 0) returns the origin (0, 0, 0) without calling itself. A for-loop over the joints is "
            "end_effector_loop, not the recursion.",
            "no_recursion",
        )
    if got["depth"] < n:
        fail(
            f"point_k(q3, {n}) recurses only {got['depth']} levels deep (in {got['function']}), expected at least "
            f"{n}: one call per point on the way down to the origin.",
            "Let each call handle one point: point_k(q, k) calls point_k(q, k - 1), down to k = 0.",
            "shallow_recursion",
        )
    _assert_recursion_value(got["value"], expected_point, f"point_k(q3, {n})")
    got = _nesting(ctx, "end_effector_recursive", q, d)
    if got["depth"] < n:
        fail(
            f"end_effector_recursive(q3, {d}) does not recurse: the deepest nesting of a function of your package "
            f"was {got['depth']}, expected at least {n}.",
            "end_effector_recursive must get P_n from point_k(q, n) (the recursion) and add the final link.",
            "no_recursion",
        )
    _assert_recursion_value(got["value"], expected_end, f"end_effector_recursive(q3, {d})")
