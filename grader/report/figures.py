"""Figures as pictures: a result's ``Figure`` (the student's curves over the reference's) drawn with matplotlib,
laid out to read at the report's text size, and encoded as a base64 PNG; ``png`` draws a plain plot (the class
summary's).  matplotlib is imported only when a picture is drawn."""

from __future__ import annotations

import base64
import hashlib
import io
import math
from collections import OrderedDict
from dataclasses import replace

from ..results import Figure

__all__ = ["png", "figure_canvas", "on_grid"]


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
    _place(canvas, [ax], _lines(ax.get_title()), 0.0, 0.0, False)
    return _encode(canvas)


#: the line of a curve by its role (style, width in points, drawing order): the reference's wide and pale beneath,
#: the student's thin on top, so that a right answer shows the reference around it; other curves dotted
STYLES = {"student": ("-", 1.6, 3), "reference": ("-", 6.0, 1)}
OTHER_STYLE = (":", 1.4, 2)
#: how much of its colour the reference's line keeps (the rest is white): pale, opaque, whatever lies beneath
REFERENCE_TINT = 0.4
#: the report's text [px], and the width [px] its column gives a figure in a 1280 px window (report.html.j2: a
#: 60rem page): legends, titles and axis labels are drawn so that they show at the report's text size even when a
#: wide figure is scaled down to that column; tick labels a little smaller
TEXT_PX = 15.0
COLUMN_PX = 800.0
TICK_SHARE = 0.8
#: the tick marks of each axis in space, at most (more crowd their labels into each other), and the room between
#: their labels and the axis's name [pt]
TICKS_3D = 4
LABEL_PAD_3D = 14
#: inches of one panel: one panel alone is as wide as a plot of the class summary, panels side by side narrower
PANEL = {1: (6.4, 4.2), 2: (4.4, 4.0)}
#: panels side by side in one row, at most: more go on into further rows, so that a figure fits the report's column
#: (``COLUMN_PX``) at its own size and its text is not scaled down
ACROSS = 2
#: inches of a single panel in space (its legend stands beside it, in room added to the figure's width)
SPATIAL = (5.6, 4.6)
#: a figure's margins in inches, set rather than measured (measuring the whole figure, as ``tight_layout`` and a
#: tight bounding box do, costs a drawing of it each): room left of and below 2-D axes for tick labels and an axis
#: label (more when the tick labels are wider), above them for each line of title; 3-D axes draw their tick labels
#: within their own box
MARGINS = {"left": 0.85, "bottom": 0.65, "right": 0.35, "top": 0.15, "title_line": 0.28, "legend_gap": 0.1}
MARGINS_3D = {"left": 0.05, "bottom": 0.55, "right": 0.3, "top": 0.1}
#: the figures' resolution [dots per inch]
DPI = 90


def _lines(text: str) -> int:
    return text.count("\n") + 1 if text else 0


def _legend_entries(axes) -> dict:
    """Each label once (the three axes of a frame share the colour of their axis, not of their frame)."""
    entries = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            entries.setdefault(label, handle)
    return entries


def _left_room(canvas, ax) -> float:
    """Inches left of 2-D axes that their tick labels and axis label take (the labels' text measured alone)."""
    renderer = canvas.canvas.get_renderer()
    low, high = sorted(ax.get_ylim())
    ticks = [t.get_window_extent(renderer).width for t in ax.get_yticklabels()
             if t.get_text() and low <= t.get_position()[1] <= high]
    label = ax.yaxis.label.get_window_extent(renderer).width if ax.get_ylabel() else 0.0
    return (max(ticks, default=0.0) + label) / canvas.dpi + 0.25


def _place(canvas, axes, title_lines: int, below: float, beside: float, spatial: bool, rows: int = 1,
           panel_title_lines: int = 0) -> None:
    """Put the axes in the figure with the fixed margins, ``below`` and ``beside`` inches kept free for a legend;
    ``rows`` of panels, each under the x labels of the one above and its own title (``panel_title_lines``)."""
    width, height = canvas.get_figwidth(), canvas.get_figheight()
    m = MARGINS_3D if spatial else dict(MARGINS, left=max(MARGINS["left"], *(_left_room(canvas, ax) for ax in axes)))
    top = m["top"] + MARGINS["title_line"] * title_lines
    between = m["left"] + m["right"]  # one panel's tick labels and the next one's axis label
    across = -(-len(axes) // rows)
    inner = (width - m["left"] - m["right"] - beside - between * (across - 1)) / across
    under = MARGINS["bottom"] + m["top"] + MARGINS["title_line"] * panel_title_lines  # between two rows
    tall = (height - top - m["bottom"] - below - under * (rows - 1)) / rows
    canvas.subplots_adjust(left=m["left"] / width, right=1 - (m["right"] + beside) / width,
                           bottom=(m["bottom"] + below) / height, top=1 - top / height,
                           wspace=between / inner if across > 1 else 0.2, hspace=under / tall if rows > 1 else 0.2)


def _pale(colour) -> tuple[float, float, float]:
    from matplotlib.colors import to_rgb

    return tuple(REFERENCE_TINT * c + (1 - REFERENCE_TINT) for c in to_rgb(colour))


def _draw_series(ax, series) -> None:
    style, width, order = STYLES.get(series.role, OTHER_STYLE)
    options = {"linewidth": width, "label": series.label, "zorder": order, "solid_capstyle": "round"}
    if series.colour:
        options["color"] = series.colour
    if series.marker:
        options.update(marker=series.marker, markersize=6 if series.role == "student" else 11)
    coordinates = (series.x, series.y, series.z) if series.z else (series.x, series.y)
    (line,) = ax.plot(*coordinates, style, **options)
    if series.role == "reference":  # its own colour (or the cycle's), pale: told apart from the student's on top
        line.set_color(_pale(line.get_color()))
        line.set_gid("reference")


def _points(px: float, shown: float) -> float:
    """The font size [pt] at the figure's dpi that shows as ``px`` pixels once the figure is scaled by ``shown``."""
    return px / shown / DPI * 72


def _readable(canvas, axes, spatial: bool) -> float:
    """Titles, axis labels and tick labels at the report's text size (``TEXT_PX``) as the figure will be shown:
    scaled down to the report's column when it is wider.  In space, at most ``TICKS_3D`` ticks per axis.  Returns
    the font size of the legend [pt]."""
    from matplotlib.ticker import MaxNLocator

    shown = min(1.0, COLUMN_PX / (canvas.get_figwidth() * DPI))
    text, ticks = _points(TEXT_PX, shown), _points(TEXT_PX * TICK_SHARE, shown)
    for ax in axes:
        ax.title.set_fontsize(text)
        ax.xaxis.label.set_fontsize(text)
        ax.yaxis.label.set_fontsize(text)
        ax.tick_params(labelsize=ticks)
        if spatial:
            ax.zaxis.label.set_fontsize(text)
            ax.computed_zorder = False  # the drawing order of the curves holds: the student's on top
            for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
                axis.set_major_locator(MaxNLocator(TICKS_3D))
                axis.labelpad = LABEL_PAD_3D
    return text


def _wrap(title: str, inches: float, points: float = 10.0) -> str:
    """A title broken into lines that fit ``inches`` of width at a font of ``points``."""
    import textwrap

    per_inch = 72 / (0.6 * points)  # characters of an average width
    return "\n".join(textwrap.wrap(title, max(16, int(inches * per_inch)))) if title else title


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


def _inches(canvas, artist) -> tuple[float, float]:
    """Width and height of one artist in inches, measured with the figure's renderer (its text alone is laid out,
    not the figure drawn)."""
    box = artist.get_window_extent(canvas.canvas.get_renderer())
    return box.width / canvas.dpi, box.height / canvas.dpi


def figure_canvas(fig):
    """The matplotlib figure of a result's figure, laid out: the student's curves solid, the reference's dashed;
    panels side by side, on 3-D axes for a figure in space; one legend, each label once: in a single 2-D panel,
    beside a single 3-D panel, under panels side by side (the figure grows to hold it)."""
    plt = _pyplot()
    panels = fig.panels or ("",)
    width, height = SPATIAL if fig.spatial and len(panels) == 1 else PANEL[min(len(panels), ACROSS)]
    across = min(len(panels), ACROSS)
    rows = -(-len(panels) // across)
    total = width * across
    canvas = plt.figure(figsize=(total, height * rows), dpi=DPI)
    text = _points(TEXT_PX, min(1.0, COLUMN_PX / (total * DPI)))
    axes = []
    for index, name in enumerate(panels):
        ax = canvas.add_subplot(rows, across, index + 1, projection="3d" if fig.spatial else None)
        mine = [s for s in fig.series if s.panel == index]
        for series in mine:
            _draw_series(ax, series)
        ax.set_title(_wrap(name if fig.panels else fig.title, width, text))
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
    text = _readable(canvas, axes, fig.spatial)
    entries = _legend_entries(axes)
    heading = _wrap(fig.title, total, text) if fig.panels else ""
    below = beside = 0.0
    under = len(axes) > 1
    if entries and fig.spatial and not under:  # beside the single panel in space, in room added to the figure ...
        legend = canvas.legend(entries.values(), entries.keys(), fontsize=text, loc="upper right",
                               bbox_to_anchor=(1.0, 1.0))
        beside = _inches(canvas, legend)[0] + MARGINS["legend_gap"]
        if (total + beside) * DPI <= COLUMN_PX:
            canvas.set_figwidth(total + beside)
        else:  # ... unless the figure would be wider than the report's column: then under it
            legend.remove()
            beside, under = 0.0, True
    if entries and under:  # under the panels: as many columns (up to four) as the width holds
        for columns in range(min(len(entries), 4), 0, -1):
            legend = canvas.legend(entries.values(), entries.keys(), fontsize=text, loc="lower center",
                                   ncol=columns, frameon=False, bbox_to_anchor=(0.5, 0.0))
            wide, tall = _inches(canvas, legend)
            if wide <= total or columns == 1:
                break
            legend.remove()
        below = tall + MARGINS["legend_gap"]
        canvas.set_figheight(height * rows + below)
        if wide > total:  # one entry wider than the panels: the figure takes the legend's width
            canvas.set_figwidth(wide + MARGINS["legend_gap"] * 2)
    elif entries and not fig.spatial:
        axes[0].legend(entries.values(), entries.keys(), fontsize=text, loc="best")
    if heading:
        canvas.suptitle(heading, y=1 - MARGINS["top"] / canvas.get_figheight() / 2, va="top", fontsize=text)
    panel_lines = max(_lines(ax.get_title()) for ax in axes)
    _place(canvas, axes, panel_lines + _lines(heading), below, beside, fig.spatial, rows, panel_lines)
    return canvas


#: a figure's coordinates are drawn on a grid of 1/4096 of their panel's extent (a power of two at most that, so
#: that the grid does not move with a tiny change of the extent): the widest panel is under 600 px at the report's
#: 90 dpi, so no point moves by a tenth of a pixel.  Figures equal on that grid are one picture, drawn once per
#: process: a batch's exporter draws the figure of a right answer once for every student whose answer agrees with
#: it to the pixel, rather than once per student
GRID = 1 / 4096
#: pictures kept by ``_figure_png`` (each some 30-100 kB of base64 text)
DRAWN_KEPT = 256
_drawn: OrderedDict[bytes, tuple[str, dict]] = OrderedDict()


def _grid_step(values) -> float:
    import numpy as np

    finite = values[np.isfinite(values)]
    with np.errstate(over="ignore"):
        extent = float(finite.max() - finite.min()) if finite.size else 0.0
    if extent == 0.0:
        extent = float(np.abs(finite).max()) if finite.size else 0.0
    # the power of two from the extent's own exponent: extent * GRID may underflow (a subnormal extent), and a
    # step that underflows to zero leaves the values as they are
    return 2.0 ** (math.floor(math.log2(extent)) + math.floor(math.log2(GRID))) if 0.0 < extent < math.inf else 0.0


def on_grid(fig: Figure) -> Figure:
    """The figure with each coordinate rounded to its panel's grid (``GRID``); what ``_figure_png`` draws."""
    import numpy as np

    series = list(fig.series)
    for panel in {s.panel for s in series}:
        members = [i for i, s in enumerate(series) if s.panel == panel]
        for axis in ("x", "y", "z"):
            columns = [np.asarray(getattr(series[i], axis), dtype=float) for i in members]
            if not any(c.size for c in columns):
                continue
            step = _grid_step(np.concatenate(columns))
            if not step:
                continue
            for i, column in zip(members, columns):
                with np.errstate(invalid="ignore", over="ignore"):
                    rounded = np.round(column / step) * step
                series[i] = replace(series[i], **{axis: tuple(rounded.tolist())})
    return replace(fig, series=tuple(series))


def _figure_key(fig: Figure) -> bytes:
    import numpy as np

    digest = hashlib.blake2b(digest_size=20)
    digest.update(repr((fig.title, fig.xlabel, fig.ylabel, fig.zlabel, fig.equal_axes, fig.panels)).encode())
    for s in fig.series:
        digest.update(repr((s.label, s.role, s.colour, s.marker, s.panel, len(s.x), len(s.y), len(s.z))).encode())
        for values in (s.x, s.y, s.z):
            digest.update(np.asarray(values, dtype=float).tobytes())
    return digest.digest()


def _figure_png(fig: Figure) -> str:
    """A result's figure as a base64 PNG, drawn from its coordinates on the grid (``on_grid``): once per process
    for each different picture."""
    return _figure_drawn(fig)[0]


def _facts(canvas) -> dict:
    """What the report says of a picture beside it (``data-`` attributes of its image, for whoever checks how it
    shows): the legend's text [px of the picture] and the colours of the reference's lines."""
    from matplotlib.colors import to_hex

    legends = [*canvas.legends, *(ax.get_legend() for ax in canvas.axes if ax.get_legend())]
    text = max((t.get_fontsize() for legend in legends for t in legend.get_texts()), default=0.0)
    colours = sorted({to_hex(line.get_color()) for ax in canvas.axes for line in ax.get_lines()
                      if line.get_gid() == "reference"})
    return {"text_px": round(text / 72 * canvas.dpi, 2), "reference": colours}


def _figure_drawn(fig: Figure) -> tuple[str, dict]:
    """``_figure_png``'s picture, and its ``_facts``."""
    fig = on_grid(fig)
    key = _figure_key(fig)
    drawn = _drawn.get(key)
    if drawn is None:
        canvas = figure_canvas(fig)
        facts = _facts(canvas)
        drawn = _drawn[key] = (_encode(canvas), facts)
        while len(_drawn) > DRAWN_KEPT:
            _drawn.popitem(last=False)
    else:
        _drawn.move_to_end(key)
    return drawn
