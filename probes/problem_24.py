"""Probes of problem 24: recursive forward kinematics (positions and orientations) of the triple pendulum and of
random trees of rotational joints."""

import numpy as np

from . import _trees, module, probe
from ._dynamics import ode_terms
from ._trees import OUTLINE, POSES
from ._forms import Arr, Dict, Seq


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


@probe(returns=Seq(Arr(6), length=lambda cases: len(cases)), says="pendulum_ode",
       terms="problem_24.pendulum_ode_terms")
def pendulum_ode(pkg, cases):
    """``pendulum_ode(t, y, build_triple_pendulum(DynamicBody))`` for every ``(t, y)`` of ``cases`` (the
    diagnosis engine compares it with the reference's at states along a run)."""
    p24 = module(pkg, "problem_24")
    tree = p24.build_triple_pendulum(module(pkg, "dynamics").DynamicBody)
    return [np.array(p24.pendulum_ode(float(t), np.asarray(y, dtype=float), tree), dtype=float) for t, y in cases]


@probe(reference_only=True)
def pendulum_ode_terms(pkg, cases):
    """``pendulum_ode`` of every case split into named terms (the diagnosis engine calls it on the reference):
    ``dy/dt = (qd, 0) + (0, M^-1 f) + (0, M^-1 g)`` with the package's own ``M, f, g``."""
    p24 = module(pkg, "problem_24")
    tree = p24.build_triple_pendulum(module(pkg, "dynamics").DynamicBody)
    return ode_terms(pkg, tree, cases, p24.I_GRAV)
