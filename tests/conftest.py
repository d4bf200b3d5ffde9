"""The header of a test run says how student code runs on this machine: most tests grade submissions, and where
the grader must refuse to run student code (root, no bubblewrap, a Python no other user can read) they fail with
that refusal; the header says so once, with the fix, before the failures."""

from __future__ import annotations

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
from .kit_support import answer_key, deferred_ids, kit_oracle  # noqa: E402,F401


@pytest.fixture(scope="session")
def kit_site():
    """The student kit's dependencies installed once, in a folder every user can read, for the tests that install
    the kit (``environments.KIT_SITE_GROUP``): each installs the kit's wheel with pip into a fresh environment that
    sees this site, and pip installs what the kit requires that the site lacks.  tests/test_install.py installs
    the grader and all it requires from the package index into an environment of its own."""
    import os

    from grader.kit import kit_dependencies

    from .environments import dependency_site

    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "GRADER_ORACLE", "VIRTUAL_ENV")}
    with dependency_site(kit_dependencies(), env) as site:
        yield site
