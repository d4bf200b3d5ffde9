"""MuJoCo models for Exercise I (problems 2-5): the sheet's link, and small helpers to write and run MJCF.

The course built its first models in Simscape Multibody; here they are MJCF models (MuJoCo's XML format) that
functions of ``problem_02`` ... ``problem_05`` return as text.  The models of problems 2-4 are planar:

* every joint is a hinge about the world z-axis at the end of the previous link; a joint angle of 0 is a link
  along +x, counter-clockwise positive (so a link released horizontally falls to negative angles);
* gravity points along -y (the sheet's ``(0, -g, 0)``).  MuJoCo's default gravity points along -z, so every
  model sets ``<option gravity="0 -g 0"/>``;
* a link is the sheet's brick, ``LENGTH x WIDTH x HEIGHT`` (20 x 1 x 1 cm), length along the body's x-axis,
  pivot at one end.

MJCF facts that decide the numbers (see MuJoCo's XML reference):

* a box geom's ``size`` is HALF its edge lengths; ``pos`` is the geom's centre in the body frame;
* ``density`` (kg/m^3) lets MuJoCo compute mass and inertia from the geometry ("calculate from geometry" in
  Simscape); ``mass`` sets the mass directly; an ``<inertial pos mass fullinertia/>`` element replaces both
  (custom inertia);
* angles in MJCF attributes are degrees unless ``<compiler angle="radian"/>``;
* a hinge's ``damping`` is in N m s/rad (torque per angular velocity in radians per second);
* ``<option integrator="RK4" timestep="0.001"/>`` integrates accurately enough to compare with a tight ODE
  solution; MuJoCo's default (semi-implicit Euler, 2 ms) is too coarse for the double pendulum.

How the grader runs a model: it loads the text with MuJoCo inside the sandbox, resets it to its first
``<keyframe>`` if it has one (otherwise to the configuration as written, at rest), and steps it; where a problem
has an input signal (the tutorial's torque of problem 2) the grader sets the controls at every step.  Models may
not read files: ``<include>``, meshes, textures and every ``file`` attribute are refused, and so are models of
more than a few thousand elements.  Write numbers with full precision (``number`` and ``vector`` below): a
model rounded to a few digits parts from the reference sooner in a chaotic motion.
"""

import numpy as np

__all__ = [
    "LENGTH",
    "WIDTH",
    "HEIGHT",
    "ALUMINIUM",
    "HDPE",
    "EARTH",
    "MOON",
    "TUTORIAL_DAMPING",
    "TUTORIAL_TORQUE",
    "number",
    "vector",
    "load",
    "simulate",
]

#: the link: a brick 20 x 1 x 1 cm [m], length along its x-axis
LENGTH, WIDTH, HEIGHT = 0.2, 0.01, 0.01
#: densities [kg/m^3]: aluminium (the tutorial) and high-density polyethylene (2b, 2c, 3, 4)
ALUMINIUM, HDPE = 2700.0, 950.0
#: magnitudes of gravity [m/s^2] on the Earth and on the Moon (2c); gravity points along -y
EARTH, MOON = 9.81, 1.62
#: the tutorial's joint damping, as the tutorial gives it: N m per (deg/s)
TUTORIAL_DAMPING = 8e-5
#: amplitude [N m] of the tutorial's input torque TUTORIAL_TORQUE * sin(t)
TUTORIAL_TORQUE = 0.06


def number(x) -> str:
    """``x`` as MJCF text with every digit (``repr`` of the float): ``number(0.1) == "0.1"``."""
    return repr(float(x))


def vector(v) -> str:
    """A vector as MJCF text: ``vector([0, -9.81, 0]) == "0.0 -9.81 0.0"``."""
    return " ".join(number(x) for x in np.asarray(v, dtype=float).ravel())


def load(xml: str):
    """``(model, data)`` of MJCF text, reset to the first keyframe if the model has one."""
    import mujoco

    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    if model.nkey:
        mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    return model, data


def simulate(xml: str, duration: float, control=None, every: int = 10) -> dict:
    """Run a model for ``duration`` seconds: ``{"t", "qpos", "qvel"}`` every ``every`` steps.

    ``control(t)`` (optional) returns the controls of the model's actuators; it is evaluated at the middle of each
    step.  For plots of your own models (the grader runs its own loop, as described in the module docstring).
    """
    import mujoco

    model, data = load(xml)
    dt = model.opt.timestep
    steps = int(np.ceil(duration / dt - 1e-9))
    t, qpos, qvel = [], [], []
    for k in range(steps + 1):
        if k % every == 0 or k == steps:
            t.append(data.time)
            qpos.append(data.qpos.copy())
            qvel.append(data.qvel.copy())
        if k == steps:
            break
        if control is not None:
            data.ctrl[:] = control(data.time + dt / 2)
        mujoco.mj_step(model, data)
    return {"t": np.array(t), "qpos": np.array(qpos), "qvel": np.array(qvel)}
