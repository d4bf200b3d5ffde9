"""How long a worker waited for a processor: the part of a call's wall time that is the machine's, not the code's.

A call's time limit is a wall-clock deadline, which on a busy machine (a batch on every core, a laptop compiling in
the background) also counts the time the student's code was ready to run and waited for a core.  Linux counts
that time per task (``/proc/<pid>/task/<tid>/schedstat``, its second field: nanoseconds spent runnable on a run
queue), so the parent can read it for the worker's whole tree of processes and threads, from outside the sandbox,
without trusting anything the worker says.  The child's handle (``grader.sandbox.child``) moves a call's deadline
on by what its worker waited, within a bound, and files a call whose worker waited most of its limit as the
machine's fault rather than the student's time-out.

What moves a deadline is the smaller of two figures over the call: the longest wait of one task of the tree (its
threads, its children's), and the wall time the tree did not spend on a processor (wall time less the processor time
of all its tasks, with that of children that ended).  A single-threaded worker on a busy machine is granted its
wait; code that sleeps waits for no processor and is granted nothing; code that keeps the cores busy with threads or
processes of its own, so that its main thread waits for them, spends the processor time that the second figure
takes off, and is granted nothing either.  Elsewhere (macOS, Windows, a kernel without the counters) there is no
figure and deadlines are plain wall clock.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

__all__ = ["Queueing", "waited", "task_counts", "excess_wait", "LEAST_WAIT", "MAX_TASKS"]

#: the most tasks (processes and threads) of a tree read for one figure: a tree larger than this (a fork bomb) is
#: read in part
MAX_TASKS = 512
_TICKS = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100
#: a wait for a processor shorter than this [s] does not move a deadline (the counters' and the reads' own noise)
LEAST_WAIT = 0.05


@dataclass(frozen=True)
class Queueing:
    """What the scheduler counted for a worker's tree at one moment: the longest wait of one task for a processor
    and the processor time of the whole tree (its tasks', and that of its children that ended and were reaped),
    both in seconds."""

    wait: float
    cpu: float


def _read(path: str) -> str | None:
    try:
        return Path(path).read_text()
    except OSError:  # the task ended, or /proc is not there
        return None


def _reaped(process: int) -> float:
    """The processor time of ``process``'s children that ended and were reaped (``cutime`` and ``cstime``)."""
    stat = _read(f"/proc/{process}/stat")
    fields = stat.rpartition(")")[2].split() if stat else []
    try:
        return (int(fields[13]) + int(fields[14])) / _TICKS
    except (IndexError, ValueError):
        return 0.0


def excess_wait(wall: float, cpu: float, wait: float, granted: float) -> float | None:
    """How much more than ``granted`` the machine kept a tree waiting over ``wall`` seconds in which its tasks used
    ``cpu`` seconds of a processor and the longest wait of one of them was ``wait``: the smaller of that wait and the
    wall time off a processor.  None when it is no more than the counters' noise (``LEAST_WAIT``)."""
    excess = min(wait, wall - cpu) - granted
    return excess if excess >= LEAST_WAIT else None


def waited(pid: int | None) -> Queueing | None:
    """The scheduler's counts for the process tree rooted at ``pid`` over the tasks alive now; ``None`` where they
    cannot be read (not Linux, no such process, no scheduler statistics)."""
    counts = task_counts(pid)
    if counts is None:
        return None
    waits, cpu = counts
    return Queueing(max(waits.values()), cpu)


def task_counts(pid: int | None) -> tuple[dict[int, float], float] | None:
    """The wait for a processor of each task of the process tree rooted at ``pid`` alive now, by its thread id,
    and the processor time of the whole tree (as ``Queueing.cpu``); ``None`` where they cannot be read.  A wait
    over some time is then a task's own difference, which a task born in between counts from 0."""
    if pid is None or pid <= 0 or os.name != "posix":
        return None
    waits: dict[int, float] = {}
    cpu, seen, stack = 0.0, 0, [pid]
    while stack and seen < MAX_TASKS:
        process = stack.pop()
        try:
            tasks = os.listdir(f"/proc/{process}/task")
        except OSError:
            continue
        cpu += _reaped(process)
        for tid in tasks:
            seen += 1
            if seen > MAX_TASKS:
                break
            stat = _read(f"/proc/{process}/task/{tid}/schedstat")
            fields = stat.split() if stat else []
            if len(fields) >= 2 and fields[0].isdigit() and fields[1].isdigit() and tid.isdigit():
                cpu += int(fields[0]) / 1e9
                waits[int(tid)] = int(fields[1]) / 1e9
            children = _read(f"/proc/{process}/task/{tid}/children")
            if children:
                stack.extend(int(child) for child in children.split() if child.isdigit())
    return (waits, cpu) if waits else None
