"""One exception root with a student-fault and a grader-fault branch."""

__all__ = [
    "GradingError",
    "StudentFault",
    "SubmissionError",
    "StudentCodeError",
    "StudentTimeout",
    "WorkerCrash",
    "GraderFault",
    "SandboxError",
]


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


class GraderFault(GradingError):
    """A defect of the grader itself: never reported as the student's fault."""


class SandboxError(GraderFault):
    """The sandbox could not be set up."""
