"""A student's own laptop (issue 28): the light kit, installed into a fresh virtual environment whose
start-up (``sitecustomize``'s part, here a ``.pth`` file's) takes away what exists only on Linux or POSIX (as on
Windows: no ``resource``, ``fcntl``, ``pwd``, ``grp``, ``termios``; no ``os.fork``, ``os.killpg``, ``os.setsid``,
``os.setpgrp``, ``os.getuid``, ``os.geteuid``; and for reading folders no ``os.O_NOFOLLOW``, ``os.O_DIRECTORY``,
``os.O_NONBLOCK``, ``os.O_CLOEXEC``, no ``dir_fd=`` (``os.supports_dir_fd`` empty, ``NotImplementedError`` as
Windows raises it) and no ``os.scandir`` or ``os.listdir`` of a descriptor), whose output to a pipe is in the
ANSI code page (cp1252) as Windows has it, with no bubblewrap on the PATH, run by a user who is not root:
``grade init``, ``grade problem-6`` and ``check(6)`` work there in the portable mode, the reference to full marks
and the template to 0, and a submission that holds a symbolic link is refused; forced into the plain-process mode
on the same platform, the grader cannot start its worker.  Slow: the kit is installed with its dependencies."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from grader.kit import KIT_DEPENDENCIES, build_kit, record_key

from .environments import outside_env, public_tmp_dir, purelib, venv_on_site
from .kit_support import KIT_SEED
from .notebooks import problem_06_cells, r3_transposed, write_notebook
from .submissions import ROOT, copy_reference

pytestmark = pytest.mark.slow

#: what the simulated platform lacks
MISSING_MODULES = ("resource", "fcntl", "pwd", "grp", "termios")
MISSING_FUNCTIONS = ("fork", "killpg", "setsid", "setpgrp", "getuid", "geteuid")
#: the user the student's commands run as when the tests run as root
NOBODY = 65534

#: what the simulated platform lacks to read a folder relative to a descriptor of it, never through a link
MISSING_FLAGS = ("O_NOFOLLOW", "O_DIRECTORY", "O_NONBLOCK", "O_CLOEXEC")
#: the encoding of a program's output to a pipe on Windows (its ANSI code page; a console gets UTF-8)
PIPE_ENCODING = "cp1252"

SITECUSTOMIZE = f'''"""A platform without the POSIX-only modules and functions (a stand-in for Windows)."""
import os
import sys

for _name in {MISSING_MODULES!r}:
    sys.modules[_name] = None  # import _name: ModuleNotFoundError
for _name in {MISSING_FUNCTIONS + MISSING_FLAGS!r}:
    if hasattr(os, _name):
        delattr(os, _name)


def _no_dir_fd(function):
    def call(*args, dir_fd=None, **kwargs):
        if dir_fd is not None:
            raise NotImplementedError("dir_fd unavailable on this platform")
        return function(*args, **kwargs)

    call.__name__ = call.__qualname__ = function.__name__
    return call


def _no_descriptor(function):
    def call(path=None, *args, **kwargs):
        if isinstance(path, int):
            raise TypeError(f"{{function.__name__}}: path should be string, bytes, os.PathLike or None, not int")
        return function(*args, **kwargs) if path is None else function(path, *args, **kwargs)

    call.__name__ = call.__qualname__ = function.__name__
    return call


_replaced = {{}}
for _function in [*os.supports_dir_fd, os.lstat]:
    _replaced[_function] = _no_dir_fd(_function)
for _function in (os.scandir, os.listdir):
    _replaced[_function] = _no_descriptor(_replaced.get(_function, _function))
for _old, _new in _replaced.items():
    setattr(os, _old.__name__, _new)
os.supports_dir_fd = set()
os.supports_fd = {{_replaced.get(f, f) for f in os.supports_fd if f.__name__ in ("stat", "truncate")}}
os.supports_follow_symlinks = {{_replaced.get(f, f) for f in os.supports_follow_symlinks}}
if hasattr(os, "fwalk"):
    del os.fwalk
'''


def _run(argv, cwd, env, timeout=600):
    return subprocess.run(argv, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)


@pytest.fixture(scope="module")
def laptop(kit_site):
    """(the virtual environment, a home folder of the student's): the kit of problem 6 installed, the platform
    simulated."""
    with public_tmp_dir("grader-laptop-") as base:
        key, _ = record_key([6], seed=KIT_SEED)
        kit = build_kit(base / "dist", key=key)
        venv = base / "venv"
        env = outside_env()
        venv_on_site(venv, kit_site, env)
        done = _run([str(venv / "bin" / "python"), "-m", "pip", "install", "-q", str(kit.wheel)], base, env,
                    timeout=1200)
        assert done.returncode == 0, done.stdout + done.stderr
        site = purelib(venv / "bin" / "python", env)
        # Imported by a .pth file of the environment (read at every start, -I included): a Debian Python's own
        # sitecustomize, in its standard library, would come first on sys.path and hide one of that name
        (site / "simulated_platform.py").write_text(SITECUSTOMIZE)
        (site / "simulated_platform.pth").write_text("import simulated_platform\n")
        home = base / "home"
        home.mkdir()
        if os.geteuid() == 0:
            os.chown(home, NOBODY, NOBODY)
        yield venv, home


def _student(venv: Path, home: Path, argv: list[str], cwd: Path, **env) -> subprocess.CompletedProcess:
    """``argv`` run by the student: as a user who is not root, with the virtual environment's commands alone on
    the PATH (no bubblewrap), its output to a pipe in ``PIPE_ENCODING``."""
    if os.geteuid() == 0:
        argv = [shutil.which("setpriv") or "/usr/bin/setpriv", f"--reuid={NOBODY}", f"--regid={NOBODY}", "--clear-groups", "--", *argv]
    environment = {"PATH": str(venv / "bin"), "HOME": str(home), "LANG": "C.UTF-8", "PYTHONIOENCODING": PIPE_ENCODING,
                   **env}
    return _run(argv, cwd, environment)


def test_the_platform_is_simulated(laptop):
    venv, home = laptop
    probe = ("import importlib, json, os, sys\n"
             "def gone(name):\n"
             "    try:\n"
             "        importlib.import_module(name)\n"
             "    except ImportError:\n"
             "        return True\n"
             "    return False\n"
             "def refused(call, error):\n"
             "    try:\n"
             "        call()\n"
             "    except error:\n"
             "        return True\n"
             "    return False\n"
             "fd = os.open('.', os.O_RDONLY)\n"
             f"print(json.dumps({{'modules': [m for m in {MISSING_MODULES!r} if not gone(m)],"
             f" 'functions': [f for f in {MISSING_FUNCTIONS + MISSING_FLAGS!r} if hasattr(os, f)],"
             " 'dir_fd': sorted(f.__name__ for f in os.supports_dir_fd),"
             " 'open_at': refused(lambda: os.open('x', os.O_RDONLY, dir_fd=fd), NotImplementedError),"
             " 'stat_at': refused(lambda: os.stat('x', dir_fd=fd), NotImplementedError),"
             " 'scandir_fd': refused(lambda: os.scandir(fd), TypeError),"
             " 'scandir': os.scandir in os.supports_fd, 'fwalk': hasattr(os, 'fwalk'),"
             " 'output': sys.stdout.encoding}))")
    expected = {"modules": [], "functions": [], "dir_fd": [], "open_at": True, "stat_at": True, "scandir_fd": True,
                "scandir": False, "fwalk": False}
    for flags in ([], ["-I"]):  # the grader, and its worker (started with -I, which ignores PYTHONIOENCODING)
        done = _student(venv, home, [str(venv / "bin" / "python"), *flags, "-c", probe], home)
        assert json.loads(done.stdout) == dict(expected, output=PIPE_ENCODING if not flags else "utf-8"), done.stderr
    assert shutil.which("bwrap", path=str(venv / "bin")) is None


def test_the_light_kit_brings_no_dask(laptop):
    venv, home = laptop
    listing = "import importlib.metadata as m, json; print(json.dumps([d.metadata['Name'] for d in m.distributions()]))"
    done = _student(venv, home, [str(venv / "bin" / "python"), "-c", listing], home)
    installed = {name.lower().replace("_", "-") for name in json.loads(done.stdout)}
    assert set(KIT_DEPENDENCIES) <= installed
    assert not installed & {"dask", "distributed", "tornado", "jupyterlab"}, installed


def _graded(done: subprocess.CompletedProcess, report: Path) -> dict:
    assert report.exists(), done.stdout + done.stderr
    (graded,) = json.loads(report.read_text())["reports"]
    assert "grader_error" not in {r["status"] for r in graded["results"]}, done.stdout
    return graded


def _points(graded: dict) -> float:
    return sum(r["max_score"] for r in graded["results"])


def test_grade_init_and_problem_6_work_without_posix(laptop):
    venv, home = laptop
    grade = str(venv / "bin" / "grade")
    done = _student(venv, home, [grade, "init", "mywork"], home)
    assert done.returncode == 0, done.stdout + done.stderr
    work = home / "mywork"

    done = _student(venv, home, [grade, "problem-6", "--json", "template.json"], work)
    assert done.returncode == 1, done.stdout + done.stderr
    template = _graded(done, work / "template.json")
    assert template["visible_score"] == 0 and _points(template) > 0
    assert "portable mode" in done.stdout and "not your computer from the code" in done.stdout

    reference = home / "reference"
    copy_reference(reference)
    if os.geteuid() == 0:
        shutil.chown(reference, NOBODY, NOBODY)
    done = _student(venv, home, [grade, "problem-6", "--submission", str(reference), "--json", "reference.json"],
                    work)
    assert done.returncode == 0, done.stdout + done.stderr
    full = _graded(done, work / "reference.json")
    assert full["visible_score"] == _points(full) > 0
    assert "portable mode" in full["sandbox"]


def test_links_are_refused_without_posix(laptop):
    """Without ``dir_fd`` and ``O_NOFOLLOW``, a link inside the submission (a module's file, a folder) and a
    submission that is itself a link are refused, as on Linux, and the files they name are never graded."""
    venv, home = laptop
    grade = str(venv / "bin" / "grade")
    elsewhere = copy_reference(home / "elsewhere")  # followed, a link to it would grade the reference: 10/10
    linked = copy_reference(home / "linked")
    (linked / "rotations.py").unlink()
    (linked / "rotations.py").symlink_to(elsewhere / "rotations.py")
    (linked / "etc").symlink_to("/etc")
    done = _student(venv, home, [grade, "problem-6", "--submission", str(linked)], home)
    assert done.returncode == 2, done.stdout + done.stderr
    shown = " ".join(done.stdout.split())
    assert shown.count("the submission holds symbolic links, which the grader never follows") == 1, shown
    assert "rotations.py →" in shown and "etc → /etc" in shown, shown
    assert "0 / 10 points" in shown, shown

    (home / "mylink").symlink_to(elsewhere)
    done = _student(venv, home, [grade, "problem-6", "--submission", str(home / "mylink")], home)
    assert done.returncode == 2, done.stdout + done.stderr
    assert "is a symbolic link, which the grader never follows" in " ".join(done.stdout.split()), done.stdout


def test_check_6_gives_the_verdicts_of_grade_without_posix(laptop):
    """``check(6)``, as a notebook's cell calls it (here from a plain Python, naming its notebook), grades the
    notebook's folder on the simulated platform with the verdicts of ``grade problem-6``: a notebook of the
    reference's definitions with R3 transposed, so that some checks pass and others fail."""
    venv, home = laptop
    done = _student(venv, home, [str(venv / "bin" / "grade"), "init", "books", "--notebook"], home)
    assert done.returncode == 0, done.stdout + done.stderr
    work = home / "books"
    cells = r3_transposed(problem_06_cells(ROOT / "reference"))
    write_notebook(work / "problem_06.ipynb", ["import numpy as np", *cells])

    done = _student(venv, home, [str(venv / "bin" / "grade"), "problem-6", "--seed", "5", "--json", "grade.json"],
                    work)
    assert done.returncode == 1, done.stdout + done.stderr
    graded = _graded(done, work / "grade.json")
    verdicts = {r["check_id"]: r["status"] for r in graded["results"]}
    assert {"passed", "failed"} <= set(verdicts.values()), verdicts

    script = ("import json\nfrom grader import check\n"
              "print(json.dumps(check(6, notebook='problem_06.ipynb', seed=5).verdicts))")
    done = _student(venv, home, [str(venv / "bin" / "python"), "-c", script], work)
    assert done.returncode == 0, done.stdout + done.stderr
    checked = json.loads(done.stdout.splitlines()[-1])
    assert {k: v for k, v in checked.items() if k in verdicts} == verdicts


def test_without_the_portable_mode_the_platform_cannot_grade(laptop):
    """The same kit on the same platform, forced into the plain-process mode: its worker needs ``resource`` (and,
    as root, ``pwd`` and ``fcntl``) and the grader ``os.killpg``, so no check can run: exit code 3."""
    venv, home = laptop
    reference = home / "reference-plain"
    copy_reference(reference)
    done = _student(venv, home, [str(venv / "bin" / "grade"), "problem-6", "--submission", str(reference)], home,
                    GRADER_SANDBOX="process")
    assert done.returncode == 3, done.stdout + done.stderr
    # the worker's start fails (no resource) and the grader's own handling of it (os.killpg): nothing is graded
    assert "grader installation fault" in done.stderr or "internal grader error" in done.stdout, done.stdout
    assert "✔" not in done.stdout, done.stdout
