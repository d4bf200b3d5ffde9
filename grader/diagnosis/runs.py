"""Slips of runs (probes that declare ``motion``, or runs a check compares with its own code): a time shift, an output
grid one sample off (as many times as asked, spaced as a grid of one more or one fewer), a constant offset, a state
from the wrong row (of the run, or of the state at an event: another row, or a slice of the whole state there from
another start), the state at an event read from the run's last output before it, the run returned rounded (in
float32), a wrong start, an event found late or early, and an error that grows with the step (against fixed-step
runs of the reference's own right-hand side); and the reference re-run as a slip would run it
(``parameter_variants``: its arguments exchanged, scaled or ignored, its start's entries exchanged, solve_ivp at
looser tolerances), every such run a function of the run's arguments alone.  The checks use some pieces themselves:
``reread_runs`` (a run whose columns are read from the wrong rows of the solution, which looks like a wrong start or
a drifting energy) and ``exchanged_events``.

Where the run's probe declares its right-hand side (``motion["rhs"]``), the student's is first compared with the
reference's at states along the reference's run (``model_evidences``): a run that leaves the reference's is not
proof that its integration is at fault, and when the right-hand sides differ the mistake is in the model."""

from __future__ import annotations

import itertools
import re

import numpy as np

from ..errors import GraderFault, StudentFault
from ..values import Tol, format_array
from .evidence import (
    array_of,
    at,
    call_key,
    Declaration,
    declaration,
    DISTINCT,
    distinct,
    Evidence,
    Hypothesis,
    Source,
    within,
)
from .grammar import precision_slips
from .scene import Scene

__all__ = [
    "START_KEY",
    "OFFSET_KEY",
    "variant_sheets",
    "FIXED_STEPS",
    "STEP_WINDOW",
    "STEP_SHAPE",
    "STEP_EXACT",
    "run_of",
    "aligned_runs",
    "motion_slips",
    "grid_slips",
    "event_slips",
    "event_times",
    "step_slips",
    "interpolated",
    "time_shift",
    "is_run",
    "run_in_log",
    "remember_run",
    "RHS_STATES",
    "RHS_TOL",
    "INTEGRATION",
    "rhs_cases",
    "rhs_call",
    "model_evidences",
    "PARAMETER_FACTORS",
    "LOOSE_TOLERANCES",
    "LOOSE_SHARE",
    "run_slips",
    "MAX_FAMILIES",
    "parameter_variants",
    "parameter_slips",
    "event_state_slips",
    "event_state",
    "reread",
    "reread_runs",
    "exchanged_events",
    "EVENT_AGREES",
    "LAST_OUTPUT_SHARE",
]


#: the key of a run's start that differs from the given one (``motion_slips``), and the prefix of the keys of the
#: slips of a value that made it (``engine``)
START_KEY = "motion:start"
#: the key of a run that is the reference's plus a constant offset (and, beginning so, of its start moved by it)
OFFSET_KEY = "motion:offset"
#: the steps of the reference's fixed-step runs that a run's error is compared with [s]
FIXED_STEPS = (0.005, 0.01, 0.02, 0.05)
#: the states along the reference's run at which the student's right-hand side is compared with the reference's,
#: in each half of the run (the second half is the engine's second case)
RHS_STATES = 3
#: two codings of one right-hand side agree within this (a solve for an inverse, terms summed in another order); a
#: slip of the model (a sign, a term, a row) moves it by far more
RHS_TOL = Tol("right-hand side", 1e-7, 1e-6)
#: the causes that blame the integration of a run (with every name of the step_size family), told only where its
#: right-hand side is the reference's
INTEGRATION = ("step_size", "event_late", "event_early", "energy_drift", "no_event")
#: the student's event is found where the reference's is, for a value at it to be read (rows of the state there)
EVENT_AGREES = Tol("event time", 1e-3, 1e-3)
#: the factors a run's parameter (a mass, an inertia, g) is tried at, and their words
PARAMETER_FACTORS = ((2.0, "twice"), (0.5, "half"))
#: a parameter with a sign convention, by its name (the gravity: g = 9.81 or -9.81), tried with its sign turned; a
#: mass, an inertia or a drag coefficient is a magnitude, which no convention turns
SIGNED = re.compile(r"^(g|grav\w*)$", re.IGNORECASE)
#: the tolerances ``(rtol, atol)`` of ``solve_ivp`` (its default method) at which the reference's run is re-run
#: where the probe takes them (``motion["variants"]``): looser than the defaults (1e-3, 1e-6), which every check's
#: bands admit
LOOSE_TOLERANCES = ((1e-2, 1e-2), (1e-1, 1e-1), (1e-2, 1e-6), (1e-1, 1e-6))
#: a fit of a run's error this close, by about one times a fixed-step run's, needs no other run to be tried (the
#: student's run is that scheme at that step)
STEP_EXACT = 0.05
#: a run's error is compared with a fixed-step run's while it is at most this many tolerances
STEP_WINDOW = 30.0
#: a run's error has the shape of a fixed-step integration's when what is left of it, once the best multiple of the
#: latter's error is taken away, is at most this fraction of it (root mean square)
STEP_SHAPE = 0.2


def run_of(root, motion: dict):
    """``(t, {state key: 2-D array (samples x components)})`` of a run's result, or None."""
    if not isinstance(root, dict):
        return None
    t = array_of(root.get(motion.get("time", "t")))
    if t is None or t.ndim != 1 or t.size < 3:
        return None
    states = {}
    for key in motion.get("states", ()):
        value = array_of(root.get(key))
        if value is None or value.shape[0] != t.size:
            return None
        states[key] = value.reshape(t.size, -1)
    return (t, states) if states else None


def aligned_runs(evidence: Evidence, decl: Declaration):
    """The student's run and the reference's on the student's output times (the reference's interpolated there),
    from both runs' start to the first event or end of either: ``(t, {key: mine}, {key: ours}, reference's times,
    reference's run)``, or None."""
    motion = decl.motion
    mine = run_of(evidence.student.root if evidence.student else None, motion)
    ours = run_of(evidence.source.root, motion)
    if mine is None or ours is None:
        return None
    (t_s, G), (t_r, R) = mine, ours
    keys = [k for k in G if k in R and G[k].shape[1] == R[k].shape[1]]
    end = min([t_s[-1], t_r[-1], *event_times(evidence.student.root, motion),
               *event_times(evidence.source.root, motion)])
    inside = (t_s >= max(t_s[0], t_r[0]) - 1e-12) & (t_s <= end + 1e-12)
    if inside.sum() < 3 or not keys:
        return None
    t = t_s[inside]
    ours_at = {k: np.column_stack([np.interp(t, t_r, R[k][:, j]) for j in range(R[k].shape[1])]) for k in keys}
    return t, {k: G[k][inside] for k in keys}, ours_at, t_r, {k: R[k] for k in keys}


def motion_slips(evidence: Evidence, decl: Declaration) -> list:
    """The motion slips that reproduce the student's run: an event found late or early, the run returned rounded
    (in single precision or to a few decimals: then no other, since the rounding makes every difference, the
    start's too), a constant offset, a state read from the wrong row, a time shift, a wrong initial state."""
    motion = decl.motion
    tol = evidence.tol
    found = event_slips(evidence, decl) + event_state_slips(evidence, decl)
    if tuple(evidence.source.path) == (motion.get("time", "t"),):  # the output times compared: their grid
        found += grid_slips(evidence, decl)
    aligned = aligned_runs(evidence, decl)
    if aligned is None:
        return found
    t, G, R, t_r, R_full = aligned
    keys = list(G)
    wrong = [k for k in keys if not within(G[k], R[k], tol)]
    if not wrong:
        return found if any(h.key == "motion:grid" for h in found) else found + grid_slips(evidence, decl)
    # the reference's run returned rounded (float32, a few decimals), in the states that differ: every other
    # difference, the start's too, is that rounding's, so none of the slips below is heard beside it
    rounded = precision_slips(np.concatenate([np.ravel(G[k]) for k in wrong]),
                              np.concatenate([np.ravel(R[k]) for k in wrong]), tol)
    if rounded:
        return found + rounded
    # a constant offset
    offsets = {k: np.mean(G[k] - R[k], axis=0) for k in keys}
    if all(within(G[k] - offsets[k], R[k], tol) for k in keys):
        words = "; ".join(f"{k}: {format_array(offsets[k])}" for k in wrong)
        found.append(Hypothesis(OFFSET_KEY, "offset", 2, f"your run is the reference's plus a constant offset "
                                 f"({words})"))
        if abs(t[0] - t_r[0]) < 1e-9:  # a run from a start moved by the offset looks the same where the motion
            # does not depend on where it is (a height, say)
            found.append(Hypothesis(f"{OFFSET_KEY}-start", "initial_state", 2, f"your run starts at {words} from "
                                     "the given state and keeps that offset"))
    # a state read from the wrong row
    rows = reread(G, R, keys, tol)
    if rows is not None:
        found.append(rows)
    # a time shift
    shift = time_shift(t, G, t_r, R_full, tol)
    if shift is not None:
        found.append(Hypothesis("motion:shift", "time_shift", 2, f"your run is the reference's shifted in time: "
                                 f"yours at t is the reference's at t {shift:+.4g}"))
    # a wrong initial state: the start differs from the given one (not where states read from other rows give the
    # whole run, its start too; nor of a state declared after one whose whole run is the reference's: the states
    # are declared coordinates first, then their rates, and a run's coordinates follow from their rates' start, so
    # rates whose start differs beside coordinates that are right throughout did not drive the run, where that
    # start, kept over the run, would have moved the coordinates past the tolerance: they were derived otherwise,
    # differenced from the angles, say; a coordinate's start may differ where its rates do not)
    states = list(motion.get("states", ()))
    start = [k for k in states if k in G and abs(t[0] - t_r[0]) < 1e-9 and not within(G[k][0], R[k][0], tol)]
    settled = [k for k in states if k in G and k not in start and within(G[k], R[k], tol)]
    start = [k for k in start if not any(states.index(s) < states.index(k) and _moves(G[k][0] - R[k][0], t, R[s], tol)
                                         for s in settled)]
    if start and rows is None:
        words = "; ".join(f"{k}(t0) = {format_array(G[k][0])}, expected {format_array(R[k][0])}" for k in start)
        found.append(Hypothesis(START_KEY, "initial_state", 3, f"your run starts from another state: {words}"))
    return found


def _moves(difference, t, settled, tol) -> bool:
    """Whether a start of rates off by ``difference``, kept over the run's times ``t``, moves the coordinates
    ``settled`` (the reference's run) past the tolerance: a start off by less (a rounding of the rates) may leave
    them as they are."""
    drift = float(np.max(np.abs(difference))) * float(t[-1] - t[0])
    return not within(np.asarray(settled, dtype=float) + drift, np.asarray(settled, dtype=float), tol)


#: how evenly a grid's samples must lie, and how closely its spacing must be a grid's of one sample more or fewer
#: over the reference's span (relative)
GRID_EVEN = 1e-6


def grid_slips(evidence: Evidence, decl: Declaration) -> list:
    """An output grid one sample off, cut to the asked count: the student's output times, as many as the
    reference's, run evenly from the reference's first time with the spacing of a grid of one sample more or fewer
    over the reference's span (``np.linspace(t0, t_end, n, endpoint=False)``; a step of ``(t_end - t0) / (n - 2)``).
    Heard where the output times are the value compared, or where the states at the student's times are the
    reference's run there (the motion is right, only sampled at other times, and ``motion_slips`` finds nothing
    else in it).  Every sample after the first then lies at another time than asked."""
    motion = decl.motion
    mine = run_of(evidence.student.root if evidence.student else None, motion)
    ours = run_of(evidence.source.root, motion)
    if mine is None or ours is None:
        return []
    t, t_r = mine[0], ours[0]
    n = t_r.size
    if t.size != n or n < 4 or not (np.all(np.isfinite(t)) and np.all(np.isfinite(t_r))):
        return []
    span, steps, theirs = t_r[-1] - t_r[0], np.diff(t), np.diff(t_r)
    if span <= 0 or np.any(steps <= 0) or np.ptp(steps) > GRID_EVEN * steps.mean() \
            or np.ptp(theirs) > GRID_EVEN * theirs.mean() or abs(t[0] - t_r[0]) > GRID_EVEN * span:
        return []
    for count, words in ((n + 1, "one more"), (n - 1, "one fewer")):
        if abs(steps.mean() * (count - 1) - span) <= GRID_EVEN * span:
            return [Hypothesis("motion:grid", "grid_off_by_one", 2, f"your {n} output times lie {steps.mean():.6g} s "
                               f"apart, the spacing of a grid of {words} sample ({count}) from {t_r[0]:.6g} s to "
                               f"{t_r[-1]:.6g} s, not {theirs.mean():.6g} s: every sample after the first comes at "
                               "another time than asked, while the motion at your times is the reference's "
                               "(np.linspace(t0, t_end, n) holds both ends)")]
    return []


def reread(G: dict, R: dict, keys, tol: Tol) -> Hypothesis | None:
    """The student's run ``G`` is the reference's ``R`` (both ``{key: samples x components}`` at the same times) with
    columns read from other rows of the solution (the rates for the angles, the halves exchanged): every column of
    the student's that is not the reference's own is, within ``tol``, another column of the reference's that
    differs clearly from its own; None where some column is neither (or none is wrong).  A whole state read from
    another (``"qd": y[:, :3]``, the angles' rows for the rates) is one slip, told by the block as a whole: every
    wrong state is then, within ``tol``, all of another state of its shape, which differs clearly from its own
    somewhere (``_blocks_reread``), though a column of it may lie close to its own column: heard where the columns
    alone tell nothing."""
    columns = [(k, j) for k in keys if k in R for j in range(R[k].shape[1])]
    mapping = {}
    for k in keys:
        if k not in G or k not in R or G[k].shape != R[k].shape:
            return None
        for i in range(G[k].shape[1]):
            if within(G[k][:, i], R[k][:, i], tol):
                continue
            rows = [(k2, j) for k2, j in columns if (k2, j) != (k, i) and within(G[k][:, i], R[k2][:, j], tol)
                    and distinct(R[k2][:, j], R[k][:, i], tol) and distinct(R[k2][:, j], 0.0 * R[k2][:, j], tol)]
            if not rows:
                return _blocks_hypothesis(G, R, keys, tol)
            mapping[(k, i)] = rows[0]
    if not mapping:
        return None
    words = ", ".join(f"{k}[{i}] is the reference's {k2}[{j}]" for (k, i), (k2, j) in mapping.items())
    return Hypothesis("motion:row", "state_row", 2, f"your run has a state from the wrong row: {words}")


def _blocks_hypothesis(G: dict, R: dict, keys, tol: Tol) -> Hypothesis | None:
    """``reread``'s hypothesis of whole states read from others (``_blocks_reread``), or None."""
    blocks = _blocks_reread(G, R, keys, tol)
    if not blocks:
        return None
    words = ", ".join(f"{k} is the reference's {k2}" for k, k2 in blocks.items())
    return Hypothesis("motion:row", "state_row", 2, f"your run has a state from the wrong rows: {words}")


def _blocks_reread(G: dict, R: dict, keys, tol: Tol) -> dict:
    """``{key: other key}``: every state of the student's run ``G`` that is not the reference's own is, as a whole
    and within ``tol``, another state of the reference's ``R`` of the same shape that differs clearly from the own
    one and from zero; empty where some wrong state is not (or none is wrong)."""
    found = {}
    for k in keys:
        if k not in G or k not in R or G[k].shape != R[k].shape:
            return {}
        if within(G[k], R[k], tol):
            continue
        others = [k2 for k2 in keys if k2 != k and k2 in R and R[k2].shape == G[k].shape and within(G[k], R[k2], tol)
                  and distinct(R[k2], R[k], tol) and distinct(R[k2], 0.0 * R[k2], tol)]
        if not others:
            return {}
        found[k] = others[0]
    return found


def reread_runs(got, expected, keys, tol: Tol) -> Hypothesis | None:
    """``reread`` of two runs' results (dicts with ``"t"`` and the ``keys``) at the same output times; None where
    their times differ or a key is missing."""
    t = array_of(expected.get("t")) if isinstance(expected, dict) else None
    mine_t = array_of(got.get("t")) if isinstance(got, dict) else None
    if t is None or mine_t is None or t.ndim != 1 or mine_t.shape != t.shape or not np.allclose(mine_t, t,
                                                                                                 atol=1e-9):
        return None
    G, R = {}, {}
    for key in keys:
        mine, ours = array_of(got.get(key)), array_of(expected.get(key))
        if mine is None or ours is None or mine.size != ours.size or ours.size % t.size:
            return None
        G[key], R[key] = mine.reshape(t.size, -1), ours.reshape(t.size, -1)
    return reread(G, R, keys, tol)


def exchanged_events(got: dict, expected: dict, keys, tol: Tol):
    """``(a, b)``: the student's times of the events ``a`` and ``b`` (keys of the runs' results) are the reference's
    exchanged (the results of two events unpacked in each other's place), where the reference's two differ
    clearly; None where no two are."""
    times = {}
    for key in keys:
        mine, ours = array_of(got.get(key)), array_of(expected.get(key))
        if mine is None or ours is None or mine.size != 1 or ours.size != 1:
            continue
        times[key] = (mine.reshape(()), ours.reshape(()))
    for a, b in itertools.combinations(times, 2):
        (mine_a, ours_a), (mine_b, ours_b) = times[a], times[b]
        if distinct(ours_a, ours_b, tol) and within(mine_a, ours_b, tol) and within(mine_b, ours_a, tol):
            return a, b
    return None


def event_state_slips(evidence: Evidence, decl: Declaration) -> list:
    """A state at an event read from the wrong row (``motion["at_events"]``: ``{key: (event, state[, entry])}``, the
    values of a run's result taken from its state at an event): where the student's event is found when the
    reference's is, their value of the compared key is, within the comparison's tolerance, another entry of the
    reference's state at that event (another such key, the reference's run there, or as many consecutive entries of
    its whole state there from another start: ``_windows``, a slice one entry off, the halves exchanged) that
    differs clearly from the right one and is not zero within the tolerance (a zero, a velocity at an apex say,
    tells no row).  Only where the event itself is found where the reference's is: an event on another quantity
    moves the state read at it, which no row then reproduces.  The compared value's own state (entry) of the run
    interpolated at the event's time (``np.interp`` of the output samples where ``y_events`` belongs) is no other
    row: a value that is it is told as the event's state interpolated (``event_interpolated``)."""
    motion, tol = decl.motion, evidence.tol
    at_events = motion.get("at_events") or {}
    source, student = evidence.source, evidence.student
    if source is None or student is None or not source.path or source.path[0] not in at_events:
        return []
    key = source.path[0]
    event = at_events[key][0]
    mine_t, our_t = array_of(at(student.root, (event,))), array_of(at(source.root, (event,)))
    if mine_t is None or our_t is None or mine_t.size != 1 or our_t.size != 1:
        return []
    te = float(our_t)
    if abs(float(mine_t) - te) > EVENT_AGREES.atol + EVENT_AGREES.rtol * abs(te):
        return []  # the event itself is found elsewhere: a value at it tells nothing of its rows
    mine, ours = array_of(at(student.root, (key,))), array_of(at(source.root, (key,)))
    if mine is None or ours is None or mine.shape != ours.shape or within(mine, ours, tol):
        return []
    candidates = {}
    for other, (other_event, *_rest) in at_events.items():
        value = array_of(at(source.root, (other,)))
        if other_event == event and value is not None:
            candidates[f"its {other}"] = value
            if value.size > 1:
                candidates.update({f"its {other}[{j}]": value.reshape(-1)[j] for j in range(value.size)})
    ran = run_of(source.root, motion)
    last = _last_output(evidence, ran, at_events[key], te)
    if last is not None:
        return last
    interpolated = None  # the compared value's own state (entry) interpolated at the event: no other row
    _, own, *entry = at_events[key]
    if ran is not None and ran[0][0] <= te <= ran[0][-1]:
        t, R = ran
        for state, samples in R.items():
            row = np.array([np.interp(te, t, samples[:, j]) for j in range(samples.shape[1])])
            rows = {f"its {state} at the event": row}
            rows.update({f"its {state}[{j}] at the event": row[j] for j in range(row.size)})
            if state == own:  # the compared value's own row, interpolated: no other row (told apart below)
                interpolated = np.asarray(row[int(entry[0])] if entry else row, dtype=float)
                rows.pop(f"its {state}[{int(entry[0])}] at the event" if entry else f"its {state} at the event")
            candidates.update(rows)
    if interpolated is not None and interpolated.shape == ours.shape and within(mine, interpolated, tol) \
            and distinct(interpolated, ours, tol):
        return [Hypothesis(f"event:interpolated:{key}", "event_interpolated", 2,
                           f"your {key} is the reference's {own} interpolated between its output samples at the "
                           f"event {event} = {te:.6g} s, not its state at the event itself (solve_ivp's y_events): "
                           f"it is {format_array(interpolated)} (expected {format_array(ours)})")]
    candidates.update(_windows(evidence, motion, event, te, key, ours.size))
    wrong = [label for label, value in candidates.items()
             if np.shape(value) == ours.shape and within(mine, np.asarray(value, dtype=float), tol)
             and distinct(np.asarray(value, dtype=float), ours, tol)
             and not within(np.asarray(value, dtype=float), 0.0 * ours, tol)]
    if not wrong:
        return []
    return [Hypothesis(f"event:row:{key}", "state_row", 2,
                       f"your {key} is the reference's state at the event {event} = {te:.6g} s read from the wrong "
                       f"row: it is {wrong[0]} (expected {format_array(ours)})")]


#: the state at an event read from the last output is told only where the student's value is that output up to this
#: share of its difference from the expected value (a loose tolerance lets a value near it pass for it)
LAST_OUTPUT_SHARE = 0.1


def _last_output(evidence: Evidence, ran, spec: tuple, te: float) -> list | None:
    """The state at an event read from the run's last output before the event (``sol.y[:, -1]`` where
    ``sol.y_events`` belongs): the student's value of the compared key is the reference's own output of that state
    (``spec``: ``(event, state[, entry])``) at its last output time before ``te`` (within the tolerance, and up to
    ``LAST_OUTPUT_SHARE`` of the difference), which is beyond the tolerance of the state at the event.  Told as the
    state at the event read otherwise and, a twin, as a state of another time: the event itself is found where it
    belongs."""
    if ran is None:
        return None
    t, R = ran
    _, state, *entry = spec
    before = np.flatnonzero(np.asarray(t) < te)
    if state not in R or not before.size:
        return None
    k = int(before[-1])
    row = np.asarray(R[state][k], dtype=float)
    value = row[int(entry[0])] if entry else row
    key = evidence.source.path[0]
    mine, ours = array_of(at(evidence.student.root, (key,))), array_of(at(evidence.source.root, (key,)))
    value = np.asarray(value, dtype=float)
    if mine is None or ours is None or value.shape != ours.shape or mine.shape != ours.shape \
            or within(value, ours, evidence.tol) or not within(mine, value, evidence.tol):
        return None
    if np.max(np.abs(mine - value)) > LAST_OUTPUT_SHARE * np.max(np.abs(mine - ours)):
        return None  # near the last output, inside a loose tolerance, but not it
    return [Hypothesis(f"event:last:{key}", "state_before_event", 2,
                       f"your {key} is the reference's {state} at its last output time t = {float(t[k]):.6g} s, before "
                       f"the event at {te:.6g} s: read the state at the event (solve_ivp's y_events), not the last "
                       "row of the output"),
            Hypothesis(f"event:last:{key}:time", "time_shift", 2,
                       f"your {key} is a state of another time, {float(t[k]):.6g} s, where the event's at "
                       f"{te:.6g} s belongs", twin=True)]


def event_state(root, motion: dict, event: str, te: float):
    """The whole state at the event ``event`` (at ``te``) of a run's result ``root``, its declared states
    concatenated in their order: each from the result's value of that whole state at the event where it holds one
    (``at_events``: exact, where a state jumps there), else the run interpolated at ``te``; with the offset of each
    state in it (``{state: offset}``), or None where a state is missing."""
    at_events = motion.get("at_events") or {}
    held = {}
    for other, (other_event, *rest) in at_events.items():
        if other_event == event and len(rest) == 1:
            held.setdefault(rest[0], other)
    ran = run_of(root, motion)
    parts, offsets, size = [], {}, 0
    for state in motion.get("states", ()):
        value = array_of(at(root, (held[state],))) if state in held else None
        if value is None and ran is not None and state in ran[1] and ran[0][0] <= te <= ran[0][-1]:
            t, samples = ran[0], ran[1][state]
            value = np.array([np.interp(te, t, samples[:, j]) for j in range(samples.shape[1])])
        if value is None:
            return None
        offsets[state] = size
        parts.append(value.reshape(-1))
        size += value.size
    return (np.concatenate(parts), offsets) if parts else None


def _windows(evidence: Evidence, motion: dict, event: str, te: float, key: str, n: int) -> dict:
    """``{label: value}``: the reference's whole state at the event (``event_state``) read at another offset,
    ``n`` consecutive entries from each other start than the compared value's own (a slice one entry off, the
    halves of the state exchanged); the compared value's own offset from ``at_events`` (its state's, and its
    entry's)."""
    _, state, *entry = motion["at_events"][key]
    whole = event_state(evidence.source.root, motion, event, te)
    if whole is None or state not in whole[1]:
        return {}
    y, offsets = whole
    own = offsets[state] + (int(entry[0]) if entry else 0)
    if n < 2:  # one entry: the entries of each state are candidates already
        return {}
    return {f"its state at the event y_event[{k}:{k + n}] (where {key} is y_event[{own}:{own + n}])": y[k:k + n]
            for k in range(y.size - n + 1) if k != own}


def event_slips(evidence: Evidence, decl: Declaration) -> list:
    """An event found late or early: the student's event time differs from the reference's, while their run agrees
    with the reference's up to the earlier of the two."""
    motion = decl.motion
    tol = evidence.tol
    mine = run_of(evidence.student.root if evidence.student else None, motion)
    ours = run_of(evidence.source.root, motion)
    if mine is None or ours is None:
        return []
    (t_s, G), (t_r, R) = mine, ours
    found = []
    for key in motion.get("events", ()):
        mine_event, our_event = array_of(at(evidence.student.root, (key,))), array_of(at(evidence.source.root, (key,)))
        if mine_event is None or our_event is None or mine_event.size != 1 or our_event.size != 1:
            continue
        te, tr = float(mine_event), float(our_event)
        before = (t_s <= min(te, tr) + 1e-12) & (t_s >= t_r[0])
        if before.sum() < 3:
            continue
        agree = all(within(G[k][before], np.column_stack([np.interp(t_s[before], t_r, R[k][:, j])
                                                           for j in range(R[k].shape[1])]), tol)
                    for k in G if k in R and G[k].shape[1] == R[k].shape[1])
        if agree and abs(te - tr) > tol.atol + tol.rtol * abs(tr):
            if te > tr:
                found.append(Hypothesis(f"event:late:{key}", "event_late", 2,
                                         f"your run agrees with the reference's up to its event, but your {key} "
                                         f"is {te:.6g} where it is {tr:.6g}: the event is found {te - tr:.3g} s "
                                         "late (a coarse search for it, or a step that jumps over it)"))
            elif t_s[-1] <= te + tol.atol + tol.rtol * abs(te):  # a run that goes on past te was not stopped there
                found.append(Hypothesis(f"event:early:{key}", "event_early", 2,
                                         f"your run agrees with the reference's until it stops, but your {key} is "
                                         f"{te:.6g} where it is {tr:.6g}: the event is found {tr - te:.3g} s early"))
    return found


def event_times(root, motion: dict) -> list:
    times = []
    for key in motion.get("events", ()):
        value = array_of(at(root, (key,)))
        if value is not None and value.size == 1:
            times.append(float(value))
    return times


def step_slips(scene: Scene, evidence: Evidence, decl: Declaration) -> list:
    """An integration error that scales with the step: the student's run leaves the reference's as a fixed-step
    run of the reference's own right-hand side does (the probe ``motion["fixed_step"]``, at the steps
    ``FIXED_STEPS``), by a multiple of its error between 1/2 and 2 (the step, to first order), up to the first event
    of either run and while the error is still small (``STEP_WINDOW`` tolerances: past that, a chaotic or unstable
    run's error no longer scales)."""
    motion = decl.motion
    probe = motion.get("fixed_step")
    student, source = evidence.student, evidence.source
    if not probe or student is None:
        return []
    mine, ours = run_of(student.root, motion), run_of(source.root, motion)
    if mine is None or ours is None:
        return []
    (t_s, G), (t_r, R) = mine, ours
    keys = [key for key in G if key in R and G[key].shape[1] == R[key].shape[1]]
    if abs(t_s[0] - t_r[0]) > 1e-9 or not all(within(G[k][0], R[k][0], evidence.tol) for k in keys):
        return []  # another start: a fixed-step run from the given one does not explain the run
    end = min([t_s[-1], t_r[-1], *event_times(student.root, motion), *event_times(source.root, motion)])
    inside = (t_s >= max(t_s[0], t_r[0])) & (t_s < end - 1e-12)
    t = t_s[inside]
    if t.size < 5 or not keys:
        return []
    ours_at = {key: np.column_stack([np.interp(t, t_r, R[key][:, j]) for j in range(R[key].shape[1])])
               for key in keys}
    error = np.concatenate([G[key][inside] - ours_at[key] for key in keys], axis=1)
    size = evidence.tol.atol + evidence.tol.rtol * np.abs(np.concatenate([ours_at[k] for k in keys], axis=1))
    beyond = np.any(np.abs(error) > size, axis=1)
    if not beyond.any():
        return []
    large = np.flatnonzero(np.any(np.abs(error) > STEP_WINDOW * size, axis=1))
    n = max(5, int(large[0])) if large.size else t.size
    e_s = error[:n].ravel()
    best = None
    tries = [(scheme, h) for scheme in motion.get("schemes", ("euler",)) for h in motion.get("steps", FIXED_STEPS)]
    for scheme, h in tries:
        if best is not None and best[0] <= STEP_EXACT and abs(best[3] - 1.0) <= 0.1:
            break  # a run of this scheme and step is the student's: no other needs to be tried
        fixed = run_of(scene.reference(probe, (*source.args, h, scheme), persist=True), motion)
        if fixed is None or fixed[0][-1] < t[n - 1] - 1e-12:
            continue
        t_f, F = fixed
        e_h = np.concatenate([np.column_stack([np.interp(t[:n], t_f, F[key][:, j]) for j in range(F[key].shape[1])])
                              - ours_at[key][:n] for key in keys], axis=1).ravel()
        if e_h.shape != e_s.shape or not np.any(e_h):
            continue
        scale = float(e_s @ e_h / (e_h @ e_h))
        rest = float(np.linalg.norm(e_s - scale * e_h) / np.linalg.norm(e_s))
        if 0.5 <= scale <= 2.0 and rest <= STEP_SHAPE and (best is None or rest < best[0]):
            best = (rest, scheme, scale * h, scale)
    if best is None:
        return []
    _, scheme, step, _ = best
    words = {"euler": "explicit Euler", "symplectic": "semi-implicit (symplectic) Euler"}.get(scheme, scheme)
    return [Hypothesis("motion:step", "step_size", 2,
                        f"your run leaves the reference's as a fixed-step {words} integration does, with a step of "
                        f"about {step:.2g} s (its error grows with the step): integrate with "
                        "scipy.integrate.solve_ivp (any method at its default tolerances) or a far smaller step")]


def interpolated(t, t_r, R):
    """The rows of ``R`` (samples at the times ``t_r``, increasing) linearly interpolated at the times ``t``."""
    k = np.clip(np.searchsorted(t_r, t) - 1, 0, t_r.size - 2)
    w = ((t - t_r[k]) / np.where(t_r[k + 1] > t_r[k], t_r[k + 1] - t_r[k], 1.0))[:, None]
    return (1.0 - w) * R[k] + w * R[k + 1]


def time_shift(t, G, t_r, R, tol: Tol):
    """The shift ``tau`` (larger than half an output step) that makes the student's run at ``t`` the reference's
    at ``t + tau`` within the tolerance, on the times both cover (half of them at least); None when there is none."""
    span = t_r[-1] - t_r[0]
    if span <= 0 or t.size < 4 or t_r.size < 2:
        return None
    mine = np.concatenate([G[k] for k in G], axis=1)
    ours = np.concatenate([R[k] for k in G], axis=1)

    def residual(tau):
        inside = (t + tau >= t_r[0]) & (t + tau <= t_r[-1])
        if inside.sum() < max(3, t.size // 2):
            return np.inf
        moved = interpolated(t[inside] + tau, t_r, ours)
        return float(np.max(np.abs(mine[inside] - moved) - (tol.atol + tol.rtol * np.abs(moved))))

    grid = np.linspace(-0.2 * span, 0.2 * span, 41)
    values = [residual(tau) for tau in grid]
    best = int(np.argmin(values))
    if not np.isfinite(values[best]):
        return None
    lo, hi = grid[max(best - 1, 0)], grid[min(best + 1, grid.size - 1)]
    for _ in range(25):
        a, b = lo + (hi - lo) / 3, hi - (hi - lo) / 3
        if residual(a) <= residual(b):
            hi = b
        else:
            lo = a
    tau = 0.5 * (lo + hi)
    step = float(np.median(np.diff(t)))
    return tau if residual(tau) <= 0.0 and abs(tau) > 0.5 * step else None


def is_run(evidence: Evidence) -> bool:
    if evidence.motion:
        return evidence.source is not None and evidence.student is not None
    decl = declaration(evidence.source.probe) if evidence.source is not None else None
    return decl is not None and bool(decl.motion) and evidence.student is not None


def run_in_log(ctx, evidence: Evidence) -> Evidence | None:
    """The run behind a failing comparison of a check of a run that compares some other value (a constraint along
    the run, an end effector's position): the last probe of the check's log that declares ``motion`` and was asked
    of the reference and of the student with the same arguments, judged with the comparison's tolerance."""
    calls = getattr(ctx, "calls", ())
    students = dict(getattr(ctx, "runs", {}))
    for side, probe, args, value in reversed(calls):
        decl = declaration(probe)
        if side != "reference" or decl is None or not decl.motion:
            continue
        theirs = students.get(call_key(probe, tuple(args)))
        if theirs is not None:
            return Evidence(evidence.got, evidence.expected, evidence.tol, evidence.name, None, None,
                            Source(probe, tuple(args), (), value), Source(probe, tuple(args), (), theirs))
    return None


def remember_run(ctx, probe: str, args: tuple, value) -> None:
    """Keep the student's runs (the values of probes that declare ``motion``) on the grading context for the
    problem's later checks, which may compare the run that an earlier check asked for."""
    decl = declaration(probe)
    if decl is not None and decl.motion:
        ctx.__dict__.setdefault("runs", {})[call_key(probe, tuple(args))] = value


def rhs_cases(root, motion: dict):
    """Two lists of ``(t, y)`` from the reference's run ``root`` before its first event (``y``: the declared states
    in their order), ``RHS_STATES`` from each half of it; None when the run is too short.  An event that the
    right-hand side holds through (``motion["rhs_through"]``: an apex, where only the sign of a velocity changes)
    does not end that part of the run."""
    ours = run_of(root, motion)
    if ours is None:
        return None
    t, R = ours
    through = set(motion.get("rhs_through", ()))
    ends = {**motion, "events": tuple(key for key in motion.get("events", ()) if key not in through)}
    end = min([t[-1], *event_times(root, ends)])
    inside = np.flatnonzero(t < end - 1e-12)
    if inside.size < 2 * RHS_STATES:
        return None
    picks = inside[np.linspace(0, inside.size - 1, 2 * RHS_STATES).round().astype(int)]
    y = np.concatenate([R[key] for key in motion.get("states", ())], axis=1)
    cases = [(float(t[i]), y[i].copy()) for i in picks]
    return cases[:RHS_STATES], cases[RHS_STATES:]


def rhs_call(motion: dict, args: tuple, cases) -> tuple:
    """The arguments of the right-hand side's probe: the run's arguments it takes (``motion["rhs_args"]``, None for
    one not given), then the cases."""
    return (*(args[i] if i < len(args) else None for i in motion.get("rhs_args", ())), cases)


def model_evidences(scene: Scene, evidence: Evidence, decl: Declaration):
    """The student's right-hand side against the reference's at states along the reference's run, one evidence
    per half of it; None where the probe declares no right-hand side or the student's cannot be evaluated there."""
    motion = decl.motion
    probe, source = motion.get("rhs"), evidence.source
    if not probe or source is None or evidence.student is None:
        return None
    halves = rhs_cases(source.root, motion)
    if halves is None:
        return None
    found = []
    for cases in halves:
        args = rhs_call(motion, tuple(source.args), cases)
        expected_root = scene.reference(probe, args)
        try:
            got_root = scene.student(probe, args)
        except StudentFault:
            return None
        expected, got = array_of(expected_root), array_of(got_root)
        if expected is None or got is None or got.shape != expected.shape:
            return None
        found.append(Evidence(got, expected, RHS_TOL, "the right-hand side", None, None,
                              Source(probe, args, (), expected_root), Source(probe, args, (), got_root)))
    return found


def run_slips(scene: Scene, evidence: Evidence, decl: Declaration, integration: bool) -> list:
    """Every slip of a run that reproduces the student's: its arguments varied (``parameter_slips``), an error that
    grows with the step (``step_slips``, which an event found late then is a part of) and the motion's slips
    (``motion_slips``); a cause that blames the integration only where the student's right-hand side is the
    reference's (``integration``).  Where those at the simplest span more than ``MAX_FAMILIES`` families, none."""
    steps = step_slips(scene, evidence, decl) if integration else []
    found = parameter_slips(scene, evidence, decl, integration)
    # an event that a varied run finds where the student's does is found late or early because of that variation
    moved = steps or (found and evidence.source is not None and _compared_event(evidence.source.path, decl.motion))
    found += steps + [h for h in motion_slips(evidence, decl) if not (moved and h.name.startswith("event"))
                      and (integration or h.name not in INTEGRATION)]
    return found if len(_families(found)) <= MAX_FAMILIES else []


#: a run whose hypotheses (at their simplest) span more families than this is told no cause: that many causes fit
#: it alike, and none is known
MAX_FAMILIES = 2


def _families(found: list) -> set:
    from checks._diagnoses import DIAGNOSES

    if not found:
        return set()
    cost = min(h.cost for h in found)
    return {DIAGNOSES[h.name].family if h.name in DIAGNOSES else h.name for h in found if h.cost == cost}


def parameter_variants(motion: dict, args: tuple, sheet, start=None, parts=None) -> list:
    """``(hypothesis, arguments)``: the run's arguments varied, each a run of the reference that a slip of the
    student's would give (every one a function of the run's arguments alone, so the kit's key holds them).

    ``motion["parameters"]``, the run's parameters (``sheet``: their values where an argument is not given):

    * ``{"arg": index, "names": (...)}``, one argument holding them all: exchanged in pairs, scaled by the
      ``PARAMETER_FACTORS``, one with a sign convention (``SIGNED``: the gravity) with its sign turned, and, where
      the argument is given, each at the sheet's value (that parameter ignored) and each at zero (passed as zero);
    * ``{"args": (indices), "names": (...)}``, one argument each: exchanged in pairs (any two, where one at least is
      not given: the grammar's input slips exchange the given ones), one with a sign convention with its sign
      turned, and each given one at the sheet's value (the argument ignored, the module's constant used instead)
      and at zero (passed as zero, its term left out).

    ``motion["start"]`` (``{"arg": index, "name": ..., "sheet": probe}``), the argument that holds the run's start
    (``start``: the sheet's): the reference's run from the sheet's start where another is given (the argument
    ignored, the module's start used instead); told beside a start that differs (``initial_state``), at its cost.

    ``motion["parts"]`` (``{"arg": index, "names": (...), "sheet": probe}``), an argument that holds several values
    of the run's set-up that are not its parameters (a wire's anchor and length, each a vector or a number;
    ``parts``: the sheet's): each given one at the sheet's value (that value ignored where the run uses it, an event
    that reads the module's constant, say).

    Two parameters of equal value are not exchanged: that cannot be told.  ``motion["variants"]`` (``{"arg":
    index, "starts": ((i, j), ...), "tolerances": True}``): the reference re-run by the probe from its start with
    the entries ``i`` and ``j`` exchanged, and by ``solve_ivp`` at the ``LOOSE_TOLERANCES``."""
    found = []
    spec = motion.get("parameters")
    if spec and "arg" in spec:
        found += _vector_variants(spec, args, sheet)
    elif spec and "args" in spec:
        found += _scalar_variants(spec, args, sheet)
    found += _start_variants(motion.get("start"), args, start)
    found += _part_variants(motion.get("parts"), args, parts)
    variants = motion.get("variants")
    if variants:
        index = variants["arg"]

        def run_with(variant):
            new = list(args) + [None] * max(0, index + 1 - len(args))
            new[index] = variant
            return tuple(new)

        for i, j in variants.get("starts", ()):
            found.append((Hypothesis(f"run:start:{i}:{j}", "initial_state", 2,
                                     f"your run starts from the given state with its entries {i} and {j} exchanged: "
                                     "the reference's run from there is yours"), run_with(["start", i, j])))
        if variants.get("tolerances"):
            for rtol, atol in LOOSE_TOLERANCES:
                found.append((Hypothesis(f"run:tolerance:{rtol:g}:{atol:g}", "step_size", 2,
                                         f"your run is the reference's integrated by solve_ivp at rtol = {rtol:g}, "
                                         f"atol = {atol:g} (its error grows with the tolerance, and so with the "
                                         "steps it lets the solver take): integrate at the defaults (rtol 1e-3, "
                                         "atol 1e-6) or tighter"), run_with(["tolerance", rtol, atol])))
    return found


def _start_variants(spec: dict | None, args: tuple, start) -> list:
    """The run from the sheet's start (``start``) where the argument ``spec["arg"]`` gives another: the start
    ignored."""
    if not spec or start is None:
        return []
    index, name = spec["arg"], spec.get("name", "the start")
    given = array_of(args[index]) if index < len(args) and args[index] is not None else None
    sheet = array_of(start)
    if given is None or sheet is None or given.shape != sheet.shape or np.allclose(given, sheet, rtol=1e-9, atol=0.0):
        return []
    changed = list(args)
    changed[index] = [float(x) for x in sheet.ravel()]
    return [(Hypothesis("run:start-sheet", "ignored_argument", 3,
                        f"{name} = {format_array(given)} is given, but your run is the reference's from the sheet's "
                        f"{name} = {format_array(sheet)}: the argument is ignored"), tuple(changed))]


def variant_sheets(ask, motion: dict) -> tuple:
    """``(sheet, start, parts)`` of ``parameter_variants``: the sheet's values of the run's parameters, start and
    parts, each asked of the reference (``ask(probe, ())``) where the run declares it, else None."""
    spec = motion.get("parameters") or {}
    return (ask(spec["sheet"], ()) if spec.get("sheet") else None,
            ask(motion["start"]["sheet"], ()) if motion.get("start") else None,
            ask(motion["parts"]["sheet"], ()) if motion.get("parts") else None)


def _sheets_value(key: str, name: str, given: str, sheet: str) -> Hypothesis:
    """The hypothesis of a run whose ``name`` is given (``given``, as words) but that is the reference's run with the
    sheet's value (``sheet``): the argument ignored."""
    return Hypothesis(key, "ignored_argument", 2, f"{name} = {given} is given, but your run is the reference's with "
                      f"the sheet's {name} = {sheet}: the argument is ignored")


def _part_variants(spec: dict | None, args: tuple, sheet) -> list:
    """The run with one part of the argument ``spec["arg"]`` (a tuple of values, each a number or an array) at the
    sheet's value where another is given: that part ignored."""
    if not spec or sheet is None:
        return []
    index, names = spec["arg"], tuple(spec["names"])
    given = args[index] if index < len(args) else None
    if given is None or len(given) != len(names) or len(sheet) != len(names):
        return []
    found = []
    for k, name in enumerate(names):
        mine, theirs = array_of(given[k]), array_of(sheet[k])
        if mine is None or theirs is None or mine.shape != theirs.shape \
                or np.allclose(mine, theirs, rtol=1e-9, atol=0.0):
            continue
        changed = list(args)
        changed[index] = [sheet[j] if j == k else given[j] for j in range(len(names))]
        found.append((_sheets_value(f"run:part:{k}", name, format_array(mine), format_array(theirs)),
                      tuple(changed)))
    return found


def _vector_variants(spec: dict, args: tuple, sheet) -> list:
    index, names = spec["arg"], tuple(spec["names"])
    given = args[index] if index < len(args) and args[index] is not None else sheet
    values = array_of(given)
    if values is None or values.shape != (len(names),):
        return []

    def run_with(changed):
        new = list(args) + [None] * max(0, index + 1 - len(args))
        new[index] = [float(x) for x in changed]
        return tuple(new)

    found = []
    for i, j in itertools.combinations(range(len(names)), 2):
        if np.isclose(values[i], values[j], rtol=1e-9, atol=0.0):
            continue
        changed = values.copy()
        changed[[i, j]] = values[[j, i]]
        found.append((Hypothesis(f"run:swap:{i}:{j}", "argument_order", 2,
                                 f"{names[i]} and {names[j]} are exchanged: the reference's run with {names[i]} = "
                                 f"{values[j]:g} and {names[j]} = {values[i]:g} is yours"), run_with(changed)))
    for i, name in enumerate(names):
        for factor, words in PARAMETER_FACTORS:
            changed = values.copy()
            changed[i] = values[i] * factor
            found.append((Hypothesis(f"run:scale:{factor:g}:{i}", "scaled_argument", 2,
                                     f"{name} enters at {words} its value: the reference's run with {name} = "
                                     f"{changed[i]:g} is yours"), run_with(changed)))
        if values[i] != 0.0 and SIGNED.match(name):
            changed = values.copy()
            changed[i] = -values[i]
            found.append((_negated(i, name, changed[i]), run_with(changed)))
    if given is not sheet:  # each given one passed as zero
        found += [(_zeroed(i, name, values[i]), run_with(np.where(np.arange(values.size) == i, 0.0, values)))
                  for i, name in enumerate(names) if values[i] != 0.0]
    # each parameter given at its sheet value (the module's constant used where the argument belongs)
    defaults = array_of(sheet)
    if given is not sheet and defaults is not None and defaults.shape == values.shape:
        for i, name in enumerate(names):
            if np.isclose(values[i], defaults[i], rtol=1e-9, atol=0.0):
                continue
            changed = values.copy()
            changed[i] = defaults[i]
            found.append((_sheets_value(f"run:sheet:{i}", name, f"{values[i]:g}", f"{defaults[i]:g}"),
                          run_with(changed)))
    return found


def _scalar_variants(spec: dict, args: tuple, sheet) -> list:
    indices, names = tuple(spec["args"]), tuple(spec["names"])
    defaults = array_of(sheet)
    if defaults is None or defaults.shape != (len(names),):
        return []
    given = [index < len(args) and args[index] is not None for index in indices]
    values = [float(args[index]) if g else float(defaults[k]) for k, (index, g) in enumerate(zip(indices, given))]

    def run_with(changes):
        new = list(args) + [None] * max(0, max(indices) + 1 - len(args))
        for k, value in changes.items():
            new[indices[k]] = value
        return tuple(new)

    found = []
    for i, j in itertools.combinations(range(len(names)), 2):
        if (given[i] and given[j]) or np.isclose(values[i], values[j], rtol=1e-9, atol=0.0):
            continue
        found.append((Hypothesis(f"run:swap:{i}:{j}", "argument_order", 2,
                                 f"{names[i]} and {names[j]} are exchanged: the reference's run with {names[i]} = "
                                 f"{values[j]:g} and {names[j]} = {values[i]:g} is yours"),
                      run_with({i: values[j], j: values[i]})))
    for k, name in enumerate(names):
        if given[k] and not np.isclose(values[k], defaults[k], rtol=1e-9, atol=0.0):
            found.append((_sheets_value(f"run:sheet:{k}", name, f"{values[k]:g}", f"{defaults[k]:g}"),
                          run_with({k: float(defaults[k])})))
        if values[k] != 0.0 and SIGNED.match(name):
            found.append((_negated(k, name, -values[k]), run_with({k: -values[k]})))
        if given[k] and values[k] != 0.0:
            found.append((_zeroed(k, name, values[k]), run_with({k: 0.0})))
    return found


def _zeroed(k: int, name: str, value: float) -> Hypothesis:
    """The hypothesis of a run whose parameter ``name``, given as ``value``, is passed as zero (``args=(0.0, g)``
    for ``args=(drag, g)``): its term left out; the gravity so is the gravity missing."""
    if SIGNED.match(name):
        return Hypothesis(f"run:zero:{k}", "missing_gravity", 2, f"{name} = {value:g} is given, but your run is the "
                          f"reference's with {name} = 0: the gravity is left out")
    return Hypothesis(f"run:zero:{k}", "ignored_argument", 2, f"{name} = {value:g} is given, but your run is the "
                      f"reference's with {name} = 0: the argument is ignored (passed as zero)")


def _negated(k: int, name: str, value: float) -> Hypothesis:
    """The hypothesis of a run whose parameter ``name`` enters with its sign turned (a signed constant, g = -9.81,
    passed where its magnitude belongs, or the reverse; ``SIGNED``): the reference's run at ``value``."""
    return Hypothesis(f"run:negated:{k}", "sign_flip", 2, f"{name} enters with its sign turned: the reference's run "
                      f"with {name} = {value:g} is yours")


def parameter_slips(scene: Scene, evidence: Evidence, decl: Declaration, integration: bool = True) -> list:
    """The run's arguments varied (``parameter_variants``): the reference re-run so reproduces the student's run
    over the whole span both cover (and ends where it does), while it differs clearly from the reference's own run
    or, for a run at looser tolerances, while the student's is far nearer to it than to the reference's
    (``LOOSE_SHARE``: a solver's error at a loose tolerance may leave the band by a few tolerances only).  A run at
    loose tolerances (``step_size``) is told only where the student's right-hand side is the reference's
    (``integration``)."""
    motion = decl.motion
    spec, source, student = motion.get("parameters"), evidence.source, evidence.student
    if not (spec or motion.get("variants") or motion.get("start") or motion.get("parts")) or source is None \
            or student is None:
        return []
    mine, ours = run_of(student.root, motion), run_of(source.root, motion)
    if mine is None or ours is None:
        return []
    event = _compared_event(source.path, motion)
    found = []
    for hypothesis, args in parameter_variants(motion, tuple(source.args), *variant_sheets(scene.reference, motion)):
        if hypothesis.name in INTEGRATION and not integration:
            continue
        try:
            root = scene.reference(source.probe, args, persist=True)
        except GraderFault:
            continue  # the reference refuses the varied run (it never ends, say): no hypothesis
        theirs = run_of(root, motion)
        if theirs is not None and event is not None and hypothesis.name not in INTEGRATION:
            found += _event_variant(hypothesis, (mine, student.root), (theirs, root), (ours, source.root), event,
                                    evidence.tol)
            continue
        if theirs is None or not _same_run(mine, theirs, evidence.tol):
            continue
        if not _same_run(ours, theirs, evidence.tol, DISTINCT) or hypothesis.name in INTEGRATION \
                and _loose_explains((mine, student.root), (theirs, root), (ours, source.root), motion, evidence.tol):
            found.append(hypothesis)
    return found


#: a run of the reference's at looser tolerances that stays near its own run explains the student's where the
#: student's is nearer to it than this share of their distance from the reference's own run (both in tolerances,
#: at the worst output time or event): the solver's error at a loose tolerance is a student's run just outside the
#: band, which the rule of every other variant (clearly another run than the reference's) cannot see
LOOSE_SHARE = 0.25


def _loose_explains(mine, theirs, ours, motion: dict, tol: Tol) -> bool:
    """The student's run leaves the reference's (``ours``) beyond the tolerance, and the run at looser tolerances
    (``theirs``) leaves at most ``LOOSE_SHARE`` of that distance (each ``(run, root)``: its events counted)."""
    far, near = _misfit(mine, ours, motion, tol), _misfit(mine, theirs, motion, tol)
    return far is not None and near is not None and far > 1.0 and near <= LOOSE_SHARE * far


def _misfit(mine, theirs, motion: dict, tol: Tol) -> float | None:
    """The largest distance of the run ``mine`` from ``theirs`` (each ``(run, root)``, a run ``(t, states)``), in
    tolerances, at the output times of the first that the second covers and at the events both find; None where
    they start apart or share no state."""
    ((t_m, M), root_m), ((t_t, T), root_t) = mine, theirs
    if abs(t_m[0] - t_t[0]) > 1e-9:
        return None
    inside = t_m <= t_t[-1] + 1e-12
    worst, shared = 0.0, False
    for key in M:
        if key not in T or M[key].shape[1] != T[key].shape[1]:
            continue
        at_t = np.column_stack([np.interp(t_m[inside], t_t, T[key][:, j]) for j in range(T[key].shape[1])])
        worst = max(worst, float(np.max(np.abs(M[key][inside] - at_t) / (tol.atol + tol.rtol * np.abs(at_t)),
                                        initial=0.0)))
        shared = True
    for key in motion.get("events", ()):
        a, b = array_of(at(root_m, (key,))), array_of(at(root_t, (key,)))
        if a is not None and b is not None and a.size == 1 and b.size == 1:
            worst = max(worst, abs(float(a) - float(b)) / (tol.atol + tol.rtol * abs(float(b))))
    return worst if shared else None


def _compared_event(path, motion: dict) -> str | None:
    """The event whose time the compared value is (``motion["events"]``) or is read at (``motion["at_events"]``),
    or None for a value of the run itself."""
    key = path[0] if path else None
    if key in motion.get("events", ()):
        return key
    if key in motion.get("at_events", {}):
        return motion["at_events"][key][0]
    return None


def _event_variant(hypothesis, mine, theirs, ours, event: str, tol: Tol) -> list:
    """``[hypothesis]`` where the compared value belongs to an event (``event``) and the reference's varied run
    reproduces the student's up to it: both find the event at the same time (within ``tol``) and agree at every
    output time before it, while the reference's own run finds it clearly elsewhere.  What the runs do after the
    event is another comparison's (a slip that moves an event alone, an event function that reads the module's
    constant, leaves the motion after it to the arguments given)."""
    (run_m, root_m), (run_t, root_t), (_, root_o) = mine, theirs, ours
    times = [array_of(at(root, (event,))) for root in (root_m, root_t, root_o)]
    if any(t is None or t.size != 1 for t in times):
        return []
    t_m, t_t, t_o = (float(t) for t in times)
    if not within(np.array(t_m), np.array(t_t), tol) or not distinct(np.array(t_t), np.array(t_o), tol):
        return []
    before = [(t[t < t_m - 1e-12], {k: v[t < t_m - 1e-12] for k, v in S.items()}) for t, S in (run_m, run_t)]
    if before[0][0].size < 3 or before[1][0].size < 3:
        return []
    return [hypothesis] if _agree(*before, tol) else []


def _same_run(mine, theirs, tol: Tol, times: float = 1.0) -> bool:
    """Two runs ``(t, states)`` end together (within an output step) and agree within ``times`` the tolerance at
    every output time of the first."""
    (t_m, _), (t_t, _) = mine, theirs
    step = float(np.median(np.diff(t_m)))
    if abs(t_m[-1] - t_t[-1]) > step + 1e-9 or abs(t_m[0] - t_t[0]) > 1e-9:
        return False
    return _agree(mine, theirs, Tol(tol.name, times * tol.atol, times * tol.rtol))


def _agree(mine, theirs, tol: Tol) -> bool:
    """Every state of the run ``mine`` is, within ``tol``, the run ``theirs``'s (interpolated) at every output time
    of ``mine`` that ``theirs`` covers."""
    (t_m, M), (t_t, T) = mine, theirs
    inside = t_m <= t_t[-1] + 1e-12
    for key in M:
        if key not in T or M[key].shape[1] != T[key].shape[1]:
            return False
        at_t = np.column_stack([np.interp(t_m[inside], t_t, T[key][:, j]) for j in range(T[key].shape[1])])
        if not within(M[key][inside], at_t, tol):
            return False
    return True
