"""Problem 12: rigid body kinematics, integrated with accelerations constant in body coordinates."""

import numpy as np

from .rigid_body import RigidBodyKinematics, fixed_step_count

__all__ = ["CASES", "PART_B", "B_R_BQ", "run_case", "run_part_b"]

#: Initial velocities and constant accelerations of part (a), cases 1-3 (A_IB = E, B_r_IB = 0 initially).
CASES = {
    1: dict(B_v_B=(0, 0, 0), B_omega_B=(0, 1.5, 0), B_a_B=(0, 0, 0), B_omegaDot_B=(0, 0, 0)),
    2: dict(B_v_B=(1.5, 0, 0), B_omega_B=(0, 1.5, 0), B_a_B=(0, 0, 0), B_omegaDot_B=(0, 0, 0)),
    3: dict(B_v_B=(0, 0, 0), B_omega_B=(0, 0, 0), B_a_B=(1.5, 0, 0), B_omegaDot_B=(0, 1.5, 0)),
}
#: Part (b): a rolling wheel.
PART_B = dict(B_v_B=(0, 0, 0), B_omega_B=(0, 0, 4), B_a_B=(0, 3, 0), B_omegaDot_B=(0, 0, 0))
#: Part (b): the body point Q.
B_R_BQ = np.array([0.0, 3 / 16, 0.0])


def run_case(k, dt=0.01, t_end=1.0):
    """Case ``k`` (1-3) of part (a): 100 integration steps of 0.01 s. Returns the final ``(A_IB, B_r_IB)``."""
    body = RigidBodyKinematics(**CASES[k])
    for _ in range(fixed_step_count(dt, t_end)):
        body.integration_step(dt)
    return body.A_IB, body.B_r_IB


def run_part_b(dt=0.001, t_end=3.0):
    """Part (b): 3001 steps of 1 ms. Returns the inertial traces ``{"I_r_IB", "I_r_IQ"}`` of B and Q, arrays of
    shape (n_steps + 1, 3) starting at the initial state."""
    body = RigidBodyKinematics(**PART_B)
    n = fixed_step_count(dt, t_end)
    I_r_IB, I_r_IQ = np.empty((n + 1, 3)), np.empty((n + 1, 3))
    for i in range(n + 1):
        if i:
            body.integration_step(dt)
        I_r_IB[i] = body.position_of_point(np.zeros(3))
        I_r_IQ[i] = body.position_of_point(B_R_BQ)
    return {"I_r_IB": I_r_IB, "I_r_IQ": I_r_IQ}
