"""A run that ends before the reference's event while it agrees with the reference's run up to its end never
reached the event (``span_short``: the span of its integration too short); one that runs past the event's time
without firing it missed the event (``no_event``), and one that has left the reference's run by its end is judged by
what differs.  On problem 42's flight (``checks.problem_42._flight``) and the shared check of problems 44 and 46
(``checks._dynamics.assert_event_found``), with runs made here from the reference's own."""

import numpy as np
import pytest

from checks import problem_42 as check_42
from checks._dynamics import assert_event_found
from grader.checking import CheckFailure, Tol
from reference import problem_42 as ref_42


@pytest.fixture(scope="module")
def flight():
    return ref_42.throw()


def cut(run, t_max):
    """The run ``run`` without its landing, up to ``t_max`` (as a span ending there leaves it)."""
    keep = run["t"] <= t_max
    return {**run, "t_land": None, "v_land": None, "t": run["t"][keep], "y": run["y"][keep]}


def failure(got, expected):
    with pytest.raises(CheckFailure) as caught:
        check_42._flight(got, expected, ref_42.V0, ref_42.DRAG, check_42.SHEET_BANDS)
    return caught.value


def test_a_flight_that_ends_before_the_landing_and_agrees_up_to_there_is_a_span_too_short(flight):
    failed = failure(cut(flight, 1.0), flight)
    assert failed.diagnosis == "span_short"
    assert "your run ends at t = " in failed.message and "before the reference's landing" in failed.message
    assert "t_max" in failed.hint


def test_a_flight_that_runs_past_the_landing_without_one_missed_the_event(flight):
    from scipy.integrate import solve_ivp

    longer = solve_ivp(ref_42.ball_ode, (0.0, 3.0), [0.0, ref_42.V0], rtol=1e-10, atol=1e-12)
    got = {**flight, "t_land": None, "v_land": None, "t": longer.t, "y": longer.y.T}
    assert got["t"][-1] > flight["t_land"]
    assert failure(got, flight).diagnosis == "no_event"


def test_a_flight_that_ends_early_on_another_path_is_not_told_a_span_too_short(flight):
    got = cut(flight, 1.0)
    got["y"] = got["y"] * np.array([1.3, 1.0])  # higher than the reference's: another flight, not a short one
    assert failure(got, flight).diagnosis == "no_event"


def run(t, q):
    return {"t": t, "q": q[:, None], "qd": np.gradient(q, t)[:, None]}


def test_the_shared_check_tells_a_run_that_ends_before_the_event_from_one_that_misses_it():
    t = np.linspace(0.0, 2.0, 201)
    expected = {**run(t, np.cos(t)), "t_event": 1.5}
    band = {"q": Tol("q", 1e-6, 1e-6), "qd": Tol("qd", 1e-3, 1e-3)}
    short = {**run(t[t <= 1.2], np.cos(t[t <= 1.2])), "t_event": None}
    with pytest.raises(CheckFailure) as caught:
        assert_event_found(short, expected, "t_event", ("q", "qd"), band, "a run", "No event.", "Pass the event.")
    assert caught.value.diagnosis == "span_short" and "ends at t = 1.2 s" in caught.value.message
    past = {**run(t, np.cos(t)), "t_event": None}
    with pytest.raises(CheckFailure) as caught:
        assert_event_found(past, expected, "t_event", ("q", "qd"), band, "a run", "No event.", "Pass the event.")
    assert caught.value.diagnosis == "no_event"


@pytest.mark.parametrize("t, y", [
    (np.array([[0.0], [0.5], [1.0]]), np.zeros((3, 2))),  # times as a column
    (np.array([0.0, np.nan, 1.0]), np.zeros((3, 2))),  # a time that is no number
    (np.array([0.0, 0.5, 1.0]), [[0.0, 1.0], [0.0], [1.0, 2.0]]),  # ragged rows
    (np.array([0.0, 0.5, 1.0]), np.zeros((3, 5))),  # rows of another width
])
def test_a_run_that_cannot_be_read_is_no_span_too_short(flight, t, y):
    assert check_42._ended({"t": t, "y": y}, flight) is None
