"""A catalogue's name needs evidence: a known mistake is named only where the slip it stands for reproduces the
student's answer, not where a property of the answer that the slip would give happens to hold.

* On a second input (``grader.checking.confirmed``): a mistake named on the input shown is named only where it
  reproduces the student's value on a second input the check chooses as well (problem 24's pendulum in a second
  configuration).  Planted: a value in body coordinates that equals the inertial one at the angle shown only; near
  misses: the inertial value on both inputs keeps its name; a second input that passes, or fails another property,
  or raises, names nothing.
"""

import numpy as np
import pytest

from grader.checking import EXACT, CheckFailure, Mistake, assert_close, confirmed
from grader.errors import StudentCodeError

R = np.array([0.5, 0.0, 0.0])


def _turn(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _comparison(answer, angle, hint="the generic hint"):
    """The comparison of ``answer(angle)`` with a body-frame position ``R`` whose inertial value is ``turn(angle) R``
    (the catalogue's ``wrong_frame``); ``known``: False compares without the catalogue."""
    def compare(known=True):
        try:
            assert_close(answer(angle), R, "B_r_IB of link_1", EXACT,
                         [Mistake("wrong_frame", _turn(angle) @ R, "the inertial position")] if known else [])
        except CheckFailure as exc:
            if exc.diagnosis or exc.hint:
                raise
            raise CheckFailure(exc.message, hint, "", exc.candidates, exc.evidence) from None

    return compare


def _told(answer, second=0.7):
    try:
        confirmed(_comparison(answer, np.pi / 6), _comparison(answer, second))
    except CheckFailure as exc:
        return exc
    pytest.fail("the comparison passed")


def _by_chance(a):
    """A position off by a shift that makes it the inertial one at the angle shown (pi/6) only."""
    return R + (_turn(np.pi / 6) @ R - R)


def test_a_name_that_holds_on_the_input_shown_only_is_not_told():
    told = _told(_by_chance)
    assert told.diagnosis == "" and told.hint == "the generic hint", (told.diagnosis, told.hint)
    assert told.evidence is not None  # the diagnosis engine is asked


def test_a_name_that_holds_on_both_inputs_is_told():
    assert _told(lambda a: _turn(a) @ R).diagnosis == "wrong_frame"


def test_a_second_input_that_passes_fails_another_property_or_raises_names_nothing():
    passes = _told(lambda a: _turn(a) @ R if a == np.pi / 6 else R)
    assert passes.diagnosis == ""

    def other(known=True):
        assert_close(np.zeros(3), np.ones(3), "A_IB of link_2", EXACT, [Mistake("wrong_frame", np.zeros(3), "")])

    with pytest.raises(CheckFailure) as raised:
        confirmed(_comparison(lambda a: _turn(a) @ R, np.pi / 6), other)
    assert raised.value.diagnosis == ""

    def crashes():
        raise StudentCodeError("exception", "ValueError", "raised on the second input", "", "call")

    with pytest.raises(CheckFailure) as raised:
        confirmed(_comparison(lambda a: _turn(a) @ R, np.pi / 6), crashes)
    assert raised.value.diagnosis == ""
