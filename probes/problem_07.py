"""Probes of problem 7: skew/unskew, angular velocity from a transformation, the symbolic derivation."""

from . import module, probe, remembered
from ._forms import Arr, Dict, Items, Seq
from ._symbolic import lambdify

NAMES = ("alpha", "beta", "gamma", "alpha_dot", "beta_dot", "gamma_dot")
_DERIVED = {}


@probe(returns=Arr(3, 3), says="skew({0})", args=("vector",))
def skew(pkg, w):
    return module(pkg, "rotations").skew(w)


@probe(returns=Arr(3), says="unskew({0})")
def unskew(pkg, W):
    return module(pkg, "rotations").unskew(W)


@probe(returns=Arr(3), says="omega_body(A_IC, dA_IC)", args=("rotation", ""), rotation=0)
def omega_body(pkg, A, dA):
    return module(pkg, "rotations").omega_body(A, dA)


@probe(returns=Arr(3), says="omega_inertial(A_IC, dA_IC)", args=("rotation", ""), rotation=0)
def omega_inertial(pkg, A, dA):
    return module(pkg, "rotations").omega_inertial(A, dA)


@probe(returns=Items(Seq(Arr(any_shape=True))), says="derive()")
def symbolic(pkg, points):
    """Evaluate every expression of ``derive()`` at the given points (dicts of the six symbol values); the
    derivation is made once per package and process (``remembered``), whatever the points."""
    import sympy as sp

    p07 = module(pkg, "problem_07")
    derived = remembered(_DERIVED, (pkg.__name__, id(p07)), p07.derive)
    if not isinstance(derived, dict):
        raise TypeError(f"derive() must return a dict, got {type(derived).__name__}")
    out = {}
    for key, expr in derived.items():
        expr = sp.Matrix(expr) if not isinstance(expr, sp.MatrixBase) else expr
        known = {s.name: s for s in expr.free_symbols}
        unknown = sorted(set(known) - set(NAMES))
        if unknown or expr.atoms(sp.Function) - expr.atoms(sp.sin, sp.cos, sp.tan):
            raise ValueError(
                f"{key} contains symbols or functions other than {', '.join(NAMES)}: "
                f"{unknown or sorted(map(str, expr.atoms(sp.Function)))}"
            )
        symbols = [known.get(n, sp.Symbol(n)) for n in NAMES]
        func = lambdify(symbols, expr, modules="numpy")
        out[key] = [func(*(p[n] for n in NAMES)) for p in points]
    return out


@probe(returns=Dict({"A_IC3": Arr(3, 3), "angles": Arr(3)}), says="animate()",
       rebind={"module": "problem_07", "names": ("START_ANGLES",)})
def animate(pkg):
    return module(pkg, "problem_07").animate()


@probe(reference_only=True)
def expressions(pkg, points):
    """The values of ``derive()``'s expressions at the given points, from the package's numeric rotations
    (``R3``, ``R2``, ``cardan``, ``cardan_rate_matrix``): what a correct derivation evaluates to."""
    import numpy as np

    rotations = module(pkg, "rotations")
    out = {key: [] for key in ("A_IC1", "A_IC2", "A_IC3", "A_C3I", "C3_omega_IC3")}
    for p in points:
        a, b, g = p["alpha"], p["beta"], p["gamma"]
        rates = np.array([p["alpha_dot"], p["beta_dot"], p["gamma_dot"]])
        A3 = rotations.cardan(a, b, g)
        out["A_IC1"].append(rotations.R3(g))
        out["A_IC2"].append(rotations.R3(g) @ rotations.R2(b))
        out["A_IC3"].append(A3)
        out["A_C3I"].append(A3.T)
        out["C3_omega_IC3"].append((rotations.cardan_rate_matrix(a, b, g) @ rates).reshape(3, 1))
    return out
