"""A run's output grid one sample off is told as such, and only where the run fails its shape anyway; a run at the
solver's own steps (uneven, over the span, mostly off the grid asked for) is told as the output times left out."""

import numpy as np
import pytest

from checks._dynamics import run_array
from grader.checking import CheckFailure

#: the expected output times: 101 samples from 0 to 2 s
TIMES = np.linspace(0.0, 2.0, 101)


def _run(t):
    return {"t": np.asarray(t, dtype=float), "q": np.zeros((len(t), 2))}


@pytest.mark.parametrize("n, late", [(100, "late"), (102, "early")])
def test_evenly_spaced_times_over_the_span_one_off_are_a_grid_off_by_one(n, late):
    with pytest.raises(CheckFailure) as caught:
        run_array(_run(np.linspace(0.0, 2.0, n)), "q", (101, 2), "simulate()", times=TIMES)
    assert caught.value.diagnosis == "grid_off_by_one"
    assert f"comes {late}" in caught.value.message and "round((t_end - t0) / dt) + 1" in caught.value.hint


@pytest.mark.parametrize("t", [np.linspace(0.0, 2.0, 99),  # two samples short
                               np.arange(0.0, 2.0, 0.02),  # the right step, the end time left out: none is late
                               np.r_[0.0, np.sort(np.random.default_rng(1).uniform(0.0, 2.0, 98)), 2.0]])  # uneven
def test_other_grids_of_the_wrong_length_stay_a_shape(t):
    with pytest.raises(CheckFailure) as caught:
        run_array(_run(t), "q", (101, 2), "simulate()", times=TIMES)
    assert caught.value.diagnosis != "grid_off_by_one"


def test_without_the_expected_times_a_grid_one_off_is_a_shape():
    with pytest.raises(CheckFailure) as caught:
        run_array(_run(np.linspace(0.0, 2.0, 100)), "q", (101, 2), "simulate()")
    assert caught.value.diagnosis != "grid_off_by_one"


def test_a_value_of_the_right_length_beside_times_one_off_is_not_failed_by_the_grid():
    run = {"t": np.linspace(0.0, 2.0, 100), "q": np.zeros((101, 2))}
    assert run_array(run, "q", (101, 2), "simulate()", times=TIMES).shape == (101, 2)


def _told(t):
    with pytest.raises(CheckFailure) as caught:
        run_array(_run(t), "q", (101, 2), "simulate()", times=TIMES)
    return caught.value


def test_output_times_kept_twice_on_a_boundary_are_told_by_their_times():
    told = _told(np.concatenate([TIMES[:51], TIMES[50:]]))  # the sample at 1 s kept by both halves
    assert told.diagnosis == "samples_repeated"
    assert "1 s comes twice" in told.message and "one of them only" in told.hint


def test_output_times_left_out_inside_the_span_are_told_by_their_times():
    told = _told(np.delete(TIMES, [0, 25, 50, 75]))  # the start and three breaks left out
    assert told.diagnosis == "samples_left_out"
    assert "0, 0.5, 1, 1.5 s are left out" in told.message


def test_every_tenth_output_time_alone_is_an_output_step_too_long():
    told = _told(TIMES[::10])
    assert told.diagnosis == "output_step"
    assert "one of every 10" in told.message and "0.2 s apart, not 0.02 s" in told.message


def test_a_run_that_lacks_its_last_output_time_alone_left_the_end_out_or_ended_a_step_short():
    told = _told(TIMES[:-1])  # np.arange(0, t_end, dt), t < t_end: the end taken with < where <= belongs
    assert told.diagnosis == "samples_left_out or span_short"
    assert "the last output time, 2 s, is not in it" in told.message


def test_a_run_that_stops_further_short_says_where_and_names_no_cause():
    told = _told(TIMES[:80])  # the last piece never integrated, an event, a span cut short: too many causes
    assert told.diagnosis == "shape"
    assert "the last 21 output times, from 1.6 s to 2 s, are not in it" in told.message


@pytest.mark.parametrize("t", [np.r_[np.delete(TIMES, 10), 2.0, 2.0],  # 0.2 s left out, 2 s thrice
                               np.r_[TIMES[:50], TIMES[50:] + 1e-4, 2.5]])  # times off the grid
def test_times_both_left_out_and_twice_or_off_the_grid_name_no_cause(t):
    assert _told(t).diagnosis == "shape"


#: a solver's own steps from 0 to 2 s: short at the start, growing, uneven
OWN_STEPS = 2.0 * np.cumsum(np.r_[0.0, np.geomspace(1.0, 8.0, 36)]) / np.sum(np.geomspace(1.0, 8.0, 36))


def test_uneven_times_over_the_span_mostly_off_the_grid_are_the_solvers_own_steps():
    with pytest.raises(CheckFailure) as caught:
        run_array(_run(OWN_STEPS), "q", (101, 2), "simulate()", times=TIMES)
    assert caught.value.diagnosis == "solver_steps"
    assert "the solver's own steps" in caught.value.message and "t_eval" in caught.value.hint


@pytest.mark.parametrize("t", [OWN_STEPS[OWN_STEPS <= 1.5],  # a run that stops short of the span's end
                               TIMES[np.r_[0, 1, 3, 6, 10, 15, 21, 28, 36, 45, 55, 66, 78, 91, 100]]])  # on the grid
def test_uneven_times_that_stop_short_or_lie_on_the_grid_are_no_solvers_own_steps(t):
    with pytest.raises(CheckFailure) as caught:
        run_array(_run(t), "q", (101, 2), "simulate()", times=TIMES)
    assert caught.value.diagnosis != "solver_steps"


def test_a_run_in_pieces_that_lacks_its_last_output_time_may_also_have_left_its_last_piece_out():
    """Integrated in pieces between breaks at the output times, a run's last piece is one output step long: left
    un-integrated, it leaves out the last output time alone, as the end taken with < does; both are named, a piece
    left out beside the end left out or a span one step short."""
    with pytest.raises(CheckFailure) as caught:
        run_array(_run(TIMES[:-1]), "q", (101, 2), "simulate()", times=TIMES, pieces=True)
    assert caught.value.diagnosis == "samples_left_out or span_short or piece_left_out"
    assert "the last output time, 2 s, is not in it" in caught.value.message
    assert "the last piece of the run" in caught.value.hint
    with pytest.raises(CheckFailure) as caught:  # further short: too many causes (an event, a span cut short)
        run_array(_run(TIMES[:80]), "q", (101, 2), "simulate()", times=TIMES, pieces=True)
    assert caught.value.diagnosis == "shape"
