"""Allocates without bound when the frames are asked for."""
import numpy as np


def frames():
    hoard = []
    while True:
        hoard.append(np.ones(10_000_000))


def vectors():
    return frames()
