"""Probes of problem 2: the pendulum's MJCF, loaded and run by MuJoCo in the sandbox; the reference's ODE."""

from . import _mjcf, module, probe


def _xml(pkg, density, gravity, damping, torque):
    return module(pkg, "problem_02").pendulum(density, gravity, damping, torque)


@probe(returns=_mjcf.RESULT_OF_DESCRIBE, says="pendulum({0}, {1}, {2}, {3})")
def model(pkg, density, gravity, damping=0.0, torque=0.0):
    """What ``pendulum(...)`` declares (``_mjcf.describe``), or ``{"error": ...}``."""
    xml = _xml(pkg, density, gravity, damping, torque)
    return _mjcf.guarded(lambda: _mjcf.describe(*_mjcf.load(xml)))


@probe(returns=_mjcf.RESULT_OF_RUN, says="pendulum({0}, {1}, {2}, {3})")
def run(pkg, density, gravity, damping, torque, duration, sample, as_sheet=False):
    """``pendulum(...)`` run for ``duration`` seconds; every actuator gets the control sin(t) (the tutorial's
    sine-wave source).  ``as_sheet``: stepped with the sheet's integration (RK4 at 1 ms) whatever the model
    declares."""
    xml = _xml(pkg, density, gravity, damping, torque)
    load = (lambda: _mjcf.integrated_as_sheet(*_mjcf.load(xml))) if as_sheet else (lambda: _mjcf.load(xml))
    return _mjcf.guarded(lambda: _mjcf.run(*load(), duration, sample, control="sine"))


# The reference's own computations (its ODE, independent of MuJoCo): called on the reference only.


@probe(reference_only=True)
def ode(pkg, density, gravity, damping, torque, duration, sample):
    return module(pkg, "problem_02").pendulum_ode(density, gravity, damping, torque, duration, sample)


@probe(reference_only=True)
def period(pkg, density, gravity):
    return module(pkg, "problem_02").pendulum_period(density, gravity)
