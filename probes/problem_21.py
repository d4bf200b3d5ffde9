"""Probes of problem 21: the planar arms of cases a and b and their Jacobians."""

import numpy as np

from . import module, probe
from ._forms import Arr, Dict, Seq

CHAINS = {"a": ("chain_a", "jacobian_a"), "b": ("chain_b", "jacobian_b")}


@probe(returns=Arr(None), says="chain_{0}(q, d)", args=("", "vector", "scalar"))
def chain(pkg, case, q, d):
    return getattr(module(pkg, "planar"), CHAINS[case][0])(q, d)


@probe(returns=Arr(None, None), says="jacobian_{0}(q, d)", args=("", "vector", "scalar"))
def jacobian(pkg, case, q, d):
    return getattr(module(pkg, "planar"), CHAINS[case][1])(q, d)


@probe(
    returns=Dict({"J": Arr(None, None), "plus": Seq(Arr(None)), "minus": Seq(Arr(None))}),
    says="chain_{0} and jacobian_{0}",
)
def jacobian_and_steps(pkg, case, q, d, h):
    """The analytic Jacobian and the chain at ``q +- h e_j`` for every joint j (for central differences)."""
    planar = module(pkg, "planar")
    f, J = (getattr(planar, name) for name in CHAINS[case])
    q = np.asarray(q, dtype=float)
    steps = h * np.eye(q.size)
    return {"J": J(q, d), "plus": [f(q + e, d) for e in steps], "minus": [f(q - e, d) for e in steps]}


def _complex_step(f, q):
    """Jacobian of ``f`` at ``q`` by complex steps (exact to rounding)."""
    q = np.asarray(q, dtype=float)
    return np.column_stack([np.imag(f(q + 1e-30j * e)) / 1e-30 for e in np.eye(q.size)])


@probe(reference_only=True)
def mistakes(pkg, q, d):
    """What ``chain_a`` / ``chain_b`` (by the length of ``q``) and their Jacobians give with each known mistake
    (``mistaken_layout``, which only the reference has): ``{"chain": {mistake: x}, "jacobian": {mistake: J}}``."""
    planar = module(pkg, "planar")
    return {
        "chain": {mistake: planar.mistaken_layout(q, d, mistake) for mistake in planar.ARM_MISTAKES},
        "jacobian": {mistake: _complex_step(lambda p, mistake=mistake: planar.mistaken_layout(p, d, mistake), q)
                     for mistake in planar.ARM_MISTAKES},
    }


@probe(reference_only=True)
def sheet_case(pkg):
    """Case (2) of the sheet with ``q_b``: the joint coordinates, ``d`` and the printed end-effector pose."""
    p21 = module(pkg, "problem_21")
    return {"q_b": p21.CASES[2][1], "d": p21.D, "target": p21.TARGET_END_EFFECTOR_CASE_2}
