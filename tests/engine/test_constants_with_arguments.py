"""The engine's second input where a probe takes arguments and also declares the module's constants its functions
read (``rebind``): the arguments and the constants are drawn anew at once (``grader.diagnosis.rebound.rebound_with``).

Problem 25's walker reads the leg's length and the foot's radius from its module, and on the sheet the leg is twice
the radius: ``dy + l - r`` (the two terms' signs turned) equals ``dy + r`` (the leg's length left out of
``dy - l + r``) at every pair of angles.  Drawn with the angles only, the second input kept that coincidence, and the
engine told a term left out; with the lengths drawn too it tells nothing.  A term truly left out (the radius) is
still named on the same two inputs."""

import pytest

from grader import grade_problem
from grader.results import Status
from grader.workers import Forked

from ..kit_support import SEED, warm_slot
from ..submissions import Planted, build_planted

OLD = "S_r_SDs=(-DX, DY - l + r, 0.0),"
SIGNS_TURNED = Planted(name="walker-foot-above-the-hip", problem=25, file="problem_25.py", old=OLD,
                       new="S_r_SDs=(-DX, DY + l - r, 0.0),", check="p25.sheet_values")
RADIUS_LEFT_OUT = Planted(name="walker-radius-left-out", problem=25, file="problem_25.py", old=OLD,
                          new="S_r_SDs=(-DX, DY - l, 0.0),", check="p25.sheet_values", diagnosis="missing_term",
                          message="one term of a sum in `build_walker` is left out")


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot([25])


def _graded(mistake, tmp_path, slot):
    submission = build_planted(mistake, tmp_path / mistake.name)
    report = grade_problem(25, submission, seed=SEED, workers=Forked(slot))
    return {r.check_id: r for r in report.results}[mistake.check]


def test_a_coincidence_of_the_sheets_lengths_is_not_told_as_a_term_left_out(tmp_path, slot):
    result = _graded(SIGNS_TURNED, tmp_path, slot)
    assert result.status is Status.FAILED, result.message
    assert result.diagnosis != "missing_term", result.hint


def test_a_term_left_out_is_still_named_with_the_lengths_drawn(tmp_path, slot):
    result = _graded(RADIUS_LEFT_OUT, tmp_path, slot)
    assert result.status is Status.FAILED, result.message
    assert result.diagnosis == RADIUS_LEFT_OUT.diagnosis, (result.diagnosis, result.hint)
    assert RADIUS_LEFT_OUT.message in result.hint, result.hint
