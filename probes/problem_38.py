"""Probes of problem 38: the walker's right-hand side and its simulation, with the energies of the package's own
walker at every output time."""

import numpy as np

from . import module, probe
from ._dynamics import energies, trace


@probe
def walker_ode(pkg, cases):
    """``walker_ode(t, y, build_dynamic_walker())`` for every ``(t, y)`` of ``cases``."""
    p38 = module(pkg, "problem_38")
    tree = p38.build_dynamic_walker()
    return [np.array(p38.walker_ode(float(t), np.asarray(y, dtype=float), tree), dtype=float) for t, y in cases]


@probe
def simulate(pkg, t_end, n, I_grav):
    """``simulate(t_end, n)`` and the energies ``T``, ``V`` (under ``I_grav``) of the package's own walker at every
    output time."""
    p38 = module(pkg, "problem_38")
    t, q, qd = trace(p38.simulate(t_end, n), 2, "problem_38.simulate")
    tree = p38.build_dynamic_walker()
    T, V = np.array([energies(tree, a, b, I_grav) for a, b in zip(q, qd)]).reshape(-1, 2).T
    return {"t": t, "q": q, "qd": qd, "T": T, "V": V}
