"""Figures of the problems whose answer is a motion, a shape or a configuration: the student's answer drawn over the
reference's (solid over dashed) in the HTML report.

A figure never changes a verdict.  Each ``add_*`` function takes what the check already received from the student
(raw: it may be anything) and the reference's value (through ``ctx.reference``, with arguments from the inputs
alone, made whatever the student returned, so that the student kit's key holds the call), and adds a figure; a
student's value that cannot be drawn is left out of the figure and its panel says so, nothing fails.  The one
exception, ``student_or_none``, runs a probe on the student's code only for a figure and turns any failure of the
student's code into "nothing to draw" (the checks that judge that code report the failure).
"""

import numpy as np

from grader.errors import StudentCodeError, StudentTimeout, WorkerCrash
from grader.results import Figure, Series
from probes import problem_17 as p17

__all__ = [
    "AXIS_COLOURS",
    "MAX_POINTS",
    "student_or_none",
    "add_frames",
    "add_vectors",
    "add_integrator_paths",
    "add_screw_run",
    "ellipsoid_drawer",
    "add_planar_arm",
    "seat_between",
    "add_chairoplane",
]

#: the x, y, z axes of a frame (the usual red, green, blue)
AXIS_COLOURS = ("tab:red", "tab:green", "tab:blue")
#: the figures draw at most this many points per curve
MAX_POINTS = 200
#: what a panel says when the student's value could not be drawn
UNDRAWABLE = "yours could not be drawn"
#: seconds allowed for a probe that runs only for a figure
FIGURE_TIMEOUT = 10.0
ROLES = {"student": "yours", "reference": "reference"}


def _array(value, shape=None):
    """``value`` as a finite float array (of ``shape``), or None."""
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError, OverflowError):
        return None
    if (shape is not None and array.shape != tuple(shape)) or not np.all(np.isfinite(array)):
        return None
    return array


def _entry(value, key, shape=None):
    return _array(value.get(key), shape) if isinstance(value, dict) else None


def _curve(label, points, role, colour="", marker="", panel=0):
    """A series through ``points`` (n x 2 or n x 3), thinned to ``MAX_POINTS``."""
    points = np.asarray(points, dtype=float)
    step = max(1, int(np.ceil(len(points) / MAX_POINTS)))
    if step > 1:
        points = np.concatenate([points[::step], points[-1:]])
    z = tuple(map(float, points[:, 2])) if points.shape[1] == 3 else ()
    return Series(f"{ROLES.get(role, role)}: {label}" if role in ROLES else label, tuple(map(float, points[:, 0])),
                  tuple(map(float, points[:, 1])), role, z, colour, marker, panel)


def student_or_none(ctx, probe, *args):
    """The student's ``probe`` for a figure only: None when the student's code raises, crashes or takes too long
    (the checks of that code say so)."""
    try:
        return ctx.student(probe, *args, timeout=FIGURE_TIMEOUT)
    except (StudentCodeError, StudentTimeout, WorkerCrash):
        return None


def _panel_title(name, drawn):
    return name if drawn else f"{name} ({UNDRAWABLE})"


# ------------------------------------------------------------------------------------------ frames


def _triad(A, role, panel, origin=np.zeros(3), scale=1.0):
    """The three axes of the frame whose orientation is ``A`` (its columns), from ``origin``."""
    return [_curve(f"{axis}-axis", np.array([origin, origin + scale * A[:, k]]), role, AXIS_COLOURS[k], panel=panel)
            for k, axis in enumerate("xyz")]


def _inertial(panel, scale=1.0):
    return [_curve("I", np.array([np.zeros(3), scale * np.eye(3)[k]]), "other", "0.7", panel=panel)
            for k in range(3)]


def _frames_figure(title, got, expected, names, labels):
    series, panels = [], []
    for panel, (name, label) in enumerate(zip(names, labels)):
        mine = _entry(got, name, (3, 3))
        series += _inertial(panel) + _triad(np.asarray(expected[name], dtype=float), "reference", panel)
        if mine is not None:
            series += _triad(mine, "student", panel)
        panels.append(_panel_title(label, mine is not None))
    return Figure(title, "x", "y", tuple(series), True, "z", tuple(panels))


def add_frames(ctx, title, got, expected, names, labels=None):
    """Frames as 3-D axes (x, y, z red, green, blue; yours solid, the reference's dashed, I in grey), one panel per
    entry ``names`` of the dicts ``got`` and ``expected`` (orientations A_IC)."""
    ctx.add_figure(_frames_figure(title, got, expected, names, labels or [n.replace("A_I", "") for n in names]))


def add_vectors(ctx, title, got, frames, target):
    """The vector V as the student's coordinates in I, C1, C2, C3 put it, each mapped back to I by the reference's
    frames (``A_ICk @ Ck_v``): five arrows that coincide when every coordinate is right."""
    series = _inertial(0, 2.0) + [_curve("I_v", np.array([np.zeros(3), target]), "reference", "black")]
    colours = ("tab:purple", "tab:red", "tab:green", "tab:blue")
    for colour, key in zip(colours, ("I_v", "C1_v", "C2_v", "C3_v")):
        v = _entry(got, key, (3,))
        if v is not None:
            A = np.eye(3) if key == "I_v" else np.asarray(frames[f"A_I{key[:2]}"], dtype=float)
            mapped = "I_v" if key == "I_v" else f"A_I{key[:2]} @ {key}"
            series.append(_curve(mapped, np.array([np.zeros(3), A @ v]), "student", colour))
    ctx.add_figure(Figure(title, "x", "y", tuple(series), True, "z"))


# ------------------------------------------------------------------------------------------ problem 8

INTEGRATORS = {"a": "(a) Euler on A_IC", "b": "(b) Euler on the Cardan angles", "c": "(c) exponential"}


def add_integrator_paths(ctx, title, got, expected):
    """The three integrators of problem 8 side by side: the tips of the body's x, y, z axes along each run (the
    columns of A_IC at every step), yours over the reference's."""
    series, panels = [], []
    for panel, (key, name) in enumerate(INTEGRATORS.items()):
        ours = np.asarray(expected[key], dtype=float)
        mine = _entry(got, key, ours.shape)
        for k, axis in enumerate("xyz"):
            series.append(_curve(f"{axis}-axis tip", ours[:, :, k], "reference", AXIS_COLOURS[k], panel=panel))
            if mine is not None:
                series.append(_curve(f"{axis}-axis tip", mine[:, :, k], "student", AXIS_COLOURS[k], panel=panel))
        series += _inertial(panel)
        panels.append(_panel_title(name, mine is not None))
    ctx.add_figure(Figure(title, "x", "y", tuple(series), True, "z", tuple(panels)))


# ------------------------------------------------------------------------------------------ problem 14


def _screw_series(run, role, instants):
    """The body's path in I and its screw axis at the given steps (through T, along omega)."""
    n = len(run["A_IB"])
    A, r = run["A_IB"], run["B_r_IB"]
    path = np.einsum("nij,nj->ni", A, r)
    series = [_curve("path of B", path, role, "tab:blue")]
    size = max(float(np.ptp(path, axis=0).max()), 1.0) / 2
    for i in instants:
        if i >= n:
            continue
        w = A[i] @ run["B_omega_B"][i]
        if w @ w == 0:
            continue
        T = A[i] @ (r[i] + run["screw"][i][0])
        u = w / np.linalg.norm(w)
        series.append(_curve("screw axis", np.array([T - size * u, T + size * u]), role, "tab:orange"))
        series.append(_curve("T", np.array([T]), role, "tab:orange", marker="o"))
    return series


def _screw_run(value, n):
    shapes = {"A_IB": (n, 3, 3), "B_r_IB": (n, 3), "B_omega_B": (n, 3), "screw": (n, 2, 3)}
    run = {key: _entry(value, key, shape) for key, shape in shapes.items()}
    return run if all(v is not None for v in run.values()) else None


def add_screw_run(ctx, title, got, expected, instants=(0, 25, 50, 75, 100)):
    """Problem 14: the body's path in I and its screw axis at a few instants, yours over the reference's."""
    ours = _screw_run(expected, len(expected["A_IB"]))
    mine = _screw_run(got, len(expected["A_IB"]))
    series = _screw_series(ours, "reference", instants)
    if mine is not None:
        series += _screw_series(mine, "student", instants)
    ctx.add_figure(Figure(title if mine is not None else f"{title} ({UNDRAWABLE})", "x [m]", "y [m]",
                          tuple(series), True, "z [m]"))


# ------------------------------------------------------------------------------------------ problem 17


def _ellipse_rings(semi, V, role, panel):
    """The three principal sections of the ellipsoid with semi-axes ``semi`` along the columns of ``V``."""
    t = np.linspace(0, 2 * np.pi, 61)
    circle = np.column_stack([np.cos(t), np.sin(t)])
    colour = {"student": "tab:blue", "reference": "tab:orange"}[role]
    rings = []
    for i, j in ((0, 1), (1, 2), (2, 0)):
        points = circle[:, :1] * semi[i] * V[:, i] + circle[:, 1:] * semi[j] * V[:, j]
        rings.append(_curve("ellipsoid", points, role, colour, panel=panel))
    return rings


def _ellipsoid(value, key):
    entry = value.get(key) if isinstance(value, dict) else None
    axes, V = _entry(entry, "axes", (3,)), _entry(entry, "V", (3, 3))
    return None if axes is None or V is None else (axes / 2, V)


def ellipsoid_drawer(ctx, title, assertion, key="ellipsoid"):
    """Wrap ``assertion(got, B_I_G, m, where)`` of problem 17's representations: every matrix of the sheet it is
    given (``where`` set) adds a panel with the student's ellipsoid over the reference's, before the assertion
    judges it, in one figure."""
    panels, series, shown = [], [], []

    def draw(got, B_I_G, m, where):
        if where:
            expected = ctx.reference(p17.representations, B_I_G, m)
            panel = len(panels)
            series.extend(_ellipse_rings(*_ellipsoid(expected, key), "reference", panel))
            mine = _ellipsoid(got, key)
            if mine is not None:
                series.extend(_ellipse_rings(*mine, "student", panel))
            panels.append(_panel_title(f"matrix {panel + 1}", mine is not None))
            figure = Figure(title, "x [m]", "y [m]", tuple(series), True, "z [m]", tuple(panels))
            ctx.figures[:] = [f for f in ctx.figures if f not in shown]
            shown[:] = [figure]
            ctx.add_figure(figure)
        return assertion(got, B_I_G, m, where)

    return draw


# ------------------------------------------------------------------------------------------ problems 21, 22


def _arm(poses, tick):
    """The points of a planar arm from the origin through the poses ``(x, y, gamma)``, and a tick along the last
    pose's orientation."""
    points = np.vstack([np.zeros(2), poses[:, :2]])
    end, gamma = poses[-1, :2], poses[-1, 2]
    return points, np.array([end, end + tick * np.array([np.cos(gamma), np.sin(gamma)])])


def add_planar_arm(ctx, title, got, expected, tick=0.05, end_only=False):
    """A planar arm through its poses ``(x, y, gamma)`` (rows), yours over the reference's, with a tick along the
    end effector's orientation gamma.  ``end_only``: the student gave only the end effector's pose."""
    ours = np.reshape(np.asarray(expected, dtype=float), (-1, 3))
    points, heading = _arm(ours, tick)
    series = [_curve("arm", points, "reference", "tab:orange", marker="o"),
              _curve("orientation of the end", heading, "reference", "tab:orange")]
    mine = _array(got)
    if mine is not None and mine.size == (3 if end_only else ours.size):
        mine = mine.reshape(-1, 3)
        points, heading = _arm(mine, tick)
        series += [_curve("end effector" if end_only else "arm", points[-1:] if end_only else points, "student",
                          "tab:blue", marker="o"),
                   _curve("orientation of the end", heading, "student", "tab:blue")]
    else:
        title = f"{title} ({UNDRAWABLE})"
    ctx.add_figure(Figure(title, "x [m]", "y [m]", tuple(series), True))


# ------------------------------------------------------------------------------------------ problem 26


def seat_between(steps):
    """The seat's position at q from the positions at q + h e_1 and q - h e_1 (``jacobian_and_steps``): their mean,
    right to O(h^2); None when they cannot be read."""
    plus = _array(steps.get("plus"), (2, 3)) if isinstance(steps, dict) else None
    minus = _array(steps.get("minus"), (2, 3)) if isinstance(steps, dict) else None
    return None if plus is None or minus is None else (plus[0] + minus[0]) / 2


def add_chairoplane(ctx, title, seat, expected, beta, l1, l2):
    """The chairoplane: mast and arm (grey, from the inputs), the chain to the seat and the seat's circle, yours
    over the reference's; drawn with the course's axis 2 (up) as the vertical axis."""
    up = [0, 2, 1]  # (x1, x3, x2): matplotlib's third axis is the vertical one
    mast_top = np.array([0.0, l1, 0.0])
    arm_end = mast_top + l2 * np.array([np.sin(beta), 0.0, np.cos(beta)])
    series = [_curve("mast and arm", np.array([np.zeros(3), mast_top, arm_end])[:, up], "other", "0.5")]
    t = np.linspace(0, 2 * np.pi, 61)
    for role, x, colour in (("reference", np.asarray(expected, dtype=float), "tab:orange"),
                            ("student", _array(seat, (3,)), "tab:blue")):
        if x is None:
            title = f"{title} ({UNDRAWABLE})"
            continue
        radius = np.hypot(x[0], x[2])
        circle = np.column_stack([radius * np.sin(t), np.full_like(t, x[1]), radius * np.cos(t)])
        seat = "seat" if role == "reference" else "seat (mean of yours at q +- h)"
        series += [_curve("chain", np.array([arm_end, x])[:, up], role, colour),
                   _curve(seat, np.array([x])[:, up], role, colour, marker="o"),
                   _curve("seat's circle", circle[:, up], role, colour)]
    ctx.add_figure(Figure(title, "x1 [m]", "x3 [m]", tuple(series), True, "x2 [m] (up)"))
