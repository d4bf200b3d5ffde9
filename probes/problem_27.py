"""Probes of problem 27: the Jacobian columns, the two restated Jacobians, and the computations behind the keys."""

from . import module, probe


@probe(args=("vector", "vector"))
def revolute_column(pkg, p, p_e):
    return module(pkg, "problem_27").revolute_column(p, p_e)


@probe(args=("vector",))
def prismatic_column(pkg, u):
    return module(pkg, "problem_27").prismatic_column(u)


@probe
def jacobian_a(pkg):
    return module(pkg, "problem_27").jacobian_a()


@probe
def governor_jacobian(pkg):
    return module(pkg, "problem_27").governor_jacobian()


@probe
def frame_derivative_residuals(pkg, seed, t):
    return module(pkg, "problem_27").frame_derivative_residuals(seed, t)


@probe
def velocity_residuals(pkg):
    return module(pkg, "problem_27").velocity_residuals()


@probe
def bias_acceleration_residuals(pkg):
    return module(pkg, "problem_27").bias_acceleration_residuals()


@probe
def answers(pkg):
    return module(pkg, "problem_27").answers()


@probe
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
