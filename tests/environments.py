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

__all__ = ["SYSTEM_PYTHON", "base_python", "public_tmp_dir"]

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
