"""Probes of problem 1: the course's packages, imported inside the sandbox, and a tiny MuJoCo model."""

from . import _mjcf, module, probe
from ._forms import ANY, Dict, Items, Maybe, Text

#: the smallest model that exercises MuJoCo: one hinged link falling under gravity (problem 2b's pendulum)
TINY_MODEL = """<mujoco model="tiny">
  <option gravity="0 -9.81 0" timestep="0.001" integrator="RK4"/>
  <worldbody>
    <body>
      <joint type="hinge" axis="0 0 1"/>
      <geom type="box" size="0.1 0.005 0.005" pos="0.1 0 0" density="950"/>
    </body>
  </worldbody>
</mujoco>
"""


@probe(
    returns=Dict(
        {
            "python": Text(),
            "packages": Items(Dict({"version": Maybe(Text()), "distribution": Maybe(Text()), "error": Maybe(Text())})),
            "student": ANY,
        },
        optional=("student",),
    ),
    says="versions()",
)
def environment(pkg, names):
    """Python's version and, per package, the version it reports on import (or why it does not import) and its
    installed distribution's version; then the package's own ``problem_01.versions()``, asked only when every
    package imports (a broken installation is reported as such, whatever the student's function does)."""
    import importlib
    import platform
    from importlib import metadata

    found = {"python": platform.python_version(), "packages": {}}
    for name in names:
        entry = {"version": None, "distribution": None, "error": None}
        try:
            entry["version"] = str(getattr(importlib.import_module(name), "__version__", "") or "") or None
        except Exception as exc:  # noqa: BLE001 - whatever breaks the import is what the student must fix
            entry["error"] = f"{type(exc).__name__}: {exc}"[:300]
        try:
            entry["distribution"] = metadata.version(name)
        except Exception:  # noqa: BLE001 - not installed as a distribution
            pass
        found["packages"][name] = entry
    if all(entry["error"] is None for entry in found["packages"].values()):
        found["student"] = module(pkg, "problem_01").versions()
    return found


@probe(returns=_mjcf.RESULT_OF_RUN)
def tiny_model(pkg, duration, sample):
    """``TINY_MODEL`` loaded and run by MuJoCo: its traces (or why it failed)."""
    return _mjcf.guarded(lambda: _mjcf.run(*_mjcf.load(TINY_MODEL), duration, sample))
