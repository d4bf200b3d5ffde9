"""Checks of problem 38: the passive dynamic walker's right-hand side (``walker_ode``) and its motion
(``simulate``).

The right-hand side is compared with the reference at random states, with the usual ways of getting the slope
wrong.  The motion is judged by physics first (the energy of the student's own walker is conserved: the rolling
contact does no work) and then against a tight reference run within bands that any ``solve_ivp`` method at its
default tolerances meets.
"""

import numpy as np

from grader import strategies as st
from grader.checking import EXACT, STAGE_STRUCTURE, STAGE_VALUES, CheckFailure, Mistake, Tol, assert_close, check, close

from ._dynamics import WALKER, assert_energy_conserved, assert_run, run_array, run_figure
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
    mfg = ctx.reference("_dynamics.mfg", WALKER, q, qd, I_grav)
    return np.concatenate([qd, np.linalg.solve(mfg["M"], mfg["f"] + mfg["g"])])


@check(2, title="walker_ode(t, y, tree) = (qd, qdd) of the unactuated walker on the 1 degree slope, at random "
       "states", stage=STAGE_STRUCTURE, group="walker")
def check_walker_ode(ctx):
    def compare(got, expected, args):
        (t, y), = args[0]
        found = [Mistake(name, _accelerations(ctx, y, I_grav), hint) for name, (I_grav, hint) in GRAVITIES.items()]
        found.append(Mistake("state_order", np.concatenate([expected[0][2:], expected[0][:2]]),
                             "dy/dt = (qd, qdd) for y = (q, qd): the velocities come first."))
        assert_close(got[0] if isinstance(got, list) and got else got, expected[0],
                     f"walker_ode at y = {np.round(y, 4).tolist()}", EXACT, found)

    compare = judging(ctx, "problem_38.walker_ode", compare,
                      lambda got, value, args: assert_close(got[0] if isinstance(got, list) and got else got, value[0],
                                                            f"walker_ode at y = {np.round(args[0][0][1], 4).tolist()}",
                                                            EXACT))
    ctx.compare_random("problem_38.walker_ode", _cases(), name="walker_ode", tol=EXACT, compare=compare, examples=10,
                       describe=lambda args: f"t = {args[0][0][0]:.4g}, y = {np.round(args[0][0][1], 6).tolist()}")


@check(3, title="the walker from q0 = (0, 0), qd0 = (-0.1, 1) over 2 s: its energy is conserved and the run follows "
       "the reference's", stage=STAGE_VALUES, group="walker")
def check_walker_run(ctx):
    expected = ctx.reference("problem_38.simulate", T_END, N_OUTPUT, I_GRAV, persist=True)
    got = ctx.student("problem_38.simulate", T_END, N_OUTPUT, I_GRAV, timeout=SIMULATION_TIMEOUT)
    what = f"simulate({T_END:g}, {N_OUTPUT})"
    for key in ("t", "q", "qd"):
        run_array(got, key, np.shape(expected[key]), what)
    ctx.add_figure(run_figure("Problem 38: the walker's angles", "[rad]", got["t"], got["q"], expected["t"],
                              expected["q"], ["alpha (stance leg)", "gamma (between the legs)"]))
    ctx.add_figure(run_figure("Problem 38: the walker's energy T + V (conserved)", "E", got["t"],
                              np.column_stack([got["T"] + got["V"]]), expected["t"],
                              np.column_stack([expected["T"] + expected["V"]]), ["T + V"]))
    if not close(got["t"], expected["t"], EXACT):
        assert_close(got["t"], expected["t"], "the output times", EXACT,
                     note=f"The sheet asks for {N_OUTPUT} equally spaced outputs from 0 to {T_END:g} s "
                          f"(np.linspace(0, t_end, n)).")
    assert_energy_conserved(got, ENERGY, "the unactuated walker",
                            "With M, f, g right (problem 37) and walker_ode right (the check above), the energy "
                            "drifts only if the integration is coarse: use scipy.integrate.solve_ivp.")
    try:
        assert_run(got, expected, ("q", "qd"), BAND, "the walker's run",
                   note="Any solve_ivp method at its default tolerances stays within the band.")
    except CheckFailure as exc:
        start = np.concatenate([expected["q"][0], expected["qd"][0]])
        if not close(np.concatenate([got["q"][0], got["qd"][0]]), start, EXACT):
            raise CheckFailure(exc.message, "The run starts at q0 = (0, 0), qd0 = (-0.1, +1).", "initial_state") \
                from None
        raise
