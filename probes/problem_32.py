"""Probes of problem 32: rigid joints, generalized gravity, and the robot arm's gravity-compensating torques."""

import numpy as np

from . import _trees, module, probe
from ._forms import Arr, Dict, Seq, Tup
from ._trees import BODIES, OUTLINE, POSES


@probe(
    returns=Dict({**POSES.fields, "outline": OUTLINE, "end_effector": Arr(any_shape=True, finite=False)}),
    says="build_robot()",
    args=("vector",),
)
def robot(pkg, q):
    """The arm of ``build_robot`` at ``q``: body states, outline and ``end_effector_position``."""
    p32 = module(pkg, "problem_32")
    tree = p32.build_robot()
    end_effector = p32.end_effector_position(tree, np.asarray(q, dtype=float))
    return {**_trees.state(tree, motion=False), "outline": _trees.outline(tree), "end_effector": end_effector}


@probe(returns=Arr(None), says="generalized_gravity(tree, q, I_grav)", args=("", "vector", "vector"))
def gravity(pkg, description, q, I_grav):
    tree_module = module(pkg, "tree")
    return tree_module.generalized_gravity(_trees.build(tree_module, description), np.asarray(q, dtype=float),
                                           np.asarray(I_grav, dtype=float))


@probe(returns=Dict({"g": Arr(None), "shifted": Seq(Tup(BODIES, BODIES))}), says="generalized_gravity(tree, q, I_grav)")
def potential(pkg, description, q, I_grav, h):
    """``generalized_gravity`` at ``q`` and the poses at ``q +- h e_i``."""
    tree_module = module(pkg, "tree")
    tree = _trees.build(tree_module, description)
    q = np.asarray(q, dtype=float)
    g = tree_module.generalized_gravity(tree, q, np.asarray(I_grav, dtype=float))
    shifted = []
    for e in np.eye(q.size):
        pair = []
        for sign in (1.0, -1.0):
            tree.forward_kinematics(q + sign * h * e)
            pair.append(_trees.state(tree, motion=False)["bodies"])
        shifted.append(pair)
    return {"g": g, "shifted": shifted, "names": [body.name for body in tree.bodies]}


@probe(returns=Dict({"t": Arr(None), "q": Arr(None, 3)}), says="desired_trajectory()")
def trajectory(pkg):
    """The desired joint trajectory ``{"t", "q"}`` (inverse kinematics on the 209-point grid)."""
    table = module(pkg, "problem_32").desired_trajectory()
    return {"t": table["t"], "q": table["q"]}


@probe(returns=Seq(Arr(3)), says="gravity_compensation(tree, q)", rows=0)
def torques(pkg, qs):
    """``gravity_compensation(build_robot(), q)`` for every row of ``qs``."""
    p32 = module(pkg, "problem_32")
    tree = p32.build_robot()
    return [p32.gravity_compensation(tree, q) for q in np.asarray(qs, dtype=float)]


@probe(reference_only=True)
def robot_case(pkg):
    """The arm of ``build_robot`` as a plain-data description, and the start of the end effector's path."""
    p32 = module(pkg, "problem_32")
    return {"description": _trees.describe(module(pkg, "tree"), p32.build_robot()), "x_start": p32.X_START}
