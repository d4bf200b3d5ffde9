"""A catalogue's known mistake whose value is as truly another family's slip is told with both names.

* A value that is the sheet's answer whatever an argument is: typed in, or the argument ignored
  (``checks._answers.typed_or_ignored``).  Where a check passes another argument than the sheet's and the student's
  value is the sheet's answer (the reference's run for the sheet's bar), the value cannot tell the sheet's numbers
  typed in from the argument ignored (a module's constant or a default read in its place computes the same): both
  are told, as problem 4 tells its sheet's configuration whatever fixed point is asked.  Planted: problem 44's run
  that keeps the sheet's m and theta whatever bar it is given (a bar_ode that reads the module's mass and inertia);
  near miss: a run that keeps the sheet's theta alone, which no entry of the catalogue runs, names neither.
* An apex read from the highest of a run's rows (problem 42's ``_apex_mistakes``): an extremum from the solver's
  steps, and the row nearest the apex read in its place, a value of another time (``nearest_sample``).  Planted: the
  apex time read from the highest row; near miss: the row after it names neither.
"""

import numpy as np
import pytest

from grader.checking import CheckFailure, assert_close


def _other_bar(kept):
    """Problem 44's comparison of the run of a bar the sheet does not print, where the student's run hits the support
    when the run of the bar ``kept`` does: the failure."""
    from checks import problem_44 as c44

    runs = {c44.OTHER_BAR: 0.506, (0.5, 1.0, 9.81): 0.685, (0.8, 0.6, 9.81): 0.551, (0.5, 1.0, 11.0): 0.645,
            (0.8, 1.0, 11.0): 0.598}

    class Ctx:
        def reference(self, probe, q0, t_end, s, bar, persist=False):
            return {"t_event": runs[tuple(bar)]}

        def student(self, probe, q0, t_end, s, bar, timeout=None):
            return {"t_event": runs[kept]}

    with pytest.raises(CheckFailure) as failure:
        c44._assert_other_bar(Ctx(), {"t_event": runs[(0.5, 1.0, 9.81)]})
    return failure.value


def test_a_run_that_keeps_a_part_of_the_sheets_bar_could_be_typed_or_ignored():
    """Planted: bar_ode reads the module's mass and inertia, the sheet's m and theta, whatever bar it is given."""
    failure = _other_bar((0.5, 1.0, 11.0))
    assert failure.diagnosis == "typed_numbers or ignored_argument", failure.diagnosis
    assert "sheet's m and theta whatever bar" in failure.hint and "ignores the bar's m and theta" in failure.hint, \
        failure.hint


def test_a_run_that_keeps_no_part_of_the_sheets_bar_is_neither():
    """The near miss: a run of a bar whose inertia alone is the sheet's, which no catalogue entry runs, names
    neither."""
    failure = _other_bar((0.8, 1.0, 11.0))
    assert "typed_numbers" not in failure.diagnosis and "ignored_argument" not in failure.diagnosis, failure


def _apex(row: int):
    """Problem 42's comparison of the apex time where the student's is the time of ``row`` of a run whose highest
    row is the fourth: the failure."""
    from checks import problem_42 as c42

    t = np.linspace(0.0, 1.4, 8)
    y = np.column_stack([t * (1.3 - t), 1.3 - 2 * t])
    with pytest.raises(CheckFailure) as failure:
        assert_close(float(t[row]), 0.65, "t_apex", c42.RANDOM_BANDS["t_apex"],
                     c42._apex_mistakes("t_apex", c42._highest_step(t, y)))
    return failure.value


def test_an_apex_read_from_the_highest_row_is_an_extremum_from_steps_or_the_nearest_row():
    assert _apex(3).diagnosis == "extremum_from_steps or nearest_sample", _apex(3).diagnosis


def test_an_apex_read_from_another_row_is_neither():
    assert _apex(4).diagnosis == "", _apex(4).diagnosis
