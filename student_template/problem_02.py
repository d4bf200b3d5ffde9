"""Problem 2: a pendulum in MuJoCo (the course's "Getting started with Simscape Multibody").

One link, the sheet's brick (``mjcf.LENGTH x WIDTH x HEIGHT``), hangs from a hinge about the world z-axis at
one of its ends; it starts at rest, horizontal along +x.  (a) The tutorial's model: aluminium, joint damping
8e-5 N m/(deg/s), input torque 0.06 sin(t) N m.  (b) HDPE, no torque, no damping: plot the angle and the angle
rate over 10 s; does the motion change with the density?  (c) The same on the Moon.

Read the module docstring of ``mjcf`` first: it states the conventions (gravity along -y, angles about +z) and
how the grader runs a model.
"""

import numpy as np

from .mjcf import HEIGHT, LENGTH, WIDTH, number, vector

__all__ = ["pendulum"]


def pendulum(density, gravity, damping=0.0, torque=0.0):
    """MJCF text of the pendulum: one body with one hinge joint and one box geom.

    ``density``  [kg/m^3] of the link; MuJoCo computes its mass and inertia from the box (use the ``density``
                 attribute of the geom, not ``mass``).
    ``gravity``  the magnitude g [m/s^2] (``mjcf.EARTH``, ``mjcf.MOON``); it points along -y.
    ``damping``  the joint's damping AS THE TUTORIAL GIVES IT, in N m/(deg/s); MuJoCo's hinge ``damping`` is in
                 N m s/rad, so convert it.
    ``torque``   amplitude [N m] of the input torque ``torque * sin(t)``.  Declare one ``<motor>`` on the joint
                 whose ``gear`` is ``torque``: the grader feeds it the control ``sin(t)`` at every step (the
                 tutorial's sine-wave source), so that the joint torque is ``torque * sin(t)``.  With
                 ``torque = 0`` declare no actuator.

    The joint sits at the world origin with axis +z; the link extends from the joint along +x (angle 0 is
    horizontal, counter-clockwise positive).  Declare the integrator: ``<option integrator="RK4"
    timestep="0.001"/>``.  Write numbers with ``mjcf.number``/``mjcf.vector`` (full precision).
    """
    # TODO problem 2: write your solution here
    raise NotImplementedError("Problem 2: pendulum is not implemented yet")


