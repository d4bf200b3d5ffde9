"""Problem 9: relative coordinate systems reproduce problem 6."""

from .cosys import CoSys
from .problem_06 import ALPHA, BETA, C3_V, GAMMA
from .rotations import R1, R2, R3

__all__ = ["build_chain", "vectors"]


def build_chain():
    """The frames I -> C1 -> C2 -> C3 of problem 6, each built relative to its predecessor."""
    C1 = CoSys(R3(GAMMA))
    C2 = CoSys(R2(BETA), C1)
    C3 = CoSys(R1(ALPHA), C2)
    return C1, C2, C3


def vectors():
    """V in I, C1, C2, C3 computed with ``get_transform`` only."""
    C1, C2, C3 = build_chain()
    I_v = C3.get_transform() @ C3_V
    return {
        "I_v": I_v,
        "C1_v": C3.get_transform(C1) @ C3_V,
        "C2_v": C3.get_transform(C2) @ C3_V,
        "C3_v": C3.get_transform(C3) @ C3_V,
    }
