"""Probes of problem 6: elementary rotations, the Cardan sequence, and the sheet's frames and vectors."""

from . import module, probe


@probe
def elementary(pkg, axis, angle):
    rotations = module(pkg, "rotations")
    return {1: rotations.R1, 2: rotations.R2, 3: rotations.R3}[axis](angle)


@probe
def cardan(pkg, alpha, beta, gamma):
    return module(pkg, "rotations").cardan(alpha, beta, gamma)


@probe
def frames(pkg):
    return module(pkg, "problem_06").frames()


@probe
def vectors(pkg):
    return module(pkg, "problem_06").vectors()
