"""The parent's handle on a worker process: start it, call probes with absolute deadlines, restart after a crash.

Everything the worker sends after it said ready is untrusted: every read has one absolute deadline per call,
whatever arrives before it (replies with other ids, a header and half a body, nothing at all), and every size is
checked before anything is stored.  Faults of the set-up (a worker that cannot start or cannot import its
dependencies, a probe that does not exist) are the grader's: they raise ``GraderFault`` (a probe's,
``ProbeFault``), never a student error.
"""

from __future__ import annotations

import importlib
import importlib.util
import os
import select
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import probes

from ..errors import MachineBusy, ProbeFault, SandboxError, StudentCodeError, StudentTimeout, WorkerCrash
from . import protocol
from .queueing import LEAST_WAIT, Queueing, excess_wait, waited
from .launch import Launch, Limits, SandboxMode, prepare, sandbox_mode
from .portable import PORTABLE, PortableProcess, prepare_portable
from .zygote import ForkedProcess

__all__ = ["Child", "canary", "probe_name"]

#: how much of the child's stdout/stderr is kept for the report
OUTPUT_TAIL = 4000
#: a call's deadline moves on by the time its worker waited for a processor (``grader.sandbox.queueing``), by at
#: most this many times the call's limit: a call of limit T ends by (1 + LOAD_GRACE) T of wall time at the latest
LOAD_GRACE = 4.0
#: a call's scheduler counts are read once it has lasted this long [s], not when it is sent: most calls answer
#: sooner, and a read walks the worker's tree in /proc; the wait it misses is below ``LEAST_WAIT``, which no grant
#: would count anyway
COUNTS_AFTER = LEAST_WAIT
#: a call's counts not read yet
UNREAD = object()


def probe_name(probe) -> str:
    """The name of ``probe`` (``"problem_06.vectors"``, or the probe function itself), checked against the
    probes package: a probe that does not exist is the grader's fault, found before anything is sent."""
    try:
        name = probes.name_of(probe)
        if name not in _KNOWN_PROBES:
            probes.lookup(name)
    except probes.ProbeLookupError as exc:
        raise ProbeFault(f"a check asks for the probe {probe!r}, which does not exist (a typo in the check?): "
                         f"{exc}") from exc
    _KNOWN_PROBES.add(name)
    return name


_KNOWN_PROBES: set[str] = set()


def _notes(value) -> tuple[str, ...]:
    """The notes of an import reply (the worker's account of a notebook's definitions that raised), bounded:
    the reply comes from a process that ran student code."""
    notes = value.get("notes") if isinstance(value, dict) else None
    if not isinstance(notes, list):
        return ()
    return tuple(str(note)[:500] for note in notes[:50] if isinstance(note, str))


class Child:
    """A worker process for one submission.  ``call`` runs a probe; a crash or time-out kills the process, and
    the next call starts a fresh one (unless importing the submission itself failed: that failure is final)."""

    def __init__(self, submission: Path, limits: Limits | None = None, mode: SandboxMode | None = None,
                 python: str | None = None, zygote=None, on_grace=None):
        self.submission = Path(submission)
        self.on_grace = on_grace  # told each grant of time for a wait for a processor, in seconds (or None)
        self.limits = limits or Limits()
        self.zygote = zygote  # a warm process to fork workers from (``grader.sandbox.zygote``), or a fresh one each
        self.mode = zygote.mode if zygote is not None else (mode or sandbox_mode())
        self.python = zygote.python if zygote is not None else python
        self.info: dict = {}
        self._proc: subprocess.Popen | None = None
        self._launch: Launch | None = None
        self._reader: protocol.FrameReader | None = None
        self._send_fd = -1
        self._next_id = 0
        self._ready = False
        self._pending_import = False
        self._import_unsent = False
        self._import_failure: Exception | None = None
        # a portable worker opens the file of its output by name (it is not handed a descriptor)
        self._output = (tempfile.NamedTemporaryFile(prefix="grader-output-", delete=False) if self._portable_mode
                        else tempfile.TemporaryFile())
        self._errors = tempfile.TemporaryFile()
        self.calls = 0
        self.restarts = 0
        self.import_notes: tuple[str, ...] = ()  # what the worker said about the submission's notebooks
        self._interrupted = False

    # ------------------------------------------------------------------ process life

    @property
    def _forked(self) -> bool:
        return isinstance(self._proc, ForkedProcess)

    @property
    def _portable_mode(self) -> bool:
        return self.mode.kind == PORTABLE

    def start(self) -> None:
        """Start the worker and ask it to import the submission, without waiting: the parent's own work
        overlaps with the child's start-up; the first ``call`` waits for the import to finish."""
        if self._proc is None and self._import_failure is None:
            self._spawn()
            self._send_import()

    def ready(self) -> dict:
        """Start the worker if needed and wait until it said ready; returns what it reported about itself."""
        if self._proc is None:
            self._spawn()
        self._await_ready()
        return dict(self.info)

    def interrupt(self) -> None:
        """Called from another thread than the one using this Child: kill the worker now and start no other.  The
        using thread's wait for a reply ends (the worker's pipe closes), and its next start of a worker raises
        ``KeyboardInterrupt``; its ``close`` (or ``with``) still cleans up."""
        self._interrupted = True
        proc = self._proc
        if proc is None or isinstance(proc, ForkedProcess) or proc.returncode is not None:
            return
        if isinstance(proc, PortableProcess):
            proc.kill()
            return
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except OSError:
            pass

    def _spawn(self) -> None:
        if self._interrupted:
            raise KeyboardInterrupt("the grading was interrupted")
        if self._portable_mode:
            self._spawn_portable()
            return
        to_child_r, to_child_w = os.pipe()
        from_child_r, from_child_w = os.pipe()
        try:
            if self.zygote is not None:
                if self._launch is None:
                    self._launch = self.zygote.prepare(self.submission, self.limits)
                self._proc = self.zygote.fork(self._launch, to_child_r, from_child_w, self._output, self._errors)
            else:
                self._spawn_fresh(to_child_r, from_child_w)
        except OSError as exc:
            for fd in (to_child_w, from_child_r):
                os.close(fd)
            raise self._setup_fault(f"the worker process cannot be started: {exc}") from exc
        except BaseException:
            for fd in (to_child_w, from_child_r):
                os.close(fd)
            raise
        finally:
            os.close(to_child_r)
            os.close(from_child_w)
        os.set_blocking(to_child_w, False)
        self._send_fd = to_child_w
        self._reader = protocol.FrameReader(from_child_r)
        self._spawned_at = time.monotonic()
        self._ready = False
        self.restarts += 1

    def _spawn_portable(self) -> None:
        """A portable worker (``portable``): the protocol on its standard input and output."""
        if self._launch is None:
            self._launch = prepare_portable(self.submission, self._output.name, self.limits, self.python)
        try:
            self._proc = PortableProcess(self._launch, self._errors)
        except OSError as exc:
            raise self._setup_fault(f"the worker process cannot be started: {exc}") from exc
        self._send_fd = -1
        self._reader = self._proc.replies
        self._spawned_at = time.monotonic()
        self._ready = False
        self.restarts += 1

    def _write(self, message: dict, deadline: float) -> None:
        """Send ``message`` to the worker before ``deadline`` (``protocol.Deadline``; ``OSError`` when it closed
        its end)."""
        if isinstance(self._proc, PortableProcess):
            self._proc.send(message, deadline)
        else:
            protocol.send_before(self._send_fd, message, deadline)

    def _spawn_fresh(self, to_child_r: int, from_child_w: int) -> None:
        if self._launch is None:
            self._launch = prepare(self.submission, to_child_r, from_child_w, self.limits, self.mode, self.python)
        launch = self._launch
        self._proc = subprocess.Popen(
            launch.with_pipes(to_child_r, from_child_w),
            stdin=subprocess.DEVNULL,
            stdout=self._output,
            stderr=self._errors,
            pass_fds=(to_child_r, from_child_w),
            env=launch.env,
            cwd=launch.cwd,
            start_new_session=True,
        )

    def _send_import(self) -> None:
        self._next_id += 1
        self._import_id = self._next_id
        deadline = time.monotonic() + self.limits.setup_timeout
        try:
            self._write({"op": "import", "id": self._import_id}, deadline)
        except protocol.Deadline:
            self._kill()
            raise StudentTimeout(self.limits.setup_timeout, "import") from None
        except OSError:  # the worker ended before it read a word (a forked one may end that fast): its start-up
            self._import_unsent = True  # message says why, read by ``_await_ready``, a fault of the set-up
        self._pending_import = True

    def _exit_code(self) -> int | None:
        """The worker's exit code once it ended (negative: the signal), without reaping it."""
        if self._proc is None:
            return None
        if self._proc.returncode is not None:
            return self._proc.returncode
        if self._forked or isinstance(self._proc, PortableProcess):
            return self._proc.poll()
        try:
            info = os.waitid(os.P_PID, self._proc.pid, os.WEXITED | os.WNOHANG | os.WNOWAIT)
        except ChildProcessError:
            return self._proc.poll()
        if info is None:
            return None
        return info.si_status if info.si_code == os.CLD_EXITED else -info.si_status

    def _wait_exit(self, deadline: float) -> int | None:
        """The exit code once the worker ended, or None if it still runs at ``deadline`` (not reaped)."""
        code = self._exit_code()
        if code is not None or self._proc is None:
            return code
        if isinstance(self._proc, PortableProcess):
            try:
                return self._proc.wait(max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                return None
        try:  # readable when the process ends (Linux 5.3)
            pidfd = os.dup(self._proc.pidfd) if self._forked else os.pidfd_open(self._proc.pid)
        except (AttributeError, OSError):
            pidfd = None
        try:
            pause = 0.001
            while code is None and time.monotonic() < deadline:
                if pidfd is not None:
                    select.select([pidfd], [], [], max(0.0, deadline - time.monotonic()))
                else:
                    time.sleep(pause)
                    pause = min(0.05, pause * 2)
                code = self._exit_code()
            return code
        finally:
            if pidfd is not None:
                os.close(pidfd)

    def _kill(self, final: bool = False) -> None:
        """Kill the worker and every process of its session (and, under its own uid, every process of that uid),
        even when it has already ended.  ``final``: no other worker follows (``close`` sweeps once, last)."""
        self._pending_import = self._import_unsent = False
        self._ready = False
        proc, self._proc = self._proc, None
        if proc is None:
            return
        for fd in (self._send_fd, self._reader.fd if self._reader else -1):
            try:
                os.close(fd)
            except OSError:
                pass
        self._send_fd, self._reader = -1, None
        forked = isinstance(proc, ForkedProcess)
        if isinstance(proc, PortableProcess):  # its own process only: a portable worker has no group of its own
            proc.kill()
        elif proc.returncode is None and not forked:
            try:  # before the worker is reaped: its pid, the group's id, cannot have been reused
                os.killpg(proc.pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass
        if proc.returncode is None:
            try:
                proc.kill()
            except OSError:
                pass
        try:
            proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            pass
        if forked or isinstance(proc, PortableProcess):  # a forked worker's children: killed by the zygote's sweep
            proc.close()
        if self._launch is not None and not final:
            if self.zygote is not None:
                self.zygote.after_exit(self._launch)
            else:
                self._launch.after_exit()

    def close(self) -> None:
        """End the worker and everything it started, at once: every reply it owed is in, and it flushed what it
        printed before each reply, so nothing is lost by not waiting for its interpreter to shut down."""
        try:
            self._kill(final=True)
        finally:
            if self._launch is not None:
                if self.zygote is not None:
                    self.zygote.release(self._launch)
                else:
                    self._launch.release()
                self._launch = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        self._output.close()
        self._errors.close()
        if self._portable_mode:
            try:
                os.unlink(self._output.name)
            except OSError:
                pass

    # ------------------------------------------------------------------ the start-up handshake

    def _setup_fault(self, detail: str, missing: str | None = None) -> SandboxError:
        where = ("in the bubblewrap sandbox" if self.mode.isolated else "as a portable process" if self._portable_mode
                 else "as a plain process")
        stderr = self.output()[1].strip()
        shown = f"\nits error output ends with:\n{stderr[-1500:]}" if stderr and stderr not in detail else ""
        fix = ("Fix: reinstall the grader with its dependencies (`pip install -e .` in the project, or `pip install` "
               "its wheel), then check the installation with `grade demo`.")
        spec = importlib.util.find_spec(missing) if missing and self.python is None else None
        if spec is not None and spec.origin:
            where_installed = os.path.dirname(spec.origin)
            if self.mode.isolated:
                fix = (f"{missing} is installed for the grader ({where_installed}), but the sandbox does not show "
                       "that folder: a defect of the grader, not of your installation. Please report it with the "
                       f"output of `python -m pip show -f mbd-autograder {missing}`.")
            else:
                fix = (f"{missing} is installed for the grader ({where_installed}), but the worker's unprivileged "
                       f"uid cannot read it. Fix: chmod -R o+rX {where_installed}")
        return SandboxError(
            f"grader installation fault: the worker that runs submissions cannot start {where}: {detail}{shown}\n"
            f"Python: {self.python or sys.executable}. This is not the submission's fault; no grade was given.\n"
            + fix
        )

    def _await_ready(self) -> None:
        if self._ready:
            return
        deadline = self._spawned_at + self.limits.setup_timeout
        try:
            message = self._reader.read(deadline)
        except protocol.Deadline:
            self._kill()
            raise self._setup_fault(f"it did not start within {self.limits.setup_timeout:g} s") from None
        except (ValueError, RecursionError) as exc:
            self._kill()
            raise self._setup_fault(f"its first message could not be read: {exc}") from None
        if message is None:
            code = self._wait_exit(time.monotonic() + 5)
            self._kill()
            raise self._setup_fault(f"it ended (exit code {code}) before it was ready")
        if not message.get("ok") or message.get("op") != "ready":
            self._kill()
            missing = message.get("missing") if isinstance(message.get("missing"), str) else None
            raise self._setup_fault(str(message.get("message") or message)[:2000], missing)
        self.info = message.get("info") if isinstance(message.get("info"), dict) else {}
        self._ready = True

    @property
    def note(self) -> str:
        """How the submission ran, for the report: the mode, and what the worker reported at start-up (before
        any code of the submission ran)."""
        if self._portable_mode or not self.info:  # a portable worker: no confinement to report
            return self.mode.note
        parts = [self.mode.note]
        if not self.mode.isolated:
            parts += self._plain_notes()
        if self.info.get("syscalls"):
            parts.append("a fresh session keyring and a system-call filter (no keyrings, tracing, mounts, namespaces, "
                         "BPF, performance counters, userfaultfd, io_uring or Unix sockets)")
        return "; ".join(parts)

    def _plain_notes(self) -> list[str]:
        """What a plain process had of isolation, as it reported at start-up."""
        parts = []
        if self.info.get("pid_namespace"):
            parts.append("its own PID and mount namespaces and /proc (no other process of the machine in view)")
        landlock = self.info.get("landlock")
        if landlock:
            parts.append("Landlock let it read only the Python runtime and the submission and write only a "
                         "private folder" + ("; it could not signal other processes" if landlock.get("signals")
                                             else ""))
        else:
            parts.append("it could use every file its user may read or write (no Landlock in this kernel)")
        if "network_isolated" in self.info and self.info["network_isolated"]:
            parts.append("network isolated (a network namespace of its own)")
        elif landlock and landlock.get("tcp"):
            parts.append("TCP connections blocked (Landlock); the network was otherwise not isolated")
        else:
            parts.append("the network was NOT isolated")
        return parts

    # ------------------------------------------------------------------ protocol

    def _crash_detail(self, code, forked: bool = False) -> str:
        if self.mode.isolated and not forked and code is not None and code > 128:
            code = -(code - 128)  # bubblewrap reports a signal of its child as 128 + the signal
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

    def _ended(self, deadline: float, phase: str) -> WorkerCrash:
        """The worker closed its end of the reply pipe: wait (until the call's deadline) for it to end."""
        code = self._wait_exit(deadline)
        forked = self._forked  # a forked worker's code comes from waitpid, not from bubblewrap
        self._kill()
        if code is None:
            return WorkerCrash("the process running your code closed its connection to the grader and did not "
                               "end; it was stopped at the time limit", phase)
        return WorkerCrash(self._crash_detail(code, forked), phase)

    def _send(self, message: dict, timeout: float, phase: str, deadline: float | None = None) -> None:
        deadline = time.monotonic() + timeout if deadline is None else deadline
        try:
            self._write(message, deadline)
        except protocol.Deadline:
            self._kill()
            raise StudentTimeout(timeout, phase) from None
        except OSError:  # the worker closed its request pipe: it ended, or its code closed it
            raise self._ended(deadline, phase) from None

    def _request(self, message: dict | None, timeout: float, phase: str = "call") -> dict:
        """Send ``message`` (None: only wait for the reply to the import request) and return the reply, all
        before one deadline, ``timeout`` seconds from now."""
        return self._reply(*self._post(message, timeout, phase, waited_now=True))

    def _post(self, message: dict | None, timeout: float, phase: str = "call", waited_now: bool = False) -> tuple:
        """Send ``message`` (None: nothing, the reply awaited is the import's): what ``_reply`` needs to read its
        reply before one deadline, ``timeout`` seconds from now."""
        deadline = time.monotonic() + timeout
        if message is not None:
            self._next_id += 1
            self._send(dict(message, id=self._next_id), timeout, phase, deadline)
            expected = self._next_id
            # ``waited_now``: the reply is awaited at once, and its counts are read once the call has lasted
            # COUNTS_AFTER (``_reply``); a reply awaited later (``call_later``) needs them now
            start = (time.monotonic(), UNREAD if waited_now else self._waited())
        else:  # the import's counts run from the worker's start, when they were 0
            expected, start = self._import_id, (self._spawned_at, Queueing(0.0, 0.0))
        return message, expected, deadline, timeout, phase, self._proc, start

    def _waited(self) -> Queueing | None:
        """The scheduler's counts for the worker's tree (``queueing.waited``), read from outside the sandbox;
        None where they cannot be read."""
        proc = self._proc
        if proc is None:
            return None
        if isinstance(proc, ForkedProcess):  # its pid as this process sees it (the zygote's may be another
            try:  # namespace's): the pidfd's
                info = Path(f"/proc/self/fdinfo/{proc.pidfd}").read_text()
            except OSError:
                return None
            pids = [line.split()[1] for line in info.splitlines() if line.startswith("Pid:")]
            return waited(int(pids[0])) if pids and pids[0].lstrip("-").isdigit() else None
        return waited(getattr(proc, "pid", None))

    def _late(self, start: tuple | None, granted: float) -> float | None:
        """How much more than ``granted`` the machine has kept the worker waiting since ``start`` (the time and
        the counts then): the smaller of its longest task's wait and the wall time its tree spent off a processor
        (``grader.sandbox.queueing``).  None: it cannot be told, or it is no more than the counters' noise."""
        if start is None or start[1] is None:
            return None
        now = self._waited()
        if now is None:
            return None
        return excess_wait(time.monotonic() - start[0], now.cpu - start[1].cpu, now.wait - start[1].wait, granted)

    def _reply(self, message: dict | None, expected: int, deadline: float, timeout: float, phase: str,
               proc=None, start: tuple | None = None) -> dict:
        """The reply with id ``expected``, read before ``deadline`` (replies to abandoned requests are skipped)
        from the worker ``proc`` the request went to.  The deadline moves on by the time the worker waited for a
        processor since the request (``start``: its wait then), up to ``LOAD_GRACE`` times the limit.  At the last
        deadline, a worker that had its whole limit to run is the student's time-out; one that waited longer than
        the grace, and so had less than its limit, is the machine's fault (``MachineBusy``), graded again later."""
        if self._reader is None or self._proc is not proc:  # that worker was stopped since
            raise WorkerCrash("the process running your code was stopped before it replied", phase)
        granted = 0.0
        while True:
            unread = start is not None and start[1] is UNREAD
            until = min(deadline, start[0] + COUNTS_AFTER) if unread else deadline
            try:
                reply = self._reader.read(until)
            except protocol.Deadline:
                if unread:  # the call has lasted COUNTS_AFTER: the counts it is measured from
                    start = (time.monotonic(), self._waited())
                    if until < deadline:
                        continue
                late = self._late(start, granted)
                if late is not None and granted < LOAD_GRACE * timeout:
                    grant = min(late, LOAD_GRACE * timeout - granted)
                    granted, deadline = granted + grant, deadline + grant
                    if self.on_grace is not None:
                        self.on_grace(grant)
                    continue
                self._kill()
                if late is not None:  # the grace is spent and the code still had less than its limit to run
                    raise MachineBusy(timeout, granted + late, phase) from None
                raise StudentTimeout(timeout, phase) from None
            except (ValueError, RecursionError) as exc:
                self._kill()
                raise StudentCodeError("bad_value", "ValueError", f"the answer could not be read: {exc}", "",
                                       phase) from None
            if reply is None:
                raise self._ended(deadline, phase)
            if reply.get("id") == expected:
                break
        if reply.get("ok"):
            return reply
        kind = str(reply.get("kind", "exception"))
        if kind == "probe":
            raise ProbeFault(f"the worker could not run the probe {message and message.get('probe')!r}: "
                              f"{reply.get('message', '')} (its copy of the probes differs from the grader's, or "
                              "the submission tampered with them)")
        raise StudentCodeError(
            kind if kind in protocol.STUDENT_KINDS else "exception",
            str(reply.get("type", "Exception")),
            str(reply.get("message", "")),
            str(reply.get("traceback", "")),
            str(reply.get("phase", phase)),
        )

    def _ensure_imported(self) -> None:
        if self._import_failure is not None:
            raise self._import_failure
        if self._proc is not None and not self._pending_import and self._exit_code() is not None:
            self._kill()
        if self._proc is None:
            self._spawn()
            self._send_import()
        if not self._pending_import:
            return
        self._await_ready()
        if self._import_unsent:  # it said ready after all: ask again
            self._import_unsent = False
            self._pending_import = False
            self._send_import()
        try:
            self._pending_import = False
            reply = self._request(None, self.limits.import_timeout, phase="import")
            self.import_notes = _notes(reply.get("value"))
        except (StudentCodeError, StudentTimeout, WorkerCrash) as exc:
            if exc.phase == "import" and not getattr(exc, "not_implemented", False):
                self._import_failure = exc
            raise

    def call(self, probe, *args, timeout: float | None = None):
        """Run ``probe`` (e.g. ``"problem_06.vectors"``) on the submission; return its decoded value."""
        return self.call_later(probe, *args, timeout=timeout, waited_now=True)()

    def call_later(self, probe, *args, timeout: float | None = None, waited_now: bool = False):
        """Send the call of ``probe`` now; returns a function that waits for its value (or raises what ``call``
        raises), so that the grader's own work in between overlaps the student's code.  The call's deadline runs
        from now; the next call is sent after this one's value was asked for (or the value abandoned).
        ``waited_now``: the caller asks for the value at once (``call``)."""
        from probes._codec import encode

        name = probe_name(probe)
        self._ensure_imported()
        self.calls += 1
        pending = self._post({"op": "call", "probe": name, "args": encode(list(args))},
                             timeout or self.limits.call_timeout, waited_now=waited_now)
        return lambda: self._value(self._reply(*pending))

    @staticmethod
    def _value(reply: dict):
        from probes._codec import decode

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


def canary(limits: Limits | None = None, mode: SandboxMode | None = None, python: str | None = None) -> dict:
    """Start one worker on an empty submission and wait until it is ready: the check of an installation that a
    batch runs before grading anyone.  Returns what the worker reported; raises ``SandboxError``."""
    with tempfile.TemporaryDirectory(prefix="grader-canary-") as empty:
        os.chmod(empty, 0o755)
        with Child(Path(empty), limits, mode, python) as child:
            return child.ready()
