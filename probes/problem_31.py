"""Probes of problem 31: velocities, accelerations and Jacobians of the triple pendulum and of random trees."""

import numpy as np

from . import _trees, module, probe
from ._forms import Dict
from ._trees import OUTLINE, STATE


@probe(
    returns=Dict({**STATE.fields, "outline": OUTLINE}),
    says="build_triple_pendulum()",
    args=("vector", "vector", "vector"),
)
def pendulum(pkg, q, qd, qdd):
    """The triple pendulum of ``build_triple_pendulum`` after a full pass at ``(q, qd, qdd)``."""
    tree = module(pkg, "problem_24").build_triple_pendulum()
    tree.forward_kinematics(*(np.asarray(v, dtype=float) for v in (q, qd, qdd)))
    return {**_trees.state(tree), "outline": _trees.outline(tree)}


@probe(reference_only=True)
def pendulum_case(pkg):
    """The sheet's test case: the triple pendulum as a plain-data description, ``Q``, ``QD`` and ``QDD``."""
    p31 = module(pkg, "problem_31")
    tree = module(pkg, "problem_24").build_triple_pendulum()
    return {"description": _trees.describe(module(pkg, "tree"), tree), "q": p31.Q, "qd": p31.QD, "qdd": p31.QDD}
