"""A catalogue's name told on a shrunk input is checked on a second failing input (``context._narrowed``) also where
the comparison's name shows the input's numbers (``the body's inertia with your dimensions [...]``): the two
failures are of one property when their first lines agree without the numbers, and a known mistake that the
answer reproduces on the degenerate input only (a value multiplied by m² is a quarter of it at m = 0.5) is not
told; the diagnosis engine is asked instead.

* Planted: an answer m² I where the catalogue knows I / 4: at m = 0.5 the mistake reproduces it, at m = 2 not, so
  the name is dropped.
* Near misses: an answer I / 4 on every input keeps the name; failures of two different properties are reported as
  the one shown is.
"""

import numpy as np
import pytest

from grader import context
from grader.checking import EXACT, CheckFailure, Mistake, assert_close

MOMENTS = np.array([1.0, 2.0, 2.5])


def _failure(answer, m, name="the body's inertia with your dimensions {}"):
    """The failure of comparing ``answer(m, I)`` with ``I`` at the mass ``m``, the comparison named with numbers
    that depend on the input, the catalogue knowing the quarter of the expected value."""
    expected = MOMENTS * (1.0 + m)
    try:
        assert_close(answer(m, expected), expected, name.format(np.round(np.sqrt(expected * m), 4)), EXACT,
                     [Mistake("semi_axes", expected / 4, "a quarter of the expected moments")])
    except CheckFailure as exc:
        return exc
    pytest.fail("the comparison passed")


def test_a_name_that_holds_on_the_degenerate_input_only_is_dropped():
    shown, other = _failure(lambda m, I: m**2 * I, 0.5), _failure(lambda m, I: m**2 * I, 2.0)
    assert shown.diagnosis == "semi_axes"  # the catalogue's name on the shrunk input alone
    assert shown.message.partition("\n")[0] != other.message.partition("\n")[0]
    told = context._narrowed(shown, other)
    assert told.diagnosis == "" and not told.candidates, told.diagnosis
    assert told.message == shown.message


def test_a_name_that_holds_on_both_inputs_stays():
    shown, other = _failure(lambda m, I: I / 4, 0.5), _failure(lambda m, I: I / 4, 2.0)
    told = context._narrowed(shown, other)
    assert told.diagnosis == "semi_axes"


def test_failures_of_two_properties_are_reported_as_shown():
    shown = _failure(lambda m, I: m**2 * I, 0.5)
    other = _failure(lambda m, I: m**2 * I, 2.0, name="the body's principal axes at {}")
    assert context._narrowed(shown, other) is shown
