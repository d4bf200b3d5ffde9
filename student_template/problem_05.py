"""Problem 5: debugging a model.

``BROKEN_MODEL`` is the model of the sheet's Figure 7 in MJCF: joint 1, a revolute joint at the origin, carries a
body without any mass; a spherical joint (MuJoCo's ``ball``) connects that body to a link, the brick of problem
2b.  (In the course's Simscape model a torque on joint 1, computed from the rate of the spherical joint, drives
the system.)  MuJoCo refuses to load it: ``mujoco.MjModel.from_xml_string(BROKEN_MODEL)`` raises an error.

Find and describe the error; how would you fix it?  Is this an energy-conserving system?  (answers.toml,
[problem_05.free_text] error and energy)  Then write the repaired model (``fixed_model``).
"""

__all__ = ["BROKEN_MODEL", "fixed_model"]

BROKEN_MODEL = """<mujoco model="broken">
  <compiler angle="radian"/>
  <option gravity="0 -9.81 0" timestep="0.001" integrator="RK4"/>
  <worldbody>
    <body name="connector">
      <joint name="revolute1" type="hinge" axis="0 0 1"/>
      <body name="link">
        <joint name="spherical" type="ball"/>
        <geom name="brick" type="box" size="0.1 0.005 0.005" pos="0.1 0 0" density="950" contype="0" conaffinity="0"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def fixed_model():
    """``BROKEN_MODEL`` repaired with the smallest change: the same bodies and joints, the link unchanged, and a
    small mass (at most a tenth of the link's) where the model lacks one."""
    # TODO problem 5: write your solution here
    raise NotImplementedError("Problem 5: fixed_model is not implemented yet")
