"""The header of a test run says how student code runs on this machine: most tests grade submissions, and where
the grader must refuse to run student code (root, no bubblewrap, a Python no other user can read) they fail with
that refusal; the header says so once, with the fix, before the failures."""

from __future__ import annotations


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
