"""Problem 14: the screw axis of a moving rigid body."""

import numpy as np

from .rigid_body import RigidBodyKinematics, fixed_step_count

__all__ = ["INITIAL", "run"]

#: Initial state (A_IB = E, B_r_IB = 0) and constant accelerations.
INITIAL = dict(B_v_B=(0, 0, 0), B_omega_B=(0, 1.5, 1.5), B_a_B=(1.5, 1.5, 0), B_omegaDot_B=(0, 0, 0))


def run(dt=0.01, t_end=1.0):
    """100 steps of 0.01 s. Returns the final ``A_IB``, ``B_r_IB``, the final screw ``B_r_BT``, ``B_v_T`` and the
    inertial traces ``I_r_IT`` (point T) and ``I_v_T`` (its velocity), shape (n_steps + 1, 3)."""
    body = RigidBodyKinematics(**INITIAL)
    n = fixed_step_count(dt, t_end)
    I_r_IT, I_v_T = np.empty((n + 1, 3)), np.empty((n + 1, 3))
    for i in range(n + 1):
        if i:
            body.integration_step(dt)
        B_r_BT, B_v_T = body.screw_axis()
        I_r_IT[i] = body.position_of_point(B_r_BT)
        I_v_T[i] = body.A_IB @ B_v_T
    return {"A_IB": body.A_IB, "B_r_IB": body.B_r_IB, "B_r_BT": B_r_BT, "B_v_T": B_v_T,
            "I_r_IT": I_r_IT, "I_v_T": I_v_T}
