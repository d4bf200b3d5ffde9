"""Shared by the checks of problems 1-5 (Exercise I, MuJoCo models): the sheet's link, models that must load,
runs that must not diverge, traces compared with the reference's own ODE (within the chaos horizon), figures.

The student's MJCF is loaded and run only inside the sandbox (``probes/_mjcf.py``); what comes back is plain
data: what the model declares, or its traces, or ``{"error": ...}`` when the model was refused or MuJoCo could not
load it.
"""

import weakref
from dataclasses import replace

import numpy as np

from grader.checking import CheckFailure, Mistake, Tol, assert_close, fail, figure
from grader.errors import StudentFault, ends_grading
from grader.results import Series
from probes import call_key

__all__ = [
    "LENGTH", "WIDTH", "HEIGHT", "VOLUME", "ALUMINIUM", "HDPE", "EARTH", "MOON", "SAMPLE",
    "MASS", "POSITION", "DIRECTION", "student_once", "model_of", "reference_of", "run_of", "hinges",
    "body_of", "assert_link_masses", "compare_traces", "departure", "stepped_otherwise", "integration_to_blame",
    "run_as_sheet", "trace_figure", "MAX_POINTS", "SHEET_INTEGRATOR", "SHEET_TIMESTEP",
]

#: the sheet's link [m] (problem data, P2): a brick 20 x 1 x 1 cm, length along its x-axis
LENGTH, WIDTH, HEIGHT = 0.2, 0.01, 0.01
VOLUME = LENGTH * WIDTH * HEIGHT
#: densities [kg/m^3] and magnitudes of gravity [m/s^2] of the sheet
ALUMINIUM, HDPE = 2700.0, 950.0
MATERIALS = {ALUMINIUM: "aluminium", HDPE: "HDPE"}
EARTH, MOON = 9.81, 1.62
#: traces are compared every 10 ms
SAMPLE = 0.01
#: the sheet's integration of every model: RK4 at 1 ms
SHEET_INTEGRATOR, SHEET_TIMESTEP = "rk4", 0.001
MAX_POINTS = 500

#: mass and inertia as MuJoCo computes them or as the model declares them (four significant digits suffice)
MASS = Tol("declared mass and inertia, 4 significant digits", 1e-12, 5e-4)
#: positions of joints and centres of mass (a micrometre)
POSITION = Tol("positions, a micrometre", 1e-6)
#: unit vectors: joint axes, the direction of gravity
DIRECTION = Tol("directions", 1e-6, 1e-6)

_ONCE: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def student_once(ctx, probe, *args, timeout=None):
    """``ctx.student(probe, *args)``, run once per graded submission: several checks read the same run."""
    cache = _ONCE.setdefault(ctx.child, {})
    key = call_key(probe, args)
    if key not in cache:
        cache[key] = ctx.student(probe, *args, timeout=timeout)
    else:  # the running check's log holds the call its values came from (the diagnosis engine reads it)
        ctx.calls.append(("student", probe, args, cache[key]))
    return cache[key]


def model_of(result, what):
    """The student's model description, or a failure that says why the model could not be used."""
    if not isinstance(result, dict):
        fail(f"{what}: the probe expected a model description, got {str(result)[:200]}")
    if "error" in result:
        message = str(result["error"])
        if message.startswith("MuJoCo cannot load"):
            fail(f"{what} does not load in MuJoCo.\n{message}",
                 "Read MuJoCo's message: it names the element and line. Load the text yourself with "
                 "mjcf.load(xml) to see the same error.", "load_error")
        fail(f"{what} was not run: {message}",
             "Return one self-contained MJCF string built from the parameters (see the docstring of mjcf).",
             "refused")
    return result


def reference_of(result, what):
    """The reference's result; a failure here is the grader's (the runner reports it as a grader error)."""
    if isinstance(result, dict) and "error" in result:
        raise RuntimeError(f"the reference's {what} failed: {result['error']}")
    return result


def run_of(result, what):
    """The student's run (``_mjcf.run``), or a failure naming why it is unusable (refused, not loaded, diverged)."""
    run = model_of(result, what)
    diverged = run.get("diverged")
    if diverged:
        fail(f"the simulation of {what} diverged at t = {float(diverged['time']):.3f} s (MuJoCo: "
             f"{diverged['reason']}).",
             "A diverging run means a mass or inertia that is (nearly) zero, a timestep far too large, or a servo "
             "too stiff for the integrator. MuJoCo resets a diverging simulation silently: watch data.warning.",
             "diverged")
    if run.get("max_contacts", 0):
        fail(f"in the simulation of {what} up to {run['max_contacts']} contacts act.",
             'The links must not touch anything: give the geoms contype="0" conaffinity="0" and add no floor '
             "(MuJoCo's default plane lies in the x-y plane of the motion).", "contacts")
    return run


def hinges(desc, n, what):
    """The model's joints, which must be exactly ``n`` hinges."""
    joints = desc["joints"]
    kinds = [j["type"] for j in joints]
    if kinds != ["hinge"] * n:
        fail(f"{what} must have exactly {n} hinge joint{'s' * (n > 1)}; it has {len(joints)} joint(s): "
             f"{', '.join(kinds) or 'none'}.",
             "One <joint type=\"hinge\" axis=\"0 0 1\"/> per link, at the body's origin (the pivot).", "joints")
    return joints


def body_of(desc, joint):
    """The body a joint moves."""
    return desc["bodies"][int(joint["body"]) - 1]


def assert_link_masses(desc, what, links, density, link_mass):
    """The model ``desc`` was built of ``density``: each of its ``links`` hinged bodies has the mass of the sheet's
    link of that density (``link_mass(density)``, the reference's); an HDPE link's mass there is the density
    ignored."""
    expected, sheet = link_mass(density), link_mass(HDPE)
    material = MATERIALS.get(density, "a density")
    for k, joint in enumerate(hinges(desc, links, what)):
        assert_close(body_of(desc, joint)["mass"], expected,
                     f"the mass of link {k + 1} of {what} built of {material} ({density:g} kg/m^3)", MASS,
                     mistakes=[Mistake("ignored_argument", sheet, f"That is the mass of an HDPE link ({HDPE:g} "
                                       "kg/m^3): build the model with the density you are given.")])


def departure(t, got, expected, tols, window):
    """``(index, label)`` of the first sample with ``t <= window`` where a student's trace leaves the reference's
    (``compare_traces``), or None where none does."""
    t = np.asarray(t, dtype=float)
    inside = t <= window + 1e-9
    first, label = None, None
    for key, tol in tols.items():
        g = np.asarray(got[key], dtype=float)
        e = np.asarray(expected[key], dtype=float)
        bad = inside & ~(np.abs(g - e) <= tol.atol + tol.rtol * np.abs(e))
        hits = np.flatnonzero(bad)
        if hits.size and (first is None or hits[0] < first):
            first, label = int(hits[0]), key
    return None if first is None else (first, label)


def stepped_otherwise(run) -> str:
    """How a run of the student's model is integrated otherwise than the sheet's (RK4 at 1 ms), in words ("" where
    it is integrated as the sheet's, or the run does not say)."""
    integrator, timestep = run.get("integrator"), run.get("timestep")
    found = []
    if timestep is not None and not np.isclose(float(timestep), SHEET_TIMESTEP, rtol=1e-6, atol=0.0):
        found.append(f"steps at {float(timestep) * 1000:g} ms")
    if integrator is not None and str(integrator).lower() != SHEET_INTEGRATOR:
        found.append(f"integrates with {integrator}")
    return " and ".join(found)


def integration_to_blame(ctx, probe, args, run, traces, t, expected, tols, window) -> str:
    """How the student's model is stepped otherwise than the sheet's, where its traces leave the reference's and the
    same model stepped with RK4 at 1 ms (``probe(*args, True)``, the probe's ``as_sheet``) follows them: its
    integration is then what strays; "" where the model is stepped as the sheet's, its traces follow the reference's,
    the run stepped as the sheet's strays as well (a slip of the model) or cannot be read.  ``run``: the student's
    run, ``traces(run)``: its traces by label, as compared."""
    stepped = stepped_otherwise(run)
    if not stepped or departure(t, traces(run), expected, tols, window) is None:
        return ""
    again = run_as_sheet(ctx, probe, args)
    try:
        follows = again is not None and departure(t, traces(again), expected, tols, window) is None
    except (KeyError, TypeError, ValueError, IndexError):
        return ""
    return stepped if follows else ""


def run_as_sheet(ctx, probe, args):
    """The student's run of ``probe(*args)`` stepped with the sheet's integration (RK4 at 1 ms) whatever the model
    declares (the probe's ``as_sheet``), or None where it cannot be used (refused, diverged, or a fault of the
    student's code that does not end the grading)."""
    try:
        return run_of(ctx.student(probe, *args, True, timeout=30), "the model stepped with RK4 at 1 ms")
    except StudentFault as exc:
        if ends_grading(exc):
            raise
        return None
    except CheckFailure:
        return None


def compare_traces(t, got, expected, tols, window, what, hint="", diagnosis="", note=""):
    """Fail at the first sample with ``t <= window`` where a student's trace leaves the reference's.

    ``got`` and ``expected`` map a label (e.g. "q2 [rad]") to a 1-D trace on the times ``t``; ``tols`` maps the same
    labels to a tolerance.  The message names the time and the trace (then ``note``: why the window ends where
    it does), and lists the samples around it.
    """
    t = np.asarray(t, dtype=float)
    inside = t <= window + 1e-9
    found = departure(t, got, expected, tols, window)
    if found is None:
        return
    first, label = found
    rows = ["      t [s]  " + "".join(f"{'yours: ' + k:>22}{'reference':>12}" for k in tols)]
    for i in range(max(0, first - 3), min(len(t), first + 3)):
        mark = "  ✘" if i == first else ""
        cells = "".join(f"{float(got[k][i]):>+22.4f}{float(expected[k][i]):>+12.4f}" for k in tols)
        rows.append(f"  {t[i]:>9.2f}  {cells}{mark}")
    lines = [
        f"{label} {what} leaves the reference's at t = {t[first]:.2f} s (compared over 0 to {window:.2f} s).",
        *([note] if note else []),
        f"tolerance: {tols[label]}",
        *rows,
    ]
    raise CheckFailure("\n".join(lines), hint, diagnosis, evidence=_traces(t, got, expected, inside, tols, label))


def _traces(t, got, expected, inside, tols, label):
    """The traces up to the window as a run for the diagnosis engine (a time shift, an offset, a trace that is
    another's, a wrong start)."""
    from grader.diagnosis import Evidence, Source

    mine = {k: np.asarray(got[k], dtype=float)[inside] for k in tols}
    ours = {k: np.asarray(expected[k], dtype=float)[inside] for k in tols}
    runs = [Source("", (), (label,), {"t": t[inside], **traces}) for traces in (ours, mine)]
    return Evidence(mine[label], ours[label], tols[label], label, source=runs[0], student=runs[1],
                    motion={"time": "t", "states": tuple(tols)})


def trace_figure(title, t, got, expected, horizon=None):
    """Student's traces over the reference's (``got``/``expected``: label -> trace), with a vertical line at the
    chaos horizon when given."""
    t = np.asarray(t, dtype=float)
    every = max(1, int(np.ceil(len(t) / MAX_POINTS)))

    def series(traces):
        out = []
        for label, y in traces.items():
            y = np.asarray(y, dtype=float)
            n = min(len(t), len(y))
            keep = np.isfinite(y[:n])
            out.append((label, t[:n][keep][::every], y[:n][keep][::every]))
        return out

    fig = figure(title, "t [s]", "angle [rad], rate [rad/s]", student=series(got), reference=series(expected))
    if horizon is None:
        return fig
    values = [v for s in fig.series for v in s.y] or [0.0]
    line = Series(f"chaos horizon, t = {horizon:.2f} s", (float(horizon), float(horizon)),
                  (float(min(values)), float(max(values))), "other")
    return replace(fig, series=fig.series + (line,))
