"""Probes of problem 13: the screw axis of a body's twist."""

from . import probe
from ._forms import Arr, Tup
from ._scenario import BODY_ROLES, body_run


@probe(returns=Tup(Arr(3, finite=False), Arr(3, finite=False)), says="screw_axis()", args=(BODY_ROLES,),
       rotation=(0, "A_IB"))
def screw(pkg, state):
    """``screw_axis()`` of a kinematic body in ``state``: ``[B_r_BT, B_v_T]``."""
    out = body_run(pkg, "rigid_body.RigidBodyKinematics", state, [], 0, read=[("screw", "screw_axis", [])])
    return out["final"]["screw"]
