"""Probes of problem 24: recursive forward kinematics (positions and orientations) of the triple pendulum and of
random trees of rotational joints."""

import numpy as np

from . import _trees, module, probe
from ._trees import OUTLINE, POSES
from ._forms import Dict


@probe(returns=Dict({**POSES.fields, "outline": OUTLINE}), says="build_triple_pendulum()")
def pendulum(pkg, q):
    """The triple pendulum of ``build_triple_pendulum`` after a positions-only pass at ``q``."""
    tree = module(pkg, "problem_24").build_triple_pendulum()
    tree.forward_kinematics(np.asarray(q, dtype=float))
    return {**_trees.state(tree, motion=False), "outline": _trees.outline(tree)}


@probe(returns=POSES, says="forward_kinematics of the tree")
def tree_poses(pkg, description, q):
    return _trees.tree_state(pkg, description, q)


@probe(reference_only=True)
def pendulum_case(pkg):
    """The sheet's case: the triple pendulum as a plain-data description and the test configuration ``Q``."""
    p24 = module(pkg, "problem_24")
    return {"description": _trees.describe(module(pkg, "tree"), p24.build_triple_pendulum()), "q": p24.Q}
