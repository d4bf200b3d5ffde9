"""Checks of problem 24: the rotational joint and the recursive forward kinematics of positions and orientations
(``Body.forward_kinematics``, ``Joint.successor_pose``, ``RotationalJoint.joint_pose``)."""

from grader.checking import STAGE_RANDOM, STAGE_STRUCTURE, STAGE_VALUES, STRUCTURE, assert_rotation, check, confirmed
from probes import problem_24 as p24

from ._trees import (
    assert_tree_no_side_effects,
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
from ._upstream import held, judged

TITLE = "Rotational Joint and Recursive Forward Kinematics"

#: rotational joints and the probe's test joint (a relative translation for the generic pass)
KINDS = ("rotational", "test")


#: the configuration in which a known mistake named in the sheet's must hold as well: no angle a multiple of pi/4
SECOND_Q = (0.7, 0.4, -1.1)


def _pendulum(ctx):
    case = ctx.reference(p24.pendulum_case)
    return case["description"], case["q"]


@check(1, title="the orientations A_IB of every body of random trees are proper rotations", stage=STAGE_STRUCTURE,
       group="trees")
def check_orientations(ctx):
    def compare(got, expected, args):
        for name, body in zip(expected["names"], bodies_of(got, expected["names"])):
            assert_rotation(body["A_IB"], f"A_IB of {name}", STRUCTURE)

    args = rich_case(KINDS, motion=False)
    compare(ctx.student(p24.tree_poses, *args), ctx.reference(p24.tree_poses, *args), args)
    ctx.compare_random(p24.tree_poses, cases(KINDS, motion=False), name="A_IB", tol=STRUCTURE,
                       compare=compare, examples=10, describe=describe_case)


@check(2, title="the triple pendulum at q = (pi/6, -pi/4, pi/3): A_IB and B_r_IB of every body",
       stage=STAGE_VALUES, group="pendulum")
def check_pendulum(ctx):
    description, q = _pendulum(ctx)
    mistakes = candidates(ctx, description, q)
    own = judged(ctx, p24.pendulum, q)  # the reference's pendulum with the student's R3 (problem 6)
    got = ctx.student(p24.pendulum, q)
    expected = ctx.reference(p24.pendulum, q)
    drawing = configuration_figure("Problem 24: the triple pendulum at q = (pi/6, -pi/4, pi/3)", got, expected)
    if drawing is not None:
        ctx.add_figure(drawing)
    # a known mistake is named where it holds in a second configuration too (its reference calls are in the key)
    other = ctx.catalogue(lambda: [ctx.reference(p24.pendulum, SECOND_Q), candidates(ctx, description, SECOND_Q)])

    def again():
        compare_states(ctx.student(p24.pendulum, SECOND_Q), other[0], mistakes=other[1],
                       context="(the sheet's configuration)")

    def shown(known):
        compare_states(got, expected, mistakes=mistakes if known else (), context="(the sheet's configuration)",
                       known=known)

    held(ctx, own, lambda: confirmed(shown, again),
         lambda value: compare_states(got, value, context="(the sheet's configuration)"))


@check(3, title="random trees of rotational joints: A_IB and B_r_IB of every body, in recursion order",
       stage=STAGE_RANDOM, group="trees")
def check_random_trees(ctx):
    compare_trees(ctx, p24.tree_poses, KINDS, tree_comparison(ctx, motion=False), motion=False,
                  name="the bodies' poses")


@check(1, title="forward_kinematics leaves q unchanged, and a tree used again gives what a fresh tree gives (no "
       "state kept between calls)", stage=STAGE_RANDOM + 1, group="trees")
def check_side_effects(ctx):
    description, q = rich_case(KINDS, motion=False)
    assert_tree_no_side_effects(ctx, description, (q,), (q[::-1] - 0.4,))


# ------------------------------------------------------------------------------------------ the motion
# The sheet's second part animated a recorded Simscape run; the course's port simulates the pendulum instead
# (problem_24.simulate, with the equations of motion of problem 37) and grades the motion by physics.  The block
# is self-contained (its own imports) so that it stays apart from the kinematic checks above.

import numpy as np  # noqa: E402

from grader.checking import EXACT, Mistake, Tol, assert_close, close, fail  # noqa: E402
from probes import _dynamics as probe_dynamics  # noqa: E402

from ._dynamics import assert_energy_conserved, assert_run, run_array, run_figure  # noqa: E402

#: problem data P24: released at rest from Q under gravity along -y
SIMULATION_Q0 = (np.pi / 6, -np.pi / 4, np.pi / 3)
SIMULATION_GRAV = np.array([0.0, -9.81, 0.0])
SIMULATION_T_END = 2.0
#: simulate()'s output step (its default dt)
SIMULATION_DT = 0.01
#: the motion is chaotic: runs are compared over the first second only
HORIZON = 1.0
#: any solve_ivp method at its default tolerances: energy drift <= 0.94 J over 2 s, within 0.015 rad and 0.15 rad/s
#: of a tight run over the first second; a fixed-step Euler loop at dt = 0.01 s drifts by 51 J
SIMULATION_ENERGY = Tol("energy drift (a reasonable integrator: 0.94 J of 389 J)", 4.0)
SIMULATION_BAND = {"q": Tol("a reasonable integrator", 5e-2), "qd": Tol("a reasonable integrator", 0.5)}
SIMULATION_TIMEOUT = 30.0
#: the run released from a configuration of its own is compared over this time [s]: RK45 at its defaults parts
#: from a tight run sooner than the other methods, and over 0.5 s it left the band in 6 of 400 drawn starts
OWN_T_END = 0.3
#: that run's start: every angle within this of 0 [rad], every speed between these in size, either sign [rad/s];
#: over 50 draws RK45 at its defaults leaves a tight run by 0.015 rad and 0.19 rad/s at most (29 % and 38 % of
#: SIMULATION_BAND), RK23, DOP853 and LSODA by 4 % at most (tests/test_run_bands.py)
OWN_Q0 = 1.0
OWN_QD0 = (0.5, 1.5)
#: that run's output step, one of these [s] (none the default 0.01 s)
OWN_DT = (0.005, 0.02, 0.025)


def draw_start(rng):
    """The arguments ``[q0, qd0, dt]`` of the run released from a configuration of its own: angles up to
    ``OWN_Q0``, speeds of order 1 rad/s, none of them near 0 (a run that ignored ``qd0`` would start at rest), an
    output step of ``OWN_DT`` (a run that ignored ``dt`` would output every 0.01 s)."""
    q0 = rng.uniform(-OWN_Q0, OWN_Q0, 3)
    qd0 = rng.choice((-1.0, 1.0), 3) * rng.uniform(*OWN_QD0, 3)
    return [[float(x) for x in q0], [float(x) for x in qd0], float(rng.choice(OWN_DT))]


def _assert_start(run, q0, qd0, what):
    """The run's first output is its start ``(q0, qd0)``: the angles and the speeds told apart, each named."""
    for key, value in (("q", q0), ("qd", qd0)):
        assert_close(np.asarray(run[key])[0], value, f"{key} at t = 0", EXACT, context=f"({what})",
                     note="The run starts from the state it is given: q = q0 and qd = qd0 at t = 0.")


def _assert_output_times(run, expected, what, dt=SIMULATION_DT):
    """The run's output times are the reference's (every ``dt`` from 0): the states are compared row by row, so a
    run whose times are shifted would otherwise pass with the right states at the wrong times.  Times at the
    default step where another ``dt`` is given are the argument ignored; times that are some of the expected ones
    are told by those left out or kept twice (``run_array``)."""
    expected = np.asarray(expected, dtype=float)
    note = f"An output every dt = {dt:g} s from 0 to {expected[-1]:g} s (the t_eval of solve_ivp)."
    t = run_array(run, "t", None, what)
    if dt != SIMULATION_DT and t.size != expected.size:
        default = np.linspace(0.0, expected[-1], int(round(expected[-1] / SIMULATION_DT)) + 1)
        if t.shape == default.shape and close(t, default, EXACT):
            fail(f"the output times of {what} lie {SIMULATION_DT:g} s apart, the default step, not the dt = "
                 f"{dt:g} s it is given.\n{note}", "Output every dt that simulate is given (t_eval from dt), not "
                 "at the default step.", "ignored_argument")
    run_array(run, "t", None, what, times=expected)
    if t.shape != expected.shape:
        fail(f"the output times of {what} are {t.size} values, expected {expected.size}.\n{note}",
             diagnosis="shape")
    if close(t, expected, EXACT):
        return
    shifts = [Mistake("time_shift", expected + sign * dt, "The states are right, the times beside them "
                      "are not: return the times solve_ivp returns (result.t), which start at t = 0.")
              for sign in (1, -1)]
    assert_close(t, expected, f"the output times of {what}", EXACT, shifts, note=note)


@check(2, title="simulate(): released at rest from q = (pi/6, -pi/4, pi/3), the pendulum conserves its energy over "
       "2 s and follows a tight reference run over the first second (uses the equations of motion of problem 37)",
       stage=STAGE_VALUES, group="motion")
def check_simulated_motion(ctx):
    expected = ctx.reference(probe_dynamics.pendulum_motion, SIMULATION_T_END, SIMULATION_GRAV, persist=True)
    got = ctx.student(probe_dynamics.pendulum_motion, SIMULATION_T_END, SIMULATION_GRAV, timeout=SIMULATION_TIMEOUT)
    what = f"problem_24.simulate({SIMULATION_T_END:g})"
    for key in ("t", "q", "qd"):
        run_array(got, key, np.shape(expected[key]), what, times=expected["t"])
    ctx.add_figure(run_figure("Problem 24: the triple pendulum's joint angles", "q [rad]", got["t"], got["q"],
                              expected["t"], expected["q"], ["q1", "q2", "q3"]))
    ctx.add_figure(run_figure("Problem 24: the energy T + V (conserved)", "E [J]", got["t"],
                              np.column_stack([got["T"] + got["V"]]), expected["t"],
                              np.column_stack([expected["T"] + expected["V"]]), ["T + V"]))
    _assert_output_times(got, expected["t"], what)
    start = np.concatenate([SIMULATION_Q0, np.zeros(3)])
    if not close(np.concatenate([got["q"][0], got["qd"][0]]), start, EXACT):
        assert_close(np.concatenate([got["q"][0], got["qd"][0]]), start, "(q, qd) at t = 0", EXACT,
                     context="(the pendulum is released at rest from the sheet's configuration)")
    assert_energy_conserved(got, SIMULATION_ENERGY, "the unactuated pendulum",
                            "The energy of your own pendulum drifts: either M, f, g (problem 37) or the integration is "
                            "off. With the checks of problem 37 passing, use scipy.integrate.solve_ivp (any method at "
                            "its default tolerances conserves the energy well enough).")
    within = np.asarray(expected["t"]) <= HORIZON
    head = {key: np.asarray(got[key])[within] for key in ("t", "q", "qd")}
    ours = {key: np.asarray(expected[key])[within] for key in ("t", "q", "qd")}
    assert_run(head, ours, ("q", "qd"), SIMULATION_BAND, "the first second of the run", roots=(got, expected),
               note="Any solve_ivp method at its default tolerances stays within the band; later the motion is "
                    "chaotic and accurate runs part.")
    # released from a configuration and with speeds of its own, output at a step of its own, drawn anew at each
    # grading (no key holds its run)
    q0, qd0, dt = ctx.draw(draw_start)
    ours = ctx.reference(probe_dynamics.pendulum_motion, OWN_T_END, SIMULATION_GRAV, q0, qd0, dt)
    mine = ctx.student(probe_dynamics.pendulum_motion, OWN_T_END, SIMULATION_GRAV, q0, qd0, dt,
                       timeout=SIMULATION_TIMEOUT)
    own = f"problem_24.simulate({OWN_T_END:g}, q0, qd0, dt={dt:g})"
    released = f"the run released at q0 = {np.round(q0, 4).tolist()} with qd0 = {np.round(qd0, 4).tolist()}"
    _assert_output_times(mine, ours["t"], own, dt)
    _assert_start(mine, q0, qd0, released)
    assert_run(mine, ours, ("q", "qd"), SIMULATION_BAND, f"{released} (the first {OWN_T_END:g} s)",
               note="Any solve_ivp method at its default tolerances stays within the band.")
