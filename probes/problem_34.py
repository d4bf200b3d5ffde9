"""Probes of problem 34: the biped on its virtual 3-DOF joint, and random trees with translational and virtual
3-DOF joints."""

from . import _trees, module, probe
from ._trees import OUTLINE, STATE
from ._forms import Dict


@probe(returns=Dict({**STATE.fields, "outline": OUTLINE}), says="build_biped()")
def biped(pkg, t):
    """The biped of ``build_biped`` following ``gait(t)``; the outline starts at the main body."""
    p34 = module(pkg, "problem_34")
    tree = p34.build_biped()
    tree.forward_kinematics(*p34.gait(t))
    return {**_trees.state(tree), "outline": _trees.outline(tree, tree["main_body"])}


@probe(reference_only=True)
def biped_case(pkg, frame):
    """The biped of ``build_biped`` as a plain-data description, the time of the gait's ``frame`` and ``gait(t)``
    there (``q``, ``qd``, ``qdd``)."""
    p34 = module(pkg, "problem_34")
    t = p34.frame_time(frame)
    q, qd, qdd = p34.gait(t)
    return {"description": _trees.describe(module(pkg, "tree"), p34.build_biped()), "t": t, "q": q, "qd": qd,
            "qdd": qdd}
