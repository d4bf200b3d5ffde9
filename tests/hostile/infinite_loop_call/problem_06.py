"""R1 and friends are fine; vectors() never returns."""
from .rotations import R1, R2, R3  # noqa: F401


def frames():
    while True:
        pass


def vectors():
    while True:
        pass
