"""Probes of problem 8: the three integration steps, the Cardan-rate matrix, and the three runs."""

import numpy as np

from . import module, probe
from ._forms import Arr, ByArgs, Dict, Items, Maybe


@probe(returns=Arr(3, 3), says="cardan_rate_matrix({0}, {1}, {2})", args=("angle", "angle", "angle"))
def rate_matrix(pkg, alpha, beta, gamma):
    return module(pkg, "rotations").cardan_rate_matrix(alpha, beta, gamma)


@probe(
    returns=ByArgs(lambda which, *_: Arr(3) if which == "cardan" else Arr(3, 3)),
    says="the {0} step",
    args=("", "", "vector", "scalar"),
    rotation=1,
)
def step(pkg, which, x, I_omega, dt):
    p8 = module(pkg, "problem_08")
    func = {"euler": p8.euler_matrix_step, "cardan": p8.cardan_euler_step, "exp": p8.exponential_step}[which]
    return func(x, I_omega, dt)


@probe(
    returns=ByArgs(lambda which: Dict({"A_IC": Arr(3, 3), "angles": Arr(3)}) if which == "b" else Arr(3, 3)),
    says="part_{0}()",
    rebind={"module": "problem_08", "names": ("I_OMEGA", "ANGLES0")},
)
def part(pkg, which):
    return getattr(module(pkg, "problem_08"), f"part_{which}")()


@probe(returns=Items(Maybe(Arr(None, 3, 3, finite=False))), says="the three runs")
def paths(pkg):
    """A_IC at every step of the three runs (the package's own steps, start, step size and, for (b), its cardan):
    ``{"a": [...], "b": [...], "c": [...]}``, n + 1 matrices each; a run whose step raises is None."""
    p8, rotations = module(pkg, "problem_08"), module(pkg, "rotations")
    runs = {"a": (p8.euler_matrix_step, p8.A_IC0, np.asarray),
            "b": (p8.cardan_euler_step, p8.ANGLES0, lambda angles: rotations.cardan(*angles)),
            "c": (p8.exponential_step, p8.A_IC0, np.asarray)}
    found = {}
    for key, (step, start, orientation) in runs.items():
        try:
            x = np.array(start, dtype=float)
            matrices = [orientation(x)]
            for _ in range(p8.N_STEPS):
                x = step(x, p8.I_OMEGA, p8.DT)
                matrices.append(orientation(x))
            found[key] = np.array(matrices, dtype=float)
        except Exception:  # noqa: BLE001 - the checks of the step report its failure; the figure leaves it out
            found[key] = None
    return found
