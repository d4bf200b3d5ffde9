"""Checks of problem 27: the five multiple-choice answers (keys computed by the reference), and the Jacobian
columns and matrices behind (a), (d) and (e).

A wrong choice is explained without naming the key: which columns of the chosen matrix disagree with the
geometry, or on which example the chosen formula fails or holds.

Secret checks (their keys stay with the instructor): the five choices, and the three values behind them —
``jacobian_a()`` and ``governor_jacobian()`` equal one printed option each, and the residuals of (e) name the
statement that fails, so recording any of them in the student kit would hand out the keys of (a), (d) and (e).
The Jacobian columns on random geometry stay public.
"""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_VALUES,
    CheckFailure,
    Mistake,
    Tol,
    assert_close,
    check,
    close,
    fail,
    format_array,
)
from grader.context import explained
from probes import problem_27 as p27

from ._answers import choice
from ._planar import FINITE, sign_flips, swapped_columns
from ._upstream import held, judged

TITLE = "Understanding Jacobians"

QUESTIONS = {
    "a": "(a) the constraint Jacobian J_f of the planar arm (geometry restated in the problem data)",
    "b": "(b) the formula for the Cartesian velocity and its constraint type",
    "c": "(c) the statement that is NOT correct for the bias acceleration of a rheonomic constraint",
    "d": "(d) the Jacobian of the flyball governor's right ball at phi = 0, gamma = 30 deg",
    "e": "(e) the statement about time derivatives in moving frames that is NOT correct",
}
#: a formula "holds" on the examples when its residual is below this
HOLDS = 1e-6
#: residuals of (e) are computed with central differences
RESIDUALS = Tol("central differences", 1e-5, 1e-5)
#: the random rigid motions (seed) and times of (e) the residuals are compared on
FRAME_CASES = ((0, 0.3), (3, -0.2))
COORDINATES = st.floats(-5.0, 5.0, **FINITE)
POINTS = st.tuples(COORDINATES, COORDINATES)


# ------------------------------------------------------------------------------------ the choices


def _choice(ctx, key):
    return choice(ctx, key, (1, 2, 3, 4), QUESTIONS[key])


def _key(ctx, key):
    return int(ctx.reference(p27.answers, persist=True)[key])


def _wrong(key, choice, reasons, hint, diagnosis):
    fail(f"{QUESTIONS[key]}: option {choice} is not the right choice.\n{reasons}".rstrip(), hint, diagnosis)


def _columns(option, expected, names, scale=""):
    """Lines naming the columns of ``option`` that disagree with ``expected`` (printed to two decimals)."""
    return [
        f"  column {j + 1} ({name}): the option has {format_array(option[:, j], 2)}{scale}, "
        f"the geometry gives {format_array(expected[:, j], 2)}{scale}"
        for j, name in enumerate(names)
        if not np.allclose(option[:, j], expected[:, j], atol=5e-3)
    ]


def _options(ctx, key):
    """The options of question ``key`` as typed from the sheet, by number."""
    return {int(option): value for option, value in ctx.reference(p27.options, persist=True)[key].items()}


def _residuals(ctx, probe, *args):
    return {int(k): v for k, v in ctx.reference(probe, *args, persist=True).items()}


def _point(value):
    return str(tuple(float(x) for x in value))


@check(1, title="(a) the chosen matrix is J_f of the arm", stage=STAGE_VALUES, group="a", secret=True)
def check_choice_a(ctx):
    key, options = _key(ctx, "a"), _options(ctx, "a")
    geometry = ctx.reference(p27.options, persist=True)["geometry"]
    J = np.asarray(ctx.reference(p27.jacobian_a))
    choice = _choice(ctx, "a")
    if choice == key:
        return
    names = [f"revolute joint 1 at {_point(geometry['joint_1'])}", f"prismatic joint 2 along "
             f"{_point(geometry['axis_2'])}", f"revolute joint 3 at {_point(geometry['joint_3'])}"]
    lines = _columns(options[choice], J, names)
    _wrong("a", choice, "\n".join(lines), (
        f"With the end effector at {_point(geometry['end_effector'])}, a revolute joint at p contributes the column "
        "(-(ye - py), xe - px, 1): the end effector moves perpendicular to its lever arm and turns with the joint; "
        "a prismatic joint along u contributes (ux, uy, 0)."), "wrong_column")


@check(1, title="(b) the chosen velocity formula holds for its constraint type", stage=STAGE_VALUES, group="b",
       secret=True)
def check_choice_b(ctx):
    key, options = _key(ctx, "b"), _options(ctx, "b")
    residuals = _residuals(ctx, p27.velocity_residuals)
    choice = _choice(ctx, "b")
    if choice == key:
        return
    derivative, kind = options[choice]["derivative"], options[choice]["kind"]
    residual = residuals[choice]
    if residual is None:
        _wrong("b", choice, f"Option {choice} is stated for {kind} constraints.", (
            "An explicit equality constraint x = f(q, t) is holonomic by construction: a non-holonomic constraint "
            "(a condition on velocities that cannot be integrated) cannot be written this way."), "non_holonomic")
    misses = f"On an example {kind} constraint, option {choice} misses x_dot by {residual:.3g}."
    if derivative == "total":
        _wrong("b", choice, misses, (
            "The TOTAL derivative df/dt already contains J q_dot, which the formula then counts twice: the velocity "
            "is J q_dot plus the PARTIAL derivative df/dt at fixed q (the explicit time dependence)."),
            "total_derivative")
    _wrong("b", choice, misses, "", "wrong_choice")


def _holds(key, choice, residual, where):
    _wrong(key, choice, f"Statement {choice} is correct: on {where} both sides agree to {residual:.1e}.",
           "The question asks for the statement that is NOT correct: look for the one whose two sides differ.",
           "correct_statement")


@check(1, title="(c) the chosen statement is the wrong one for the bias acceleration", stage=STAGE_VALUES, group="c",
       secret=True)
def check_choice_c(ctx):
    key, residuals = _key(ctx, "c"), _residuals(ctx, p27.bias_acceleration_residuals)
    choice = _choice(ctx, "c")
    if choice == key:
        return
    residual = residuals[choice]
    if residual < HOLDS:
        _holds("c", choice, residual, "an example rheonomic constraint, sigma = x_ddot - J q_ddot")
    _wrong("c", choice, "", "", "wrong_choice")


@check(1, title="(d) the chosen matrix is the Jacobian of the governor's ball", stage=STAGE_VALUES, group="d",
       secret=True)
def check_choice_d(ctx):
    key, options = _key(ctx, "d"), _options(ctx, "d")
    J = np.asarray(ctx.reference(p27.governor_jacobian, persist=True))
    choice = _choice(ctx, "d")
    if choice == key:
        return
    lines = _columns(options[choice], J, ["d r / d phi", "d r / d gamma"], " * l")
    _wrong("d", choice, "\n".join(lines), (
        "The ball sits at I_r = R2(phi) (l sin gamma, -l cos gamma, 0): phi turns it about the vertical spindle "
        "(the y-axis), so it moves along z; gamma swings it in the x-y plane. Differentiate each coordinate."),
        "wrong_column")


@check(1, title="(e) the chosen statement is the wrong one about derivatives in moving frames", stage=STAGE_VALUES,
       group="e", secret=True)
def check_choice_e(ctx):
    key, residuals = _key(ctx, "e"), _residuals(ctx, p27.frame_derivative_residuals, 0, 0.3)
    choice = _choice(ctx, "e")
    if choice == key:
        return
    residual = residuals[choice]
    if residual < HOLDS:
        _holds("e", choice, residual, "a random rigid motion")
    _wrong("e", choice, "", "", "wrong_choice")


# ------------------------------------------------------------------------------------ the code behind the keys


def _revolute_mistakes(args, expected):
    p, p_e = np.asarray(args[0]), np.asarray(args[1])
    (dx, dy), (xe, ye) = p_e - p, p_e
    return [
        Mistake("lever_arm", (dx, dy, 1.0), "This is the lever arm itself: the end effector moves PERPENDICULAR to "
                "it, (-(ye - py), xe - px)."),
        Mistake("absolute_position", (-ye, xe, 1.0), "Use the lever arm from the joint p to the end effector, "
                "p_e - p, not p_e alone."),
        Mistake("no_rotation", (-dy, dx, 0.0), "A revolute joint turns the end effector with it: d gamma / d q = 1."),
    ]


def _prismatic_mistakes(args, expected):
    ux, uy = args[0]
    return [
        Mistake("swapped", (uy, ux, 0.0), "The column is the sliding direction itself: (ux, uy, 0)."),
        Mistake("rotation", (ux, uy, 1.0), "A prismatic joint does not turn the end effector: d gamma / d q = 0."),
    ]


def _compare_column(name, mistakes, sign_hint):
    def compare(got, expected, args):
        assert_close(got, expected, name, EXACT, mistakes(args, expected) + sign_flips(got, expected, EXACT, sign_hint))

    return compare


@check(1, title="revolute_column(p, p_e) and prismatic_column(u) on random geometry", stage=STAGE_RANDOM,
       group="columns")
def check_columns(ctx):
    ctx.compare_random(p27.revolute_column, st.tuples(POINTS, POINTS), name="revolute_column(p, p_e)",
                       tol=EXACT, compare=_compare_column("revolute_column(p, p_e)", _revolute_mistakes, (
                           "The end effector moves perpendicular to the lever arm p_e - p, turned by +90 deg "
                           "(counter-clockwise): (-(ye - py), xe - px).")),
                       describe=lambda args: f"revolute_column(p={args[0]}, p_e={args[1]})")
    ctx.compare_random(p27.prismatic_column, st.tuples(POINTS), name="prismatic_column(u)",
                       tol=EXACT, compare=_compare_column("prismatic_column(u)", _prismatic_mistakes,
                                                          "The end effector slides along +u: (ux, uy, 0)."),
                       describe=lambda args: f"prismatic_column(u={args[0]})")


@check(1, title="jacobian_a() is J_f of the restated arm of (a)", stage=STAGE_VALUES, group="jacobian_a",
       secret=True)
def check_jacobian_a(ctx):
    expected = ctx.reference(p27.jacobian_a)
    got = ctx.student(p27.jacobian_a)
    assert_close(got, expected, "jacobian_a()", EXACT, [
        Mistake("transpose", np.transpose(expected), "Column j of J_f belongs to joint j: you stacked the joints' "
                "columns as rows (use np.column_stack)."),
        *swapped_columns(expected, ["joint 1", "joint 2", "joint 3"]),
        *sign_flips(got, expected, EXACT, "A revolute joint at p contributes (-(ye - py), xe - px, 1), a prismatic "
                    "joint along u contributes (ux, uy, 0)."),
    ])


@check(1, title="governor_jacobian() is J / l of the ball of (d) at phi = 0, gamma = 30 deg", stage=STAGE_VALUES,
       group="governor", secret=True)
def check_governor_jacobian(ctx):
    expected = np.asarray(ctx.reference(p27.governor_jacobian, persist=True))
    got = ctx.student(p27.governor_jacobian)
    assert_close(got, expected, "governor_jacobian()", EXACT, [
        *swapped_columns(expected, ["phi", "gamma"]),
        *sign_flips(got, expected, EXACT, "Differentiate I_r = R2(phi) (l sin gamma, -l cos gamma, 0) again."),
    ])


@check(1, title="frame_derivative_residuals(seed, t) = |lhs - rhs| of the statements of (e) on random rigid motions",
       stage=STAGE_VALUES, group="frames", secret=True)
def check_frame_residuals(ctx):
    failures = []
    for seed, t in FRAME_CASES:
        expected = _residuals(ctx, p27.frame_derivative_residuals, seed, t)
        own = judged(ctx, p27.frame_derivative_residuals, seed, t)  # with the student's cardan, skew, ...
        got = ctx.student(p27.frame_derivative_residuals, seed, t)
        if not isinstance(got, dict) or sorted(map(str, got)) != ["1", "2", "3", "4"]:
            if failures:  # the first case's failure is the one shown
                break
            fail(f"frame_derivative_residuals({seed}, {t}) must return a dict with the keys 1, 2, 3, 4; got "
                 f"{str(got)[:200]}")
        name = f"|lhs - rhs| of statements 1-4, frame_derivative_residuals({seed}, {t})"
        mine = [got[str(k)] for k in (1, 2, 3, 4)]
        try:
            held(ctx, own, lambda mine=mine, expected=expected, name=name: assert_close(
                mine, [expected[k] for k in (1, 2, 3, 4)], name, RESIDUALS),
                 lambda value, mine=mine, name=name: assert_close(mine, [value[str(k)] for k in (1, 2, 3, 4)], name,
                                                                  RESIDUALS))
        except CheckFailure as failure:
            failures.append((failure, got, expected))
    if failures:
        raise _statement_failure(ctx, failures)


def _statement_failure(ctx, failures):
    """The first failure of the residuals, its evidence the residual of the first statement that differs from the
    reference's (one entry of each side's result, so that the engine finds the calls it came from), on each case
    where it differs (the engine hears two inputs where both cases fail there)."""
    failure, got, expected = failures[0]
    if failure.diagnosis or failure.evidence is None:
        return failure
    differing = [k for k in (1, 2, 3, 4) if not close(np.asarray(float(got[str(k)])), np.asarray(expected[k]),
                                                      RESIDUALS)]
    if not differing:  # judged on the student's own shared functions: that comparison stands
        return failure
    k = differing[0]
    evidences = [_statement_evidence(mine, ours, k) for _, mine, ours in failures
                 if not close(np.asarray(float(mine[str(k)])), np.asarray(ours[k]), RESIDUALS)]
    failure = CheckFailure(failure.message, failure.hint, failure.diagnosis, failure.candidates, evidences[0])
    return explained(ctx, failure, evidences)


def _statement_evidence(got, expected, k):
    from grader.diagnosis import Evidence

    return Evidence(np.asarray(float(got[str(k)])), np.asarray(float(expected[k])), RESIDUALS,
                    f"|lhs - rhs| of statement {k}", got[str(k)], expected[k])
