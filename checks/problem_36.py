"""Checks of problem 36: the class hierarchy, the predicted output of PART I and PART II (answers.toml), and the
port that prints them; the free-text questions (a) and (c) are scored by hand.

Every check is secret: the hierarchy is the answer of (a) (a fixed pair of arrows), the predictions' key is the
output itself, and the ports are compared with the same output, so recording any of them in the student kit would
hand out a key.
"""

from grader.checking import STAGE_VALUES, Mistake, check
from probes import problem_36 as p36

from ._answers import answer_text, assert_same_diagram, assert_same_text, diagram_pairs, text_lines

TITLE = "Understanding Inheritance"

MANUAL = {
    "a": ("(a) Show the hierarchy of the three classes in a diagram (in words; the arrows are graded from "
          "[problem_36] hierarchy).", 1),
    "c": ("(c) Is there a way of getting rid of the third line of 'PART I' ('redQueen.foe = alice') by changing the "
          "first line 'redQueen = WonderlandCharacter('The Red Queen', [])'? If yes, how? If not, why not?", 2),
}

ORDER_HINTS = {
    "part1": "The two disp lines run in the order of the script.",
    "part2": ("TweedleDum.TellStory prints its two lines first and then calls obj.foe.TellStory(), which prints "
              "TweedleDee's two lines."),
}


def _swapped(line, a="TweedleDum", b="TweedleDee"):
    return line.replace(a, "\0").replace(b, a).replace("\0", b)


def _mistakes(part, expected):
    lines = text_lines(expected)
    if part == "part1":
        return [Mistake("typo_corrected", expected.replace("figthing", "fighting"),
                        "Predict exactly what the script prints, its typo included: the first disp says "
                        "'figthing'.")]
    return [
        Mistake("missing_foe_story", "\n".join(lines[:2]),
                "TweedleDum.TellStory ends with obj.foe.TellStory(): his foe, TweedleDee, continues the story."),
        Mistake("swapped",
                lambda got, exp: len(got) == len(exp) and all(g in (e, _swapped(e)) for g, e in zip(got, exp)),
                "In TweedleDee.TellStory, obj is TweedleDee and obj.foe is TweedleDum (who created him with "
                "TweedleDee('TweedleDee', obj)): 'For ' + obj.name + ' said ' + obj.foe.name."),
    ]


def _has_a(got, expected):
    subclasses = {sub for sub, _ in expected}
    return any(sub in subclasses and base in subclasses for sub, base in got)


@check(1, title="[problem_36] hierarchy: TweedleDum and TweedleDee and their base class", stage=STAGE_VALUES,
       group="hierarchy", secret=True)
def check_hierarchy(ctx):
    got = diagram_pairs(ctx.answer("hierarchy"), "answers.toml [problem_36] hierarchy")
    expected = {tuple(pair) for pair in ctx.reference(p36.class_hierarchy)}
    assert_same_diagram(got, expected, "Your hierarchy", [(
        "has_a", _has_a,
        "TweedleDum creates a TweedleDee and each holds the other as its foe: that is a reference (has-a), not "
        "inheritance (is-a). Look at the classdef lines: 'classdef TweedleDee < WonderlandCharacter'.")])


def _prediction(ctx, part, label):
    expected = ctx.reference(p36.output, part)
    assert_same_text(answer_text(ctx, part), expected, f"Your predicted output of {label}", (),
                     _mistakes(part, expected), ORDER_HINTS[part])


def _port(ctx, part):
    expected = ctx.reference(p36.output, part)
    assert_same_text(ctx.student(p36.output, part), expected, f"What your {part}() prints", (),
                     _mistakes(part, expected), ORDER_HINTS[part])


@check(2, title="[problem_36] part1 is what PART I prints", stage=STAGE_VALUES, group="part1", secret=True)
def check_part1(ctx):
    _prediction(ctx, "part1", "PART I")


@check(2, title="[problem_36] part2 is what PART II prints", stage=STAGE_VALUES, group="part2", secret=True)
def check_part2(ctx):
    _prediction(ctx, "part2", "PART II")


@check(1, title="the port part1() prints what PART I prints", stage=STAGE_VALUES, group="port1", secret=True)
def check_port_part1(ctx):
    _port(ctx, "part1")


@check(1, title="the port part2() prints what PART II prints", stage=STAGE_VALUES, group="port2", secret=True)
def check_port_part2(ctx):
    _port(ctx, "part2")
