"""Checks of problem 30: the class diagram of the v2 classes (answers.toml and class_diagram()); the free-text
questions (c), (d), (e) are scored by hand.

The comparison of class diagrams (``assert_same_diagram``) is shared with problem 36.
"""

from grader.checking import STAGE_VALUES, check, fail

TITLE = "Inheritance to Structure Code"

MANUAL = {
    "c": ('(c) Why did we change certain properties from being "private" to being "protected"?', 1),
    "d": ("(d) What does the line obj = obj@LinkedGenericJointCLASS_v2(env, predBody, sucBody) do in the "
          "constructor of LinkedRotationalJointCLASS_v2.m?", 1),
    "e": ("(e) Why do we first define a LinkedGenericJointCLASS_v2 (that inherits from LinkedJointObjectCLASS_v2) "
          "and then inherit from it to get the LinkedRotationalJointCLASS_v2, rather than directly have "
          "LinkedRotationalJointCLASS_v2 inherit from LinkedJointObjectCLASS_v2?", 2),
}

EXAMPLE = '[["SubclassName", "BaseClassName"], ...]'


def diagram_pairs(value, name):
    """``value`` as a set of ``(subclass, base)`` pairs of class names, or a failure that says what is wrong."""
    ok = isinstance(value, (list, tuple)) and all(
        isinstance(pair, (list, tuple)) and len(pair) == 2 and all(isinstance(c, str) for c in pair)
        for pair in value)
    if not ok:
        fail(f"{name} must be a list of [subclass, base] pairs of class names, got {str(value)[:200]}",
             f"Write one pair per inheritance arrow: {EXAMPLE}.", "format")
    return {(sub.strip(), base.strip()) for sub, base in value}


def _bases(pairs, name):
    """Every class that ``name`` inherits from in ``pairs``, directly or not."""
    direct = {base for sub, base in pairs if sub == name}
    return direct.union(*(_bases(pairs, base) for base in direct))


def _arrows(pairs):
    return "\n".join(f"    {sub} -> {base}" for sub, base in sorted(pairs)) or "    (none)"


def _loose(name):
    return name.casefold().removesuffix("_v2")


def assert_same_diagram(got, expected, name, mistakes=()):
    """Fail unless the set of ``(subclass, base)`` pairs ``got`` is ``expected``; name what is missing or extra and
    recognise reversed pairs, misspelt names, a forgotten second base, a class left out and indirect bases.
    ``mistakes`` are further ``(diagnosis, predicate(got, expected), hint)``, tried first after the names."""
    if got == expected:
        return
    message = (f"{name} does not match the class diagram: {len(got & expected)} of your {len(got)} inheritance "
               f"arrows (subclass -> base) are right, {len(expected)} are expected.\n"
               f"missing:\n{_arrows(expected - got)}\nnot in the diagram:\n{_arrows(got - expected)}")
    if {(base, sub) for sub, base in got} == expected:
        fail(message, "Each pair is [subclass, base]: you wrote [base, subclass].", "reversed")
    if {(_loose(sub), _loose(base)) for sub, base in got} == {(_loose(s), _loose(b)) for s, b in expected}:
        fail(message, "Use the class names exactly as in the code (with the _v2 suffix and the same capitals).",
             "class_names")
    for diagnosis, predicate, hint in mistakes:
        if predicate(got, expected):
            fail(message, hint, diagnosis)
    for sub in sorted({sub for sub, _ in expected}):
        bases = {base for s, base in expected if s == sub}
        if len(bases) > 1 and not bases <= {base for s, base in got if s == sub}:
            fail(message, f"{sub} inherits from {len(bases)} classes: {', '.join(sorted(bases))}.",
                 "multiple_inheritance")
    absent = sorted({c for pair in expected for c in pair} - {c for pair in got for c in pair})
    if absent:
        fail(message, f"Your diagram leaves out {', '.join(absent)}: every class of the hierarchy has its place, "
             f"with an arrow to each of its direct base classes.", "missing_class")
    for sub, base in sorted(got - expected):
        if base in _bases(expected, sub):
            fail(message, f"List only DIRECT base classes: {sub} inherits from {base} only through another class.",
                 "indirect")
    fail(message)


def _expected(ctx):
    return {tuple(pair) for pair in ctx.reference("problem_30.class_diagram")}


@check(2, title="[problem_30] diagram: the inheritance arrows between the v2 classes", stage=STAGE_VALUES,
       group="diagram")
def check_diagram(ctx):
    got = diagram_pairs(ctx.answer("diagram"), "answers.toml [problem_30] diagram")
    assert_same_diagram(got, _expected(ctx), "Your diagram")


@check(1, title="class_diagram() returns the inheritance arrows between the v2 classes", stage=STAGE_VALUES,
       group="code")
def check_class_diagram(ctx):
    got = diagram_pairs(ctx.student("problem_30.class_diagram"), "class_diagram()")
    assert_same_diagram(got, _expected(ctx), "class_diagram()")
