"""Problem 3: a double pendulum in MuJoCo.

Two identical HDPE links (the link of problem 2b): joint 1 at the world origin, joint 2 at the free end of link 1,
both hinges about z, both angles 0 at the start (straight, horizontal along +x, at rest), no damping, no torque.
(a) The model, with mass and inertia computed by MuJoCo from the geometry.  (b) The same model with the inertia
given by hand (Simscape's "Custom" inertia): mass, centre of mass, moments and products of inertia from L, W, H
and rho; the motion must not change.  (c) Joint 1 driven kinematically at a constant rate, ``q1 = rate t``.

The sheet compared only the first five seconds: why?  (answers.toml, [problem_03.free_text] why_five_seconds)
"""

import numpy as np

from .mjcf import HEIGHT, LENGTH, WIDTH, number, vector

__all__ = ["double_pendulum", "link_inertia", "double_pendulum_custom_inertia", "driven_double_pendulum"]


def double_pendulum(density, gravity):
    """MJCF text of the double pendulum (3a): body ``link1`` with hinge ``joint1`` at the origin, and inside it body
    ``link2`` with hinge ``joint2`` at the free end of link 1 (``pos`` = the link's length along link 1's x).
    Inertia from the geometry (``density``); gravity ``(0, -gravity, 0)``; RK4 with a 1 ms step."""
    # BEGIN SOLUTION problem 3
    from .problem_02 import link_body

    inner = link_body(2, density, pos=LENGTH)
    return _model("double_pendulum", gravity, link_body(1, density, children=inner))
    # END SOLUTION


def link_inertia(length, width, height, density):
    """The custom inertia of a brick link (3b), in the link's body frame (origin at the joint, x along the link):
    ``{"mass": m, "com": (3,), "inertia": (3, 3)}``, the inertia about the centre of mass.

    ``m = L W H rho``; the centre of mass is the middle of the brick; the moments are
    ``m/12 (W^2 + H^2)``, ``m/12 (L^2 + H^2)``, ``m/12 (L^2 + W^2)``; the products are 0.
    """
    # BEGIN SOLUTION problem 3
    m = length * width * height * density
    moments = m / 12 * np.array([width**2 + height**2, length**2 + height**2, length**2 + width**2])
    return {"mass": m, "com": np.array([length / 2, 0.0, 0.0]), "inertia": np.diag(moments)}
    # END SOLUTION


def double_pendulum_custom_inertia(density, gravity):
    """MJCF text of the double pendulum with custom inertia (3b): each body declares
    ``<inertial pos="..." mass="..." fullinertia="Ixx Iyy Izz Ixy Ixz Iyz"/>`` from ``link_inertia`` (an explicit
    ``<inertial>`` replaces the inertia MuJoCo would compute from the geoms); otherwise as ``double_pendulum``."""
    # BEGIN SOLUTION problem 3
    from .problem_02 import link_body

    custom = link_inertia(LENGTH, WIDTH, HEIGHT, density)
    inertial = (custom["mass"], custom["com"], custom["inertia"])
    inner = link_body(2, pos=LENGTH, inertial=inertial)
    return _model("double_pendulum_custom", gravity, link_body(1, children=inner, inertial=inertial))
    # END SOLUTION


def driven_double_pendulum(density, gravity, rate):
    """MJCF text of the double pendulum of 3a with joint 1 driven kinematically (3c): ``q1 = rate t``.

    The MuJoCo idiom for a prescribed joint motion is a stiff servo: an ``<intvelocity>`` actuator on joint 1
    (``kp="1000"``, no ``kv``) integrates its control, the velocity setpoint, into a position setpoint and pulls
    the joint onto it.  The model starts from a keyframe in which the drive already runs:
    ``<keyframe><key qvel="rate 0" ctrl="rate"/></keyframe>`` (joint 1 turns at ``rate`` from t = 0, joint 2 at
    rest relative to link 1).  The grader resets the model to its first keyframe and never changes the control.
    """
    # BEGIN SOLUTION problem 3
    from .problem_02 import link_body

    inner = link_body(2, density, pos=LENGTH)
    extra = f"""
  <actuator>
    <intvelocity name="drive" joint="joint1" kp="1000"/>
  </actuator>
  <keyframe>
    <key name="start" qvel="{vector([rate, 0.0])}" ctrl="{number(rate)}"/>
  </keyframe>"""
    return _model("driven_double_pendulum", gravity, link_body(1, density, children=inner), extra)
    # END SOLUTION


# BEGIN REFERENCE ONLY
#: a perturbation of the start angle [rad] that stands for "tiny differences" (solver, rounding, how the inertia is
#: computed): the chaos horizon is where the reference started this far off parts from itself
CHAOS_PERTURBATION = 1e-3


def _model(name, gravity, bodies, extra=""):
    return f"""<mujoco model="{name}">
  <compiler angle="radian"/>
  <option gravity="{vector([0.0, -gravity, 0.0])}" timestep="0.001" integrator="RK4"/>
  <worldbody>
    {bodies}
  </worldbody>{extra}
</mujoco>
"""


def double_pendulum_ode(density, gravity, duration=5.0, sample=0.01, rate=None, q0=None):
    """The reference's double pendulum (``rate``: joint 1 driven, ``q1 = rate t``); see ``problem_02.chain_run``."""
    from .problem_02 import chain_run

    return chain_run(2, density, gravity, duration, sample, rate=rate, q0=q0)


def chaos_horizon(density, gravity, duration=5.0, sample=0.01, rate=None, angle_tol=0.05, rate_tol=0.5):
    """The first time [s] at which the reference, started ``CHAOS_PERTURBATION`` off in either joint angle (of the
    free joints), parts from the unperturbed reference by more than ``angle_tol`` [rad] in an angle or ``rate_tol``
    [rad/s] in a rate; ``duration`` when it never does."""
    base = double_pendulum_ode(density, gravity, duration, sample, rate)
    first = duration
    for joint in ([1] if rate is not None else [0, 1]):
        for sign in (1.0, -1.0):
            q0 = np.zeros(2)
            q0[joint] = sign * CHAOS_PERTURBATION
            other = double_pendulum_ode(density, gravity, duration, sample, rate, q0)
            apart = ((np.abs(other["q"] - base["q"]) > angle_tol) | (np.abs(other["qd"] - base["qd"]) > rate_tol))
            hit = np.flatnonzero(apart.any(axis=1))
            if hit.size:
                first = min(first, float(base["t"][hit[0]]))
    return first


# END REFERENCE ONLY
