"""Checks of problem 46: the robot arm of problem 37 caught by a wire (``make_wire_event``, ``constraint_terms``,
``plastic_impact``, ``constrained_dynamics``, ``constrained_ode``, ``simulate``).

The pieces first, by physics where it decides (the constraint Jacobian is minus the gradient of the student's own
event function; after a plastic impact ``J qd+ = 0`` and the impulse pulls, ``Lam > 0``; the constrained dynamics
meet the constraint and the equations of motion) and against the reference at random states with a catalogue of
known mistakes.  Then the run: the event, the impact and the constrained motion, against a tight reference run
within the bands of the problem data's erratum (the sheet's digits come from MATLAB's loose ode45), and the
constraint violation with and without Baumgarte stabilisation.  After the plastic impact the wire is taut, so the
runs with and without stabilisation differ only by the drift: ``constrained_ode`` is called both ways at states off
the wire and in turn on one robot, and the two runs must not be the same run.  The run needs every piece: when one
of them fails, the run's checks are not run (they share one group, the pieces at an earlier stage).
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
    as_array,
    assert_close,
    check,
    close,
    fail,
    figure,
)
from probes import problem_37 as p37, problem_46 as p46

from ._dynamics import assert_event_found, assert_fresh_along_a_run, assert_run, run_array, same_crossings, subsample
from ._effects import assert_no_side_effects, same, shown
from ._real import rank_flaw, require_real
from ._upstream import judging

TITLE = "Robotic Arm. 3 - Event Detection"
MANUAL = {"derivation": ("46: derive the constraint terms J_lambda and sigma_lambda (and the Baumgarte terms).", 2)}

#: problem data P46
ANCHOR = np.array([-1.0, -1.0, -1.0])
WIRE_LENGTH = 2.0
T_END = 2.0
SHEET_EVENT_TIME = 0.93313
SHEET_Q_PLUS = np.array([0.45214, -0.59389, -1.6775])
SHEET_QD_PLUS = np.array([0.98849, 0.01024, -0.99379])
#: the erratum's bands around a tight reference run
EVENT_TIME = Tol("event time, erratum band", 2e-3)
Q_PLUS = Tol("q_PLUS, erratum band", 1e-3)
QD_PLUS = Tol("d_q_PLUS, erratum band", 5e-2)
#: two codings of the constrained phase's derivative agree to this (a solve of the whole system or of its Schur
#: complement); a slip moves it by far more
ODE = Tol("the constrained derivative, a linear solve", 1e-7, 1e-6)
ERRATUM = ("The sheet's t = 0.93313, q_PLUS and d_q_PLUS come from MATLAB's ode45 at RelTol 1e-3: a tight "
           "integration gives q_PLUS to 1e-5 and the event time to 2e-4, but d_q_PLUS differs by up to 0.04 per "
           "component. Graded against a tight reference run with the bands of the problem data.")
#: after the impact: the same bands as the free robot (problem 37); any solve_ivp method at default tolerances
#: stays within 0.0021 rad and 0.015 rad/s
BAND = {"q": Tol("a reasonable integrator", 1e-2), "qd": Tol("a reasonable integrator", 5e-2)}
#: with Baumgarte stabilisation the wire stays taut to this [m] (solve_ivp at default tolerances: 4e-5)
TAUT = Tol("constraint violation with Baumgarte", 1e-3)
IMPACT = Tol("after a plastic impact", 1e-8, 1e-8)
PHYSICS = Tol("constrained dynamics", 1e-8, 1e-8)
H = 1e-6
DIFFERENCES = Tol("finite differences, h = 1e-6", 1e-6, 1e-6)
SIMULATION_TIMEOUT = 30.0
_SEEDS = st.integers(0, 2**32 - 1)

BANDS_NOTE = ("Any scipy.integrate.solve_ivp method at its default tolerances, with events=[wire_stretched], lands "
              "within the bands.")
CONSTRAINT_HINTS = {
    "baumgarte_sign": "Baumgarte adds P_B c + D_B c_dot with c = wire_length - |anchor - I_r_E| and c_dot = -dir.T "
                      "I_v_E, so that c_ddot + D_B c_dot + P_B c = 0 drives a violation back to zero; with the wrong "
                      "sign it grows.",
    "missing_baumgarte": "With baumgarte=True, sigma_lam gets the stabilisation P_B (wire_length - |anchor - I_r_E|) "
                         "+ D_B (0 - dir.T I_v_E).",
    "jacobian_sign": "J_lam = -dir.T A_IE B_J_S,E with dir = (I_r_E - anchor) / |I_r_E - anchor|: the constraint is "
                     "c = wire_length - |anchor - I_r_E|, whose rate is -dir.T I_v_E.",
    "constraint_sign": "The sheet writes the constraint as c = wire_length - |anchor - I_r_E| (J_lam = -dir.T A_IE "
                       "B_J_S,E): then lambda > 0 is the wire's pull. Yours is the same constraint with the other sign "
                       "(J and sigma both flipped).",
    "wrong_frame": "B_J_S,E and B_a_E are in the end effector's coordinates: bring them to I with A_IE before the dot "
                  "product with dir (which is in I).",
    "missing_centripetal": "sigma_lam = -dir.T A_IE B_a_E - |dir x I_v_E|^2 / wire_length: the second derivative of "
                      "|anchor - I_r_E| has a centripetal part (the direction turns).",
    "centripetal_sign": "The centripetal part of sigma_lam is -|dir x I_v_E|^2 / wire_length (c_ddot = J qdd + "
                        "sigma with c = wire_length - |anchor - I_r_E|).",
}


def _robot_state(rng, spread=1.0):
    return rng.uniform(-spread, spread, 3) + np.array([0.4, -0.6, -1.6]), rng.uniform(-1.5, 1.5, 3)


# ------------------------------------------------------------------------------------------ the event


@st.composite
def _event_cases(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    return ([np.concatenate(_robot_state(rng)) for _ in range(3)],)


def _taut(ctx):
    """The state where the reference's run finds the wire taut (the event: the residual is zero there) and the
    student's event function's value at it."""
    table = ctx.reference(p37.trajectory, persist=True)
    run = ctx.reference(p46.simulate, table, True, T_END, persist=True)
    state = np.concatenate([np.asarray(run["q_minus"], dtype=float), np.asarray(run["qd_minus"], dtype=float)])
    return state, ctx.reference(p46.event, [state])["values"][0]


@check(2, title="make_wire_event: the residual |anchor - I_r_E| - wire_length at random states (or a residual with "
       "the same zero crossings), terminal, direction +1 (or 0: the same run)", stage=STAGE_STRUCTURE, group="wire")
def check_event_function(ctx):
    taut, at_taut = _taut(ctx)
    mine_at_taut = as_array(ctx.student(p46.event, [taut])["values"], "wire_stretched(t, y)", (1,))[0]

    def compare(got, expected, args):
        if not isinstance(got, dict):
            fail(f"the probe could not evaluate your event function: {str(got)[:200]}")
        values = np.asarray(expected["values"])
        mine = as_array(got["values"], "wire_stretched(t, y)", values.shape)
        if not (close(mine, values, EXACT)
                or same_crossings(np.append(mine, mine_at_taut), np.append(values, at_taut))):
            assert_close(mine, values, "wire_stretched(t, y)", EXACT, [
                Mistake("event_sign", -values, "The residual is |anchor - I_r_E| - wire_length: negative while the "
                        "wire is slack, zero when it is taut (with direction +1 the event fires as it becomes taut)."),
            ], context="(three random states of the arm)",
                note="Another residual with the same zero crossings (the same sign everywhere, zero where the wire "
                     "becomes taut) is as good.")
        if got["terminal"] is not True:
            fail(f"wire_stretched.terminal is {got['terminal']!r}: the integration must stop when the wire becomes "
                 f"taut (the impact follows).", "Set wire_stretched.terminal = True.", "not_terminal")
        if got["direction"] not in (1.0, 0.0):
            fail(f"wire_stretched.direction is {got['direction']!r}, expected +1 (or 0): the residual crosses zero "
                 f"from - to + when the wire becomes taut.",
                 "direction = +1 detects only crossings from - to +; -1 would wait for the wire to go slack again "
                 "(it never does) and 0 also fires on that.", "event_direction")

    compare = judging(ctx, p46.event, compare)
    ctx.compare_random(p46.event, _event_cases(), name="the event", tol=EXACT, compare=compare, examples=6,
                       describe=lambda args: f"y = {[np.round(y, 4).tolist() for y in args[0]]}")


# ------------------------------------------------------------------------------------------ constraint terms


@st.composite
def _states(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    return (rng.uniform(-2, 2, 3),)


@check(1, title="J_lam is minus the gradient of your own event residual |anchor - I_r_E| - wire_length (finite "
       "differences)", stage=STAGE_STRUCTURE, group="wire")
def check_constraint_jacobian(ctx):
    def compare(got, expected, args):
        J = as_array(got["J"], "J_lam", (1, 3))
        fd = np.array([[(plus - minus) / (2 * H) for plus, minus in got["shifted"]]])
        reformulated = not close(got["shifted"], expected["shifted"], EXACT)
        if reformulated and not close(J, -fd, DIFFERENCES) and close(J, expected["J"], EXACT):
            return  # another residual of the same event (the check above judges it): J of the sheet's constraint
        require_real("J_lam", "event residual", [("d/dq of your own event residual", rank_flaw(fd, expected["J"]))])
        assert_close(J, -fd, "J_lam", DIFFERENCES, [
            Mistake("jacobian_sign", fd, CONSTRAINT_HINTS["jacobian_sign"]),
        ], context=f"at q = {np.round(args[0], 4).tolist()} (expected: -d/dq of your own event residual)")

    compare = judging(ctx, p46.event_differences, compare,
                      lambda got, value, args: assert_close(got["J"], value["J"], "J_lam", EXACT,
                                                            context=f"at q = {np.round(args[0], 4).tolist()}"))
    ctx.compare_random(p46.event_differences, _states().map(lambda a: (a[0], H)), name="J_lam",
                       tol=DIFFERENCES, compare=compare, examples=6,
                       describe=lambda args: f"q = {np.round(args[0], 4).tolist()}")


@st.composite
def _term_cases(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    q, qd = _robot_state(rng, 2.0)
    return ([(q, qd, draw(st.booleans()))],)


@check(3, title="constraint_terms: J_lam and sigma_lam (with and without Baumgarte) at random states",
       stage=STAGE_STRUCTURE, group="wire")
def check_constraint_terms(ctx):
    def compare(got, expected, args):
        q, qd, baumgarte = args[0][0]
        mistakes = ctx.reference(p46.constraint_mistakes, q, qd, baumgarte)
        if not isinstance(got, list) or not got or not isinstance(got[0], dict):
            fail(f"constraint_terms must return (J_lam, sigma_lam), got {str(got)[:200]}", diagnosis="format")
        for key, name in (("J", "J_lam"), ("sigma", "sigma_lam")):
            value = np.asarray(expected[0][key])
            found = [Mistake(mistake, terms[key], CONSTRAINT_HINTS[mistake]) for mistake, terms in mistakes.items()
                     if not close(terms[key], value, EXACT)]
            assert_close(got[0][key], value, name, EXACT, found, context=f"(baumgarte = {baumgarte})")

    compare = judging(ctx, p46.constraint_terms, compare)
    ctx.compare_random(p46.constraint_terms, _term_cases(), name="J_lam, sigma_lam", tol=EXACT,
                       compare=compare, examples=10,
                       describe=lambda args: f"q = {np.round(args[0][0][0], 4).tolist()}, qd = "
                       f"{np.round(args[0][0][1], 4).tolist()}, baumgarte = {args[0][0][2]}")


# ------------------------------------------------------------------------------------------ impact


def _spd(rng, n=3):
    A = rng.uniform(-1, 1, (n, n))
    return A @ A.T + 0.5 * np.eye(n)


@st.composite
def _impacts(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    M, J, qd = _spd(rng), rng.uniform(-1, 1, (1, 3)), rng.uniform(-2, 2, 3)
    if (J @ qd)[0] > 0:  # closing: J qd- < 0 (c = wire_length - |anchor - I_r_E| decreasing)
        qd = -qd
    return ([(M, J, qd)],)


#: two closing impacts ``(M, J, qd_minus)`` without special structure, for the side-effect check of plastic_impact
SIDE_IMPACTS = (
    (np.array([[2.0, 0.3, -0.2], [0.3, 1.5, 0.4], [-0.2, 0.4, 1.2]]), np.array([[0.6, -0.3, 0.8]]),
     np.array([-1.1, 0.7, -0.9])),
    (np.array([[1.4, -0.2, 0.1], [-0.2, 2.2, 0.3], [0.1, 0.3, 0.9]]), np.array([[-0.4, 0.9, 0.5]]),
     np.array([0.8, -1.3, -0.6])),
)


@check(3, title="plastic_impact: J qd+ = 0, Lam > 0 and no energy gained on random closing impacts, and the values "
       "of the reference; qd_minus is left as it was", stage=STAGE_STRUCTURE, group="wire")
def check_plastic_impact(ctx):
    def compare(got, expected, args):
        M, J, qd_minus = args[0][0]
        if not isinstance(got, list) or not got or not isinstance(got[0], dict):
            fail(f"plastic_impact must return (qd_plus, Lam), got {str(got)[:200]}", diagnosis="format")
        qd_plus = as_array(got[0]["qd_plus"], "qd_plus", (3,))
        Lam = as_array(got[0]["Lam"], "Lam", (1,))
        expected_plus, expected_Lam = np.asarray(expected[0]["qd_plus"]), np.asarray(expected[0]["Lam"])
        elastic = 2 * expected_plus - qd_minus
        # an elastic impact is told only where every velocity after it is the elastic law's, not merely the
        # reversed closing velocity (all velocities reversed reverse it too)
        assert_close(J @ qd_plus, np.zeros(1), "J qd_plus", IMPACT, [
            *([Mistake("elastic", J @ elastic, "A fully plastic impact stops the closing velocity: qd_plus = "
                       "qd_minus + M^-1 J.T Lam with Lam = -(J M^-1 J.T)^-1 J qd_minus gives J qd_plus = 0; yours "
                       "reverses it (restitution 1, elastic).")] if close(qd_plus, elastic, IMPACT) else []),
            Mistake("unchanged", J @ qd_minus, "The impact changes the velocities: qd_plus = qd_minus + M^-1 J.T Lam."),
        ], context="(after a plastic impact the constraint's velocity is zero)")
        if Lam[0] <= 0:
            assert_close(Lam, expected_Lam, "Lam", EXACT, [
                Mistake("impulse_sign", -expected_Lam, "Lam = -(J M^-1 J.T)^-1 J qd_minus > 0 for a closing "
                        "impact (J qd_minus < 0): the wire pulls; the impulse acts through +J.T Lam."),
            ], context="(a plastic impulse on a closing impact is positive)")
        energy = (qd_plus @ M @ qd_plus, qd_minus @ M @ qd_minus)
        if energy[0] > energy[1] * (1 + 1e-9):
            fail(f"the impact gained kinetic energy: qd_plus.T M qd_plus = {energy[0]:.6g} > qd_minus.T M qd_minus = "
                 f"{energy[1]:.6g}.", "A plastic impact dissipates energy.", "energy_gain")
        assert_close(qd_plus, expected_plus, "qd_plus", EXACT)
        assert_close(Lam, expected_Lam, "Lam", EXACT)

    ctx.compare_random(p46.impact, _impacts(), name="the impact", tol=EXACT, compare=compare, examples=10,
                       describe=lambda args: "M = {}, J = {}, qd_minus = {}".format(
                           *(np.round(x, 4).tolist() for x in args[0][0])))
    assert_no_side_effects(ctx, "problem_46", "plastic_impact", *SIDE_IMPACTS, ("M", "J", "qd_minus"))


@st.composite
def _constrained_cases(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    return ([(_spd(rng), *rng.uniform(-3, 3, (3, 3)), rng.uniform(-1, 1, (1, 3)), rng.uniform(-3, 3, 1))],)


@check(2, title="constrained_dynamics: J qdd = -sigma on random systems, and qdd and lam (the force through "
       "+J.T lam) of the reference", stage=STAGE_STRUCTURE, group="wire")
def check_constrained_dynamics(ctx):
    def compare(got, expected, args):
        M, f, g, tau, J, sigma = args[0][0]
        if not isinstance(got, list) or not got or not isinstance(got[0], dict):
            fail(f"constrained_dynamics must return (qdd, lam), got {str(got)[:200]}", diagnosis="format")
        qdd = as_array(got[0]["qdd"], "qdd", (3,))
        lam = as_array(got[0]["lam"], "lam", (1,))
        expected_qdd, expected_lam = np.asarray(expected[0]["qdd"]), np.asarray(expected[0]["lam"])
        assert_close(J @ qdd, -sigma, "J qdd", PHYSICS, [
            Mistake("sigma_sign", sigma, "The constraint acceleration is zero: J qdd + sigma = 0, so the lower "
                    "block row is [J, 0] [qdd; lam] = -sigma."),
        ], context="(the constraint holds: J qdd + sigma = 0)")
        assert_close(lam, expected_lam, "lam", EXACT, [
            Mistake("constraint_force_sign", -expected_lam, "The constraint force acts through +J.T lam: "
                    "M qdd = f + g + tau + J.T lam, so the system is [[M, -J.T], [J, 0]] [qdd; lam] = "
                    "[f + g + tau; -sigma]."),
        ])
        assert_close(qdd, expected_qdd, "qdd", EXACT)

    ctx.compare_random(p46.constrained, _constrained_cases(), name="qdd, lam", tol=EXACT, compare=compare,
                       examples=10, describe=lambda args: "M = {}, f = {}, g = {}, tau = {}, J = {}, sigma = {}".format(
                           *(np.round(x, 4).tolist() for x in args[0][0])))


# ------------------------------------------------------------------------------------------ the run


#: a wire the sheet does not print: hung 10 cm higher and 10 cm longer, it becomes taut at about 0.987 s (the
#: sheet's at 0.933 s), so that the sheet's event time typed in instead of detected earns nothing
OTHER_WIRE = (np.array([-1.0, -0.9, -1.0]), 2.1)
#: the run with the other wire ends shortly after its impact
T_OTHER = 1.1
IGNORED_WIRE_HINT = ("Your run becomes taut where the sheet's wire does whatever wire it is given: pass simulate's "
                     "anchor and wire_length on to make_wire_event (and to the constrained phase).")
TYPED_EVENT_HINT = ("Your run has the sheet's event time whatever wire it is given: detect the event with "
                    "solve_ivp(..., events=[wire_stretched]) for the anchor and wire_length passed to simulate.")


def _run(ctx, baumgarte):
    """The student's run and the reference's; the student's is simulated once per grading (kept on the context,
    which lives for the checks of this problem)."""
    table = ctx.reference(p37.trajectory, persist=True)
    expected = ctx.reference(p46.simulate, table, baumgarte, T_END, persist=True)
    runs = ctx.__dict__.setdefault("problem_46_runs", {})
    if baumgarte not in runs:
        runs[baumgarte] = ctx.student(p46.simulate, table, baumgarte, T_END, timeout=SIMULATION_TIMEOUT)
    return runs[baumgarte], expected


def _violation(run, what, anchor=ANCHOR, wire_length=WIRE_LENGTH):
    """The times after the event and the wire's stretch ``|anchor - I_r_E| - wire_length`` at them."""
    t = run_array(run, "t", None, what)
    x = run_array(run, "x", (t.size, 3), what)
    after = t >= run["t_event"]
    return t[after], np.linalg.norm(anchor - x[after], axis=1) - wire_length


def _event(got, what, expected):
    """The student's event time; where their run has none, the first place it leaves the reference's run
    ``expected`` before the reference's event is what differs (``assert_event_found``), and only a run that follows
    the reference's there and never fires has missed the event."""
    if not isinstance(got, dict):
        fail(f"{what} returned no dict of the run.", "Return a dict with the keys named in the docstring.", "format")
    assert_event_found(got, expected, "t_event", ("q", "qd"), BAND, what,
                       f"{what}: no event, the wire never became taut (t_event is None); the reference's run hits it "
                       f"at t = {float(expected['t_event']):.3f} s.",
                       "Your run follows the reference's up to its event, yet no event fires: the residual |anchor - "
                       "I_r_E| - wire_length rises through zero there, so the event needs direction = +1 (and "
                       "terminal = True).")
    return float(got["t_event"])


def _aligned(got, expected, margin=0.01):
    """Rows of both runs at their common output times away from both event times."""
    t_mine, t_ours = np.asarray(got["t"]), np.asarray(expected["t"])
    events = sorted([float(got["t_event"]), float(expected["t_event"])])
    common = np.intersect1d(np.round(t_mine, 6), np.round(t_ours, 6))  # output times, to a microsecond
    keep = common[(common < events[0] - margin) | (common > events[1] + margin)]
    mine, ours = np.isin(np.round(t_mine, 6), keep), np.isin(np.round(t_ours, 6), keep)
    return ({"t": t_mine[mine], "q": np.asarray(got["q"])[mine], "qd": np.asarray(got["qd"])[mine]},
            {"t": t_ours[ours], "q": np.asarray(expected["q"])[ours], "qd": np.asarray(expected["qd"])[ours]})


def _assert_closing(got, J, q_minus, Lam):
    """Where the impulse does not pull (``Lam <= 0``) and the run's own rates before the impact do not stretch the
    wire (``J_lam qd_minus >= 0``), the impulse follows from those rates, not from a sign of its formula: fail on the
    rates, told as the angles read where the rates belong (a state's wrong rows) where they are the angles."""
    if got.get("qd_minus") is None:
        return
    qd_minus = as_array(got["qd_minus"], "qd_minus", (3,))
    closing = float((J @ qd_minus)[0])
    if closing < 0:
        return
    rows = bool(np.array_equal(qd_minus, q_minus))
    fail(f"the impulse of the wire is Lam = {Lam:.6g}, and with your rates before the impact, qd_minus = "
         f"{np.round(qd_minus, 6).tolist()}, J_lam qd_minus = {closing:.6g} >= 0: those rates do not stretch the "
         "wire, so no impulse is needed to stop them" + (" (they are the angles q_minus)." if rows else "."),
         "The impact starts from the state at the event: q_minus = y_event[:3] and qd_minus = y_event[3:], the "
         "rates with which the wire becomes taut (J_lam qd_minus < 0).", "state_row" if rows else "")


@check(3, title="the run: the wire becomes taut at t = 0.933 s (within 2e-3 s of a tight run), q+ = q-, the impact "
       "leaves J qd+ = 0 with Lam > 0, and q+, qd+ match within the erratum's bands; with a wire hung elsewhere, the "
       "event and q+ follow and the run stays on that wire", stage=STAGE_VALUES, group="wire")
def check_event_and_impact(ctx):
    got, expected = _run(ctx, True)
    what = "simulate(trajectory, baumgarte=True)"
    t_event = _event(got, what, expected)
    assert_close(t_event, expected["t_event"], "t_event", EVENT_TIME, context=f"(a tight reference run; the sheet "
                 f"prints {SHEET_EVENT_TIME})", note=f"{ERRATUM} {BANDS_NOTE}")
    q_minus, q_plus = (as_array(got[key], key, (3,)) for key in ("q_minus", "q_plus"))
    _positions_kept(q_minus, q_plus, expected, "", "an impact changes velocities only: q_plus = q_minus")
    qd_plus, Lam = as_array(got["qd_plus"], "qd_plus", (3,)), as_array(got["Lam"], "Lam", (1,))
    J = as_array(got["J_plus"], "J_lam at the impact (your constraint_terms)", (1, 3))
    assert_close(J @ qd_plus, np.zeros(1), "J_lam qd_plus", Tol("after a plastic impact", 1e-6, 1e-6),
                 context="(with your own constraint_terms at the impact: a plastic impact stops the wire's stretching)")
    if Lam[0] <= 0:
        _assert_closing(got, J, q_minus, Lam[0])
        fail(f"the impulse of the wire is Lam = {Lam[0]:.6g}: a taut wire pulls, Lam > 0 (J_lam = -dir.T A_IE "
             f"B_J_S,E).", "Lam = -(J M^-1 J.T)^-1 J qd_minus with J qd_minus < 0 at the moment the wire becomes "
             "taut.", "impulse_sign")
    assert_close(q_plus, expected["q_plus"], "q_plus", Q_PLUS, context=f"(a tight reference run; the sheet prints "
                 f"{SHEET_Q_PLUS.tolist()})", note=f"{ERRATUM} {BANDS_NOTE}")
    assert_close(qd_plus, expected["qd_plus"], "qd_plus", QD_PLUS, context=f"(a tight reference run; the sheet prints "
                 f"{SHEET_QD_PLUS.tolist()})", note=f"{ERRATUM} {BANDS_NOTE}")
    _assert_halves_after(got, t_event, q_plus, qd_plus)
    _assert_other_wire(ctx, got)


def _assert_halves_after(got, t_event, q_plus, qd_plus):
    """The run's row at the event time is the state after the impact, from which the constrained phase starts.
    Where that row holds the impact's state with its halves exchanged (``qd_plus`` as the angles, ``q_plus`` as the
    rates: the second phase started from ``concatenate([qd_plus, q_plus])``), the state was put together in the
    wrong order: told as such.  Any other row there is left to the checks of the motion (a run may end its first
    phase at the event time, with the state before the impact in the last such row)."""
    try:
        t, q, qd = (np.asarray(got[key], dtype=float) for key in ("t", "q", "qd"))
    except (KeyError, TypeError, ValueError):
        return
    if t.ndim != 1 or q.shape != (t.size, 3) or qd.shape != (t.size, 3):
        return
    rows = np.flatnonzero(np.abs(t - t_event) <= 1e-9 * max(1.0, abs(t_event)))
    if rows.size and close(q[rows[-1]], qd_plus, EXACT) and close(qd[rows[-1]], q_plus, EXACT) \
            and not close(q_plus, qd_plus, EXACT):
        fail(f"the run's state at the event time t = {t_event:.6g} s, from which the constrained phase starts, holds "
             f"your qd_plus as its angles and your q_plus as its rates: the state after the impact is put together "
             f"with its halves exchanged.", "The state is y = (q, qd): start the constrained phase from "
             "concatenate([q_plus, qd_plus]).", "state_row")


def _positions_kept(q_minus, q_plus, expected, of, why):
    """The impact keeps the positions, ``q_plus = q_minus``.  Where the two differ, the one that leaves the
    reference's is the one to blame: a ``q_minus`` off the reference's state at the event (within the erratum's band)
    fails against it, so that its cause (a state of another time, say) can be named; else ``q_plus`` fails against
    the student's own ``q_minus``."""
    if not close(q_plus, q_minus, EXACT):
        assert_close(q_minus, expected["q_minus"], f"q_minus{of}", Q_PLUS,
                     context="(the state at the event, against a tight reference run)", note=BANDS_NOTE)
    assert_close(q_plus, q_minus, f"q_plus{of}", EXACT, context=f"({why})")


def _assert_other_wire(ctx, sheet_run):
    """The run with a wire hung elsewhere (``OTHER_WIRE``) becomes taut when the reference's does, and the impact
    happens there: the sheet's event time typed in fails.  ``sheet_run``: the student's run on the sheet's wire."""
    table = ctx.reference(p37.trajectory, persist=True)
    anchor, length = OTHER_WIRE
    expected = ctx.reference(p46.simulate, table, True, T_OTHER, OTHER_WIRE, persist=True)
    what = (f"simulate(trajectory, baumgarte=True, t_end={T_OTHER:g}, anchor={anchor.tolist()}, "
            f"wire_length={length:g})")
    got = ctx.student(p46.simulate, table, True, T_OTHER, OTHER_WIRE, timeout=SIMULATION_TIMEOUT)
    t_event = _event(got, what, expected)
    sheet = ctx.reference(p46.simulate, table, True, T_END, persist=True)["t_event"]
    assert_close(t_event, expected["t_event"], f"t_event of {what}", EVENT_TIME,
                 [Mistake("typed_numbers", SHEET_EVENT_TIME, TYPED_EVENT_HINT),
                  Mistake("ignored_argument", sheet, IGNORED_WIRE_HINT)],
                 context="(a tight reference run; a wire the sheet does not print)", note=BANDS_NOTE)
    q_minus, q_plus = (as_array(got[key], f"{key} of {what}", (3,)) for key in ("q_minus", "q_plus"))
    _positions_kept(q_minus, q_plus, expected, f" of {what}", "an impact changes velocities only")
    assert_close(q_plus, expected["q_plus"], f"q_plus of {what}", Q_PLUS, context="(a tight reference run)",
                 note=BANDS_NOTE)
    _assert_taut(ctx, got, what, anchor, length, sheet_run)


def _stays_taut(run, what, anchor=ANCHOR, wire_length=WIRE_LENGTH) -> bool:
    """The run holds the end effector on its wire after the impact, within ``TAUT``; False for a run whose times or
    positions cannot be read (the failure at hand is the other run's, not this one's)."""
    try:
        t, violation = _violation(run, what, anchor, wire_length)
    except CheckFailure:
        return False
    return not t.size or np.abs(violation).max() <= TAUT.atol


def _assert_taut(ctx, run, what, anchor, wire_length, sheet_run=None):
    """After the impact the run holds the end effector on the wire it was given, within ``TAUT``.  Where the
    student's run on the sheet's wire (``sheet_run``) stays taut and this one does not, their constrained phase holds
    the sheet's wire alone: the wire it is given is ignored somewhere (told as such).  Any other slip of the
    constrained phase leaves the sheet's wire too: constrained_ode is then compared with the reference's where the
    slip is made (``_assert_constrained_values``), and only a constrained_ode that gives the reference's values
    leaves the failure in words."""
    t, violation = _violation(run, what, anchor, wire_length)
    if t.size and np.abs(violation).max() > TAUT.atol:
        i = int(np.argmax(np.abs(violation) > TAUT.atol))
        ignored = sheet_run is not None and _stays_taut(sheet_run, "simulate(trajectory, baumgarte=True)")
        if not ignored:
            _assert_constrained_values(ctx)
        fail(f"{what}: after the impact the end effector leaves the wire it was given: |anchor - I_r_E| - "
             f"wire_length = {violation[i]:.3g} m at t = {t[i]:.4g} s (with Baumgarte stabilisation it stays "
             f"within {TAUT.atol:g} m)" + (", although your run on the sheet's wire stays on it." if ignored else
                                           ", and so does your run on the sheet's wire."),
             "The constrained phase holds the end effector on the wire passed to simulate: every function of the "
             "constrained phase (constrained_ode, constraint_terms) needs that anchor and wire_length, not the "
             "sheet's." if ignored else
             "The constrained phase does not hold the end effector on any wire: look at how simulate runs it (the "
             "state it starts from after the impact, the arguments it passes) and at constraint_terms.",
             "ignored_argument" if ignored else "")


@check(3, title="the constrained motion after the impact: constrained_ode honours baumgarte and keeps nothing "
       "between calls, the two runs differ, with Baumgarte the wire stays taut (within 1e-3 m) and the run follows "
       "the reference's; without it the violation is shown", stage=STAGE_VALUES, group="wire")
def check_constrained_motion(ctx):
    got, expected = _run(ctx, True)
    plain, plain_expected = _run(ctx, False)
    what = "simulate(trajectory, baumgarte=True)"
    _event(got, what, expected)
    _event(plain, "simulate(trajectory, baumgarte=False)", plain_expected)
    curves = {}
    for label, run in (("with Baumgarte", got), ("without", plain)):
        curves[label] = _violation(run, label)
    ours = {label: _violation(run, label) for label, run in (("with Baumgarte", expected),
                                                             ("without", plain_expected))}
    ctx.add_figure(figure("Problem 46: constraint violation after the impact",
                          "t [s]", "c [m]",
                          student=[(label, *subsample(*curve)) for label, curve in curves.items()],
                          reference=[(label, *subsample(*curve)) for label, curve in ours.items()]))
    ctx.add_figure(figure("Problem 46: joint angles with Baumgarte", "t [s]", "q [rad]",
                          student=[(f"q{k + 1}", *subsample(got["t"], np.asarray(got["q"])[:, k])) for k in range(3)],
                          reference=[(f"q{k + 1}", *subsample(expected["t"], np.asarray(expected["q"])[:, k]))
                                     for k in range(3)]))
    _assert_constrained_values(ctx)
    _assert_flag_passed_on(got, plain, expected, plain_expected)
    t, violation = curves["with Baumgarte"]
    if np.abs(violation).max() > TAUT.atol:
        i = int(np.argmax(np.abs(violation) > TAUT.atol))
        assert_close(violation[i], 0.0, f"the constraint violation at t = {t[i]:.4g} s", TAUT,
                     context="(with Baumgarte stabilisation the wire stays taut)",
                     note="The figure shows the violation with and without stabilisation, yours over the "
                          "reference's.")
    mine, reference = _aligned(got, expected)
    assert_run(mine, reference, ("q", "qd"), BAND, "the run with Baumgarte", roots=(got, expected), pieces=True,
               note="Any solve_ivp method at its default tolerances stays within the band (output times near "
                    "the event are left out).")


#: states ``(t, y)`` off the wire (c and c_dot not zero, so that the Baumgarte terms are not), at which
#: constrained_ode is called with and without stabilisation, in turn on one robot as solve_ivp calls it
WIRE_STATES = ((1.05, np.array([0.5, -0.7, -1.5, 0.4, -0.6, 0.3])),
               (1.3, np.array([0.8, -0.4, -1.8, -0.3, 0.5, 0.7])),
               (1.6, np.array([0.2, -0.9, -1.3, 0.6, 0.2, -0.5])))
WIRE_CASES = tuple((t, y, baumgarte) for t, y in WIRE_STATES for baumgarte in (True, False))
STALE_HINT = ("M depends on q: compute M, f, g from the state y at every call of constrained_ode; yours reuses the M "
              "of its first call. Computed torques hide most of it (tau = M qdd_des - f - g + PD cancels whichever M "
              "is used), so the run stays near the reference's.")
FLAG_HINT = ("constrained_ode(t, y, tree, trajectory, baumgarte) must pass its baumgarte on to constraint_terms: the "
             "stabilisation P_B c + D_B c_dot is added only when it is True. Right after the plastic impact the wire "
             "is taut (c = 0, c_dot = 0), so the two runs differ only as the integration drifts, and the runs alone "
             "barely show a flag that is ignored.")
SIMULATE_FLAG_HINT = ("Pass simulate's baumgarte on to the constrained phase (to constrained_ode through solve_ivp's "
                      "args): constrained_ode honours it (checked above), simulate does not.")


def _describe_wire_case(case):
    t, y, baumgarte = case
    return f"t = {t:g}, y = {np.round(y, 4).tolist()}, baumgarte = {baumgarte}"


def _assert_constrained_ode(ctx):
    """constrained_ode called in turn on one robot gives what it gives on a fresh one (a mass matrix computed once is
    ``stale_mass_matrix``), and its value with baumgarte=True differs from that with False wherever the reference's
    do (an ignored flag is ``baumgarte_ignored``)."""
    table = ctx.reference(p37.trajectory, persist=True)
    ours = ctx.reference(p46.constrained_ode, table, WIRE_CASES)
    stale = ctx.reference(p46.stale_mass_matrix, table, WIRE_CASES)
    mine = assert_fresh_along_a_run(ctx, p46.constrained_ode, (table,), WIRE_CASES, "constrained_ode",
                                    [("stale_mass_matrix", stale, STALE_HINT)], describe=_describe_wire_case)
    for k in range(0, len(WIRE_CASES), 2):
        (on, off), (ours_on, ours_off) = mine[k:k + 2], ours[k:k + 2]
        if not same(on, off) or same(ours_on, ours_off):
            continue
        way = ("always with the stabilisation" if same(on, ours_on) else
               "always without the stabilisation" if same(on, ours_off) else "the same either way")
        t, y, _ = WIRE_CASES[k]
        fail(f"constrained_ode ignores its baumgarte argument: at t = {t:g}, y = {np.round(y, 4).tolist()} (off the "
             f"wire, where the Baumgarte terms are not zero) it gives with baumgarte=True and with baumgarte=False "
             f"the same\n{shown(on)}\n({way}); the reference's with Baumgarte:\n{shown(ours_on)}\nwithout:\n"
             f"{shown(ours_off)}", FLAG_HINT, "baumgarte_ignored")
    return mine, ours


def _assert_constrained_values(ctx):
    """constrained_ode gives the reference's derivative at states off the wire (``WIRE_CASES``), with and without
    the stabilisation: a slip of the constrained phase, compared where it is made."""
    mine, ours = _assert_constrained_ode(ctx)
    assert_close(np.asarray(mine, dtype=float), np.asarray(ours, dtype=float), "constrained_ode(t, y, ...)", ODE,
                 context=f"(at {len(WIRE_CASES)} states off the wire, each with and without the stabilisation: "
                         f"{_describe_wire_case(WIRE_CASES[0])}, ...)")


def _after_impact(run):
    t = np.asarray(run["t"], dtype=float)
    after = t > float(run["t_event"])
    return t[after], np.asarray(run["q"], dtype=float)[after], np.asarray(run["qd"], dtype=float)[after]


def _assert_flag_passed_on(got, plain, expected, plain_expected):
    """The student's runs with and without Baumgarte differ after the impact (the stabilisation acts on the drift,
    so a correct pair of runs never agrees to the last bit): the same run twice is ``baumgarte_ignored``."""
    (t_on, q_on, qd_on), (t_off, q_off, qd_off) = _after_impact(got), _after_impact(plain)
    if not (t_on.size and np.array_equal(t_on, t_off) and np.array_equal(q_on, q_off)
            and np.array_equal(qd_on, qd_off)):
        return
    (_, ours_on, _), (_, ours_off, _) = _after_impact(expected), _after_impact(plain_expected)
    n = min(len(ours_on), len(ours_off))
    fail(f"simulate(trajectory, baumgarte=False) gives the very run of baumgarte=True after the impact: all "
         f"{t_on.size} outputs from t = {t_on[0]:.4g} s to {t_on[-1]:.4g} s are equal to the last bit, where the "
         f"stabilisation always changes the run, if only by the drift it corrects (the reference's tight runs "
         f"differ by up to {np.abs(ours_on[:n] - ours_off[:n]).max():.2g} rad).", SIMULATE_FLAG_HINT,
         "baumgarte_ignored")
