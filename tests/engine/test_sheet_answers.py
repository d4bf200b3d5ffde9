"""A value that is the sheet's answer whatever an argument is: typed in, or the argument ignored
(``checks._answers.typed_or_ignored``).

Where a check passes another argument than the sheet's and the student's value is the sheet's answer (the reference's
run for the sheet's bar), the value cannot tell the sheet's numbers typed in from the argument ignored (a module's
constant or a default read in its place computes the same): both are told, as problem 4 tells its sheet's
configuration whatever fixed point is asked.  Planted: problem 44's run that keeps the sheet's m and theta whatever
bar it is given (a bar_ode that reads the module's mass and inertia); near miss: a run that keeps the sheet's theta
alone, which no entry of the catalogue runs, names neither.
"""

import pytest

from grader.checking import CheckFailure


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
