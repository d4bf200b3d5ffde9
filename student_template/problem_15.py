"""Problem 15: torque-free motion of a rigid body (m = 1, B_I_B = diag(1.5, 2, 2.5))."""

import numpy as np

from .rigid_body import RigidBodyDynamics, fixed_step_count

__all__ = ["MASS", "INERTIA", "CASES", "make_body", "run_case"]

MASS = 1.0
INERTIA = np.diag([1.5, 2.0, 2.5])
#: Initial velocities (B_v_B, B_omega_B) of cases 1-6; A_IB = E, B_r_IB = 0 initially.
CASES = {
    1: ((1, 1, 1), (0, 0, 0)),
    2: ((0, 0, 0), (1, 0, 0)),
    3: ((0, 0, 0), (1, 1, 1)),
    4: ((0, 0, 0), (1, 0.01, 0.01)),
    5: ((0, 0, 0), (0.01, 1, 0.01)),
    6: ((0, 0, 0), (0.01, 0.01, 1)),
}


def make_body(k):
    """The body of case ``k`` (1-6) at t = 0."""
    B_v_B, B_omega_B = CASES[k]
    return RigidBodyDynamics(MASS, INERTIA, B_v_B=B_v_B, B_omega_B=B_omega_B)


def run_case(k, dt=0.001, t_end=30.0):
    """Case ``k``: 30000 steps of 1 ms, each natural dynamics then integration step.
    Returns the final ``(A_IB, B_r_IB)``."""
    body = make_body(k)
    for _ in range(fixed_step_count(dt, t_end)):
        body.compute_natural_dynamics()
        body.integration_step(dt)
    return body.A_IB, body.B_r_IB
