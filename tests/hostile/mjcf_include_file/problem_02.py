"""A model that asks MuJoCo to read a file outside the submission (MuJoCo reads files named in a string model)."""

__all__ = ["pendulum"]


def pendulum(density, gravity, damping=0.0, torque=0.0):
    return '<mujoco><include file="/etc/passwd"/><asset><mesh name="m" file="../reference/problem_02.py"/></asset></mujoco>'
