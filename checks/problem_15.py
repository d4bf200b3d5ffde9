"""Checks of problem 15: the torque-free rigid body (Newton-Euler in body coordinates), simulated.

The long fixed runs of the reference are cached on disk; the randomized runs are short.  A wrong run is localized
at the first step where it leaves the reference and diagnosed by applying each known mistake (of the dynamics or
of the integration step of problem 12) from the reference's state just before.
"""

import numpy as np

from checks._rigid import (
    FINITE,
    KINEMATIC_MISTAKES,
    MAX_POINTS,
    ROTATIONS,
    SIMULATION,
    STATE,
    assert_traces,
    describe_state,
    first_departure,
    kinematic_mistakes_at,
    kinematic_step,
    skew,
    subsample,
    trace_array,
    vectors,
)
from grader import strategies as st
from grader.checking import (
    EXACT,
    SHEET,
    STAGE_RANDOM,
    STAGE_VALUES,
    CheckFailure,
    Mistake,
    Tol,
    assert_close,
    check,
    close,
    fail,
    figure,
)
from grader.errors import StudentFault, ends_grading
from probes import problem_15 as p15

TITLE = "Rigid Body Dynamics"
MANUAL = {"a": ("15(a): Qualitatively, describe the difference of what you observe for the cases (4), (5) and (6).", 2)}

DT = 0.001
LONG = 30000  # t_end = 30 s with the course's loop
SHORT = 1000  # the first second of the cases without a printed target
MOMENTUM_STEPS, MOMENTUM_EVERY = 5000, 10  # case 3 over 5 s, 501 samples
#: the sheet's final A_IB of case 6 (four decimals); B_r_IB stays zero
SHEET_CASE_6 = [[0.1564, 0.9877, 0.0004], [-0.9876, 0.1564, 0.0145], [0.0142, -0.0026, 0.9999]]
#: the inertial angular momentum drifts at first order in dt: by 7e-4 over the 5 s of case 3 (reference)
MOMENTUM = Tol("conservation, first order in dt", 0.02)

DYNAMIC_MISTAKES = {
    "missing_gyroscopic": (
        "The gyroscopic term is missing: without torque, Euler's equation is B_I_B @ omegaDot = -omega x (B_I_B @ "
        "omega), which is not zero unless omega is a principal axis."
    ),
    "gyroscopic_sign": (
        "The gyroscopic term has the wrong sign or order: B_I_B @ omegaDot = -omega x (B_I_B @ omega) = "
        "(B_I_B @ omega) x omega."
    ),
    "multiplied_not_solved": (
        "You multiplied by B_I_B instead of solving with it: omegaDot = solve(B_I_B, -omega x (B_I_B @ omega)) "
        "(np.linalg.solve; the inverse would also do)."
    ),
    "principal_axes_only": (
        "Dividing by the diagonal of B_I_B solves Euler's equation only when B_I_B is diagonal (principal axes): "
        "in general solve the linear system B_I_B @ omegaDot = -omega x (B_I_B @ omega)."
    ),
    "euler_component_form": (
        "Euler's equations in components (I1 omegaDot1 = (I2 - I3) omega2 omega3, ...) hold only in principal axes, "
        "where B_I_B is diagonal; here B_I_B is a full matrix: solve B_I_B @ omegaDot = -omega x (B_I_B @ omega)."
    ),
    "acceleration_not_reset": (
        "B_a_B must be set to zero: no force acts, so the absolute acceleration of the centre of gravity vanishes "
        "(the term -omega x v of the velocity update is in integration_step)."
    ),
}


def _euler_components(moments, w):
    """Euler's equations in components with the diagonal entries ``moments`` (right for a diagonal inertia only)."""
    I1, I2, I3 = moments
    return np.array([(I2 - I3) * w[1] * w[2] / I1, (I3 - I1) * w[2] * w[0] / I2, (I1 - I2) * w[0] * w[1] / I3])


def natural_dynamics(state, mistake=None):
    """``(B_a_B, B_omegaDot_B)`` of the problem data, or with the named mistake of ``DYNAMIC_MISTAKES``."""
    I, w = np.asarray(state["B_I_B"], dtype=float), np.asarray(state["B_omega_B"], dtype=float)
    gyroscopic = -skew(w) @ I @ w
    omega_dot = {
        "missing_gyroscopic": lambda: np.zeros(3),
        "gyroscopic_sign": lambda: np.linalg.solve(I, -gyroscopic),
        "multiplied_not_solved": lambda: I @ gyroscopic,
        "principal_axes_only": lambda: gyroscopic / np.diag(I),
        "euler_component_form": lambda: _euler_components(np.diag(I), w),
    }.get(mistake, lambda: np.linalg.solve(I, gyroscopic))()
    a = np.asarray(state["B_a_B"], dtype=float) if mistake == "acceleration_not_reset" else np.zeros(3)
    return a, omega_dot


def dynamic_step(state, dt, mistake=None):
    """Natural dynamics then the integration step, with a mistake of either (named as in the catalogues)."""
    a, omega_dot = natural_dynamics(state, mistake if mistake in DYNAMIC_MISTAKES else None)
    return kinematic_step({**state, "B_a_B": a, "B_omegaDot_B": omega_dot}, dt,
                          mistake if mistake in KINEMATIC_MISTAKES else None)


STEP_MISTAKES = {**DYNAMIC_MISTAKES, **KINEMATIC_MISTAKES}


def case_state(ctx, k):
    """The sheet's case ``k``: the body (mass, inertia) with its initial velocities (the package's constants)."""
    sheet = ctx.reference(p15.constants)
    v, w = (np.array(x, dtype=float) for x in sheet["CASES"][str(k)])
    return {"m": sheet["MASS"], "B_I_B": sheet["INERTIA"], "B_v_B": v, "B_omega_B": w}


def full_state(state):
    """The state of a fresh body: the given entries, zeros and the identity elsewhere."""
    zeros = {k: np.zeros(3) for k in ("B_r_IB", "B_v_B", "B_a_B", "B_omega_B", "B_omegaDot_B")}
    return {"A_IB": np.eye(3), **zeros, **state}


@st.composite
def inertias(draw):
    """Well-conditioned inertia matrices (principal moments in [1, 3]) in a random orientation."""
    A = draw(ROTATIONS)
    x2, y2, z2 = (draw(st.floats(0.5, 1.5, **FINITE)) for _ in range(3))
    return A @ np.diag([y2 + z2, x2 + z2, x2 + y2]) @ A.T


#: a body without special structure: a full (rotated) inertia, omega along no principal axis, every entry non-zero
#: (the accelerations it holds before the call as well: an answer built from them is not the zero of a term left out)
_A = np.array([[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]])
GENERIC_STATE = {"m": 1.3, "B_I_B": _A @ np.diag([1.2, 2.0, 2.6]) @ _A.T, "A_IB": _A.T,
                 "B_r_IB": np.array([0.3, -0.2, 0.5]), "B_v_B": np.array([-0.4, 0.7, 0.2]),
                 "B_a_B": np.array([0.6, -0.3, 0.9]), "B_omega_B": np.array([0.8, -1.1, 0.5]),
                 "B_omegaDot_B": np.array([-0.7, 0.4, 0.3])}

STATES = st.fixed_dictionaries({
    "m": st.floats(0.5, 2.0, **FINITE),
    "B_I_B": inertias(),
    "A_IB": ROTATIONS,
    "B_r_IB": vectors(2.0),
    "B_v_B": vectors(2.0),
    "B_a_B": vectors(2.0),
    "B_omega_B": vectors(2.0),
})


# ------------------------------------------------------------------------------------ the accelerations


@check(3, title="compute_natural_dynamics: B_a_B = 0 and B_I_B omegaDot = -omega x (B_I_B omega) on random states",
       stage=STAGE_RANDOM, group="natural_dynamics")
def check_natural_dynamics(ctx):
    ctx.student(p15.accelerations, case_state(ctx, 3))

    def compare(got, expected, args):
        _compare_accelerations(got, expected, args[0], lambda: _keeps_inertia(ctx, args[0]))

    # first a state without special structure (a full inertia, omega off every axis), where each mistake of the
    # catalogue has its own value: on a shrunk random input several coincide
    state = GENERIC_STATE
    try:
        compare(ctx.student(p15.accelerations, state), ctx.reference(p15.accelerations, state),
                (state,))
    except CheckFailure as exc:
        first, _, rest = exc.message.partition("\n")
        raise CheckFailure(f"{first}\non the fixed state {describe_state(state)}\n{rest}", exc.hint,
                           exc.diagnosis, exc.candidates, exc.evidence) from None
    ctx.compare_random(p15.accelerations, st.tuples(STATES), name="the accelerations", tol=EXACT,
                       compare=compare, examples=15, describe=lambda args: describe_state(args[0]))


def _compare_accelerations(got, expected, state, keeps_inertia=lambda: True):
    """``B_a_B`` and ``B_omegaDot_B`` with the catalogue of ``DYNAMIC_MISTAKES``.  A gyroscopic term missing
    (``omegaDot = 0``) is named only where the body keeps the inertia it is given (``keeps_inertia()``, asked only
    then): the term omega x (B_I_B omega) also vanishes, written as it should be, with an inertia lost for the
    identity (or any multiple of it), which is no term left out."""
    if not isinstance(got, dict):
        fail(f"the probe expected the attributes B_a_B and B_omegaDot_B, got {str(got)[:200]}")
    for key, index in (("B_a_B", 0), ("B_omegaDot_B", 1)):
        mistakes = [Mistake(name, natural_dynamics(state, name)[index], hint)
                    for name, hint in DYNAMIC_MISTAKES.items()]
        mine = got.get(key)
        if key == "B_omegaDot_B" and _vanishes(mine) and not keeps_inertia():
            mistakes = [m for m in mistakes if m.name != "missing_gyroscopic"]
        assert_close(mine, expected[key], f"{key} after compute_natural_dynamics()", EXACT, mistakes)


def _vanishes(value) -> bool:
    try:
        return close(value, np.zeros(3), EXACT)
    except Exception:  # noqa: BLE001 - a value of another shape fails its comparison below
        return False


def _keeps_inertia(ctx, state) -> bool:
    """Whether the student's body keeps the inertia ``state`` gives it: its angular momentum is B_I_B omega (False
    where their code cannot say)."""
    try:
        mine = ctx.student(p15.angular_momentum, state)
    except StudentFault as exc:
        if ends_grading(exc):
            raise
        return False
    try:
        return close(mine, np.asarray(state["B_I_B"], dtype=float) @ np.asarray(state["B_omega_B"], dtype=float),
                     EXACT)
    except Exception:  # noqa: BLE001 - a reply of another shape keeps nothing
        return False


@check(1, title="angular_momentum() = B_I_B omega (body coordinates) on random states", stage=STAGE_RANDOM,
       group="angular_momentum")
def check_angular_momentum(ctx):
    def mistakes(args, expected):
        state = args[0]
        return [Mistake("wrong_frame", state["A_IB"] @ expected, "B_L_B is the angular momentum in BODY "
                        "coordinates: B_I_B @ B_omega_B, without A_IB (the check maps it to I itself).")]

    ctx.student(p15.angular_momentum, case_state(ctx, 3))
    ctx.compare_random(p15.angular_momentum, st.tuples(STATES), name="angular_momentum()", tol=EXACT,
                       mistakes=mistakes, examples=10, describe=lambda args: describe_state(args[0]))


# ------------------------------------------------------------------------------------ simulations


def _diagnose_run(exc, got, expected, state, limit=1000):
    """Re-raise ``exc`` with the first step where the run leaves the reference's and the diagnosis of the known
    mistake that reproduces it (simulated from the start when it happens within ``limit`` steps)."""
    found = first_departure(got, expected, STATE, SIMULATION)
    if found is None:
        raise exc
    i, key, trace = found
    steps = int(expected["step"][i])
    message = exc.message
    if "first departure" not in message:
        message += (f"\nYour run first leaves the reference's in {key} after {steps} steps (t = {steps * DT:g} s; "
                    f"tolerance {SIMULATION}).")
    if steps <= limit:
        for name, hint in STEP_MISTAKES.items():
            s = full_state(state)
            for _ in range(steps):
                s = dynamic_step(s, DT, name)
            if close(trace[i], s[key], SIMULATION):
                fail(message, hint, name)
    fail(message, exc.hint or "The checks of compute_natural_dynamics above (and of integration_step in problem 12) "
         "localize the mistake.", exc.diagnosis)


@check(3, title="the sheet's case 6 after 30 s (30000 steps of 1 ms): A_IB and B_r_IB as printed; and the same body "
       "over its first second from a spin drawn anew", stage=STAGE_VALUES, group="simulation")
def check_case_6(ctx):
    state, every = full_state(case_state(ctx, 6)), 100
    expected = ctx.reference(p15.simulate, state, DT, LONG, every, persist=True)
    got = ctx.student(p15.simulate, state, DT, LONG, every, timeout=30)
    n = len(expected["step"])
    final = {key: trace_array(got, key, (n, *np.shape(state[key])))[-1] for key in ("A_IB", "B_r_IB")}
    try:
        assert_close(final["A_IB"], SHEET_CASE_6, "A_IB at t = 30 s", SHEET, context="(the sheet's value)")
        assert_close(final["B_r_IB"], np.zeros(3), "B_r_IB at t = 30 s", SHEET, context="(the sheet's value)")
    except CheckFailure as exc:
        _diagnose_run(exc, got, expected, state)
    # the printed numbers alone are not enough: the same body from a spin of its own (no key holds it)
    spin = ctx.draw(lambda rng: [float(x) for x in rng.uniform(-1.0, 1.0, 3)])
    spun = full_state({**case_state(ctx, 6), "B_omega_B": np.array(spin)})
    expected = ctx.reference(p15.simulate, spun, DT, SHORT, 10)
    got = ctx.student(p15.simulate, spun, DT, SHORT, 10, timeout=20)
    try:
        assert_traces(got, expected, STATE, SIMULATION, what=f"from B_omega_B = {np.round(spin, 4).tolist()}", dt=DT)
    except CheckFailure as exc:
        _diagnose_run(exc, got, expected, spun)


@check(2, title="cases 1, 2, 4 and 5 over their first second (1000 steps of 1 ms) follow the reference, and a spin "
       "of its own",
       stage=STAGE_VALUES, group="simulation")
def check_other_cases(ctx):
    spin = ctx.draw(lambda rng: [float(x) for x in rng.uniform(-1.0, 1.0, 3)])  # no key holds its run
    for k in (1, 2, 4, 5, "own"):
        state = full_state(case_state(ctx, k) if k != "own" else {**case_state(ctx, 1), "B_omega_B": np.array(spin)})
        expected = ctx.reference(p15.simulate, state, DT, SHORT, SHORT, persist=True)
        # the trace every 10 steps, to localize a departure (fetched whether or not it is needed)
        traced = ctx.reference(p15.simulate, state, DT, SHORT, 10, persist=True)
        got = ctx.student(p15.simulate, state, DT, SHORT, SHORT, timeout=20)
        if first_departure(got, expected, STATE, SIMULATION) is None:
            continue
        got, expected = ctx.student(p15.simulate, state, DT, SHORT, 10), traced
        try:
            what = f"in case {k}" if k != "own" else f"from B_omega_B = {np.round(spin, 4).tolist()}"
            assert_traces(got, expected, STATE, SIMULATION, what=what, dt=DT)
        except CheckFailure as exc:
            _diagnose_run(exc, got, expected, state)


@check(2, title="case 3 over 5 s: the inertial angular momentum A_IB B_L_B stays constant (and follows the "
       "reference)", stage=STAGE_VALUES, group="momentum")
def check_momentum_case_3(ctx):
    state = full_state(case_state(ctx, 3))
    args = (state, DT, MOMENTUM_STEPS, MOMENTUM_EVERY, True)
    expected = ctx.reference(p15.simulate, *args, persist=True)
    got = ctx.student(p15.simulate, *args, timeout=30)
    n = len(expected["step"])
    A, L = trace_array(got, "A_IB", (n, 3, 3)), trace_array(got, "B_L_B", (n, 3))
    I_L = np.einsum("nij,nj->ni", A, L)
    I_L_ref = np.einsum("nij,nj->ni", expected["A_IB"], expected["B_L_B"])
    t = expected["step"] * DT
    ctx.add_figure(figure(
        "Problem 15(b), case 3: inertial angular momentum A_IB @ B_L_B", "t [s]", "I_L [kg m²/s]",
        student=[(f"I_L{j + 1}", *subsample(t, I_L[:, j], MAX_POINTS)) for j in range(3)],
        reference=[(f"I_L{j + 1}", *subsample(t, I_L_ref[:, j], MAX_POINTS)) for j in range(3)],
    ))
    drift = np.abs(I_L - I_L[0]).max(axis=1)
    try:
        if np.all(np.isfinite(drift)) and drift.max() > MOMENTUM.atol:
            i = int(np.argmax(drift > MOMENTUM.atol))
            assert_close(I_L[i], I_L[0], f"A_IB @ B_L_B at t = {t[i]:g} s", MOMENTUM,
                         context="(its value at t = 0: no torque acts, so it is conserved)",
                         note="The figure shows its components over time.")
        assert_traces({"I_L": I_L}, {"I_L": I_L_ref, "step": expected["step"]}, ["I_L"], SIMULATION,
                      what="(A_IB @ B_L_B)", dt=DT)
    except CheckFailure as exc:
        _diagnose_run(exc, got, expected, state)
    # and a spin of its own over 0.5 s (drawn anew at each grading: no key holds it)
    spin = ctx.draw(lambda rng: [float(x) for x in rng.uniform(-1.0, 1.0, 3)])
    spun = full_state({**case_state(ctx, 3), "B_omega_B": np.array(spin)})
    own = ctx.reference(p15.simulate, spun, DT, MOMENTUM_STEPS // 10, MOMENTUM_EVERY, True)
    mine = ctx.student(p15.simulate, spun, DT, MOMENTUM_STEPS // 10, MOMENTUM_EVERY, True, timeout=30)
    try:
        assert_traces(mine, own, ("B_omega_B", "B_L_B"), SIMULATION,
                      what=f"from B_omega_B = {np.round(spin, 4).tolist()}", dt=DT)
    except CheckFailure as exc:
        _diagnose_run(exc, mine, own, spun)


@check(2, title="natural dynamics + integration step follow the reference from random states (1-20 steps)",
       stage=STAGE_RANDOM, group="random_runs")
def check_random_runs(ctx):
    def compare(got, expected, args):
        state, dt, _ = args
        at = kinematic_mistakes_at(expected, state, dt, mistakes=STEP_MISTAKES, step=dynamic_step)
        assert_traces(got, expected, STATE, EXACT, at, dt=dt)

    # first a run from a state without special structure, where each mistake has its own value
    args = (GENERIC_STATE, 0.01, 5)
    try:
        compare(ctx.student(p15.simulate, *args), ctx.reference(p15.simulate, *args), args)
    except CheckFailure as exc:
        first, _, rest = exc.message.partition("\n")
        raise CheckFailure(f"{first}\nfrom the fixed state {describe_state(GENERIC_STATE)}, dt = 0.01, 5 steps\n"
                           f"{rest}", exc.hint, exc.diagnosis, exc.candidates, exc.evidence) from None
    ctx.compare_random(
        p15.simulate, st.tuples(STATES, st.floats(1e-3, 0.05, **FINITE), st.integers(1, 20)),
        name="the state", tol=EXACT, compare=compare, examples=10,
        describe=lambda args: f"{describe_state(args[0])}, dt = {args[1]!r}, {args[2]} step(s)",
    )
