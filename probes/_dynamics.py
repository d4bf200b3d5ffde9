"""Shared probes of the dynamics problems (24, 37, 38, 46): kinematic trees with equations of motion.

A tree travels as the plain data of ``probes._trees`` with each body's inertia added::

    {"bodies": [{"name": "body_0", "m": 1.0, "I": [[...], ...]}, ...], "joints": [...]}

``build`` creates it with the package's ``dynamics.DynamicBody`` in place of ``tree.Body`` (through
``_trees.build``) and gives every body its ``B_I_B``.  The probes read back plain arrays: the package's ``M``, ``f``,
``g``, and what the physics checks need from the package's own kinematics (Jacobians, velocities, positions at
shifted coordinates).  ``mfg_mistakes`` computes, from the package's kinematics, the ``M``, ``f``, ``g`` that known
mistakes give; the grader calls it on the reference only.
"""

from contextlib import contextmanager
from types import SimpleNamespace

import numpy as np

from . import _trees, module, probe
from ._forms import Arr, Dict, Num, Seq, Text, Tup

__all__ = [
    "MFG",
    "MFG_MISTAKES",
    "classes",
    "build",
    "mfg",
    "mfg_mistakes",
    "lagrange",
    "forward_dynamics",
    "energies",
    "trace",
    "pendulum_motion",
    "fixed_step",
    "fixed_run",
    "pendulum_motion_fixed",
    "solver_variant",
    "mfg_terms",
]

#: ``{"M", "f", "g"}`` of ``equations_of_motion`` (n x n, n, n)
MFG = Dict({"M": Arr(None, None), "f": Arr(None), "g": Arr(None)})
#: mistakes of a body's share of M, f, g (see ``_mistaken_share``)
MFG_MISTAKES = ("missing_gyroscopic", "missing_bias", "gravity_sign", "gravity_body_frame", "transpose", "f_sign",
                "gyroscopic_sign")


def classes(pkg):
    """The names of the package's ``tree`` module with ``Body`` replaced by ``dynamics.DynamicBody``."""
    tree = module(pkg, "tree")
    names = {name: getattr(tree, name) for name in dir(tree) if not name.startswith("_")}
    return SimpleNamespace(**{**names, "Body": module(pkg, "dynamics").DynamicBody})


def build(pkg, description):
    """The described tree, built with the package's classes, bodies of ``DynamicBody`` with their inertias."""
    tree = _trees.build(classes(pkg), description)
    inertias = {body["name"]: body.get("I") for body in description["bodies"]}
    for body in tree.bodies:
        if inertias.get(body.name) is not None:
            body.B_I_B = np.array(inertias[body.name], dtype=float).reshape(3, 3)
    return tree


def _vectors(q, qd):
    return np.asarray(q, dtype=float), np.asarray(qd, dtype=float)


def _mfg(pkg, tree, q, qd, I_grav):
    M, f, g = module(pkg, "dynamics").equations_of_motion(tree, q, qd, np.asarray(I_grav, dtype=float))
    return {"M": np.array(M, dtype=float), "f": np.array(f, dtype=float), "g": np.array(g, dtype=float)}


@probe(returns=MFG, args=("", "vector", "vector", "vector"), terms="_dynamics.mfg_terms")
def mfg(pkg, description, q, qd, I_grav):
    """``{"M", "f", "g"}`` of the described tree at ``(q, qd)`` (``equations_of_motion``)."""
    return _mfg(pkg, build(pkg, description), *_vectors(q, qd), I_grav)


def _skew(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def _mistaken_share(body, I_grav, mistake):
    """A body's share of ``(M, f, g)`` from its state, with one mistake:

    ``no_gyroscopic``       f without ``skew(omega) I omega``
    ``gyroscopic_sign``     f with ``+skew(omega) I omega`` inside the bracket turned around (``(I omega) x omega``)
    ``no_bias``             f without the bias accelerations ``sigma_S``, ``sigma_R`` (gyroscopic term only)
    ``gravity_sign``        g with ``-I_grav``
    ``gravity_body_frame``  g with ``I_grav`` taken as body coordinates (no ``A_IB.T``)
    ``transpose``           ``J`` where ``J.T`` belongs (square Jacobians only: M = J m J.T, f, g projected by J)
    ``f_sign``              f with the opposite sign
    """
    J_S, J_R, I, m = (np.asarray(x, dtype=float) for x in (body.B_J_S, body.B_J_R, body.B_I_B, body.m))
    omega, sigma_S, sigma_R = (np.asarray(x, dtype=float) for x in (body.B_omega_B, body.B_a_B, body.B_omegaDot_B))
    A_IB = np.asarray(body.A_IB, dtype=float)
    P_S, P_R = (J_S, J_R) if mistake == "transpose" else (J_S.T, J_R.T)
    gyroscopic = {"missing_gyroscopic": 0.0, "gyroscopic_sign": -1.0}.get(mistake, 1.0) * _skew(omega) @ I @ omega
    bias = 0.0 if mistake == "missing_bias" else 1.0
    gravity = -I_grav if mistake == "gravity_sign" else I_grav
    B_grav = gravity if mistake == "gravity_body_frame" else A_IB.T @ gravity
    M = m * P_S @ P_S.T + P_R @ I @ P_R.T
    f = -(m * bias * P_S @ sigma_S + P_R @ (bias * I @ sigma_R + gyroscopic))
    return M, (-f if mistake == "f_sign" else f), m * P_S @ B_grav


@probe(reference_only=True)
def mfg_mistakes(pkg, description, q, qd, I_grav):
    """``{mistake: {"M", "f", "g"}}`` for the mistakes of ``MFG_MISTAKES`` (``transpose`` only when every Jacobian is
    square), from the package's kinematics of the described tree at ``(q, qd)``."""
    tree = build(pkg, description)
    q, qd = _vectors(q, qd)
    tree.forward_kinematics(q, qd, np.zeros(q.size))
    I_grav = np.asarray(I_grav, dtype=float)
    out = {}
    for mistake in MFG_MISTAKES:
        if mistake == "transpose" and q.size != 3:
            continue
        shares = [_mistaken_share(body, I_grav, mistake) for body in tree.bodies]
        out[mistake] = {key: sum(share[k] for share in shares) for k, key in enumerate(("M", "f", "g"))}
    return out


@probe(reference_only=True)
def mfg_terms(pkg, description, q, qd, I_grav):
    """``M``, ``f``, ``g`` of the described tree at ``(q, qd)`` split into named terms, from the package's
    kinematics (the diagnosis engine calls it on the reference): ``M`` = translation + rotation, ``f`` = bias +
    gyroscopic, ``g`` = gravity; and terms that do not belong: gravity counted in ``f`` as well."""
    tree = build(pkg, description)
    q, qd = _vectors(q, qd)
    tree.forward_kinematics(q, qd, np.zeros(q.size))
    I_grav = np.asarray(I_grav, dtype=float)
    n = q.size
    translation, rotation = np.zeros((n, n)), np.zeros((n, n))
    bias, gyroscopic, gravity = np.zeros(n), np.zeros(n), np.zeros(n)
    for body in tree.bodies:
        J_S, J_R, I, m = (np.asarray(x, dtype=float) for x in (body.B_J_S, body.B_J_R, body.B_I_B, body.m))
        omega, sigma_S, sigma_R = (np.asarray(x, dtype=float) for x in (body.B_omega_B, body.B_a_B, body.B_omegaDot_B))
        translation += m * J_S.T @ J_S
        rotation += J_R.T @ I @ J_R
        bias -= m * J_S.T @ sigma_S + J_R.T @ I @ sigma_R
        gyroscopic -= J_R.T @ _skew(omega) @ I @ omega
        gravity += m * J_S.T @ np.asarray(body.A_IB, dtype=float).T @ I_grav
    return {"terms": {"translation": {"M": translation}, "rotation": {"M": rotation}, "bias": {"f": bias},
                      "gyroscopic": {"f": gyroscopic}, "gravity": {"g": gravity}},
            "extra": {"gravity": {"f": gravity}}}


def _positions(tree):
    return [np.asarray(body.A_IB, dtype=float) @ np.asarray(body.B_r_IB, dtype=float).reshape(3)
            for body in tree.bodies]


@probe(
    returns=Dict(
        {
            **MFG.fields,
            "bodies": Seq(
                Dict({"name": Text(), "m": Num(), "I": Arr(3, 3), "B_J_S": Arr(3, None), "B_J_R": Arr(3, None)})
            ),
            "M_coordinates": Seq(Tup(Arr(None, None), Arr(None, None))),
            "M_path": Tup(Arr(None, None), Arr(None, None)),
            "positions": Seq(Tup(Seq(Arr(3)), Seq(Arr(3)))),
        }
    ),
    part={"keys": ("M", "f", "g"), "probe": "_dynamics.mfg", "args": (0, 1, 2, 3)},
)
def lagrange(pkg, description, q, qd, I_grav, h):
    """What the physics checks need from the package alone: ``M``, ``f``, ``g`` at ``(q, qd)``; every body's mass,
    inertia and Jacobians after that pass (``"bodies"``); ``M`` at ``q +- h e_i`` (``"M_coordinates"``) and at
    ``q +- h qd`` (``"M_path"``); the bodies' inertial positions at ``q +- h e_i`` (``"positions"``)."""
    tree = build(pkg, description)
    q, qd = _vectors(q, qd)
    at = _mfg(pkg, tree, q, qd, I_grav)
    bodies = [{"name": body.name, "m": float(body.m), "I": np.array(body.B_I_B, dtype=float),
               "B_J_S": np.array(body.B_J_S, dtype=float), "B_J_R": np.array(body.B_J_R, dtype=float)}
              for body in tree.bodies]
    zero = np.zeros(q.size)

    def mass_matrix(x):
        return _mfg(pkg, tree, x, zero, I_grav)["M"]

    shifted_M, positions = [], []
    for e in np.eye(q.size):
        shifted_M.append([mass_matrix(q + h * e), mass_matrix(q - h * e)])
        pair = []
        for sign in (1.0, -1.0):
            tree.forward_kinematics(q + sign * h * e)
            pair.append(_positions(tree))
        positions.append(pair)
    return {**at, "bodies": bodies, "M_coordinates": shifted_M, "M_path": [mass_matrix(q + h * qd),
                                                                             mass_matrix(q - h * qd)],
            "positions": positions}


@probe(returns=Arr(None), says="forward_dynamics(M, f, g, tau)")
def forward_dynamics(pkg, M, f, g, tau):
    """``dynamics.forward_dynamics(M, f, g, tau)``."""
    args = (np.asarray(x, dtype=float) for x in (M, f, g, tau))
    return np.array(module(pkg, "dynamics").forward_dynamics(*args), dtype=float)


def energies(tree, q, qd, I_grav):
    """``(T, V)`` of a tree of the package at ``(q, qd)`` from its own kinematics: ``T = sum(m v.v + omega.I omega)
    / 2`` with ``v = A_IB B_J_S qd``, ``omega = B_J_R qd``; ``V = -sum(m I_grav . A_IB B_r_IB)``."""
    q, qd = _vectors(q, qd)
    tree.forward_kinematics(q, qd, np.zeros(q.size))
    T = V = 0.0
    for body in tree.bodies:
        v = np.asarray(body.B_J_S, dtype=float) @ qd
        omega = np.asarray(body.B_J_R, dtype=float) @ qd
        T += 0.5 * float(body.m) * v @ v + 0.5 * omega @ np.asarray(body.B_I_B, dtype=float) @ omega
        V -= float(body.m) * np.asarray(I_grav, dtype=float) @ (np.asarray(body.A_IB, dtype=float)
                                                                 @ np.asarray(body.B_r_IB, dtype=float))
    return float(T), float(V)


def trace(run, n, what):
    """``(t, q, qd)`` of a simulation's result ``{"t", "q", "qd"}`` as float arrays (``q``, ``qd``: one row of ``n``
    values per output time), or a ValueError that says what is wrong."""
    if not isinstance(run, dict) or not {"t", "q", "qd"} <= set(run):
        raise ValueError(f"{what} must return a dict with the keys 't', 'q' and 'qd', got {str(run)[:200]}")
    t = np.asarray(run["t"], dtype=float).reshape(-1)
    arrays = []
    for key in ("q", "qd"):
        value = np.asarray(run[key], dtype=float)
        if value.shape != (t.size, n):
            raise ValueError(f"{what}: {key!r} must have one row of {n} values per output time ({t.size} x {n}), "
                             f"got shape {value.shape}")
        arrays.append(value)
    return t, arrays[0], arrays[1]


@probe(
    returns=Dict(
        {
            "t": Arr(None),
            "q": Arr(None, 3),
            "qd": Arr(None, 3),
            "T": Arr(None, finite=False),
            "V": Arr(None, finite=False),
        }
    ),
    says="problem_24.simulate({0})",
    motion={"time": "t", "states": ("q", "qd"), "fixed_step": "_dynamics.pendulum_motion_fixed",
               "schemes": ("euler", "symplectic"), "steps": (0.002, 0.005, 0.01, 0.02),
               "rhs": "problem_24.pendulum_ode", "rhs_args": (),
               "start": {"arg": 2, "name": "q0", "sheet": "_dynamics.pendulum_start"}},
)
def pendulum_motion(pkg, t_end, I_grav, q0=None, qd0=None, dt=None):
    """Problem 24: the package's ``problem_24.simulate(t_end)`` (released at ``q0`` with the speeds ``qd0``, output
    every ``dt``, each when given) and, at every output time, the energies ``T`` and ``V`` of its own triple
    pendulum (``build_triple_pendulum(DynamicBody)``) under ``I_grav``."""
    p24 = module(pkg, "problem_24")
    given = [q0, qd0, None if dt is None else float(dt)]
    while given and given[-1] is None:
        given.pop()
    args = [np.asarray(default if x is None else x, dtype=float) for x, default in zip(given, (p24.Q, np.zeros(3)))]
    run = p24.simulate(t_end, *args, *given[2:])
    t, q, qd = trace(run, 3, "problem_24.simulate")
    tree = p24.build_triple_pendulum(module(pkg, "dynamics").DynamicBody)
    T, V = np.array([energies(tree, a, b, I_grav) for a, b in zip(q, qd)]).reshape(-1, 2).T
    return {"t": t, "q": q, "qd": qd, "T": T, "V": V}


@contextmanager
def solver_variant(variant, *modules):
    """While the package computes a run: ``scipy.integrate.solve_ivp`` as a slip would call it (the diagnosis
    engine's runs of the reference, ``variant``): ``["tolerance", rtol, atol]``, every call by the default method
    (RK45) at those tolerances; ``["start", i, j]``, the first call from its ``y0`` with the entries ``i`` and ``j``
    exchanged.  ``modules``: the package's modules that hold ``solve_ivp`` by name, replaced there too."""
    import scipy.integrate

    original = scipy.integrate.solve_ivp
    kind, *rest = variant
    if kind not in ("tolerance", "start"):
        raise ValueError(f"no run variant {kind!r}")
    calls = []

    def varied(fun, t_span, y0, *args, **kwargs):
        if kind == "tolerance":
            kwargs.update(method="RK45", rtol=float(rest[0]), atol=float(rest[1]))
        elif not calls:
            y0 = np.array(y0, dtype=float)
            i, j = (int(k) for k in rest)
            y0[[i, j]] = y0[[j, i]]
        calls.append(kind)
        return original(fun, t_span, y0, *args, **kwargs)

    held = [m for m in modules if getattr(m, "solve_ivp", None) is original]
    scipy.integrate.solve_ivp = varied
    for m in held:
        m.solve_ivp = varied
    try:
        yield
    finally:
        scipy.integrate.solve_ivp = original
        for m in held:
            m.solve_ivp = original


def fixed_run(run, n):
    """``{"t", "q", "qd"}`` of a ``fixed_step`` run of ``y = (q, qd)`` with ``n`` coordinates (and its
    ``t_event``)."""
    times, states = run["t"], run["y"]
    return {"t": times, "q": states[:, :n], "qd": states[:, n:], "t_event": run["t_event"]}


def fixed_step(fun, y0, t_end, h, scheme, event=None, direction=-1.0):
    """A run of ``dy/dt = fun(t, y)`` from ``y0`` at ``t = 0`` to ``t_end`` with a fixed step ``h``: ``scheme``
    "euler" (explicit Euler) or "symplectic" (semi-implicit Euler on ``y = (q, qd)``: ``qd`` first, then ``q`` with
    the new ``qd``).  With ``event``, the run ends at the first step over which ``event(t, y)`` crosses zero in its
    ``direction`` (-1: from + to -; +1: from - to +).  ``{"t", "y", "t_event"}``: times and rows of the run.

    The grader's diagnosis engine compares a student's run with such runs of the reference's own right-hand side
    (an error that has the shape of a fixed-step integration's, and scales with its step)."""
    y = np.asarray(y0, dtype=float)
    t, times, rows, t_event = 0.0, [0.0], [y], None
    half = y.size // 2
    for k in range(int(round(t_end / h))):
        slope = np.asarray(fun(t, y), dtype=float)
        if scheme == "symplectic":
            qd = y[half:] + h * slope[half:]
            following = np.concatenate([y[:half] + h * qd, qd])
        else:
            following = y + h * slope
        t_next = (k + 1) * h
        if event is not None:
            before, after = event(t, y), event(t_next, following)
            if (direction <= 0 and before > 0 >= after) or (direction >= 0 and before < 0 <= after):
                t_event = t_next
                times.append(t_next)
                rows.append(following)
                break
        t, y = t_next, following
        times.append(t)
        rows.append(y)
    return {"t": np.array(times), "y": np.array(rows), "t_event": t_event}


@probe(reference_only=True)
def pendulum_start(pkg):
    """Problem 24's start ``Q``: the angles ``simulate`` releases the pendulum at where it is given no ``q0`` (the
    diagnosis engine calls it on the reference)."""
    return [float(x) for x in module(pkg, "problem_24").Q]


@probe(reference_only=True)
def pendulum_motion_fixed(pkg, t_end, I_grav, *rest):
    """Problem 24's pendulum released as in ``problem_24.simulate``, run by a fixed-step ``scheme`` at step ``h``
    with the package's own ``pendulum_ode`` (the diagnosis engine calls it on the reference, with the arguments of
    ``pendulum_motion`` followed by ``h, scheme``: ``rest`` is ``(h, scheme)``, ``(q0, h, scheme)``,
    ``(q0, qd0, h, scheme)`` or ``(q0, qd0, dt, h, scheme)``)."""
    *start, h, scheme = rest
    q0, qd0 = (list(start) + [None, None])[:2]
    p24 = module(pkg, "problem_24")
    tree = p24.build_triple_pendulum(module(pkg, "dynamics").DynamicBody)
    y0 = np.concatenate([np.asarray(p24.Q if q0 is None else q0, dtype=float),
                         np.zeros(3) if qd0 is None else np.asarray(qd0, dtype=float)])
    return fixed_run(fixed_step(lambda t, y: p24.pendulum_ode(t, y, tree), y0, t_end, h, scheme), 3)


def ode_terms(pkg, tree, cases, I_grav):
    """The right-hand side ``dy/dt`` of ``tree`` (``y = (q, qd)``) at every ``(t, y)`` of ``cases`` split into named
    terms with the package's own ``M, f, g``: ``(qd, 0) + (0, M^-1 f) + (0, M^-1 g)`` (the diagnosis engine's split
    of a run's right-hand side)."""
    equations_of_motion = module(pkg, "dynamics").equations_of_motion
    terms = {"velocity": [], "f": [], "gravity": []}
    for t, y in cases:
        y = np.asarray(y, dtype=float)
        n = len(y) // 2
        q, qd = y[:n], y[n:]
        M, f, g = (np.array(x, dtype=float) for x in equations_of_motion(tree, q.copy(), qd.copy(), I_grav))
        zero = np.zeros(n)
        terms["velocity"].append(np.concatenate([qd, zero]))
        terms["f"].append(np.concatenate([zero, np.linalg.solve(M, f)]))
        terms["gravity"].append(np.concatenate([zero, np.linalg.solve(M, g)]))
    return {"terms": terms, "extra": {}}
