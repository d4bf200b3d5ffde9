"""Checks of problem 28: the predicted output of main.m (answers.toml), and the port that prints it.

The text comparison (``text_lines``, ``answer_text``, ``assert_same_text``) lives in ``checks/_answers.py``.

Both checks are secret: their key is the output itself, which a recorded answer key would hand out; the port's
check compares with the same text.
"""

from grader.checking import STAGE_VALUES, Mistake, check
from probes import problem_28 as p28

from ._answers import answer_text, assert_same_text, text_lines

TITLE = "Understanding Recursion"

#: the prompt line, compared without regard to case
PROMPT = "Rainbow:"
ORDER_HINT = ("The walk follows the child links, starting from red; the order in which the objects are created or "
              "linked does not matter.")


def _mistakes(expected):
    lines = text_lines(expected, (PROMPT,))
    return [
        Mistake("missing_prompt", "\n".join(lines[1:]),
                f"disp('{PROMPT}') prints the prompt before the walk starts; clc only clears the command window "
                "before it."),
        Mistake("leaf_prints_color", lambda got, _: "green" in got,
                "green is a leaf (green.isLeaf = true): its Rainbow prints 'Sandwich' instead of its color."),
        Mistake("past_leaf", lambda got, _: "purple" in got,
                "The recursion stops at the leaf: green prints 'Sandwich' and does not call its child purple."),
    ]


def _expected(ctx):
    return ctx.reference(p28.output)


@check(3, title="[problem_28] output is what main.m prints", stage=STAGE_VALUES, group="prediction", secret=True)
def check_prediction(ctx):
    got = answer_text(ctx, "output")
    expected = _expected(ctx)
    assert_same_text(got, expected, "Your predicted output", (PROMPT,), _mistakes(expected), ORDER_HINT)


@check(1, title="the port main() prints the output of main.m", stage=STAGE_VALUES, group="port", secret=True)
def check_port(ctx):
    got = ctx.student(p28.output)
    expected = _expected(ctx)
    assert_same_text(got, expected, "What your main() prints", (PROMPT,), _mistakes(expected),
                     "Rainbow prints its own color first and then calls the Rainbow of its child.")
