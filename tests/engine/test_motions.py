"""The diagnosis engine on runs: a wrong model is told from a wrong integration.

A run that leaves the reference's is not proof that its integration is at fault.  Where a run's probe declares its
right-hand side (``motion["rhs"]``), the engine compares the student's with the reference's at states along the
reference's run: where they differ, the cause is sought on the right-hand sides (their declared terms, say) and no
integration cause is told, by the engine or by a check (``energy_drift``); where they agree, a step too large is
told as before.  Each mistake below is planted into a copy of the reference where no catalogue names it, graded as
``grade batch`` grades (a warm fork), live and from the kit's answer key (the same verdicts).
"""

import numpy as np
import pytest

import grader.diagnosis as engine
from checks._diagnoses import families_of
from grader.checking import Tol
from grader.diagnosis import Evidence, explain
from grader.results import Status

from tests.kit_support import (  # noqa: F401 (fixtures)
    assert_told,
    failed_alike,
    grade_live_and_kit,
    warm_slot,
)
from tests.engine.stand_ins import StandInChild, StandInOracle
from tests.submissions import Planted, build_planted

#: the families of the causes that blame a run's integration
INTEGRATION = {"step_size", "event"}

GRAVITY_SIGN_PENDULUM = Planted(
    name="motions-p24-gravity-sign", problem=24, file="problem_24.py",
    old="return np.concatenate([qd, forward_dynamics(M, f, g, np.zeros(3))])",
    new="return np.concatenate([qd, forward_dynamics(M, f, -g, np.zeros(3))])",
    check="p24.simulated_motion", diagnosis="gravity_sign or transpose", message="the mistake is in the model")
# (the planar arm's joints all turn about the 3-axis: its joint rotations transposed, the angles negated, mirror
# the arm, whose gravity torques then change sign; the formula tier reproduces the right-hand side so too)
GRAVITY_SIGN_BAR = Planted(
    name="motions-p44-gravity-sign", problem=44, file="problem_44.py",
    old="qdd, _ = accelerations(y[:3], y[3:], m, theta, g)",
    new="qdd, _ = accelerations(y[:3], y[3:], m, theta, -g)",
    check="p44.motion", diagnosis="gravity_sign or sign_flip", message="the mistake is in the model")
ROWS_OF_THE_BAR = Planted(
    name="motions-p44-ode-rows", problem=44, file="problem_44.py",
    old="return np.concatenate([y[3:], qdd])",
    new="return np.concatenate([qdd, y[3:]])",
    check="p44.motion", diagnosis="swapped", message="two entries that `bar_ode` builds are exchanged")
EULER_WALKER = Planted(
    name="motions-p38-euler-loop", problem=38, file="problem_38.py",
    old='''    result = solve_ivp(walker_ode, (0.0, t_end), y0, method="DOP853", t_eval=np.linspace(0.0, t_end, n),
                       rtol=1e-10, atol=1e-10, args=(tree,))
    return {"t": result.t, "q": result.y[:2].T, "qd": result.y[2:].T}''',
    new='''    times = np.linspace(0.0, t_end, n)
    rows, y = [y0], y0
    for a, b in zip(times[:-1], times[1:]):
        y = y + (b - a) * walker_ode(a, y, tree)
        rows.append(y)
    rows = np.array(rows)
    return {"t": times, "q": rows[:, :2], "qd": rows[:, 2:]}''',
    check="p38.walker_run", diagnosis="step_size", message="fixed-step explicit Euler integration")
RATES_AS_ANGLES = Planted(
    name="motions-p24-rates-as-angles", problem=24, file="problem_24.py",
    old='return {"t": result.t, "q": result.y[:3].T, "qd": result.y[3:].T}',
    new='return {"t": result.t, "q": result.y[3:].T, "qd": result.y[:3].T}',
    check="p24.simulated_motion", diagnosis="state_row", message="from the wrong row")

MASS_AND_INERTIA_EXCHANGED = Planted(
    name="motions-p44-mass-and-inertia-exchanged", problem=44, file="problem_44.py",
    old="result = solve_ivp(bar_ode, (0.0, t_end), y0, t_eval=t_eval, args=(m, theta, g),",
    new="result = solve_ivp(bar_ode, (0.0, t_end), y0, t_eval=t_eval, args=(theta, m, g),",
    check="p44.motion", diagnosis="argument_order", message="m and theta are exchanged")

REVERSED_WIRE = Planted(
    name="motions-p46-velocities-reversed", problem=46, file="problem_46.py",
    old="    return qd_minus + Minv_JT @ Lam, Lam", new="    return -qd_minus, Lam",
    check="p46.plastic_impact", diagnosis="", message="")
REVERSED_PIN = Planted(
    name="motions-p47-velocities-reversed", problem=47, file="problem_47.py",
    old="    return np.array(q_minus, dtype=float), qd_minus + M_inv @ J.T @ Lam, float(Lam[0])",
    new="    return np.array(q_minus, dtype=float), -qd_minus, float(Lam[0])",
    check="p47.plastic_impact", diagnosis="", message="")

#: solve_ivp at tolerances far looser than its defaults: the reference re-run so is the student's run (its error
#: grows with the tolerance), and the right-hand side agrees: a step-size cause
LOOSE_BAR = Planted(
    name="motions-p44-loose-tolerances", problem=44, file="problem_44.py",
    old="events=[make_contact_event(s, d)], rtol=1e-10, atol=1e-12)",
    new="events=[make_contact_event(s, d)], rtol=1e-1, atol=1e-1)",
    check="p44.event", diagnosis="step_size", message="rtol = 0.1, atol = 0.1")
#: the start speed and the gravity exchanged (g is not given: the sheet's)
V0_AND_G_EXCHANGED = Planted(
    name="motions-p42-v0-and-g-exchanged", problem=42, file="problem_42.py",
    old="result = solve_ivp(ball_ode, (0.0, t_max), [0.0, v0], args=(drag, g),",
    new="result = solve_ivp(ball_ode, (0.0, t_max), [0.0, g], args=(drag, v0),",
    check="p42.flight", diagnosis="argument_order", message="v0 and g are exchanged")
#: the drag on the thrown ball left out on its way down (it only brakes a rising ball): the right-hand side differs
#: from the reference's only past the apex, an event the run goes on through by the same model
DRAG_ON_THE_WAY_UP_ONLY = Planted(
    name="motions-p42-drag-on-the-way-up-only", problem=42, file="problem_42.py",
    old="return np.array([velocity, -g - drag * abs(velocity) * velocity])",
    new="return np.array([velocity, -g - drag * max(velocity, 0.0) * velocity])",
    check="p42.flight", diagnosis="", message="Your right-hand side differs from the reference's")
#: the module's V0 thrown whatever v0 is given: the sheet's ball is right, a random one is the sheet's speed
V0_IGNORED = Planted(
    name="motions-p42-v0-ignored", problem=42, file="problem_42.py",
    old="result = solve_ivp(ball_ode, (0.0, t_max), [0.0, v0], args=(drag, g),",
    new="result = solve_ivp(ball_ode, (0.0, t_max), [0.0, V0], args=(drag, g),",
    check="p42.flight_random", diagnosis="ignored_argument", message="the argument is ignored")
#: the pendulum released at the module's start whatever q0 is given: the run from the sheet's start (the probe
#: declares it) reproduces it, told beside the start that differs
Q0_IGNORED = Planted(
    name="motions-p24-q0-ignored", problem=24, file="problem_24.py",
    old="tree = build_triple_pendulum(DynamicBody)\n    t_eval",
    new="tree, q0 = build_triple_pendulum(DynamicBody), Q\n    t_eval",
    check="p24.simulated_motion", diagnosis="ignored_argument or initial_state", message="the argument is ignored")
#: the bar's run integrated with the module's inertia whatever bar = (m, theta, g) is given: the reference's run
#: with that one parameter at its sheet value reproduces it (the check's catalogue knows g typed in, not theta)
THETA_IGNORED = Planted(
    name="motions-p44-theta-ignored", problem=44, file="problem_44.py",
    old="args=(m, theta, g),", new="args=(m, THETA, g),",
    check="p44.event", diagnosis="ignored_argument", message="sheet's theta = 1: the argument is ignored")
#: the wire's event measured against the module's length whatever wire the run is given: the reference's run with
#: that part of the wire at the sheet's value reproduces it (the event is found late only because of it)
WIRE_LENGTH_IGNORED = Planted(
    name="motions-p46-event-wire-length-ignored", problem=46, file="problem_46.py",
    old="return float(np.linalg.norm(anchor - I_r_E) - wire_length)",
    new="return float(np.linalg.norm(anchor - I_r_E) - WIRE_LENGTH)",
    check="p46.event_and_impact", diagnosis="ignored_argument", message="sheet's wire_length = 2")
#: its near miss: the pendulum released at the given angles negated, a start that is not the module's
START_NEGATED = Planted(
    name="motions-p24-start-negated", problem=24, file="problem_24.py",
    old="result = solve_ivp(pendulum_ode, (0.0, t_end), y0,",
    new="result = solve_ivp(pendulum_ode, (0.0, t_end), y0 * np.array([-1, -1, -1, 1, 1, 1]),",
    check="p24.simulated_motion", diagnosis="", message="")
#: the rates at the event read from the position rows of the event's state
EVENT_RATES_FROM_POSITIONS = Planted(
    name="motions-p44-event-rates-from-positions", problem=44, file="problem_44.py",
    old="q_event=y_event[:3], qd_event=y_event[3:])",
    new="q_event=y_event[:3], qd_event=y_event[:3])",
    check="p44.event", diagnosis="state_row", message="its q_event")
#: the walker's angles read from the rate rows: its energy drifts too, which is not the integration's
ANGLES_FROM_RATE_ROWS = Planted(
    name="motions-p38-angles-from-rate-rows", problem=38, file="problem_38.py",
    old='return {"t": result.t, "q": result.y[:2].T, "qd": result.y[2:].T}',
    new='return {"t": result.t, "q": result.y[2:].T, "qd": result.y[2:].T}',
    check="p38.walker_run", diagnosis="state_row", message="q[0] is the reference's qd[0]")
#: the arm's rates read from the angle columns: its start looks wrong only because of the columns returned
RATES_FROM_ANGLE_COLUMNS = Planted(
    name="motions-p37-rates-from-angle-columns", problem=37, file="problem_37.py",
    old='return {"t": run["t"], "q": run["y"][:, :3], "qd": run["y"][:, 3:]}',
    new='return {"t": run["t"], "q": run["y"][:, :3], "qd": run["y"][:, :3]}',
    check="p37.computed_torques_run", diagnosis="state_row", message="qd[0] is the reference's q[0]")
#: the apex event reads the height: only one event reads the other row, the two are not exchanged; it watches the
#: other quantity (an event's slip, as an event of the other support is), no state of a run is read from it
APEX_ON_THE_HEIGHT = Planted(
    name="motions-p42-apex-on-the-height", problem=42, file="problem_42.py",
    old="    def apex(t, y, *args):\n        return y[1]",
    new="    def apex(t, y, *args):\n        return y[0]",
    check="p42.events", diagnosis="event_quantity", message="apex reads the other row")
#: a near miss of a state read from the wrong rows: the walker started with its rates negated is a wrong start,
#: and (its angles zero) the given start with the opposite sign: could be either
RATES_NEGATED_AT_THE_START = Planted(
    name="motions-p38-start-rates-negated", problem=38, file="problem_38.py",
    old="y0 = np.concatenate([np.asarray(q0, dtype=float), np.asarray(qd0, dtype=float)])",
    new="y0 = np.concatenate([np.asarray(q0, dtype=float), -np.asarray(qd0, dtype=float)])",
    check="p38.walker_run", diagnosis="initial_state or sign_flip", message="")
#: a near miss of a run at loose tolerances: gravity 5% too strong in the run's arguments (the right-hand side
#: agrees, the run is off); no run of the reference's at a looser tolerance is it
STRONGER_GRAVITY = Planted(
    name="motions-p44-stronger-gravity", problem=44, file="problem_44.py",
    old="result = solve_ivp(bar_ode, (0.0, t_end), y0, t_eval=t_eval, args=(m, theta, g),",
    new="result = solve_ivp(bar_ode, (0.0, t_end), y0, t_eval=t_eval, args=(m, theta, 1.05 * g),",
    check="p44.event", diagnosis="", message="")
#: the bar's weight turned up by the run's own arguments (its right-hand side is right): the bar never falls onto the
#: second support, and the run leaves the reference's from its first samples (no missed event); the reference's run
#: with g negated is it
GRAVITY_PASSED_NEGATIVE = Planted(
    name="motions-p44-gravity-passed-negative", problem=44, file="problem_44.py",
    old="result = solve_ivp(bar_ode, (0.0, t_end), y0, t_eval=t_eval, args=(m, theta, g),",
    new="result = solve_ivp(bar_ode, (0.0, t_end), y0, t_eval=t_eval, args=(m, theta, -g),",
    check="p44.event", diagnosis="sign_flip", message="g enters with its sign turned")
#: its near miss: g negated and halved, which no single variant of the run's parameters gives
GRAVITY_PASSED_NEGATIVE_AND_HALVED = Planted(
    name="motions-p44-gravity-passed-negative-and-halved", problem=44, file="problem_44.py",
    old="result = solve_ivp(bar_ode, (0.0, t_end), y0, t_eval=t_eval, args=(m, theta, g),",
    new="result = solve_ivp(bar_ode, (0.0, t_end), y0, t_eval=t_eval, args=(m, theta, -0.5 * g),",
    check="p44.event", diagnosis="", message="")

#: the output step taken as the span over the count of samples, not of steps: as many times as asked, evenly from 0,
#: each after the first early by a growing share of the step (the grid of one sample more, cut to the count); the
#: states at those times are the reference's run there
SPAN_OVER_SAMPLES = Planted(
    name="motions-p24-span-over-the-samples", problem=24, file="problem_24.py",
    old="t_eval = np.linspace(0.0, t_end, int(round(t_end / dt)) + 1)",
    new="t_eval = np.arange(int(round(t_end / dt)) + 1) * t_end / (int(round(t_end / dt)) + 1)",
    check="p24.simulated_motion", diagnosis="grid_off_by_one", message="a grid of one more sample")

#: the pendulum's rates returned in single precision: its start is the given one in float32, a rounding, not a start
#: of its own
RATES_IN_SINGLE = Planted(
    name="motions-p24-rates-in-single-precision", problem=24, file="problem_24.py",
    old='"qd": result.y[3:].T}', new='"qd": result.y[3:].T.astype(np.float32)}',
    check="p24.simulated_motion", diagnosis="float32", message="single precision")

#: the arm's whole solution cast to single precision: its start is no start of its own for the check's catalogue
#: either
ARM_IN_SINGLE = Planted(
    name="motions-p37-solution-in-single-precision", problem=37, file="problem_37.py",
    old='return {"t": run["t"], "q": run["y"][:, :3], "qd": run["y"][:, 3:]}',
    new='y = run["y"].astype(np.float32)\n    return {"t": run["t"], "q": y[:, :3], "qd": y[:, 3:]}',
    check="p37.computed_torques_run", diagnosis="float32", message="single precision")

RUN_SLIPS = [RATES_IN_SINGLE, ARM_IN_SINGLE, SPAN_OVER_SAMPLES, LOOSE_BAR, V0_AND_G_EXCHANGED, V0_IGNORED,
             EVENT_RATES_FROM_POSITIONS, ANGLES_FROM_RATE_ROWS, RATES_FROM_ANGLE_COLUMNS, APEX_ON_THE_HEIGHT,
             RATES_NEGATED_AT_THE_START, Q0_IGNORED, THETA_IGNORED, WIRE_LENGTH_IGNORED, GRAVITY_PASSED_NEGATIVE]
NEAR_MISSES = [STRONGER_GRAVITY, GRAVITY_PASSED_NEGATIVE_AND_HALVED]

MISTAKES = [GRAVITY_SIGN_PENDULUM, GRAVITY_SIGN_BAR, ROWS_OF_THE_BAR, EULER_WALKER, RATES_AS_ANGLES,
            MASS_AND_INERTIA_EXCHANGED]


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({m.problem for m in MISTAKES + RUN_SLIPS + NEAR_MISSES
                                 + [REVERSED_WIRE, REVERSED_PIN]}))


@pytest.mark.parametrize("mistake", MISTAKES, ids=lambda m: m.name)
def test_a_run_is_told_its_cause(mistake, tmp_path, kit_oracle, deferred_ids, slot):
    target = failed_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    assert_told(mistake, target)


@pytest.mark.parametrize("mistake", RUN_SLIPS, ids=lambda m: m.name)
def test_a_slip_of_the_run_itself_is_told(mistake, tmp_path, kit_oracle, deferred_ids, slot):
    """Slips of the run, not of its model: its output grid one sample off, the run's arguments exchanged or
    ignored, solve_ivp's tolerances loosened, states read from the wrong rows of the solution or of an event's
    state, an event function reading the other row, the run returned in single precision; and a wrong start, which a
    state read from the wrong rows must not be mistaken for."""
    target = failed_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    assert_told(mistake, target)


def test_a_start_that_is_not_the_modules_is_not_told_as_the_argument_ignored(tmp_path, kit_oracle, deferred_ids,
                                                                             slot):
    """The near miss of ``Q0_IGNORED``: a run released at the given angles negated starts from another state, which
    is not the module's start: the start is told, not the argument ignored."""
    target = failed_alike(START_NEGATED, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    told = set(families_of(target.diagnosis))
    assert "initial_state" in told and "ignored_argument" not in told, (target.diagnosis, target.hint)


@pytest.mark.parametrize("mistake", NEAR_MISSES, ids=lambda m: m.name)
def test_a_run_off_for_another_reason_is_not_told_as_its_tolerances(mistake, tmp_path, kit_oracle, deferred_ids,
                                                                      slot):
    """A run whose arguments are off by a factor no hypothesis tries: its right-hand side agrees and the run
    leaves the reference's, but no run at looser tolerances, no exchange, no parameter with its sign turned and no
    wrong row is it."""
    target = failed_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    told = set(families_of(target.diagnosis))
    assert not told & (INTEGRATION | {"state_row", "order", "initial_state", "sign"}), (target.diagnosis, target.hint)


def test_a_model_that_differs_past_an_event_the_run_goes_on_through_is_told_as_the_model(tmp_path, kit_oracle,
                                                                                         deferred_ids, slot):
    """The right-hand side is compared at states along the whole run up to an event that ends it: a ball braked
    on its way up only agrees with the reference's up to the apex, and its run is told as a wrong model (with no
    cause, none of the grammar being it), never as its integration."""
    target = failed_alike(DRAG_ON_THE_WAY_UP_ONLY, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    assert_told(DRAG_ON_THE_WAY_UP_ONLY, target)


@pytest.mark.parametrize("mistake", [GRAVITY_SIGN_PENDULUM, GRAVITY_SIGN_BAR, ROWS_OF_THE_BAR],
                         ids=lambda m: m.name)
def test_a_wrong_model_is_never_told_as_its_integration(mistake, tmp_path, kit_oracle, deferred_ids, slot):
    """A slip in the right-hand side makes the run drift and its energy too; neither the engine nor the check's
    own ``energy_drift`` blames the integration for it, on any check of the problem."""
    submission = build_planted(mistake, tmp_path / "pkg")
    live, _ = grade_live_and_kit(mistake.problem, submission, kit_oracle, zygote=slot)
    told = {r.check_id: r.diagnosis for r in live.results if r.status is Status.FAILED}
    assert mistake.check in told
    blamed = {check: d for check, d in told.items() if set(families_of(d)) & INTEGRATION}
    assert not blamed, blamed


@pytest.mark.parametrize("mistake", [REVERSED_WIRE, REVERSED_PIN], ids=lambda m: m.name)
def test_an_impact_is_told_elastic_only_where_its_velocities_follow_that_law(mistake, tmp_path, kit_oracle,
                                                                            deferred_ids, slot):
    """Every velocity reversed also reverses the closing one (restitution 1 along the constraint), but the other
    velocities are not the elastic law's: no elastic impact is told."""
    target = failed_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    assert "elastic" not in target.diagnosis.split(" or "), (target.diagnosis, target.hint)


def test_the_energy_drift_of_a_wrong_model_was_blamed_on_the_integration(tmp_path, kit_oracle, slot,
                                                                        monkeypatch):
    """Without the engine the check blames the integration for the pendulum's drifting energy: the cause the
    differential replaces."""
    from grader import grade_problem
    from grader.workers import Forked

    from tests.kit_support import SEED

    monkeypatch.setattr(engine, "ENABLED", False)
    submission = build_planted(GRAVITY_SIGN_PENDULUM, tmp_path / "pkg")
    off = grade_problem(24, submission, seed=SEED, workers=Forked(slot))
    assert {r.check_id: r for r in off.results}["p24.simulated_motion"].diagnosis == "energy_drift"


# ------------------------------------------------------------------------------------------ stand-ins


def _ball(v0, g, t):
    return {"t": t, "y": np.column_stack([v0 * t - g * t * t / 2, v0 - g * t])}


def _explain_ball(monkeypatch, student_g, reference_g, student_v0=4.0):
    """A ball's run ``throw(v0, g)`` (its probe declares both as scalars, and its right-hand side): the student's
    run with their own ``v0`` and ``g``, the reference's with the given ones."""
    from grader.diagnosis import Declaration

    decl = Declaration(args=("scalar", "scalar"), names=("v0", "g"),
                       motion={"time": "t", "states": ("y",), "rhs": "stub.rhs", "rhs_args": (1,)})
    monkeypatch.setitem(engine.DECLARATIONS, "stub.throw", decl)
    monkeypatch.setitem(engine.DECLARATIONS, "stub.rhs", None)
    t = np.linspace(0.0, 0.8, 81)

    def rhs(g, cases):
        return [np.array([y[1], -g]) for _, y in cases]

    reference = {"stub.throw": lambda v0, g: _ball(v0, g, t), "stub.rhs": rhs}
    student = {"stub.throw": lambda v0, g: _ball(student_v0, student_g, t),
               "stub.rhs": lambda g, cases: rhs(student_g, cases)}
    expected, got = _ball(4.0, reference_g, t), _ball(student_v0, student_g, t)

    class Ctx:
        calls = [("reference", "stub.throw", (4.0, reference_g), expected),
                 ("student", "stub.throw", (4.0, reference_g), got)]
        check_id = "p99.run"
        oracle = StandInOracle(reference)
        child = StandInChild(student)
        seed = 1

    evidence = Evidence(np.asarray(got["y"]), np.asarray(expected["y"]), Tol("band", 1e-3), "y", got, expected)
    return explain(Ctx(), [evidence])


def test_an_exchange_of_equal_values_is_not_told(monkeypatch):
    """With v0 = g = 4 an exchange of the two cannot be told from the right values; the student's run differs
    (another start speed), and the engine does not name the exchange (which gives the expected run), but the
    start."""
    finding = _explain_ball(monkeypatch, student_g=4.0, reference_g=4.0, student_v0=5.0)
    assert finding is None or "argument_order" not in finding.names, finding


def test_a_model_that_differs_names_no_start_and_no_step(monkeypatch):
    """The student's ball falls under another gravity (their right-hand side differs): the run is not told as a
    wrong start, an offset or an integration's error, only what the right-hand sides say (a scaled gravity, or
    nothing)."""
    finding = _explain_ball(monkeypatch, student_g=9.81 * 2, reference_g=9.81)
    assert finding is not None and "not in the integration" in finding.hint, finding
    assert not set(finding.names) & {"initial_state", "offset", "step_size", "time_shift", "state_row"}, finding


def test_parameters_of_equal_value_are_never_exchanged():
    """A run's parameters are tried exchanged only where their values differ: two equal masses cannot tell an
    exchange (the reference's run with them exchanged is its own run)."""
    from grader.diagnosis.runs import parameter_variants

    motion = {"parameters": {"arg": 0, "names": ("m1", "m2", "g")}}
    keys = {h.key for h, _ in parameter_variants(motion, ((1.5, 1.5, 9.81),), None)}
    assert not {k for k in keys if k.startswith("run:swap:0:1")}
    assert {"run:swap:0:2", "run:swap:1:2"} <= keys
    keys = {h.key for h, _ in parameter_variants(motion, (None,), (1.5, 2.5, 9.81))}
    assert "run:swap:0:1" in keys


def test_parameters_given_in_one_argument_are_each_tried_at_the_sheets_value_only_where_given():
    """Parameters held in one argument: each given one that differs from the sheet's is tried at the sheet's value
    (that parameter ignored, the module's constant used); none where the argument is not given (the run is the
    sheet's already)."""
    from grader.diagnosis.runs import parameter_variants

    motion = {"parameters": {"arg": 0, "names": ("m", "theta", "g")}}
    variants = dict((h.key, args) for h, args in parameter_variants(motion, ((0.8, 0.6, 9.81),), (0.5, 1.0, 9.81)))
    assert variants["run:sheet:0"] == ([0.5, 0.6, 9.81],) and variants["run:sheet:1"] == ([0.8, 1.0, 9.81],)
    assert "run:sheet:2" not in variants
    assert not {k for k, _ in parameter_variants(motion, (None,), (0.5, 1.0, 9.81)) if k.key.startswith("run:sheet")}


def test_each_given_parameter_is_tried_at_zero_left_out_and_the_gravity_so_is_missing():
    """``args=(0.0, g)`` for ``args=(drag, g)``: a parameter given but passed as zero (its term left out) is tried
    where it is given and not zero already, in one argument or in one argument each; the gravity so is the gravity
    missing, any other the argument ignored."""
    from grader.diagnosis.runs import parameter_variants

    motion = {"parameters": {"args": (0, 1, 2), "names": ("v0", "drag", "g")}}
    variants = {h.key: (h, args) for h, args in parameter_variants(motion, (10.0, 0.1, 9.81), (10.0, 0.1, 9.81))}
    assert variants["run:zero:1"][1] == (10.0, 0.0, 9.81) and variants["run:zero:1"][0].name == "ignored_argument"
    assert variants["run:zero:2"][1] == (10.0, 0.1, 0.0) and variants["run:zero:2"][0].name == "missing_gravity"
    variants = {h.key for h, _ in parameter_variants(motion, (10.0, 0.0), (10.0, 0.1, 9.81))}
    assert "run:zero:1" not in variants and "run:zero:2" not in variants  # zero already; not given
    motion = {"parameters": {"arg": 0, "names": ("m", "theta", "g")}}
    variants = {h.key: (h, args) for h, args in parameter_variants(motion, ((0.8, 0.6, 9.81),), (0.5, 1.0, 9.81))}
    assert variants["run:zero:2"][1] == ([0.8, 0.6, 0.0],) and variants["run:zero:2"][0].name == "missing_gravity"
    assert not {k for k, _ in parameter_variants(motion, (None,), (0.5, 1.0, 9.81)) if k.key.startswith("run:zero")}


def test_a_varied_run_explains_an_event_only_where_it_agrees_up_to_it_and_finds_it_at_the_students_time():
    """An event's time compared: the reference's varied run must find the event at the student's time and agree
    with the student's run before it (what follows the event is another comparison's), while the reference's own
    run finds it clearly elsewhere; a varied run that agrees at the event but not before it, or that finds it where
    the reference's own run does, explains nothing."""
    from grader.diagnosis.runs import _event_variant

    t = np.linspace(0.0, 1.0, 11)
    run = (t, {"q": np.column_stack([t, t * t])})
    tol = Tol("event time", 2e-3)
    hypothesis = object()
    mine, theirs, ours = ({"t_event": 0.8}, {"t_event": 0.8005}, {"t_event": 0.7})
    assert _event_variant(hypothesis, (run, mine), (run, theirs), (run, ours), "t_event", tol) == [hypothesis]
    bent = (t, {"q": np.column_stack([t, t * t + 0.1 * t])})
    assert _event_variant(hypothesis, (run, mine), (bent, theirs), (run, ours), "t_event", tol) == []
    assert _event_variant(hypothesis, (run, mine), (run, theirs), (run, {"t_event": 0.801}), "t_event", tol) == []
    assert _event_variant(hypothesis, (run, mine), (run, {"t_event": 0.75}), (run, ours), "t_event", tol) == []


def test_parameters_given_one_argument_each_are_exchanged_only_where_one_is_the_sheets():
    """A run's parameters given one argument each: two given ones are the grammar's to exchange (its input slips),
    so the run's tier exchanges a pair only where one takes the sheet's value; a given one is also tried at the
    sheet's value (ignored), where it differs from it; the gravity, given or not, is tried with its sign turned
    (a sign convention: the speed and the drag have none)."""
    from grader.diagnosis.runs import parameter_variants

    motion = {"parameters": {"args": (0, 1, 2), "names": ("v0", "drag", "g")}}
    variants = dict((h.key, args) for h, args in parameter_variants(motion, (10.0, 0.1), (10.0, 0.1, 9.81)))
    assert set(variants) - {"run:zero:0", "run:zero:1"} == {"run:swap:0:2", "run:swap:1:2", "run:negated:2"}, \
        variants
    assert variants["run:swap:0:2"] == (9.81, 0.1, 10.0)
    assert variants["run:negated:2"] == (10.0, 0.1, -9.81)
    variants = dict((h.key, args) for h, args in parameter_variants(motion, (20.0, 0.3), (10.0, 0.1, 9.81)))
    assert variants["run:sheet:0"] == (10.0, 0.3, None) and variants["run:sheet:1"] == (20.0, 0.1, None)
    assert "run:sheet:2" not in variants
    # v0 = g: their exchange cannot be told
    assert "run:swap:0:2" not in {h.key for h, _ in parameter_variants(motion, (9.81, 0.1), (10.0, 0.1, 9.81))}


def test_run_variants_are_functions_of_the_arguments():
    """The start's entries exchanged and the looser tolerances are asked of the probe by its own variant argument,
    after the run's arguments (the kit's key holds them: they depend on nothing of the student's)."""
    from grader.diagnosis.runs import LOOSE_TOLERANCES, parameter_variants

    motion = {"variants": {"arg": 3, "starts": ((0, 1),), "tolerances": True}}
    found = parameter_variants(motion, (10.0, 0.1), None)
    assert [args for _, args in found][0] == (10.0, 0.1, None, ["start", 0, 1])
    assert [h.name for h, _ in found] == ["initial_state"] + ["step_size"] * len(LOOSE_TOLERANCES)
    assert all(args[:3] == (10.0, 0.1, None) for _, args in found)


def test_events_exchanged_are_told_apart_from_events_found_late():
    from grader.diagnosis.runs import exchanged_events

    expected = {"t_apex": 0.9, "t_land": 1.7}
    band = Tol("event time", 2e-3)
    assert exchanged_events({"t_apex": 1.7, "t_land": 0.9}, expected, ("t_apex", "t_land"), band) == ("t_apex",
                                                                                                       "t_land")
    assert exchanged_events({"t_apex": 0.95, "t_land": 1.75}, expected, ("t_apex", "t_land"), band) is None
    assert exchanged_events({"t_apex": 1.7, "t_land": None}, expected, ("t_apex", "t_land"), band) is None
    # two events at one time: no exchange can be told
    assert exchanged_events({"t_apex": 1.0, "t_land": 1.0}, {"t_apex": 1.0, "t_land": 1.0}, ("t_apex", "t_land"),
                            band) is None


def test_a_row_read_from_a_column_that_is_zero_is_not_told():
    """A state that stays zero tells no row: a run that returns zeros for it is not told as read from there."""
    from grader.diagnosis.runs import reread

    t = np.linspace(0.0, 1.0, 11)
    R = {"q": np.column_stack([np.sin(t), np.zeros_like(t)]), "qd": np.column_stack([np.cos(t), 2 * t])}
    tol = Tol("band", 1e-3)
    found = reread({"q": R["q"], "qd": np.column_stack([np.cos(t), np.sin(t)])}, R, ("q", "qd"), tol)
    assert found is not None and "qd[1] is the reference's q[0]" in found.detail, found
    assert reread({"q": R["q"], "qd": np.column_stack([np.cos(t), np.zeros_like(t)])}, R, ("q", "qd"), tol) is None
    assert reread(R, R, ("q", "qd"), tol) is None


def test_a_whole_state_read_from_another_is_told_where_a_column_of_it_lies_close_to_its_own():
    """Rates returned from the angles' rows, where one angle and its rate stay within a few tolerances of each
    other: no column alone tells the row, the whole state does; the start that then differs is not told beside it."""
    from grader.diagnosis import Declaration, Source
    from grader.diagnosis.runs import motion_slips, reread

    t = np.linspace(0.0, 1.0, 21)
    R = {"q": np.column_stack([np.sin(3 * t) + 1.0, 0.1 + 0.5 * t]), "qd": np.column_stack([3 * np.cos(3 * t),
                                                                                            0.5 + 0 * t])}
    tol = Tol("band", 5e-2)  # q[1] and qd[1] differ by at most 0.4 < 10 tolerances: not told apart column by column
    mine = {"q": R["q"], "qd": R["q"].copy()}
    found = reread(mine, R, ("q", "qd"), tol)
    assert found is not None and found.name == "state_row" and "qd is the reference's q" in found.detail, found
    # near misses: the rates off the angles by more than the tolerance, and rates that are the reference's own
    assert reread({"q": R["q"], "qd": R["q"] + 0.2}, R, ("q", "qd"), tol) is None
    assert reread(R, R, ("q", "qd"), tol) is None
    decl = Declaration(motion={"time": "t", "states": ("q", "qd")})
    ours, got = dict(R, t=t), dict(mine, t=t)
    evidence = Evidence(got["qd"], ours["qd"], tol, "qd", source=Source("stub.run", (), ("qd",), ours),
                        student=Source("stub.run", (), ("qd",), got))
    assert [h.name for h in motion_slips(evidence, decl)] == ["state_row"]


def _event_evidence(student_event, student_value):
    """The rates at an event of a stand-in run: the student's event time and rates, against the reference's."""
    from grader.diagnosis import Declaration, Source

    t = np.linspace(0.0, 1.0, 11)
    ours = {"t": t, "q": np.column_stack([t, t * t]), "qd": np.column_stack([np.ones_like(t), 2 * t]),
            "t_event": 1.0, "q_event": np.array([1.0, 1.0]), "qd_event": np.array([1.0, 2.0])}
    mine = dict(ours, t_event=student_event, qd_event=np.asarray(student_value, dtype=float))
    decl = Declaration(motion={"time": "t", "states": ("q", "qd"), "events": ("t_event",),
                               "at_events": {"q_event": ("t_event", "q"), "qd_event": ("t_event", "qd")}})
    evidence = Evidence(mine["qd_event"], ours["qd_event"], Tol("qd at the event", 1e-3), "qd_event",
                        source=Source("stub.run", (), ("qd_event",), ours),
                        student=Source("stub.run", (), ("qd_event",), mine))
    return evidence, decl


def test_a_state_at_an_event_is_read_from_its_rows_only_where_the_event_agrees():
    from grader.diagnosis.runs import event_state_slips

    evidence, decl = _event_evidence(1.0, [1.0, 1.0])  # the rates are the positions at the event
    assert [h.name for h in event_state_slips(evidence, decl)] == ["state_row"]
    evidence, decl = _event_evidence(1.2, [1.0, 1.0])  # the event itself is found late: its rows tell nothing
    assert event_state_slips(evidence, decl) == []
    evidence, decl = _event_evidence(1.0, [1.0, 3.0])  # no row of the state at the event
    assert event_state_slips(evidence, decl) == []


def test_a_state_at_an_event_interpolated_between_samples_is_its_own_row_read_approximately():
    """An apex between two output samples: the height interpolated linearly there is the height's own row, read
    between the samples where the state at the event (y_events) belongs; not another row.  The speed's row
    interpolated there is another row."""
    from grader.diagnosis import Declaration, Source
    from grader.diagnosis.runs import event_state_slips

    t = np.linspace(0.0, 1.0, 11)
    te = 0.57  # between the samples at 0.5 and 0.6, nearer the later
    exact = {"h": lambda s: 5.0 - 4.0 * (s - te) ** 2, "v": lambda s: -8.0 * (s - te) + 3.0}
    ours = {"t": t, "y": np.column_stack([exact["h"](t), exact["v"](t)]), "t_apex": te,
            "height_apex": np.array(exact["h"](te))}
    decl = Declaration(motion={"time": "t", "states": ("y",), "events": ("t_apex",),
                               "at_events": {"height_apex": ("t_apex", "y", 0)}})

    def told(value):
        mine = dict(ours, height_apex=np.array(value))
        evidence = Evidence(mine["height_apex"], ours["height_apex"], Tol("the apex's height", 1e-4), "height_apex",
                            source=Source("stub.run", (), ("height_apex",), ours),
                            student=Source("stub.run", (), ("height_apex",), mine))
        return [(h.name, h.detail) for h in event_state_slips(evidence, decl)]

    interpolated = float(np.interp(te, t, ours["y"][:, 0]))
    assert abs(interpolated - 5.0) > 1e-3  # the samples miss the apex by more than the tolerance
    found = told(interpolated)
    assert [name for name, _ in found] == ["event_interpolated"], found
    assert "interpolated between its output samples" in found[0][1], found
    found = told(float(np.interp(te, t, ours["y"][:, 1])))  # the speed's row there: another row
    assert [name for name, _ in found] == ["state_row"], found
    assert told(5.0 + 0.3) == []


def _grid_evidence(times):
    """A run compared by its output times: the student's at ``times``, the reference's every 0.1 s over 1 s, both
    the same motion (sin t) at their own times."""
    ours = np.linspace(0.0, 1.0, 11)
    source = {"t": ours, "q": np.sin(ours)[:, None]}
    mine = {"t": np.asarray(times, dtype=float), "q": np.sin(times)[:, None]}
    return Evidence(mine["t"], ours, Tol("t", 1e-9, 1e-9), "t", source=engine.Source("p.run", (), ("t",), source),
                    student=engine.Source("p.run", (), ("t",), mine))


@pytest.mark.parametrize("times, told", [
    (np.linspace(0.0, 1.0, 11, endpoint=False), True),  # the span over the samples: a grid of one more, cut
    (np.arange(11) * 0.1 * 10 / 9, True),  # the span over one step fewer: a grid of one fewer, run past the end
    (np.linspace(0.0, 0.95, 11), False),  # another end: no grid of one sample more or fewer
    (np.linspace(0.0, 1.0, 11) + 0.1, False),  # shifted: it starts elsewhere
    (np.linspace(0.0, 1.0, 11) ** 2, False),  # not even
])
def test_an_output_grid_one_sample_off_is_told_only_for_that_spacing(times, told):
    from grader.diagnosis.evidence import Declaration
    from grader.diagnosis.runs import grid_slips

    found = grid_slips(_grid_evidence(times), Declaration(motion={"time": "t", "states": ("q",)}))
    assert [h.name for h in found] == (["grid_off_by_one"] if told else [])


def _rates_run(mine, span=1.0):
    """The motion slips of a stand-in run of two angles and their rates, over ``span`` seconds, against the
    student's ``mine``."""
    from grader.diagnosis import Declaration, Source
    from grader.diagnosis.runs import motion_slips

    t = np.linspace(0.0, span, 41)
    ours = {"t": t, "q": np.column_stack([np.sin(2 * t), 0.3 * t * t]),
            "qd": np.column_stack([2 * np.cos(2 * t), 0.6 * t])}
    got = dict(mine(ours), t=t)
    decl = Declaration(motion={"time": "t", "states": ("q", "qd")})
    evidence = Evidence(got["qd"], ours["qd"], Tol("band", 1e-3), "qd", source=Source("stub.run", (), ("qd",), ours),
                        student=Source("stub.run", (), ("qd",), got))
    return {h.name for h in motion_slips(evidence, decl)}


def test_rates_derived_from_angles_that_are_right_are_no_wrong_start():
    """A run whose angles are the reference's throughout, its rates differenced from them afterwards (the first
    rate a forward difference): the rates' start differs, but rates from another start would have moved the angles,
    declared before them, so no wrong start is told; the near miss, a run from other rates, moves the angles too and
    is told so.  (A coordinate's start that differs beside rates right throughout is a wrong start still:
    ``test_one_input``'s drift of a matrix.)"""
    def differenced(ours):
        return {"q": ours["q"], "qd": np.vstack([np.diff(ours["q"], axis=0) / np.diff(ours["t"])[:, None],
                                                 (ours["q"][-1] - ours["q"][-2]) / (ours["t"][-1] - ours["t"][-2])])}

    assert "initial_state" not in _rates_run(differenced)

    def started_otherwise(ours):
        t = ours["t"][:, None]
        return {"q": ours["q"] + 0.05 * t, "qd": ours["qd"] + 0.05}

    assert "initial_state" in _rates_run(started_otherwise)


def test_rates_started_a_little_off_beside_angles_within_the_tolerance_are_a_wrong_start():
    """A start of the rates off by so little that, kept over the run, it would move the angles by less than their
    tolerance (rounded, say): the angles being right says nothing of the start, which is told."""
    def nudged(ours):
        t = ours["t"][:, None]
        return {"q": ours["q"] + 2e-3 * t, "qd": ours["qd"] + 2e-3 * np.exp(-20 * t)}

    assert "initial_state" in _rates_run(nudged, span=0.2)
