"""Checks of problem 8: integrating a constant angular velocity three ways."""

import numpy as np

from checks._figures import add_integrator_paths, student_or_none
from checks._rigid import ROTATIONS, expm_skew, skew
from checks._upstream import assert_close_judged, judged, judged_comparison
from grader import strategies as st
from grader.checking import (
    EXACT,
    STRUCTURE,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    Mistake,
    Tol,
    as_array,
    assert_rotation,
    check,
    close,
    fail,
    format_array,
)
from probes import problem_06 as p06, problem_08 as p08

TITLE = "Integrating angular velocities"
MANUAL = {"c": ("8(c): compare the error accumulation of (a) and (b); which suits rotations better, and how "
                "does one line make (a) exact?", 2)}

FLOATS = st.floats(-3, 3, allow_nan=False, allow_infinity=False)
VECTORS = st.tuples(FLOATS, FLOATS, FLOATS).map(np.array)
ANGLES = st.floats(-np.pi, np.pi, allow_nan=False, allow_infinity=False)
PITCH = st.floats(-1.3, 1.3, allow_nan=False, allow_infinity=False)  # away from the Cardan singularity
STEPS = st.floats(0.001, 0.5, allow_nan=False)
RUN = Tol("100 steps", 1e-7, 1e-7)

EULER_HINT = ("This is an explicit Euler step (A + dt * skew(w) @ A), which does not stay orthonormal. The "
              "exponential step is A_IC(t + dt) = expm(dt * skew(I_omega)) @ A_IC.")


def _step_mistakes(ctx, which):
    def mistakes(args, expected):
        x, w, dt = (np.asarray(a, dtype=float) for a in args)
        if which == "cardan":
            B = ctx.reference(p08.rate_matrix, *(float(angle) for angle in x))
            body = x + dt * np.linalg.solve(B, w)
            return [Mistake("wrong_frame", body, "You used I_omega as if it were C_omega: the rates are "
                            "(A_IC @ B)^-1 @ I_omega, with A_IC from the current angles.")]
        backwards = x - dt * skew(w) @ x if which == "euler" else expm_skew(-dt * skew(w)) @ x
        found = [
            Mistake("wrong_frame", x + dt * x @ skew(w) if which == "euler" else x @ expm_skew(dt * skew(w)),
                    "The angular velocity is given in inertial coordinates: dA_IC/dt = skew(I_omega) @ A_IC; "
                    "A_IC @ skew(w) would treat w as body coordinates."),
            Mistake("sign_flip", backwards,
                    "The rotation runs backwards: check the sign of skew(w) (skew(w) @ x == cross(w, x))."),
            # the same value: skew(w).T == -skew(w), and expm(dt skew(w)).T == expm(-dt skew(w))
            Mistake("transpose", backwards,
                    "The step's matrix is transposed: skew(w).T == -skew(w)"
                    + ("." if which == "euler" else ", so expm(dt skew(w)).T == expm(-dt skew(w)).")
                    + " A transpose there runs the rotation backwards."),
        ]
        if which == "exp":
            found.insert(0, Mistake("euler_not_exponential", x + dt * skew(w) @ x, EULER_HINT))
        return found

    return mistakes


@check(1, title="cardan_rate_matrix(alpha, beta, gamma) gives C_omega = B @ (alpha_dot, beta_dot, gamma_dot)",
       stage=STAGE_RANDOM, group="rates")
def check_rate_matrix(ctx):
    ctx.compare_random(
        p08.rate_matrix, st.tuples(ANGLES, PITCH, ANGLES), name="B", tol=EXACT,
        mistakes=lambda args, expected: [
            Mistake("transpose", np.asarray(expected).T, "B is transposed: its columns are the axes of the three "
                    "rotations (e1 of C, the rotated 2-axis, the 3-axis of I), in C-coordinates.")],
    )


@check(2, title="euler_matrix_step is one explicit Euler step of dA_IC/dt = skew(I_omega) @ A_IC",
       stage=STAGE_RANDOM, group="euler")
def check_euler_step(ctx):
    ctx.compare_random(p08.step, st.tuples(ROTATIONS, VECTORS, STEPS).map(lambda t: ("euler", *t)),
                       name="A_IC after one Euler step", tol=EXACT,
                       compare=judged_comparison(ctx, p08.step, "A_IC after one Euler step", EXACT,
                                                 lambda args, e: _step_mistakes(ctx, "euler")(args[1:], e)))


@check(1, title="exponential_step keeps A_IC orthonormal (even for a large step)", stage=STAGE_STRUCTURE,
       group="exp")
def check_exponential_orthonormal(ctx):
    A0, w, dt = ctx.reference(p06.elementary, 3, np.pi / 2), np.sqrt(1 / 3) * np.ones(3), 0.5
    got = as_array(ctx.student(p08.step, "exp", A0, w, dt), "exponential_step(R3(90°), w, 0.5)", (3, 3))
    if np.allclose(got, A0 + dt * skew(w) @ A0, atol=1e-9):
        fail(f"exponential_step(R3(90°), w, 0.5) is not orthonormal: it is the Euler step.\n"
             f"got:\n{format_array(got)}", EULER_HINT, "euler_not_exponential")
    assert_rotation(got, "exponential_step(R3(90°), w, 0.5)")
    assert_moves(got, A0, "exponential_step(R3(90°), w, 0.5)")


def assert_moves(got, start, name):
    """Fail when one step with a non-zero angular velocity left ``A_IC`` where it was."""
    if close(got, start, STRUCTURE):
        fail(f"{name} returned A_IC unchanged: the body did not turn, although omega is not zero.\n"
             f"got:\n{format_array(got)}",
             "One step turns A_IC by the angle dt * |I_omega| about I_omega: A_IC(t + dt) = expm(dt * "
             "skew(I_omega)) @ A_IC.", "no_motion")


@check(2, title="exponential_step equals expm(dt * skew(I_omega)) @ A_IC on random inputs", stage=STAGE_RANDOM,
       group="exp")
def check_exponential_step(ctx):
    ctx.compare_random(p08.step, st.tuples(ROTATIONS, VECTORS, STEPS).map(lambda t: ("exp", *t)),
                       name="A_IC after one exponential step", tol=EXACT,
                       compare=judged_comparison(ctx, p08.step, "A_IC after one exponential step", EXACT,
                                                 lambda args, e: _step_mistakes(ctx, "exp")(args[1:], e)))


def same_turn(angles, target):
    """The angles moved by whole turns next to ``target``'s: the same orientation (an answer that wraps its angles
    into (-pi, pi] is as right as one that does not)."""
    try:
        angles, target = np.asarray(angles, dtype=float), np.asarray(target, dtype=float)
    except (TypeError, ValueError):
        return angles
    if angles.shape != target.shape:
        return angles
    return target + (angles - target + np.pi) % (2 * np.pi) - np.pi


@check(2, title="cardan_euler_step advances the angles by dt * (A_IC @ B)^-1 @ I_omega (up to whole turns)",
       stage=STAGE_RANDOM, group="cardan")
def check_cardan_step(ctx):
    angles = st.tuples(ANGLES, PITCH, ANGLES).map(np.array)
    ctx.compare_random(p08.step, st.tuples(angles, VECTORS, STEPS).map(lambda t: ("cardan", *t)),
                       name="angles after one step", tol=EXACT,
                       compare=judged_comparison(ctx, p08.step, "angles after one step", EXACT,
                                                 lambda args, e: _step_mistakes(ctx, "cardan")(args[1:], e),
                                                 normalize=same_turn))


@check(1, title="(a) after 100 Euler steps the matrix has grown (not orthonormal) exactly as Euler predicts",
       stage=STAGE_VALUES, group="runs")
def check_part_a(ctx):
    expected = ctx.reference(p08.part, "a")
    own = judged(ctx, p08.part, "a")  # the reference's run with the student's R3 and skew (problems 6, 7)
    got = ctx.student(p08.part, "a")
    assert_close_judged(ctx, got, expected, own, "A_IC after (a)", RUN)


@check(1, title="(b) after 100 Euler steps of the Cardan angles", stage=STAGE_VALUES, group="runs")
def check_part_b(ctx):
    expected = ctx.reference(p08.part, "b")
    own = judged(ctx, p08.part, "b")  # the reference's run with the student's cardan (problem 6)
    got = ctx.student(p08.part, "b")
    assert_close_judged(ctx, got["A_IC"], expected["A_IC"], own, "A_IC after (b)", RUN, pick=lambda v: v["A_IC"])


@check(2, title="(c) the exponential returns exactly to A_IC(t0) = R3(90°) after 2 pi", stage=STAGE_VALUES,
       group="runs")
def check_part_c(ctx):
    start = ctx.reference(p06.elementary, 3, np.pi / 2)
    euler = ctx.reference(p08.part, "a")
    own = judged(ctx, p08.part, "c")  # the reference's run with the student's R3, skew and unskew
    paths = ctx.reference(p08.paths)
    add_integrator_paths(ctx, "Problem 8: the body's axes along the three runs",
                         student_or_none(ctx, p08.paths), paths)
    w, dt = np.sqrt(1 / 3) * np.ones(3), 2 * np.pi / 100
    # a step that does not move would also "return" to the start: (c) counts only for a step that turns
    one = as_array(ctx.student(p08.step, "exp", start, w, dt), "exponential_step(R3(90°), w, 2 pi / 100)",
                   (3, 3))
    assert_moves(one, start, "exponential_step(R3(90°), w, 2 pi / 100)")
    got = as_array(ctx.student(p08.part, "c"), "A_IC after (c)", (3, 3))
    assert_close_judged(ctx, got, start, own, "A_IC after (c)", Tol("exact rotation", 1e-9), [
        Mistake("lost_orthonormality", euler, EULER_HINT),
    ])
