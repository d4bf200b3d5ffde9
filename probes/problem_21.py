"""Probes of problem 21: the planar arms of cases a and b and their Jacobians."""

import numpy as np

from . import module, probe

CHAINS = {"a": ("chain_a", "jacobian_a"), "b": ("chain_b", "jacobian_b")}


@probe
def chain(pkg, case, q, d):
    return getattr(module(pkg, "planar"), CHAINS[case][0])(q, d)


@probe
def jacobian(pkg, case, q, d):
    return getattr(module(pkg, "planar"), CHAINS[case][1])(q, d)


@probe
def jacobian_and_steps(pkg, case, q, d, h):
    """The analytic Jacobian and the chain at ``q +- h e_j`` for every joint j (for central differences)."""
    planar = module(pkg, "planar")
    f, J = (getattr(planar, name) for name in CHAINS[case])
    q = np.asarray(q, dtype=float)
    steps = h * np.eye(q.size)
    return {"J": J(q, d), "plus": [f(q + e, d) for e in steps], "minus": [f(q - e, d) for e in steps]}
