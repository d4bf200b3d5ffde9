"""Probes of problem 41: the computations behind the multiple-choice keys (called on the reference only)."""

import numpy as np

from . import module, probe


@probe(reference_only=True)
def keys(pkg):
    """``{"a", "b", "c"}``: the keys, computed by the package's reference-only functions."""
    return {key: int(value) for key, value in module(pkg, "problem_41").answers().items()}


@probe(reference_only=True)
def residuals(pkg, l, m):
    """Per question, per option: (a) the relative residual of the statement on a random motion, (b) of the option
    against the virtual work, (c) the largest entry of the option minus the ball's ``m J.T J`` for ``l``, ``m``."""
    p41 = module(pkg, "problem_41")
    M = p41.flyball_mass_matrix(l, m)
    return {
        "a": {str(k): float(v) for k, v in p41.angular_momentum_residuals().items()},
        "b": {str(k): float(v) for k, v in p41.projection_residuals().items()},
        "c": {str(k): float(np.abs(option - M).max()) for k, option in p41.flyball_options(l, m).items()},
    }
