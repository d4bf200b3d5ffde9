"""What the tests read of the machine's processes through /proc: a process's descendants, whether it still runs,
its command line, and the processes a test leaves behind; and how a test starts a process that it interrupts."""

from __future__ import annotations

import os
import signal
from pathlib import Path

__all__ = ["descendants", "alive", "cmdline", "processes_with", "new_processes", "default_ctrl_c"]


def default_ctrl_c() -> None:
    """For ``subprocess.Popen(preexec_fn=...)``: the child starts with SIGINT's default action, whatever this
    process inherited.  A non-interactive shell starts its background jobs (``pytest ... &``) with SIGINT ignored,
    every process they start inherits that, and Python leaves an ignored SIGINT ignored (it raises
    KeyboardInterrupt only when SIGINT had its default action at start-up): a test that sends SIGINT would then
    test how pytest was started, not the program."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def descendants(pid: int) -> list[int]:
    """Every process below ``pid`` (children of all its threads, recursively); ones that end meanwhile are left out."""
    found, todo = [], [pid]
    while todo:
        for task in Path(f"/proc/{todo.pop()}/task").glob("*"):
            try:
                children = [int(c) for c in (task / "children").read_text().split()]
            except OSError:  # ended meanwhile
                continue
            found += children
            todo += children
    return found


def alive(pid: int | str) -> bool:
    """Whether ``pid`` exists and is neither a zombie nor dead."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] not in ("Z", "X")
    except (OSError, IndexError):
        return False


def cmdline(pid: int | str) -> bytes:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return b""


def processes_with(text: str) -> list[int]:
    """The live processes whose command line holds ``text``."""
    return [int(p) for p in os.listdir("/proc") if p.isdigit() and text.encode() in cmdline(p) and alive(p)]


def new_processes(before: set[int]) -> list[int]:
    """Live descendants of this process that were not there ``before`` (e.g. not multiprocessing's helpers)."""
    return [p for p in descendants(os.getpid()) if p not in before and alive(p)]
