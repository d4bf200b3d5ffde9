"""What the students' system-call filter and fresh session keyring cost: the same gradings with the worker's runtime
as it is and with a copy whose filter and keyring are left out, taken in turns so that both see the same machine.

    python benchmarks/bench_filter.py [--runs 15] [--process]

Prints the median (and min/max) of:

* `grade problem-6` on the reference in this process (a fresh worker: start, confinement, imports, every check);
* a worker forked from a batch slot's warm process, until it said ready (the fork, its confinement);
* one system call (``getppid``) in a loop of a child process, with the filter installed and without;
* joining the fresh keyring and installing the filter, in a child forked from a process that loaded ctypes (as the
  worker has, for Landlock, by then).

``--process``: plain processes instead of bubblewrap (as root, the Python must be one that an unprivileged uid can
read).  Run it on an otherwise quiet machine.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from grader.loader import cleanup, materialize  # noqa: E402
from grader.runner import grade_problem  # noqa: E402
from grader.workers import Fresh  # noqa: E402
from grader.sandbox import Child, launch, plain_mode, sandbox_mode  # noqa: E402
from grader.sandbox.zygote import Zygote, warm_modules  # noqa: E402
from tests.submissions import copy_reference  # noqa: E402

#: appended to a copy of the runtime's seccomp.py: the worker then neither joins a keyring nor installs the filter
NO_FILTER = ("\n\ndef install(libc=None, arch=None):\n    return {}\n\n\n"
             "def join_fresh_session_keyring(libc=None, arch=None):\n    return 0\n")
#: getppid calls timed in one child
CALLS = 200_000
LOOP = f"""
import os, sys, time
sys.path.insert(0, sys.argv[1])
if sys.argv[2] == "filtered":
    import seccomp
    seccomp.install()
start = time.perf_counter()
for _ in range({CALLS}):
    os.getppid()
print(time.perf_counter() - start)
"""


SETUP = f"""
import ctypes, os, sys, time
sys.path.insert(0, sys.argv[1])
import seccomp
libc = ctypes.CDLL(None, use_errno=True)
libc.syscall.restype = ctypes.c_long
for _ in range(int(sys.argv[2])):
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:
        start = time.perf_counter()
        seccomp.join_fresh_session_keyring(libc)
        joined = time.perf_counter()
        seccomp.install(libc)
        os.write(write, f"{{joined - start}} {{time.perf_counter() - joined}}".encode())
        os._exit(0)
    os.close(write)
    print(os.read(read, 100).decode())
    os.close(read)
    os.waitpid(pid, 0)
"""


def unfiltered_runtime(base: Path) -> Path:
    runtime = base / "runtime"
    shutil.copytree(launch.runtime_dir(), runtime)
    with open(runtime / "seccomp.py", "a", encoding="utf-8") as handle:
        handle.write(NO_FILTER)
    launch._make_readable(runtime)
    return runtime


def summary(times: list[float], unit: float = 1e3, name: str = "ms") -> str:
    return (f"median {statistics.median(times) * unit:8.2f} {name}  (min {min(times) * unit:.2f}, "
            f"max {max(times) * unit:.2f})")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    parser.add_argument("--process", action="store_true", help="plain processes instead of bubblewrap")
    args = parser.parse_args()
    mode = plain_mode("benchmark") if args.process else sandbox_mode("bwrap")
    filtered = launch.runtime_dir()
    with tempfile.TemporaryDirectory(prefix="grader-bench-filter-") as base:
        base = Path(base)
        base.chmod(0o755)
        runtimes = {"filter": filtered, "no filter": unfiltered_runtime(base)}
        reference = copy_reference(base / "ref")
        grading = {name: [] for name in runtimes}
        forks = {name: [] for name in runtimes}
        zygotes, staged = {}, {}
        try:
            for name, runtime in runtimes.items():
                launch.runtime_dir = lambda runtime=runtime: runtime
                zygotes[name] = Zygote(mode=mode, preload=warm_modules([6]))
                zygotes[name].start()
                staged[name] = materialize(reference, zygotes[name].staging)
            for run in range(args.runs + 1):  # the first round warms up
                for name, runtime in runtimes.items():
                    launch.runtime_dir = lambda runtime=runtime: runtime
                    start = time.perf_counter()
                    report = grade_problem(6, reference, seed=1, workers=Fresh(mode=mode))
                    took = time.perf_counter() - start
                    assert report.score == report.auto_max_score, report.results
                    assert ("system-call filter" in report.sandbox) == (name == "filter"), report.sandbox
                    start = time.perf_counter()
                    with Child(staged[name].path, zygote=zygotes[name]) as child:
                        child.ready()
                        forked = time.perf_counter() - start
                    if run:
                        grading[name].append(took)
                        forks[name].append(forked)
        finally:
            for submission in staged.values():
                cleanup(submission)
            for zygote in zygotes.values():
                zygote.close()
        loops = {name: [] for name in ("filtered", "unfiltered")}
        for run in range(args.runs):
            for name in loops:
                done = subprocess.run([sys.executable, "-I", "-c", LOOP, str(filtered), name], capture_output=True,
                                      text=True, check=True)
                loops[name].append(float(done.stdout) / CALLS)
        done = subprocess.run([sys.executable, "-I", "-c", SETUP, str(filtered), str(args.runs * 4)],
                              capture_output=True, text=True, check=True)
        setup = [tuple(map(float, line.split())) for line in done.stdout.splitlines()]
    print(f"mode: {mode.kind}, {args.runs} runs each, taken in turns")
    for name in runtimes:
        print(f"grade problem-6, {name:9}: {summary(grading[name])}")
    for name in runtimes:
        print(f"warm fork ready, {name:9}: {summary(forks[name])}")
    for name, times in loops.items():
        print(f"getppid, {name:10}:        {summary(times, 1e9, 'ns')}")
    print(f"join the fresh keyring:            {summary([joined for joined, _ in setup])}")
    print(f"install the filter:                {summary([installed for _, installed in setup])}")
    difference = statistics.median(grading["filter"]) - statistics.median(grading["no filter"])
    print(f"filter's cost on grade problem-6: {difference * 1e3:+.1f} ms (difference of the medians)")
    difference = statistics.median(forks["filter"]) - statistics.median(forks["no filter"])
    print(f"filter's cost on a warm fork:     {difference * 1e3:+.1f} ms (difference of the medians)")


if __name__ == "__main__":
    main()
