"""The slips of precision on a run's time (``grader.diagnosis.engine._rounded``): a time of the student's own output
grid (an event's time read off the grid, where the run ended at its event) is no rounding, whatever decimals the
grid's spacing matches, and a rounding is told only where it gives the student's value on every input of the
comparison, as every tier is held to them."""

import numpy as np

from grader.checking import Tol
from grader.diagnosis.engine import _rounded
from grader.diagnosis.evidence import Evidence, Source

TIGHT = Tol("event time", 1e-6, 1e-6)
MOTION = {"time": "t", "states": ("q",), "events": ("t_event",)}


def event_time(got: float, expected: float, times) -> Evidence:
    """A run's event time compared, with the student's run (its output times ``times``) behind it."""
    run = {"t": np.asarray(times, dtype=float), "q": np.zeros((len(times), 1)), "t_event": got}
    reference = {"t": np.asarray(times, dtype=float), "q": np.zeros((len(times), 1)), "t_event": expected}
    return Evidence(np.array(got), np.array(expected), TIGHT, "t_event", source=Source("run", (), ("t_event",),
                    reference), student=Source("run", (), ("t_event",), run), motion=MOTION)


GRID = np.arange(0.0, 0.94, 0.01)  # a run on a grid of 10 ms that ended at its event, 0.9331 s


def test_an_event_time_read_off_the_output_grid_is_no_rounding():
    evidence = event_time(0.93, 0.9331, GRID)
    assert _rounded([evidence], evidence, None) == []


def test_an_event_time_one_step_past_the_grid_is_no_rounding():
    """The grid's next time after the run's last (the run ended at its event): on the grid's spacing still."""
    evidence = event_time(0.94, 0.9361, GRID)
    assert _rounded([evidence], evidence, None) == []


def test_a_time_rounded_off_the_grid_is_a_rounding():
    evidence = event_time(0.935, 0.9351, np.arange(0.0, 0.94, 0.02))
    assert [h.name for h in _rounded([evidence], evidence, None)] == ["rounded"]


def test_a_rounding_that_holds_on_one_input_of_two_is_not_told():
    shown = event_time(0.935, 0.9351, np.arange(0.0, 0.94, 0.02))
    other = event_time(0.988, 0.9871, np.arange(0.0, 0.98, 0.02))
    assert _rounded([shown, other], None, None) == []
    assert [h.name for h in _rounded([shown, event_time(0.987, 0.9871, np.arange(0.0, 0.98, 0.02))], None, None)] \
        == ["rounded"]
