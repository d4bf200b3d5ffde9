"""The portable mode: a student's own code, on the student's own machine (macOS, Windows, a Linux without
bubblewrap such as a locked-down JupyterHub), run where the grader cannot confine it.

The worker is a separate Python process started with ``subprocess`` (``portable_worker.py``, which serves with
``worker.py``'s own loop and dispatch), talked to over its standard input (requests) and output (replies) in the
frames of ``protocol``.  Every call has its absolute deadline, read by a thread of the grader that takes whole
frames off the pipe (``select`` on pipes exists on POSIX only); a worker that misses its deadline, crashes or
says something unreadable is ended with ``terminate`` and then ``kill``.  Nothing here needs ``fork``, ``prctl``,
``killpg``, ``setsid``, ``fcntl``, ``pwd`` or Landlock; ``resource`` limits are applied by the worker where the
platform has them (macOS, Linux).

It is the student's own code under the student's own user: the mode protects the grading from crashes and hangs,
not the machine from the code, and the report says so.  It is chosen for a student's own grading only
(``student_mode``: ``grade problem-N`` and ``check`` in Jupyter, in the student kit, by a grader that is not root
where bubblewrap cannot run, or when ``GRADER_SANDBOX=portable`` asks for it); instructor grading (a batch,
Gradescope) never uses it.
"""

from __future__ import annotations

import json
import os
import queue
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from . import protocol
from .launch import REQUIRED, Limits, SandboxMode, _bwrap_works, child_env, is_root, runtime_dir, sandbox_mode

__all__ = ["PORTABLE", "PORTABLE_NOTE", "portable_mode", "student_mode", "PortableLaunch", "prepare_portable",
           "PortableProcess"]

#: the kind of the mode (``SandboxMode.kind``)
PORTABLE = "portable"
#: what the report says of it, in one line
PORTABLE_NOTE = ("portable mode: your code ran in a separate process with a time limit per call, which protects the "
                 "grading from crashes and hangs, not your computer from the code")
#: seconds a worker is given to end after ``terminate`` before it is killed
TERMINATE_GRACE = 0.5
#: environment variables a Python on Windows needs to start (and that say nothing secret)
_WINDOWS_ENV = ("SYSTEMROOT", "SYSTEMDRIVE", "WINDIR", "COMSPEC", "PATHEXT", "NUMBER_OF_PROCESSORS",
                "PROCESSOR_ARCHITECTURE")


def portable_mode() -> SandboxMode:
    return SandboxMode(PORTABLE, PORTABLE_NOTE)


def student_mode(kit: bool) -> SandboxMode:
    """The mode of a student's own grading.  ``GRADER_SANDBOX=portable`` forces the portable mode; in the student
    kit (``kit``), a grader that is not root where bubblewrap cannot run uses it; otherwise ``sandbox_mode``
    chooses, as for instructor grading."""
    prefer = os.environ.get("GRADER_SANDBOX", "auto")
    if prefer == PORTABLE:
        return portable_mode()
    if prefer == "auto" and kit and not is_root() and not _bwrap_runs():
        return portable_mode()
    return sandbox_mode()


def _bwrap_runs() -> bool:
    """Whether bubblewrap is installed and can make its namespaces here."""
    bwrap = shutil.which("bwrap")
    return bool(bwrap) and _bwrap_works(bwrap)


# ------------------------------------------------------------------------------------------ the launch


def _portable_env(home: str) -> dict[str, str]:
    """``child_env`` (no variable of the grader's environment), with what the platform's Python needs to start
    and find its temporary folder there."""
    env = dict(child_env(home), TEMP=home, TMP=home, USERPROFILE=home)
    if os.name == "nt":
        env.update({name: os.environ[name] for name in _WINDOWS_ENV if name in os.environ})
        env["PATH"] = os.environ.get("PATH", "")  # where a Python's DLLs may be found
    return env


@dataclass
class PortableLaunch:
    """How a portable worker is started (argv, environment, its private folder as working directory), and the
    folder to remove after it."""

    argv: list[str]
    env: dict[str, str]
    cwd: str
    home: str | None

    def after_exit(self, again: bool = True) -> None:
        """After the worker ended: remove its folder, and with ``again`` make a fresh one for the next worker."""
        if self.home is None:
            return
        shutil.rmtree(self.home, ignore_errors=True)
        if again:
            home = tempfile.mkdtemp(prefix="grader-child-")
            self.argv = [arg.replace(json.dumps(self.home)[1:-1], json.dumps(home)[1:-1]) for arg in self.argv]
            self.env = _portable_env(home)
            self.home = self.cwd = home
        else:
            self.home = None

    def release(self) -> None:
        self.after_exit(again=False)


def prepare_portable(submission: Path, output: str, limits: Limits, python: str | None = None) -> PortableLaunch:
    """The launch of a portable worker for ``submission``; what the student's code prints goes to the file
    ``output``."""
    import importlib.util

    python = python or sys.executable
    home = tempfile.mkdtemp(prefix="grader-child-")
    required = [name for name in REQUIRED if importlib.util.find_spec(name) is not None]
    config = {"limits": limits.for_worker(), "require": required, "submission": str(submission),
              "output": str(output), "home": home}
    worker = runtime_dir() / "portable_worker.py"
    # -X utf8: files and the student's prints in UTF-8, as in C.UTF-8 on Linux, not in the ANSI code page of
    # Windows (cp1252: a print("ω") would raise there); -I ignores PYTHONUTF8 and PYTHONIOENCODING
    argv = [python, "-I", "-B", "-X", "utf8", str(worker), json.dumps(config)]
    return PortableLaunch(argv, _portable_env(home), home, home)


# ------------------------------------------------------------------------------------------ the process


def _read_exact(stream, n: int) -> bytes | None:
    chunks = []
    while n:
        chunk = stream.read(min(n, protocol.CHUNK))
        if not chunk:
            return None
        chunks.append(chunk)
        n -= len(chunk)
    return b"".join(chunks)


class _Replies:
    """The worker's replies, taken off its output pipe by a thread of their own: whole frames, each size checked
    against ``limit`` before its body is read.  ``read`` waits for the next one until a deadline."""

    fd = -1  # no descriptor for the caller to close: the pipe is the process's

    def __init__(self, stream, limit: int = protocol.MAX_MESSAGE):
        self._frames: queue.Queue = queue.Queue(maxsize=4)
        self._stopped = threading.Event()
        self.closed = False
        threading.Thread(target=self._pump, args=(stream, limit), name="portable-replies", daemon=True).start()

    def _put(self, item) -> None:
        while not self._stopped.is_set():
            try:
                self._frames.put(item, timeout=0.1)
                return
            except queue.Full:
                continue

    def _pump(self, stream, limit: int) -> None:
        try:
            while not self._stopped.is_set():
                header = _read_exact(stream, protocol.HEADER.size)
                if header is None:
                    break
                (size,) = protocol.HEADER.unpack(header)
                if size > limit:
                    self._put(protocol.ProtocolError(f"message of {size} bytes exceeds the limit of {limit}"))
                    return
                data = _read_exact(stream, size)
                if data is None:
                    break
                self._put(data)
        except (OSError, ValueError):
            pass
        finally:
            self._put(None)

    def read(self, deadline: float) -> dict | None:
        """The next message; None once the worker closed its end.  Raises ``protocol.Deadline`` when the deadline
        passes first, ``ProtocolError`` (or a ``ValueError`` of JSON) for a malformed message."""
        if self.closed:
            return None
        try:
            item = self._frames.get(timeout=max(0.0, deadline - time.monotonic()))
        except queue.Empty:
            raise protocol.Deadline("the deadline passed") from None
        if item is None:
            self.closed = True
            return None
        if isinstance(item, Exception):
            self.closed = True
            raise item
        message = json.loads(item)
        if not isinstance(message, dict):
            raise protocol.ProtocolError(f"a message must be a JSON object, not {type(message).__name__}")
        return message

    def stop(self) -> None:
        self._stopped.set()


class PortableProcess:
    """A portable worker: a ``subprocess.Popen`` with the protocol on its standard input and output."""

    def __init__(self, launch: PortableLaunch, errors):
        self._popen = subprocess.Popen(launch.argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=errors,
                                       env=launch.env, cwd=launch.cwd, bufsize=0)
        self.pid = self._popen.pid
        self.replies = _Replies(self._popen.stdout)

    @property
    def returncode(self) -> int | None:
        return self._popen.returncode

    def poll(self) -> int | None:
        return self._popen.poll()

    def wait(self, timeout: float | None = None) -> int:
        return self._popen.wait(timeout)

    def send(self, message: dict, deadline: float) -> None:
        """Write ``message`` before ``deadline``: a thread writes it, so that a worker that does not read cannot
        block the grader.  Raises ``protocol.Deadline``, or ``OSError`` when the worker closed its input."""
        data = protocol.frame(message)
        failed: list[BaseException] = []
        done = threading.Event()

        def write() -> None:
            try:
                view = memoryview(data)
                while view:
                    view = view[self._popen.stdin.write(view):]
            except (OSError, ValueError) as exc:
                failed.append(exc if isinstance(exc, OSError) else BrokenPipeError(str(exc)))
            finally:
                done.set()

        threading.Thread(target=write, name="portable-request", daemon=True).start()
        if not done.wait(max(0.0, deadline - time.monotonic())):
            raise protocol.Deadline("the deadline passed")
        if failed:
            raise failed[0]

    def kill(self) -> None:
        """``terminate``, then ``kill`` if it has not ended within ``TERMINATE_GRACE``."""
        if self._popen.poll() is not None:
            return
        try:
            self._popen.terminate()
            self._popen.wait(TERMINATE_GRACE)
        except subprocess.TimeoutExpired:
            self._popen.kill()
        except OSError:
            pass

    def close(self) -> None:
        """Close the pipes (after the worker ended)."""
        self.replies.stop()
        for stream in (self._popen.stdin, self._popen.stdout):
            try:
                stream.close()
            except OSError:
                pass
