"""A model of a hundred thousand bodies: the text is refused before MuJoCo compiles it."""

__all__ = ["pendulum"]


def pendulum(density, gravity, damping=0.0, torque=0.0):
    bodies = "".join(f'<body pos="{i} 0 0"><joint/><geom size="0.1"/></body>' for i in range(100_000))
    return f"<mujoco><worldbody>{bodies}</worldbody></mujoco>"
