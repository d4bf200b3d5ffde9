"""Probes of problem 18: the rotation for which a body point does not accelerate."""

from . import module, probe
from ._forms import Arr, Either, Text


@probe(
    returns=Either(Text(), Arr(2, finite=False)),
    says="non_accelerating_point({0}, {1}, {2}, {3})",
    args=("scalar", "scalar", "scalar", "scalar"),
)
def non_accelerating(pkg, a_x, a_y, r_x, r_y):
    """``(omega, omega_dot)``, or ``"ValueError: ..."`` if the function raises ``ValueError``."""
    try:
        return list(module(pkg, "inertia").non_accelerating_point(a_x, a_y, r_x, r_y))
    except ValueError as exc:
        return f"ValueError: {exc}"
