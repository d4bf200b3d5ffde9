"""Renderers: every report goes out through a jinja2 template (terminal text, HTML) or as plain data (JSON;
Gradescope's results.json comes from its one builder, ``grader.gradescope.results_json``)."""

from __future__ import annotations

import base64
import io
import json
from functools import lru_cache

from jinja2 import Environment, FileSystemBytecodeCache, PackageLoader, StrictUndefined

from .results import ProblemReport, Status, student_view

__all__ = ["render_terminal", "render_html", "render_json", "render_gradescope"]

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


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _encode(canvas, tight: bool = False) -> str:
    buffer = io.BytesIO()
    canvas.savefig(buffer, format="png", bbox_inches="tight" if tight else None)
    _pyplot().close(canvas)
    return base64.b64encode(buffer.getvalue()).decode()


def png(draw, height: float = 4.2) -> str:
    """A base64 PNG of what ``draw(ax)`` puts on one matplotlib axes (imported only when a plot is drawn)."""
    canvas, ax = _pyplot().subplots(figsize=(6.4, height), dpi=90)
    draw(ax)
    ax.grid(True, alpha=0.3)
    canvas.tight_layout()
    return _encode(canvas)


#: the line of a curve by its role: the student's solid and wider, the reference's dashed
STYLES = {"student": ("-", 2.2), "reference": ("--", 1.4)}
#: inches of one panel: one panel alone is as wide as a plot of the class summary, panels side by side narrower
PANEL = {1: (6.4, 4.2), 2: (4.6, 4.2), 3: (4.0, 3.9), 4: (3.4, 3.6)}
#: a figure in space of one panel is wider: its legend stands beside the axes, not over them
SPATIAL = (8.0, 4.6)


def _legend(axes, canvas) -> None:
    """One legend for the figure, each label once (the three axes of a frame share the colour of their axis, not
    of their frame); in the single panel, or under the panels side by side."""
    entries = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            entries.setdefault(label, handle)
    if not entries:
        return
    if len(axes) == 1 and axes[0].name == "3d":
        axes[0].legend(entries.values(), entries.keys(), fontsize="small", loc="upper left",
                       bbox_to_anchor=(1.12, 1.0))
    elif len(axes) == 1:
        axes[0].legend(entries.values(), entries.keys(), fontsize="small", loc="best")
    else:
        canvas.legend(entries.values(), entries.keys(), fontsize="small", loc="lower center",
                      ncol=min(len(entries), 4), frameon=False)


def _wrap(title: str, inches: float) -> str:
    """A title broken into lines that fit ``inches`` of width."""
    import textwrap

    return "\n".join(textwrap.wrap(title, max(20, int(inches * 9)))) if title else title


def _equal_box(ax, series) -> None:
    """Axes of a figure in space with one scale on all three (a frame looks orthogonal, a sphere round)."""
    import numpy as np

    points = np.array([p for s in series for p in zip(s.x, s.y, s.z)], dtype=float)
    if not len(points):
        return
    low, high = points.min(axis=0), points.max(axis=0)
    centre, half = (low + high) / 2, max(float(np.max(high - low)) / 2, 1e-9) * 1.05
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1))


def _draw_series(ax, series) -> None:
    style, width = STYLES.get(series.role, (":", 1.4))
    options = {"linewidth": width, "label": series.label}
    if series.colour:
        options["color"] = series.colour
    if series.marker:
        options.update(marker=series.marker, markersize=7 if series.role == "student" else 9,
                       markerfacecolor="none" if series.role == "reference" else None)
    coordinates = (series.x, series.y, series.z) if series.z else (series.x, series.y)
    ax.plot(*coordinates, style, **options)


def _figure_png(fig) -> str:
    """A result's figure: the student's curves solid, the reference's dashed; panels side by side, on 3-D axes for
    a figure in space."""
    plt = _pyplot()
    panels = fig.panels or ("",)
    width, height = SPATIAL if fig.spatial and not fig.panels else PANEL.get(len(panels), PANEL[4])
    legend_room = 0.5 if len(panels) > 1 else 0.0
    canvas = plt.figure(figsize=(width * len(panels), height + legend_room), dpi=90)
    axes = []
    for index, name in enumerate(panels):
        ax = canvas.add_subplot(1, len(panels), index + 1, projection="3d" if fig.spatial else None)
        mine = [s for s in fig.series if s.panel == index]
        for series in mine:
            _draw_series(ax, series)
        ax.set_title(_wrap(name if fig.panels else fig.title, width), fontsize="medium")
        ax.set_xlabel(fig.xlabel)
        ax.set_ylabel(fig.ylabel)
        if fig.spatial:
            ax.set_zlabel(fig.zlabel)
            _equal_box(ax, mine)
        else:
            ax.grid(True, alpha=0.3)
            if fig.equal_axes:
                ax.set_aspect("equal", adjustable="datalim")
        axes.append(ax)
    _legend(axes, canvas)
    if fig.panels:
        canvas.suptitle(_wrap(fig.title, width * len(panels)))
    canvas.tight_layout(rect=(0, legend_room / (height + legend_room), 1, 1))
    return _encode(canvas, tight=True)


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


def render_gradescope(reports: list[ProblemReport]) -> str:
    """Gradescope's results.json: the one builder, ``grader.gradescope.results_json`` (JSON, no template)."""
    from .gradescope import render_results

    return render_results(reports)
