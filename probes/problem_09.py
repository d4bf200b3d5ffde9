"""Probes of problem 9: relative coordinate systems."""

from . import module, probe
from ._forms import ANY, Arr, Dict, Maybe, Seq

#: the sheet's angles of problem 6, which ``build_chain()`` reads from the module (imported there), and its vector
#: ``C3_V``, which ``vectors()`` reads (drawn anew so that its two entries alike are not: see problem 6's probes)
REBIND = {"module": "problem_09", "names": ("GAMMA", "BETA", "ALPHA", "C3_V")}
#: ``vectors()``: the coordinates of V in I, C1, C2, C3
VECTORS = Dict({"I_v": Arr(3), "C1_v": Arr(3), "C2_v": Arr(3), "C3_v": Arr(3)})


@probe(returns=Dict({"to_inertial": Seq(ANY), "pairs": Seq(ANY)}), says="CoSys.get_transform over the chain")
def chain(pkg, relatives):
    """Build C1 (relative to I), C2 (relative to C1), ... from the given A_BC; return every get_transform."""
    CoSys = module(pkg, "cosys").CoSys
    frames = []
    for A_BC in relatives:
        frames.append(CoSys(A_BC, frames[-1]) if frames else CoSys(A_BC))
    return {
        "to_inertial": [f.get_transform() for f in frames],
        "pairs": [[c.get_transform(b) for b in frames] for c in frames],
    }


@probe(returns=Dict({"A_BC": Arr(3, 3), "A_IC": Arr(3, 3)}), says="CoSys.set_transform", args=("rotation", "rotation"))
def set_later(pkg, A_IB, A_BC):
    """Create C at the identity, then place it relative to B with set_transform; return A_BC read back and A_IC."""
    CoSys = module(pkg, "cosys").CoSys
    B = CoSys(A_IB)
    C = CoSys()
    C.set_transform(A_BC, B)
    return {"A_BC": C.get_transform(B), "A_IC": C.get_transform()}


@probe(returns=VECTORS, says="vectors()", rebind=REBIND)
def vectors(pkg):
    return module(pkg, "problem_09").vectors()


@probe(returns=Dict({"vectors": VECTORS, "chain": Maybe(Seq(Arr(3, 3), length=4))}), says="vectors()",
       rebind=REBIND)
def vectors_with_chain(pkg):
    """``vectors()`` with the transformations of the package's own ``build_chain()``: ``A_IC3`` and ``A_CkC3``
    (None when they cannot be had)."""
    import numpy as np

    problem = module(pkg, "problem_09")
    try:
        C1, C2, C3 = problem.build_chain()
        own = [np.asarray(T, dtype=float) for T in
               (C3.get_transform(), C3.get_transform(C1), C3.get_transform(C2), C3.get_transform(C3))]
        own = own if all(T.shape == (3, 3) and np.all(np.isfinite(T)) for T in own) else None
    except Exception:  # noqa: BLE001 - the chain is judged by its own checks
        own = None
    return {"vectors": problem.vectors(), "chain": own}
