"""A problem of a submission graded in this process with its sandboxed child wrapped, so a test sees every call a
check sends to the student's package (the argument audit, the null family)."""

from __future__ import annotations

from grader.context import Context
from grader.loader import cleanup, materialize
from grader.oracle import LiveOracle
from grader.runner import _run_checks, problem_module
from grader.sandbox import Child

from .kit_support import SEED

__all__ = ["grade_wrapped"]


def grade_wrapped(problem: int, source, zygote, wrap):
    """The results of ``problem`` for the submission at ``source`` (live reference, the suite's seed) and the
    wrapper: ``wrap(child)`` returns the object the checks call instead of the child (``call``, ``output``); it
    is given the grading context as ``ctx`` before the first check runs."""
    submission = materialize(source, zygote.staging)
    try:
        with Child(submission.path, zygote=zygote) as child:
            child.start()
            wrapper = wrap(child)
            ctx = Context(problem, wrapper, submission.answers, submission.answers_error, SEED, LiveOracle())
            wrapper.ctx = ctx
            results = _run_checks(problem_module(problem), ctx, problem)
    finally:
        cleanup(submission)
    return results, wrapper
