"""Probes of problem 18: the rotation for which a body point does not accelerate."""

from . import module, probe


@probe(args=("scalar", "scalar", "scalar", "scalar"))
def non_accelerating(pkg, a_x, a_y, r_x, r_y):
    """``(omega, omega_dot)``, or ``"ValueError: ..."`` if the function raises ``ValueError``."""
    try:
        return list(module(pkg, "inertia").non_accelerating_point(a_x, a_y, r_x, r_y))
    except ValueError as exc:
        return f"ValueError: {exc}"
