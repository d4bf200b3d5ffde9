"""Explaining a failing comparison: the hypotheses of the grammar, of the declared terms and of runs evaluated on
the input shown and a second one, the simplest that reproduce the student's answer kept; and, while the kit's key
is recorded, the engine's reference calls made for every comparison of a declared probe."""

from __future__ import annotations

import threading
from dataclasses import dataclass, field

import numpy as np

from checks._diagnoses import DIAGNOSES
from probes import ProbeLookupError, lookup, name_of

from ..values import Tol, format_array
from ..errors import GraderFault, StudentFault
from .evidence import (
    array_of,
    at,
    call_key,
    counterpart,
    evaluated,
    at_point,
    numbers_told,
    ONE_INPUT_NUMBERS,
    sibling,
    Declaration,
    declaration,
    distinct,
    Evidence,
    Finding,
    Hypothesis,
    locate,
    part_of,
    Source,
    stepped,
    within,
)
from .grammar import (
    changed_how,
    moved,
    ignore_candidates,
    input_slips,
    label_of,
    output_slips,
    perturbations,
    perturbed,
    precision_slips,
    replaced,
    rotation_of,
    second_args,
    typed_slips,
    unturned,
)
from . import trace
from .models import is_model, model_slips
from .rebound import REBOUND, rebound_input, rebound_with
from .mutants import Contested, KIT_NOTE, left_to_live, mutant_slips, opposite_slips
from .scene import Budget, constants_of, evidence_at, MAX_STUDENT_CALLS, Scene
from .terms import term_slips, term_values
from .runs import (
    aligned_runs,
    START_KEY,
    OFFSET_KEY,
    FIXED_STEPS,
    is_run,
    model_evidences,
    parameter_variants,
    rhs_cases,
    rhs_call,
    RHS_TOL,
    run_in_log,
    run_slips,
    variant_sheets,
)

__all__ = [
    "RECORDING",
    "value_slips",
    "find",
    "doubted",
    "recording",
    "note_comparison",
    "prepared",
    "prepare_call",
    "prepare",
    "RESULT_LEAVES",
    "JUDGED_TOL",
    "judged",
    "rivalled",
]


#: while the student kit's answer key is recorded: the recording context of the running check (``recording``), so
#: that each comparison (``grader.checking``) makes the reference calls the engine may need
RECORDING = threading.local()


@dataclass
class _Input:
    """One input's evidence and what the engine computed for it: hypothesis key -> predicted value."""

    evidence: Evidence
    predicted: dict = field(default_factory=dict)
    hypotheses: dict = field(default_factory=dict)
    terms: dict | None = None
    extras: dict | None = None


def _predict(scene: Scene, evidence: Evidence, constants: dict) -> _Input:
    """The hypotheses' predicted values on one input."""
    one = _Input(evidence)
    source = evidence.source
    decl = declaration(source.probe) if source is not None else None
    rotation = rotation_of(decl, source.args) if decl is not None else None
    for hypothesis, value in output_slips(evidence.expected, constants, rotation, evidence.got):
        one.hypotheses[hypothesis.key] = hypothesis
        one.predicted[hypothesis.key] = value
    if source is None:
        return one
    for hypothesis, args in input_slips(decl, source.args) if decl is not None else ():
        try:
            value = scene.reference_at(source.probe, args, source.path)
        except GraderFault:
            continue
        if value is not None:
            one.hypotheses[hypothesis.key] = hypothesis
            one.predicted[hypothesis.key] = value
    terms = terms_call(decl, source)
    if terms is not None:
        try:
            split = scene.reference(*terms)
        except GraderFault:
            split = None
        if isinstance(split, dict):
            one.terms = term_values(split.get("terms", {}), source.path, evidence.expected.shape)
            one.extras = term_values(split.get("extra", {}), source.path, evidence.expected.shape)
    return one


def terms_call(decl: Declaration | None, source: Source) -> tuple | None:
    """``(probe, args)`` of the reference's call that splits ``source``'s value into its terms: the declared
    ``terms`` of its probe, or of the cheaper call that holds the value (``part``: problem 37's Lagrange probe
    holds ``M``, ``f``, ``g`` of the probe of the mass matrix), on that call's arguments; None where neither
    declares terms."""
    if decl is not None and decl.terms:
        return decl.terms, tuple(source.args)
    part = part_of(source)
    inner = declaration(part[0]) if part is not None else None
    return (inner.terms, part[1]) if inner is not None and inner.terms else None


def _sources(scene: Scene, evidence: Evidence) -> None:
    log = getattr(scene.ctx, "calls", ())
    if evidence.source is None:
        evidence.source = locate(log, evidence.raw_expected, "reference", evidence.tol)
    if evidence.student is None:
        evidence.student = locate(log, evidence.raw_got, "student")
    if evidence.student is None:  # a copy of the student's result, compared up to the tolerance
        evidence.student = counterpart(log, evidence.got, evidence.source, evidence.tol)
    if evidence.student is None:  # a value of the student's call at one of several points
        evidence.student = evaluated(log, evidence.got, evidence.tol,
                                     evidence.source.path if evidence.source is not None else ())
    if evidence.source is None and evidence.student is not None:
        evidence.source = traced(scene, evidence.student, evidence.raw_expected, evidence.tol)
        if evidence.source is not None:  # the reference's own value, at full precision, stands for the printed one
            evidence.expected = array_of(at_point(evidence.source.root, evidence.source.path))
    if evidence.source is not None and evidence.student is not None \
            and evidence.student.probe != evidence.source.probe:
        alike = _asked_alike(scene, evidence)
        if alike is not None:
            evidence.student = alike
        else:
            answered = _answered_alike(scene, evidence)
            if answered is not None:  # both sides named alike: the student's call was logged with its function
                student = evidence.student
                evidence.source = answered
                evidence.student = Source(answered.probe, tuple(student.args), student.path, student.root)


def _asked_alike(scene: Scene, evidence: Evidence) -> Source | None:
    """The student's call of the expected value's own probe, on its arguments, where the compared value came from
    another probe of theirs (a reply that holds it beside other things: a Jacobian beside the chain's values its
    central differences were taken from) and that call gives the compared value again: the second input and the
    formula tier then ask the two sides alike.  One call of the student's code; None where it raises, gives
    another value, or the probe declares nothing to the engine."""
    source = evidence.source
    if declaration(source.probe) is None or evidence.got is None:
        return None
    try:
        root = scene.student(source.probe, source.args)
    except (StudentFault, GraderFault, Budget):  # their code cannot answer that probe: the call found stands
        return None
    value = array_of(at(root, source.path))
    if value is None or value.shape != evidence.got.shape or not within(value, evidence.got, evidence.tol):
        return None
    return Source(source.probe, tuple(source.args), source.path, root)


def _answered_alike(scene: Scene, evidence: Evidence) -> Source | None:
    """The reference's call of the student's own probe, on the student's arguments, where the expected value came
    from another probe (a mass the check computes with the reference's formula, compared with the mass of the
    student's MuJoCo model: the reference's model stands for the formula) and the reference's call gives the
    expected value at the student's path: the second input, the test of an ignored argument and the formula tier
    then ask the two sides alike.  One call of the reference; None where it fails, gives another value, or the
    student's call is no MuJoCo model (a run, a symbolic answer evaluated at the check's points, whose second input
    is the reference's call at another point)."""
    student = evidence.student
    if not is_model(student.root):
        return None
    try:
        probe = name_of(student.probe)
    except ProbeLookupError:
        return None
    decl = declaration(probe)
    if evidence.motion or (decl is not None and decl.motion):
        return None
    try:
        return _reference_alike(scene, Source(probe, tuple(student.args), student.path, student.root),
                                evidence.expected, evidence.tol)
    except (GraderFault, Budget):
        return None


def traced(scene: Scene, student: Source, expected, tol: Tol) -> Source | None:
    """The reference's call with the arguments of the student's call of a declared probe, when its value is the
    expected one within the tolerance (a value the sheet prints, compared before the check asks the reference):
    the source of the expected value, or None."""
    if declaration(student.probe) is None:
        return None
    return _reference_alike(scene, student, expected, tol)


def _reference_alike(scene: Scene, student: Source, expected, tol: Tol) -> Source | None:
    """The reference's call of ``student``'s probe on its arguments, as a source, where its value at the student's
    path is ``expected`` within the tolerance; None otherwise (or where there is no expected value)."""
    target = array_of(expected)
    if target is None:
        return None
    root = scene.reference(student.probe, tuple(student.args))
    value = array_of(at_point(root, student.path))
    if value is None or value.shape != target.shape or not within(value, target, tol):
        return None
    return Source(student.probe, tuple(student.args), student.path, root)


#: the engine's draws of a second input before it gives up: a draw on which the reference raises, or gives a
#: degenerate value (none, or zeros where the input shown has none), is not used; one that gives another shape
#: ends the search (the arguments set the shape: a duration, a count).  Every grading of one check draws the same
#: (the seed is the check's and the call's): where half the draws are refused (problem 4's fixed point drawn beyond
#: the linkage's reach), three left every grading of the check without a second input one time in eight
DRAW_ATTEMPTS = 8


def _drawn(scene: Scene, source: Source, expected: np.ndarray, tol: Tol):
    """``(args, root)``: the first of the engine's draws of a second input for ``source``'s call (``second_args``) on
    which the reference gives a usable value at ``source.path`` (``expected``: the value of the input shown), ``ALONE``
    where there is nothing to draw or the value does not change with the arguments (a second input would tell nothing),
    or None where no draw is usable.  In the student kit a draw whose value the key does not hold ends the explanation
    (a grader fault), as every other call the key lacks."""
    decl = declaration(source.probe)
    seed = scene.draw_seed(source)
    fault = None
    for attempt in range(DRAW_ATTEMPTS):
        args = second_args(decl, tuple(source.args), seed, attempt)
        if args is None:
            trace.note("second", reason="nothing to draw")
            return ALONE
        try:
            root = scene.reference(source.probe, args)
        except GraderFault as exc:
            fault = exc
            continue
        value = array_of(at(root, source.path))
        if value is not None and value.shape != expected.shape:  # the arguments set the shape (a duration, say)
            trace.note("second", reason="the value's shape changes with the arguments")
            return None
        if value is None or _vanishes(value, expected, tol):
            continue
        if not distinct(value, expected, tol):
            trace.note("second", reason="the value does not change with the arguments")
            return ALONE
        return args, root
    trace.note("second", reason="no usable draw")
    if fault is not None and getattr(scene.ctx.oracle, "mode", "") == "kit":
        raise fault
    return None


#: what ``_drawn`` gives where one input is all there is: the call has no arguments to draw, or its value does not
#: change with them
ALONE = "alone"


def _vanishes(value: np.ndarray, expected: np.ndarray, tol: Tol) -> bool:
    """A drawn value of zeros where the value shown has none: a degenerate input."""
    zeros = np.zeros_like(value)
    return not distinct(value, zeros, tol) and distinct(expected, zeros, tol)


def _second_input(scene: Scene, evidence: Evidence, constants: bool = False) -> Evidence | None:
    """The same comparison on an input the engine draws (``_drawn``: the probe's declared angles, vectors,
    rotations and scalars drawn anew, or every float of its arguments varied; where that draws nothing, the
    module's constants the probes declare drawn anew, ``rebound_input``): the student's value there and the
    reference's, or None.  Where the call has no arguments to draw or its value does not change with them, and no
    constant is drawn anew, the evidence is marked ``alone``: its one input is all there is.  ``constants``: the
    formula tier's third input, where the module's constants the probe declares are drawn at once with its
    arguments (``rebound_with``): a slip of the code that gives the student's value only where the sheet's constants
    are related (problem 25's leg twice its foot's radius) is refuted there.  The second input keeps the constants:
    the grammar's slips of the arguments and the terms a probe declares are asked of its own call."""
    source, student = evidence.source, evidence.student
    if source is None or student is None or evidence.motion:
        return None
    if source.probe == REBOUND or source.probe != student.probe or not _equal_args(source.args, student.args):
        return rebound_input(scene, evidence)
    drawn = _drawn(scene, source, evidence.expected, evidence.tol)
    if drawn is None or drawn is ALONE:
        second = rebound_input(scene, evidence)
        evidence.alone = second is None and drawn is ALONE
        return second
    args, expected_root = drawn
    plain = evidence_at(scene, evidence, Source(source.probe, tuple(args), source.path, expected_root),
                        (source.probe, tuple(args)), "second")
    if not constants:
        return plain
    return rebound_with(scene, evidence, args, expected_root, plain) or plain


#: the other values of the call shown that a slip of the formula tier must reproduce as well, at most
SIBLINGS = 12


def _siblings(evidences: list) -> list:
    """The other values of the call behind the input shown (where there are two inputs, or the one is ``alone``), as
    comparisons of their own, those nearest the compared one first: a slip inside a formula must give the student's
    whole result of that call (the values they have right as well as the ones they have wrong), not only the one
    compared; two slips that give the same compared value (a term left out, two arguments exchanged that put that term
    elsewhere) differ there.  Where the student's call is another probe's, its values are those below the same start of
    the reference's paths (``_prefix``)."""
    if len(evidences) < 2 and not (evidences and evidences[0].alone):
        return []
    first = evidences[0]
    source, student = first.source, first.student
    if source is None or student is None or source.root is None or student.root is None:
        return []
    prefix = _prefix(tuple(source.path), tuple(student.path))
    if prefix is None or (prefix if source.probe == student.probe else not student.path):
        return []
    found = []
    for path, expected in _leaves(at(source.root, prefix)):
        if (*prefix, *path) == tuple(source.path):
            continue
        got = array_of(at(student.root, path))
        if got is None or got.shape != expected.shape:
            continue
        found.append(Evidence(got, expected, first.tol, first.name, None, None,
                              Source(source.probe, tuple(source.args), (*prefix, *path), source.root),
                              Source(student.probe, tuple(student.args), path, student.root)))
    found.sort(key=lambda e: -_shared(e.source.path, tuple(source.path)))
    return found[:SIBLINGS]


def _prefix(source_path: tuple, student_path: tuple) -> tuple | None:
    """The start of the reference's path before the student's (the student's call gives, at its own paths, the
    values the reference's gives below it: ``frames()`` within a call that returns the frames beside other values),
    or None where the student's path is no end of the reference's."""
    start = len(source_path) - len(student_path)
    if start < 0 or source_path[start:] != student_path:
        return None
    return source_path[:start]


def _shared(a: tuple, b: tuple) -> int:
    """The length of the common start of two paths."""
    n = 0
    for x, y in zip(a, b):
        if x != y:
            break
        n += 1
    return n


def _equal_args(a, b) -> bool:
    try:
        return call_key("", tuple(a)) == call_key("", tuple(b))
    except Exception:  # noqa: BLE001
        return False


def _testable(evidence: Evidence) -> bool:
    """A comparison the test of an ignored argument can change: the reference's and the student's value come from
    calls of one probe with the same arguments (not a run), and the student's value is not zero (a product that
    vanishes on an input stays zero when one of its factors changes: that tells nothing)."""
    source, student = evidence.source, evidence.student
    if source is None or student is None or source.probe != student.probe or evidence.motion:
        return False
    if not _equal_args(source.args, student.args):
        return False
    decl = declaration(source.probe)
    if decl is not None and decl.motion:
        return False
    return evidence.got.size > 0 and distinct(evidence.got, np.zeros_like(evidence.got), evidence.tol)


def _unchanged(scene: Scene, at_input: Evidence, path) -> bool | None:
    """Whether the student's value stays what it is on ``at_input`` (a comparison: its arguments, the student's
    value and the reference's) when the argument at ``path`` takes another value (``grammar.perturbed``); None
    where that tells nothing: the argument cannot be changed, the reference's value does not change with it (no
    sensitivity), or either side refuses the changed input."""
    source, student = at_input.source, at_input.student
    try:
        changed = perturbed(at(list(source.args), path))
    except (IndexError, KeyError, TypeError):
        return None
    if changed is None:
        return None
    args = replaced(tuple(source.args), path, changed)
    try:
        theirs = scene.reference_at(source.probe, args, source.path)
    except GraderFault:
        return None
    if theirs is None or theirs.shape != at_input.expected.shape \
            or not distinct(theirs, at_input.expected, at_input.tol):
        return None
    try:
        other = scene.student_at(source.probe, args, student.path)
    except StudentFault:
        return None
    if other is None or other.shape != at_input.got.shape:
        return None
    return within(other, at_input.got, at_input.tol)


def _moved_input(scene: Scene, evidence: Evidence, decl: Declaration | None) -> Evidence | None:
    """The comparison on ``evidence``'s input with every argument moved at once (``grammar.moved``): the
    student's value there and the reference's, or None (nothing to move, a side refuses it, or a value of zero)."""
    source, student = evidence.source, evidence.student
    args = moved(decl, source.args)
    if args is None:
        return None
    try:
        expected = scene.reference_at(source.probe, args, source.path)
        got = scene.student_at(source.probe, args, student.path)
    except (GraderFault, StudentFault):
        return None
    if expected is None or got is None or got.shape != expected.shape \
            or not distinct(got, np.zeros_like(got), evidence.tol):
        return None
    return Evidence(got, expected, evidence.tol, evidence.name, None, None,
                    Source(source.probe, args, source.path, None), Source(source.probe, args, student.path, None))


#: the student's calls the test of an ignored argument may make, at most (one per argument the reference's value
#: follows, one for the input with every argument moved, and one more for each argument that the student's value
#: does not follow): it is heard beside every other tier, and the formula tier's third input still needs one of
#: the explanation's ``MAX_STUDENT_CALLS``
IGNORED_CALLS = 5


def _ignored(scene: Scene, evidences: list, unreached: list | None = None) -> list:
    """The arguments the student's function ignores: where the reference's value changes with an argument, the
    student's stays the same, on the input shown and again on an input where every argument is moved at once
    (``grammar.moved``, from the second input where there is one): a value unchanged by chance (a zero among the
    other arguments, an axis the input's inertia happens to keep) does not survive the move.  A value that does
    not follow an argument at all is the finding itself, not a guess.  Every declared angle, scalar, vector and
    rotation is changed, and every other argument of real numbers; where every argument the reference follows is
    ignored, the answer is constant.  ``unreached`` receives the positions of the call's arguments that the test
    ran out of its budget before changing (the formula tier may tell one that its slip leaves unused)."""
    first = evidences[0]
    if not _testable(first):
        trace.note("ignored", reason="not testable")
        return []
    decl = declaration(first.source.probe)
    second = evidences[1] if len(evidences) > 1 and _testable(evidences[1]) \
        and evidences[1].source.probe == first.source.probe else None
    leaves = ignore_candidates(decl, first.source.args)
    budget = scene.student_calls + min(IGNORED_CALLS, MAX_STUDENT_CALLS - 1 - scene.student_calls)
    found, followed, complete, shifted = [], [], True, False
    for k, (path, role, value) in enumerate(leaves):
        if scene.student_calls + (2 if shifted else 3) > budget:  # an argument ignored is tested on both inputs
            complete = False
            if unreached is not None:
                unreached += [p[0] for p, _, _ in leaves[k:] if len(p) == 1 and isinstance(p[0], int)]
            break
        unchanged = _unchanged(scene, first, path)
        if unchanged is None:
            continue
        followed.append(path)
        if not unchanged:
            continue
        if shifted is False:
            shifted = _moved_input(scene, second if second is not None else first, decl)
        if shifted is not None and _unchanged(scene, shifted, path):
            key = f"{IGNORED_KEYS[0] if array_of(value).ndim == 0 else IGNORED_ARRAY}{path}"
            found.append(Hypothesis(key, "ignored_argument", 3,
                                    f"your value does not change when {_label(decl, path)} {changed_how(value)} "
                                    "(on the input shown and on one with every argument changed), while the "
                                    "expected one does: the function ignores it"))
            found += _unturned(scene, [first, shifted], found[-1], decl, path, role) \
                or _zeroed(scene, [first, shifted], found[-1], decl, path, role)
    trace.note("ignored", arguments=len(leaves), followed=len(followed), found=[h.key for h in found],
               complete=complete)
    ignored = [h for h in found if not h.twin]  # a twin reads an argument ignored another way
    if complete and len(followed) > 1 and len(ignored) == len(followed):  # nothing changes it: no use of the input
        return [Hypothesis("ignored:all", "constant_answer", 3, "your value does not change when any of the "
                           f"arguments ({', '.join(_label(decl, p) for p in followed)}) does")]
    return found


def _unturned(scene: Scene, inputs: list, ignored: Hypothesis, decl: Declaration | None, path,
              role: str) -> list:
    """The rival of an angle or a rotation found ignored (``ignored``): where the student's value is the
    reference's with that argument turning nothing (``grammar.unturned``: the angle zero, the rotation the identity)
    on the input shown and on the moved one (``inputs``), a rotation by it is left out, a slip of the frame told
    beside the argument ignored (a twin: one value, read two ways).  Two reference calls; none where the argument
    is of another kind."""
    if not _reproduced_with(scene, inputs, path, lambda value: unturned(role, value)):
        return []
    return [Hypothesis(f"{ignored.key}=unturned", "wrong_frame", ignored.cost,
                       f"your value is the expected one with {_label(decl, path)} turning nothing: a rotation by it "
                       "is left out (the value stays in the coordinates of the frame not turned)", twin=True)]


def _zeroed(scene: Scene, inputs: list, ignored: Hypothesis, decl: Declaration | None, path, role: str) -> list:
    """The rival of an argument found ignored (``ignored``) that adds terms to the value: where the student's value
    is the reference's with that argument zero on the input shown and on the moved one (``inputs``), the terms it
    makes are left out, a term missing told beside the argument ignored (a twin: one value, read two ways; ``M qdd =
    f + g`` for ``M qdd = f + g + tau``, a gait's sine series left out with its coefficients).  Two reference calls;
    none for an angle or a rotation (zero turns nothing: ``_unturned``'s), nor where the argument is zero already."""
    def zero(value):
        array = array_of(value)
        if array is None or not np.all(np.isfinite(array)) or not np.any(array != 0) \
                or unturned(role, value) is not None:
            return None
        zeros = np.zeros_like(array, dtype=float)
        return float(zeros) if zeros.ndim == 0 else zeros.tolist() if isinstance(value, (list, tuple)) else zeros

    if not _reproduced_with(scene, inputs, path, zero):
        return []
    return [Hypothesis(f"{ignored.key}{ZEROED}", "missing_term", ignored.cost,
                       f"your value is the expected one with {_label(decl, path)} zero: the terms it makes are left "
                       "out", twin=True)]


def _reproduced_with(scene: Scene, inputs: list, path, replacement) -> bool:
    """Whether the reference, with the argument at ``path`` replaced by ``replacement(argument)``, gives the
    student's value on every one of ``inputs``: False where the replacement is None (no such value) or the
    reference fails there."""
    for one in inputs:
        args = tuple(one.source.args)
        try:
            new = replacement(at(list(args), path))
        except (IndexError, KeyError, TypeError):
            return False
        if new is None:
            return False
        try:
            value = scene.reference_at(one.source.probe, replaced(args, path, new), one.source.path)
        except GraderFault:
            return False
        if value is None or value.shape != one.got.shape or not within(value, one.got, one.tol):
            return False
    return True


def _label(decl: Declaration | None, path) -> str:
    return label_of(decl, path) if decl is not None else f"argument {path[0] + 1}" + "".join(
        f"[{k!r}]" for k in path[1:])


def _keep(inputs: list, keys) -> list:
    """The hypotheses (keys) that reproduce the student's value on every input and give a value clearly other than
    the expected one, and clearly other than zero (which a loose tolerance lets a small value match), on one of them
    at least."""
    kept = []
    for key in keys:
        if not all(key in one.predicted for one in inputs):
            continue
        values = [one.predicted[key] for one in inputs]
        if not all(within(one.evidence.got, v, one.evidence.tol) for one, v in zip(inputs, values)):
            continue
        if not any(distinct(v, one.evidence.expected, one.evidence.tol) for one, v in zip(inputs, values)):
            continue
        if not any(distinct(v, np.zeros_like(v), one.evidence.tol) for one, v in zip(inputs, values)):
            continue
        kept.append(inputs[0].hypotheses[key])
    return kept


def _at_sheet_digits(scene: Scene, first: Evidence) -> bool:
    """True in the student kit where the expected value is one its key holds at the sheet's digits only (or comes
    from such a check's values): the engine's slips reproduce a value exactly, which those digits cannot tell."""
    if first.source is None:
        return bool(getattr(scene.ctx, "sheet_digits", False))
    held = getattr(scene.ctx.oracle, "held_at_sheet_digits", None)
    return held is not None and bool(held(first.source.probe, tuple(first.source.args)))


def find(scene: Scene, evidences: list, runs: bool = True) -> Finding | None:
    """The cause of a failing comparison (``evidences``: the input shown first); ``runs``: the run behind it is
    explained too (False for the engine's own comparisons of a run's right-hand side).  Where the student's value
    is derived from their results (no call of theirs holds it) and its expected value was traced to a call of the
    reference that explains nothing (a total mass found equal to the module's constant the check passed), the call
    the check judged is compared with the reference's, as for a value traced to no call (``judged``)."""
    finding = _find(scene, evidences, runs)
    first = evidences[0]
    if (finding is None or not finding.names) and _derived(first):
        trace.note("derived", traced=True)
        return _judged_derived(scene, first, finding)
    return finding


def _judged_derived(scene: Scene, evidence: Evidence, finding: Finding | None = None) -> Finding | None:
    """``judged`` for a value the check derived from the student's results, or ``finding`` where it finds none; in
    the kit, whose key may lack the call judged, ``finding`` is left to live, which may tell more."""
    try:
        return judged(scene, evidence) or finding
    except GraderFault:
        if getattr(scene.ctx.oracle, "mode", "") == "kit":  # the key lacks that call: live may tell more
            return _left_to_live(finding)
        raise


def _derived(evidence: Evidence) -> bool:
    """A value the check derived from the student's results whose expected value is traced to a call: the student's
    side to none, and no run or typed answer behind it."""
    return evidence.source is not None and evidence.student is None and evidence.call is None \
        and not evidence.typed and not is_run(evidence)


def _find(scene: Scene, evidences: list, runs: bool) -> Finding | None:
    if evidences[0].typed:  # a value typed into answers.toml: the output grammar alone, on its one input
        found = typed_slips(evidences[0])
        trace.note("typed", shape=list(evidences[0].expected.shape), found=[h.name for h in found])
        return _told([found], "here")
    for evidence in evidences:
        _sources(scene, evidence)
    first = evidences[0]
    if len(evidences) == 1:  # the same comparison at another point the check asked, where there is one
        other = sibling(getattr(scene.ctx, "calls", ()), first)
        evidences = evidences if other is None else [first, other]
    trace.note("evidence", inputs=len(evidences), source=_traced_source(first.source),
               student=_traced_source(first.student), call=first.call is not None, run=is_run(first),
               shape=list(first.expected.shape) if first.expected is not None else None)
    if _at_sheet_digits(scene, first):
        trace.note("sheet_digits")
        return None
    run = (first if is_run(first) else run_in_log(scene.ctx, first)) if runs else None
    found: list[Hypothesis] = []
    if run is not None:
        decl = Declaration(motion=run.motion) if run.motion else declaration(run.source.probe)
        model = _model(scene, run, decl)
        trace.note("model", state=model.state, finding=None if model.finding is None else list(model.finding.names))
        if model.state == "differs":  # the mistake is in the model: its cause, or none (never the integration)
            return model.finding
        integration = model.state == "agrees"
        found += run_slips(scene, run, decl, integration)
        second = evidences[1] if len(evidences) > 1 and is_run(evidences[1]) else None
        if found and second is not None:  # a randomized comparison's second failing run: the causes of both
            again = {h.key for h in run_slips(scene, second, decl, integration)}
            found = [h for h in found if h.key in again]
        start = next((h for h in found if h.key == START_KEY), None)
        if start is not None:
            made = _start_slips(run, decl, start.cost)
            if any(h.name == "float32" and not h.twin for h in made):  # the rounded start moved the whole run:
                found = [h for h in found if not h.key.startswith(OFFSET_KEY)]  # its offset is the start's
            found += made
    if run is not None:
        trace.note("run", found=[h.name for h in found])
    described = [] if run is not None else _described(scene, first)
    if described is None:  # the kit, without the reference's model: the graded submission may say more
        trace.note("model_slips", left_to_live=True)
        return _left_to_live(_told([found], "here") if found else None)
    if described:  # a value of the student's MuJoCo model: its differences from the reference's model
        trace.note("model_slips", found=[h.name for h in described])
    if first.source is None and first.student is None and first.call is None and not (found or described):
        # a value the check derived from the student's results (a centre of gravity of their points, an anchor's
        # first two coordinates): the call it judges, against the reference's call on the same arguments
        trace.note("derived")
        return _judged_derived(scene, first)
    if first.source is None:  # a value derived from the student's own: explain the results it came from
        if found or described or first.call is None:
            return _told([found, described], "in your model" if described else "here")
        return _from_results(scene, evidences)
    decl = declaration(first.source.probe)
    constants = constants_of(scene, decl, first.source.args)
    in_steps = stepped(decl)
    if len(evidences) == 1 and not (decl is not None and decl.motion):
        second = _second_input(scene, first)
        if second is not None:
            evidences = [first, second]
    elif len(evidences) == 1 and in_steps:
        first.alone = True  # a run of the student's own steps from the one start asked: its other states say more
    trace.note("inputs", count=len(evidences), declared=decl is not None,
               motion=bool(decl is not None and decl.motion), found_so_far=[h.name for h in found])
    inputs = [_predict(scene, e, constants) for e in evidences]
    if len(inputs) == 1:
        inputs[0] = _single(inputs[0])
    keys = list(inputs[0].predicted)
    outputs = _keep(inputs, [k for k in keys if not k.startswith(INPUT_KEYS)])
    if all(_same_shape(e) for e in evidences) and (len(inputs) > 1 or _told_enough(first)):
        outputs += _rounded(evidences, run, decl)  # a run's value as well: rounded only if so
    tiers = [found, outputs, _keep(inputs, [k for k in keys if k.startswith(INPUT_KEYS)]), term_slips(inputs),
             described]
    trace.note("grammar", hypotheses=len(inputs[0].predicted), found=[h.name for tier in tiers for h in tier])
    explained = any(tiers)
    unreached = []
    tiers.append(_heard(lambda: _ignored(scene, evidences, unreached), explained, "ignored"))
    if not (decl is not None and decl.motion) or in_steps:  # slips inside a formula: the last tier
        # an array argument ignored is told only beside another explanation (``_beside``): alone it explains
        # nothing, and the formula tier is heard in full
        explaining = _without_arrays_ignored(tiers)
        told = {DIAGNOSES[h.name].family for tier in explaining for h in tier} if any(explaining) else None
        untested = not (_testable(first) and ignore_candidates(decl, first.source.args))
        try:
            formulas = _heard(lambda: mutant_slips(scene, evidences + _siblings(evidences),
                                                   lambda: _second_input(scene, evidences[-1], constants=True),
                                                   told, untested, tuple(unreached)),
                              any(explaining), "formulas")
        except Contested:  # rivals of the earlier explanation, of too many families to tell
            return None
        formulas = _unscaled(_told_apart(formulas), evidences)
        if not formulas and left_to_live(scene, evidences):
            tiers = _beside(tiers)
            return _left_to_live(_told(tiers, _where(evidences)) if any(tiers) else None)
        tiers.append(formulas)
    return _told(_beside(tiers), _where(evidences))


def _rounded(evidences: list, run: Evidence | None, decl: Declaration | None) -> list:
    """The slips of precision (``precision_slips``: float32, a rounding) that give the student's value on every input
    of the comparison, as every tier is held to them; none for a time of the student's own output grid
    (``_on_its_grid``), which the grid's spacing rounds."""
    if _on_its_grid(run, decl, evidences[0]):
        return []
    each = [precision_slips(e.got, e.expected, e.tol) for e in evidences]
    return [h for h in each[0] if all(h.key in {o.key for o in other} for other in each[1:])]


def _on_its_grid(run: Evidence | None, decl: Declaration | None, evidence: Evidence) -> bool:
    """The student's value is a time of their run's own output grid (``decl.motion``'s times), or of that grid
    extended at its spacing (past a run that ended at its event): a time read off the grid where the run's own time
    belongs (an event's), which a rounding matches by the grid's spacing."""
    motion = (run.motion if run is not None and run.motion else decl.motion if decl is not None else None) or {}
    root = run.student.root if run is not None and run.student is not None else None
    if not isinstance(motion.get("time"), str) or not isinstance(root, dict) or evidence.got is None:
        return False
    times = array_of(root.get(motion["time"]))
    if times is None or times.ndim != 1 or times.size < 2 or evidence.got.size != 1:
        return False
    value, steps = float(evidence.got.ravel()[0]), np.diff(times)
    scale = 1e-9 * max(1.0, float(np.abs(times).max()), abs(value))
    if np.any(np.abs(times - value) <= scale):
        return True
    if steps.min() <= 0 or np.ptp(steps) > 1e-9 * steps.mean():  # no even grid to extend
        return False
    k = (value - times[0]) / steps.mean()  # a time of the grid beyond its last (a run ended at its event)
    return abs(k - round(k)) * steps.mean() <= scale


def _start_slips(run: Evidence, decl: Declaration, cost: int) -> list:
    """What made a run start from another state than the given one: a start that differs (``START_KEY``) is what
    the answer shows, and the grammar's slips of a value (``output_slips``: entries exchanged, a sign, a factor,
    degrees; ``precision_slips``: the start rounded) that give the student's start from the given one say what
    produced it.  Each is told beside the start that differs, at its ``cost``: the start is wrong, and so made.  The
    start is one value, so it must say enough of its slip (``numbers_told``, ``ONE_INPUT_NUMBERS``) to be told as
    what made it; where it says fewer numbers (one angle typed with the wrong sign, two rates exchanged) the slip
    is told as a twin of the wrong start, "could be" either: a start wrong in a number or two is as truly that
    number's slip, and a twin is left out where it would take the families told past ``MAX_FAMILIES``."""
    aligned = aligned_runs(run, decl)
    if aligned is None:
        return []
    t, G, R, t_r, _ = aligned
    keys = [k for k in decl.motion.get("states", ()) if k in G and abs(t[0] - t_r[0]) < 1e-9]
    if not keys:
        return []
    got = np.concatenate([np.ravel(G[k][0]) for k in keys])
    E = np.concatenate([np.ravel(R[k][0]) for k in keys])
    told = numbers_told(got, E, run.tol) if np.all(np.isfinite(got)) else 0
    if not told:
        return []
    few = told < ONE_INPUT_NUMBERS
    slips = value_slips(got, E, run.tol)
    if not slips:  # one state rounded (a rotation matrix in float32 beside rates in float64): that state's start
        slips = [h for h in _rounded_states(G, R, keys, run.tol) if h.name == "float32"]
    trace.note("start", found=[h.name for h in slips], numbers=told)
    # a start in float32 stands on every entry's bits (each one exact in single precision), not on the numbers it
    # says beyond the tolerance
    return [Hypothesis(f"{START_KEY}:{h.key}", h.name, cost, f"your run's start is the given one changed so: "
                       f"{h.detail}", twin=few and h.name != "float32") for h in slips]


def _rounded_states(G: dict, R: dict, keys: list, tol: Tol) -> list:
    """The rounding slips (``precision_slips``) of the run's start in one of its states ``keys`` (the student's
    ``G``, the reference's ``R``) that differs, every other state's start within the tolerance."""
    starts = [(np.asarray(G[k][0], dtype=float), np.asarray(R[k][0], dtype=float)) for k in keys]
    off = [(mine, theirs) for mine, theirs in starts if not within(mine, theirs, tol)]
    if len(off) != 1:
        return []
    (mine, theirs), = off
    return precision_slips(mine, theirs, tol) if mine.shape == theirs.shape and np.all(np.isfinite(mine)) else []


def value_slips(got, given, tol: Tol) -> list:
    """The grammar's slips of one value (``output_slips``: entries exchanged, a sign, a factor, degrees;
    ``precision_slips``: rounded; every number cut to a whole one, an integer dtype) that give the student's ``got``
    from the ``given`` one, each a hypothesis: what made a start typed wrongly, say.  Told beside the wrong value, never
    as its only cause where it says fewer than ``ONE_INPUT_NUMBERS`` numbers."""
    got, given = np.asarray(got, dtype=float), np.asarray(given, dtype=float)
    if got.shape != given.shape or not np.all(np.isfinite(got)):
        return []
    whole = np.trunc(given)  # ``np.asarray(y0, dtype=int)``: every number cut to a whole one
    truncated = [Hypothesis("truncated", "integer_truncated", 1, "your values are the given ones cut to whole numbers "
                            "(converted with an integer dtype, ``dtype=int``): keep them as floats")] \
        if within(got, whole, tol) and distinct(whole, given, tol) else []
    return precision_slips(got, given, tol) + truncated + [
        h for h, value in output_slips(given, {}, None, got)
        if not h.twin and value.shape == got.shape and within(got, value, tol) and distinct(value, given, tol)]


#: the unlike slips of the formula tier that may reproduce one answer on every input and still be told: more say
#: that the inputs cannot tell causes apart
MAX_UNLIKE = 2
#: the names of two things exchanged (entries, arguments, factors, a quantity and its rate, rows of a state): an
#: exchange reproduces an answer only where the two exchanged are the two that differ, so exchanges found in
#: several places are readings of one slip, not a sign of inputs that cannot tell causes apart
EXCHANGES = frozenset({"swapped", "argument_order", "factor_order", "state_row"})


def _told_apart(formulas: list) -> list:
    """The formula tier's hypotheses, or none where more than ``MAX_UNLIKE`` unlike slips (names, twins and
    exchanges aside) of more than one family reproduce the answer on every input: many unlike edits giving one value
    is a sign that the inputs cannot tell causes apart (a term whose size dwarfs the tolerance on none of them, that
    a factor left out, a ratio upside down and a product for a division all make vanish alike), not that each is a
    reading of the slip.  Unlike names of one family (entries, arguments or names exchanged) tell one family still,
    and exchanges (``EXCHANGES``: the desired rates and accelerations exchanged as two entries, two arguments and a
    quantity read for its rate) are not counted."""
    names = {h.name for h in formulas if not h.twin and h.name not in EXCHANGES}
    if len(names) > MAX_UNLIKE and len({DIAGNOSES[name].family for name in names}) > 1:
        trace.note("unlike", names=sorted(names))
        return []
    return formulas


def _unscaled(formulas: list, evidences: list) -> list:
    """The formula tier's hypotheses, with a term left out told beside a factor left out of a product
    (``missing_factor``, a slip of scale) where the student's value is no multiple of the expected one on some input
    (``_multiple``): a factor that is a number (a step, a density) scales the answer, while one that is a quantity of
    the formula of its own (the cosine of an angle in some entries, an inverse mass matrix) leaves a part of the
    formula out, which is a term missing as truly.  A twin, told only where the families stay within
    ``MAX_FAMILIES``."""
    factors = [h for h in formulas if h.name == "missing_factor" and not h.twin]
    if not factors or all(_multiple(e) for e in evidences):
        return formulas
    return formulas + [Hypothesis(f"{h.key}=unscaled", "missing_term", h.cost,
                                  f"{h.detail}, and your value is no multiple of the expected one: the factor is a "
                                  "quantity of the formula, a part of it missing", twin=True) for h in factors]


def _multiple(evidence: Evidence) -> bool:
    """Whether the student's value is a multiple of the expected one (within the tolerance), or cannot tell: a
    number, another shape, or an expected value of zeros."""
    got, expected = evidence.got, evidence.expected
    if got is None or expected is None or got.shape != expected.shape or got.size < 2:
        return True
    e, g = np.ravel(expected).astype(float), np.ravel(got).astype(float)
    if not (np.all(np.isfinite(e)) and np.all(np.isfinite(g))) or not np.any(e):
        return True
    return within(got, (g @ e) / (e @ e) * expected, evidence.tol)


def _described(scene: Scene, evidence: Evidence) -> list | None:
    """The model tier (``models.model_slips``); where it runs out of reference calls, nothing of it."""
    try:
        return model_slips(scene, evidence)
    except Budget as exc:
        trace.note("heard", tier="model", stopped=str(exc)[:80])
        return []


def _beside(tiers: list) -> list:
    """The tiers, where a value that does not follow an array argument (a vector, a rotation, masses) is told only
    beside another tier's explanation, as a twin is (``_told``): alone it may be a term left out that carried all
    of the value's dependence on that argument (a rolling joint's translation left out leaves a velocity that no
    angle changes), which is no argument ignored, and where it would take the families told past
    ``MAX_FAMILIES`` it is left out rather than nothing named (a pendulum's Jacobian that no angle changes, beside
    a sign and a term that each reproduce it).  A number ignored, or every argument (a constant answer), is a
    tier's explanation as any other; so, where no other tier explains the answer, is an array ignored whose value
    is the reference's with the array zero (``_zeroed``), told with the terms it makes left out: both readings."""
    others = [tier for tier in tiers if not any(h.key.startswith(IGNORED_KEYS) for h in tier)]
    simplest = [h for tier in others if tier for h in tier if h.cost == min(g.cost for g in tier) and not h.twin]
    families = {DIAGNOSES[h.name].family for h in simplest}
    if simplest and len(families | {DIAGNOSES["ignored_argument"].family}) <= MAX_FAMILIES:
        return tiers
    return _without_arrays_ignored(tiers, zeroed=not simplest)


def _without_arrays_ignored(tiers: list, zeroed: bool = False) -> list:
    """The tiers without their hypotheses of an array argument ignored (``IGNORED_ARRAY``); with ``zeroed``, but
    those with their twin of the array zero (``_zeroed``: the terms it makes left out) and that twin."""
    def kept(tier):
        pairs = {h.key[:-len(ZEROED)] for h in tier if h.key.endswith(ZEROED)}
        return [h for h in tier if not h.key.startswith(IGNORED_ARRAY)
                or zeroed and (h.key in pairs or h.key.endswith(ZEROED))]

    return [kept(tier) for tier in tiers]


def _where(evidences: list) -> str:
    return "on the input shown and on a second one" if len(evidences) > 1 else "here"


def _left_to_live(finding: Finding | None) -> Finding:
    """The student kit's finding where the graded submission would also hear the formula tier, which the kit
    cannot (it holds no reference code): no name, since a slip inside a formula may reproduce the answer as well
    and be told beside it, and the hint of what the kit's own tiers found, with the note that the graded
    submission may say more."""
    if finding is None or not finding.names:
        return Finding((), KIT_NOTE)
    return Finding((), f"{finding.hint}\n{KIT_NOTE}")


#: the keys of the input tier's hypotheses (``grammar.input_slips``): the reference on transformed arguments
INPUT_KEYS = "in:"
#: the keys of the test of an ignored argument: a number ignored (or every argument), an array ignored
IGNORED_ARRAY = "ignored-array:"
IGNORED_KEYS = ("ignored:", IGNORED_ARRAY)
#: the end of the key of an argument ignored's twin of the argument zero (``_zeroed``)
ZEROED = "=zeroed"


def _heard(ask, explained: bool, tier: str) -> list:
    """The hypotheses of a later tier, asked whether or not an earlier one explained the answer (``explained``): a
    slip that two tiers reproduce alike is told with both families.  Where an earlier tier explained it, a later
    tier that runs out of its budget leaves the earlier finding standing (as it stood before the later was heard);
    where none did, the budget ends the explanation (``Budget``)."""
    if not explained:
        return ask()
    try:
        found = ask()
    except Budget as exc:
        trace.note("heard", tier=tier, stopped=str(exc)[:80])
        return []
    trace.note("heard", tier=tier, found=[h.name for h in found])
    return found


def _traced_source(source: Source | None):
    return None if source is None else {"probe": source.probe, "path": list(source.path)}


@dataclass(frozen=True)
class _Model:
    """What the engine knows of the model behind a run: ``state`` "agrees" (the student's right-hand side is the
    reference's along the run, or the run declares none to doubt), "differs" (with the cause found on the
    right-hand sides, or None) or "unknown" (the student's could not be evaluated)."""

    state: str
    finding: Finding | None = None


def _model(scene: Scene, run: Evidence, decl: Declaration) -> _Model:
    """The differential between the model and the integration of a failing run: the student's right-hand side
    against the reference's at states along the reference's run (``runs.model_evidences``)."""
    if not decl.motion.get("rhs"):
        return _Model("agrees")
    try:
        evidences = model_evidences(scene, run, decl)
    except GraderFault:
        evidences = None
    if evidences is None:
        return _Model("unknown")
    if all(within(e.got, e.expected, e.tol) for e in evidences):
        return _Model("agrees")
    finding = find(scene, evidences, runs=False)
    e = next(e for e in evidences if not within(e.got, e.expected, e.tol))
    i = int(np.argmax(np.max(np.abs(e.got - e.expected) - e.tol.rtol * np.abs(e.expected), axis=-1)))
    t, y = e.source.args[-1][i]
    where = (f"Your right-hand side differs from the reference's at states along its run (at t = {t:.4g} s, "
             f"y = {format_array(y)}: yours {format_array(e.got[i])}, expected {format_array(e.expected[i])}), so "
             "the mistake is in the model, not in the integration.")
    if finding is None:
        return _Model("differs", Finding((), where))
    return _Model("differs", Finding(finding.names, f"{where} {finding.hint}"))


def rivalled(scene: Scene, evidence: Evidence, diagnosis: str) -> Finding | None:
    """The rivals of another family of a check's ``diagnosis`` told from what its value shows (a sign), on the
    failing comparison ``evidence`` and a second input where the engine draws one (``mutants.opposite_slips``):
    the check's name and theirs, "could be" either; None where none reproduces the student's value, or where rivals
    of two families do (with the check's, three: the check's name stands alone).  A value the check derived from the
    student's results (``J @ qdd`` of their ``qdd``), which no call holds, is explained by the results of the call it
    came from (``judged_call``) that differ from the reference's: a rival is told where every such result names it."""
    _sources(scene, evidence)
    if evidence.got is None:
        return None
    if evidence.source is not None:
        rivals = _rivals(scene, evidence, diagnosis)
    else:
        judged_ = _judged_results(scene, evidence, evidence.tol)
        if judged_ is None:
            trace.note("rival", reason="no call behind the derived value")
            return None
        found = [_rivals(scene, result, diagnosis) for result in list(judged_[1].values())[:RESULT_LEAVES]]
        agreed = found and all(found) and all(set(found[0].names) <= set(f.names) for f in found)
        rivals = found[0] if agreed else None
    if rivals is None:
        return None
    said = " or ".join(DIAGNOSES[n].student for n in rivals.names)
    return Finding((diagnosis, *rivals.names),
                   f"Could be {DIAGNOSES[diagnosis].student} or, as well, {said}, whose effect it is.\n{rivals.hint}")


def _rivals(scene: Scene, evidence: Evidence, diagnosis: str) -> Finding | None:
    """``rivalled``'s rivals on one comparison with a reference call behind it: the cheapest, of one family."""
    evidences = [evidence]
    second = _second_input(scene, evidence)
    if second is not None:
        evidences.append(second)
    trace.note("inputs", count=len(evidences), declared=declaration(evidence.source.probe) is not None,
               motion=False, found_so_far=[diagnosis])
    found = opposite_slips(scene, evidences, DIAGNOSES[diagnosis].family)
    if not found:
        return None
    cost = min(h.cost for h in found)
    cheapest = [h for h in found if h.cost == cost]
    families = {DIAGNOSES[h.name].family for h in cheapest}
    if len(families) > 1:  # rivals of two families: with the check's, three
        trace.note("rivals", families=sorted(families))
        return None
    return _finding(cheapest, _where(evidences))


def doubted(scene: Scene, evidence: Evidence) -> Finding | None:
    """Where a check blames the integration of the run behind ``evidence``: the engine's finding when that run's
    right-hand side is not the reference's (its cause, or with no name what differs), else None."""
    if evidence is None:  # a failure stated in words: the check's last run
        evidence = Evidence(np.zeros(0), np.zeros(0), RHS_TOL, "the run")
    else:
        _sources(scene, evidence)
    run = evidence if is_run(evidence) else run_in_log(scene.ctx, evidence)
    if run is None:
        return None
    decl = Declaration(motion=run.motion) if run.motion else declaration(run.source.probe)
    model = _model(scene, run, decl)
    return model.finding if model.state == "differs" else None


#: the results of a call judged by a property that the engine compares with the reference's, at most
RESULT_LEAVES = 3


def _leaves(value, path=()):
    """``(path, array)`` of the numeric arrays of a probe's result, outermost first (a list of numbers is one)."""
    if isinstance(value, dict):
        for key, item in value.items():
            yield from _leaves(item, (*path, key))
        return
    array = None if isinstance(value, str) else array_of(value)
    if array is not None and array.size:
        yield path, array
    elif isinstance(value, (list, tuple)) and len(value) <= 64:
        for index, item in enumerate(value):
            yield from _leaves(item, (*path, index))


def _result_evidences(evidence: Evidence) -> dict:
    """``{path: Evidence}``: the results of ``evidence.call`` (not a run's) that differ from the reference's beyond
    the comparison's tolerance."""
    if evidence.call is None:
        return {}
    probe, args, got_root, expected_root = evidence.call
    decl = declaration(probe)
    if decl is not None and decl.motion and not stepped(decl):
        return {}
    found = {}
    for path, expected in _leaves(expected_root):
        got = array_of(at(got_root, path))
        if got is None or got.shape != expected.shape or within(got, expected, evidence.tol):
            continue
        label = " ".join(str(k) for k in path if isinstance(k, str)) or "result"
        found[path] = Evidence(got, expected, evidence.tol, label, None, None,
                               Source(probe, tuple(args), path, expected_root),
                               Source(probe, tuple(args), path, got_root))
    return found


def _from_results(scene: Scene, evidences: list) -> Finding | None:
    """The cause of a failing property of values derived from a call's results (``Evidence.call``): each result
    that differs from the reference's on both failing inputs (on one, where the check has no second: on it and on
    the engine's own second input) is explained as a comparison of its own, and the causes that every result
    explained names are named (one result's "could be X or Y" beside another's "X" is X), with the hints of the
    results that name those alone.  A run counted in steps is such a call too (``evidence.stepped``: its results are the
    states the student's own step gives)."""
    first = _result_evidences(evidences[0])
    second = _result_evidences(evidences[1]) if len(evidences) > 1 else None
    findings, left = [], False
    for path in [path for path in first if second is None or path in second][:RESULT_LEAVES]:
        # on one failing input, each result on it and on the engine's own second input (``find`` draws it)
        finding = find(scene, [first[path]] if second is None else [first[path], second[path]])
        if finding is not None and finding.names:
            findings.append((first[path].name, finding))
        left = left or (finding is not None and not finding.names and KIT_NOTE in finding.hint)
    if left:  # the student kit: a result left to the graded submission's formula tier, which may say more
        return Finding((), KIT_NOTE)
    return _agreed(findings)


def _agreed(findings: list, labelled: bool = True) -> Finding | None:
    """The causes that every result's finding (``(label, finding)``) names, with the hints of the results that name
    those alone (all, where none does), each after its label; None where they share none.  One result alone is told
    as it was found where not ``labelled``."""
    common = [name for name in findings[0][1].names if all(name in f.names for _, f in findings)] if findings else []
    if not common:
        return None
    if len(findings) == 1 and not labelled:
        return findings[0][1]
    exact = [(label, f) for label, f in findings if list(f.names) == common] or findings
    hint = "\n".join(f"Your {label}: {finding.hint[:1].lower()}{finding.hint[1:]}" for label, finding in exact)
    return Finding(tuple(common), hint)


#: the tolerance of the comparison the engine makes itself where a check judged the student's value by a property
#: and named a symptom (``judged``): the student's call against the reference's on the same arguments
JUDGED_TOL = Tol("the reference's value of the same call", 1e-8, 1e-8)


def judged(scene: Scene, evidence: Evidence | None) -> Finding | None:
    """Where a check judged the student's value by a property and said its symptom (a matrix that is not
    orthonormal, a body in the wrong orientation), the cause behind it: the student's call the value came from
    (``judged_call``) compared with the reference's call on the same arguments, each result that differs explained
    as a failing comparison of its own (on the input shown and the engine's own second input), and a cause named
    where the results explained agree on it; None otherwise.  ``evidence``: the failure's comparison, if any (the
    value it holds tells the call; its tolerance is the comparison's)."""
    if evidence is not None and evidence.typed:  # a typed answer judged by a property: its key stands beside it
        return find(scene, [evidence])
    tol = evidence.tol if evidence is not None and isinstance(evidence.tol, Tol) else JUDGED_TOL
    judged_ = _judged_results(scene, evidence, tol)
    if judged_ is None:
        trace.note("judged", reason="no declared call")
        return None
    call, results = judged_
    trace.note("judged", probe=call.probe, differs=[list(map(str, path)) for path in results])
    findings, left = [], False
    for path in list(results)[:RESULT_LEAVES]:
        finding = find(scene, [results[path]])
        if finding is not None and finding.names:
            findings.append((results[path].name, finding))
        left = left or (finding is not None and not finding.names and KIT_NOTE in finding.hint)
    if left:
        return Finding((), KIT_NOTE)
    return _agreed(findings, labelled=False)


def _judged_results(scene: Scene, evidence: Evidence | None, tol) -> tuple[Source, dict] | None:
    """``(call, results)``: the student's call behind a value a check judged (``judged_call``) and those of its
    results that differ beyond ``tol`` from the reference's call on the same arguments (``_result_evidences``); None
    where no such call is known."""
    call = judged_call(getattr(scene.ctx, "calls", ()), evidence)
    if call is None:
        return None
    expected_root = scene.reference(call.probe, call.args)
    return call, _result_evidences(Evidence(np.zeros(0), np.zeros(0), tol, "the result",
                                            call=(call.probe, call.args, call.root, expected_root)))


def judged_call(log, evidence: Evidence | None) -> Source | None:
    """The student's probe call (not a run's, but for one counted in steps) behind a value a check judged: the call of
    the failure's comparison (``Evidence.call``), else the call whose result holds the compared value, else the last
    probe call the check made of the student's code (the check judges what it asked last); None."""
    if evidence is not None and evidence.call is not None:
        probe, args, got_root, _ = evidence.call
        return Source(probe, tuple(args), (), got_root) if _judgeable(probe) else None
    if evidence is not None:
        found = locate(log, evidence.raw_got, "student")
        if found is not None and _judgeable(found.probe):
            return Source(found.probe, found.args, (), found.root)
    for side, probe, args, value in reversed(log):
        if side == "student" and _judgeable(probe):
            return Source(probe, tuple(args), (), value)
    return None


#: the probe by which the grader calls a student's function of an earlier problem to judge a value on what the
#: reference's code makes of it (``grader.upstream``): a question of the grader's, not the check's of the student
UPSTREAM_PROBE = "_upstream.call"


def _judgeable(probe) -> bool:
    """A probe whose call the engine may compare with the reference's: one it knows by name (``probes``), not a
    run's (whose comparison is the checks' own) but one counted in steps (``evidence.stepped``: the student's own step
    called again and again, whose states a formula's slip gives exactly), nor the grader's own call of an earlier
    problem's function (``UPSTREAM_PROBE``)."""
    if not isinstance(probe, str) or probe == UPSTREAM_PROBE:
        return False
    decl = declaration(probe)
    if decl is None:
        try:
            lookup(probe)
        except ProbeLookupError:
            return False
        return True
    return not decl.motion or stepped(decl)


def _same_shape(evidence: Evidence) -> bool:
    return evidence.got.shape == evidence.expected.shape


def _single(one: _Input) -> _Input:
    """With a single input (nothing to draw), only hypotheses whose value is clearly another than the expected one
    are kept: a near-degenerate input tells little.  Nor a slip of a number's size (``BY_CHANCE``) where the value
    says too few numbers of its slip (``_told_enough``)."""
    ev = one.evidence
    enough = _told_enough(ev)
    for key in list(one.predicted):
        chance = not enough and DIAGNOSES[one.hypotheses[key].name].family in BY_CHANCE
        if chance or not distinct(one.predicted[key], ev.expected, ev.tol):
            del one.predicted[key]
    return one


#: the families of the slips that a number or two of an array match by chance: a factor (quantities of a problem
#: stand in simple ratios, a full length and a half) and a rounding
BY_CHANCE = ("scale", "precision")


def _told_enough(evidence: Evidence) -> bool:
    """Whether an array the engine has on one input only differs in enough entries for a slip of a number's size
    (``BY_CHANCE``) found on it to be told (``ONE_INPUT_NUMBERS`` entries, as many as a run's start must say): an
    array whose difference lies in one or two entries among zeros (a joint's one offset twice its length) has its
    shape right and those entries wrong, which a factor matches by chance whatever made them.  A single number is
    the whole answer, and a factor or a rounding of it is told as before."""
    got, expected = evidence.got, evidence.expected
    if expected is None or got is None or np.size(expected) < 2 or np.shape(got) != np.shape(expected):
        return True
    off = int(np.count_nonzero(np.abs(got - expected) > evidence.tol.atol + evidence.tol.rtol * np.abs(expected)))
    if off < ONE_INPUT_NUMBERS:
        trace.note("single", entries=off)
    return off >= ONE_INPUT_NUMBERS


#: the families a finding may span, at most: past them, that many causes fit the answer alike and none is told
MAX_FAMILIES = 2


def _told(tiers: list, where: str) -> Finding | None:
    """The finding of the tiers heard (``tiers``: the hypotheses of each, in the engine's order): the simplest of
    each tier, all of them told ("could be X or Y"), or None where they span more than ``MAX_FAMILIES`` families.
    A twin (the same value as another slip by mathematics, ``grammar.EQUIVALENCES``) is told beside its slip where
    the families stay within ``MAX_FAMILIES``, and left out where they would not: it adds a name, not an
    explanation, and never makes the engine name nothing.
    Within a tier the simplest outranks the others (its costs rank slips of one kind, on the same inputs); across
    tiers no cost outranks a rival that reproduces the answer on the same inputs (see the package's map)."""
    told = []
    for tier in tiers:
        if tier:
            cost = min(h.cost for h in tier)
            told += [h for h in tier if h.cost == cost and h not in told]
    if not told:
        return None
    told = _specific(told)
    seen = [h for h in told if not h.twin]
    families = {DIAGNOSES[h.name].family for h in seen}
    if len(families) > MAX_FAMILIES:
        trace.note("rivals", families=sorted(families))
        return None
    if len(families | {DIAGNOSES[h.name].family for h in told}) > MAX_FAMILIES:  # a twin adds no explanation
        trace.note("twins", dropped=[h.name for h in told if h.twin])
        told = seen
    return _finding(told, where)


def _specific(told: list) -> list:
    """``told`` without a hypothesis of a family's own name (``missing_term``) beside one of a name of that family
    that says more (``missing_f``: which term): the second is the first, told more closely."""
    named = {DIAGNOSES[h.name].family for h in told if h.name != DIAGNOSES[h.name].family}
    return [h for h in told if h.name != DIAGNOSES[h.name].family or h.name not in named]


def _finding(found: list, where: str) -> Finding | None:
    """The hypotheses told (``_told``), by name, and the hint that says what they are and where they hold."""
    if not found:
        return None
    by_name: dict[str, list[Hypothesis]] = {}
    for h in found:
        by_name.setdefault(h.name, []).append(h)
    names = tuple(by_name)
    if len(names) == 1:
        name = names[0]
        details = "; ".join(dict.fromkeys(h.detail for h in by_name[name]))
        hint = f"Looks like {DIAGNOSES[name].student}: {details}. This reproduces your answer {where}."
        return Finding(names, hint)
    lines = [f"- {DIAGNOSES[name].student}: {'; '.join(dict.fromkeys(h.detail for h in hs))}"
             for name, hs in by_name.items()]
    hint = (f"Could be {' or '.join(DIAGNOSES[n].student for n in names)}: each reproduces your answer {where}.\n"
            + "\n".join(lines))
    return Finding(names, hint)


def recording(ctx) -> None:
    """While the kit's answer key is recorded, every comparison of a declared probe's value makes the engine's
    reference calls for it (``prepare``); ``ctx`` is the recording context of the check that runs (None: none)."""
    RECORDING.ctx = ctx


def note_comparison(ctx, expected, tol: Tol | None = None, got=None) -> None:
    """A comparison of ``got`` with ``expected`` (within ``tol``) is made while the key is recorded: prepare the
    engine's calls for the probe call it came from, found as ``explain`` finds it (the calls of declared probes are
    searched first; a printed value is traced through the student's call, ``traced``; a value of another probe's
    call gets the engine's second input only)."""
    calls = getattr(ctx, "calls", ())
    declared = [entry for entry in calls if declaration(entry[1]) is not None]
    source = locate(declared, expected, "reference", tol if isinstance(tol, Tol) else None) if declared else None
    if source is None and got is not None and isinstance(tol, Tol) and declared:
        student = locate(declared, got, "student") or evaluated(declared, got, tol)
        if student is not None:
            try:
                source = traced(Scene(ctx), student, expected, tol)
            except (Budget, GraderFault):
                source = None
    if source is None:
        source = locate(calls, expected, "reference", tol if isinstance(tol, Tol) else None)
        if source is None or declaration(source.probe) is not None:
            return
    seen = ctx.__dict__.setdefault("_engine_prepared", set())
    key = call_key(source.probe, source.args)
    if key in seen:
        return
    seen.add(key)
    prepare(ctx, source, tol if isinstance(tol, Tol) else None)


def prepare_call(ctx, probe: str, args: tuple) -> None:
    """While the key is recorded: the results of a call that a randomized comparison judges by its own ``compare``
    may be explained against the reference's (``Evidence.call``): make the engine's calls for it."""
    if declaration(probe) is None or declaration(probe).motion:
        return
    key = call_key(probe, args)
    seen = ctx.__dict__.setdefault("_engine_prepared", set())
    if key not in seen:
        seen.add(key)
        prepare(ctx, Source(probe, tuple(args), ()))


def prepared(ctx, probe: str, args: tuple) -> None:
    """While the key is recorded: a run (a probe that declares ``motion``) is compared by the checks' own code
    rather than a comparison of its value, so the engine's calls for it are made as soon as it is asked for."""
    decl = declaration(probe)
    if decl is None or not decl.motion:
        return
    key = call_key(probe, args)
    seen = ctx.__dict__.setdefault("_engine_prepared", set())
    if key not in seen:
        seen.add(key)
        prepare(ctx, Source(probe, tuple(args), ()))


def prepare(ctx, source: Source, tol: Tol | None = None) -> None:
    """Make every reference call the engine may need to explain a failing comparison with a value of ``source``'s
    call: its inputs transformed, its terms, the problem's constants, and a second input drawn with its own
    variants (the kit's key then holds them; ``tol``: the comparison's, which tells a usable draw)."""
    decl = declaration(source.probe)
    scene = Scene(ctx)

    def ask(probe, args, persist=False):
        """A call the engine may make; where the reference refuses the transformed input (a number that breaks
        its preconditions), the engine skips that hypothesis, here and when it explains."""
        try:
            return scene.reference(probe, args, persist=persist)
        except GraderFault:
            return None

    try:
        if decl is not None:
            _prepare_declared(scene, ask, decl, source)
        else:  # the test of an ignored argument changes the numbers of a probe that declares nothing
            for args in perturbations(None, source.args):
                ask(source.probe, args)
            terms = terms_call(None, source)  # those of the cheaper call that holds the value
            if terms is not None:
                ask(*terms)
        if not (decl is not None and decl.motion) and not getattr(ctx, "randomized", False):
            root = source.root if source.root is not None else ask(source.probe, source.args)
            expected = array_of(at(root, source.path))
            drawn = None if expected is None else _drawn(scene, source, expected, tol or SECOND_TOL)
            drawn = None if drawn is ALONE else drawn
            if drawn is not None:
                for args in perturbations(decl, drawn[0]):
                    ask(source.probe, args)
            if drawn is not None and decl is not None:
                for _, variant in input_slips(decl, drawn[0]):
                    ask(source.probe, variant)
            terms = None if drawn is None else terms_call(decl, Source(source.probe, tuple(drawn[0]),
                                                                          tuple(source.path)))
            if terms is not None:
                ask(*terms)
    except (Budget, GraderFault):
        pass


#: the tolerance that tells a usable second input while the key is recorded, for a comparison that gives none
SECOND_TOL = Tol("drawn", 1e-9, 1e-9)


def _prepare_declared(scene: Scene, ask, decl: Declaration, source: Source) -> None:
    """The calls of a declared probe's slips, terms, constants, fixed steps, right-hand sides and parameters."""
    constants_of(scene, decl, source.args)
    for _, args in input_slips(decl, source.args):
        ask(source.probe, args)
    for args in perturbations(decl, source.args):
        ask(source.probe, args)
    terms = terms_call(decl, source)
    if terms is not None:
        ask(*terms)
    if decl.motion.get("fixed_step"):
        for scheme in decl.motion.get("schemes", ("euler",)):
            for h in decl.motion.get("steps", FIXED_STEPS):
                ask(decl.motion["fixed_step"], (*source.args, h, scheme), persist=True)
    if decl.motion.get("rhs"):
        _prepare_model(ask, decl, source)
    if decl.motion.get("parameters") or decl.motion.get("start") or decl.motion.get("parts"):
        for _, args in parameter_variants(decl.motion, tuple(source.args), *variant_sheets(ask, decl.motion)):
            ask(source.probe, args, persist=True)


def _prepare_model(ask, decl: Declaration, source: Source) -> None:
    """The reference's right-hand side at the states along its run that ``_model`` compares (and its terms)."""
    root = source.root if source.root is not None else ask(source.probe, source.args)
    halves = rhs_cases(root, decl.motion) if root is not None else None
    rhs = declaration(decl.motion["rhs"])
    for cases in halves or ():
        args = rhs_call(decl.motion, tuple(source.args), cases)
        ask(decl.motion["rhs"], args)
        if rhs is not None and rhs.terms:
            ask(rhs.terms, args)
