"""Error carried forward across problems: a later problem's answer judged on the student's own functions of earlier
problems.

Problem 8's steps use the student's ``R3``, ``cardan`` and ``skew`` (problems 6 and 7); a tree's recursion (problem
24) uses their ``R3``; problem 44's run uses their ``accelerations`` of problem 43.  When one of those functions is
wrong, its own check fails (its points are lost there), and every later answer built on it differs from the
reference's even where the later code is right.  ``assert_close_judged`` compares the student's answer with the
reference's and, where they differ, with what the *reference's* code of the later problem gives on the *student's*
shared functions (``grader.upstream``): when the answer matches that, the check passes with full credit and points
at the check that finds the mistake; when it does not, it fails against that value and says so.  Credit is carried
forward only where the student's values are real (``flaw``, the rule of ``checks._real``): an upstream function
that returns zeros, a constant, NaN, a matrix that is not orthonormal or the identity where the reference's turns
gives nothing to carry.

Within a problem it is the same: problem 8's Cardan step and its part (b) use the student's own
``cardan_rate_matrix``, which ``p08.rate_matrix`` grades, and are judged on it.  A shared function is never
carried into the check that grades it (``p08.exponential_step`` compares the student's step, built on their
``expm_skew``, with the reference's).

``SHARED`` lists the shared functions (``"module.function"``), with the problem that owns each (its solution
region) and the check that grades it; a test holds it to the reference's regions.  The student kit cannot compose
the reference's code with the student's functions: where they differ it leaves the check to the graded
submission, naming the function and its check.
"""

import numpy as np

from grader.checking import CheckFailure, Tol, assert_close, close, is_rotation
from grader.problems import check_title
from grader.upstream import COULD_NOT_USE

from ._real import flaw as real_flaw
from ._real import rotation_flaw

__all__ = ["SHARED", "flaw", "judged", "assert_close_judged", "judged_comparison", "judging", "judge_failure",
           "held", "carried_note"]

#: "module.function" -> (the problem whose solution region it is, the check that grades it)
SHARED = {
    "rotations.R1": (6, "p06.elementary_values"),
    "rotations.R2": (6, "p06.elementary_values"),
    "rotations.R3": (6, "p06.elementary_values"),
    "rotations.cardan": (6, "p06.cardan_values"),
    "rotations.skew": (7, "p07.skew_values"),
    "rotations.unskew": (7, "p07.unskew_values"),
    "rotations.omega_body": (7, "p07.omega_body"),
    "rotations.omega_inertial": (7, "p07.omega_inertial"),
    "rotations.cardan_rate_matrix": (8, "p08.rate_matrix"),
    "rotations.expm_skew": (8, "p08.exponential_step"),
    "inertia.cuboid_inertia": (16, "p16.cuboid"),
    "inertia.parallel_axis": (19, "p19.parallel_axis"),
    "dynamics.forward_dynamics": (37, "p37.forward_dynamics"),
    "problem_37.gravity_compensation_torque": (37, "p37.gravity_compensation_torque"),
    "problem_37.computed_torque": (37, "p37.computed_torque"),
    "problem_43.accelerations": (43, "p43.accelerations_values"),
}

def _numeric(value):
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return None
    return array


#: the shared functions whose values are rotations, judged as rotations by ``flaw``: another function's value that is
#: a rotation on some input (problem 8's rate matrix at zero angles is the identity) is judged as any value
ROTATION_VALUED = frozenset({"rotations.R1", "rotations.R2", "rotations.R3", "rotations.cardan",
                             "rotations.expm_skew"})


def flaw(mine, reference, function: str | None = None) -> str:
    """Why the student's value ``mine`` of a shared function is not a real result to carry forward, judged against
    the reference's value of the same call ("" when it is real), by the one rule of ``checks._real``: not numeric
    where the reference's is, another shape, NaN or infinite, all zeros or one constant where the reference's is
    not; where the reference's is a rotation, not orthonormal or the identity (for ``function``, the shared
    function called, only where it is one of ``ROTATION_VALUED``).  Lists and dicts are judged entry by entry."""
    if isinstance(reference, dict):
        if not isinstance(mine, dict) or mine.keys() != reference.keys():
            return "does not have the reference's entries"
        return next((f"[{k!r}] {found}" for k in reference if (found := flaw(mine[k], reference[k], function))),
                    "")
    if isinstance(reference, (str, bool)) or reference is None:
        return ""
    theirs = _numeric(reference)
    if theirs is None or theirs.dtype == object:
        if isinstance(reference, (list, tuple)) and isinstance(mine, (list, tuple)):
            if len(mine) != len(reference):
                return f"has {len(mine)} entries, not {len(reference)}"
            return next((f"[{i}] {found}" for i, (a, b) in enumerate(zip(mine, reference))
                         if (found := flaw(a, b, function))), "")
        return ""
    if mine is None:
        return "is None"
    ours = _numeric(mine)
    if ours is None or ours.dtype == object:
        return "is not numeric"
    if is_rotation(theirs) and (function is None or function in ROTATION_VALUED):
        return rotation_flaw(ours, theirs)
    return real_flaw(ours, reference=theirs)


def judged(ctx, probe: str, *args):
    """``ctx.upstream`` for ``probe(*args)`` with the course's shared functions and ``flaw``: make it before looking
    at the student's answer (the kit's key records its calls)."""
    return ctx.upstream(probe, args, SHARED, flaw)


def _names(found) -> str:
    return ", ".join(dict.fromkeys(function.rpartition(".")[2] for function in found.functions))


def _carry(ctx, found) -> None:
    """Record that the running check passed on the student's own shared functions of ``found``: error carried
    forward, pointing at the checks that grade them."""
    for function in found.functions:
        if function in SHARED:
            ctx.carry_forward(SHARED[function][1], _names(found))


def carried_note(found) -> str:
    """The sentence that says which of the student's shared functions differ and which checks grade them."""
    graded = "; ".join(dict.fromkeys(check_title(SHARED[f][1]) for f in found.functions if f in SHARED))
    first = found.differing[0]
    example = f"{first.shown()} raised: {first.error}" if first.error else f"e.g. {first.shown()}"
    return (f"Your {_names(found)} {'differs' if len(found.functions) == 1 else 'differ'} from the reference's "
            f"({example}); {'it is' if len(found.functions) == 1 else 'they are'} graded by {graded}.")


def assert_close_judged(ctx, got, expected, judged_value, name: str, tol: Tol, mistakes=(), pick=None,
                        context: str = "", note: str = "", normalize=None):
    """``assert_close(got, expected, ...)``, where a difference may come from the student's own shared functions of
    earlier problems: ``judged_value`` (from ``judged``, made before the student's answer was looked at) gives what
    the reference's code makes of them, ``pick`` the part of the probe's value that ``expected`` is.  The answer
    passes (error carried forward, with a pointer to the check that finds the mistake) when it matches that;
    otherwise it fails, judged on it, or, when nothing can be carried forward, against the reference's value with a
    note why.  ``normalize(got, target)`` brings the answer to the form of the value it is compared with (angles
    moved by whole turns next to the target's, say)."""
    answer = got
    if normalize is not None:
        got = normalize(answer, expected)
    if close(got, expected, tol):
        return
    found = judged_value.result()
    if found is None:
        assert_close(got, expected, name, tol, mistakes, context=context, note=note)
        return
    why = carried_note(found)
    if found.flaw or found.value is None:
        extra = f"{why} But {found.flaw}: nothing is carried forward on it."
        assert_close(got, expected, name, tol, mistakes, context=context, note=_join(note, extra))
        return
    value = pick(found.value) if pick is not None else found.value
    if normalize is not None:
        got = normalize(answer, value)
    if close(got, value, tol):
        _carry(ctx, found)
        return
    assert_close(got, value, name, tol, (), context=_join_context(context, f"judged on your own {_names(found)}"),
                 note=_join(note, f"{why} This answer is judged on {'it' if len(found.functions) == 1 else 'them'}: "
                                  f"the reference's code of this problem with your {_names(found)}."))


def _join(first: str, second: str) -> str:
    return f"{first}\n{second}" if first else second


def _join_context(context: str, extra: str) -> str:
    return f"{context} ({extra})" if context else f"({extra})"


def judged_comparison(ctx, probe: str, name: str, tol: Tol, mistakes=None, pick=None, normalize=None):
    """A ``compare`` for ``ctx.compare_random`` on ``probe``: the reference's value, or where the student's own
    shared functions differ, what the reference's code makes of them (``assert_close_judged``); ``mistakes(args,
    expected)`` is the catalogue of known mistakes."""

    def compare(got, expected, args):
        judged_value = judged(ctx, probe, *args)
        found = list(mistakes(args, expected)) if mistakes else ()
        assert_close_judged(ctx, got, expected, judged_value, name, tol, found, pick, normalize=normalize)

    compare.carried_error = lambda error, args: _carried_raise(ctx, judged(ctx, probe, *args), error)
    return compare


def _carried_raise(ctx, judged_value, error) -> bool:
    """Whether the student's code raised ``error`` (a ``StudentCodeError``) where the reference's code, on the
    student's own shared functions (``judged_value``, from ``judged``), raises the same: a singular rate matrix of
    theirs makes a step of theirs and the reference's fail alike.  Then the error is carried forward, as a value
    would be (True: the input passes, pointing at the check that finds the mistake); ``ctx.compare_random`` holds
    it to the inputs judged by their value beside it, so that code that only raises earns nothing."""
    found = judged_value.result()
    if found is None or found.value is not None \
            or not found.flaw.startswith(f"{COULD_NOT_USE} ({error.type_name}:"):
        return False
    _carry(ctx, found)
    return True


def judge_failure(ctx, failure: CheckFailure, judged_value, rejudge):
    """After ``failure`` of a comparison with the reference: where the student's own shared functions differ,
    ``rejudge(value)`` compares the answer with what the reference's code makes of them (raising ``CheckFailure``
    when it differs too); a match carries the error forward, anything else fails with a note that says on what the
    answer was judged."""
    found = judged_value.result()
    if found is None:
        raise failure
    why = carried_note(found)
    if found.flaw or found.value is None:
        raise CheckFailure(f"{failure.message}\n{why} But {found.flaw}: nothing is carried forward on it.",
                           failure.hint, failure.diagnosis, failure.candidates, failure.evidence) from None
    try:
        rejudge(found.value)
    except CheckFailure as again:
        first, _, rest = again.message.partition("\n")
        raise CheckFailure(f"{first}\n(judged on your own {_names(found)}: the reference's code of this problem "
                           f"with your {_names(found)})\n{why}\n{rest}", again.hint, again.diagnosis,
                           again.candidates, again.evidence) from None
    _carry(ctx, found)


def judging(ctx, probe: str, compare, rejudge=None):
    """``compare(got, expected, args)`` (for ``ctx.compare_random`` or a fixed case of ``probe``) with the error of
    the student's shared functions carried forward: where it fails, the answer is judged again on what the
    reference's code of ``probe`` makes of the student's own functions, by ``rejudge(got, value, args)`` (default:
    ``compare`` itself)."""
    again = rejudge or compare

    def wrapped(got, expected, args):
        judged_value = judged(ctx, probe, *args)
        try:
            compare(got, expected, args)
        except CheckFailure as failure:
            judge_failure(ctx, failure, judged_value, lambda value: again(got, value, args))

    return wrapped


def held(ctx, judged_value, check, rejudge):
    """``check()`` (a comparison of the student's answer with the reference's); where it fails, the answer is judged
    again on what the reference's code makes of the student's own shared functions: ``rejudge(value)`` (see
    ``judge_failure``)."""
    try:
        check()
    except CheckFailure as failure:
        judge_failure(ctx, failure, judged_value, rejudge)
