"""The report as plain data: ``grade problem-N --json`` (JSON, no template)."""

from __future__ import annotations

import json

from ..results import ProblemReport, student_view

__all__ = ["render_json"]


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
