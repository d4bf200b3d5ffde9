"""Checks of problem 44: the bar of problem 43 until it hits the second support (``make_contact_event``,
``bar_ode``, ``simulate``).

The event function at random states (its residual, ``terminal``, ``direction = -1``); then the sheet's run: the
event time and state against a tight reference run within bands that any ``solve_ivp`` method at its default
tolerances meets (a fixed-step loop at a large step does not), the run ends at the event, follows the reference's
and keeps the bar on its first support; the bar's motion up to the event is drawn, the student's over the
reference's.  Random starting states make a memorised event time worthless, a bar of another mass, inertia and
gravity one that keeps the sheet's, and a bar with a half-width (d = 0.05 m, the grader's own case: the sheet's
bar has d = 0) an event that drops its d.
"""

import numpy as np
from grader import strategies as st

from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    Mistake,
    Tol,
    as_array,
    assert_close,
    check,
    close,
    fail,
    figure,
)
from probes import problem_44 as p44

from ._answers import typed_or_ignored
from ._dynamics import assert_event_found, assert_run, run_array, same_crossings, subsample

TITLE = "Implementing Event Detection"

#: problem data P44
Q0 = np.array([1.0, 1.0, np.pi / 4])
T_END, S = 1.0, 0.5
#: bands around a tight reference run: any solve_ivp method at its default tolerances errs by at most 6.7e-4 s in
#: the event time, 2.1e-3 in q, 1.2e-2 in the state at the event and 8.2e-3 in qd (BDF, LSODA); explicit Euler at a
#: step of 0.01 s misses the event time by 0.015 s
EVENT_TIME = Tol("event time, a reasonable integrator", 2e-3)
EVENT_STATE = {"q_event": Tol("q at the event, a reasonable integrator", 1e-2),
               "qd_event": Tol("qd at the event, a reasonable integrator", 4e-2)}
SHEET_BANDS = {"t_event": EVENT_TIME, **EVENT_STATE}
#: from random starting states the default tolerances err by up to 4.7e-3 s, 1.2e-2 and 2.4e-2 (DOP853)
RANDOM_BANDS = {"t_event": Tol("event time, a reasonable integrator", 1e-2),
                "q_event": Tol("q at the event, a reasonable integrator", 3e-2),
                "qd_event": Tol("qd at the event, a reasonable integrator", 6e-2)}
BAND = {"q": Tol("a reasonable integrator", 1e-2), "qd": Tol("a reasonable integrator", 4e-2)}
#: the bar stays on its first support along the run (default tolerances: 2.1e-3 m)
ON_SUPPORT = Tol("the first contact stays closed", 1e-2)
SIMULATION_TIMEOUT = 30.0
_SEEDS = st.integers(0, 2**32 - 1)

BANDS_NOTE = ("Any scipy.integrate.solve_ivp method at its default tolerances, with events=[second_contact], lands "
              "within the bands.")
DIRECTION_HINT = ("The bar's lower edge falls onto the second support: its height above it decreases through zero, "
                  "which only direction = -1 (or 0) detects; with +1 the event never fires.")

#: the run's checks come after make_contact_event's own (its residual, terminal and direction), which a failure blocks
NO_EVENT_HINT = ("Where your make_contact_event(s, d) passes its own check, look at the event simulate builds from it: "
                 "made for the support s and half-width d it is given (in that order), passed to "
                 "solve_ivp(..., events=[...]), with direction -1 (or 0): the bar's lower edge falls onto the second "
                 "support, its height above it decreasing through zero.")

# ------------------------------------------------------------------------------------------ the event function


@st.composite
def _event_cases(draw):
    """Three random states, and a fourth with the bar's edge on the second support (the residual is zero)."""
    rng = np.random.default_rng(draw(_SEEDS))
    states = [np.concatenate([rng.uniform(-2, 2, 2), rng.uniform(-np.pi / 2, np.pi / 2, 1), rng.uniform(-2, 2, 3)])
              for _ in range(3)]
    s, d = float(rng.uniform(0.2, 1.0)), float(rng.uniform(-0.2, 0.2))
    touching = states[0].copy()
    touching[2] = np.clip(touching[2], -1.2, 1.2)
    touching[1] = ((touching[0] - s) * np.sin(touching[2]) + d) / np.cos(touching[2])
    return [*states, touching], s, d


@check(2, title="make_contact_event(s, d): the height y cos phi - (x - s) sin phi - d at random states (or a residual "
       "with the same zero crossings), terminal, direction -1 (or 0: the same run)", stage=STAGE_STRUCTURE,
       group="run")
def check_event_function(ctx):
    def compare(got, expected, args):
        states, s, d = args
        values = np.asarray(expected["values"])
        turn = np.array([np.sin(y[2]) for y in states])
        mine = as_array(got["values"], "second_contact(t, y)", values.shape)
        if not close(mine, values, EXACT) and not same_crossings(mine, values):
            assert_close(mine, values, "second_contact(t, y)", EXACT, [
                Mistake("event_sign", -values, "The residual is the height of the lower edge above the second "
                        "support: positive while the bar is above it, falling through zero when it hits (direction "
                        "-1)."),
                Mistake("support_side", values - 2 * s * turn, "The second support sits at x = +s: the edge's height "
                        "above it is y cos phi - (x - s) sin phi - d."),
                Mistake("first_support", values - s * turn, "This is the first support's constraint c (at O); the "
                        "second sits at (s, 0): y cos phi - (x - s) sin phi - d."),
            ], context=f"(three random states and one with the edge on the support, s = {s:.4g}, d = {d:.4g})",
                note="Another residual with the same zero crossings (the same sign everywhere) is as good.")
        if got["terminal"] is not True:
            fail(f"second_contact.terminal is {got['terminal']!r}: the integration must stop when the bar hits the "
                 f"second support (an impact follows, problem 45).", "Set second_contact.terminal = True.",
                 "not_terminal")
        if got["direction"] not in (-1.0, 0.0):
            fail(f"second_contact.direction is {got['direction']!r}, expected -1 (or 0): the height falls through "
                 f"zero when the bar hits.", DIRECTION_HINT, "event_direction")

    ctx.compare_random(p44.event, _event_cases(), name="the event", tol=EXACT, compare=compare, examples=6,
                       describe=lambda args: f"y = {[np.round(y, 4).tolist() for y in args[0]]}, s = {args[1]:.4g}, "
                       f"d = {args[2]:.4g}")


# ------------------------------------------------------------------------------------------ the run


def _runs(ctx):
    """The student's run of the sheet's bar and the reference's; the student's is simulated once per grading (kept
    on the context, which lives for the checks of this problem)."""
    expected = ctx.reference(p44.simulate, Q0, T_END, S, persist=True)
    runs = ctx.__dict__.setdefault("problem_44_runs", {})
    if "sheet" not in runs:
        runs["sheet"] = ctx.student(p44.simulate, Q0, T_END, S, timeout=SIMULATION_TIMEOUT)
    return runs["sheet"], expected


def _event(got, expected, what, bands, s=S):
    """The event is found, ends the run and lies within the bands of the reference's.  Where the run has no event,
    the first place it leaves the reference's run before the reference's event is what differs
    (``assert_event_found``); only a run that follows the reference's there and never fires has missed it, and one
    that ends early at the support's distance ``s`` of the call took it for the end time."""
    assert_event_found(got, expected, "t_event", ("q", "qd"), BAND, what,
                       f"{what}: no event, the bar never reached the second support (t_event is None); the "
                       f"reference's run hits it at t = {expected['t_event']:.4f} s.", NO_EVENT_HINT, {"s": s})
    t = run_array(got, "t", None, what)
    if t.size and t[-1] > got["t_event"] + 1e-9:
        fail(f"{what}: the run goes on after the event at t = {got['t_event']:.4f} s, to t = {t[-1]:.4g} s.",
             "Set second_contact.terminal = True: the motion of problem 43 ends where the bar hits the second "
             "support.", "not_terminal")
    for key, tol in bands.items():
        assert_close(as_array(got[key], key, np.shape(expected[key])), expected[key], key, tol,
                     context=f"({what}, against a tight reference run)", note=BANDS_NOTE)


@check(3, title="simulate(): the bar hits the second support at the reference's time (within 2e-3 s) and state, "
       "and the run ends there; a bar of another mass, inertia and gravity, and one with a half-width d = 0.05 m "
       "(the grader's own case: the sheet's bar has d = 0), hit it at their own time",
       stage=STAGE_VALUES, group="run")
def check_event(ctx):
    got, expected = _runs(ctx)
    labels = ("x [m]", "y [m]", "phi [rad]")
    ctx.add_figure(figure("Problem 44: the bar's motion up to the second contact", "t [s]", "q",
                          student=[(label, *subsample(got["t"], np.asarray(got["q"])[:, k]))
                                   for k, label in enumerate(labels)],
                          reference=[(label, *subsample(expected["t"], np.asarray(expected["q"])[:, k]))
                                     for k, label in enumerate(labels)]))
    _event(got, expected, "simulate()", SHEET_BANDS)
    _assert_other_bar(ctx, expected)
    _assert_wide_bar(ctx)


#: a bar the sheet does not print, (m, theta, g) = (0.8 kg, 0.6 kg m^2, 11 m/s^2): it hits the second support at
#: 0.506 s (the sheet's at 0.685 s); any solve_ivp method at its default tolerances errs there by up to 2.9e-4 s,
#: 1.8e-3 in q and 1.0e-2 in qd at the event (BDF), within the sheet's bands
OTHER_BAR = (0.8, 0.6, 11.0)
#: the bars a simulate that keeps some of the sheet's m = 0.5, theta = 1, g = 9.81 whatever it is given runs instead
SHEET_PARTS = {"m, theta and g": (0.5, 1.0, 9.81), "g": (0.8, 0.6, 9.81), "m and theta": (0.5, 1.0, 11.0)}


def _assert_other_bar(ctx, sheet):
    """The run of ``OTHER_BAR`` hits the second support when the reference's does: a bar_ode or simulate that keeps
    the sheet's m, theta or g whatever it is given fails (``typed_numbers``)."""
    expected = ctx.reference(p44.simulate, Q0, T_END, S, OTHER_BAR, persist=True)
    kept = {part: sheet if part == "m, theta and g" else
            ctx.reference(p44.simulate, Q0, T_END, S, bar, persist=True)
            for part, bar in SHEET_PARTS.items()}
    m, theta, g = OTHER_BAR
    what = f"simulate(q0, {T_END:g}, {S:g}, m = {m:g}, theta = {theta:g}, g = {g:g})"
    got = ctx.student(p44.simulate, Q0, T_END, S, OTHER_BAR, timeout=SIMULATION_TIMEOUT)
    typed = [mistake for part, run in kept.items() if run.get("t_event") is not None
             for mistake in typed_or_ignored(run["t_event"], f"Your run keeps the sheet's {part} whatever bar it is "
                                             f"given: pass simulate's m, theta, g on to bar_ode (solve_ivp(..., "
                                             f"args=(m, theta, g))) and bar_ode's on to the accelerations of problem "
                                             f"43.", f"bar's {part}")]
    if got.get("t_event") is not None and any(close(got["t_event"], mistake.value, EVENT_TIME) for mistake in typed):
        assert_close(got["t_event"], expected["t_event"], f"t_event of {what}", EVENT_TIME, typed,
                     context="(a bar the sheet does not print, against a tight reference run)")
    _event(got, expected, what, SHEET_BANDS)


#: the half-width of a bar the sheet does not print (its d = 0): the grader's own case, so that a simulate that
#: drops its d (an event at d = 0 whatever it is given) is seen
WIDE = 0.05
#: the sheet's bar moved out by WIDE along its normal (-sin phi, cos phi), so that its lower edge rests on the first
#: support (c = y cos phi - x sin phi - d = 0): it hits the second support at 0.686 s, and a run that ignores d
#: (its edge WIDE below the support when the event fires) at 0.727 s; any solve_ivp method at its default tolerances
#: errs there by up to 6.8e-4 s, 2.3e-3 in q and 1.5e-2 in qd at the event (BDF, LSODA), within the sheet's bands
WIDE_Q0 = Q0 + WIDE * np.array([-np.sin(Q0[2]), np.cos(Q0[2]), 0.0])


def _assert_wide_bar(ctx):
    """The run of a bar with the half-width ``WIDE``, at rest on its first support, hits the second support when
    the reference's does: a simulate that builds its event without d (``make_contact_event(s)``) fails
    (``ignored_argument``)."""
    expected = ctx.reference(p44.simulate, WIDE_Q0, T_END, S, None, WIDE, persist=True)
    ignored = ctx.reference(p44.simulate, WIDE_Q0, T_END, S, None, 0.0, persist=True)
    what = f"simulate(q0 = {np.round(WIDE_Q0, 4).tolist()}, {T_END:g}, {S:g}, d = {WIDE:g})"
    got = ctx.student(p44.simulate, WIDE_Q0, T_END, S, None, WIDE, timeout=SIMULATION_TIMEOUT)
    dropped = [Mistake("ignored_argument", ignored["t_event"], "Your run detects the second support as if the bar "
                       "had no width (d = 0) whatever d it is given: pass simulate's d on to the event "
                       "(make_contact_event(s, d)).")] if ignored.get("t_event") is not None else []
    if got.get("t_event") is not None and dropped and close(got["t_event"], dropped[0].value, EVENT_TIME):
        assert_close(got["t_event"], expected["t_event"], f"t_event of {what}", EVENT_TIME, dropped,
                     context="(a bar of half-width d = 0.05 m, the grader's own case: the sheet's has d = 0)")
    _event(got, expected, what, SHEET_BANDS)


def _common(got, expected):
    """Both runs at their common output times (the student's run may end a step earlier or later)."""
    t_mine, t_ours = np.asarray(got["t"], dtype=float), np.asarray(expected["t"], dtype=float)
    common = np.intersect1d(np.round(t_mine, 9), np.round(t_ours, 9))
    mine, ours = np.isin(np.round(t_mine, 9), common), np.isin(np.round(t_ours, 9), common)
    return ({"t": t_mine[mine], "q": np.asarray(got["q"])[mine], "qd": np.asarray(got["qd"])[mine]},
            {"t": t_ours[ours], "q": np.asarray(expected["q"])[ours], "qd": np.asarray(expected["qd"])[ours]})


@check(2, title="simulate(): the run follows the reference's at the output times (every 0.01 s) and the bar stays "
       "on its first support (|c| <= 1e-2 m)", stage=STAGE_VALUES, group="run")
def check_motion(ctx):
    got, expected = _runs(ctx)
    what = "simulate()"
    t = run_array(got, "t", None, what)
    c = run_array(got, "c", t.shape, what)
    if _event_appended(t, got):
        fail(f"{what}: the last of your {t.size} output times, t = {t[-1]:.6g} s, is your event's, appended after "
             f"the output times asked for (every 0.01 s from 0, the last at {t[-2]:.6g} s).",
             "The run is the solution at the output times asked for (t_eval) up to the event; the state at the event "
             "belongs in t_event, q_event and qd_event, not in the run.", "event_appended")
    if t.size < 2 or np.abs(np.diff(t) - 0.01).max() > 1e-9 or abs(t[0]) > 1e-12:
        fail(f"{what}: the output times must run from 0 in steps of 0.01 s (t_eval), got {t.size} times "
             f"{np.round(t[:4], 4).tolist()}...", "Pass t_eval=np.arange(0, t_end + 0.005, 0.01) to solve_ivp.",
             "format")
    if np.abs(c).max() > ON_SUPPORT.atol:
        i = int(np.argmax(np.abs(c) > ON_SUPPORT.atol))
        assert_close(c[i], 0.0, f"c at t = {t[i]:.4g} s", ON_SUPPORT,
                     context="(your own constraint of problem 43 along your run: the bar stays on its support)")
    mine, reference = _common(got, expected)
    assert_run(mine, reference, ("q", "qd"), BAND, what, roots=(got, expected),
               note="Any solve_ivp method at its default tolerances stays within the band.")


def _event_appended(t, got) -> bool:
    """The run's output times are the ones asked for (every 0.01 s from 0) but for the last, which is the run's own
    event time and lies off them: the state at the event appended to the run."""
    t_event = got.get("t_event") if isinstance(got, dict) else None
    if t.size < 3 or t_event is None or abs(t[0]) > 1e-12 or np.abs(np.diff(t[:-1]) - 0.01).max() > 1e-9:
        return False
    try:
        t_event = float(t_event)
    except (TypeError, ValueError):
        return False
    return abs(t[-1] - t_event) <= 1e-9 * max(1.0, abs(t_event)) and 1e-9 < t[-1] - t[-2] < 0.01 - 1e-9


@st.composite
def _starts(draw):
    """``(q0, t_end, s)``: the bar on its support (``y0 = x0 tan phi0``), at rest."""
    rng = np.random.default_rng(draw(_SEEDS))
    x0, phi0 = rng.uniform(1.0, 1.5), rng.uniform(0.3, 0.9)
    return np.array([x0, x0 * np.tan(phi0), phi0]), 1.5, float(rng.uniform(0.2, 0.9))


@check(2, title="simulate(q0, 1.5, s) from random states on the support: the event within the bands",
       stage=STAGE_RANDOM, group="run")
def check_event_random(ctx):
    ctx.compare_random(p44.simulate, _starts(), name="the event", tol=EVENT_TIME, examples=3,
                       compare=lambda got, expected, args: _event(got, expected, f"simulate(q0 = "
                                                                  f"{np.round(args[0], 4).tolist()}, ...)",
                                                                  RANDOM_BANDS, args[2]),
                       describe=lambda args: f"q0 = {np.round(args[0], 4).tolist()} at rest, t_end = {args[1]}, "
                       f"s = {args[2]:.4g}")
