"""Probes of problem 12: a kinematic rigid body integrated from a state, and the motion of its points."""

import numpy as np

from . import module, probe
from ._forms import Arr, Dict
from ._scenario import BODY_ROLES, body_run

BODY = "rigid_body.RigidBodyKinematics"
STATE = ("A_IB", "B_r_IB", "B_v_B", "B_omega_B")


@probe(
    returns=Dict({"step": Arr(None), **{key: Arr(any_shape=True, finite=False) for key in STATE}}),
    says="integration_step over {2} steps",
    draw=False,
    motion={"time": "step", "states": ("A_IB", "B_r_IB", "B_v_B", "B_omega_B")},
)
def integrate(pkg, state, dt, n, every=1):
    """``n`` calls of ``integration_step(dt)`` from ``state``: the traces of the state (every ``every`` steps)."""
    out = body_run(pkg, BODY, state, [("integration_step", [dt])], n, trace=[(k, k) for k in STATE], every=every)
    return {"step": out["step"], **out["trace"]}


@probe(
    returns=Arr(3),
    says="{1}({2})",
    args=(BODY_ROLES, "", "vector"),
    rotation=(0, "A_IB"),
    terms="problem_12.point_terms",
)
def point(pkg, state, method, B_r_BQ):
    """``position_of_point``, ``velocity_of_point`` or ``acceleration_of_point`` of Q for a body in ``state``."""
    return body_run(pkg, BODY, state, [], 0, read=[("value", method, [B_r_BQ])])["final"]["value"]


@probe(
    returns=Dict({"step": Arr(None), "I_r_IB": Arr(None, 3, finite=False), "I_r_IQ": Arr(None, 3, finite=False)}),
    says="the wheel's run",
    draw=False,
    motion={"time": "step", "states": ("I_r_IB", "I_r_IQ")},
)
def wheel(pkg, state, dt, n, B_r_BQ, every=1):
    """Part (b): the inertial traces of B and of the body point Q over ``n`` steps."""
    trace = [("I_r_IB", "position_of_point", [[0.0, 0.0, 0.0]]), ("I_r_IQ", "position_of_point", [B_r_BQ])]
    out = body_run(pkg, BODY, state, [("integration_step", [dt])], n, trace=trace, every=every)
    return {"step": out["step"], **out["trace"]}


@probe(reference_only=True)
def constants(pkg):
    """The sheet's data of problem 12: the cases of part (a), the state of part (b) and the point Q."""
    p12 = module(pkg, "problem_12")
    return {"CASES": p12.CASES, "PART_B": p12.PART_B, "B_R_BQ": p12.B_R_BQ}


def _skew(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


@probe(reference_only=True)
def point_terms(pkg, state, method, B_r_BQ):
    """The velocity and acceleration of the point Q of ``point`` split into named terms (the diagnosis engine calls
    it on the reference; the body's state read back from the package): ``I_v_Q = A_IB (B_v_B + omega x r)``,
    ``I_a_Q = A_IB (B_a_B + omegaDot x r + omega x (omega x r))``; no terms for the position."""
    read = [(key, key) for key in ("A_IB", "B_v_B", "B_a_B", "B_omega_B", "B_omegaDot_B")]
    body = body_run(pkg, BODY, state, [], 0, read=read)["final"]
    A, v, a, w, wd = (np.asarray(body[key], dtype=float) for key, _ in read)
    r = np.asarray(B_r_BQ, dtype=float)
    if method == "velocity_of_point":
        return {"terms": {"base": A @ v, "omega_x_r": A @ _skew(w) @ r}, "extra": {}}
    if method == "acceleration_of_point":
        return {"terms": {"base": A @ a, "tangential": A @ _skew(wd) @ r, "centripetal": A @ _skew(w) @ _skew(w) @ r},
                "extra": {}}
    return {"terms": {}, "extra": {}}
