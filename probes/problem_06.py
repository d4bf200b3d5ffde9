"""Probes of problem 6: elementary rotations, the Cardan sequence, and the sheet's frames and vectors."""

from . import module, probe
from ._forms import ANY, Arr, Dict, Maybe, Tup

#: the student's own value of an upstream function (``_own``): a rotation, or None when it cannot be had
OWN = Maybe(Arr(3, 3))
#: the sheet's angles, which ``frames()`` and ``vectors()`` read from the module
REBIND = {"module": "problem_06", "names": ("GAMMA", "BETA", "ALPHA")}
#: the sheet's angles and the vector ``C3_V``, which ``vectors()`` reads: the sheet's (1, 1, 1) has two entries
#: alike, so a rotation about x taken the wrong way round exchanges them; drawn anew, each entry is its own
REBIND_VECTORS = {"module": "problem_06", "names": (*REBIND["names"], "C3_V")}
#: ``vectors()``: the coordinates of V in I, C1, C2, C3
VECTORS = Dict({"I_v": Arr(3), "C1_v": Arr(3), "C2_v": Arr(3), "C3_v": Arr(3)})


@probe(returns=Arr(3, 3), says="R{0}({1})", args=("", "angle"))
def elementary(pkg, axis, angle):
    rotations = module(pkg, "rotations")
    return {1: rotations.R1, 2: rotations.R2, 3: rotations.R3}[axis](angle)


@probe(returns=Arr(3, 3), says="cardan({0}, {1}, {2})", args=("angle", "angle", "angle"))
def cardan(pkg, alpha, beta, gamma):
    return module(pkg, "rotations").cardan(alpha, beta, gamma)


@probe(returns=Dict({"A_IC1": Arr(3, 3), "A_IC2": Arr(3, 3), "A_IC3": Arr(3, 3)}), says="frames()", rebind=REBIND)
def frames(pkg):
    return module(pkg, "problem_06").frames()


@probe(returns=VECTORS, says="vectors()", rebind=REBIND_VECTORS)
def vectors(pkg):
    return module(pkg, "problem_06").vectors()


def _own(call):
    """The student's own value of an upstream function (judged on in a later check), or None when it cannot be
    had (not implemented, raises, not numeric)."""
    try:
        import numpy as np

        value = np.asarray(call(), dtype=float)
        return value if value.shape == (3, 3) and np.all(np.isfinite(value)) else None
    except Exception:  # noqa: BLE001 - a missing upstream value is judged by its own check
        return None


@probe(
    returns=Dict({"cardan": Arr(3, 3), "R1": OWN, "R2": OWN, "R3": OWN}),
    says="cardan({0}, {1}, {2})",
    args=("angle", "angle", "angle"),
)
def cardan_with_factors(pkg, alpha, beta, gamma):
    """``cardan(alpha, beta, gamma)`` with the package's own factors ``R1(alpha), R2(beta), R3(gamma)``."""
    rotations = module(pkg, "rotations")
    return {
        "cardan": rotations.cardan(alpha, beta, gamma),
        "R1": _own(lambda: rotations.R1(alpha)),
        "R2": _own(lambda: rotations.R2(beta)),
        "R3": _own(lambda: rotations.R3(gamma)),
    }


@probe(returns=Dict({"frames": ANY, "R1": OWN, "R2": OWN, "R3": OWN, "cardan": Tup(OWN, OWN, OWN)}), says="frames()",
       rebind=REBIND)
def frames_with_factors(pkg, alpha, beta, gamma):
    """``frames()`` with the package's own ``R3(gamma), R2(beta), R1(alpha)`` and ``cardan`` of the partial
    sequences ``(0, 0, gamma), (0, beta, gamma), (alpha, beta, gamma)``."""
    rotations = module(pkg, "rotations")
    return {
        "frames": module(pkg, "problem_06").frames(),
        "R1": _own(lambda: rotations.R1(alpha)),
        "R2": _own(lambda: rotations.R2(beta)),
        "R3": _own(lambda: rotations.R3(gamma)),
        "cardan": [_own(lambda: rotations.cardan(0.0, 0.0, gamma)), _own(lambda: rotations.cardan(0.0, beta, gamma)),
                   _own(lambda: rotations.cardan(alpha, beta, gamma))],
    }


@probe(
    returns=Dict({"vectors": VECTORS, "frames": Maybe(Dict({"A_IC1": OWN, "A_IC2": OWN, "A_IC3": OWN}))}),
    says="vectors()",
    rebind=REBIND_VECTORS,
)
def vectors_with_frames(pkg):
    """``vectors()`` with the package's own ``frames()`` (None when they cannot be had)."""
    problem = module(pkg, "problem_06")
    try:
        own = problem.frames()
        own = {key: _own(lambda key=key: own[key]) for key in ("A_IC1", "A_IC2", "A_IC3")}
    except Exception:  # noqa: BLE001
        own = None
    return {"vectors": problem.vectors(), "frames": own}
