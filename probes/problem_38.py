"""Probes of problem 38: the walker's right-hand side and its simulation, with the energies of the package's own
walker at every output time."""

import numpy as np

from . import module, probe
from ._dynamics import energies, fixed_run, fixed_step, ode_terms, trace
from ._forms import Arr, Dict, Seq


@probe(returns=Seq(Arr(4), length=lambda cases: len(cases)), says="walker_ode", terms="problem_38.walker_ode_terms")
def walker_ode(pkg, cases):
    """``walker_ode(t, y, build_dynamic_walker())`` for every ``(t, y)`` of ``cases``."""
    p38 = module(pkg, "problem_38")
    tree = p38.build_dynamic_walker()
    return [np.array(p38.walker_ode(float(t), np.asarray(y, dtype=float), tree), dtype=float) for t, y in cases]


@probe(
    returns=Dict(
        {
            "t": Arr(None),
            "q": Arr(None, 2),
            "qd": Arr(None, 2),
            "T": Arr(None, finite=False),
            "V": Arr(None, finite=False),
        }
    ),
    says="simulate({0}, {1})",
    motion={"time": "t", "states": ("q", "qd"), "fixed_step": "problem_38.simulate_fixed",
               "schemes": ("euler", "symplectic"), "rhs": "problem_38.walker_ode", "rhs_args": ()},
)
def simulate(pkg, t_end, n, I_grav, start=None):
    """``simulate(t_end, n)`` (from ``start = (q0, qd0)`` where given) and the energies ``T``, ``V`` (under
    ``I_grav``) of the package's own walker at every output time."""
    p38 = module(pkg, "problem_38")
    starts = () if start is None else tuple(np.array(x, dtype=float) for x in start)
    t, q, qd = trace(p38.simulate(t_end, n, *starts), 2, "problem_38.simulate")
    tree = p38.build_dynamic_walker()
    T, V = np.array([energies(tree, a, b, I_grav) for a, b in zip(q, qd)]).reshape(-1, 2).T
    return {"t": t, "q": q, "qd": qd, "T": T, "V": V}


@probe(reference_only=True)
def simulate_fixed(pkg, t_end, n, I_grav, *rest):
    """The walker of ``simulate`` run by a fixed-step ``scheme`` at step ``h`` with the package's own
    ``walker_ode`` (the diagnosis engine calls it on the reference, with the arguments of ``simulate`` followed by
    ``h, scheme``: ``rest`` is ``(h, scheme)`` or ``(start, h, scheme)``)."""
    *start, h, scheme = rest
    p38 = module(pkg, "problem_38")
    tree = p38.build_dynamic_walker()
    q0, qd0 = start[0] if start and start[0] is not None else (p38.Q0, p38.QD0)
    y0 = np.hstack([np.asarray(q0, dtype=float).reshape(-1), np.asarray(qd0, dtype=float).reshape(-1)])
    return fixed_run(fixed_step(lambda t, y: p38.walker_ode(t, y, tree), y0, t_end, h, scheme), 2)


@probe(reference_only=True)
def walker_ode_terms(pkg, cases):
    """``walker_ode`` of every case split into named terms (the diagnosis engine calls it on the reference):
    ``dy/dt = (qd, 0) + (0, M^-1 f) + (0, M^-1 g)`` with the package's own ``M, f, g``."""
    p38 = module(pkg, "problem_38")
    tree = p38.build_dynamic_walker()
    return ode_terms(pkg, tree, cases, p38.I_GRAV)


@probe(reference_only=True)
def stale_mass_matrix(pkg, cases):
    """Called on the reference only: ``walker_ode`` at every ``(t, y)`` of ``cases`` in turn as a right-hand side
    gives it that computes its model once, at the first case, and reuses it: ``{"M": ...}`` with the mass matrix of
    the first case (``f``, ``g`` at each state), ``{"model": ...}`` with its whole ``M, f, g``."""
    p38 = module(pkg, "problem_38")
    dynamics = module(pkg, "dynamics")
    tree = p38.build_dynamic_walker()
    first, out = None, {"M": [], "model": []}
    for _, y in cases:
        y = np.asarray(y, dtype=float)
        M, f, g = dynamics.equations_of_motion(tree, y[:2], y[2:], p38.I_GRAV)
        first = (M, f, g) if first is None else first
        for key, (M_, f_, g_) in (("M", (first[0], f, g)), ("model", first)):
            out[key].append(np.concatenate([y[2:], dynamics.forward_dynamics(M_, f_, g_, np.zeros(2))]))
    return out
