"""Batch grading: every student of a folder, in parallel (or on a Dask cluster), into a gradebook that survives
interruption.

    grade batch SUBMISSIONS --out RESULTS [--problems N ...] [--jobs N | --cluster ADDRESS] [--force] [--course F]
    grade import-manual RESULTS SCORES.csv
    grade export RESULTS [--course F] [--canvas] [--moodle] [--roster F]

Each entry of SUBMISSIONS is one student: a folder, a .zip archive or a .ipynb notebook (``discover``).  Students
are graded on ``--jobs`` worker processes (``pool``), each with a warm sandboxed child from which every student's
child is forked, or on the workers of a Dask cluster (``cluster``); the parent alone writes the gradebook
(``gradebook``), one transaction per student, and each student's exports as soon as they are recorded
(``exports``).  A student whose content and grader version are already in the gradebook is skipped unless
``--force``.

RESULTS receives the gradebook (``gradebook.sqlite``), ``grades.csv``, ``summary.html`` (the class summary),
``manual_answers.csv`` (free-text answers, with a score column to fill in and import) and, per student,
``students/NAME/results.json`` (Gradescope's, built as the autograder builds it:
``grader.report.gradescope_results``) and ``students/NAME/report.html`` (the student's view).
With a course file (``course``: assignments, due dates, extensions, a late policy), grades.csv has each assignment's
raw score, late penalty and final score, recomputed at every export; ``canvas.csv`` and ``moodle.csv`` (``lms``) are
the LMS's grade import files.

The names below are imported when first used, so that ``grade`` starts without importing the batch machinery.
"""

from __future__ import annotations

from ..lazy import lazy_names

# The function, not the module of the same name: imported now, so that it keeps the name ``discover`` here.
from .discover import Entry, discover, student_seed, submission_hash

__all__ = [
    "Entry",
    "BatchReport",
    "Progress",
    "BatchLocked",
    "discover",
    "submission_hash",
    "student_seed",
    "run_batch",
    "export_results",
    "export_student",
    "add_batch_parser",
]

_WHERE = {
    "Progress": "progress",
    "BatchReport": "run", "BatchLocked": "run", "run_batch": "run", "_locked": "run",
    "default_student_timeout": "run",
    "export_results": "exports", "export_student": "exports",
    "add_batch_parser": "commands",
}


__getattr__ = lazy_names(__name__, _WHERE, globals())
