"""Checks of problem 42: event detection with ``solve_ivp`` on the thrown ball (``make_events``, ``throw``), and
the multiple-choice question (b) (answers.toml ``[problem_42] b``).

The event functions at random states and their attributes; then the flight of the sheet's ball, of balls thrown
in a vacuum (whose solver steps lie far apart, so an apex read from the highest step misses) and of random balls:
the apex and the landing against a tight reference run within bands that any ``solve_ivp`` method at its default
tolerances meets (a fixed-step loop at a large step does not), the landing ends the run (terminal) and is not the
launch (direction -1).  The key of (b) is computed by the reference and stays with the instructor.
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
    assert_close,
    check,
    close,
    fail,
    figure,
)
from probes import problem_42 as p42

from ._answers import choice, typed_or_ignored
from ._dynamics import ended_early, subsample

TITLE = "Event Detection"

#: the warm-up's ball (problem 42's module)
V0, DRAG = 10.0, 0.1
#: bands around a tight reference run: any solve_ivp method at its default tolerances stays within a third of them
#: (largest errors: 6e-4 s, 1.1e-3 m, 5.8e-3 m/s); explicit Euler at a step of 0.05 s misses by 0.055 s
TIME = Tol("event time, a reasonable integrator", 2e-3)
HEIGHT = Tol("apex height, a reasonable integrator", 1e-2)
SPEED = Tol("landing velocity, a reasonable integrator", 2e-2)
#: the state (height, velocity) of a flight that ends early, against the reference's at its end
ALONG = Tol("a state along the flight, a reasonable integrator", 1e-2, 1e-2)
SHEET_BANDS = {"t_land": TIME, "v_land": SPEED, "t_apex": TIME, "height_apex": HEIGHT}
#: on random balls (up to 30 m/s, flights up to 6 s) the default tolerances err by up to 0.4 % in the times and
#: 0.15 % in the height (DOP853's interpolated landing velocity by up to 3 %, so it is compared on the sheet's ball
#: only)
RANDOM_BANDS = {"t_land": Tol("event time, a reasonable integrator", 2e-3, 1e-2),
                "t_apex": Tol("event time, a reasonable integrator", 2e-3, 1e-2),
                "height_apex": Tol("apex height, a reasonable integrator", 1e-2, 5e-3)}
#: a landing before this [s] is the launch from the ground
LAUNCH = 1e-6
#: a height below the ground by more than this [m] after the landing is a run that goes on through the ground (a
#: terminal event ends the run at the crossing, within the event's own tolerance); a later time alone is not, as a
#: landing time rounded down leaves the last step of a terminal run after it
GROUND = 1e-6
RESIDUALS = {"apex": "the velocity y[1]", "landing": "the height y[0]"}
_SEEDS = st.integers(0, 2**32 - 1)

BANDS_NOTE = ("Any scipy.integrate.solve_ivp method at its default tolerances, with events=make_events(), lands "
              "within the bands.")
APEX_HINT = ("Your apex is the highest of your run's own rows (at t = {t:.4f} s): the solver's steps fall where "
             "its step size puts them, and the apex lies between two of them. Read it from the apex event, "
             "t_events[0] and y_events[0], which solve_ivp locates on its dense output.")
NEAREST_HINT = ("Your apex is your run's row nearest it (at t = {t:.4f} s), a value of another time: the apex lies "
                "between two rows, where the apex event locates it on the solver's dense output.")
DIRECTION_HINT = ("The ball starts on the ground, where the height is zero: with direction 0 or +1 that zero "
                  "counts as a landing and the integration stops at once. direction = -1 counts only a fall "
                  "through zero (from + to -).")


# ------------------------------------------------------------------------------------------ the event functions


@st.composite
def _states(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    return ([np.array([rng.uniform(-1.0, 6.0), rng.uniform(-15.0, 15.0)]) for _ in range(4)],)


def _attributes(got, name, terminal, directions, hints):
    event = got[name]
    if event["terminal"] is not terminal:
        fail(f"{name}.terminal is {event['terminal']!r}, expected {terminal}: {hints['terminal']}",
             hints["terminal_hint"], hints["terminal_diagnosis"])
    if event["direction"] not in directions:
        fail(f"{name}.direction is {event['direction']!r}, expected {' or '.join(f'{d:+g}' for d in directions)}: "
             f"{hints['direction']}", hints["direction_hint"], "event_direction")


@check(2, title="make_events(): apex(t, y) = velocity (direction -1, not terminal) and landing(t, y) = height "
       "(direction -1, terminal) at random states", stage=STAGE_STRUCTURE, group="events")
def check_events(ctx):
    def compare(got, expected, args):
        if not isinstance(got, dict) or "problem" in got:
            fail(got.get("problem") if isinstance(got, dict) else f"the probe could not read your events: {got}",
                 "Return the two event functions as a tuple: return apex, landing.", "format")
        heights, velocities = (np.array([y[k] for y in args[0]]) for k in (0, 1))
        rows = {"apex": velocities, "landing": heights}
        exchanged = all(close(got[name]["values"], rows[other], EXACT)
                        for name, other in (("apex", "landing"), ("landing", "apex")))
        for name, value, other in (("apex", velocities, heights), ("landing", heights, velocities)):
            read = (Mistake("swapped", other, "make_events() returns (apex, landing): the apex is where the velocity "
                            "y[1] falls through zero, the landing where the height y[0] does.") if exchanged else
                    Mistake("event_quantity", other, f"{name} reads the other row of the state y = (height, "
                            f"velocity), so it watches the other quantity: its residual is {RESIDUALS[name]}."))
            assert_close(got[name]["values"], value, f"{name}(t, y)", EXACT, [
                read,
                Mistake("event_sign", -value, f"The residual of {name} is {RESIDUALS[name]} itself: with its sign "
                        f"turned, the crossing runs the other way and direction -1 misses it."),
            ], context="at four random states y = (height, velocity)")
        _attributes(got, "landing", True, (-1.0,), {
            "terminal": "the flight ends when the ball lands.",
            "terminal_hint": "Set landing.terminal = True: solve_ivp stops at the first crossing of a terminal event.",
            "terminal_diagnosis": "not_terminal", "direction": "the height falls through zero at the landing.",
            "direction_hint": DIRECTION_HINT})
        _attributes(got, "apex", False, (-1.0, 0.0), {
            "terminal": "the apex only marks a point of the flight, the integration goes on.",
            "terminal_hint": "Set apex.terminal = False: a terminal apex stops the flight at its top.",
            "terminal_diagnosis": "apex_terminal",
            "direction": "the velocity falls through zero at the apex (0, both ways, finds it as well).",
            "direction_hint": "direction = -1 counts a crossing from + to -; +1 would wait for the velocity to rise "
                              "through zero, which never happens in this flight."})

    ctx.compare_random(p42.events, _states(), name="the events", tol=EXACT, compare=compare, examples=6,
                       describe=lambda args: f"y = {[np.round(y, 4).tolist() for y in args[0]]}")


# ------------------------------------------------------------------------------------------ the flight


def _flight(got, expected, v0, drag, bands, g=None):
    """The landing is found, is not the launch, ends the run; the apex and the landing lie within the bands."""
    what = f"throw(v0 = {v0:.4g}, drag = {drag:.4g}{'' if g is None else f', g = {g:g}'})"
    if got["t_land"] is None:
        ended = _ended(got, expected)
        if ended is not None:
            fail(f"{what}: the ball never landed (t_land is None): your run ends at t = {ended:.4g} s, before the "
                 f"reference's landing at t = {expected['t_land']:.4f} s, and agrees with the reference's flight up to "
                 f"there.", "The flight is integrated until the ball lands: the span (0, t_max) must reach past the "
                 "landing (t_max = T_MAX = 10 s unless another is given).", "span_short")
        fail(f"{what}: the ball never landed (t_land is None); the reference's lands at t = "
             f"{expected['t_land']:.4f} s.", "The landing event (height through zero, direction -1, terminal) must be "
             "among the events passed to solve_ivp(..., events=...).", "no_event")
    from grader.diagnosis.runs import exchanged_events

    if exchanged_events(got, expected, ("t_apex", "t_land"), bands["t_land"]) is not None:
        fail(f"{what}: your t_land = {got['t_land']:.4f} s is the reference's apex and your t_apex = "
             f"{got['t_apex']:.4f} s its landing: the two events' results are read in each other's place.",
             "solve_ivp returns t_events and y_events in the order of events=[...]: with make_events() = (apex, "
             "landing), t_events[0] is the apex and t_events[1] the landing.", "swapped")
    if got["t_land"] < LAUNCH:
        fail(f"{what}: the landing was found at t = {got['t_land']:.3g} s, the launch; the reference's ball lands at "
             f"t = {expected['t_land']:.4f} s.", DIRECTION_HINT, "event_direction")
    t, height = np.asarray(got["t"]), np.asarray(got["y"])[:, 0]
    below = (t > got["t_land"] + 1e-9) & (height < -GROUND)
    if below.any():
        fail(f"{what}: the run goes on after the landing at t = {got['t_land']:.4f} s, to t = {t[-1]:.4g} s: the "
             f"ball falls through the ground (height {height[below].min():.3g} m).",
             "Set landing.terminal = True: the flight ends at the landing.", "not_terminal")
    if got["t_apex"] is None:
        fail(f"{what}: no apex was marked (t_apex is None); the reference's is at t = {expected['t_apex']:.4f} s.",
             "Pass both events to solve_ivp; t_events[0] holds the apex times.", "no_event")
    at_step = _highest_step(t, np.asarray(got["y"]))
    for key, tol in bands.items():
        assert_close(got[key], expected[key], key, tol, _apex_mistakes(key, at_step),
                     context=f"({what}, against a tight reference run)", note=BANDS_NOTE)


def _ended(got, expected):
    """The end time of a flight that stops before the reference's landing while it agrees with the reference's
    flight there (the span of the integration too short), or None (``checks._dynamics.ended_early``)."""
    try:
        t, y = np.asarray(got["t"], dtype=float), np.asarray(got["y"], dtype=float)
    except (KeyError, TypeError, ValueError):
        return None
    ours = {"t": expected["t"], "y": expected["y"]}
    return ended_early(t, {"y": y}, ours, ("y",), float(expected["t_land"]), {"y": ALONG})


def _highest_step(t, y):
    """``{"t_apex", "height_apex"}`` of the highest row of a run strictly inside it (not its first or last row,
    where a run that starts or ends at an event has the event's own state), or None."""
    if t.size < 3 or y.shape != (t.size, 2):
        return None
    top = int(np.argmax(y[:, 0]))
    return {"t_apex": float(t[top]), "height_apex": float(y[top, 0])} if 0 < top < t.size - 1 else None


def _apex_mistakes(key, at_step):
    """The apex read from the highest of the run's own rows (the solver's steps) rather than its event: an extremum
    from the steps, and as truly the row nearest the apex read where the apex itself, which lies between two rows,
    belongs (a value of another time); the value cannot tell the two readings apart, so both are told."""
    if at_step is None or key not in at_step:
        return []
    return [Mistake("extremum_from_steps", at_step[key], APEX_HINT.format(t=at_step["t_apex"])),
            Mistake("nearest_sample", at_step[key], NEAREST_HINT.format(t=at_step["t_apex"]))]


@check(3, title="throw(): the sheet's ball (v0 = 10 m/s, k = 0.1 1/m) peaks and lands at the reference's times "
       "(within 2e-3 s) and heights; the landing ends the run and is not the launch; thrown on the Moon it follows "
       "its g, thrown in a vacuum (on the Earth and on Mars) it peaks at the parabola's apex, and it stops at its "
       "t_max", stage=STAGE_VALUES, group="events")
def check_flight(ctx):
    expected = ctx.reference(p42.throw, V0, DRAG)
    got = ctx.student(p42.throw, V0, DRAG, timeout=20)
    ctx.add_figure(figure("Problem 42: the height of the ball", "t [s]", "height [m]",
                          student=[("height", *subsample(got["t"], np.asarray(got["y"])[:, 0]))],
                          reference=[("height", *subsample(expected["t"], np.asarray(expected["y"])[:, 0]))]))
    _flight(got, expected, V0, DRAG, SHEET_BANDS)
    _assert_moon(ctx, expected)
    _assert_vacuum(ctx)
    _assert_cut_short(ctx)


#: the sheet's ball thrown on the Moon (g = 1.62 m/s^2, problem 2's Moon): it lands at 7.03 s (the sheet's at 1.69
#: s), so a throw that keeps the sheet's g whatever it is given earns nothing; any solve_ivp method at its default
#: tolerances errs there by up to 6.5e-3 s in the landing time and 8.9e-3 m in the apex height (BDF), within the
#: bands of the random balls
MOON = 1.62
MOON_HINT = ("Your flight is the one under the sheet's g = 9.81 whatever g throw is given: pass g on to ball_ode "
             "(solve_ivp(..., args=(drag, g))); ball_ode's own default is the sheet's.")


def _assert_moon(ctx, sheet):
    """The ball thrown with ``g = MOON`` lands where the reference's does, not where the sheet's ball lands."""
    expected = ctx.reference(p42.throw, V0, DRAG, MOON)
    got = ctx.student(p42.throw, V0, DRAG, MOON, timeout=20)
    if got["t_land"] is not None and close(got["t_land"], sheet["t_land"], TIME):
        assert_close(got["t_land"], expected["t_land"], f"t_land of throw(v0 = {V0:g}, drag = {DRAG:g}, g = {MOON:g})",
                     TIME, typed_or_ignored(sheet["t_land"], MOON_HINT, "g"),
                     context="(the sheet's ball on the Moon, against a tight reference run)")
    _flight(got, expected, V0, DRAG, RANDOM_BANDS, g=MOON)


#: the sheet's ball thrown in a vacuum (k = 0), on the Earth (the sheet's g) and on Mars (g = 3.71 m/s^2): the
#: flight is a parabola (apex at v0/g, at the height v0^2/(2 g)), on which the error estimates of the solve_ivp
#: methods are (near) zero, so their steps grow up to tenfold at a time and lie far apart: at the reference's
#: tolerances the highest step lies 0.09 s from the apex on the Earth and 1.6 s on Mars, and for each method
#: (RK45, RK23, DOP853, Radau, BDF, LSODA) at rtol from 1e-3 to 1e-12 (atol 1e-6 or rtol / 100) at least 0.21 s
#: from it on one of the two, where the events of every method find the apex to 2e-6 s and 3e-5 m, and a grid of
#: 1 ms to 5e-4 s; both land before the sheet's t_max
MARS = 3.71
#: the gravities of the throws in a vacuum (None: the sheet's, which throw is not given)
VACUUM = (None, MARS)


def _assert_vacuum(ctx):
    """The sheet's ball thrown in a vacuum peaks and lands where the reference's does, within the sheet's bands."""
    throws = [(V0, 0.0) if g is None else (V0, 0.0, g) for g in VACUUM]
    expected = [ctx.reference(p42.throw, *args) for args in throws]
    for args, g, ours in zip(throws, VACUUM, expected):
        _flight(ctx.student(p42.throw, *args, timeout=20), ours, V0, 0.0, SHEET_BANDS, g=g)


#: a t_max [s] after the sheet's ball's apex (0.80 s) and before its landing (1.69 s)
CUT = 1.2


def _assert_cut_short(ctx):
    """The sheet's ball thrown with ``t_max = CUT`` stops there in the air: no landing, the run ends at CUT.  A
    t_max ignored is named only where the run does not end at CUT: a run that ends there follows its t_max, and a
    landing it reports there is read from something else (the end of the run taken for a landing)."""
    expected = ctx.reference(p42.cut_short, V0, DRAG, CUT)
    got = ctx.student(p42.cut_short, V0, DRAG, CUT, timeout=20)
    what = f"throw(v0 = {V0:g}, drag = {DRAG:g}, t_max = {CUT:g})"
    ends = close(got["t_end"], expected["t_end"], TIME)
    if got["t_land"] is not None or not ends:
        landed = "" if got["t_land"] is None else f" and lands at t = {got['t_land']:.4f} s"
        fail(f"{what}: the flight must end at t_max = {CUT:g} s with the ball still in the air (t_land None); your "
             f"run ends at t = {got['t_end']:.4f} s{landed}.",
             "Integrate over the span (0, t_max) that throw is given: solve_ivp(ball_ode, (0.0, t_max), ...)."
             if not ends else "The ball lands only where the landing event fires (result.t_events); a run that "
             "ends at t_max without it has not landed: t_land is None.",
             "" if ends else "ignored_argument")


@st.composite
def _balls(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    return float(rng.uniform(2.0, 30.0)), float(rng.uniform(0.0, 0.5))


@check(2, title="throw() on random balls (v0 in [2, 30] m/s, k in [0, 0.5] 1/m): apex and landing times and the "
       "apex height within the bands", stage=STAGE_RANDOM, group="events")
def check_flight_random(ctx):
    ctx.compare_random(p42.throw, _balls(), name="the flight", tol=TIME, examples=5,
                       compare=lambda got, expected, args: _flight(got, expected, *args, RANDOM_BANDS),
                       describe=lambda args: f"v0 = {args[0]:.4g} m/s, drag = {args[1]:.4g} 1/m")


# ------------------------------------------------------------------------------------------ (b)


@check(1, title="(b) the chosen outcome of a landing event with direction 0 is what the integration shows",
       stage=STAGE_VALUES, group="b", secret=True)
def check_direction_choice(ctx):
    value = choice(ctx, "b", (1, 2, 3, 4), "(b)")
    key = ctx.reference(p42.key, persist=True)
    if value != key["b"]:
        fail(f"(b): option {value} is not what the integration shows: run throw() with the landing event's "
             f"direction set to 0 and look where the flight ends.",
             "Where does the height start? direction 0 counts every zero crossing, and solve_ivp also counts a "
             "residual that starts at zero and leaves it.", "wrong_choice")
