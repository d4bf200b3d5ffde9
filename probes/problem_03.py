"""Probes of problem 3: the double pendulums' MJCF (geometry, custom inertia, driven joint 1), loaded and run by
MuJoCo in the sandbox; the custom inertia of a link; the reference's ODE and its chaos horizon."""

from . import _mjcf, module, probe
from ._forms import Arr, Dict, Num


def _xml(pkg, variant, density, gravity, rate):
    p3 = module(pkg, "problem_03")
    if variant == "geometry":
        return p3.double_pendulum(density, gravity)
    if variant == "custom":
        return p3.double_pendulum_custom_inertia(density, gravity)
    if variant == "driven":
        return p3.driven_double_pendulum(density, gravity, rate)
    raise LookupError(f"unknown variant {variant!r}")


@probe(returns=_mjcf.RESULT_OF_DESCRIBE, says="the model of 3({0})")
def model(pkg, variant, density, gravity, rate=None):
    """What the variant's model declares (``_mjcf.describe``), or ``{"error": ...}``."""
    xml = _xml(pkg, variant, density, gravity, rate)
    return _mjcf.guarded(lambda: _mjcf.describe(*_mjcf.load(xml)))


@probe(returns=_mjcf.RESULT_OF_RUN, says="the model of 3({0})")
def run(pkg, variant, density, gravity, duration, sample, rate=None, as_sheet=False):
    """The variant's model run for ``duration`` seconds from its first keyframe (or as written); controls as the
    keyframe sets them.  ``as_sheet``: stepped with the sheet's integration (RK4 at 1 ms) whatever the model
    declares."""
    xml = _xml(pkg, variant, density, gravity, rate)
    if as_sheet:
        return _mjcf.guarded(lambda: _mjcf.run(*_mjcf.integrated_as_sheet(*_mjcf.load(xml)), duration, sample))
    return _mjcf.guarded(lambda: _mjcf.run(*_mjcf.load(xml), duration, sample))


@probe(returns=Dict({"mass": Num(), "com": Arr(3), "inertia": Arr(3, 3)}), says="link_inertia({0}, {1}, {2}, {3})")
def link_inertia(pkg, length, width, height, density):
    return module(pkg, "problem_03").link_inertia(length, width, height, density)


# The reference's own computations (its ODE, independent of MuJoCo): called on the reference only.


@probe(reference_only=True)
def ode(pkg, density, gravity, duration, sample, rate=None):
    return module(pkg, "problem_03").double_pendulum_ode(density, gravity, duration, sample, rate)


@probe(reference_only=True)
def horizon(pkg, density, gravity, duration, sample, rate, angle_tol, rate_tol):
    return {
        "horizon": module(pkg, "problem_03").chaos_horizon(density, gravity, duration, sample, rate, angle_tol,
                                                           rate_tol),
        "perturbation": module(pkg, "problem_03").CHAOS_PERTURBATION,
    }
