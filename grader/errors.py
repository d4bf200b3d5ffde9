"""One exception root with a student-fault and a grader-fault branch, and the exit codes of the ``grade`` command
(whose fault each failure is, and the code it ends with, is ``grader.faults``)."""

__all__ = [
    "EXIT_OK",
    "EXIT_FAILED",
    "EXIT_USAGE",
    "EXIT_GRADER",
    "GradingError",
    "ends_grading",
    "StudentFault",
    "SubmissionError",
    "StudentCodeError",
    "StudentTimeout",
    "MachineBusy",
    "WorkerCrash",
    "GraderFault",
    "SandboxError",
    "ProbeFault",
]

#: every check passed; some check did not pass; a usage error or a submission that cannot be loaded; a fault of
#: the grader (its installation or a defect), never the student's
EXIT_OK, EXIT_FAILED, EXIT_USAGE, EXIT_GRADER = 0, 1, 2, 3


class GradingError(Exception):
    """Root of every error the grader raises on purpose."""


class StudentFault(GradingError):
    """Something about the submission: shown to the student as their error."""


class SubmissionError(StudentFault):
    """The submission cannot be loaded (missing, malformed zip, unreadable notebook, ...)."""


class StudentCodeError(StudentFault):
    """The student's code raised an exception (or returned a value that cannot be sent back)."""

    def __init__(self, kind, type_name, message, traceback="", phase="call"):
        super().__init__(f"{type_name}: {message}" if message else type_name)
        self.kind = kind
        self.type_name = type_name
        self.message = message
        self.traceback = traceback
        self.phase = phase

    @property
    def not_implemented(self):
        return self.kind == "not_implemented"


class StudentTimeout(StudentFault):
    """The student's code did not answer within its time limit."""

    def __init__(self, seconds, phase="call"):
        super().__init__(f"no answer within {seconds:g} s")
        self.seconds = seconds
        self.phase = phase


class WorkerCrash(StudentFault):
    """The process running the student's code ended without answering (os._exit, a memory limit, a signal)."""

    def __init__(self, detail, phase="call"):
        super().__init__(detail)
        self.detail = detail
        self.phase = phase


def ends_grading(exc: BaseException) -> bool:
    """Whether a fault of the student's code stops the grading of the submission wherever it happens: a time-out, a
    crashed worker, or a function left unimplemented (the others fail one comparison)."""
    return isinstance(exc, (StudentTimeout, WorkerCrash)) or getattr(exc, "not_implemented", False)


class GraderFault(GradingError):
    """A defect of the grader itself: never reported as the student's fault."""


class MachineBusy(GraderFault):
    """A call ran out of time after its worker had waited for a processor longer than the grace its deadline
    allows (``grader.sandbox.child.LOAD_GRACE``): the machine was too busy to give the code its time limit, which
    is no fault of the student's."""

    def __init__(self, seconds, waited, phase="call"):
        super().__init__(f"the machine grading was too busy: the code waited {waited:.1f} s for a processor "
                         f"during a call limited to {seconds:g} s; grade again when the machine is less loaded")
        self.seconds = seconds
        self.waited = waited
        self.phase = phase


class SandboxError(GraderFault):
    """The sandbox could not be set up."""


class ProbeFault(GraderFault):
    """A check asked for a probe that the worker could not run (it does not exist, it cannot be imported, or it
    raised on its own rather than in the student's code)."""
