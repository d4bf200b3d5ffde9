"""Results as data: frozen dataclasses that every renderer and the gradebook read, and what a class's results add
up to (each student's rows, the possible points every student is measured against)."""

from __future__ import annotations

from collections import defaultdict
from dataclasses import asdict, dataclass, field, replace
from enum import Enum

__all__ = ["Status", "Series", "Figure", "CheckResult", "ManualItem", "ProblemReport", "student_view", "Graded",
           "rows_by_student", "scored_items", "problem_possible", "possible"]


class Status(str, Enum):
    PASSED = "passed"
    FAILED = "failed"  # the value or property is wrong
    ERROR = "error"  # the student's code raised, crashed or returned something unusable
    TIMEOUT = "timeout"  # the student's code did not answer in time
    NOT_IMPLEMENTED = "not_implemented"  # still the template's stub, or an unanswered question
    SKIPPED = "skipped"  # not run because an earlier stage failed
    GRADER_ERROR = "grader_error"  # a defect of the grader: not the student's fault
    DEFERRED = "deferred"  # not graded here: its key stays with the instructor (graded on submission)

    @property
    def symbol(self) -> str:
        return {
            "passed": "✔",
            "failed": "✘",
            "error": "!",
            "timeout": "⏱",
            "not_implemented": "…",
            "skipped": "-",
            "grader_error": "?",
            "deferred": "◇",
        }[self.value]


@dataclass(frozen=True)
class Series:
    """One curve of a figure: ``role`` is "student", "reference" or "other".  A curve in space has ``z`` too (the
    figure is then drawn on 3-D axes); ``colour`` fixes its colour (the x, y, z axes of a frame in red, green,
    blue), ``marker`` draws its points ("o"), and ``panel`` is the panel it belongs to in a figure of panels side
    by side."""

    label: str
    x: tuple[float, ...]
    y: tuple[float, ...]
    role: str = "other"
    z: tuple[float, ...] = ()
    colour: str = ""
    marker: str = ""
    panel: int = 0


@dataclass(frozen=True)
class Figure:
    """A figure of a check: the student's curves over the reference's.  ``panels`` names the panels drawn side by
    side (none: one panel); ``zlabel`` is set for a figure in space."""

    title: str
    xlabel: str
    ylabel: str
    series: tuple[Series, ...]
    equal_axes: bool = False
    zlabel: str = ""
    panels: tuple[str, ...] = ()

    @property
    def spatial(self) -> bool:
        return bool(self.zlabel) or any(s.z for s in self.series)


@dataclass(frozen=True)
class CheckResult:
    check_id: str  # e.g. "p06.cardan_values"
    problem: int
    title: str  # the property checked, one line
    status: Status
    score: float
    max_score: float
    message: str = ""  # got/expected, tolerance, mismatch table
    hint: str = ""  # the likely mistake and what to do
    diagnosis: str = ""  # short name of a recognised mistake, e.g. "transpose"
    visibility: str = "visible"  # "visible" | "hidden"
    stage: int = 0
    seed: int | None = None
    figures: tuple[Figure, ...] = ()
    duration: float = 0.0

    @property
    def passed(self) -> bool:
        return self.status is Status.PASSED


@dataclass(frozen=True)
class ManualItem:
    """A free-text answer scored by a person: shown with the course's model answer; the person's comment goes back
    to the student with the score."""

    problem: int
    key: str
    question: str
    answer: str
    model_answer: str
    max_score: float
    score: float | None = None  # None until a person scores it
    comment: str = ""  # the scorer's comment to the student ("" when none)


@dataclass(frozen=True)
class ProblemReport:
    problem: int
    title: str
    results: tuple[CheckResult, ...]
    manual: tuple[ManualItem, ...] = ()
    sandbox: str = ""
    isolated: bool = True
    seed: int = 0
    duration: float = 0.0
    stdout: str = ""
    stderr: str = ""
    submission: str = ""
    grader_version: str = ""
    notes: tuple[str, ...] = field(default=())
    #: why the submission could not be loaded ("" when it was): said once, for the whole problem; no check ran
    load_error: str = ""
    #: the wrong answers on inputs every student is asked (``grader.answers.Answer``), recorded by a batch for
    #: ``grade similarity``: the instructor's, never in a student's report
    wrong_answers: tuple = ()

    @property
    def score(self) -> float:
        manual = sum(m.score for m in self.manual if m.score is not None)
        return sum(r.score for r in self.results) + manual

    @property
    def max_score(self) -> float:
        return sum(r.max_score for r in self.results) + sum(m.max_score for m in self.manual)

    @property
    def auto_max_score(self) -> float:
        return sum(r.max_score for r in self.results)

    @property
    def visible_score(self) -> float:
        """The score a student may see before the deadline: the visible checks' points (reports show it out of
        the full maximum, with the hidden checks' count and points beside it)."""
        return sum(r.score for r in self.results if r.visibility == "visible")

    @property
    def deferred(self) -> tuple[CheckResult, ...]:
        """The checks not graded here (student kit): graded when the work is submitted."""
        return tuple(r for r in self.results if r.status is Status.DEFERRED)

    @property
    def pending_manual(self) -> float:
        return sum(m.max_score for m in self.manual if m.score is None)

    def count(self, status: Status) -> int:
        return sum(1 for r in self.results if r.status is status)

    def to_dict(self) -> dict:
        data = asdict(replace(self, wrong_answers=()))
        data.pop("wrong_answers")
        for result in data["results"]:
            result["status"] = result["status"].value
        data["score"] = self.score
        data["max_score"] = self.max_score
        return data


def student_view(report: ProblemReport) -> ProblemReport:
    """The report as a student may see it, whatever the format: hidden checks keep only their count and points
    (not their score, status, title or messages), and free-text items lose the course's model answer."""
    results = tuple(
        r if r.visibility == "visible" else replace(
            r, title="hidden check", status=Status.SKIPPED, score=0.0, message="", hint="", diagnosis="", seed=None,
            figures=())
        for r in report.results
    )
    manual = tuple(replace(m, model_answer="") for m in report.manual)
    return replace(report, results=results, manual=manual, wrong_answers=())


@dataclass(frozen=True)
class Graded:
    """The current result of one problem of one student, as a batch's gradebook keeps it."""

    student: str
    content_hash: str
    grader_version: str
    run_id: int
    graded_at: str
    outcome: str
    report: ProblemReport


# ---------------------------------------------------------------------------------------------- a class's results


def rows_by_student(graded: list[Graded]) -> dict[str, list[Graded]]:
    """The rows of each student, by name in order."""
    students: dict[str, list[Graded]] = defaultdict(list)
    for g in graded:
        students[g.student].append(g)
    return dict(sorted(students.items()))


def scored_items(graded: list[Graded]) -> dict[int, dict[str, float]]:
    """Per problem, the free-text answers that a person has scored for some student of the class, with their
    points: from then on they count in every student's possible points, before that in no one's."""
    items: dict[int, dict[str, float]] = defaultdict(dict)
    for g in graded:
        for m in g.report.manual:
            if m.score is not None:
                items[m.problem][m.key] = m.max_score
    return dict(items)


def problem_possible(report, scored: dict[int, dict[str, float]]) -> float:
    """A problem's possible points: its checks' (hidden ones included), and its free-text answers' once scored for
    someone (``scored_items``); the same for every student, whether their submission could be loaded or not."""
    return report.auto_max_score + sum(scored.get(report.problem, {}).values())


def possible(items: list[Graded], scored: dict[int, dict[str, float]]) -> float:
    """A student's possible points over the problems graded (``problem_possible``)."""
    return sum(problem_possible(g.report, scored) for g in items)
