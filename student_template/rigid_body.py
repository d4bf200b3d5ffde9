"""Kinematics and torque-free dynamics of a single rigid body (problems 12-15).

Conventions (problem data): a body stores *body-frame* quantities.

``A_IB``          orientation: maps B-coordinates to I-coordinates.
``B_r_IB``        position of the body point B, expressed in B (inertial position ``A_IB @ B_r_IB``).
``B_v_B``         absolute velocity of B, in B-coordinates.
``B_a_B``         absolute acceleration of B, in B-coordinates.
``B_omega_B``     absolute angular velocity of the body, in B-coordinates.
``B_omegaDot_B``  absolute angular acceleration of the body, in B-coordinates.
``m``, ``B_I_B``  mass and inertia about the centre of gravity (in B); B is the centre of gravity.
"""

import numpy as np

from .conventions import as_matrix, as_vector
from .rotations import expm_skew, skew

__all__ = ["RigidBodyKinematics", "RigidBodyDynamics", "fixed_step_count"]


def fixed_step_count(dt, t_end):
    """Number of steps of the course's loop ``t = 0; while t < t_end: t += dt; step()``.

    The float accumulation decides the count: 100 for (0.01, 1), 3001 for (0.001, 3), 30000 for (0.001, 30).
    """
    t, n = 0.0, 0
    while t < t_end:
        t += dt
        n += 1
    return n


class RigidBodyKinematics:
    """A rigid body's pose, velocities and accelerations, all stored in body coordinates.

    Every keyword argument defaults to the identity (``A_IB``) or to zeros; the arrays are copied.
    """

    def __init__(self, A_IB=None, B_r_IB=None, B_v_B=None, B_a_B=None, B_omega_B=None, B_omegaDot_B=None):
        self.A_IB = np.eye(3) if A_IB is None else as_matrix(A_IB).copy()
        self.B_r_IB = _vector_or_zeros(B_r_IB)
        self.B_v_B = _vector_or_zeros(B_v_B)
        self.B_a_B = _vector_or_zeros(B_a_B)
        self.B_omega_B = _vector_or_zeros(B_omega_B)
        self.B_omegaDot_B = _vector_or_zeros(B_omegaDot_B)

    def integration_step(self, dt):
        """Advance the state by one step of size ``dt`` with the accelerations currently set.

        In this order, both skew matrices taken from the values *before* the step:

        1. ``B_Om = skew(B_omega_B)``, ``I_Om = skew(A_IB @ B_omega_B)``;
        2. ``B_r_IB += dt * (B_v_B - B_Om @ B_r_IB)``  (Euler forward);
        3. ``B_v_B += dt * (B_a_B - B_Om @ B_v_B)``  (Euler forward);
        4. ``A_IB = expm(dt * I_Om) @ A_IB``  (exact exponential, keeps ``A_IB`` orthonormal);
        5. ``B_omega_B += dt * B_omegaDot_B``  (Euler forward).
        """
        # TODO problem 12: write your solution here
        raise NotImplementedError("Problem 12: RigidBodyKinematics.integration_step is not implemented yet")

    def position_of_point(self, B_r_BQ):
        """Inertial position of the body-fixed point Q: ``I_r_IQ = A_IB @ (B_r_IB + B_r_BQ)``."""
        # TODO problem 12: write your solution here
        raise NotImplementedError("Problem 12: RigidBodyKinematics.position_of_point is not implemented yet")

    def velocity_of_point(self, B_r_BQ):
        """Inertial velocity of the body-fixed point Q: ``I_v_Q = A_IB @ (B_v_B + B_omega_B x B_r_BQ)``."""
        # TODO problem 12: write your solution here
        raise NotImplementedError("Problem 12: RigidBodyKinematics.velocity_of_point is not implemented yet")

    def acceleration_of_point(self, B_r_BQ):
        """Inertial acceleration of the body-fixed point Q:
        ``I_a_Q = A_IB @ (B_a_B + (skew(B_omegaDot_B) + skew(B_omega_B)^2) @ B_r_BQ)``."""
        # TODO problem 12: write your solution here
        raise NotImplementedError("Problem 12: RigidBodyKinematics.acceleration_of_point is not implemented yet")

    def screw_axis(self):
        """The twist's screw axis as ``(B_r_BT, B_v_T)``, both in B-coordinates.

        T is the point of the screw axis closest to B: ``B_r_BT = (omega x v_B) / |omega|^2``; its velocity
        ``B_v_T = v_B + omega x B_r_BT`` is the projection of ``v_B`` onto ``omega`` (parallel to the axis).
        Without rotation (``omega = 0``) there is no axis and both vectors are zero.
        """
        # TODO problem 14: write your solution here
        raise NotImplementedError("Problem 14: RigidBodyKinematics.screw_axis is not implemented yet")


class RigidBodyDynamics(RigidBodyKinematics):
    """A rigid body with mass ``m`` and inertia ``B_I_B`` about its centre of gravity B (in B-coordinates)."""

    def __init__(self, m=1.0, B_I_B=None, **kinematics):
        super().__init__(**kinematics)
        self.m = float(m)
        self.B_I_B = np.eye(3) if B_I_B is None else as_matrix(B_I_B).copy()

    def compute_natural_dynamics(self):
        """Set the accelerations of the force- and torque-free body (Newton-Euler in B-coordinates):

        ``B_a_B = 0`` (no force: the absolute acceleration vanishes) and
        ``B_I_B @ B_omegaDot_B = -B_omega_B x (B_I_B @ B_omega_B)`` (Euler's equation, solved, not inverted).
        """
        # TODO problem 15: write your solution here
        raise NotImplementedError("Problem 15: RigidBodyDynamics.compute_natural_dynamics is not implemented yet")

    def angular_momentum(self):
        """Angular momentum about the centre of gravity in B-coordinates: ``B_L_B = B_I_B @ B_omega_B``."""
        # TODO problem 15: write your solution here
        raise NotImplementedError("Problem 15: RigidBodyDynamics.angular_momentum is not implemented yet")


def _vector_or_zeros(v):
    return np.zeros(3) if v is None else as_vector(v).copy()
