"""Problem 18: rotation rate and acceleration for which a body point Q does not accelerate."""

from .inertia import non_accelerating_point

__all__ = ["solutions"]


def solutions(a_x, a_y, r_x, r_y):
    """Both solutions ``[(omega, omega_dot), (-omega, omega_dot)]`` (one if ``omega = 0``)."""
    omega, omega_dot = non_accelerating_point(a_x, a_y, r_x, r_y)
    return [(omega, omega_dot)] if omega == 0.0 else [(omega, omega_dot), (-omega, omega_dot)]
