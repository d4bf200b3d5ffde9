"""Probes of problem 26: position and constraint Jacobian of the chairoplane's seat."""

import numpy as np

from . import module, probe


@probe
def position(pkg, beta, phi, l1, l2, l3):
    return module(pkg, "problem_26").position(beta, phi, l1, l2, l3)


@probe
def jacobian(pkg, beta, phi, l1, l2, l3):
    return module(pkg, "problem_26").jacobian(beta, phi, l1, l2, l3)


@probe
def jacobian_and_steps(pkg, beta, phi, l1, l2, l3, h):
    """The analytic Jacobian and the position at ``q +- h e_j`` for ``q = (beta, phi)`` (for central differences)."""
    p26 = module(pkg, "problem_26")
    steps = h * np.eye(2)
    return {
        "J": p26.jacobian(beta, phi, l1, l2, l3),
        "plus": [p26.position(beta + db, phi + dp, l1, l2, l3) for db, dp in steps],
        "minus": [p26.position(beta - db, phi - dp, l1, l2, l3) for db, dp in steps],
    }
