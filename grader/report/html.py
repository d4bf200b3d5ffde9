"""The HTML report (a student's, or an instructor's with the hidden checks) with its figures, and the report shown
inline in a Jupyter notebook."""

from __future__ import annotations

from ..results import ProblemReport, Status, student_view
from .environment import environment
from .figures import _figure_drawn

__all__ = ["render_html", "render_notebook"]


def render_html(reports: list[ProblemReport], show_hidden: bool = False, title: str = "Grading report",
                deadlines: list[str] = ()) -> str:
    """The HTML report; ``deadlines``: what the course's due dates made of the work, one line per assignment."""
    if not show_hidden:
        reports = [student_view(r) for r in reports]
    images = {}
    for report in reports:
        for result in report.results:
            if result.visibility == "visible" or show_hidden:
                for index, fig in enumerate(result.figures):
                    images[(result.check_id, index)] = _figure_drawn(fig)
    template = environment("html").get_template("report.html.j2")
    return template.render(reports=reports, images=images, show_hidden=show_hidden, title=title, Status=Status,
                           deadlines=list(deadlines))


def render_notebook(reports: list[ProblemReport], source: str, notes=(), height: int = 640) -> str:
    """The report shown inline in a notebook: a line of scores and the HTML report in a frame of its own."""
    page = render_html(reports, title=f"Problem {', '.join(str(r.problem) for r in reports)}")
    template = environment("html").get_template("notebook.html.j2")
    return template.render(reports=[student_view(r) for r in reports], page=page, source=source, notes=list(notes),
                           height=height)
