"""PrairieLearn's ``results.json``: the one builder of that file (``results_json``), for the job that
``grade prairielearn --run`` grades.

What it says:

* a graded submission: ``gradable: true``, ``score`` the fraction of the problem's points, one test per public
  check (its points, message, likely mistake, figures), the secret and hidden checks in one test that shows their
  points but not their messages (PrairieLearn shows every result at once: it has no "after publication");
* a submission that cannot be loaded: ``gradable: false`` with the reason in ``format_errors`` (the student's
  fault, which costs no attempt);
* a fault of the grader (a broken installation, a check the grader could not run): ``gradable: false`` too, so
  that it costs the student nothing, said plainly to be the grader's fault; the job exits with code 3;
* without bubblewrap in the container, the students' code runs as a plain process (an unprivileged uid, resource
  limits) and the message says so.

results.json stays under PrairieLearn's 1 MB: figures are drawn smaller, then left out, and long texts cut, until
it fits.
"""

from __future__ import annotations

import base64
import io
import json

from ..problems import withheld_check_ids
from ..results import CheckResult, Figure, ProblemReport, Status
from .environment import environment
from .figures import _pyplot, figure_canvas, on_grid

__all__ = ["results_json", "fault_results", "unloadable_results", "grader_faults", "RESULTS_BYTES"]

#: PrairieLearn's bound on results.json
RESULTS_BYTES = 1_000_000
#: the longest text of one test (a student's traceback, a mismatch table); the rest is cut
TEXT_CHARS = 20_000
#: the resolutions a figure is drawn at, best first, until results.json fits
FIGURE_DPI = (90, 60, 40)


def grader_faults(reports: list[ProblemReport]) -> list[str]:
    """The checks that are the grader's fault (it could not run them): a submission with any is not a grade."""
    return [r.check_id for report in reports for r in report.results if r.status is Status.GRADER_ERROR]


def _whose(reports: list[ProblemReport]) -> tuple[bool, bool]:
    """``(graded, loaded)`` by ``grader.faults``' table: a fault of the grader's makes the reports no grade; the
    loader's (the student's) makes them a submission that could not be loaded."""
    from ..faults import LOADER, faults_in

    faults = faults_in(reports)
    return all(fault.student for fault in faults), LOADER not in faults


def _fmt(x: float) -> str:
    return f"{x:g}"


def _cut(text: str, limit: int = TEXT_CHARS) -> str:
    if len(text) <= limit:
        return text
    return text[:limit] + f"\n[... {len(text) - limit} more characters left out]"


def _check_message(r: CheckResult) -> str:
    """The first line a student reads of a public check: passed, or what is wrong."""
    if r.passed:
        return "passed"
    first = r.message.splitlines()[0] if r.message else r.status.value.replace("_", " ")
    return f"{first} (likely mistake: {r.diagnosis})" if r.diagnosis else first


def _check_output(r: CheckResult) -> str:
    parts = [r.message or ("passed" if r.passed else r.status.value.replace("_", " "))]
    if r.diagnosis:
        parts.append(f"likely mistake: {r.diagnosis}")
    if r.hint:
        parts.append(f"hint: {r.hint}")
    if r.seed is not None and not r.passed:
        parts.append(f"random inputs drawn with seed {r.seed}")
    return _cut("\n".join(parts))


def _withheld_test(report: ProblemReport, withheld: list[CheckResult]) -> dict:
    points = sum(r.score for r in withheld)
    maximum = sum(r.max_score for r in withheld)
    secret = [r for r in withheld if r.visibility == "visible"]
    hidden = len(withheld) - len(secret)
    lines = [f"{len(withheld)} check{'s' if len(withheld) != 1 else ''} graded now whose messages your course "
             "staff keep back (their answers would give the key away):"]
    lines += [f"  - {r.title} ({_fmt(r.max_score)} point{'s' if r.max_score != 1 else ''})" for r in secret]
    if hidden:
        lines.append(f"  - {hidden} hidden check{'s' if hidden != 1 else ''}")
    return {
        "name": f"Problem {report.problem}: checks whose details are withheld",
        "description": "graded now; only their points are shown",
        "points": float(points),
        "max_points": float(maximum),
        "message": f"{_fmt(points)} of {_fmt(maximum)} points",
        "output": "\n".join(lines),
    }


def _test(r: CheckResult, images: list[dict]) -> dict:
    test = {
        "name": f"Problem {r.problem}: {r.title}",
        "description": r.check_id,
        "points": float(r.score),
        "max_points": float(r.max_score),
        "message": _cut(_check_message(r), 2_000),
        "output": _check_output(r),
    }
    if images:
        test["images"] = images
    return test


def _manual_test(report: ProblemReport, item) -> dict:
    return {
        "name": f"Problem {item.problem}: {item.question} (scored by hand)",
        "description": f"free text: {item.key}",
        "points": 0.0,
        "max_points": 0.0,
        "message": f"scored by hand by your course staff ({_fmt(item.max_score)} points, not part of this score)",
        "output": _cut(f"Your answer:\n{item.answer or '(blank)'}"),
    }


def _png(fig: Figure, dpi: int) -> str:
    canvas = figure_canvas(on_grid(fig))
    buffer = io.BytesIO()
    canvas.savefig(buffer, format="png", dpi=dpi)
    _pyplot().close(canvas)
    return base64.b64encode(buffer.getvalue()).decode()


def _images(results: list[CheckResult], dpi: int | None) -> dict[str, list[dict]]:
    """The figures of ``results`` as PrairieLearn's images (data URLs) at ``dpi``; none when ``dpi`` is None."""
    if dpi is None:
        return {}
    return {r.check_id: [{"label": fig.title, "url": "data:image/png;base64," + _png(fig, dpi)}
                         for fig in r.figures]
            for r in results if r.figures}


def _size(data: dict) -> int:
    return len(json.dumps(data).encode("utf-8"))


def _message(reports: list[ProblemReport], seed: int | None, earned: float, maximum: float, public: float,
             public_max: float, figures_left: int) -> str:
    notes = sorted({n for report in reports for n in report.notes}
                   | {report.sandbox for report in reports if not report.isolated and report.sandbox})
    return environment("text").get_template("prairielearn/message.txt.j2").render(
        reports=reports, seed=seed, earned=earned, maximum=maximum, public=public, public_max=public_max,
        notes=notes, figures_left=figures_left, fmt=_fmt).strip() + "\n"


def results_json(reports: list[ProblemReport], *, withheld_ids: set[str] | None = None, seed: int | None = None,
                 limit: int = RESULTS_BYTES) -> dict:
    """PrairieLearn's results.json of one graded submission (see the module's docstring), within ``limit``
    bytes: a submission that could not be loaded, or that the grader could not grade in full, is not gradable."""
    graded, loaded = _whose(reports)
    if not graded:  # the grader's fault first: never the student's zero
        faults = grader_faults(reports)
        return fault_results(f"the grader could not run {len(faults)} check{'s' if len(faults) != 1 else ''} "
                             f"({', '.join(faults)})")
    if not loaded:
        return unloadable_results(next(r.load_error for r in reports if r.load_error))
    if withheld_ids is None:
        withheld_ids = withheld_check_ids([r.problem for r in reports])
    earned = sum(r.score for report in reports for r in report.results)
    maximum = sum(r.auto_max_score for r in reports)
    shown, withheld = [], []
    for report in reports:
        for r in report.results:
            (withheld if r.check_id in withheld_ids or r.visibility == "hidden" else shown).append(r)
    public = sum(r.score for r in shown)
    public_max = sum(r.max_score for r in shown)
    drawn = sum(len(r.figures) for r in shown)

    def build(dpi: int | None, chars: int) -> dict:
        images = _images(shown, dpi)
        tests = []
        for report in reports:
            mine = [r for r in shown if r.problem == report.problem]
            tests += [_test(r, images.get(r.check_id, [])) for r in mine]
            held = [r for r in withheld if r.problem == report.problem]
            if held:
                tests.append(_withheld_test(report, held))
            tests += [_manual_test(report, item) for item in report.manual]
        for test in tests:
            test["output"] = _cut(test["output"], chars)
        return {
            "gradable": True,
            "score": float(earned / maximum) if maximum else 0.0,
            "message": _message(reports, seed, earned, maximum, public, public_max,
                                drawn if dpi is None else 0),
            "tests": tests,
        }

    for dpi in (*FIGURE_DPI, None):
        data = build(dpi, TEXT_CHARS)
        if _size(data) <= limit or dpi is None:
            break
    chars = TEXT_CHARS
    while _size(data) > limit and chars > 200:  # long texts (a student's output) cut further until it fits
        chars //= 4
        data = build(None, chars)
    return data


def unloadable_results(reason: str) -> dict:
    """A submission that cannot be loaded: not gradable (it costs no attempt), the reason in ``format_errors``."""
    message = f"Your submission could not be loaded, so nothing was graded: {_cut(reason, 4_000)}"
    return {"gradable": False, "score": 0.0, "message": message, "format_errors": [message], "tests": []}


def fault_results(reason: str) -> dict:
    """A submission the grader could not grade (its fault, not the student's): not gradable, so that it costs the
    student no attempt and no score is recorded, and said plainly."""
    text = environment("text").get_template("prairielearn/fault.txt.j2").render(reason=_cut(reason, 4_000)).strip()
    return {"gradable": False, "score": 0.0, "message": text, "format_errors": [text], "tests": []}
