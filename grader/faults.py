"""Whose fault each failure is: one table, read by ``grade problem-N``, ``grade batch`` and Gradescope's
``run_autograder`` alike.

=================  ================================================  ========  =====  ==============================
failure            raised as                                         whose     grade  a batch / run_autograder
=================  ================================================  ========  =====  ==============================
loader             ``SubmissionError``: the submission cannot be     student   2      recorded once, every check 0,
                   loaded (a broken archive or notebook, a link, a                    the reason said once; results
                   shape the loader refuses)                                          .json score 0, exit 0
worker start       ``SandboxError``: the worker cannot start or      grader    3      nothing stored (retried on the
                   import its dependencies                                            next run, the batch exits 3);
                                                                                      fault results.json, exit 3
student code       ``StudentCodeError``: the student's code raised,  student   1      recorded: the checks it stops
                   called sys.exit, is not written yet; answers.toml                  score 0 with the error; exit 0
                   does not parse
student process    ``WorkerCrash``: the process running the          student   1      recorded, as above
                   student's code ended (os._exit, a memory limit)
codec              ``StudentCodeError`` ``bad_value``: the student's  student   1      recorded, as above
                   answer cannot be sent or read back (a value of no
                   known type, a forged or malformed reply)
timeout            ``StudentTimeout``: no answer within the call's   student   1      recorded, as above (a batch's
                   or the import's limit (a batch's per-student                       stopped student: outcome
                   bound too)                                                         ``timeout``)
probe              ``ProbeFault``: a check asked for a probe the     grader    3      nothing stored, as for worker
                   worker could not run (missing, or it raised by                     start; the check says it is
                   itself)                                                            the grader's fault
grader exception   ``GraderFault``, or any other exception of the    grader    3      nothing stored, as above
                   grader (a check, the reference, a batch's
                   grading process that died)
=================  ================================================  ========  =====  ==============================

A failure of the student's is graded (0 for what it stops, with the reason) and recorded like any grade; a
failure of the grader's is never a grade: the command exits 3, a batch stores nothing for that student (they are
graded on the next run), and Gradescope's results say that the grader failed (``grader_fault``).  An exception the
grader did not foresee is the grader's, never the student's.
"""

from __future__ import annotations

from dataclasses import dataclass

from .errors import (EXIT_FAILED, EXIT_GRADER, EXIT_OK, EXIT_USAGE, ProbeFault, SandboxError, StudentCodeError,
                     StudentFault, StudentTimeout, SubmissionError, WorkerCrash)
from .results import Status

__all__ = ["Fault", "FAULTS", "fault_of", "faults_in", "exit_code", "stored", "grader_fault_reason"]


@dataclass(frozen=True)
class Fault:
    """One row of the table."""

    failure: str
    student: bool  # the student's fault (graded and recorded), else the grader's (nothing stored)
    exit_code: int  # what ``grade problem-N`` exits with
    recorded: str  # how a batch and Gradescope record it

    @property
    def whose(self) -> str:
        return "student" if self.student else "grader"

    @property
    def autograder_exit(self) -> int:
        """``run_autograder``'s exit code: 0 once the submission is graded, whatever the student's faults; 3 for
        the grader's."""
        return EXIT_OK if self.student else EXIT_GRADER


_GRADED = "recorded as a grade: every check it stops scores 0 with the reason; results.json says so, exit 0"
_NOT_STORED = ("never a grade: nothing stored (a batch grades the student again on its next run and exits 3); "
               "results.json says that the grader failed (grader_fault), exit 3")

LOADER = Fault("loader", True, EXIT_USAGE, "recorded once: every check 0, the reason said once (load_error); "
                                           "results.json score 0 with the reason, exit 0")
WORKER_START = Fault("worker start", False, EXIT_GRADER, _NOT_STORED)
STUDENT_CODE = Fault("student code", True, EXIT_FAILED, _GRADED)
STUDENT_PROCESS = Fault("student process", True, EXIT_FAILED, _GRADED)
CODEC = Fault("codec", True, EXIT_FAILED, _GRADED)
TIMEOUT = Fault("timeout", True, EXIT_FAILED, _GRADED + " (a batch's stopped student: outcome timeout)")
PROBE = Fault("probe", False, EXIT_GRADER, _NOT_STORED)
GRADER_EXCEPTION = Fault("grader exception", False, EXIT_GRADER, _NOT_STORED)

#: the table, by failure
FAULTS = {fault.failure: fault for fault in (LOADER, WORKER_START, STUDENT_CODE, STUDENT_PROCESS, CODEC, TIMEOUT,
                                             PROBE, GRADER_EXCEPTION)}

def fault_of(exc: BaseException) -> Fault:
    """The row of an exception: the student's for the student-fault branch of ``grader.errors``, the grader's for
    anything else (a ``GraderFault``, or an exception the grader did not foresee)."""
    if isinstance(exc, SubmissionError):
        return LOADER
    if isinstance(exc, StudentTimeout):
        return TIMEOUT
    if isinstance(exc, WorkerCrash):
        return STUDENT_PROCESS
    if isinstance(exc, StudentCodeError):
        return CODEC if exc.kind == "bad_value" else STUDENT_CODE
    if isinstance(exc, StudentFault):
        return STUDENT_CODE
    if isinstance(exc, SandboxError):
        return WORKER_START
    if isinstance(exc, ProbeFault):
        return PROBE
    return GRADER_EXCEPTION


def faults_in(reports) -> tuple[Fault, ...]:
    """The rows behind graded reports: the loader's for a submission that could not be loaded, the grader's for a
    check that is the grader's fault (``GRADER_ERROR``), the timeout's for a check stopped at its limit, the
    student's code for a check that errored (the code raised, its process ended or its answer could not be read:
    the report keeps the status, not which)."""
    found = []
    statuses = {r.status for report in reports for r in report.results}
    if any(report.load_error for report in reports):
        found.append(LOADER)
    if Status.GRADER_ERROR in statuses:
        found.append(GRADER_EXCEPTION)
    if Status.TIMEOUT in statuses:
        found.append(TIMEOUT)
    if Status.ERROR in statuses and not any(report.load_error for report in reports):
        found.append(STUDENT_CODE)
    return tuple(found)


def stored(reports) -> bool:
    """Whether reports are a grade to store (a batch's gradebook) or give (results.json): none of the grader's
    faults is in them."""
    return all(fault.student for fault in faults_in(reports))


def exit_code(reports) -> int:
    """What ``grade problem-N`` exits with for its reports: the grader's fault (3) before an unloadable submission
    (2) before a check that did not pass (1); 0 when every check passed (or is graded when submitted)."""
    codes = [fault.exit_code for fault in faults_in(reports)]
    if codes:
        return max(codes)
    statuses = {r.status for report in reports for r in report.results}
    return EXIT_OK if statuses <= {Status.PASSED, Status.DEFERRED} else EXIT_FAILED


def grader_fault_reason(exc: BaseException, out) -> str:
    """What a platform's results say of a failure that is the grader's: a ``GraderFault``'s own words (said on
    ``out`` too), or, for the unforeseen, that the grader failed internally (its traceback on ``out``, the course
    staff's log)."""
    import traceback

    from .errors import GraderFault
    from .terminal import say

    if isinstance(exc, GraderFault):
        say(f"grader fault: {exc}", out)
        return str(exc)
    traceback.print_exception(exc, file=out)
    return f"internal error of the grader ({type(exc).__name__}); the course staff have its log"
