"""The grader's handle on the warm child of a batch slot: a sandboxed process (``forkserver.py``, the fork server)
that has imported what the students' workers need (numpy and, where the batch's problems use them, scipy, sympy,
mujoco and the probes) and forks one worker per student.

Starting a fresh worker costs an interpreter, a sandbox and the imports, for every student; forking a warm one
costs a few milliseconds.  The isolation is the fresh worker's, established in the fork before any student code
runs (``forkserver._forked``):

* files: under bubblewrap the zygote is started once per slot with the slot's *staging folder* at ``/slot`` (the
  grader materializes each student's package there, one student at a time).  Each forked worker enters a mount
  and an IPC namespace of its own, binds its own package read-only at ``/submission``, covers ``/slot`` with an
  empty read-only tmpfs (bubblewrap's mounts cannot be detached in an unprivileged user namespace), and
  mounts empty ``/tmp`` and ``/dev/shm``: it sees exactly what a fresh worker sees.  (The submission is not
  handed over as an open directory: a directory descriptor of the host's tree lets ``..`` climb to the host's
  root from inside the sandbox, and a mount from a descriptor of another mount namespace is refused by the
  kernel; a staging folder bound at start-up needs neither.)  As plain processes, the worker's Landlock rules
  name its own submission and private home, as a fresh worker's do.
* uid: as root, every student's worker switches to a uid claimed for that student alone (``users``); the zygote
  itself stays root and never runs student code.  Without root, the zygote runs in bubblewrap's user namespace
  with CAP_SYS_ADMIN for those mounts, and the worker drops every capability before the student's code runs.
* limits, Landlock, network: applied in the fork exactly as a fresh worker applies them (``confinement.confine``).
* nothing of the previous student: the fork is a copy of the zygote, which never imported a submission; no
  module, global, thread, environment variable or open file of another student can be in it, the numpy global
  random state is reseeded, and after each student the zygote kills every process the student left (in the
  slot's pid namespace, or the worker's process group; as root, the grader also sweeps the student's uid).  The
  zygote is not dumpable: no process of the same uid can read or write its memory.  A zygote that dies (a
  student of the same uid may kill it) is started again for the next student.
"""

from __future__ import annotations

import json
import os
import secrets
import select
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ..errors import GraderFault, SandboxError
from . import users
from .launch import ForkConfig, Limits, SandboxMode, prepare_fork, prepare_zygote, renew_home, sandbox_mode

__all__ = ["Zygote", "ForkedProcess", "warm_modules", "SLOT_PREFIX", "sweep_orphans", "ending_slots"]

#: the project's packages: never preloaded (the zygote cannot see them, except the probes it imports itself)
_PROJECT = ("grader", "checks", "probes", "reference", "student_template", "tests", "tools")


def warm_modules(problems) -> list[str]:
    """What a zygote imports for ``problems``: their probe modules and the third-party modules that the probes and
    the reference modules they reach import (the students' packages are built on the same modules)."""
    from ..sources import absolute_imports, parsed, verdict_sources

    modules = {"probes", "probes._codec"}
    third_party: set[str] = set()
    for number in problems:
        modules.add(f"probes.problem_{number:02d}")
        for path in verdict_sources(number):
            if path.parent.name not in ("probes", "reference"):
                continue
            if path.parent.name == "probes" and path.stem != "__init__":
                modules.add(f"probes.{path.stem}")
            try:
                imported = absolute_imports(parsed(path))
            except (OSError, SyntaxError, ValueError):
                imported = set()
            third_party |= {name for name in imported
                            if name.split(".")[0] not in _PROJECT and name.split(".")[0] not in sys.stdlib_module_names}
    return sorted(third_party) + sorted(modules)


class ForkedProcess:
    """The grader's handle on a worker forked by a zygote, with what ``Child`` uses of ``subprocess.Popen``: its
    exit code (reported by the zygote, its parent), a kill, a wait.  ``pidfd`` becomes readable when it ends."""

    def __init__(self, zygote: Zygote, fork_id: int, pid: int, pidfd: int):
        self.zygote, self.fork_id, self.pid, self.pidfd = zygote, fork_id, pid, pidfd
        self.returncode: int | None = None

    def poll(self) -> int | None:
        if self.returncode is None and self.pidfd >= 0 and select.select([self.pidfd], [], [], 0)[0]:
            self.returncode = self.zygote.exit_code(self.fork_id)
        return self.returncode

    def wait(self, timeout: float | None = None) -> int:
        if self.returncode is None and self.pidfd >= 0:
            if not select.select([self.pidfd], [], [], timeout)[0]:
                raise subprocess.TimeoutExpired(f"worker {self.pid}", timeout)
        return self.poll()

    def kill(self) -> None:
        if self.returncode is None and self.pidfd >= 0:
            try:
                signal.pidfd_send_signal(self.pidfd, signal.SIGKILL)
            except ProcessLookupError:
                pass

    def close(self) -> None:
        if self.pidfd >= 0:
            os.close(self.pidfd)
            self.pidfd = -1


#: the staging folders of warm processes: ``grader-slot-<pid of the process that made it>-<random>``
SLOT_PREFIX = "grader-slot-"


def _owner(folder: Path) -> int | None:
    pid, _, token = folder.name[len(SLOT_PREFIX):].partition("-")
    return int(pid) if pid.isdigit() and token else None


def _stat(pid: int) -> list[str] | None:
    """The fields of ``/proc/<pid>/stat`` after the process's name (state, parent, ...), or None where there is
    no such file (another system, or the process is gone)."""
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    return text[text.rfind(")") + 2:].split()


def _alive(pid: int) -> bool:
    """The process runs: it exists and, where ``/proc`` tells, is not a zombie (ended, its exit not yet collected
    by its parent: its clean-up will never run)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process
        return True
    fields = _stat(pid)
    return not (fields and fields[0] == "Z")


def _descends_from_us(pid: int) -> bool:
    """``pid`` is a child of this process or of one of its children (read from ``/proc``; False elsewhere)."""
    for _ in range(64):
        fields = _stat(pid)
        if fields is None:
            return False
        pid = int(fields[1])
        if pid == os.getpid():
            return True
        if pid <= 1:
            return False
    return False


def ending_slots(folder: Path | None = None) -> list[Path]:
    """The staging folders in ``folder`` whose process is one of this process's own and still runs: a slot that
    is ending, whose clean-up removes its folder."""
    root = Path(folder) if folder is not None else Path(tempfile.gettempdir())
    try:
        candidates = sorted(root.glob(f"{SLOT_PREFIX}*"))
    except OSError:
        return []
    return [path for path in candidates
            if (pid := _owner(path)) is not None and _alive(pid) and _descends_from_us(pid)]


def sweep_orphans(folder: Path | None = None) -> list[Path]:
    """Remove the staging folders in ``folder`` (the temporary folder) whose process is gone without removing them
    (ended by SIGKILL, say, before its clean-up could run): each batch does at its end, each warm process before it
    makes its own.  A folder of a process still running, of another user, or of another name is left alone.  The
    folders removed."""
    removed = []
    if os.name != "posix":  # no warm processes there, and os.kill(pid, 0) would end the process it names
        return removed
    root = Path(folder) if folder is not None else Path(tempfile.gettempdir())
    try:
        candidates = sorted(root.glob(f"{SLOT_PREFIX}*"))
    except OSError:
        return removed
    for path in candidates:
        pid = _owner(path)
        if pid is None or _alive(pid):
            continue
        try:
            if path.is_symlink() or not path.is_dir() or path.stat().st_uid != os.getuid():
                continue
        except OSError:
            continue
        shutil.rmtree(path, ignore_errors=True)
        removed.append(path)
    return removed


class Zygote:
    """The warm process of one slot.  ``start`` it once; ``prepare`` and ``fork`` a worker per student (``Child``
    does, given ``zygote=``); ``sweep`` after each; ``close`` at the end.  Not thread-safe: one slot, one
    student at a time."""

    def __init__(self, limits: Limits | None = None, mode: SandboxMode | None = None, preload=(),
                 python: str | None = None):
        self.limits = limits or Limits()
        self.mode = mode or sandbox_mode()
        self.preload = list(preload)
        self.python = python
        # named now, made by ``start``: whatever interrupts the making (a stop's signal), ``close`` removes it
        self.staging = Path(tempfile.gettempdir()) / f"{SLOT_PREFIX}{os.getpid()}-{secrets.token_hex(8)}"
        self._made = False
        self.info: dict = {}
        self.starts = 0  # warm processes started (1 unless one died)
        self.forks = 0  # workers forked
        self._proc: subprocess.Popen | None = None
        self._sock: socket.socket | None = None
        self._errors = tempfile.TemporaryFile()
        self._next_id = 0
        self._exits: dict[int, int] = {}

    # ------------------------------------------------------------------ life

    @property
    def alive(self) -> bool:
        return self._proc is not None and self._proc.poll() is None

    def start(self) -> dict:
        """Start the warm process and wait until it imported everything; raises ``SandboxError`` when it cannot."""
        self._stop()
        if not self._made:
            sweep_orphans(self.staging.parent)
            self.staging.mkdir(mode=0o700)  # a new folder, as mkdtemp makes one, then readable by the sandbox
            self._made = True
            os.chmod(self.staging, 0o755)
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        try:
            launch = prepare_zygote(self.staging, theirs.fileno(), self.mode, self.preload, self.python)
            self._proc = subprocess.Popen(launch.argv, stdin=subprocess.DEVNULL, stdout=self._errors,
                                          stderr=self._errors, pass_fds=(theirs.fileno(),), env=launch.env,
                                          cwd=launch.cwd, start_new_session=True)
        except OSError as exc:
            ours.close()
            raise self._fault(f"it cannot be started: {exc}") from exc
        except BaseException:
            ours.close()
            raise
        finally:
            theirs.close()
        self._sock = ours
        self.starts += 1
        self._exits.clear()
        try:
            message, _ = self._receive(time.monotonic() + self.limits.setup_timeout, ("ready", "setup"))
        except SandboxError:
            self._stop()
            raise
        except BaseException:  # stopped while it imports (a signal in the grader): it holds nothing yet, end it now
            self._kill()
            raise
        if not message.get("ok"):
            self._stop()
            raise self._fault(str(message.get("message"))[:2000])
        self.info = message.get("info") or {}
        return dict(self.info)

    def _fault(self, detail: str) -> SandboxError:
        self._errors.flush()
        self._errors.seek(0)
        output = self._errors.read()[-1500:].decode("utf-8", "replace").strip()
        where = "in the bubblewrap sandbox" if self.mode.isolated else "as a plain process"
        shown = f"\nits error output ends with:\n{output}" if output and output not in detail else ""
        return SandboxError(f"grader installation fault: the warm worker process of a batch slot cannot run {where}: "
                            f"{detail}{shown}\nPython: {self.python or sys.executable}. This is not a submission's "
                            "fault; no grade was given.")

    def _stop(self) -> None:
        if self._sock is not None:
            try:
                self._sock.send(json.dumps({"op": "exit"}).encode())
            except OSError:
                pass
            self._sock.close()
            self._sock = None
        if self._proc is not None:
            try:
                self._proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self._kill()
            self._proc = None

    def _kill(self) -> None:
        """End the warm process and its session at once."""
        if self._sock is not None:
            self._sock.close()
            self._sock = None
        if self._proc is not None:
            try:
                os.killpg(self._proc.pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass
            self._proc.kill()
            self._proc.wait()
            self._proc = None

    def close(self) -> None:
        self._stop()
        self._errors.close()
        shutil.rmtree(self.staging, ignore_errors=True)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # ------------------------------------------------------------------ messages

    def _receive(self, deadline: float, ops: tuple[str, ...], fork_id: int | None = None) -> tuple[dict, list[int]]:
        """The next message of one of ``ops`` (and ``fork_id``), keeping the exit codes that arrive meanwhile."""
        while True:
            left = deadline - time.monotonic()
            if self._sock is None or left <= 0:
                raise self._fault("it did not answer in time" if self.alive else "it ended")
            if not select.select([self._sock], [], [], left)[0]:
                continue
            try:
                data, fds, _, _ = socket.recv_fds(self._sock, 1 << 16, 4)
            except OSError as exc:
                raise self._fault(f"its connection failed: {exc}") from None
            if not data:
                code = self._proc.wait(timeout=5) if self._proc is not None else None
                raise self._fault(f"it ended (exit code {code})")
            message = json.loads(data)
            op = message.get("op") if message.get("ok", True) else "setup"
            if op == "exited":
                self._exits[message["id"]] = int(message["code"])
            if op in ops and (fork_id is None or message.get("id") == fork_id):
                return message, fds
            for fd in fds:
                os.close(fd)

    def _send(self, message: dict, fds: list[int] = ()) -> None:
        try:
            socket.send_fds(self._sock, [json.dumps(message).encode()], list(fds))
        except OSError as exc:
            raise self._fault(f"it cannot be reached: {exc}") from None

    # ------------------------------------------------------------------ forks

    def prepare(self, submission: Path, limits: Limits) -> ForkConfig:
        """The confinement of a worker for ``submission`` (claims its uid as root)."""
        return prepare_fork(Path(submission), self.staging, limits, self.mode, self.python)

    def fork(self, fork: ForkConfig, request_fd: int, reply_fd: int, stdout, stderr) -> ForkedProcess:
        """Fork a worker confined by ``fork``, speaking on the two pipe ends; its output goes to the two files."""
        if not self.alive:  # never started, or killed (a student of the same uid may): a fresh one
            self.start()
        self._next_id += 1
        fork_id = self._next_id
        self.forks += 1
        self._send({"op": "fork", "id": fork_id, "config": fork.config},
                   [request_fd, reply_fd, stdout.fileno(), stderr.fileno()])
        message, fds = self._receive(time.monotonic() + self.limits.setup_timeout, ("forked",), fork_id)
        if len(fds) != 1:
            raise GraderFault("the warm worker process sent no handle of the worker it forked")
        return ForkedProcess(self, fork_id, int(message["pid"]), fds[0])

    def exit_code(self, fork_id: int, seconds: float = 5.0) -> int:
        """The exit code of a forked worker that ended (the zygote reaps it and says so); -9 when it cannot say
        (the zygote died, killing its workers)."""
        if fork_id not in self._exits and self.alive:
            try:
                self._receive(time.monotonic() + seconds, ("exited",), fork_id)
            except SandboxError:
                pass
        return self._exits.pop(fork_id, -9)

    def sweep(self, fork: ForkConfig | None = None) -> None:
        """After a student's worker: kill every process the student left; as root without bubblewrap, every
        process and file of the student's uid as well."""
        if self.alive:
            self._next_id += 1
            try:
                self._send({"op": "sweep", "id": self._next_id})
                message, _ = self._receive(time.monotonic() + 30, ("swept",), self._next_id)
            except SandboxError:
                message = {"left": 0}
                self._stop()  # a zygote that cannot sweep is not used again
            if message.get("left"):
                self._stop()
                raise SandboxError(f"{message['left']} processes of a student survived SIGKILL in a batch slot")
        if fork is not None and fork.claim is not None and fork.claim.sweeps:
            users.sweep(fork.claim.uid)

    def after_exit(self, fork: ForkConfig, again: bool = True) -> None:
        """After a forked worker ended: sweep; with ``again``, a fresh home for the next worker of the student."""
        self.sweep(fork)
        if again:
            renew_home(fork, self.python)
        elif fork.home is not None:
            shutil.rmtree(fork.home, ignore_errors=True)
            fork.home = None

    def release(self, fork: ForkConfig) -> None:
        """After the student's last worker: sweep, remove its home, give its uid back."""
        self.after_exit(fork, again=False)
        if fork.claim is not None:
            fork.claim.release()
            fork.claim = None
