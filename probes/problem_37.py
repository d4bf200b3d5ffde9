"""Probes of problem 37: the desired trajectory, the controllers' torques, the robot's right-hand side and its
simulation under each controller (with the end effector's motion from the package's own kinematics)."""

import numpy as np

from . import module, probe
from ._dynamics import MFG, fixed_run, fixed_step, trace
from ._forms import Arr, Dict, Maybe, Seq

TABLE = ("t", "x", "xd", "q", "qd", "qdd")


@probe(reference_only=True)
def trajectory(pkg):
    """The desired trajectory of problem 32 (``{"t", "x", "xd", "q", "qd", "qdd"}``, one row per time); the grader
    calls it on the reference and hands the table to the student's simulation, as the course's data file did."""
    table = module(pkg, "problem_32").desired_trajectory()
    return {key: np.array(table[key], dtype=float) for key in TABLE}


@probe(returns=Seq(Arr(3), length=lambda controller, cases: len(cases)), says="the {0} torque")
def torques(pkg, controller, cases):
    """The torques of ``gravity_compensation_torque`` or ``computed_torque`` (``controller``) for every case
    ``(M, f, g, q, qd, q_des, qd_des, qdd_des)``."""
    p37 = module(pkg, "problem_37")
    out = []
    for case in cases:
        M, f, g, q, qd, q_des, qd_des, qdd_des = (np.asarray(x, dtype=float) for x in case)
        if controller == "gravity_compensation":
            out.append(np.array(p37.gravity_compensation_torque(g, q, qd, q_des, qd_des), dtype=float))
        else:
            out.append(np.array(p37.computed_torque(M, f, g, q, qd, q_des, qd_des, qdd_des), dtype=float))
    return out


@probe(returns=Seq(Arr(6), length=lambda controller, table, cases: len(cases)), says="robot_ode")
def robot_ode(pkg, controller, table, cases):
    """``robot_ode(t, y, build_dynamic_robot(), table, controller)`` for every ``(t, y)`` of ``cases``."""
    p37 = module(pkg, "problem_37")
    tree = p37.build_dynamic_robot()
    return [np.array(p37.robot_ode(float(t), np.asarray(y, dtype=float), tree, table, controller), dtype=float)
            for t, y in cases]


@probe(
    returns=Dict({"t": Arr(None), "q": Arr(None, 3), "qd": Arr(None, 3), "x": Arr(None, 3), "xd": Arr(None, 3)}),
    says="simulate({0!s}, table, {2})",
    motion={"time": "t", "states": ("q", "qd"), "fixed_step": "problem_37.simulate_fixed",
               "schemes": ("euler", "symplectic"), "rhs": "problem_37.robot_ode", "rhs_args": (0, 1)},
)
def simulate(pkg, controller, table, t_end):
    """``simulate(controller, table, t_end)`` and the end effector's inertial position ``x`` and velocity ``xd`` at
    every output time, from the package's own kinematics."""
    p37 = module(pkg, "problem_37")
    t, q, qd = trace(p37.simulate(controller, table, t_end), 3, "problem_37.simulate")
    tree = p37.build_dynamic_robot()
    x, xd = [], []
    for a, b in zip(q, qd):
        end_effector = tree.forward_kinematics(a, b, np.zeros(3))["end_effector"]
        x.append(np.asarray(end_effector.A_IB, dtype=float) @ np.asarray(end_effector.B_r_IB, dtype=float))
        xd.append(np.asarray(end_effector.A_IB, dtype=float) @ np.asarray(end_effector.B_v_B, dtype=float))
    return {"t": t, "q": q, "qd": qd, "x": np.array(x).reshape(-1, 3), "xd": np.array(xd).reshape(-1, 3)}


@probe(
    returns=Seq(Dict({"ode": Arr(6), "mfg": Maybe(MFG)}), length=lambda controller, table, cases: len(cases)),
    says="robot_ode",
    terms="problem_37.robot_ode_terms",
)
def robot_ode_with_mfg(pkg, controller, table, cases):
    """``robot_ode`` as in the probe ``robot_ode``, each with the package's own ``M, f, g`` of the robot at the
    case's ``(q, qd)`` (``equations_of_motion``; None when they cannot be had)."""
    p37 = module(pkg, "problem_37")
    tree = p37.build_dynamic_robot()
    out = []
    for t, y in cases:
        y = np.asarray(y, dtype=float)
        ode = np.array(p37.robot_ode(float(t), y.copy(), tree, table, controller), dtype=float)
        try:
            M, f, g = (np.array(x, dtype=float) for x in p37.equations_of_motion(tree, y[:3].copy(), y[3:].copy(),
                                                                                  p37.I_GRAV))
            own = {"M": M, "f": f, "g": g} if M.shape == (3, 3) and f.shape == g.shape == (3,) else None
        except Exception:  # noqa: BLE001 - M, f, g are judged by their own checks
            own = None
        out.append({"ode": ode, "mfg": own})
    return out


@probe(returns=Dict({"t": Arr(None), "q": Arr(None, 3), "qd": Arr(None, 3)}), says="your robot_ode integrated")
def own_run(pkg, controller, table, t_end):
    """The robot under ``controller`` integrated from the package's own ``robot_ode`` by this probe's loop (scipy's
    ``solve_ivp``, RK45, rtol 1e-6, piece by piece between the table's times, output at them up to ``t_end``), from
    the table's first row: what ``simulate`` gives on the package's own model."""
    from scipy.integrate import solve_ivp

    p37 = module(pkg, "problem_37")
    tree = p37.build_dynamic_robot()
    times = np.asarray(table["t"], dtype=float)
    times = times[times <= t_end]
    y = np.concatenate([np.asarray(table["q"][0], dtype=float), np.asarray(table["qd"][0], dtype=float)])
    rows = [y]
    for a, b in zip(times[:-1], times[1:]):
        piece = solve_ivp(lambda t, s: np.asarray(p37.robot_ode(t, s, tree, table, controller), dtype=float),
                          (a, b), y, rtol=1e-6, atol=1e-8, first_step=b - a)
        if piece.status < 0:
            raise RuntimeError(f"the integration of your robot_ode failed at t = {piece.t[-1]:g}: {piece.message}")
        y = piece.y[:, -1]
        rows.append(y)
    rows = np.array(rows)
    return {"t": times, "q": rows[:, :3], "qd": rows[:, 3:]}


@probe(reference_only=True)
def simulate_fixed(pkg, controller, table, t_end, h, scheme):
    """The robot of ``simulate`` run by a fixed-step ``scheme`` at step ``h`` with the package's own ``robot_ode``
    (the diagnosis engine calls it on the reference)."""
    p37 = module(pkg, "problem_37")
    tree = p37.build_dynamic_robot()
    y0 = np.concatenate([np.asarray(table["q"][0], dtype=float), np.asarray(table["qd"][0], dtype=float)])
    return fixed_run(fixed_step(lambda t, y: p37.robot_ode(t, y, tree, table, controller), y0, t_end, h, scheme), 3)


@probe(reference_only=True)
def robot_ode_terms(pkg, controller, table, cases):
    """``robot_ode`` of ``robot_ode_with_mfg`` split into named terms (the diagnosis engine calls it on the
    reference): ``dy/dt = (qd, 0) + (0, M^-1 f) + (0, M^-1 g) + (0, M^-1 tau)``, with the package's own ``M, f, g``
    and the controller's torques at each case."""
    p37 = module(pkg, "problem_37")
    tree = p37.build_dynamic_robot()
    terms = {"velocity": [], "f": [], "gravity": [], "torque": []}
    for t, y in cases:
        y = np.asarray(y, dtype=float)
        q, qd = y[:3], y[3:]
        M, f, g = (np.array(x, dtype=float) for x in p37.equations_of_motion(tree, q.copy(), qd.copy(), p37.I_GRAV))
        tau = np.array(p37.controller_torque(controller, M, f, g, q, qd, *p37.desired_state(table, float(t))),
                       dtype=float)
        zero = np.zeros(3)
        terms["velocity"].append({"ode": np.concatenate([qd, zero])})
        for name, value in (("f", f), ("gravity", g), ("torque", tau)):
            terms[name].append({"ode": np.concatenate([zero, np.linalg.solve(M, value)])})
    return {"terms": terms, "extra": {}}


@probe(reference_only=True)
def stale_mass_matrix(pkg, controller, table, cases):
    """Called on the reference only: ``robot_ode`` at every ``(t, y)`` of ``cases`` in turn as a right-hand side
    gives it that computes its model once, at the first case, and reuses it: ``{"M": ...}`` with the mass matrix of
    the first case (``f``, ``g`` at each state), ``{"model": ...}`` with its whole ``M, f, g``."""
    p37 = module(pkg, "problem_37")
    dynamics = module(pkg, "dynamics")
    tree = p37.build_dynamic_robot()
    first, out = None, {"M": [], "model": []}
    for t, y in cases:
        y = np.asarray(y, dtype=float)
        q, qd = y[:3], y[3:]
        M, f, g = dynamics.equations_of_motion(tree, q, qd, p37.I_GRAV)
        first = (M, f, g) if first is None else first
        desired = p37.desired_state(table, float(t))
        for key, (M_, f_, g_) in (("M", (first[0], f, g)), ("model", first)):
            tau = p37.controller_torque(controller, M_, f_, g_, q, qd, *desired)
            out[key].append(np.concatenate([qd, dynamics.forward_dynamics(M_, f_, g_, tau)]))
    return out
