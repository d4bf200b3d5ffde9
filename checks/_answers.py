"""Written answers: the chosen option of a multiple-choice question, predicted program output (problems 28, 36),
class diagrams (problems 30, 36) and numbers typed in (``typed_failure``: problem 10's matrix read off a figure,
problem 19's multiple of m/120; ``typed_or_ignored``: the sheet's answer whatever an argument is)."""

import difflib
import math

from grader.checking import CheckFailure, fail, Mistake

__all__ = ["option_number", "choice", "text_lines", "answer_text", "assert_same_text", "EXAMPLE", "diagram_pairs",
           "assert_same_diagram",
           "typed_failure", "typed_or_ignored"]


def option_number(value):
    """The option number a written answer means, or None: ``4``, ``4.0``, ``"4"`` and ``" 4.0 "`` all mean option 4;
    a boolean, a fraction, a word or anything else means none."""
    if isinstance(value, bool):
        return None
    if isinstance(value, str):
        try:
            value = float(value.strip())
        except ValueError:
            return None
    if isinstance(value, int):
        return value
    if isinstance(value, float) and math.isfinite(value) and value.is_integer():
        return int(value)
    return None


def choice(ctx, key, options, question=""):
    """The option chosen in ``answers.toml [problem_NN] key``: one of ``options`` (integers), written as ``4``,
    ``4.0`` or ``"4"``, or a failure (diagnosis ``format``) that says how to write it.  Every multiple-choice check
    reads its answer through here, so that every natural way of writing a number is the same choice."""
    value = ctx.answer(key)
    number = option_number(value)
    options = list(options)
    if number in options:
        return number
    where = f"{question}: " if question else ""
    fail(f"{where}answers.toml [problem_{ctx.problem:02d}] {key} must be the number of one option, {options[0]} to "
         f"{options[-1]}; got {value!r}.", f"Write the option's number, e.g. {key} = {options[0]}.", "format")


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
    if not isinstance(got, str):
        fail(f"{name} must be text, got a value of type {type(got).__name__}: {str(got)[:200]}", diagnosis="format")
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
    recognise reversed pairs (all of them, or some: every arrow not in the diagram a missing one turned round),
    misspelt names, a forgotten second base, a class left out and indirect bases.
    ``mistakes`` are further ``(diagnosis, predicate(got, expected), hint)``, tried first after the names."""
    if got == expected:
        return
    message = (f"{name} does not match the class diagram: {len(got & expected)} of your {len(got)} inheritance "
               f"arrows (subclass -> base) are right, {len(expected)} are expected.\n"
               f"missing:\n{_arrows(expected - got)}\nnot in the diagram:\n{_arrows(got - expected)}")
    if {(base, sub) for sub, base in got} == expected:
        fail(message, "Each pair is [subclass, base]: you wrote [base, subclass].", "reversed")
    if got - expected and got - expected == {(base, sub) for sub, base in expected - got}:
        turned = len(got - expected)
        fail(message, f"Each pair is [subclass, base]: {turned} of your pairs {'is' if turned == 1 else 'are'} "
                      "[base, subclass] (the arrows not in the diagram are the missing ones turned round).",
             "reversed")
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


def typed_failure(ctx, message, hint, diagnosis, got, expected, tol, name):
    """The failure of a number or an array typed into answers.toml and compared with its key ``expected`` within
    ``tol`` (entry by entry: the precision the answer is written or read to), with the cause the diagnosis engine
    names from the output grammar (``grader.diagnosis.grammar.typed_slips``: a matrix whose axes were written as
    rows is the key transposed; one axis reversed is a column's sign).  Every check of a typed numeric answer fails
    through here, whatever stage found it: where the engine names a cause, it is the failure's diagnosis and its
    hint follows the check's own (``hint``: what the answer is); where it names none, the check's ``diagnosis``
    (a symptom, a verdict or none) stands."""
    import numpy as np

    from grader.context import explained
    from grader.diagnosis import Evidence

    evidence = Evidence(np.asarray(got, dtype=float), np.asarray(expected, dtype=float), tol, name, typed=True)
    found = explained(ctx, CheckFailure(message, "", "", evidence=evidence))
    if found.diagnosis:
        return CheckFailure(message, "\n".join(part for part in (hint, found.hint) if part), found.diagnosis,
                            evidence=evidence, explained=True)
    return CheckFailure(message, hint, diagnosis, evidence=evidence, explained=True)


def typed_or_ignored(value, hint: str, argument: str) -> list:
    """The known mistakes of ``value``, the sheet's answer (its numbers, or the reference's value for the sheet's
    arguments) where the check passes another ``argument``: the sheet's numbers typed in, and the argument ignored
    (a module's constant or a function's default read in its place, which computes the sheet's answer as well).
    The value cannot tell the two apart, so both are told ("could be"), as problem 4 tells the sheet's configuration
    whatever fixed point is asked."""
    return [Mistake("typed_numbers", value, hint),
            Mistake("ignored_argument", value, f"Or your code computes it, but ignores the {argument} it is given and "
                                               "reads a module's constant or a default in its place: pass the "
                                               f"{argument} on.")]
