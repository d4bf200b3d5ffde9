"""Probes of problem 33: the passive dynamic walker with velocities, accelerations and Jacobians, and random trees
with rolling contacts."""

import numpy as np

from . import _trees, module, probe
from ._forms import Dict
from ._trees import OUTLINE, STATE


@probe(returns=Dict({**STATE.fields, "outline": OUTLINE}), says="build_walker()", args=("vector", "vector", "vector"))
def walker(pkg, q, qd, qdd):
    """The walker of ``build_walker`` after a full pass at ``(q, qd, qdd)``."""
    tree = module(pkg, "problem_25").build_walker()
    tree.forward_kinematics(*(np.asarray(v, dtype=float) for v in (q, qd, qdd)))
    return {**_trees.state(tree), "outline": _trees.outline(tree)}


@probe(reference_only=True)
def walker_case(pkg):
    """The sheet's test state: the walker as a plain-data description, ``Q``, ``QD``, ``QDD``, and the foot's
    radius."""
    p33, p25 = module(pkg, "problem_33"), module(pkg, "problem_25")
    return {"description": _trees.describe(module(pkg, "tree"), p25.build_walker()), "q": p33.Q, "qd": p33.QD,
            "qdd": p33.QDD, "foot_radius": p25.FOOT_RADIUS}
