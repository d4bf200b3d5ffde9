"""Figures of the problems whose answer is a motion, a shape or a configuration: drawn for the reference and for a
wrong answer alike (the student's over the reference's), kept by the gradebook, rendered as PNGs; never a change
of verdict."""

from __future__ import annotations

import base64
import re
from dataclasses import asdict

import pytest

from grader.results import Figure, Series

from .submissions import build_planted, copy_reference, planted_mistakes

#: the figure each problem draws, by check
FIGURES = {
    6: {"p06.frames": "Problem 6: the frames C1, C2, C3 in I",
        "p06.vectors": "Problem 6: V from its coordinates in I, C1, C2, C3 (mapped to I)"},
    7: {"p07.animation": "Problem 7: the frame C3 at the end of the animation"},
    8: {"p08.part_c": "Problem 8: the body's axes along the three runs"},
    9: {"p09.vectors": "Problem 9: V from its coordinates in I, C1, C2, C3 (mapped to I by problem 6's frames)"},
    14: {"p14.run_screw": "Problem 14: the body's path and its screw axis at t = 0, 0.25, 0.5, 0.75, 1 s"},
    17: {"p17.ellipsoid": "Problem 17: the ellipsoids of the sheet's matrices"},
    21: {"p21.sheet_target": "Problem 21: the arm of case (2) with q_b"},
    22: {"p22.sheet_target": "Problem 22: the arm at q3 (reference) and your end effector"},
    26: {"p26.jacobian_derivative": "Problem 26: the chairoplane at beta = 0.7, phi = 0.4"},
}


def spatial_figure():
    return Figure("frames", "x", "y", (
        Series("reference: x-axis", (0.0, 1.0), (0.0, 0.0), "reference", (0.0, 0.0), "tab:red", "", 0),
        Series("yours: x-axis", (0.0, 0.0), (0.0, 1.0), "student", (0.0, 0.0), "tab:red", "o", 1),
    ), True, "z", ("C1", "C2"))


def test_a_figure_in_space_with_panels_renders_and_survives_the_gradebook():
    from grader.batch.gradebook import _figure
    from grader.report.figures import _figure_png

    fig = spatial_figure()
    assert fig.spatial and _figure(asdict(fig)) == fig
    png = base64.b64decode(_figure_png(fig))
    assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 5000
    old = {"title": "q(t)", "xlabel": "t", "ylabel": "q", "equal_axes": False,
           "series": [{"label": "yours", "x": [0.0, 1.0], "y": [0.0, 0.5], "role": "student"}]}
    assert not _figure(old).spatial and _figure(old).series[0].panel == 0  # rows written before 3-D figures


def _figures(report):
    return {r.check_id: [f.title for f in r.figures] for r in report.results if r.figures}


@pytest.fixture(scope="module")
def reference_reports(tmp_path_factory):
    """Every problem with a shape, graded on the reference."""
    from grader.runner import grade_submission

    return grade_submission(copy_reference(tmp_path_factory.mktemp("figures") / "ref"), sorted(FIGURES))


@pytest.mark.slow
def test_every_problem_with_a_shape_draws_it_for_the_reference(reference_reports):
    from grader.report.html import render_html

    reports = reference_reports
    for report in reports:
        assert report.score == report.auto_max_score, report.problem
        drawn = _figures(report)
        for check_id, title in FIGURES[report.problem].items():
            assert drawn.get(check_id) == [title], (check_id, drawn)
            fig = next(f for r in report.results if r.check_id == check_id for f in r.figures)
            roles = {s.role for s in fig.series}
            assert {"student", "reference"} <= roles, (check_id, roles)
            assert "could not be drawn" not in fig.title + " ".join(fig.panels)
    html = render_html(reports)
    assert len(re.findall(r'src="data:image/png;base64,', html)) == sum(len(f) for f in FIGURES.values())


@pytest.mark.slow
@pytest.mark.parametrize("name", ["p06-frames-order", "p14-screw-sign-flip", "p17-ellipsoid-semi-axes",
                                  "p22-sheet-degrees"])
def test_a_wrong_answer_is_drawn_beside_its_failure(name, tmp_path):
    from grader.runner import grade_submission

    (mistake,) = [m for m in planted_mistakes() if m.name == name]
    (report,) = grade_submission(build_planted(mistake, tmp_path / "pkg"), [mistake.problem])
    failed = {r.check_id for r in report.results if not r.passed}
    assert mistake.check in failed
    drawn = _figures(report)
    assert drawn.get(mistake.check) == [FIGURES[mistake.problem][mistake.check]], drawn
    fig = next(f for r in report.results if r.check_id == mistake.check for f in r.figures)
    assert "student" in {s.role for s in fig.series}  # the wrong answer is drawn, over the reference's


# ------------------------------------------------------------------------------------------ layout without clipping

def _curve(label, role, panel=0, spatial=False, scale=1.0, n=50):
    xs = tuple(float(i) / n for i in range(n))
    ys = tuple(scale * (x * x - 0.3) for x in xs)
    zs = tuple(1.0 - x for x in xs) if spatial else ()
    return Series(label, xs, ys, role, zs, "", "", panel)


LONG = "yours: the seat (the mean of yours at q + h and q - h, in metres)"
SHAPES = {
    "one panel, wide tick labels, a long title": Figure(
        "Problem 37, computed torques: the end effector's position against the desired one, in metres, over 2 s",
        "t [s]", "I_r_E [m]", (_curve("yours: x", "student", scale=-123456.7), _curve("reference: x", "reference"))),
    "three panels, a long legend": Figure(
        "Problem 46: the robot caught by the wire", "t [s]", "q [rad]",
        tuple(_curve(f"{who}: joint {j} of the robot", who, panel=p)
              for p in range(3) for j in range(4) for who in ("yours", "reference")), panels=("a", "b", "c")),
    "one panel in space, a long legend label": Figure(
        "Problem 26: the chairoplane at beta = 0.7, phi = 0.4", "x1 [m]", "x3 [m]",
        (_curve(LONG, "student", spatial=True), _curve("reference: seat", "reference", spatial=True)), zlabel="x2"),
    "one named panel in space": Figure(
        "Problem 7: the frame C3 at the end of the animation", "x", "y",
        (_curve("yours: x-axis", "student", spatial=True),), zlabel="z", panels=("C3 at t = pi",)),
    "four panels in space": Figure(
        "Problem 17: the ellipsoids of the sheet's matrices", "x [m]", "y [m]",
        tuple(_curve("yours: ellipsoid", "student", panel=p, spatial=True) for p in range(4)), zlabel="z [m]",
        panels=("matrix 1", "matrix 2", "matrix 3", "matrix 4")),
}


@pytest.mark.parametrize("shape", sorted(SHAPES))
def test_a_figure_holds_all_its_text(shape):
    """The margins are set rather than measured on the whole figure: every title, label, tick label and legend
    entry still lies inside the picture, and a legend under panels stays clear of their axis labels."""
    from grader.report.figures import _pyplot, figure_canvas

    canvas = figure_canvas(SHAPES[shape])
    try:
        canvas.canvas.draw()
        renderer = canvas.canvas.get_renderer()
        width, height = canvas.bbox.width, canvas.bbox.height
        parts = {f"axes {i + 1}": ax.get_tightbbox(renderer) for i, ax in enumerate(canvas.axes)}
        parts.update({f"legend {i + 1}": legend.get_window_extent(renderer) for i, legend in enumerate(canvas.legends)})
        parts.update({f"legend of axes {i + 1}": ax.get_legend().get_window_extent(renderer)
                      for i, ax in enumerate(canvas.axes) if ax.get_legend()})
        if canvas._suptitle is not None:
            parts["title"] = canvas._suptitle.get_window_extent(renderer)
        assert any(name.startswith("legend") for name in parts)
        outside = {name: tuple(round(v) for v in box.extents) for name, box in parts.items()
                   if box.x0 < -1 or box.y0 < -1 or box.x1 > width + 1 or box.y1 > height + 1}
        assert not outside, (shape, (width, height), outside)
        if len(canvas.axes) > 1 and canvas.legends:  # under the panels, clear of their axis labels
            top = canvas.legends[0].get_window_extent(renderer).y1
            assert all(ax.xaxis.label.get_window_extent(renderer).y0 >= top - 1 for ax in canvas.axes)
    finally:
        _pyplot().close(canvas)


# ------------------------------------------------------------------------------------------ one picture, drawn once

def _two_curves(student_shift=0.0, title="Problem 38: the walker's angles"):
    reference = _curve("reference: theta", "reference")
    student = _curve("yours: theta", "student")
    student = Series(student.label, student.x, tuple(y + student_shift for y in student.y), "student")
    return Figure(title, "t [s]", "theta [rad]", (student, reference))


def test_figures_equal_to_the_pixel_are_drawn_once_and_others_anew(monkeypatch):
    """A batch's exporter draws the picture of a right answer once for every student whose curve agrees with it to
    a fraction of a pixel; a curve that differs visibly, or another title, is drawn for itself."""
    import grader.report.figures as render

    drawn = []
    canvas = render.figure_canvas
    monkeypatch.setattr(render, "figure_canvas", lambda fig: drawn.append(fig) or canvas(fig))
    monkeypatch.setattr(render, "_drawn", type(render._drawn)())
    first = render._figure_png(_two_curves())
    assert len(drawn) == 1
    assert render._figure_png(_two_curves(student_shift=1e-12)) == first  # another student's rounding noise
    assert len(drawn) == 1
    moved = render._figure_png(_two_curves(student_shift=0.02))  # 1.6 % of the curve's extent: some 7 pixels
    retitled = render._figure_png(_two_curves(title="Problem 38: the walker's rates"))
    assert len(drawn) == 3 and len({first, moved, retitled}) == 3


def test_the_pictures_kept_are_bounded(monkeypatch):
    import grader.report.figures as render

    monkeypatch.setattr(render, "_drawn", type(render._drawn)())
    monkeypatch.setattr(render, "DRAWN_KEPT", 3)
    monkeypatch.setattr(render, "_encode", lambda canvas: (render._pyplot().close(canvas), "png")[1])
    for shift in range(6):
        render._figure_png(_two_curves(student_shift=float(shift)))
    assert len(render._drawn) == 3


@pytest.mark.parametrize("values", [
    (0.0, 1.0, 0.5, 1.0 / 3.0), (-123456.7, 0.001, 5e4), (1e-9, 2e-9, 3.3e-9), (7.25, 7.25, 7.25),
    (0.0, 0.0), (float("nan"), 1.0, float("inf"), -2.0), (1e308, -1e308, 0.0), (0.0, 1e-320), ()])
def test_on_the_grid_no_point_moves_by_a_tenth_of_a_pixel(values):
    """The grid is at most 1/4096 of a panel's extent, and the widest panel is under 600 px: a point moves by at
    most 1/8192 of the extent (0.07 px); values that are not finite stay as they are."""
    import math

    from grader.report.figures import on_grid

    fig = Figure("f", "x", "y", (Series("yours", values, values, "student"),))
    (series,) = on_grid(fig).series
    finite = [v for v in values if math.isfinite(v)]
    extent = (max(finite) - min(finite)) if finite else 0.0
    extent = extent if 0 < extent < math.inf else max((abs(v) for v in finite), default=0.0)
    for before, after in zip(values, series.y):
        if math.isfinite(before) and math.isfinite(extent):
            assert abs(after - before) <= extent / 8192 + 1e-300, (before, after, extent)
        else:
            assert before == after or (math.isnan(before) and math.isnan(after))
    assert len(series.x) == len(values) and series.role == "student"


# ------------------------------------------------------------------------------------------ figures that read


def _frames_figure(panels: int = 3) -> Figure:
    """Frames in space as problem 6 draws them: the student's right answer over the reference's, a panel each."""
    import numpy as np

    series = []
    for panel in range(panels):
        angle = 0.6 * (panel + 1)
        axes = np.array([[np.cos(angle), np.sin(angle), 0.3], [-np.sin(angle), np.cos(angle), 0.2], [0.1, -0.2, 1.0]])
        for k, colour in enumerate(("tab:red", "tab:green", "tab:blue")):
            end = axes[k] / np.linalg.norm(axes[k])
            for role, who in (("reference", "reference"), ("student", "yours")):
                series.append(Series(f"{who}: {'xyz'[k]}-axis", (0.0, float(end[0])), (0.0, float(end[1])), role,
                                     (0.0, float(end[2])), colour, "", panel))
    return Figure("Problem 6: the frames C1, C2, C3 in I", "x", "y", tuple(series), True, "z",
                  tuple(f"C{p + 1}" for p in range(panels)))


def _overlapping(labels, renderer) -> list[tuple[str, str]]:
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in labels if t.get_visible() and t.get_text()]
    return [(a, b) for i, (a, first) in enumerate(boxes) for b, second in boxes[i + 1:]
            if first.x0 < second.x1 - 1 and second.x0 < first.x1 - 1 and first.y0 < second.y1 - 1
            and second.y0 < first.y1 - 1]


def _texts_3d(ax) -> list:
    """The tick labels that 3-D axes drew (of ticks within their limits, where the last drawing put them: asking
    for the tick labels would lay them out anew, in 2-D), and the axes' names."""
    texts = []
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        low, high = sorted(axis.get_view_interval())
        texts += [tick.label1 for tick in axis.majorTicks if low <= tick.get_loc() <= high]
        texts.append(axis.label)
    return texts


@pytest.mark.parametrize("panels", [1, 3, 4])
def test_tick_labels_in_space_do_not_overlap(panels):
    """Neither the tick labels of one axis, nor those of two axes where they meet, nor an axis's name over them."""
    from grader.report.figures import _pyplot, figure_canvas

    canvas = figure_canvas(_frames_figure(panels))
    try:
        canvas.canvas.draw()
        renderer = canvas.canvas.get_renderer()
        crowded = {f"axes {i + 1}": pairs for i, ax in enumerate(canvas.axes)
                   if (pairs := _overlapping(_texts_3d(ax), renderer))}
        assert not crowded, crowded
    finally:
        _pyplot().close(canvas)


def test_a_right_answer_leaves_the_reference_visible():
    """The student's curve exactly on the reference's: the reference's pale colour still shows around it."""
    import io

    import numpy as np
    from matplotlib import image

    from grader.report.figures import _figure_drawn

    png, facts = _figure_drawn(_frames_figure(1))
    pixels = image.imread(io.BytesIO(base64.b64decode(png)))[..., :3]
    assert len(facts["reference"]) == 3
    for colour in facts["reference"]:
        rgb = np.array([int(colour[i:i + 2], 16) for i in (1, 3, 5)]) / 255
        shown = np.sum(np.abs(pixels - rgb).max(axis=-1) < 0.03)
        assert shown > 100, (colour, shown)


@pytest.mark.slow
def test_no_figure_in_space_of_the_reference_crowds_its_text(reference_reports):
    from grader.report.figures import _pyplot, figure_canvas, on_grid

    crowded = {}
    for report in reference_reports:
        for result in report.results:
            for fig in result.figures:
                if not fig.spatial:
                    continue
                canvas = figure_canvas(on_grid(fig))
                try:
                    canvas.canvas.draw()
                    renderer = canvas.canvas.get_renderer()
                    crowded.update({f"{fig.title}, axes {i + 1}": pairs for i, ax in enumerate(canvas.axes)
                                    if (pairs := _overlapping(_texts_3d(ax), renderer))})
                finally:
                    _pyplot().close(canvas)
    assert not crowded, crowded
