"""Checks of problem 1: the installation can do the course.

Inside the sandbox, the probe imports Python's packages for the course and reports their versions (or why they do
not import); the package's own ``versions()`` must agree with what it found.  Then a tiny MuJoCo model loads and
runs there as it does in the grader.
"""

import numpy as np

from grader.checking import STAGE_DEFINED, STAGE_STRUCTURE, Mistake, Tol, assert_close, check, fail
from probes import problem_01 as p01, problem_02 as p02

from ._mujoco import model_of

TITLE = "A working installation"

#: the course's packages (import name, the minimum version of pyproject.toml, what pip installs)
PACKAGES = {
    "numpy": ((1, 26), "numpy"),
    "scipy": ((1, 11), "scipy"),
    "sympy": ((1, 12), "sympy"),
    "mujoco": ((3, 3), "mujoco"),
}
PYTHON = (3, 11)
#: the tiny model's run: half a second, sampled every 50 ms
TINY_DURATION, TINY_SAMPLE = 0.5, 0.05
#: the tiny model (problem 2b's pendulum) against the reference's own ODE
ENGINE = Tol("MuJoCo vs the reference's ODE", 1e-4)


def _release(text):
    """The leading numbers of a version string: "1.26.4" -> (1, 26, 4), "2.0rc1" -> (2, 0); () if none."""
    numbers = []
    for part in str(text or "").split("."):
        digits = ""
        for c in part:
            if not c.isdigit():
                break
            digits += c
        if not digits:
            break
        numbers.append(int(digits))
        if digits != part:
            break
    return tuple(numbers)


def _listing(found):
    rows = [f"  python  {found['python']}"]
    for name, entry in found["packages"].items():
        state = entry["version"] or entry["distribution"] or "?"
        rows.append(f"  {name:<7} {state if entry['error'] is None else 'does not import: ' + entry['error']}")
    return "\n".join(rows)


@check(2, title="Python >= 3.11 with numpy, scipy, sympy and mujoco importable, and versions() reports their "
       "versions", stage=STAGE_DEFINED, group="setup")
def check_versions(ctx):
    found = ctx.student(p01.environment, list(PACKAGES), timeout=60)
    missing, old = [], []
    for name, (minimum, pip_name) in PACKAGES.items():
        entry = found["packages"][name]
        if entry["error"] is not None:
            missing.append(pip_name)
        elif _release(entry["version"] or entry["distribution"]) < minimum:
            old.append(f"{pip_name}>={'.'.join(map(str, minimum))}")
    python_ok = _release(found["python"]) >= PYTHON
    if missing or old or not python_ok:
        commands = []
        if not python_ok:
            commands.append(f"a Python {'.'.join(map(str, PYTHON))} or newer (this one is {found['python']})")
        if missing:
            commands.append("pip install " + " ".join(missing))
        if old:
            commands.append("pip install --upgrade " + " ".join(f'"{p}"' for p in old))
        fail("the installation cannot do the course yet.\nfound:\n" + _listing(found)
             + "\nto do:\n" + "\n".join(f"  {c}" for c in commands),
             "In the course's folder, `pip install -e .` installs every package the course needs.", "install")
    reported = found.get("student")
    if not isinstance(reported, dict):
        fail(f"versions() must return a dict of version strings, got {str(reported)[:200]}",
             'e.g. {"python": "3.11.7", "numpy": "1.26.4", ...}', "type")
    wrong = []
    installed = {"python": (found["python"],)}
    installed.update({name: (e["version"], e["distribution"]) for name, e in found["packages"].items()})
    expected = {name: [v for v in values if v] for name, values in installed.items()}
    for name, accepted in expected.items():
        if reported.get(name) not in accepted:
            wrong.append(f"  {name}: got {reported.get(name)!r}, expected {' or '.join(map(repr, accepted))}")
    if wrong:
        hint, diagnosis = _versions_slip(reported, expected)
        fail("versions() does not report the versions installed here.\n" + "\n".join(wrong)
             + "\nfound:\n" + _listing(found),
             hint or "Read them with importlib.metadata.version(name) and platform.python_version(); the keys are "
             "python, numpy, scipy, sympy and mujoco.", diagnosis)


def _versions_slip(reported: dict, expected: dict) -> tuple[str, str]:
    """``(hint, diagnosis)`` where every wrong entry of ``reported`` is wrong alike: left out (keys missing), cut
    short (a leading part of the version: ``"3.11"`` of ``"3.11.7"``), or one other entry's version reported for it
    (every version read from one package); else the plain ``versions``."""
    wrong = {name: reported.get(name) for name, accepted in expected.items() if reported.get(name) not in accepted}
    if all(name not in reported for name in wrong):
        return (f"versions() leaves out {', '.join(sorted(wrong))}: report every one of python, numpy, scipy, "
                "sympy and mujoco (the loop over the packages must reach each).", "versions_left_out")
    if all(isinstance(v, str) and v and any(a.startswith(v) and a != v for a in expected[name])
           for name, v in wrong.items()):
        return ("Your versions are cut short: report the whole version string, as importlib.metadata.version(name) "
                "and platform.python_version() give it (major, minor and patch).", "versions_cut")
    values = set(wrong.values())
    if len(wrong) > 1 and len(values) == 1 and any(values <= set(accepted) for accepted in expected.values()):
        return ("Every wrong entry holds the version of one package: read each package's own version, "
                "importlib.metadata.version(name) with the name of the loop.", "versions_of_one")
    return "", "versions"


@check(1, title="a tiny MuJoCo model (a falling link) loads and runs in the sandbox, and moves as physics says",
       stage=STAGE_STRUCTURE, group="setup")
def check_mujoco_runs(ctx):
    got = model_of(ctx.student(p01.tiny_model, TINY_DURATION, TINY_SAMPLE, timeout=30), "the tiny model")
    if got.get("diverged"):
        fail(f"MuJoCo's run of the tiny model stopped: {got['diverged']}",
             "Reinstall MuJoCo: pip install --force-reinstall mujoco", "mujoco_broken")
    expected = ctx.reference(p02.ode, 950.0, 9.81, 0.0, 0.0, TINY_DURATION, TINY_SAMPLE, persist=True)
    assert_close(np.concatenate([got["qpos"][:, 0], got["qvel"][:, 0]]),
                 np.concatenate([expected["q"][:, 0], expected["qd"][:, 0]]),
                 f"the tiny model's angle and rate over {TINY_DURATION:g} s", ENGINE,
                 note="The tiny model is the pendulum of problem 2(b); the reference's own ODE gives its motion.",
                 mistakes=[Mistake("mujoco_broken", np.zeros(2 * len(expected["t"])), "MuJoCo ran but nothing moved: "
                                   "reinstall it (pip install --force-reinstall mujoco).")])
