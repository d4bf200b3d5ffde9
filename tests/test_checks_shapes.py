"""The shape helpers of checks/_shapes.py: a reply from the sandbox must have the length and keys a comparison
loops over, or the check fails saying what is missing (an empty reply must never compare nothing)."""

import pytest

from checks._shapes import as_dict, as_list
from grader.checking import CheckFailure


def failure(helper, *args):
    with pytest.raises(CheckFailure) as info:
        helper(*args)
    return info.value


def test_a_list_of_the_right_length_passes():
    assert as_list((1, 2, 3), "the poses", 3) == [1, 2, 3]


@pytest.mark.parametrize("value, shown", [([], "got 0."), ([1], "got 1."), ([1, 2, 3, 4], "got 4.")])
def test_an_emptied_or_short_list_fails(value, shown):
    exc = failure(as_list, value, "the poses", 3)
    assert exc.message == f"the poses must have 3 entries, {shown}"
    assert exc.diagnosis == "shape"


@pytest.mark.parametrize("value", [None, {"a": 1}, "abc", 3.0])
def test_a_value_that_is_no_list_fails(value):
    exc = failure(as_list, value, "the poses", 2)
    assert exc.message.startswith("the poses must be a list of 2 entries, got a value of type")
    assert exc.diagnosis == "shape"


def test_a_dict_with_its_keys_passes():
    reply = {"J": 1, "plus": [], "minus": [], "extra": 0}
    assert as_dict(reply, "the reply", ("J", "plus", "minus")) is reply


def test_missing_keys_are_named():
    exc = failure(as_dict, {"J": 1}, "the reply", ("J", "plus", "minus"))
    assert exc.message.startswith("the reply has no entries ['plus', 'minus']")
    assert exc.diagnosis == "shape"


@pytest.mark.parametrize("value", [None, [], "J"])
def test_a_value_that_is_no_dict_fails(value):
    exc = failure(as_dict, value, "the reply", ("J",))
    assert exc.message.startswith("the reply must be a dict, got a value of type")
