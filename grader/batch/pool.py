"""The grading workers of a batch: one process per slot, each grading one student at a time.

A worker is a spawned process that imports the checks once, starts a warm sandboxed child (a zygote, see
``grader.sandbox.zygote``) from which every student's child is forked, and grades the students the parent sends
with ``grade_submission``.  It sends back plain reports.  The parent bounds each student's total time: a worker
that does not answer in time, or dies, is replaced by a fresh one, and its student is reported as stopped or not
graded.

The bound is wall time, and a busy machine is not the student's fault: it moves on by the time the machine took,
as a call's limit does (``grader.sandbox.queueing``) — the time the worker granted the student's calls because
their code waited for a processor (it tells the parent each grant), and the time the tasks of the worker's tree
(the worker, its warm process, the student's process) waited for one, which the parent reads every
``READ_EVERY`` seconds so that the student's process keeps its wait once it ended — by at most ``LOAD_GRACE``
times the bound.  A student still running when that grace is spent is the machine's fault: not
graded, graded again on the next run.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import sys
import time
import traceback
from collections import deque
from dataclasses import dataclass
from multiprocessing.connection import wait

from ..errors import GraderFault
from ..results import ProblemReport, Status
from ..sandbox import Limits, SandboxMode
from ..sandbox.child import LOAD_GRACE
from ..sandbox.queueing import excess_wait, task_counts
from .discover import Entry

__all__ = ["Task", "Slot", "run_pool", "stopped_reports", "STOP_GRACE"]

#: seconds a worker has to stop after SIGTERM before it is killed
STOP_GRACE = 3.0
#: seconds between two reads of the scheduler's counts of a grading worker's tree: a task that ends in between (the
#: student's process, once it answered) keeps the wait it had at its last read
READ_EVERY = 0.25


@dataclass(frozen=True)
class Task:
    entry: Entry
    problems: tuple[int, ...]


def _die_with_parent(parent: int) -> None:
    """Receive SIGTERM when the parent dies, even by SIGKILL (Linux); exit now if it is gone already."""
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass
    if os.getppid() != parent:
        sys.exit(0)


class _Stopped(BaseException):
    """Raised in a worker by SIGTERM: not an Exception (nor SystemExit, which hypothesis takes for a failing
    example), so that nothing on the way catches it and the Child on the way kills the student's process."""


def _stop(signum, frame):
    _cleanup_only()
    raise _Stopped


def _cleanup_only() -> None:
    """From here on the worker only cleans up (its zygote, its staging folder, its temporary folders at exit):
    another SIGTERM, such as the one the kernel sends when the parent goes away just after it stopped the worker
    (PR_SET_PDEATHSIG), must not cut that short and leave the folders behind.  The parent's SIGKILL after
    ``STOP_GRACE`` still bounds it."""
    signal.signal(signal.SIGTERM, signal.SIG_IGN)


def _serve(conn, slot: int, limits: Limits, mode: SandboxMode, problems: tuple[int, ...],
           warm: tuple[str, ...] | None, parent: int) -> None:
    """A worker process: grade the tasks the parent sends, one at a time, and send back the reports."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    signal.signal(signal.SIGTERM, _stop)
    try:
        _die_with_parent(parent)
        _work(conn, slot, limits, mode, problems, warm)
    except _Stopped:
        pass


def _work(conn, slot: int, limits: Limits, mode: SandboxMode, problems: tuple[int, ...],
          warm: tuple[str, ...] | None = None) -> None:
    """Start the slot's warm process (importing ``warm``, the modules ``warm_modules`` names, found here when None)
    and grade the tasks that come through ``conn`` until it closes."""
    from ..sandbox.zygote import Zygote, warm_modules

    zygote = None
    try:
        try:
            from ..runner import grade_submission
            from ..workers import Forked
            from ..problems import problem_module

            for number in problems:
                problem_module(number)
            modules = list(warm) if warm is not None else warm_modules(problems)
            zygote = Zygote(limits, mode, modules)  # its folder is made by start, removed by close
            zygote.start()
        except Exception as exc:  # noqa: BLE001 - reported to the parent, which stops the batch
            conn.send(("fault", str(exc) if isinstance(exc, GraderFault) else traceback.format_exc()))
            return
        conn.send(("ready", None))
        while True:
            try:
                task = conn.recv()
            except (EOFError, OSError):
                return
            if task is None:
                return
            try:
                workers = Forked(zygote, limits, on_grace=lambda seconds: conn.send(("grace", seconds)))
                reports = grade_submission(task.entry.path, list(task.problems), seed=task.entry.seed,
                                           workers=workers, record_answers=True)
                conn.send(("ok", reports))
            except GraderFault as exc:  # this student is not recorded and is retried next run
                conn.send(("fault", str(exc).strip().splitlines()[0]))
            except Exception:  # noqa: BLE001 - a grader fault: this student is not recorded, retried next run
                conn.send(("fault", traceback.format_exc()))
    finally:  # after a fault, a stop (also while the zygote starts) or the end of the batch
        _cleanup_only()
        if zygote is not None:
            zygote.close()


class _Subprocess:
    """A worker process started with ``subprocess`` instead of ``multiprocessing`` (a Dask worker is a daemonic
    process, which ``multiprocessing`` forbids to have children), with what ``Slot`` uses of a ``Process``."""

    def __init__(self, fd: int, args: tuple):
        import base64
        import pickle
        import subprocess

        payload = base64.b64encode(pickle.dumps(args)).decode()
        self._proc = subprocess.Popen([sys.executable, "-m", "grader.batch.pool", str(fd), payload],
                                      pass_fds=(fd,), stdin=subprocess.DEVNULL)
        self.sentinel = os.pidfd_open(self._proc.pid)

    def start(self) -> None:
        pass

    @property
    def pid(self) -> int:
        return self._proc.pid

    def is_alive(self) -> bool:
        return self._proc.poll() is None

    @property
    def exitcode(self) -> int | None:
        return self._proc.poll()

    def terminate(self) -> None:
        if self.is_alive():
            self._proc.terminate()

    def kill(self) -> None:
        if self.is_alive():
            self._proc.kill()

    def join(self, timeout: float | None = None) -> None:
        import subprocess

        try:
            self._proc.wait(timeout)
        except subprocess.TimeoutExpired:
            return
        if self.sentinel >= 0:
            os.close(self.sentinel)
            self.sentinel = -1


#: how often a worker may be killed by a signal while it starts before the batch gives up on the slot (a worker
#: that fails to start by itself is a broken installation at once)
START_KILLS = 3


def _warm(problems: tuple[int, ...]) -> tuple[str, ...] | None:
    """The modules a slot's warm process imports for ``problems``, found once here rather than in every worker
    that starts (finding them parses the sources of every problem's verdicts: seconds per worker); None when they
    cannot be found here, and the worker finds them and reports why not."""
    from ..sandbox.zygote import warm_modules

    try:
        return tuple(warm_modules(problems))
    except Exception:  # noqa: BLE001 - the worker meets the same fault and reports it as the batch's
        return None


class Slot:
    """One worker process and the task it grades."""

    def __init__(self, context, index: int, limits: Limits, mode: SandboxMode, problems: tuple[int, ...]):
        """``context``: a ``multiprocessing`` context to start the worker with, or None for a subprocess."""
        self.context, self.index, self.args = context, index, (limits, mode, problems, _warm(problems))
        self.task: Task | None = None
        self.deadline = self.started = self.bound = 0.0
        self.granted = 0.0  # seconds the bound of the current task moved on for the machine's load
        self._counts = None  # the scheduler's counts of the worker's tree when the task was sent
        self._waits: dict[int, float] = {}  # each task's wait since then, at its last read, ended tasks included
        self.read_at = 0.0  # when they were last read
        self._own = 0.0  # seconds of the worker's own wait for a processor granted so far
        self.killed = False  # the last worker ended by a signal (the OOM killer, an operator), not by itself
        self.kills_while_starting = 0
        self._start()

    def _start(self) -> None:
        if self.context is None:
            import socket
            from multiprocessing.connection import Connection

            ours, theirs = socket.socketpair()
            self.conn = Connection(ours.detach())
            self.process = _Subprocess(theirs.fileno(), (self.index, *self.args, os.getpid()))
            theirs.close()
        else:
            self.conn, theirs = self.context.Pipe()
            self.process = self.context.Process(
                target=_serve, args=(theirs, self.index, *self.args, os.getpid()),
                name=f"grade-worker-{self.index}", daemon=True,
            )
            self.process.start()
            theirs.close()
        self.ready = False

    def wait_ready(self) -> None:
        """Wait until the worker imported the checks and started its zygote; ``RuntimeError`` if it cannot."""
        wait(self.waitables())
        kind, payload = self.poll() or ("crashed", "no answer")
        if kind != "ready":
            raise RuntimeError(f"a grading worker could not start: {payload}")
        self.ready = True

    def outcome(self, task: Task, seconds: float) -> tuple[str, object, float]:
        """Grade ``task`` within ``seconds``: ``(kind, payload, seconds taken)`` (blocking)."""
        if not self.ready:
            self.wait_ready()
        self.submit(task, seconds)
        while True:
            wait(self.waitables(), max(0.0, self.wakeup() - time.monotonic()))
            outcome = self.poll()
            if outcome is not None:
                self.task = None
                return (*outcome, time.monotonic() - self.started)

    def restart(self) -> None:
        self.stop()
        self._start()

    def stop(self) -> None:
        if self.process.is_alive():
            self.process.terminate()
            self.process.join(STOP_GRACE)
        if self.process.is_alive():
            self.process.kill()
            self.process.join()
        self.conn.close()

    def submit(self, task: Task, seconds: float) -> None:
        self.conn.send(task)
        self.task, self.started, self.bound, self.granted = task, time.monotonic(), seconds, 0.0
        self.deadline = self.started + seconds
        self._counts, self._own, self._waits = task_counts(self.process.pid), 0.0, {}
        self.read_at = self.started

    def wakeup(self) -> float:
        """When the parent must look at this slot again: its deadline, or the next read of its tree's counts."""
        return min(self.deadline, self.read_at + READ_EVERY)

    def read_due(self) -> bool:
        return self.task is not None and time.monotonic() - self.read_at >= READ_EVERY

    def read_counts(self) -> float | None:
        """Read the scheduler's counts of the worker's tree now and keep each task's wait since the task was sent:
        the student's process waits for a processor and then ends, before the worker answers, and what it waited
        must still count.  The tree's processor time since the task was sent, or None where it cannot be read."""
        self.read_at = time.monotonic()
        now = task_counts(self.process.pid)
        if now is None or self._counts is None:
            return None
        (waits, cpu), (before, cpu_before) = now, self._counts
        for tid, seconds in waits.items():
            self._waits[tid] = max(self._waits.get(tid, 0.0), seconds - before.get(tid, 0.0))
        return cpu - cpu_before

    def _grant(self, seconds: float) -> None:
        """Move the task's deadline on by ``seconds`` of the machine's load, within the grace."""
        grant = max(0.0, min(seconds, LOAD_GRACE * self.bound - self.granted))
        self.granted += grant
        self.deadline += grant

    def _own_wait(self) -> float:
        """How long the worker's tree (the worker, its warm process, the student's process) waited for a processor
        since the task was sent, beyond what was granted for that already: the smaller of one task's longest wait
        and the tree's wall time off a processor (as ``Child`` reads a call's), 0 where it cannot be read or is
        within the counters' noise.  A task that ended counts with its wait at the last read (``read_counts``)."""
        cpu = self.read_counts()
        if cpu is None:  # else the tree had tasks to read, and their waits are kept
            return 0.0
        excess = excess_wait(time.monotonic() - self.started, cpu, max(self._waits.values()), self._own) or 0.0
        self._own += excess
        return excess

    def waitables(self) -> list:
        return [self.conn, self.process.sentinel]

    def poll(self) -> tuple[str, object] | None:
        """``(kind, payload)`` once the worker answered, died or ran out of time; None while it works (its tree's
        counts read when a read is due, ``read_counts``)."""
        if self.read_due():
            self.read_counts()
        if self.conn.poll():
            try:
                message = self.conn.recv()
            except (EOFError, OSError):
                pass
            else:
                if message[0] != "grace":
                    return message
                self._grant(message[1])
                return None
        elif self.process.is_alive():
            if self.task is None or time.monotonic() < self.deadline:
                return None
            if self.granted < LOAD_GRACE * self.bound:
                self._grant(self._own_wait())
                if time.monotonic() < self.deadline:
                    return None
            spent = self.granted >= LOAD_GRACE * self.bound
            self.restart()
            if spent:
                return "busy", (f"the machine was too busy to grade this submission within {self.bound:g} s per "
                                f"student and {self.granted:.0f} s more for its load")
            return "timeout", self.granted
        self.process.join(1)
        code = self.process.exitcode
        self.killed = code is not None and code < 0
        self.restart()
        return "crashed", f"the grading process ended with exit code {code}"


def run_pool(tasks: list[Task], jobs: int, limits: Limits, mode: SandboxMode, problems: tuple[int, ...],
              student_timeout: float, done) -> None:
    """Grade ``tasks`` on ``jobs`` workers; ``done(task, kind, payload, seconds)`` is called in this process."""
    context = multiprocessing.get_context("spawn")
    pending = deque(tasks)
    slots = [Slot(context, index + 1, limits, mode, problems) for index in range(min(jobs, len(tasks)))]
    try:
        while pending or any(s.task for s in slots):
            for slot in slots:
                if slot.ready and slot.task is None and pending:
                    try:
                        slot.submit(pending[0], student_timeout)
                        pending.popleft()
                    except OSError:  # the idle worker died: start another
                        slot.restart()
            busy = [s for s in slots if s.task is not None]
            timeout = max(0.0, min(s.wakeup() for s in busy) - time.monotonic()) if busy else None
            wait([w for s in slots if s.task is not None or not s.ready for w in s.waitables()], timeout)
            for slot in slots:
                if not slot.ready:
                    if slot.conn.poll() or not slot.process.is_alive():
                        kind, payload = slot.poll() or ("crashed", "no answer")
                        if kind == "crashed" and slot.killed and slot.kills_while_starting < START_KILLS:
                            slot.kills_while_starting += 1  # killed from outside while starting: poll started another
                            continue
                        if kind != "ready":
                            raise RuntimeError(f"a grading worker could not start: {payload}")
                        slot.ready = True
                    continue
                if slot.task is None:
                    continue
                task, started = slot.task, slot.started
                outcome = slot.poll()
                if outcome is not None:
                    seconds = time.monotonic() - started
                    slot.task = None
                    if slot.ready and pending:  # the next student first: it is graded while this one is recorded
                        try:
                            slot.submit(pending[0], student_timeout)
                            pending.popleft()
                        except OSError:
                            slot.restart()
                    done(task, *outcome, seconds)
    finally:
        for slot in slots:
            slot.stop()


def stopped_reports(task: Task, status: Status, message: str, seconds: float) -> list[ProblemReport]:
    """Reports for a student whose grading the batch stopped after ``seconds``: every check with ``status``."""
    from .. import __version__
    from ..checking import checks_of
    from ..problems import problem_module
    from ..runner import not_run

    reports = []
    for number in task.problems:
        module = problem_module(number)
        results = tuple(not_run(spec, number, status, message) for spec in checks_of(module))
        reports.append(ProblemReport(number, module.TITLE, results, seed=task.entry.seed,
                                     duration=seconds / len(task.problems), submission=str(task.entry.path),
                                     grader_version=__version__))
    return reports



def _main(argv: list[str]) -> None:
    """A worker started as a subprocess (``python -m grader.batch.pool FD ARGS``)."""
    import base64
    import pickle
    from multiprocessing.connection import Connection

    conn = Connection(int(argv[1]))
    _serve(conn, *pickle.loads(base64.b64decode(argv[2])))


if __name__ == "__main__":
    _main(sys.argv)
