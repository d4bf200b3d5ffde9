"""The parent's handle on a worker process: start it, call probes with timeouts, restart after a crash."""

from __future__ import annotations

import os
import select
import signal
import subprocess
import tempfile
import time
from pathlib import Path

from probes._codec import decode, encode

from . import worker
from .errors import GraderFault, StudentCodeError, StudentTimeout, WorkerCrash
from .sandbox import Limits, SandboxMode, child_command, child_env, sandbox_mode

__all__ = ["Child"]

#: how much of the child's stdout/stderr is kept for the report
OUTPUT_TAIL = 4000


class Child:
    """A worker process for one submission.  ``call`` runs a probe; a crash or time-out kills the process, and
    the next call starts a fresh one (unless importing the submission itself failed: that failure is final)."""

    def __init__(self, submission: Path, limits: Limits | None = None, mode: SandboxMode | None = None):
        self.submission = Path(submission)
        self.limits = limits or Limits()
        self.mode = mode or sandbox_mode()
        self._proc: subprocess.Popen | None = None
        self._next_id = 0
        self._import_failure: Exception | None = None
        self._output = tempfile.TemporaryFile()
        self._errors = tempfile.TemporaryFile()
        self.calls = 0
        self.restarts = 0
        self._pending_import = False

    # ------------------------------------------------------------------ process life

    def start(self) -> None:
        """Start the worker and ask it to import the submission, without waiting: the parent's own work
        overlaps with the child's start-up; the first ``call`` waits for the import to finish."""
        if self._proc is None and self._import_failure is None:
            self._spawn()
            self._pending_import = True

    def _start(self) -> None:
        self._spawn()
        self._finish_import()

    def _finish_import(self) -> None:
        self._pending_import = False
        self._request(None, self.limits.import_timeout, phase="import")

    def _spawn(self) -> None:
        to_child_r, to_child_w = os.pipe()
        from_child_r, from_child_w = os.pipe()
        argv = child_command(self.submission, to_child_r, from_child_w, self.limits, self.mode)
        try:
            self._proc = subprocess.Popen(
                argv,
                stdin=subprocess.DEVNULL,
                stdout=self._output,
                stderr=self._errors,
                pass_fds=(to_child_r, from_child_w),
                env=child_env(),
                cwd=tempfile.gettempdir(),
                start_new_session=True,
            )
        except OSError as exc:
            raise GraderFault(f"cannot start the worker process: {exc}") from exc
        finally:
            os.close(to_child_r)
            os.close(from_child_w)
        self._send_fd, self._recv_fd = to_child_w, from_child_r
        self.restarts += 1
        self._next_id += 1
        self._send({"op": "import", "id": self._next_id}, phase="import")

    def _kill(self) -> None:
        self._pending_import = False
        proc, self._proc = self._proc, None
        if proc is None:
            return
        for fd in (self._send_fd, self._recv_fd):
            try:
                os.close(fd)
            except OSError:
                pass
        if proc.poll() is None:
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                proc.kill()
        try:
            proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            proc.kill()

    def close(self) -> None:
        """Ask the worker to exit, then make sure it has."""
        if self._proc is not None and self._proc.poll() is None:
            try:
                worker.write_message(self._send_fd, {"id": -1, "op": "exit"})
                self._proc.wait(timeout=1)
            except (OSError, subprocess.TimeoutExpired):
                pass
        self._kill()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        self._output.close()
        self._errors.close()

    # ------------------------------------------------------------------ protocol

    def _receive(self, timeout: float, phase: str) -> dict:
        deadline = time.monotonic() + timeout
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                self._kill()
                raise StudentTimeout(timeout, phase)
            ready, _, _ = select.select([self._recv_fd], [], [], left)
            if ready:
                break
        try:
            message = worker.read_message(self._recv_fd)
        except (ValueError, UnicodeDecodeError, RecursionError) as exc:
            self._kill()
            raise StudentCodeError("bad_value", "ValueError", f"the answer could not be read: {exc}", "", phase)
        if message is None:
            code = self._proc.wait(timeout=5) if self._proc else None
            self._kill()
            raise WorkerCrash(self._crash_detail(code), phase)
        return message

    def _crash_detail(self, code) -> str:
        if code is not None and code < 0:
            try:
                name = signal.Signals(-code).name
            except ValueError:
                name = f"signal {-code}"
            cause = {
                "SIGKILL": "killed (a resource limit, e.g. memory or CPU time, or the grader's time-out)",
                "SIGXCPU": "stopped by the CPU-time limit",
                "SIGSEGV": "crashed (segmentation fault)",
            }.get(name, f"stopped by {name}")
            return f"the process running your code was {cause}"
        return f"the process running your code ended unexpectedly with exit code {code} (did it call os._exit?)"

    def _send(self, message: dict, phase: str) -> None:
        try:
            worker.write_message(self._send_fd, message)
        except (BrokenPipeError, OSError):
            code = self._proc.wait(timeout=5) if self._proc else None
            self._kill()
            raise WorkerCrash(self._crash_detail(code), phase)

    def _request(self, message: dict | None, timeout: float, phase: str = "call") -> dict:
        """Send ``message`` (None: only wait for the reply to the last request) and return the reply."""
        if message is not None:
            self._next_id += 1
            self._send(dict(message, id=self._next_id), phase)
        while True:
            reply = self._receive(timeout, phase)
            if reply.get("id") == self._next_id:
                break
        if not reply.get("ok"):
            raise StudentCodeError(
                str(reply.get("kind", "exception")),
                str(reply.get("type", "Exception")),
                str(reply.get("message", "")),
                str(reply.get("traceback", "")),
                str(reply.get("phase", phase)),
            )
        return reply

    def call(self, probe: str, *args, timeout: float | None = None):
        """Run ``probe`` (e.g. ``"problem_06.vectors"``) on the submission; return its decoded value."""
        if self._import_failure is not None:
            raise self._import_failure
        if self._pending_import or self._proc is None or self._proc.poll() is not None:
            try:
                if self._pending_import:
                    self._finish_import()
                else:
                    self._kill()
                    self._start()
            except (StudentCodeError, StudentTimeout, WorkerCrash) as exc:
                if exc.phase == "import" and not getattr(exc, "not_implemented", False):
                    self._import_failure = exc
                raise
        self.calls += 1
        reply = self._request(
            {"op": "call", "probe": probe, "args": encode(list(args))}, timeout or self.limits.call_timeout
        )
        try:
            return decode(reply.get("value"))
        except (RecursionError, ValueError, TypeError) as exc:  # only a forged reply can be malformed
            raise StudentCodeError("bad_value", type(exc).__name__, f"the answer could not be read: {exc}")

    def output(self) -> tuple[str, str]:
        """The tails of what the child printed on stdout and stderr."""

        def tail(handle) -> str:
            handle.flush()
            size = handle.seek(0, os.SEEK_END)
            handle.seek(max(0, size - OUTPUT_TAIL))
            text = handle.read().decode("utf-8", "replace")
            return ("…" + text) if size > OUTPUT_TAIL else text

        return tail(self._output), tail(self._errors)
