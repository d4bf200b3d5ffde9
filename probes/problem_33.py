"""Probes of problem 33: the passive dynamic walker with velocities, accelerations and Jacobians, and random trees
with rolling contacts."""

import numpy as np

from . import _trees, module, probe


@probe
def walker(pkg, q, qd, qdd):
    """The walker of ``build_walker`` after a full pass at ``(q, qd, qdd)``."""
    tree = module(pkg, "problem_25").build_walker()
    tree.forward_kinematics(*(np.asarray(v, dtype=float) for v in (q, qd, qdd)))
    return {**_trees.state(tree), "outline": _trees.outline(tree)}
