"""The text comparison of the output-prediction checks (problems 28 and 36): tolerant in layout, exact in content
and order, and explicit about the first wrong line."""

import pytest

from checks._answers import assert_same_text, text_lines
from grader.checking import CheckFailure, Mistake

EXPECTED = "Rainbow:\nred\nyellow\n"


def failure(got, expected=EXPECTED, **options):
    with pytest.raises(CheckFailure) as info:
        assert_same_text(got, expected, "Your output", **options)
    return info.value


def test_lines_are_stripped_and_blank_lines_dropped():
    assert text_lines("\n  red  \n\n\tyellow\n   \n") == ["red", "yellow"]


def test_caseless_lines_take_the_given_spelling():
    assert text_lines("RAINBOW:\nRed", ("Rainbow:",)) == ["Rainbow:", "Red"]


@pytest.mark.parametrize("got", [
    EXPECTED,
    "\n\n  Rainbow:\nred   \n\n    yellow\n\n",
    "rainbow:\r\nred\r\nyellow",
])
def test_layout_and_the_case_of_the_prompt_are_ignored(got):
    assert_same_text(got, EXPECTED, "Your output", ("Rainbow:",))


@pytest.mark.parametrize("got", ["Rainbow:\nRed\nyellow", "Rainbow:\nred\nyellow."])
def test_content_is_compared_exactly(got):
    failure(got, caseless=("Rainbow:",))


def test_the_prompt_is_caseless_only_when_asked():
    failure("rainbow:\nred\nyellow")


def test_first_wrong_line_without_giving_the_answer_away():
    exc = failure("Rainbow:\nred\nblue")
    assert "line 3 is the first wrong line: you wrote 'blue'." in exc.message
    assert "yellow" not in exc.message
    assert "  ✘  3: blue" in exc.message and "     2: red" in exc.message
    assert exc.message.splitlines()[0].startswith("Your output is not the expected output")
    assert "yellow" not in failure("Rainbow:\nred").message


def test_diff_when_revealing_is_allowed():
    exc = failure("Rainbow:\nred\nblue", reveal=True)
    assert "line 3 is the first wrong line: you wrote 'blue', expected 'yellow'." in exc.message
    assert "- yellow" in exc.message and "+ blue" in exc.message and "  red" in exc.message


def test_missing_and_extra_lines():
    assert "your text stops after line 2: 1 line(s) missing, from line 3 on." in failure("Rainbow:\nred").message
    extra = failure("Rainbow:\nred\nyellow\nblue").message
    assert "your text has 1 line(s) too many, from line 4 on: 'blue'." in extra


def test_wrong_order_is_diagnosed():
    exc = failure("Rainbow:\nyellow\nred", order_hint="Follow the links.")
    assert exc.diagnosis == "order"
    assert exc.hint == "Your lines are right but in the wrong order. Follow the links."


def test_mistakes_by_text_and_by_predicate():
    by_text = failure("red\nyellow", mistakes=[Mistake("missing_prompt", "red\nyellow", "prompt")])
    assert (by_text.diagnosis, by_text.hint) == ("missing_prompt", "prompt")
    by_predicate = failure("Rainbow:\nred\ngreen", mistakes=[
        Mistake("leaf_prints_color", lambda got, expected: "green" in got, "leaf"),
    ])
    assert by_predicate.diagnosis == "leaf_prints_color"


def test_no_diagnosis_without_a_match():
    exc = failure("Rainbow:\nred\nblue",
                  mistakes=[Mistake("leaf_prints_color", lambda got, expected: "green" in got, "")])
    assert (exc.diagnosis, exc.hint) == ("", "")


@pytest.mark.parametrize("got", [None, ["Rainbow:", "red", "yellow"], 3])
def test_a_reply_that_is_not_text_fails_as_the_students(got):
    exc = failure(got)
    assert exc.message.startswith("Your output must be text, got a value of type")
    assert exc.diagnosis == "format"
