"""Probes of problem 14: the screw axis traced along a simulated motion."""

from . import module, probe
from ._forms import Arr, Dict
from ._scenario import body_run

STATE = ("A_IB", "B_r_IB", "B_v_B", "B_omega_B")


@probe(
    returns=Dict(
        {
            "step": Arr(None),
            "screw": Arr(any_shape=True, finite=False),
            **{key: Arr(any_shape=True, finite=False) for key in STATE},
        }
    ),
    says="integration_step and screw_axis over {3} steps",
    draw=False,
    motion={"time": "step", "states": ("B_r_BT", "B_v_T")},
)
def screw_run(pkg, state, dt, n):
    """``n`` integration steps from ``state``; the state and ``screw_axis()`` before and after every step."""
    trace = [(k, k) for k in STATE] + [("screw", "screw_axis", [])]
    out = body_run(pkg, "rigid_body.RigidBodyKinematics", state, [("integration_step", [dt])], n, trace=trace)
    return {"step": out["step"], **out["trace"]}


@probe(reference_only=True)
def constants(pkg):
    """The sheet's initial velocities and accelerations of problem 14."""
    return {"INITIAL": module(pkg, "problem_14").INITIAL}
