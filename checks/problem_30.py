"""Checks of problem 30: the class diagram of the v2 classes (answers.toml and class_diagram()); the free-text
questions (c), (d), (e) are scored by hand.

The comparison of class diagrams (``assert_same_diagram``) lives in ``checks/_answers.py``.

Both checks are secret: the diagram is the answer of (a) itself, a fixed set of arrows that depends on no input,
so recording it in the student kit would hand it out (and a failure names missing arrows of the key).
``class_diagram()`` is compared with the same set.
"""

from grader.checking import STAGE_VALUES, check
from probes import problem_30 as p30

from ._answers import assert_same_diagram, diagram_pairs

TITLE = "Inheritance to Structure Code"

MANUAL = {
    "c": ('(c) Why did we change certain properties from being "private" to being "protected"?', 1),
    "d": ("(d) What does the line obj = obj@LinkedGenericJointCLASS_v2(env, predBody, sucBody) do in the "
          "constructor of LinkedRotationalJointCLASS_v2.m?", 1),
    "e": ("(e) Why do we first define a LinkedGenericJointCLASS_v2 (that inherits from LinkedJointObjectCLASS_v2) "
          "and then inherit from it to get the LinkedRotationalJointCLASS_v2, rather than directly have "
          "LinkedRotationalJointCLASS_v2 inherit from LinkedJointObjectCLASS_v2?", 2),
}


def _expected(ctx):
    return {tuple(pair) for pair in ctx.reference(p30.class_diagram)}


@check(2, title="[problem_30] diagram: the inheritance arrows between the v2 classes", stage=STAGE_VALUES,
       group="diagram", secret=True)
def check_diagram(ctx):
    got = diagram_pairs(ctx.answer("diagram"), "answers.toml [problem_30] diagram")
    assert_same_diagram(got, _expected(ctx), "Your diagram")


@check(1, title="class_diagram() returns the inheritance arrows between the v2 classes", stage=STAGE_VALUES,
       group="code", secret=True)
def check_class_diagram(ctx):
    got = diagram_pairs(ctx.student(p30.class_diagram), "class_diagram()")
    assert_same_diagram(got, _expected(ctx), "class_diagram()")
