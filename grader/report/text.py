"""The report on a terminal: ``grade problem-N``'s output, written through the terminal's template environment
(every expression inert)."""

from __future__ import annotations

from ..results import ProblemReport, student_view
from ..terminal import styled
from .environment import environment

__all__ = ["render_terminal", "COLOURS"]

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


def render_terminal(reports: list[ProblemReport], colour: bool = False, show_hidden: bool = False) -> str:
    def paint(text, key):
        return styled(text, COLOURS[key]) if colour and key in COLOURS else text

    def bold(text):
        return styled(text, "1") if colour else text

    if not show_hidden:
        reports = [student_view(r) for r in reports]
    template = environment("terminal").get_template("terminal.txt.j2")
    return template.render(reports=reports, paint=paint, bold=bold, show_hidden=show_hidden).strip("\n") + "\n"
