"""The formula tier's third input where a probe takes arguments and also declares the module's constants its
functions read (``rebind``): the arguments and the constants are drawn anew at once
(``grader.diagnosis.rebound.rebound_with``); the second input draws the arguments alone, as the grammar's slips of
the arguments ask.

Problem 25's walker reads the leg's length and the foot's radius from its module, and on the sheet the leg is twice
the radius: ``dy + l - r`` (the two terms' signs turned) equals ``dy + r`` (the leg's length left out of
``dy - l + r``) at every pair of angles.  Drawn with the angles only, every input kept that coincidence, and the
formula tier told a term left out; with the lengths drawn too on the third it tells nothing.  A term truly left out
(the radius) is still named, and so it is where the student typed the sheet's numbers rather than reading the
constants: their value does not change with the constants, and their third input is the angles' alone.  The angles
read as degrees, a slip of the arguments, is named on the second input as before (``engine-scale-walker-in-degrees``
of ``tests/engine/mistakes.toml``)."""

import pytest

from grader import grade_problem
from grader.results import Status
from grader.workers import Forked

from ..kit_support import SEED, warm_slot
from ..submissions import ROOT, Planted, build_planted

OLD = "S_r_SDs=(-DX, DY - l + r, 0.0),"
SIGNS_TURNED = Planted(name="walker-foot-above-the-hip", problem=25, file="problem_25.py", old=OLD,
                       new="S_r_SDs=(-DX, DY + l - r, 0.0),", check="p25.sheet_values")
RADIUS_LEFT_OUT = Planted(name="walker-radius-left-out", problem=25, file="problem_25.py", old=OLD,
                          new="S_r_SDs=(-DX, DY - l, 0.0),", check="p25.sheet_values", diagnosis="missing_term",
                          message="one term of a sum in `build_walker` is left out")

#: the radius left out, by a student who typed the sheet's numbers (the lengths, the hip's offsets): the reference's
#: joints of the walker, from its lengths read to its hip joint, with the numbers in place of the constants
_WALKER = (ROOT / "reference" / "problem_25.py").read_text()
_HIP = "q_index=[1])"
TYPED_OLD = _WALKER[_WALKER.index("    l, r = LEG_LENGTH, FOOT_RADIUS"):_WALKER.index(_HIP) + len(_HIP)]
TYPED_NEW = TYPED_OLD.replace("LEG_LENGTH, FOOT_RADIUS", "1.0, 0.5").replace("-DX", "-0.05") \
    .replace("DY - l + r", "0.7 - l").replace("DY", "0.7")
RADIUS_LEFT_OUT_TYPED = Planted(name="walker-radius-left-out-typed", problem=25, file="problem_25.py", old=TYPED_OLD,
                                new=TYPED_NEW, check="p25.sheet_values", diagnosis="missing_term",
                                message=RADIUS_LEFT_OUT.message)


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


@pytest.mark.parametrize("mistake", [RADIUS_LEFT_OUT, RADIUS_LEFT_OUT_TYPED], ids=lambda m: m.name)
def test_a_term_left_out_is_still_named_with_the_lengths_drawn(mistake, tmp_path, slot):
    result = _graded(mistake, tmp_path, slot)
    assert result.status is Status.FAILED, result.message
    assert result.diagnosis == mistake.diagnosis, (result.diagnosis, result.hint)
    assert mistake.message in result.hint, result.hint
