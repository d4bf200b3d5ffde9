"""Problem 3's driven joint off its prescribed motion at none of the rates its check names otherwise
(``checks.problem_03._off_rate``): the rate is blamed only for a steady turn at another positive rate."""

import numpy as np

from checks.problem_03 import RATE_HINT, UNSTEADY_HINT, _off_rate

T = np.linspace(0.0, 10.0, 1001)
SAID = "off its motion"


def _told(q1):
    return _off_rate(T, q1, float(np.polyfit(T, q1, 1)[0]), SAID)


def test_a_steady_turn_at_another_positive_rate_is_the_rate():
    assert _told(0.5 * T) == (SAID, RATE_HINT, "wrong_rate")


def test_an_unsteady_turn_says_how_far_it_strays_and_names_no_cause():
    message, hint, diagnosis = _told(np.minimum(T, 0.5))  # turns, then holds at 0.5 rad
    assert diagnosis == "" and hint == UNSTEADY_HINT
    assert message.startswith(SAID) and "does not turn steadily: it strays up to" in message


def test_a_joint_at_rest_or_turning_back_steadily_names_no_cause_and_is_not_called_unsteady():
    for q1 in (np.zeros_like(T), -0.3 * T):
        assert _told(q1) == (SAID, RATE_HINT, "")


def test_a_run_that_is_not_finite_names_no_cause():
    assert _off_rate(T, np.full_like(T, np.nan), float("nan"), SAID) == (SAID, RATE_HINT, "")
