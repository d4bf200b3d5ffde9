"""The header of a test run says how student code runs on this machine: most tests grade submissions, and where
the grader must refuse to run student code (root, no bubblewrap, a Python no other user can read) they fail with
that refusal; the header says so once, with the fix, before the failures."""

from __future__ import annotations

import fcntl
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest


def sandbox_header() -> list[str]:
    from grader.sandbox import refusal, sandbox_mode

    mode = sandbox_mode()
    if mode.isolated:
        return [f"sandbox: {mode.note}"]
    refused = refusal()
    if refused is not None:
        return ["sandbox: none here, and the grader refuses to run student code, so every test that grades a "
                "submission fails with this refusal:", *("  " + line for line in refused.splitlines())]
    return [f"sandbox: {mode.note or 'a plain process with resource limits'} (bubblewrap is not available)"]


def pytest_report_header(config):
    return sandbox_header()


# The kit's answer key, recorded once per test process: defined here, once, rather than imported into each test
# module (a fixture imported into a module is that module's own, and a session fixture of several modules is
# recorded once for each of them).
from .kit_support import answer_key, deferred_ids, kit_oracle, shared_key_path  # noqa: E402,F401

#: the process that records the kit's key beside the test processes of a parallel run of the whole suite
_KEY_RECORDER: list[subprocess.Popen] = []


@pytest.hookimpl(trylast=True)
def pytest_configure(config):
    """A parallel run of the whole suite (its controller, before the test processes start) records the kit's key in
    a process of its own, beside the tests that do not need it (``pytest_collection_modifyitems`` runs them first):
    the first test process to need the key used to record it while the other waited for it, idle.  Where that
    process fails, the first test process to need the key records it, as before."""
    if hasattr(config, "workerinput") or not getattr(config.option, "numprocesses", None):
        return
    if config.args_source is not pytest.Config.ArgsSource.TESTPATHS:  # some tests chosen: they may need no key
        return
    path = shared_key_path(config._tmp_path_factory.getbasetemp())
    _KEY_RECORDER.append(subprocess.Popen([sys.executable, "-m", "tests.kit_support", str(path)],
                                          cwd=Path(__file__).resolve().parents[1], stdout=subprocess.DEVNULL,
                                          stderr=subprocess.DEVNULL))


def pytest_collection_modifyitems(config, items):
    """The test modules that need the kit's key after those that do not, each whole and in its order (a module's
    fixtures are made once)."""
    keyed = {item.path for item in items if "answer_key" in getattr(item, "fixturenames", ())}
    items.sort(key=lambda item: item.path in keyed)


def _run_owner(config) -> int:
    """The process of the whole test run: the controller of a parallel run (pytest-xdist), whose test processes are
    its children, else this one."""
    return os.getppid() if hasattr(config, "workerinput") else os.getpid()


def _kit_site_folder(owner: int) -> Path:
    return Path(tempfile.gettempdir(), f"grader-kit-site-{owner}")


@pytest.fixture(scope="session")
def kit_site(request):
    """The student kit's dependencies installed once per test run, in a folder every user can read, for the tests
    that install the kit: each installs the kit's wheel with pip into a fresh environment that sees this site
    (``environments.venv_on_site``), and pip installs what the kit requires that the site lacks.  The first test
    process to need it installs it; the others wait for it (a lock); the run's end removes it.
    tests/test_install.py installs the grader and all it requires from the package index into an empty
    environment of its own."""
    from grader.kit import kit_dependencies

    from .environments import install_site, outside_env

    folder = _kit_site_folder(_run_owner(request.config))
    ready = folder.with_name(folder.name + ".ready")
    env = outside_env()
    with open(folder.with_name(folder.name + ".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not ready.exists():
            shutil.rmtree(folder, ignore_errors=True)  # what a process that failed to install it left
            ready.write_text(str(install_site(folder, kit_dependencies(), env)))
    return Path(ready.read_text())


def pytest_sessionfinish(session):
    """The run's end (in the controller of a parallel run, after its test processes): the kit's site removed."""
    if hasattr(session.config, "workerinput"):
        return
    for recorder in _KEY_RECORDER:
        recorder.kill()
        recorder.wait()
    folder = _kit_site_folder(os.getpid())
    shutil.rmtree(folder, ignore_errors=True)
    for suffix in (".ready", ".lock"):
        folder.with_name(folder.name + suffix).unlink(missing_ok=True)
