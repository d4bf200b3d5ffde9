"""Checks of problem 38: the passive dynamic walker's right-hand side (``walker_ode``) and its motion
(``simulate``).

The right-hand side is compared with the reference at random states, with the usual ways of getting the slope
wrong, and called at several states in turn on one tree as an integrator calls it (a mass matrix computed once and
reused).  The motion is judged by physics first (the energy of the student's own walker is conserved: the rolling
contact does no work) and then against a tight reference run within bands that any ``solve_ivp`` method at its
default tolerances meets.  Tolerances far looser than the defaults (``rtol = atol = 1e-2``) still follow the
sheet's motion with some methods (DOP853, Radau), so the walker is also started where the sheet does not start it,
near its equilibrium, where the motion is a few mrad: the defaults follow it, such tolerances lose it.  That run
asks another number of outputs than the sheet's 100, so that a simulate that ignores its n is seen.
"""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
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
from probes import _dynamics as probe_dynamics, problem_38 as p38

from ._dynamics import (
    WALKER,
    assert_energy_conserved,
    assert_fresh_along_a_run,
    assert_run,
    defaulted_blocks,
    run_array,
    run_figure,
    wrong_start,
)
from ._upstream import judging

TITLE = "Passive Dynamic Walker"

#: problem data P38: a slope of 1 degree as tilted gravity, normalised to 1
SLOPE = np.deg2rad(1.0)
I_GRAV = np.array([np.sin(SLOPE), -np.cos(SLOPE), 0.0])
T_END, N_OUTPUT = 2.0, 100
#: RK45 at its default tolerances drifts by 1e-3 over the 2 s (energy 0.88)
ENERGY = Tol("energy drift (a reasonable integrator: 1e-3)", 5e-3)
#: any solve_ivp method at its default tolerances stays within 0.0023 rad and 0.0035 rad/s of the reference; a
#: fixed-step Euler loop at dt = 0.02 s strays by 0.023 rad
BAND = {"q": Tol("a reasonable integrator", 7e-3), "qd": Tol("a reasonable integrator", 1e-2)}
SIMULATION_TIMEOUT = 20.0
_SEEDS = st.integers(0, 2**32 - 1)

GRAVITIES = {
    "level_ground": (np.array([0.0, -1.0, 0.0]), "The walker walks down a slope of 1 degree, entered as tilted "
                     "gravity: I_grav = (sin 1deg, -cos 1deg, 0); yours walks on level ground."),
    "slope_sign": (np.array([-np.sin(SLOPE), -np.cos(SLOPE), 0.0]), "The slope goes down along +x: I_grav = "
                   "(+sin 1deg, -cos 1deg, 0)."),
    "degrees": (np.array([np.sin(1.0), -np.cos(1.0), 0.0]), "The slope is 1 degree: np.sin(np.deg2rad(1)), not "
                "np.sin(1) (radians)."),
    "gravity_9_81": (9.81 * I_GRAV, "The walker is normalised to leg length and mass and to g = 1: I_grav = "
                     "(sin 1deg, -cos 1deg, 0) without 9.81."),
}


@st.composite
def _cases(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    return ([(float(rng.uniform(0, T_END)), np.concatenate([rng.uniform(-1, 1, 2), rng.uniform(-2, 2, 2)]))],)


def _accelerations(ctx, y, I_grav):
    """``(qd, qdd)`` of the walker under ``I_grav`` from the reference's M, f, g."""
    q, qd = y[:2], y[2:]
    mfg = ctx.reference(probe_dynamics.mfg, WALKER, q, qd, I_grav)
    return np.concatenate([qd, np.linalg.solve(mfg["M"], mfg["f"] + mfg["g"])])


@check(2, title="walker_ode(t, y, tree) = (qd, qdd) of the unactuated walker on the 1 degree slope, at random "
       "states, and called along a run on one tree as on fresh ones", stage=STAGE_STRUCTURE, group="walker")
def check_walker_ode(ctx):
    def compare(got, expected, args):
        (t, y), = args[0]
        found = [Mistake(name, _accelerations(ctx, y, I_grav), hint) for name, (I_grav, hint) in GRAVITIES.items()]
        found.append(Mistake("state_order", np.concatenate([expected[0][2:], expected[0][:2]]),
                             "dy/dt = (qd, qdd) for y = (q, qd): the velocities come first."))
        assert_close(got[0] if isinstance(got, list) and got else got, expected[0],
                     f"walker_ode at y = {np.round(y, 4).tolist()}", EXACT, found)

    compare = judging(ctx, p38.walker_ode, compare,
                      lambda got, value, args: assert_close(got[0] if isinstance(got, list) and got else got, value[0],
                                                            f"walker_ode at y = {np.round(args[0][0][1], 4).tolist()}",
                                                            EXACT))
    ctx.compare_random(p38.walker_ode, _cases(), name="walker_ode", tol=EXACT, compare=compare, examples=10,
                       describe=lambda args: f"t = {args[0][0][0]:.4g}, y = {np.round(args[0][0][1], 6).tolist()}")
    stale = ctx.reference(p38.stale_mass_matrix, RUN_STATES)
    assert_fresh_along_a_run(ctx, p38.walker_ode, (), RUN_STATES, "walker_ode",
                             [("stale_mass_matrix", stale[key], STALE_HINTS[key]) for key in ("M", "model")],
                             describe=lambda case: f"t = {case[0]:g}, y = {np.round(case[1], 4).tolist()}")


#: states ``(t, y)`` at which walker_ode is called in turn on one tree, as solve_ivp calls it: configurations far
#: enough apart that M differs
RUN_STATES = ((0.2, np.array([-0.1, 0.3, -0.4, 0.9])), (0.6, np.array([-0.3, 0.7, -0.2, 0.6])),
              (1.1, np.array([-0.5, 1.2, 0.1, 0.4])))
STALE_HINTS = {
    "M": "M depends on q: compute M, f, g from the state y at every call of walker_ode; yours reuses the M of its "
         "first call.",
    "model": "M, f and g depend on the state: compute them from y at every call of walker_ode; yours reuses those "
             "of its first call.",
}


@check(3, title="the walker from q0 = (0, 0), qd0 = (-0.1, 1) over 2 s: its energy is conserved and the run follows "
       "the reference's", stage=STAGE_VALUES, group="walker")
def check_walker_run(ctx):
    expected = ctx.reference(p38.simulate, T_END, N_OUTPUT, I_GRAV, persist=True)
    got = ctx.student(p38.simulate, T_END, N_OUTPUT, I_GRAV, timeout=SIMULATION_TIMEOUT)
    what = f"simulate({T_END:g}, {N_OUTPUT})"
    for key in ("t", "q", "qd"):
        run_array(got, key, np.shape(expected[key]), what, times=expected["t"])
    ctx.add_figure(run_figure("Problem 38: the walker's angles", "[rad]", got["t"], got["q"], expected["t"],
                              expected["q"], ["alpha (stance leg)", "gamma (between the legs)"]))
    ctx.add_figure(run_figure("Problem 38: the walker's energy T + V (conserved)", "E", got["t"],
                              np.column_stack([got["T"] + got["V"]]), expected["t"],
                              np.column_stack([expected["T"] + expected["V"]]), ["T + V"]))
    if not close(got["t"], expected["t"], EXACT):
        assert_close(got["t"], expected["t"], "the output times", EXACT,
                     note=f"The sheet asks for {N_OUTPUT} equally spaced outputs from 0 to {T_END:g} s "
                          f"(np.linspace(0, t_end, n)).")
    from grader.diagnosis.runs import reread_runs

    reread = reread_runs(got, expected, ("q", "qd"), BAND["q"])
    if reread is not None:  # the energy of states read from the wrong rows drifts too: not the integration's
        assert_run(got, expected, ("q", "qd"), BAND, "the walker's run", diagnosis="state_row",
                   hint=f"Looks like {reread.detail}: solve_ivp's y holds q in its first two rows and qd in the "
                        "last two.")
    assert_energy_conserved(got, ENERGY, "the unactuated walker",
                            "With M, f, g right (problem 37) and walker_ode right (the check above), the energy "
                            "drifts only if the integration is coarse: use scipy.integrate.solve_ivp.")
    try:
        assert_run(got, expected, ("q", "qd"), BAND, "the walker's run",
                   note="Any solve_ivp method at its default tolerances stays within the band.")
    except CheckFailure as exc:
        start, mine = np.concatenate([expected["q"][0], expected["qd"][0]]), np.concatenate([got["q"][0], got["qd"][0]])
        if not close(mine, start, EXACT):
            hint = "The run starts at q0 = (0, 0), qd0 = (-0.1, +1)."
            raise CheckFailure(exc.message, *wrong_start(mine, start, hint), evidence=exc.evidence) from None
        raise
    _assert_small_motion(ctx)


#: a start the sheet does not print: near the walker's equilibrium q* = (0.2400, -0.2939) (unstable: it rolls away
#: slowly), the swing leg nudged; over 3 s its angles move by at most 5.7e-3 rad and its rates reach 3.4e-3 rad/s
SMALL_START = (np.array([0.24, -0.294]), np.array([0.0, 2e-3]))
T_SMALL = 3.0
#: its outputs: n = 151 (every 0.02 s), not the sheet's 100, so that a simulate that ignores its n is seen
N_SMALL = 151
#: any solve_ivp method at its default tolerances (rtol 1e-3, atol 1e-6) follows that motion within 1.5e-5 rad and
#: 5.4e-5 rad/s; at rtol = atol = 1e-2, which lets an error as large as the motion itself pass, none comes closer
#: than 5.3e-4 rad and 1.1e-3 rad/s (RK45, RK23, DOP853, Radau, BDF and LSODA measured)
SMALL_BAND = {"q": Tol("a reasonable integrator on a small motion", 1e-4),
              "qd": Tol("a reasonable integrator on a small motion", 2.5e-4)}
SHEET_START = np.array([0.0, 0.0, -0.1, 1.0])
SMALL_HINT = ("walker_ode and the sheet's run agree with the reference (above), but a small motion is lost: the "
              "integration's tolerances must be tight for the size of the motion. At rtol = atol = 1e-2, say, "
              "solve_ivp accepts errors as large as a motion of a few mrad; use its defaults (rtol 1e-3, atol 1e-6) "
              "or tighter.")
START_HINT = ("The run starts at the q0, qd0 passed to simulate(t_end, n, q0, qd0) (the sheet's q0 = (0, 0), qd0 = "
              "(-0.1, +1) are only the defaults; the checks also start the walker elsewhere).")


def _assert_small_motion(ctx):
    """The walker from ``SMALL_START`` (a small motion near its equilibrium) follows the reference's run within
    ``SMALL_BAND``: a tolerance far looser than the defaults loses it, where the sheet's larger motion hides it."""
    expected = ctx.reference(p38.simulate, T_SMALL, N_SMALL, I_GRAV, SMALL_START, persist=True)
    got = ctx.student(p38.simulate, T_SMALL, N_SMALL, I_GRAV, SMALL_START, timeout=SIMULATION_TIMEOUT)
    q0, qd0 = (np.round(x, 4).tolist() for x in SMALL_START)
    what = f"simulate({T_SMALL:g}, {N_SMALL}, q0 = {q0}, qd0 = {qd0})"
    t = run_array(got, "t", None, what, times=expected["t"])
    if t.shape != np.shape(expected["t"]):
        typed = t.size == N_OUTPUT
        sheet = f" (the sheet's n = {N_OUTPUT}, whatever n is given)" if typed else ""
        fail(f"{what} returned {t.size} output times{sheet}; it was asked for n = {N_SMALL}, equally spaced from 0 "
             f"to {T_SMALL:g} s.",
             "Output at the n times simulate(t_end, n, ...) is given: t_eval = np.linspace(0, t_end, n) (the sheet's "
             f"n = {N_OUTPUT} is only the default; the checks also ask another n).",
             "ignored_argument" if typed else "shape")
    for key in ("t", "q", "qd"):
        run_array(got, key, np.shape(expected[key]), what, times=expected["t"])
    ctx.add_figure(run_figure("Problem 38: a small motion near the equilibrium, q(t) - q(0)", "[rad]", got["t"],
                              np.asarray(got["q"]) - SMALL_START[0], expected["t"],
                              np.asarray(expected["q"]) - SMALL_START[0],
                              ["alpha (stance leg)", "gamma (between the legs)"]))
    start = np.concatenate([got["q"][0], got["qd"][0]])
    try:
        assert_close(start, np.concatenate(SMALL_START), f"the state (q, qd) at t = 0 of {what}", EXACT,
                     context="(the start passed to simulate)")
    except CheckFailure as exc:
        sheet = defaulted_blocks(start, np.concatenate(SMALL_START),
                                 (("q0", SHEET_START[:2]), ("qd0", SHEET_START[2:])))
        if sheet:
            passed = " and ".join(sheet)
            hint = (f"Your run starts from the sheet's {passed} whatever {passed} simulate is given. {START_HINT}"
                    if len(sheet) < 2 else START_HINT)
            raise CheckFailure(exc.message, hint, "typed_numbers or ignored_argument", evidence=exc.evidence) from None
        raise CheckFailure(exc.message, *wrong_start(start, np.concatenate(SMALL_START), START_HINT),
                           evidence=exc.evidence) from None
    assert_run(got, expected, ("q", "qd"), SMALL_BAND, f"the small motion of {what}", hint=SMALL_HINT,
               diagnosis="integration",
               note="Any solve_ivp method at its default tolerances stays within the band; the motion itself is a "
                    "few mrad.")
