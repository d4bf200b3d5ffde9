"""Probes of problem 22: the 2n-joint arm by a loop and by recursion, and a probe that watches the recursion."""

import os
import sys

from . import module, probe
from ._forms import ANY, Arr, Dict, Maybe, Num, Seq, Text


@probe(returns=Arr(3), says="end_effector_loop(q, d)", args=("vector", "scalar"))
def loop(pkg, q, d):
    return module(pkg, "planar").end_effector_loop(q, d)


@probe(returns=Arr(3), says="end_effector_recursive(q, d)", args=("vector", "scalar"))
def recursive(pkg, q, d):
    return module(pkg, "planar").end_effector_recursive(q, d)


@probe(returns=Seq(Arr(3)), says="point_k(q, k)")
def points(pkg, q):
    """``[point_k(q, k) for k = 0..n]``."""
    point_k = module(pkg, "planar").point_k
    return [point_k(q, k) for k in range(len(q) // 2 + 1)]


@probe(reference_only=True)
def mistakes(pkg, q, d):
    """The arm with each known mistake (``mistaken_walk``, which only the reference has): ``{mistake: {"points":
    [(x_k, y_k, g_(k-1), g_k) for k = 1..n], "end": (xe, ye, g_n)}}``."""
    planar = module(pkg, "planar")
    found = {}
    for mistake in planar.ARM_MISTAKES:
        points, end = planar.mistaken_walk(q, d, mistake)
        found[mistake] = {"points": points, "end": end}
    return found


@probe(reference_only=True)
def sheet_case(pkg):
    """The sheet's case q3 (corrected in the problem data), ``d`` and the printed end-effector pose."""
    p22 = module(pkg, "problem_22")
    return {"q": p22.joint_vector("q3"), "d": p22.D, "target": p22.TARGET_Q3}


@probe(returns=Dict({"depth": Num(), "function": Text(), "value": ANY}), says="{0}")
def nesting(pkg, call, q, d):
    """Run ``point_k(q, n)`` or ``end_effector_recursive(q, d)`` and report the deepest nesting of one function of
    the package and what the call returned: ``{"depth": calls of that function active at once, "function": its
    name, "value": the result}``.

    A function that calls itself (directly, or through the module's global name) has several frames of its code
    alive at once; a loop has one.
    """
    planar = module(pkg, "planar")
    root = os.path.dirname(os.path.abspath(pkg.__file__)) + os.sep
    ours, active, deepest = {}, {}, {}

    def watch(frame, event, arg):
        code = frame.f_code
        if code not in ours:
            ours[code] = os.path.abspath(code.co_filename).startswith(root)
        if not ours[code]:
            return
        if event == "call":
            active[code] = active.get(code, 0) + 1
            deepest[code] = max(deepest.get(code, 0), active[code])
        elif event == "return":
            active[code] = active.get(code, 1) - 1

    previous = sys.getprofile()
    sys.setprofile(watch)
    try:
        if call == "point_k":
            value = planar.point_k(q, len(q) // 2)
        else:
            value = planar.end_effector_recursive(q, d)
    finally:
        sys.setprofile(previous)
    if not deepest:
        return {"depth": 0, "function": "", "value": value}
    code = max(deepest, key=deepest.get)
    return {"depth": deepest[code], "function": code.co_name, "value": value}


@probe(returns=Dict({"end": Arr(3), "point": Maybe(Arr(3))}), says="end_effector_recursive(q, d)")
def recursive_with_point(pkg, q, d):
    """``end_effector_recursive(q, d)`` with the package's own ``point_k(q, n)`` (None when it cannot be had)."""
    import numpy as np

    planar = module(pkg, "planar")
    try:
        point = np.asarray(planar.point_k(q, len(q) // 2), dtype=float)
        point = point if point.shape == (3,) and np.all(np.isfinite(point)) else None
    except Exception:  # noqa: BLE001 - point_k is judged by its own check
        point = None
    return {"end": planar.end_effector_recursive(q, d), "point": point}
