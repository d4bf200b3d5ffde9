"""Probes of problem 43: the bar on a frictionless support (mass matrix, forces, the constraint and its terms, the
constrained system and its solution), with what the physics checks need from the package's own functions."""

import numpy as np

from . import module, probe
from ._forms import Arr, Dict, Num, Seq, Tup


def _p43(pkg):
    return module(pkg, "problem_43")


def _vector(x):
    return np.asarray(x, dtype=float)


@probe(returns=Arr(3, 3), says="mass_matrix({0}, {1})", args=("scalar", "scalar"))
def mass_matrix(pkg, m, theta):
    return np.asarray(_p43(pkg).mass_matrix(m, theta), dtype=float)


@probe(returns=Dict({"f": Arr(3), "g": Arr(3)}), says="forces({0}, {1})", args=("scalar", "scalar"))
def forces(pkg, m, g):
    """``{"f", "g"}`` of ``forces(m, g)``."""
    f, G = _p43(pkg).forces(m, g)
    return {"f": _vector(f).reshape(-1), "g": _vector(G).reshape(-1)}


def _bias(p43, q, qd):
    return _vector(p43.constraint_bias(q, qd)).reshape(-1)


@probe(
    returns=Dict(
        {
            "c": Num(),
            "J": Arr(ndim=2),
            "sigma": Arr(1),
            "c_coordinates": Seq(Tup(Num(), Num()), length=3),
            "c_path": Arr(3),
        }
    ),
    says="constraint, constraint_jacobian and constraint_bias",
)
def constraint_terms(pkg, q, qd, d, h):
    """``c``, ``J`` and ``sigma`` at ``(q, qd)``, and ``c`` at ``q +- h e_i`` (``"c_coordinates"``) and at
    ``q + (-1, 0, 1) h qd`` (``"c_path"``), for the derivatives of the package's own constraint."""
    p43 = _p43(pkg)
    q, qd = _vector(q), _vector(qd)
    c = float(p43.constraint(q, d))
    J = _vector(p43.constraint_jacobian(q))
    coordinates = [[float(p43.constraint(q + sign * h * e, d)) for sign in (1.0, -1.0)] for e in np.eye(3)]
    path = [float(p43.constraint(q + k * h * qd, d)) for k in (-1.0, 0.0, 1.0)]
    return {"c": c, "J": J, "sigma": _bias(p43, q, qd), "c_coordinates": coordinates, "c_path": path}


@probe(
    returns=Dict({"A": Arr(4, 4), "b": Arr(4)}),
    says="constrained_system(q, qd, {2}, {3}, {4})",
    args=("vector", "vector", "scalar", "scalar", "scalar"),
)
def constrained_system(pkg, q, qd, m, theta, g):
    """``{"A", "b"}`` of ``constrained_system(q, qd, m, theta, g)``."""
    A, b = _p43(pkg).constrained_system(_vector(q), _vector(qd), m, theta, g)
    return {"A": _vector(A), "b": _vector(b).reshape(-1)}


@probe(
    returns=Dict(
        {"qdd": Arr(3), "lam": Arr(1), "M": Arr(3, 3), "f": Arr(3), "g": Arr(3), "J": Arr(ndim=2), "sigma": Arr(1)}
    ),
    says="accelerations(q, qd, {2}, {3}, {4})",
    args=("vector", "vector", "scalar", "scalar", "scalar"),
)
def accelerations(pkg, q, qd, m, theta, g):
    """``{"qdd", "lam"}`` of ``accelerations(q, qd, m, theta, g)``, and the package's own ``M``, ``f``, ``g``,
    ``J`` and ``sigma`` at that state."""
    p43 = _p43(pkg)
    q, qd = _vector(q), _vector(qd)
    qdd, lam = p43.accelerations(q, qd, m, theta, g)
    f, G = p43.forces(m, g)
    return {"qdd": _vector(qdd).reshape(-1), "lam": _vector(lam).reshape(-1),
            "M": _vector(p43.mass_matrix(m, theta)), "f": _vector(f).reshape(-1), "g": _vector(G).reshape(-1),
            "J": _vector(p43.constraint_jacobian(q)), "sigma": _bias(p43, q, qd)}


@probe(reference_only=True)
def system_mistakes(pkg, q, qd, m, theta, g):
    """``{mistake: {"A", "b", "qdd", "lam"}}``: the constrained system that known mistakes give, built from the
    package's own pieces, and its solution (called on the reference only)::

        constraint_force_sign   the force through -J.T lam:  [[M, J.T], [J, 0]]
        missing_sigma           the lower row without sigma:  J qdd = 0
        sigma_sign              the lower row J qdd = +sigma
        gravity_sign            gravity along +y
    """
    p43 = _p43(pkg)
    q, qd = _vector(q), _vector(qd)
    M = _vector(p43.mass_matrix(m, theta))
    f, G = (_vector(x).reshape(-1) for x in p43.forces(m, g))
    J = _vector(p43.constraint_jacobian(q)).reshape(1, 3)
    sigma = _bias(p43, q, qd)

    def system(force_sign=-1.0, lower=-sigma, gravity=G):
        A = np.zeros((4, 4))
        A[:3, :3], A[:3, 3], A[3, :3] = M, force_sign * J[0], J[0]
        b = np.concatenate([f + gravity, lower])
        x = np.linalg.solve(A, b)
        return {"A": A, "b": b, "qdd": x[:3], "lam": x[3:]}

    return {"constraint_force_sign": system(force_sign=1.0), "missing_sigma": system(lower=np.zeros(1)),
            "sigma_sign": system(lower=sigma), "gravity_sign": system(gravity=-G)}
