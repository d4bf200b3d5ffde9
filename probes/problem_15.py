"""Probes of problem 15: the torque-free rigid body, one evaluation of its dynamics or a whole simulation."""

from . import module, probe
from ._forms import Arr, Dict
from ._scenario import BODY_ROLES, body_run

BODY = "rigid_body.RigidBodyDynamics"
STATE = ("A_IB", "B_r_IB", "B_v_B", "B_omega_B")


@probe(
    returns=Dict({"B_a_B": Arr(3), "B_omegaDot_B": Arr(3)}),
    says="compute_natural_dynamics()",
    args=(BODY_ROLES,),
    rotation=(0, "A_IB"),
)
def accelerations(pkg, state):
    """``B_a_B`` and ``B_omegaDot_B`` after one call of ``compute_natural_dynamics()``."""
    read = [("B_a_B", "B_a_B"), ("B_omegaDot_B", "B_omegaDot_B")]
    return body_run(pkg, BODY, state, [("compute_natural_dynamics", [])], 1, read=read)["final"]


@probe(returns=Arr(3), says="angular_momentum()", args=(BODY_ROLES,), rotation=(0, "A_IB"))
def angular_momentum(pkg, state):
    return body_run(pkg, BODY, state, [], 0, read=[("L", "angular_momentum", [])])["final"]["L"]


@probe(
    returns=Dict(
        {
            "step": Arr(None),
            "B_L_B": Arr(any_shape=True, finite=False),
            **{key: Arr(any_shape=True, finite=False) for key in STATE},
        },
        optional=("B_L_B",),
    ),
    says="the run of {2} steps",
    draw=False,
    motion={"time": "step", "states": ("A_IB", "B_r_IB", "B_v_B", "B_omega_B")},
)
def simulate(pkg, state, dt, n, every=1, momentum=False):
    """``n`` steps of natural dynamics then integration step: the traces of the state (and of
    ``angular_momentum()`` if ``momentum``), every ``every`` steps."""
    trace = [(k, k) for k in STATE] + ([("B_L_B", "angular_momentum", [])] if momentum else [])
    steps = [("compute_natural_dynamics", []), ("integration_step", [dt])]
    out = body_run(pkg, BODY, state, steps, n, trace=trace, every=every)
    return {"step": out["step"], **out["trace"]}


@probe(reference_only=True)
def constants(pkg):
    """The sheet's body (mass, inertia) and its six cases of initial velocities."""
    p15 = module(pkg, "problem_15")
    return {"MASS": p15.MASS, "INERTIA": p15.INERTIA, "CASES": p15.CASES}
