"""A pendulum whose damping makes every integration step explode: MuJoCo warns and resets the simulation."""

__all__ = ["pendulum"]


def pendulum(density, gravity, damping=0.0, torque=0.0):
    return f"""<mujoco>
  <option gravity="0 {-gravity} 0" timestep="0.001" integrator="RK4"/>
  <worldbody>
    <body>
      <joint type="hinge" axis="0 0 1" damping="1e9"/>
      <geom type="box" size="0.1 0.005 0.005" pos="0.1 0 0" density="{density}" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>"""
