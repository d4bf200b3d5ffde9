"""The autograder of the multibody-dynamics course.

``grade_problem(problem, submission)`` grades one problem and returns a ``ProblemReport``; the ``grade``
command (``grader.cli``) and the batch grader are thin layers over it; ``check(6)`` grades problem 6 from inside
a Jupyter notebook (``grader.jupyter``); ``grader.problems`` says which problems have checks.  The names below are
imported when first used, so that ``grade`` starts without importing the grading machinery (numpy, the checks) it
does not need.
"""

__version__ = "0.1.0"

__all__ = ["__version__", "grade_problem", "grade_submission", "ProblemReport", "CheckResult", "Status", "check",
           "load_ipython_extension"]

_WHERE = {"grade_problem": "runner", "grade_submission": "runner",
          "ProblemReport": "results", "CheckResult": "results", "Status": "results",
          "check": "jupyter", "load_ipython_extension": "jupyter"}


from .lazy import lazy_names  # noqa: E402

__getattr__ = lazy_names(__name__, _WHERE, globals())
