"""The autograder of the multibody-dynamics course.

``grade_problem(problem, submission)`` grades one problem and returns a ``ProblemReport``; the ``grade``
command (``grader.cli``) and the batch grader are thin layers over it.
"""

__version__ = "0.1.0"

from .results import CheckResult, ProblemReport, Status  # noqa: E402
from .runner import grade_problem, grade_submission, problems  # noqa: E402

__all__ = ["__version__", "grade_problem", "grade_submission", "problems", "ProblemReport", "CheckResult", "Status"]
