"""Probes of problem 46: the wire's event function, its constraint terms, the plastic impact, the constrained
dynamics and the whole run (with the end effector's positions from the package's own kinematics)."""

import numpy as np

from . import module, probe
from ._dynamics import fixed_run, fixed_step, trace
from ._forms import Arr, Dict, Flag, Maybe, Num, Seq, Tup

#: an event function's values at the states, and its ``terminal`` and ``direction`` attributes (None when missing)
EVENT = Dict({"values": Arr(None), "terminal": Maybe(Flag()), "direction": Maybe(Num())})


def _robot(pkg):
    return module(pkg, "problem_37").build_dynamic_robot()


def _matrix(value, rows):
    array = np.asarray(value, dtype=float)
    return array.reshape(rows, -1) if array.size and array.size % rows == 0 else array


@probe(returns=EVENT, says="make_wire_event(robot)")
def event(pkg, states):
    """The event function of ``make_wire_event(robot)`` at every state ``y``, and its ``terminal`` and
    ``direction`` attributes (``None`` when missing)."""
    function = module(pkg, "problem_46").make_wire_event(_robot(pkg))
    values = [float(function(0.0, np.asarray(y, dtype=float))) for y in states]
    terminal = getattr(function, "terminal", None)
    direction = getattr(function, "direction", None)
    return {"values": values, "terminal": None if terminal is None else bool(terminal),
            "direction": None if direction is None else float(direction)}


def _wire(wire):
    """The keyword arguments of the wire ``(anchor, wire_length)``, or none for the sheet's wire."""
    return {} if wire is None else {"anchor": np.asarray(wire[0], dtype=float), "wire_length": float(wire[1])}


def _terms(pkg, tree, q, qd, baumgarte, wire=None):
    tree.forward_kinematics(np.asarray(q, dtype=float), np.asarray(qd, dtype=float), np.zeros(3))
    J, sigma = module(pkg, "problem_46").constraint_terms(tree["end_effector"], bool(baumgarte), **_wire(wire))
    return {"J": _matrix(J, 1), "sigma": np.asarray(sigma, dtype=float).reshape(-1)}


@probe(
    returns=Seq(Dict({"J": Arr(ndim=2), "sigma": Arr(1)}), length=lambda cases: len(cases)),
    says="constraint_terms",
    terms="problem_46.constraint_terms_split",
)
def constraint_terms(pkg, cases):
    """``{"J", "sigma"}`` of ``constraint_terms`` for every ``(q, qd, baumgarte)``."""
    tree = _robot(pkg)
    return [_terms(pkg, tree, q, qd, baumgarte) for q, qd, baumgarte in cases]


def _wire_parts(pkg, q, qd):
    """The wire's pieces at ``(q, qd)`` from the package's kinematics and the sheet's data in its ``problem_46``:
    ``J``, the bias ``-dir.T A_IE B_a_E``, the centripetal part, the Baumgarte stabilisation, and the end effector's
    frame, Jacobian, acceleration and direction (called on the reference only)."""
    p46 = module(pkg, "problem_46")
    tree = _robot(pkg)
    E = tree.forward_kinematics(np.asarray(q, dtype=float), np.asarray(qd, dtype=float), np.zeros(3))["end_effector"]
    A_IE, J_S, a_E = (np.asarray(x, dtype=float) for x in (E.A_IB, E.B_J_S, E.B_a_B))
    I_r_E, I_v_E = A_IE @ np.asarray(E.B_r_IB, dtype=float), A_IE @ np.asarray(E.B_v_B, dtype=float)
    hook, length = np.asarray(p46.ANCHOR, dtype=float), float(p46.WIRE_LENGTH)
    P_B, D_B = float(p46.P_BAUMGARTE), float(p46.D_BAUMGARTE)
    distance = np.linalg.norm(I_r_E - hook)
    direction = (I_r_E - hook) / distance
    return {"J": -(direction @ A_IE @ J_S).reshape(1, 3), "bias": -direction @ A_IE @ a_E,
            "centripetal": -np.linalg.norm(np.cross(direction, I_v_E)) ** 2 / length,
            "stabilisation": P_B * (length - distance) + D_B * (0.0 - direction @ I_v_E),
            "J_S": J_S, "a_E": a_E, "direction": direction}


@probe(reference_only=True)
def constraint_terms_split(pkg, cases):
    """``sigma`` of ``constraint_terms`` for every ``(q, qd, baumgarte)`` split into named terms (the diagnosis
    engine calls it on the reference): the bias, the centripetal part and, with ``baumgarte``, the stabilisation;
    without it the stabilisation is a term that does not belong."""
    terms = {"bias": [], "centripetal": [], "baumgarte": []}
    extra = {"baumgarte": []}
    for q, qd, baumgarte in cases:
        wire = _wire_parts(pkg, q, qd)
        zero = {"J": np.zeros((1, 3)), "sigma": np.zeros(1)}
        terms["bias"].append({"sigma": np.array([wire["bias"]])})
        terms["centripetal"].append({"sigma": np.array([wire["centripetal"]])})
        stabilisation = {"sigma": np.array([wire["stabilisation"]])}
        terms["baumgarte"].append(stabilisation if baumgarte else zero)
        extra["baumgarte"].append(zero if baumgarte else stabilisation)
    return {"terms": terms, "extra": extra}


@probe(reference_only=True)
def constraint_mistakes(pkg, q, qd, baumgarte):
    """``{mistake: {"J", "sigma"}}``: the constraint terms that known mistakes give, from the package's kinematics
    and the sheet's data in its ``problem_46`` (called on the reference only)."""
    wire = _wire_parts(pkg, q, qd)
    J, bias, centripetal, direction = wire["J"], wire["bias"], wire["centripetal"], wire["direction"]
    J_S, a_E = wire["J_S"], wire["a_E"]
    stabilisation = wire["stabilisation"] if baumgarte else 0.0

    def terms(J_, sigma_):
        return {"J": J_, "sigma": np.array([sigma_])}

    return {
        "baumgarte_sign": terms(J, bias + centripetal - stabilisation),
        "missing_baumgarte": terms(J, bias + centripetal),
        "jacobian_sign": terms(-J, bias + centripetal + stabilisation),
        "constraint_sign": terms(-J, -(bias + centripetal + stabilisation)),
        "wrong_frame": terms(-(direction @ J_S).reshape(1, 3), -direction @ a_E + centripetal + stabilisation),
        "missing_centripetal": terms(J, bias + stabilisation),
        "centripetal_sign": terms(J, bias - centripetal + stabilisation),
    }


@probe(
    returns=Dict({"J": Arr(ndim=2), "shifted": Seq(Tup(Num(), Num()), length=3)}),
    says="constraint_terms and the wire event",
)
def event_differences(pkg, q, h):
    """The constraint Jacobian at ``(q, qd = 0)`` and the event function at ``q +- h e_i`` (at rest)."""
    tree = _robot(pkg)
    q = np.asarray(q, dtype=float)
    J = _terms(pkg, tree, q, np.zeros(3), False)["J"]
    function = module(pkg, "problem_46").make_wire_event(_robot(pkg))
    shifted = [[float(function(0.0, np.concatenate([q + sign * h * e, np.zeros(3)]))) for sign in (1.0, -1.0)]
               for e in np.eye(3)]
    return {"J": J, "shifted": shifted}


@probe(returns=Seq(Dict({"qd_plus": Arr(3), "Lam": Arr(1)}), length=lambda cases: len(cases)), says="plastic_impact")
def impact(pkg, cases):
    """``{"qd_plus", "Lam"}`` of ``plastic_impact(M, J, qd_minus)`` for every case."""
    p46 = module(pkg, "problem_46")
    out = []
    for M, J, qd_minus in cases:
        qd_plus, Lam = p46.plastic_impact(np.asarray(M, dtype=float), np.asarray(J, dtype=float),
                                          np.asarray(qd_minus, dtype=float))
        out.append({"qd_plus": np.asarray(qd_plus, dtype=float), "Lam": np.asarray(Lam, dtype=float).reshape(-1)})
    return out


@probe(returns=Seq(Dict({"qdd": Arr(3), "lam": Arr(1)}), length=lambda cases: len(cases)), says="constrained_dynamics")
def constrained(pkg, cases):
    """``{"qdd", "lam"}`` of ``constrained_dynamics(M, f, g, tau, J, sigma)`` for every case."""
    p46 = module(pkg, "problem_46")
    out = []
    for case in cases:
        qdd, lam = p46.constrained_dynamics(*(np.asarray(x, dtype=float) for x in case))
        out.append({"qdd": np.asarray(qdd, dtype=float), "lam": np.asarray(lam, dtype=float).reshape(-1)})
    return out


@probe(
    returns=Dict(
        {
            "t": Arr(None),
            "q": Arr(None, 3),
            "qd": Arr(None, 3),
            "x": Arr(None, 3),
            "t_event": Maybe(Num()),
            **{key: Arr(3) for key in ("q_minus", "qd_minus", "q_plus", "qd_plus")},
            "Lam": Arr(1),
            "J_plus": Arr(ndim=2),
        },
        optional=("q_minus", "qd_minus", "q_plus", "qd_plus", "Lam", "J_plus"),
    ),
    says="simulate(table, {1}, {2})",
    motion={"time": "t", "states": ("q", "qd"), "events": ("t_event",), "fixed_step": "problem_46.simulate_fixed",
               "schemes": ("euler", "symplectic"), "rhs": "problem_46.free_ode", "rhs_args": (0,),
               "at_events": {"q_minus": ("t_event", "q"), "qd_minus": ("t_event", "qd"), "q_plus": ("t_event", "q")},
               "parts": {"arg": 3, "names": ("anchor", "wire_length"), "sheet": "problem_46.sheet_wire"}},
)
def simulate(pkg, table, baumgarte, t_end, wire=None):
    """``simulate(table, baumgarte, t_end)``: the run, the impact values, the end effector's positions at every
    output time, and at the impact the constraint Jacobian from ``constraint_terms`` (``J_plus``).  ``wire``:
    ``(anchor, wire_length)`` of a wire hung elsewhere than the sheet's, passed to ``simulate`` and
    ``constraint_terms``."""
    p46 = module(pkg, "problem_46")
    run = p46.simulate(table, bool(baumgarte), t_end, **_wire(wire))
    t, q, qd = trace(run, 3, "problem_46.simulate")
    tree = _robot(pkg)
    x = np.array([np.asarray(E.A_IB, dtype=float) @ np.asarray(E.B_r_IB, dtype=float)
                  for E in (tree.forward_kinematics(a)["end_effector"] for a in q)]).reshape(-1, 3)
    out = {"t": t, "q": q, "qd": qd, "x": x, "t_event": run.get("t_event")}
    if out["t_event"] is None:
        return out
    out["t_event"] = float(out["t_event"])
    for key in ("q_minus", "qd_minus", "q_plus", "qd_plus"):
        out[key] = np.asarray(run[key], dtype=float).reshape(3)
    out["Lam"] = np.asarray(run["Lam"], dtype=float).reshape(-1)
    out["J_plus"] = _terms(pkg, tree, out["q_plus"], out["qd_plus"], False, wire)["J"]
    return out


@probe(reference_only=True)
def sheet_wire(pkg):
    """The sheet's wire ``(anchor, wire_length)``: the values ``simulate`` hangs it by where it is given no ``wire``
    (the diagnosis engine calls it on the reference)."""
    p46 = module(pkg, "problem_46")
    return [[float(x) for x in p46.ANCHOR], float(p46.WIRE_LENGTH)]


@probe(reference_only=True)
def simulate_fixed(pkg, table, baumgarte, t_end, *rest):
    """The robot of ``simulate`` under computed torques run by a fixed-step ``scheme`` at step ``h`` with the
    package's own ``robot_ode`` of problem 37, until the wire becomes taut (the diagnosis engine calls it on the
    reference, with the arguments of ``simulate`` followed by ``h, scheme``: ``rest`` is ``(h, scheme)`` or
    ``(wire, h, scheme)``; the impact and the constrained motion after it are not run)."""
    *wire, h, scheme = rest
    p37, p46 = module(pkg, "problem_37"), module(pkg, "problem_46")
    tree = _robot(pkg)
    event = p46.make_wire_event(_robot(pkg), **_wire(wire[0] if wire else None))
    y0 = np.concatenate([np.asarray(table["q"][0], dtype=float), np.asarray(table["qd"][0], dtype=float)])
    return fixed_run(fixed_step(lambda t, y: p37.robot_ode(t, y, tree, table, "computed_torques"), y0, float(t_end),
                                h, scheme, event=event, direction=1.0), 3)


@probe(returns=Seq(Arr(6), length=lambda table, cases: len(cases)), says="constrained_ode")
def constrained_ode(pkg, table, cases):
    """``constrained_ode(t, y, tree, table, baumgarte)`` for every ``(t, y, baumgarte)`` of ``cases`` in turn, on
    one robot (the sheet's wire)."""
    p46 = module(pkg, "problem_46")
    tree = _robot(pkg)
    return [np.array(p46.constrained_ode(float(t), np.asarray(y, dtype=float), tree, table, bool(baumgarte)),
                     dtype=float) for t, y, baumgarte in cases]


@probe(reference_only=True)
def stale_mass_matrix(pkg, table, cases):
    """Called on the reference only: ``constrained_ode`` at every ``(t, y, baumgarte)`` of ``cases`` in turn as a
    right-hand side gives it that computes the mass matrix once, at the first case, and reuses it (``f``, ``g`` and
    the constraint terms at each state)."""
    p37, p46 = module(pkg, "problem_37"), module(pkg, "problem_46")
    dynamics = module(pkg, "dynamics")
    tree = _robot(pkg)
    first, out = None, []
    for t, y, baumgarte in cases:
        y = np.asarray(y, dtype=float)
        q, qd = y[:3], y[3:]
        M, f, g = dynamics.equations_of_motion(tree, q, qd, p37.I_GRAV)
        first = M if first is None else first
        tau = p37.computed_torque(first, f, g, q, qd, *p37.desired_state(table, float(t)))
        J, sigma = p46.constraint_terms(tree["end_effector"], bool(baumgarte))
        qdd, _ = p46.constrained_dynamics(first, f, g, tau, J, sigma)
        out.append(np.concatenate([qd, qdd]))
    return out


@probe(returns=Seq(Arr(6), length=lambda table, cases: len(cases)), says="robot_ode (computed torques)")
def free_ode(pkg, table, cases):
    """The robot's right-hand side before the wire is taut, ``problem_37.robot_ode(t, y, robot, table,
    "computed_torques")``, for every ``(t, y)`` of ``cases`` (the diagnosis engine compares it with the
    reference's at states along a run of ``simulate``)."""
    p37 = module(pkg, "problem_37")
    tree = _robot(pkg)
    return [np.array(p37.robot_ode(float(t), np.asarray(y, dtype=float), tree, table, "computed_torques"),
                     dtype=float) for t, y in cases]
