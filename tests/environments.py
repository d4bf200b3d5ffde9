"""Virtual environments for the install tests: made from an interpreter that every user can read, in a folder that
every user can read, so that the sandbox's unprivileged uid can run the installed grader's child."""

from __future__ import annotations

import contextlib
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

__all__ = ["SYSTEM_PYTHON", "base_python", "public_tmp_dir", "purelib", "install_site", "venv_on_site",
           "outside_env"]

#: the interpreter of the environment: a system Python every user can read, when it is recent enough
SYSTEM_PYTHON = "/usr/bin/python3"


def base_python() -> str:
    """The system Python when it is at least 3.11 and can make virtual environments, else this interpreter."""
    try:
        done = subprocess.run([SYSTEM_PYTHON, "-c", "import sys, venv, ensurepip; print(sys.version_info >= (3, 11))"],
                              capture_output=True, text=True, timeout=60)
    except OSError:
        return sys.executable
    return SYSTEM_PYTHON if done.stdout.strip() == "True" else sys.executable


@contextlib.contextmanager
def public_tmp_dir(prefix: str):
    """A fresh folder under /tmp that other users can read and enter (pytest's own tmp_path is closed to them)."""
    base = Path(tempfile.mkdtemp(prefix=prefix, dir="/tmp"))
    os.chmod(base, 0o755)
    try:
        yield base
    finally:
        shutil.rmtree(base, ignore_errors=True)


def outside_env() -> dict:
    """This process's environment without what ties a program to this tree and this interpreter (``PYTHONPATH``,
    ``GRADER_ORACLE``, ``VIRTUAL_ENV``): for a program of another environment, as a user runs it."""
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "GRADER_ORACLE", "VIRTUAL_ENV")}


def purelib(python: Path, env: dict | None = None) -> Path:
    """The folder of pure-Python packages of the environment of the interpreter ``python``."""
    done = subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                          capture_output=True, text=True, timeout=120, env=env)
    assert done.returncode == 0, done.stderr
    return Path(done.stdout.strip())


def install_site(folder: Path, requirements: list[str], env: dict) -> Path:
    """A virtual environment of ``base_python()`` made in the new folder ``folder`` (which every user can read) with
    ``requirements`` installed: returns its folder of packages, for ``venv_on_site``."""
    folder.mkdir()
    os.chmod(folder, 0o755)
    venv = folder / "venv"
    for argv in ([base_python(), "-m", "venv", str(venv)],
                 [str(venv / "bin" / "python"), "-m", "pip", "install", "-q", *requirements]):
        done = subprocess.run(argv, cwd=folder, env=env, capture_output=True, text=True, timeout=1200)
        assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return purelib(venv / "bin" / "python", env)


def venv_on_site(venv: Path, site: Path, env: dict) -> None:
    """A fresh virtual environment at ``venv`` that sees the packages of ``site`` (a ``.pth`` file of its own
    site): what a package installed there requires and ``site`` holds is found installed, and only the rest is
    installed."""
    done = subprocess.run([base_python(), "-m", "venv", str(venv)], capture_output=True, text=True, timeout=600,
                          env=env)
    assert done.returncode == 0, done.stderr
    (purelib(venv / "bin" / "python", env) / "shared-site.pth").write_text(f"{site}\n")
