"""Checks of problem 12: the integration step of a kinematic rigid body and the motion of its points.

The scenario helpers (random states, the step with a known mistake applied, the comparison of traces that names
the first departing step) live in ``checks/_rigid.py``, shared with problems 11 and 13-20.
"""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    SHEET,
    STAGE_RANDOM,
    STAGE_SHAPE,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    STRUCTURE,
    CheckFailure,
    Mistake,
    as_array,
    assert_close,
    assert_rotation,
    check,
    close,
    fail,
    figure,
    format_array,
)
from probes import problem_12 as p12

from ._real import assert_real
from ._rigid import (
    DT,
    KINEMATIC_MISTAKES,
    SHEET_TARGETS,
    SIMULATION,
    STATE,
    STATES,
    STEPS,
    STEP_COUNTS,
    STEP_SIZES,
    WHEEL_DT,
    WHEEL_EVERY,
    WHEEL_STEPS,
    assert_traces,
    compact,
    describe_state,
    initial,
    kinematic_mistakes_at,
    sheet_state,
    skew,
    simulate,
    subsample,
    trace_array,
    vectors,
)

TITLE = "Rigid Body Kinematics"
MANUAL = {
    "b": ("12(b): Give a physical example of something that behaves like the body of part (b). What are the "
          "points B and Q, respectively?", 1),
}


def _own_start(ctx):
    """A start of its own: the sheet's body with velocities and accelerations drawn anew at each grading (no key
    holds its step)."""
    return sheet_state(ctx.draw(lambda rng: {key: [float(x) for x in rng.uniform(-1.5, 1.5, 3)]
                                             for key in ("B_v_B", "B_omega_B", "B_a_B", "B_omegaDot_B")}))


@check(1, title="integration_step keeps A_IB (3 x 3) and B_r_IB, B_v_B, B_omega_B (3-vectors) numeric",
       stage=STAGE_SHAPE, group="integration")
def check_integration_shape(ctx):
    shapes = {"A_IB": (2, 3, 3), "B_r_IB": (2, 3), "B_v_B": (2, 3), "B_omega_B": (2, 3)}
    for start, what in ((initial(ctx, 2), ""), (_own_start(ctx), " from a start of its own")):
        expected = ctx.reference(p12.integrate, start, DT, 1)
        got = ctx.student(p12.integrate, start, DT, 1)
        for key, shape in shapes.items():
            assert_real(trace_array(got, key, shape)[1], f"{key} after one step{what}", shape[1:],
                        np.asarray(expected[key], dtype=float)[1])


GENERIC = {
    "A_IB": np.eye(3), "B_r_IB": np.array([0.2, -0.1, 0.4]), "B_v_B": np.array([0.5, 0.3, -0.2]),
    "B_a_B": np.array([-0.3, 0.6, 0.1]), "B_omega_B": np.array([0.7, -1.2, 0.9]),
    "B_omegaDot_B": np.array([0.4, 0.3, -0.5]),
}


@check(1, title="A_IB stays a proper rotation over 100 steps of 0.01 s (a tumbling body)", stage=STAGE_STRUCTURE,
       group="integration")
def check_integration_rotation(ctx):
    got = ctx.student(p12.integrate, GENERIC, DT, STEPS, STEPS)
    A = as_array(trace_array(got, "A_IB", (2, 3, 3))[-1], "A_IB after 100 steps", (3, 3))
    try:
        assert_rotation(A, "A_IB after 100 steps")
    except CheckFailure as exc:
        if close(A, simulate(GENERIC, DT, STEPS, "explicit_euler")["A_IB"], SHEET):
            fail(exc.message, KINEMATIC_MISTAKES["explicit_euler"], "explicit_euler", evidence=exc.evidence)
        raise
    if close(A, GENERIC["A_IB"], STRUCTURE):
        fail(f"A_IB after 100 steps is still its initial value: the body did not turn, although B_omega_B = "
             f"{compact(GENERIC['B_omega_B'])}.\ngot:\n{format_array(A)}",
             "integration_step must turn A_IB every step: A_IB = expm(dt * I_Om) @ A_IB with I_Om = "
             "skew(A_IB @ B_omega_B).", "no_motion")


@check(3, title="the sheet's cases 1-3: A_IB and B_r_IB after 100 steps of 0.01 s", stage=STAGE_VALUES,
       group="integration")
def check_sheet_cases(ctx):
    for case, (A_target, r_target) in SHEET_TARGETS.items():
        start = initial(ctx, case)
        got = ctx.student(p12.integrate, start, DT, STEPS, STEPS)
        for key, target in (("A_IB", A_target), ("B_r_IB", r_target)):
            final = trace_array(got, key, (2, *np.shape(target)))[-1]
            if close(final, target, SHEET):
                continue
            final_state = {k: trace_array(got, k, (2, *np.shape(start[k])))[-1] for k in STATE}
            mistakes = [Mistake(name, mistaken[key], hint) for name, hint in KINEMATIC_MISTAKES.items()
                        if _explains(mistaken := simulate(start, DT, STEPS, name), final_state)]
            assert_close(final, target, f"{key} at t = 1 s", SHEET, mistakes,
                         context=f"in case {case} (the sheet's value)")


def _explains(mistaken, state):
    """Whether a mistaken run reproduces the whole final state (some mistakes agree on one attribute)."""
    return all(close(state[k], mistaken[k], SHEET) for k in STATE)


@check(3, title="integration_step follows the reference from random states (1-20 steps)", stage=STAGE_RANDOM,
       group="integration")
def check_random_steps(ctx):
    def compare(got, expected, args):
        state, dt, _ = args
        assert_traces(got, expected, STATE, EXACT, kinematic_mistakes_at(expected, state, dt), dt=dt)

    ctx.compare_random(
        p12.integrate, st.tuples(STATES, STEP_SIZES, STEP_COUNTS), name="the state", tol=EXACT,
        compare=compare, examples=15,
        describe=lambda args: f"{describe_state(args[0])}, dt = {args[1]!r}, {args[2]} step(s)",
    )


# ------------------------------------------------------------------------------------ part (b): points


POINTS = vectors(2.0)


def _point_mistakes(method, state, q):
    A, r, v, a = (np.asarray(state[k], dtype=float) for k in ("A_IB", "B_r_IB", "B_v_B", "B_a_B"))
    Om, Omd = skew(state["B_omega_B"]), skew(state["B_omegaDot_B"])
    body = "The result must be in inertial coordinates: multiply the body-frame vector by A_IB."
    if method == "position_of_point":
        return [Mistake("wrong_frame", r + q, body),
                Mistake("offset_not_rotated", A @ r + q, "B_r_BQ is in body coordinates: I_r_IQ = A_IB @ "
                        "(B_r_IB + B_r_BQ), the offset is rotated too.")]
    if method == "velocity_of_point":
        return [Mistake("missing_omega_x_r", A @ v, "The velocity of Q adds omega x r_BQ to the velocity of B: "
                        "I_v_Q = A_IB @ (B_v_B + B_omega_B x B_r_BQ)."),
                Mistake("sign_flip", A @ (v - Om @ q), "The cross product is omega x r_BQ, not r_BQ x omega."),
                Mistake("wrong_frame", v + Om @ q, body),
                Mistake("offset_not_rotated", A @ v + Om @ q, "omega x B_r_BQ is in body coordinates as well: "
                        "I_v_Q = A_IB @ (B_v_B + B_omega_B x B_r_BQ), the whole sum is rotated into I.")]
    return [Mistake("missing_centripetal", A @ (a + Omd @ q), "The centripetal term is missing: I_a_Q = A_IB @ "
                    "(B_a_B + omegaDot x r_BQ + omega x (omega x r_BQ)); skew(omega) @ skew(omega) @ r_BQ."),
            Mistake("missing_tangential", A @ (a + Om @ Om @ q), "The tangential term omegaDot x r_BQ is missing."),
            Mistake("wrong_frame", a + (Omd + Om @ Om) @ q, body),
            Mistake("offset_not_rotated", A @ a + (Omd + Om @ Om) @ q, "The terms of the offset B_r_BQ are in body "
                    "coordinates as well: I_a_Q = A_IB @ (B_a_B + (skew(omegaDot) + skew(omega)^2) @ B_r_BQ), the "
                    "whole sum is rotated into I.")]


#: a state without special structure (turned, moving, every quantity non-zero) on which a mistake is named first:
#: on a shrunk random input several mistakes give the same value
POINT_STATE = {**GENERIC, "A_IB": np.array([[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]])}
POINT_OFFSET = np.array([0.3, -0.7, 0.5])


def _point_check(ctx, method):
    args = (POINT_STATE, method, POINT_OFFSET)
    expected = ctx.reference(p12.point, *args)
    assert_close(ctx.student(p12.point, *args), expected, f"{method}(B_r_BQ)", EXACT,
                 _point_mistakes(method, POINT_STATE, POINT_OFFSET),
                 context=f"on a fixed turned and moving body (A_IB = {compact(POINT_STATE['A_IB'])}, "
                         f"B_r_BQ = {compact(POINT_OFFSET)})")
    ctx.compare_random(
        p12.point, st.tuples(STATES, st.just(method), POINTS), name=f"{method}(B_r_BQ)", tol=EXACT,
        mistakes=lambda args, expected: _point_mistakes(method, args[0], args[2]), examples=15,
        describe=lambda args: f"{describe_state(args[0])}, B_r_BQ = {compact(args[2])}",
    )


@check(1, title="position_of_point: I_r_IQ = A_IB (B_r_IB + B_r_BQ) on random states", stage=STAGE_RANDOM,
       group="position_of_point")
def check_position_of_point(ctx):
    _point_check(ctx, "position_of_point")


@check(1, title="velocity_of_point: I_v_Q = A_IB (B_v_B + omega x B_r_BQ) on random states", stage=STAGE_RANDOM,
       group="velocity_of_point")
def check_velocity_of_point(ctx):
    _point_check(ctx, "velocity_of_point")


@check(1, title="acceleration_of_point: I_a_Q = A_IB (B_a_B + (skew(omegaDot) + skew(omega)^2) B_r_BQ) on "
       "random states", stage=STAGE_RANDOM, group="acceleration_of_point")
def check_acceleration_of_point(ctx):
    _point_check(ctx, "acceleration_of_point")


@check(2, title="part (b): the x-y traces of B and Q over 3 s (3001 steps of 1 ms) follow the reference (and those "
       "of a point of its own)",
       stage=STAGE_VALUES, group="wheel")
def check_wheel(ctx):
    sheet = ctx.reference(p12.constants)
    args = (sheet_state(sheet["PART_B"]), WHEEL_DT, WHEEL_STEPS, sheet["B_R_BQ"], WHEEL_EVERY)
    expected = ctx.reference(p12.wheel, *args, persist=True)
    got = ctx.student(p12.wheel, *args, timeout=20)
    keys = ("I_r_IB", "I_r_IQ")
    traces = {key: trace_array(got, key, expected[key].shape) for key in keys}
    ctx.add_figure(figure(
        "Problem 12(b): x-y traces of B and Q", "x [m]", "y [m]",
        student=[(p, *subsample(traces[f"I_r_I{p}"][:, 0], traces[f"I_r_I{p}"][:, 1])) for p in "BQ"],
        reference=[(p, *subsample(expected[f"I_r_I{p}"][:, 0], expected[f"I_r_I{p}"][:, 1])) for p in "BQ"],
        equal_axes=True,
    ))
    try:
        assert_traces(traces, expected, keys, SIMULATION, dt=WHEEL_DT)
        # the same wheel with a point Q of its own over its first 0.3 s, drawn anew (no key holds it)
        point = ctx.draw(lambda rng: [float(x) for x in rng.uniform(-0.5, 0.5, 3)])
        args = (sheet_state(sheet["PART_B"]), WHEEL_DT, WHEEL_STEPS // 10, point, WHEEL_EVERY)
        expected = ctx.reference(p12.wheel, *args)
        got = ctx.student(p12.wheel, *args, timeout=20)
        assert_traces({key: trace_array(got, key, expected[key].shape) for key in keys}, expected, keys,
                      SIMULATION, what=f"for the point B_r_BQ = {np.round(point, 4).tolist()}", dt=WHEEL_DT)
    except CheckFailure as exc:
        fail(exc.message, "The checks of integration_step and position_of_point above localize the mistake.",
             exc.diagnosis, evidence=exc.evidence)
