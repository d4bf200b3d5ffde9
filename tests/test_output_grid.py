"""A run's output grid one sample off is told as such, and only where the run fails its shape anyway."""

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
