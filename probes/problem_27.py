"""Probes of problem 27: the Jacobian columns, the two restated Jacobians, and the computations behind the keys."""

from . import module, probe
from ._forms import Arr, Items, Num


@probe(returns=Arr(3), says="revolute_column(p, p_e)", args=("vector", "vector"))
def revolute_column(pkg, p, p_e):
    return module(pkg, "problem_27").revolute_column(p, p_e)


@probe(returns=Arr(3), says="prismatic_column(u)", args=("vector",))
def prismatic_column(pkg, u):
    return module(pkg, "problem_27").prismatic_column(u)


@probe(returns=Arr(3, 3), says="jacobian_a()",
       rebind={"module": "problem_27", "names": ("JOINT_1", "AXIS_2", "JOINT_3", "END_EFFECTOR")})
def jacobian_a(pkg):
    return module(pkg, "problem_27").jacobian_a()


@probe(returns=Arr(3, 2), says="governor_jacobian()")
def governor_jacobian(pkg):
    return module(pkg, "problem_27").governor_jacobian()


@probe(returns=Items(Num()), says="frame_derivative_residuals({0}, {1})")
def frame_derivative_residuals(pkg, seed, t):
    return module(pkg, "problem_27").frame_derivative_residuals(seed, t)


@probe(reference_only=True)
def velocity_residuals(pkg):
    return module(pkg, "problem_27").velocity_residuals()


@probe(reference_only=True)
def bias_acceleration_residuals(pkg):
    return module(pkg, "problem_27").bias_acceleration_residuals()


@probe(reference_only=True)
def answers(pkg):
    return module(pkg, "problem_27").answers()


@probe(reference_only=True)
def options(pkg):
    """The options of (a), (b) and (d) as typed from the sheet, and the restated geometry of (a)."""
    p27 = module(pkg, "problem_27")
    return {
        "a": p27.OPTIONS_A,
        "b": {option: {"derivative": derivative, "kind": kind} for option, (derivative, kind) in p27.OPTIONS_B.items()},
        "d": p27.OPTIONS_D,
        "geometry": {"joint_1": p27.JOINT_1, "axis_2": p27.AXIS_2, "joint_3": p27.JOINT_3,
                     "end_effector": p27.END_EFFECTOR},
    }
