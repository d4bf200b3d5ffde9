"""Checks of problem 28: the predicted output of main.m (answers.toml), and the port that prints it.

The text comparison (``text_lines``, ``answer_text``, ``assert_same_text``) is shared with problem 36.
"""

import difflib

from grader.checking import STAGE_VALUES, Mistake, check, fail

TITLE = "Understanding Recursion"

#: the prompt line, compared without regard to case
PROMPT = "Rainbow:"
ORDER_HINT = ("The walk follows the child links, starting from red; the order in which the objects are created or "
              "linked does not matter.")


def text_lines(text, caseless=()):
    """The lines of ``text`` as they are compared: stripped, blank lines dropped, and a line equal to one of
    ``caseless`` up to case written as that one."""
    folded = {line.casefold(): line for line in caseless}
    stripped = (line.strip() for line in text.splitlines())
    return [folded.get(line.casefold(), line) for line in stripped if line]


def answer_text(ctx, key):
    """The answer ``key`` as text: a string, or a list of strings (one per line)."""
    value = ctx.answer(key)
    if isinstance(value, list) and all(isinstance(line, str) for line in value):
        return "\n".join(value)
    if not isinstance(value, str):
        fail(f"answers.toml [problem_{ctx.problem:02d}] {key} must be text, got a {type(value).__name__}: "
             f"{str(value)[:200]}", f'Write the lines in triple quotes:\n{key} = """\nfirst line\nsecond line\n"""',
             "format")
    return value


def _first_difference(got, expected, reveal=False):
    for i, (g, e) in enumerate(zip(got, expected)):
        if g != e:
            shown = f", expected {e!r}" if reveal else ""
            return f"line {i + 1} is the first wrong line: you wrote {g!r}{shown}."
    n = min(len(got), len(expected))
    if len(got) < len(expected):
        return f"your text stops after line {n}: {len(expected) - n} line(s) missing, from line {n + 1} on."
    return f"your text has {len(got) - n} line(s) too many, from line {n + 1} on: {got[n]!r}."


def assert_same_text(got, expected, name, caseless=(), mistakes=(), order_hint="", reveal=False):
    """Fail unless ``got`` has the lines of ``expected``, in order, up to surrounding spaces, blank lines and the
    case of the ``caseless`` lines.  The failure names the first wrong line and lists the student's lines with
    each wrong one marked; the expected text itself is shown only with ``reveal`` (a prediction whose failure
    printed the answer could be copied on the next attempt).  A
    ``Mistake`` whose value is the text that mistake produces (or a predicate ``value(got_lines,
    expected_lines)``) names the diagnosis, and lines in a wrong order are recognised as ``order``."""
    mine, theirs = text_lines(got, caseless), text_lines(expected, caseless)
    if mine == theirs:
        return
    ignored = ("ignoring surrounding spaces, blank lines and the case of " + ", ".join(map(repr, caseless))
               if caseless else "ignoring surrounding spaces and blank lines")
    if reveal:
        diff = "\n".join(line.rstrip() for line in difflib.ndiff(theirs, mine))
        shown = f"diff, line by line (- expected, + yours, ? marks the characters that differ):\n{diff}"
    else:
        marks = ["  ✘ " if i >= len(theirs) or line != theirs[i] else "    " for i, line in enumerate(mine)]
        shown = "your lines (✘ marks a wrong line; the expected text is not shown):\n" + "\n".join(
            f"{mark}{i + 1:>2}: {line}" for i, (mark, line) in enumerate(zip(marks, mine)))
        if len(mine) < len(theirs):
            shown += f"\n  ✘ ... {len(theirs) - len(mine)} line(s) missing"
    message = (f"{name} is not the expected output ({ignored}).\n{_first_difference(mine, theirs, reveal)}\n"
               f"{shown}")
    for mistake in mistakes:
        value = mistake.value
        if value(mine, theirs) if callable(value) else text_lines(value, caseless) == mine:
            fail(message, mistake.hint, mistake.name)
    if sorted(mine) == sorted(theirs):
        fail(message, f"Your lines are right but in the wrong order. {order_hint}".rstrip(), "order")
    fail(message)


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
    return ctx.reference("problem_28.output")


@check(3, title="[problem_28] output is what main.m prints", stage=STAGE_VALUES, group="prediction")
def check_prediction(ctx):
    got = answer_text(ctx, "output")
    expected = _expected(ctx)
    assert_same_text(got, expected, "Your predicted output", (PROMPT,), _mistakes(expected), ORDER_HINT)


@check(1, title="the port main() prints the output of main.m", stage=STAGE_VALUES, group="port")
def check_port(ctx):
    got = ctx.student("problem_28.output")
    expected = _expected(ctx)
    assert_same_text(got, expected, "What your main() prints", (PROMPT,), _mistakes(expected),
                     "Rainbow prints its own color first and then calls the Rainbow of its child.")
