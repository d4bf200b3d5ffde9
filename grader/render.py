"""Renderers: every report goes out through a jinja2 template (terminal text, HTML) or as plain data (JSON,
Gradescope's results.json)."""

from __future__ import annotations

import base64
import io
import json
from functools import lru_cache

from jinja2 import Environment, FileSystemBytecodeCache, PackageLoader, StrictUndefined

from .results import ProblemReport, Status, student_view

__all__ = ["render_terminal", "render_html", "render_json", "gradescope_results", "render_gradescope"]

COLOURS = {
    "passed": "32",
    "failed": "31",
    "error": "31",
    "timeout": "31",
    "not_implemented": "33",
    "skipped": "90",
    "grader_error": "35",
    "deferred": "34",
    "hint": "36",
}


def _fmt(x) -> str:
    return f"{x:g}"


@lru_cache(maxsize=2)
def _env(autoescape: bool) -> Environment:
    """The templates' environment.  Compiled templates are kept in jinja2's own per-user cache (a folder under the
    temporary directory that jinja2 makes readable by its owner only and refuses if anyone else owns it), so that a
    command compiles a template once rather than at every run."""
    env = Environment(
        loader=PackageLoader("grader", "templates"),
        bytecode_cache=FileSystemBytecodeCache(),
        autoescape=autoescape,
        undefined=StrictUndefined,
        trim_blocks=False,
        keep_trailing_newline=True,
    )
    env.globals["fmt"] = _fmt
    return env


def render_terminal(reports: list[ProblemReport], colour: bool = False, show_hidden: bool = False) -> str:
    def paint(text, key):
        return f"\033[{COLOURS[key]}m{text}\033[0m" if colour and key in COLOURS else text

    def bold(text):
        return f"\033[1m{text}\033[0m" if colour else text

    if not show_hidden:
        reports = [student_view(r) for r in reports]
    template = _env(False).get_template("terminal.txt.j2")
    return template.render(reports=reports, paint=paint, bold=bold, show_hidden=show_hidden).strip("\n") + "\n"


def png(draw, height: float = 4.2) -> str:
    """A base64 PNG of what ``draw(ax)`` puts on one matplotlib axes (imported only when a plot is drawn)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    canvas, ax = plt.subplots(figsize=(6.4, height), dpi=90)
    draw(ax)
    ax.grid(True, alpha=0.3)
    canvas.tight_layout()
    buffer = io.BytesIO()
    canvas.savefig(buffer, format="png")
    plt.close(canvas)
    return base64.b64encode(buffer.getvalue()).decode()


def _figure_png(fig) -> str:
    """A result's figure: the student's curves solid, the reference's dashed."""

    def draw(ax):
        for series in fig.series:
            style = {"student": "-", "reference": "--"}.get(series.role, ":")
            width = 2.2 if series.role == "student" else 1.4
            ax.plot(series.x, series.y, style, linewidth=width, label=series.label)
        ax.set_title(fig.title)
        ax.set_xlabel(fig.xlabel)
        ax.set_ylabel(fig.ylabel)
        if fig.equal_axes:
            ax.set_aspect("equal", adjustable="datalim")
        ax.legend(fontsize="small")

    return png(draw)


def render_html(reports: list[ProblemReport], show_hidden: bool = False, title: str = "Grading report") -> str:
    if not show_hidden:
        reports = [student_view(r) for r in reports]
    images = {}
    for report in reports:
        for result in report.results:
            if result.visibility == "visible" or show_hidden:
                for index, fig in enumerate(result.figures):
                    images[(result.check_id, index)] = _figure_png(fig)
    template = _env(True).get_template("report.html.j2")
    return template.render(reports=reports, images=images, show_hidden=show_hidden, title=title, Status=Status)


def _visible_dict(report: ProblemReport, show_hidden: bool) -> dict:
    data = report.to_dict() if show_hidden else student_view(report).to_dict()
    if not show_hidden:
        for item in data["manual"]:
            item.pop("model_answer")
        hidden = [r for r in data["results"] if r["visibility"] == "hidden"]
        data["results"] = [r for r in data["results"] if r["visibility"] != "hidden"]
        data["hidden_checks"] = {"count": len(hidden), "max_score": sum(r["max_score"] for r in hidden)}
        data.pop("score")
        data["visible_score"] = sum(r["score"] for r in data["results"])
    for result in data["results"]:
        result.pop("figures", None)
        result["figure_count"] = len([f for r in report.results if r.check_id == result["check_id"]
                                      for f in r.figures])
    return data


def render_json(reports: list[ProblemReport], show_hidden: bool = True) -> str:
    return json.dumps({"reports": [_visible_dict(r, show_hidden) for r in reports]}, indent=2) + "\n"


def gradescope_results(reports: list[ProblemReport]) -> dict:
    """Gradescope's autograder results format: one test per check, hidden checks after the due date."""
    tests = []
    for report in reports:
        for r in report.results:
            output = "\n".join(part for part in (r.message, f"hint: {r.hint}" if r.hint else "") if part)
            if report.load_error:
                output = "not run: the submission could not be loaded (the reason is at the top)"
            tests.append(
                {
                    "name": f"Problem {r.problem}: {r.title}",
                    "number": r.check_id,
                    "score": r.score,
                    "max_score": r.max_score,
                    "status": "passed" if r.passed else "failed",
                    "output": output or "passed",
                    "visibility": "after_due_date" if r.visibility == "hidden" else "visible",
                    "tags": [f"problem-{r.problem}"] + ([r.diagnosis] if r.diagnosis else []),
                }
            )
        for m in report.manual:
            tests.append(
                {
                    "name": f"Problem {m.problem}: {m.question} (scored by hand)",
                    "number": f"p{m.problem:02d}.free_text.{m.key}",
                    "score": m.score or 0.0,
                    "max_score": m.max_score,
                    "output": f"Your answer:\n{m.answer or '(blank)'}\n\nScored by hand; 0 until a person scores it.",
                    "visibility": "visible",
                    "tags": ["manual"],
                }
            )
    notes = sorted({r.sandbox for r in reports if not r.isolated})
    load_errors = list(dict.fromkeys(r.load_error for r in reports if r.load_error))
    # No top-level "score": Gradescope then totals the tests itself and applies each test's visibility.
    return {
        "output": "".join(f"Your submission could not be loaded: {e}\n\n" for e in load_errors)
        + "Automatically graded checks; free-text answers are scored by hand." + (" " + " ".join(notes) if notes else ""),
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "tests": tests,
    }


def render_gradescope(reports: list[ProblemReport]) -> str:
    return json.dumps(gradescope_results(reports), indent=2) + "\n"
