"""Problem 24: a triple pendulum built from rotational joints, recursive forward kinematics.

Geometry (problem data P24): ground m = 1, ``B_I_B = 1e-4 E``; links m = 10, ``B_I_B = diag(0.0042, 0.8354,
0.8354)``, 1 m long along their 1-axis with the centre of gravity in the middle.  Joint 1 (ground -> link 1):
``P_r_PDp = 0``, ``A_PDp = [[0,1,0],[-1,0,0],[0,0,1]]`` (the links hang along -y at q = 0),
``S_r_SDs = (-0.5, 0, 0)``; joints 2, 3: ``P_r_PDp = (0.5, 0, 0)``, ``A_PDp = E``, ``S_r_SDs = (-0.5, 0, 0)``;
all ``A_SDs = E``.  Test configuration ``q = (pi/6, -pi/4, pi/3)``.

The sheet's second part animates a recorded Simscape run, which we do not have: ``simulate`` generates the motion
instead, released at rest from ``Q`` under gravity ``I_grav = (0, -9.81, 0)``, with the equations of motion of
problem 37 (``dynamics``).  The motion is chaotic: two accurate integrations agree only over the first seconds,
but both conserve the energy.
"""

import numpy as np

from .conventions import GRAVITY
from .dynamics import DynamicBody, equations_of_motion, forward_dynamics
from .tree import Body, KinematicTree, RotationalJoint, inertial_state

__all__ = [
    "GROUND_MASS",
    "GROUND_INERTIA",
    "LINK_MASS",
    "LINK_INERTIA",
    "LINK_LENGTH",
    "A_PDP_FIRST",
    "Q",
    "I_GRAV",
    "T_SIMULATION",
    "build_triple_pendulum",
    "body_poses",
    "solve",
    "pendulum_ode",
    "simulate",
]

GROUND_MASS = 1.0
GROUND_INERTIA = 1e-4 * np.eye(3)
LINK_MASS = 10.0
LINK_INERTIA = np.diag([0.0042, 0.8354, 0.8354])
LINK_LENGTH = 1.0
#: orientation of the first joint frame in the ground: its 1-axis points along -y
A_PDP_FIRST = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
#: the sheet's test configuration
Q = np.array([np.pi / 6, -np.pi / 4, np.pi / 3])
#: gravity of the simulation: the links hang along -y at q = 0
I_GRAV = np.array([0.0, -GRAVITY, 0.0])
#: length of the simulated motion [s]
T_SIMULATION = 2.0


def build_triple_pendulum(body_class=Body):
    """The triple pendulum as a ``KinematicTree``: bodies ``ground``, ``link_1``, ``link_2``, ``link_3``;
    joint k has coordinate ``q[k-1]``.  ``body_class``: the class of the bodies (``dynamics.DynamicBody`` for a
    tree with equations of motion)."""
    half = 0.5 * LINK_LENGTH
    ground = body_class("ground", GROUND_MASS, GROUND_INERTIA)
    predecessor = ground
    for k in range(3):
        link = body_class(f"link_{k + 1}", LINK_MASS, LINK_INERTIA)
        RotationalJoint(
            predecessor,
            link,
            P_r_PDp=(0.0, 0.0, 0.0) if k == 0 else (half, 0.0, 0.0),
            A_PDp=A_PDP_FIRST if k == 0 else np.eye(3),
            S_r_SDs=(-half, 0.0, 0.0),
            q_index=[k],
        )
        predecessor = link
    return KinematicTree(ground)


def body_poses(tree, q):
    """``{body name: {"I_r_IB": ..., "A_IB": ...}}`` after a positions-only pass at ``q``."""
    tree.forward_kinematics(q)
    return {body.name: inertial_state(body) for body in tree.bodies}


def solve(q=Q):
    """Inertial positions and orientations of the four bodies at ``q`` (default: the sheet's ``Q``)."""
    return body_poses(build_triple_pendulum(), q)


def pendulum_ode(t, y, tree):
    """The right-hand side ``dy/dt = (qd, qdd)`` of the unactuated triple pendulum, ``y = (q, qd)``, for a tree of
    ``DynamicBody`` (``build_triple_pendulum(DynamicBody)``): ``M qdd = f + g``."""
    # TODO problem 24: write your solution here
    raise NotImplementedError("Problem 24: pendulum_ode is not implemented yet")


def simulate(t_end=T_SIMULATION, q0=Q, qd0=(0.0, 0.0, 0.0), dt=0.01):
    """The pendulum released at ``(q0, qd0)``, simulated to ``t_end`` with ``scipy.integrate.solve_ivp``; output
    every ``dt``.  Returns ``{"t", "q", "qd"}`` (one row per time)."""
    from scipy.integrate import solve_ivp

    # TODO problem 24: write your solution here
    raise NotImplementedError("Problem 24: simulate is not implemented yet")
