"""Gradescope's ``results.json``: ``results_json`` is the one builder of that file.  The autograder's
``run_autograder`` (``grader.gradescope.run``), ``grade problem-N --gradescope`` and the batch's per-student export
all write what it returns, with the same visibility rules on the instructor's side as in Gradescope's container.

What a student sees (``results.json``), following the student's view of every other report
(``grader.results.student_view``):

* a public check is a test with ``visibility: "visible"``: its score, status and message;
* a *secret* check (multiple choice, predicted output: its message would give the key away) and a *hidden* check
  are graded at once but their tests have ``visibility: "after_published"``: shown to students only when the
  instructor publishes the grades (``after_due_date`` would show them when the due date passes, while students
  with an extension may still be working).  Gradescope then also hides the total score until publication.  The
  visible top-level output names the secret checks and counts the hidden ones with their points, as every
  student report does;
* a submission that could not be loaded is said once, at the top of the output; each check's test says it did
  not run (scored 0, never as wrong answers);
* a free-text answer is an informational test (no score: it is scored by hand), without the model answer; once a
  score is imported (``grade import-manual``) it is a scored test, and the top-level score counts it;
* a fault of the grader is never a silent 0: a check the grader could not run says so in its test and in the
  top-level output, and a grader that cannot grade at all writes a results.json that says so plainly (score 0,
  ``extra_data.grader_fault``) and exits with code 3.  Gradescope's specification asks for a results.json in
  every case (without one the student only reads "The autograder failed to execute correctly").
"""

from __future__ import annotations

import json

from .. import __version__
from ..problems import withheld_check_ids
from ..results import CheckResult, ManualItem, ProblemReport, Status, student_view
from .environment import environment

__all__ = ["results_json", "render_results", "fault_results", "WITHHELD"]

#: the visibility of the tests a student may not see before the grades are published (secret and hidden checks)
WITHHELD = "after_published"


def _fmt(x: float) -> str:
    return f"{x:g}"


def _check_output(r: CheckResult, load_error: str) -> str:
    if load_error:
        return "Not run: your submission could not be loaded (the reason is at the top)."
    if r.status is Status.GRADER_ERROR:
        head = ("Not graded: a fault of the grader, not of your work. It counts 0 until your course staff "
                "regrade this submission.")
        return "\n".join(part for part in (head, r.message) if part)
    parts = [r.message or ("passed" if r.passed else r.status.value.replace("_", " "))]
    if r.diagnosis:
        parts.append(f"likely mistake: {r.diagnosis}")
    if r.hint:
        parts.append(f"hint: {r.hint}")
    return "\n".join(parts)


def _test(r: CheckResult, number: str, withheld: bool, load_error: str) -> dict:
    return {
        "name": f"Problem {r.problem}: {r.title}",
        "number": number,
        "score": float(r.score),
        "max_score": float(r.max_score),
        "status": "passed" if r.status is Status.PASSED else "failed",
        "output": _check_output(r, load_error),
        "output_format": "text",
        "visibility": WITHHELD if withheld else "visible",
        "tags": [f"problem-{r.problem}", r.status.value] + ([r.diagnosis] if r.diagnosis else []),
        "extra_data": {"check_id": r.check_id, "status": r.status.value, "diagnosis": r.diagnosis,
                       "seed": r.seed, "withheld": withheld},
    }


def _manual_test(m: ManualItem, number: str) -> dict:
    """A free-text answer, never with the model answer: informational (no score, no status) until a person scores
    it; then a scored test (passed when it earned every point)."""
    test = {
        "name": f"Problem {m.problem}: {m.question} (scored by hand, {_fmt(m.max_score)} points)",
        "number": number,
        "output": f"Your answer:\n{m.answer or '(blank)'}\n\nScored by hand by your course staff; "
                  "it counts 0 until then.",
        "output_format": "text",
        "visibility": "visible",
        "tags": [f"problem-{m.problem}", "manual"],
        "extra_data": {"free_text": m.key, "max_score": float(m.max_score)},
    }
    if m.score is not None:
        status = "passed" if m.score >= m.max_score else "failed"
        comment = f"\n\nComment from your course staff:\n{m.comment}" if m.comment else ""
        test.update(score=float(m.score), max_score=float(m.max_score), status=status,
                    output=f"Your answer:\n{m.answer or '(blank)'}\n\nScored by hand by your course staff: "
                           f"{_fmt(m.score)} of {_fmt(m.max_score)} points.{comment}")
        test["extra_data"].update(status=status, scored_by_hand=True)
        if m.comment:
            test["extra_data"]["comment"] = m.comment
    return test


def _seeds(reports: list[ProblemReport]) -> str:
    """The seed of the random inputs: one number, or one per problem when the problems were graded with different
    ones (a gradebook's problems graded at different times)."""
    seeds = list(dict.fromkeys(r.seed for r in reports))
    if len(seeds) == 1:
        return f"seed {seeds[0]}"
    return "seeds " + ", ".join(f"{r.seed} (problem {r.problem})" for r in reports)


def _load_errors(reports: list[ProblemReport]) -> list[tuple[str, str]]:
    """Why the submission could not be loaded, each reason once with the problems it stopped."""
    by_reason: dict[str, list[int]] = {}
    for report in reports:
        if report.load_error:
            by_reason.setdefault(report.load_error, []).append(report.problem)
    return [(f"problem{'s' if len(numbers) > 1 else ''} {', '.join(map(str, numbers))}", reason)
            for reason, numbers in by_reason.items()]


def results_json(reports: list[ProblemReport], *, withheld_ids: set[str] | None = None, seed: int | None = None,
                 execution_time: float | None = None, fresh_inputs: bool = False) -> dict:
    """Gradescope's results.json of one graded submission (see the module's docstring for what a student sees):
    the one builder of that file, for the autograder (``run``), ``grade problem-N --gradescope`` and the batch's
    per-student export.

    ``withheld_ids`` are the secret and hidden checks (default: those of the reports' problems, from their check
    modules); ``seed`` the seed of the random inputs (default: the reports'); ``execution_time`` seconds (default:
    the reports' grading time); ``fresh_inputs`` says that the inputs were drawn fresh for this submission."""
    if withheld_ids is None:
        withheld_ids = withheld_check_ids([r.problem for r in reports])
    if execution_time is None:
        execution_time = sum(r.duration for r in reports)
    tests = []
    withheld, grader_errors = [], []
    for report in reports:
        for index, r in enumerate(report.results, 1):
            hide = r.check_id in withheld_ids or r.visibility == "hidden"
            tests.append(_test(r, f"{report.problem}.{index}", hide, report.load_error))
            if hide and r.visibility != "hidden":
                withheld.append(r)
            if r.status is Status.GRADER_ERROR:
                grader_errors.append(r.check_id)
        for index, m in enumerate(student_view(report).manual, len(report.results) + 1):
            tests.append(_manual_test(m, f"{report.problem}.{index}"))
    views = [student_view(r) for r in reports]
    hidden = [r for report in reports for r in report.results if r.visibility == "hidden"]
    # per problem: the points of the checks a student sees now (neither secret nor hidden)
    shown = [(report, [r for r in report.results if r.visibility == "visible" and r.check_id not in withheld_ids])
             for report in reports]
    lines = [{"problem": report.problem, "title": report.title, "score": sum(r.score for r in public),
              "max_score": sum(r.max_score for r in public)} for report, public in shown]
    notes = sorted({n for report in reports for n in report.notes}
                   | {report.sandbox for report in reports if not report.isolated and report.sandbox})
    manual = [m for report in views for m in report.manual]
    output = environment("text").get_template("gradescope/output.txt.j2").render(
        problems=[r.problem for r in reports], seeds=_seeds(reports) if seed is None else f"seed {seed}",
        fresh_inputs=fresh_inputs, lines=lines,
        load_errors=_load_errors(reports),
        withheld=withheld, withheld_points=sum(r.max_score for r in withheld),
        hidden_count=len(hidden), hidden_points=sum(r.max_score for r in hidden),
        pending=[m for m in manual if m.score is None], scored=[m for m in manual if m.score is not None],
        grader_errors=grader_errors, notes=notes, fmt=_fmt).strip() + "\n"
    # every point the submission earned: the checks' and the free-text answers' scored so far (Gradescope's
    # specification asks for the top-level score, since an unscored free-text answer's test has none)
    score = sum(r.score for r in reports)
    return {
        "score": float(score),
        "execution_time": int(round(execution_time)),
        "output": output,
        "output_format": "text",
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "extra_data": {
            "grader_version": __version__,
            "seed": seed if seed is not None else reports[0].seed if len({r.seed for r in reports}) == 1 else None,
            "seeds": {str(r.problem): r.seed for r in reports},
            "problems": [r.problem for r in reports],
            "max_score": float(sum(r.max_score for report in reports for r in report.results)),
            "manual_points": float(sum(m.max_score for report in reports for m in report.manual)),
            "manual_score": float(sum(m.score for report in reports for m in report.manual if m.score is not None)),
            "sandbox": sorted({r.sandbox for r in reports}),
            "isolated": all(r.isolated for r in reports),
            "load_errors": {str(r.problem): r.load_error for r in reports if r.load_error},
            "grader_errors": grader_errors,
            "grader_fault": False,
        },
        "tests": tests,
    }


def render_results(reports: list[ProblemReport], **options) -> str:
    """``results_json`` as the text of the file (JSON, not a template)."""
    return json.dumps(results_json(reports, **options), indent=2) + "\n"


def fault_results(reason: str, *, execution_time: float = 0.0) -> dict:
    """The results.json of a submission the grader could not grade at all (its installation is broken): said
    plainly, score 0 (Gradescope needs a score), marked as the grader's fault for the course staff."""
    output = environment("text").get_template("gradescope/fault.txt.j2").render(reason=reason).strip() + "\n"
    return {
        "score": 0.0,
        "execution_time": int(round(execution_time)),
        "output": output,
        "output_format": "text",
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "extra_data": {"grader_version": __version__, "grader_fault": True, "reason": reason},
        "tests": [{
            "name": "The grader's installation (a fault of the grader, not of your work)",
            "number": "0.1",
            "score": 0.0,
            "max_score": 0.0,
            "status": "failed",
            "output": output,
            "output_format": "text",
            "visibility": "visible",
            "tags": ["grader_error"],
            "extra_data": {"grader_fault": True, "status": Status.GRADER_ERROR.value},
        }],
    }
