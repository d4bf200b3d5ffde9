"""Checks of problem 37: the equations of motion by projected Newton-Euler (``DynamicBody.mfg_contribution``,
``forward_dynamics``), the three controllers and the robot's simulation under each.

Physics first: ``M`` symmetric positive-definite, the kinetic energy and the potential energy of the student's own
kinematics, Lagrange's equations for ``f`` with the student's own ``M`` (each where the student's own model is real:
``checks._real``).  Then the values against the reference with a catalogue of known mistakes, on the robot (square
Jacobians) and on random trees.  The controllers are judged by their torques at random states and by their
behaviour: computed torques track the path, gravity compensation holds the arm still while it is not commanded to
move, PD alone sags.  ``robot_ode`` is also called at several states in turn on one tree, as an integrator calls
it: a mass matrix computed once and reused gives the right value on a fresh tree, and computed torques cancel
whichever ``M`` they are given, so neither the random states nor that run show it.  The student's simulations run
once per grading, in the sandbox, on the reference's desired trajectory; the reference's runs are cached on disk.
"""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    CheckFailure,
    Mistake,
    Tol,
    assert_close,
    check,
    close,
    fail,
)
from probes import _dynamics as probe_dynamics, problem_37 as p37

from ._dynamics import (
    H,
    ROBOT,
    assert_fresh_along_a_run,
    assert_run,
    check_gravity_gradient,
    check_kinetic_energy,
    check_lagrange,
    check_spd,
    compare_mfg,
    defaulted_blocks,
    describe_case,
    rich_case,
    robot_cases,
    run_array,
    run_figure,
    tree_cases,
    wrong_start,
)
from ._real import is_real, mass_matrix_flaw, real, require_real
from ._upstream import judging

TITLE = "Robotic Arm. 2 - Controller Evaluation"

#: the sheet's gains and gravity (problem data P32, P37)
P_GAIN, D_GAIN = 10.0, 50.0
ROBOT_GRAV = np.array([0.0, -9.81, 0.0])
CONTROLLERS = ("pd", "gravity_compensation", "computed_torques")
NAMES = {"pd": "PD", "gravity_compensation": "gravity compensation", "computed_torques": "computed torques"}
#: how far a run may stray from the tight reference run: any solve_ivp method at its default tolerances stays within
#: 0.004 rad and 0.02 rad/s; a fixed-step Euler loop with a step the fast mode (about 110 1/s) cannot follow does not
BAND = {"q": Tol("a reasonable integrator", 1e-2), "qd": Tol("a reasonable integrator", 5e-2)}
#: computed torques keep the end effector this close to the path [m] (the reference: 1e-6)
TRACK = 0.02
#: gravity compensation holds the joints this still until 0.25 s [rad] (the reference: 0)
HOLD = 1e-3
#: PD alone lets the end effector sink at least this far below the path by 0.25 s [m] (the reference: 0.096)
SAG = 0.05
T_REST = 0.25
T_END = 2.0
#: how long each controller's run is simulated [s]: computed torques over the whole path; PD and gravity
#: compensation until the end of the acceleration phase, where their sag and lag have shown (keeps grading fast)
T_RUN = {"computed_torques": T_END, "gravity_compensation": 0.75, "pd": 0.75}
#: seconds allowed for one of the student's simulations (the reference takes about 1 s)
SIMULATION_TIMEOUT = 30.0
_SEEDS = st.integers(0, 2**32 - 1)

INITIAL_HINT = ("The simulation starts on the desired trajectory at rest: y0 = (q_des(0), qd_des(0)), the first row "
                "of the table passed to simulate.")
ODE_HINT = ("Your robot_ode differs from the reference's at three states of the reference's run (the check of "
            "robot_ode above says why, or, where it was judged on your own M, f, g, the checks of M, f, g); fix it "
            "first, the simulation follows.")


# ------------------------------------------------------------------------------------------ physics


def _physics(ctx, compare, examples=8):
    """``compare(got, expected, args)`` (a property of the student's own model) on a rich case and on random trees;
    where it fails on the student's own shared functions of earlier problems (their ``R3`` inside every rotational
    joint), ``M``, ``f``, ``g`` are judged on what the reference's code makes of them (error carried forward)."""
    extra = (H,)
    args = rich_case(extra=extra)
    expected = ctx.reference(probe_dynamics.lagrange, *args)
    judged_compare = judging(ctx, probe_dynamics.lagrange, compare, lambda got, value, a: compare_mfg(got, value, {}))
    judged_compare(ctx.student(probe_dynamics.lagrange, *args), expected, args)
    ctx.compare_random(probe_dynamics.lagrange, tree_cases(extra=extra), name="M, f, g", tol=EXACT,
                       compare=judged_compare, examples=examples, describe=describe_case)


@check(2, title="M is symmetric positive-definite on random trees (rotational, prismatic, rolling, 3-DOF and rigid "
       "joints)", stage=STAGE_STRUCTURE, group="mass_matrix")
def check_mass_matrix(ctx):
    _physics(ctx, check_spd)


@check(2, title="qd.T M qd / 2 is the kinetic energy sum(m v.v + omega.I omega) / 2 from your own Jacobians",
       stage=STAGE_STRUCTURE, group="kinetic_energy")
def check_kinetic_energy_matches(ctx):
    _physics(ctx, check_kinetic_energy)


@check(1, title="g is minus the gradient of your own potential energy V = -sum(m I_grav . I_r_IB) (finite "
       "differences)", stage=STAGE_STRUCTURE, group="potential")
def check_gravity_is_potential(ctx):
    _physics(ctx, check_gravity_gradient)


@check(2, title="f satisfies Lagrange's equations with your own M: f = -Mdot qd + d/dq (qd.T M qd / 2)",
       stage=STAGE_STRUCTURE, group="lagrange")
def check_lagrange_equations(ctx):
    _physics(ctx, check_lagrange)


# ------------------------------------------------------------------------------------------ values


def _compare_mfg(ctx):
    def compare(got, expected, args):
        compare_mfg(got, expected, ctx.reference(probe_dynamics.mfg_mistakes, *args))

    return judging(ctx, probe_dynamics.mfg, compare, lambda got, value, args: compare_mfg(got, value, {}))


@check(2, title="M, f, g of the robot arm (problem 32) at random states", stage=STAGE_RANDOM, group="robot")
def check_robot_mfg(ctx):
    ctx.compare_random(probe_dynamics.mfg, robot_cases(ROBOT, 3, ROBOT_GRAV), name="M, f, g", tol=EXACT,
                       compare=_compare_mfg(ctx), examples=10, describe=describe_case)


@check(3, title="M, f, g of random trees with masses and inertias", stage=STAGE_RANDOM, group="trees")
def check_tree_mfg(ctx):
    compare = _compare_mfg(ctx)
    args = rich_case()
    compare(ctx.student(probe_dynamics.mfg, *args), ctx.reference(probe_dynamics.mfg, *args), args)
    ctx.compare_random(probe_dynamics.mfg, tree_cases(), name="M, f, g", tol=EXACT, compare=compare, examples=12,
                       describe=describe_case)


def _spd(rng, n=3):
    A = rng.uniform(-1, 1, (n, n))
    return A @ A.T + 0.5 * np.eye(n)


@st.composite
def _dynamics_cases(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    return (_spd(rng), *rng.uniform(-3, 3, (3, 3)))


@check(1, title="forward_dynamics(M, f, g, tau) solves M qdd = f + g + tau", stage=STAGE_RANDOM,
       group="forward_dynamics")
def check_forward_dynamics(ctx):
    def mistakes(args, expected):
        M, f, g, tau = args
        return [
            Mistake("multiplied_not_solved", M @ (f + g + tau), "Solve M qdd = f + g + tau for qdd "
                    "(np.linalg.solve(M, f + g + tau)); you multiplied by M."),
            Mistake("missing_torque", np.linalg.solve(M, f + g), "The torques act too: M qdd = f + g + tau."),
            Mistake("sign_flip", np.linalg.solve(M, -(f + g + tau)), "M qdd = f + g + tau: f, g and tau are on the "
                    "right-hand side with a plus sign."),
        ]

    ctx.compare_random(probe_dynamics.forward_dynamics, _dynamics_cases(), name="forward_dynamics(M, f, g, tau)",
                       tol=EXACT, mistakes=mistakes, examples=10)


# ------------------------------------------------------------------------------------------ controllers


@st.composite
def _controller_cases(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    return ([(_spd(rng), *rng.uniform(-3, 3, (7, 3)))],)


def _pd(case):
    _, _, _, q, qd, q_des, qd_des, _ = case
    return P_GAIN * (q_des - q) + D_GAIN * (qd_des - qd)


def _describe_controller_case(args):
    names = ("M", "f", "g", "q", "qd", "q_des", "qd_des", "qdd_des")
    return ", ".join(f"{name} = {np.round(np.asarray(value), 4).tolist()}" for name, value in zip(names, args[0][0]))


def _controller_check(ctx, controller, mistakes):
    def compare(got, expected, args):
        case = args[1][0]
        assert_close(got[0] if isinstance(got, list) and got else got, expected[0],
                     f"the torques of {NAMES[controller]}", EXACT,
                     [Mistake(name, value, hint) for name, value, hint in mistakes(case)])

    ctx.compare_random(p37.torques, _controller_cases().map(lambda args: (controller, *args)),
                       name=NAMES[controller], tol=EXACT, compare=compare, examples=10,
                       describe=lambda args: _describe_controller_case(args[1:]))


@check(1, title="gravity_compensation_torque: tau = -g + P (q_des - q) + D (qd_des - qd) at random states",
       stage=STAGE_RANDOM, group="gravity_compensation_torque")
def check_gravity_compensation_torque(ctx):
    def mistakes(case):
        g, pd = case[2], _pd(case)
        return [
            ("gravity_sign", g + pd, "Gravity compensation cancels g: M qdd = f + g + tau needs tau = -g (problem "
             "32), plus the PD torques."),
            ("missing_pd", -g, "Controller 2 is the PD controller plus the gravity compensation: tau = -g + PD."),
        ]

    _controller_check(ctx, "gravity_compensation", mistakes)


@check(2, title="computed_torque: tau = M qdd_des - f - g + P (q_des - q) + D (qd_des - qd) at random states",
       stage=STAGE_RANDOM, group="computed_torque")
def check_computed_torque(ctx):
    def mistakes(case):
        M, f, g, _, _, _, _, qdd_des = case
        pd = _pd(case)
        return [
            ("f_sign", M @ qdd_des + f - g + pd, "M qdd = f + g + tau: to get qdd_des, tau = M qdd_des - f - g "
             "(+ PD); yours adds f."),
            ("missing_f", M @ qdd_des - g + pd, "Computed torques compensate Coriolis and centrifugal forces too: "
             "tau = M qdd_des - f - g + PD."),
            ("gravity_sign", M @ qdd_des - f + g + pd, "tau = M qdd_des - f - g + PD: the gravity term is -g."),
            ("missing_mass_matrix", qdd_des - f - g + pd, "The desired accelerations need the torques M qdd_des."),
            ("pd_through_mass_matrix", M @ (qdd_des + pd) - f - g, "The sheet adds the PD torques after the model: "
             "tau = M qdd_des - f - g + P (q_des - q) + D (qd_des - qd), not M (qdd_des + PD) - f - g."),
            ("missing_pd", M @ qdd_des - f - g, "Controller 3 keeps the PD part: tau = M qdd_des - f - g + PD."),
        ]

    _controller_check(ctx, "computed_torques", mistakes)


def _table(ctx):
    return ctx.reference(p37.trajectory, persist=True)


def _rows_around(table, t):
    """The rows of the table around ``t`` (two on each side): what linear interpolation at ``t`` needs, and small
    enough to send with every random case."""
    times = np.asarray(table["t"])
    k = int(np.clip(np.searchsorted(times, t, side="right") - 1, 0, times.size - 2))
    rows = slice(max(k - 1, 0), min(k + 3, times.size))
    return {key: np.asarray(table[key])[rows] for key in ("t", "q", "qd", "qdd")}


def _ode_cases(table, controller):
    """Random (t, y) for ``controller``; t lies in the later half of its interval of the table, where the nearest row
    (the next) and the row before t differ, so that taking either instead of interpolating is told apart."""
    times = np.asarray(table["t"])

    @st.composite
    def draw_case(draw):
        rng = np.random.default_rng(draw(_SEEDS))
        k = int(rng.integers(0, times.size - 1))
        t = float(times[k] + (times[k + 1] - times[k]) * rng.uniform(0.55, 0.95))
        return controller, _rows_around(table, t), [(t, rng.uniform(-2, 2, 6))]

    return draw_case()


#: the check that grades the robot's M, f, g that robot_ode is judged on
ROBOT_MFG = "p37.robot_mfg"


def _own_ode(controller, rows, t, y, mfg):
    """``(qd, qdd)`` of the robot under ``controller`` with the given ``M, f, g`` (the student's own): the desired
    state interpolated linearly in the table's rows, the sheet's controller, ``M qdd = f + g + tau``."""
    M, f, g = (np.asarray(mfg[key], dtype=float) for key in ("M", "f", "g"))
    q, qd = np.asarray(y[:3], dtype=float), np.asarray(y[3:], dtype=float)
    times = np.asarray(rows["t"], dtype=float)
    q_des, qd_des, qdd_des = (np.array([np.interp(t, times, column) for column in np.asarray(rows[key]).T])
                              for key in ("q", "qd", "qdd"))
    pd = _pd((M, f, g, q, qd, q_des, qd_des, qdd_des))
    tau = {"pd": pd, "gravity_compensation": pd - g, "computed_torques": pd + M @ qdd_des - f - g}[controller]
    return np.concatenate([qd, np.linalg.solve(M, f + g + tau)])


@check(2, title="robot_ode(t, y, tree, trajectory, controller) = (qd, qdd) at random times and states, for each "
       "controller (the right-hand side of the simulations below), and called along a run on one tree as on fresh "
       "ones", stage=STAGE_STRUCTURE, group="runs")
def check_robot_ode(ctx):
    def compare(answer, reference, args):
        controller, rows, [(t, y)] = args
        expected = [reference[0]["ode"]]
        times = rows["t"]
        nearest = float(times[np.argmin(np.abs(times - t))])
        previous = float(times[max(np.searchsorted(times, t, side="right") - 1, 0)])
        found = [Mistake("nearest_sample", ctx.reference(p37.robot_ode, controller, rows, [(nearest, y)])[0],
                         "Interpolate the desired values linearly between the table's rows (np.interp per column); "
                         "you took the nearest row."),
                 Mistake("previous_sample", ctx.reference(p37.robot_ode, controller, rows,
                                                          [(previous, y)])[0],
                         "Interpolate the desired values linearly between the table's rows (np.interp per column); "
                         "you took the row before t."),
                 Mistake("state_order", np.concatenate([expected[0][3:], expected[0][:3]]),
                         "dy/dt = (qd, qdd) for y = (q, qd): the velocities come first.")]
        name = f"robot_ode at t = {t:.6g} with the {NAMES[controller]} controller"
        got = [_ode_of(answer)]
        if close(got[0], expected[0], EXACT):
            return
        own = _own_mfg(answer, reference)
        if own is None:
            assert_close(got[0], expected[0], name, EXACT, found)
            return
        require_real(name, "M, f, g of the robot", _mfg_findings(own, reference[0]["mfg"]))
        own_ode = _own_ode(controller, rows, t, y, own)
        if close(got[0], own_ode, EXACT):
            ctx.carry_forward(ROBOT_MFG, "M, f, g")
            return
        assert_close(got[0], own_ode, name, EXACT, found, context="(judged on your own M, f, g of the robot)",
                     note="Your M, f, g differ from the reference's (their own check says how); robot_ode is judged "
                          "on them.")

    table = _table(ctx)
    for controller in CONTROLLERS:  # each controller on inputs of its own
        ctx.compare_random(p37.robot_ode_with_mfg, _ode_cases(table, controller), name="robot_ode",
                           tol=EXACT, examples=4, compare=compare, describe=lambda args: f"controller {args[0]!r}, "
                           f"t = {args[2][0][0]:.6g}, y = {np.round(args[2][0][1], 4).tolist()} (the desired "
                           "trajectory of problem 32)")
    for controller in CONTROLLERS:
        _assert_fresh_along_a_run(ctx, controller, table)


#: states ``(t, y)`` at which robot_ode is called in turn on one tree, as solve_ivp calls it: times inside the
#: table's intervals, configurations far enough apart that M differs
RUN_STATES = ((0.555, np.array([0.3, -0.5, -1.4, 0.4, -0.3, 0.6])),
              (0.955, np.array([0.6, -0.8, -1.1, -0.5, 0.8, 0.2])),
              (1.355, np.array([0.9, -0.3, -1.7, 0.3, 0.5, -0.7])))
STALE_HINTS = {
    "M": "M depends on q: compute M, f, g from the state y at every call of robot_ode; yours reuses the M of its "
         "first call. Computed torques hide it (tau = M qdd_des - f - g + PD, and qdd = M^-1 (f + g + tau) cancels "
         "whichever M is used), so that run still tracks the path; the other controllers, and problem 46, do not.",
    "model": "M, f and g depend on the state: compute them from y at every call of robot_ode; yours reuses those of "
             "its first call. Computed torques hide it (tau = M qdd_des - f - g + PD cancels whichever model is "
             "used), so that run still tracks the path; the other controllers do not.",
}


def _assert_fresh_along_a_run(ctx, controller, table):
    """robot_ode called at ``RUN_STATES`` in turn on one tree (as solve_ivp calls it) gives what it gives on a
    fresh tree: a model computed once and reused is ``stale_mass_matrix``."""
    stale = ctx.reference(p37.stale_mass_matrix, controller, table, RUN_STATES)
    assert_fresh_along_a_run(
        ctx, p37.robot_ode, (controller, table), RUN_STATES, f"robot_ode with the {NAMES[controller]} "
        f"controller", [("stale_mass_matrix", stale[key], STALE_HINTS[key]) for key in ("M", "model")],
        describe=lambda case: f"t = {case[0]:g}, y = {np.round(case[1], 4).tolist()}")


def _ode_of(answer):
    """The student's ``robot_ode`` value of a ``robot_ode_with_mfg`` reply."""
    if not isinstance(answer, list) or len(answer) != 1 or not isinstance(answer[0], dict):
        fail(f"the probe could not read robot_ode back, got {str(answer)[:200]}")
    return answer[0].get("ode")


def _own_mfg(answer, reference):
    """The student's own M, f, g at the case, when they are there and differ from the reference's; else None."""
    own, ours = answer[0].get("mfg"), reference[0]["mfg"]
    if not isinstance(own, dict) or any(own.get(key) is None for key in ("M", "f", "g")):
        return None
    if all(close(own[key], ours[key], EXACT) for key in ("M", "f", "g")):
        return None
    return own


def _mfg_findings(own, ours):
    """Whether the student's own M, f, g are a real model (``checks._real``): M positive-definite, f and g not zero
    or constant where the reference's are not."""
    return [("M", mass_matrix_flaw(own["M"])), real("f", own["f"], reference=ours["f"]),
            real("g", own["g"], reference=ours["g"])]


# ------------------------------------------------------------------------------------------ simulations


def _simulation(ctx, controller):
    """The student's run and the reference's under ``controller``, with figures of the end effector's position and
    velocity against the desired ones."""
    table = _table(ctx)
    t_end = T_RUN[controller]
    expected = ctx.reference(p37.simulate, controller, table, t_end, persist=True)
    states = [int(i) for i in np.linspace(1, np.asarray(expected["t"]).size - 1, 3)]
    probes = [(float(expected["t"][i]), np.concatenate([expected["q"][i], expected["qd"][i]])) for i in states]
    ode = ctx.reference(p37.robot_ode, controller, table, probes)
    got = ctx.student(p37.simulate, controller, table, t_end, timeout=SIMULATION_TIMEOUT)
    t = np.asarray(expected["t"])
    n = t.size
    for key in ("t", "q", "qd", "x", "xd"):
        run_array(got, key, np.shape(expected[key]), f"simulate({controller!r}, trajectory, {t_end:g})",
                  times=expected["t"], pieces=True)
    desired = np.asarray(table["t"]) <= t_end
    name = NAMES[controller]
    for key, label, unit in (("x", "position", "m"), ("xd", "velocity", "m/s")):
        ctx.add_figure(run_figure(
            f"Problem 37, {name}: end-effector {label} against the desired one",
            f"I_{'r' if key == 'x' else 'v'}_E [{unit}]", got["t"], got[key], t, expected[key],
            [f"{axis}" for axis in "xyz"],
            extra=[(f"desired {axis}", table["t"][desired], table[key][desired][:, k])
                   for k, axis in enumerate("xyz")]))
    return table, got, expected, probes, ode, n


#: where the table of the start check begins [s] (mid-motion: q_des and qd_des differ from those at 0), and how long
#: that run lasts [s]
LATER_START, START_RUN = 1.0, 0.045
#: over that short run any solve_ivp method at its default tolerances follows the reference's within this (at most
#: 1.8e-4, BDF; RK45 7e-6), far closer than the band of a whole run: a run read from the wrong columns is told within it (the rates there are
#: small, and the band would not tell them from zero)
REREAD = Tol("a short run, a reasonable integrator", 1e-3)
#: the sheet's q_des(0), printed with five decimals
PRINTED = Tol("the sheet's five decimals", 1e-5)
TYPED_START_HINT = ("Your simulation starts from the sheet's q_des(0) whatever table it is given: start from the "
                    "table's first row, y0 = (q_des(0), qd_des(0)) of the trajectory passed to simulate (the checks "
                    "also pass tables that start elsewhere).")


def _later_table(table, start=LATER_START):
    """The desired trajectory from ``start`` on, its times shifted to begin at 0: a table the sheet does not print,
    whose first row is not q_des(0) of the sheet."""
    rows = np.asarray(table["t"]) >= start - 1e-12
    later = {key: np.asarray(table[key])[rows] for key in table}
    later["t"] = later["t"] - later["t"][0]
    return later


def _assert_starts_on_the_table(ctx, controller):
    """The run starts at the first row of the table it is given (a table that starts mid-motion), not at the
    sheet's q_des(0) typed in."""
    table = _table(ctx)
    later = _later_table(table)
    call = f"simulate({controller!r}, a table starting at q_des = {np.round(later['q'][0], 4).tolist()}, {START_RUN:g})"
    ours = ctx.reference(p37.simulate, controller, later, START_RUN, persist=True)  # (the kit's key holds it)
    got = ctx.student(p37.simulate, controller, later, START_RUN, timeout=SIMULATION_TIMEOUT)
    n = int(np.sum(np.asarray(later["t"]) <= START_RUN))
    q, qd = (run_array(got, key, (n, 3), call, times=ours["t"], pieces=True) for key in ("q", "qd"))
    mine, start = np.concatenate([q[0], qd[0]]), np.concatenate([later["q"][0], later["qd"][0]])
    if close(mine, start, EXACT):
        return
    try:
        assert_close(mine, start, f"the state (q, qd) at t = 0 of {call}", EXACT, context="(the table's first row)")
    except CheckFailure as exc:
        if _single(mine, start):  # the table's first row in single precision: a run returned so, no start of its own
            raise
        typed = defaulted_blocks(mine, start, (("q_des(0)", table["q"][0]), ("qd_des(0)", table["qd"][0])), PRINTED)
        reread = None if typed else _reread(got, ours, REREAD)
        if reread is not None:
            raise CheckFailure(exc.message, *reread, evidence=exc.evidence) from None
        hint = TYPED_START_HINT if len(typed) != 1 else TYPED_START_HINT.replace("q_des(0)", typed[0], 1)
        raise CheckFailure(exc.message, *(hint, "typed_numbers or ignored_argument") if typed else
                           wrong_start(mine, start, INITIAL_HINT), evidence=exc.evidence) from None


def _reread(got, expected, tol=BAND["q"]):
    """``(hint, "state_row")`` where the student's run is the reference's with its q or qd read from other columns of
    the solution within ``tol`` (a start that looks wrong only because the wrong columns are returned), else None."""
    from grader.diagnosis.runs import reread_runs

    found = reread_runs(got, expected, ("q", "qd"), tol)
    if found is None:
        return None
    return (f"Looks like {found.detail}: solve_ivp's y holds q in its first three rows and qd in the last three.",
            "state_row")


def _own_model(ctx, controller, table, probes):
    """True when the student's M, f, g of the robot differ from the reference's at the states ``probes`` of the
    reference's run while their robot_ode is right given them: their run is then judged on their own model."""
    reference = ctx.reference(p37.robot_ode_with_mfg, controller, table, probes)
    answer = ctx.student(p37.robot_ode_with_mfg, controller, table, probes)
    if not isinstance(answer, list) or len(answer) != len(probes) or not all(isinstance(a, dict) for a in answer):
        return False
    if not all(_own_mfg([mine], [ours]) is not None and is_real(_mfg_findings(mine["mfg"], ours["mfg"]))
               for mine, ours in zip(answer, reference)):
        return False
    return all(close(mine.get("ode"), _own_ode(controller, table, t, y, mine["mfg"]), EXACT)
               for mine, (t, y) in zip(answer, probes))


def _judged_on_own_model(ctx, controller, table, got, expected, probes):
    """The run judged on the student's own model (error carried forward): it follows the run of their own
    robot_ode, integrated by the grader's probe, within the bands; returns False when the model is the reference's
    (the run is then judged as usual)."""
    if not _own_model(ctx, controller, table, probes):
        return False
    own = ctx.student(p37.own_run, controller, table, T_RUN[controller], timeout=SIMULATION_TIMEOUT)
    for key in ("t", "q", "qd"):
        run_array(own, key, np.shape(expected[key]), "the run of your own robot_ode", times=expected["t"],
                  pieces=True)
    assert_run(got, own, ("q", "qd"), BAND, f"the {NAMES[controller]} run", pieces=True,
               note="Your M, f, g differ from the reference's (their own check says how): the run is judged on "
                    "them, against your own robot_ode integrated by the grader (solve_ivp, rtol 1e-6).")
    ctx.carry_forward(ROBOT_MFG, "M, f, g")
    return True


def _single(got, expected) -> bool:
    """True when each entry of ``got`` is ``expected``'s, or its rounding to single precision (float32): some
    states of a run returned in float32, others not."""
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    return bool(np.all((got == expected) | (got == expected.astype(np.float32).astype(float))))


def _diagnosis(ctx, controller, got, expected, probes, ode):
    """``(hint, diagnosis)`` of a run that goes wrong where the run shows it: a wrong start, or a right-hand side
    that differs from the reference's at three states of the reference's run; else None (the failure says where the
    run leaves the reference's, and the diagnosis engine names a cause if it finds one).  A start that is the given
    one in single precision is not a start of its own: the run was returned in float32."""
    start = np.concatenate([expected["q"][0], expected["qd"][0]])
    own = np.concatenate([got["q"][0], got["qd"][0]])
    if not close(own, start, EXACT) and not _single(own, start):
        return _reread(got, expected) or (INITIAL_HINT, "initial_state")
    if not close(ctx.student(p37.robot_ode, controller, _table(ctx), probes), ode, EXACT):
        return ODE_HINT, "wrong_ode"
    return None


def _diagnosed(ctx, controller, got, expected, probes, ode, check):
    """Run ``check()``; a failure gets the diagnosis of the run, when the run shows one."""
    try:
        check()
    except CheckFailure as exc:
        found = _diagnosis(ctx, controller, got, expected, probes, ode)
        if found is not None:
            raise CheckFailure(exc.message, *found, evidence=exc.evidence, explained=True) from None
        if exc.diagnosis:
            raise
        from grader.diagnosis import Evidence  # the whole run, for the diagnosis engine

        run = Evidence(np.asarray(got["q"], dtype=float), np.asarray(expected["q"], dtype=float), BAND["q"], "q",
                       got, expected)
        raise CheckFailure(exc.message, exc.hint, "", exc.candidates, run) from None


def _follow_reference(got, expected, controller):
    """The student's run stays within the bands of the reference's."""
    assert_run(got, expected, ("q", "qd"), BAND, f"the {NAMES[controller]} run", pieces=True,
               note="Any solve_ivp method at its default tolerances stays within the band.")


@check(3, title="computed torques: the end effector tracks the path within 0.02 m over the 2 s, and the run "
       "follows the reference's", stage=STAGE_VALUES, group="runs")
def check_computed_torques_run(ctx):
    controller = "computed_torques"
    _assert_starts_on_the_table(ctx, controller)
    table, got, expected, probes, ode, n = _simulation(ctx, controller)

    def tracks():
        error = np.linalg.norm(got["x"] - np.asarray(table["x"])[:n], axis=1)
        if error.max() > TRACK:
            i = int(np.argmax(error > TRACK))
            assert_close(got["x"][i], table["x"][i], f"the end effector at t = {got['t'][i]:.4g} s",
                         Tol("tracking", TRACK), context="(the desired path: computed torques track it)",
                         note=f"It is {error[i]:.4g} m away from the path; the figures show your run over the "
                              f"reference's.")
        _follow_reference(got, expected, controller)

    if not _judged_on_own_model(ctx, controller, table, got, expected, probes):
        _diagnosed(ctx, controller, got, expected, probes, ode, tracks)


@check(2, title="gravity compensation: the arm stays at rest for the first 0.25 s (within 1e-3 rad), and the run "
       "follows the reference's until 0.75 s", stage=STAGE_VALUES, group="runs")
def check_gravity_compensation_run(ctx):
    controller = "gravity_compensation"
    _assert_starts_on_the_table(ctx, controller)
    table, got, expected, probes, ode, n = _simulation(ctx, controller)

    def holds():
        resting = np.asarray(got["t"]) <= T_REST
        drift = np.abs(got["q"][resting] - got["q"][0]).max(axis=1)
        if drift.max() > HOLD:
            i = int(np.argmax(drift > HOLD))
            assert_close(got["q"][i], got["q"][0], f"q at t = {got['t'][i]:.4g} s", Tol("at rest", HOLD),
                         context="(the start: until 0.25 s the arm is not commanded to move, and gravity "
                                 "compensation holds it still)",
                         note="Gravity compensation cancels g exactly: with tau = -g(q) + PD and no error, qdd = 0.")
        _follow_reference(got, expected, controller)

    if not _judged_on_own_model(ctx, controller, table, got, expected, probes):
        _diagnosed(ctx, controller, got, expected, probes, ode, holds)


@check(2, title="PD alone: the end effector sags at least 0.05 m below the path by 0.25 s, and the run follows the "
       "reference's until 0.75 s", stage=STAGE_VALUES, group="runs")
def check_pd_run(ctx):
    controller = "pd"
    _assert_starts_on_the_table(ctx, controller)
    table, got, expected, probes, ode, n = _simulation(ctx, controller)

    def sags():
        i = int(np.argmin(np.abs(np.asarray(got["t"]) - T_REST)))
        sag = float(table["x"][i][1] - got["x"][i][1])
        if sag < SAG:
            fail(f"with PD alone the end effector should sink below the path before the motion starts: at t = "
                 f"{got['t'][i]:.4g} s it is {sag:.4g} m below the desired height (expected at least {SAG} m; the "
                 f"reference: {table['x'][i][1] - expected['x'][i][1]:.4g} m).",
                 "Controller 1 is PD only: tau = P (q_des - q) + D (qd_des - qd), without a gravity term; the PD "
                 "torques act only once an error has built up, so the arm sags first.", "no_sag")
        _follow_reference(got, expected, controller)

    if not _judged_on_own_model(ctx, controller, table, got, expected, probes):
        _diagnosed(ctx, controller, got, expected, probes, ode, sags)
