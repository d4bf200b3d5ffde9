"""Checks of problem 14: the screw axis along the sheet's simulated motion.

T is judged by its defining property against the student's own state at every step (any point of the axis is
accepted); the motion itself is compared with the reference.
"""

import numpy as np

from checks._figures import add_screw_run
from checks._real import real, require_real
from checks._rigid import SIMULATION, STATE, assert_traces, compact, sheet_state, trace_array
from checks.problem_13 import assert_screw
from checks.problem_12 import GENERIC
from grader.checking import EXACT, STAGE_STRUCTURE, STAGE_VALUES, CheckFailure, assert_close, check, close, fail
from probes import problem_12 as p12, problem_13 as p13, problem_14 as p14

TITLE = "Visualizing Twists"

DT, STEPS = 0.01, 100  # t_end = 1 s with the course's loop


def _start(ctx):
    return sheet_state(ctx.reference(p14.constants)["INITIAL"])


def _own_start(ctx):
    """A start of its own (velocities and accelerations drawn anew at each grading: no key holds its run)."""
    drawn = ctx.draw(lambda rng: {key: [float(x) for x in rng.uniform(-1.5, 1.5, 3)]
                                  for key in ("B_v_B", "B_omega_B", "B_a_B", "B_omegaDot_B")})
    return sheet_state(drawn)


@check(1, title="screw_axis() without rotation (omega = 0) returns zero vectors, as its docstring says",
       stage=STAGE_STRUCTURE, group="at_rest")
def check_screw_at_rest(ctx):
    moving = ctx.student(p13.screw, GENERIC)
    if close(moving, np.zeros((2, 3)), EXACT):
        fail(f"screw_axis() returns zero vectors for a rotating body too (B_omega_B = {compact(GENERIC['B_omega_B'])}): "
             "the zero answer is meant for omega = 0 only.",
             "With rotation, T is on the screw axis: B_r_BT = (omega x v_B) / |omega|^2; return zeros only when "
             "omega @ omega == 0.", "always_zero")
    state = {**_start(ctx), "B_v_B": np.array([1.0, -2.0, 0.5]), "B_omega_B": np.zeros(3)}
    try:
        assert_close(ctx.student(p13.screw, state), np.zeros((2, 3)), "screw_axis() with omega = 0",
                     EXACT)
    except CheckFailure as exc:
        fail(exc.message, "Without rotation there is no screw axis: test omega @ omega == 0 before dividing by it "
             "and return two zero vectors.", exc.diagnosis, evidence=exc.evidence)


@check(1, title="the sheet's run (100 steps of 0.01 s): the body's state follows the reference",
       stage=STAGE_VALUES, group="run")
def check_run_state(ctx):
    for start, what in ((_start(ctx), ""), (_own_start(ctx), "from a start of its own")):
        expected = ctx.reference(p12.integrate, start, DT, STEPS)
        got = ctx.student(p12.integrate, start, DT, STEPS)
        try:
            assert_traces(got, expected, STATE, SIMULATION, what=what, dt=DT)
        except CheckFailure as exc:
            fail(exc.message, "This is the integration step of problem 12: its checks localize the mistake.",
                 exc.diagnosis, evidence=exc.evidence)


@check(3, title="the sheet's run: at every step T lies on the screw axis and moves parallel to omega",
       stage=STAGE_VALUES, group="run")
def check_run_screw(ctx):
    expected = ctx.reference(p14.screw_run, _start(ctx), DT, STEPS)
    got = ctx.student(p14.screw_run, _start(ctx), DT, STEPS)
    add_screw_run(ctx, "Problem 14: the body's path and its screw axis at t = 0, 0.25, 0.5, 0.75, 1 s", got,
                  expected)
    start = _own_start(ctx)
    own = ctx.student(p14.screw_run, start, DT, STEPS)  # a run of its own: no key holds it
    own_expected = ctx.reference(p14.screw_run, start, DT, STEPS)
    n = STEPS + 1
    for run, ours, what in ((got, expected, ""), (own, own_expected, " of the run from a start of its own")):
        screws = trace_array(run, "screw", (n, 2, 3))
        w, v = trace_array(run, "B_omega_B", (n, 3)), trace_array(run, "B_v_B", (n, 3))
        require_real(f"the screw axis along your run{what}", "run (B_omega_B and B_v_B at every step)", [
            real("B_omega_B over the run", w, reference=ours["B_omega_B"]),
            real("B_v_B over the run", v, reference=ours["B_v_B"])])
        for i in range(n):
            assert_screw(screws[i], w[i], v[i], where=f"after {i} step{'s' * (i != 1)} (t = {i * DT:g} s){what}")
