"""Probes of problem 47: the bowling pin's contact (constraint, Jacobian), the plastic impact, the impulse and its
maximum."""

import numpy as np

from . import module, probe
from ._forms import Arr, Dict, Num, Seq, Tup


def _p47(pkg):
    return module(pkg, "problem_47")


@probe(
    returns=Dict({"c": Num(), "J": Arr(ndim=2), "c_coordinates": Seq(Tup(Num(), Num()), length=3)}),
    says="constraint and constraint_jacobian",
    args=("vector", "scalar", "scalar", ""),
)
def contact(pkg, q, x_cog, y_cog, h):
    """``c`` and ``J`` at ``q``, and ``c`` at ``q +- h e_i`` (``"c_coordinates"``)."""
    p47 = _p47(pkg)
    q = np.asarray(q, dtype=float)
    shifted = [[float(p47.constraint(q + sign * h * e, x_cog, y_cog)) for sign in (1.0, -1.0)] for e in np.eye(3)]
    return {"c": float(p47.constraint(q, x_cog, y_cog)),
            "J": np.asarray(p47.constraint_jacobian(q, x_cog, y_cog), dtype=float), "c_coordinates": shifted}


@probe(
    returns=Dict({"q_plus": Arr(3), "qd_plus": Arr(3), "Lam": Arr(1), "J": Arr(ndim=2)}),
    says="plastic_impact(q_minus, qd_minus, ...)",
    args=("vector", "vector", "scalar", "scalar", "scalar", "scalar"),
)
def impact(pkg, q_minus, qd_minus, m, theta, x_cog, y_cog):
    """``{"q_plus", "qd_plus", "Lam"}`` of ``plastic_impact`` and the package's own ``J`` at ``q_minus``."""
    p47 = _p47(pkg)
    q_minus, qd_minus = np.asarray(q_minus, dtype=float), np.asarray(qd_minus, dtype=float)
    q_plus, qd_plus, Lam = p47.plastic_impact(q_minus, qd_minus, m, theta, x_cog, y_cog)
    return {"q_plus": np.asarray(q_plus, dtype=float).reshape(-1),
            "qd_plus": np.asarray(qd_plus, dtype=float).reshape(-1), "Lam": np.asarray(Lam, dtype=float).reshape(-1),
            "J": np.asarray(p47.constraint_jacobian(q_minus, x_cog, y_cog), dtype=float)}


@probe(returns=Num(), says="impulse({0}, {1}, ...)", args=("angle", "scalar", "scalar", "scalar", "scalar", "scalar"))
def impulse(pkg, phi, yd_minus, m, theta, x_cog, y_cog):
    return float(_p47(pkg).impulse(phi, yd_minus, m, theta, x_cog, y_cog))


@probe(
    returns=Dict({"phi_hat": Num(), "Lam_max": Num(), "impulses": Arr(3)}),
    says="angle_of_max_impulse and max_impulse",
    args=("scalar", "scalar", "scalar", "scalar", "scalar", ""),
)
def maximum(pkg, yd_minus, m, theta, x_cog, y_cog, delta):
    """``phi_hat`` and ``Lam_max``, and the package's own ``impulse`` at ``phi_hat`` and at ``phi_hat -+ delta``."""
    p47 = _p47(pkg)
    phi_hat = float(p47.angle_of_max_impulse(x_cog, y_cog))
    at = [float(p47.impulse(phi_hat + k * delta, yd_minus, m, theta, x_cog, y_cog)) for k in (-1.0, 0.0, 1.0)]
    return {"phi_hat": phi_hat, "Lam_max": float(p47.max_impulse(yd_minus, m)), "impulses": at}
