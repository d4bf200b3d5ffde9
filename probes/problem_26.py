"""Probes of problem 26: position and constraint Jacobian of the chairoplane's seat."""

import numpy as np

from . import module, probe
from ._forms import Arr, Dict, Seq


@probe(returns=Arr(3), says="position({0}, {1}, {2}, {3}, {4})", args=("angle", "angle", "scalar", "scalar", "scalar"))
def position(pkg, beta, phi, l1, l2, l3):
    return module(pkg, "problem_26").position(beta, phi, l1, l2, l3)


@probe(
    returns=Arr(ndim=2),
    says="jacobian({0}, {1}, {2}, {3}, {4})",
    args=("angle", "angle", "scalar", "scalar", "scalar"),
)
def jacobian(pkg, beta, phi, l1, l2, l3):
    return module(pkg, "problem_26").jacobian(beta, phi, l1, l2, l3)


@probe(returns=Dict({"J": Arr(ndim=2), "plus": Seq(Arr(3)), "minus": Seq(Arr(3))}), says="position and jacobian")
def jacobian_and_steps(pkg, beta, phi, l1, l2, l3, h):
    """The analytic Jacobian and the position at ``q +- h e_j`` for ``q = (beta, phi)`` (for central differences)."""
    p26 = module(pkg, "problem_26")
    steps = h * np.eye(2)
    return {
        "J": p26.jacobian(beta, phi, l1, l2, l3),
        "plus": [p26.position(beta + db, phi + dp, l1, l2, l3) for db, dp in steps],
        "minus": [p26.position(beta - db, phi - dp, l1, l2, l3) for db, dp in steps],
    }


def _complex_step(f, q):
    """Jacobian of ``f`` at ``q`` by complex steps (exact to rounding)."""
    q = np.asarray(q, dtype=float)
    return np.column_stack([np.imag(f(q + 1e-30j * e)) / 1e-30 for e in np.eye(q.size)])


@probe(reference_only=True)
def mistakes(pkg, beta, phi, l1, l2, l3):
    """What the seat's position and its Jacobian are with each known mistake (``mistaken_position``, which only
    the reference has): ``{"position": {mistake: x}, "jacobian": {mistake: J}}``."""
    p26 = module(pkg, "problem_26")
    found = {"position": {}, "jacobian": {}}
    for mistake in p26.POSITION_MISTAKES:
        found["position"][mistake] = p26.mistaken_position(beta, phi, l1, l2, l3, mistake)
        found["jacobian"][mistake] = _complex_step(
            lambda q, mistake=mistake: p26.mistaken_position(*q, l1, l2, l3, mistake), (beta, phi))
    return found
