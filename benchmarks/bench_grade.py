"""Wall time of `grade problem-N` on a finished submission (the reference), next to a bare
`python -c "import numpy"` measured in the same run.

    python benchmarks/bench_grade.py [--runs 7] [--whole-runs 5] [--problems 2 3 7 15 16 25 37 38 44 46]

Prints, in one run, the median (and min/max) of:

* `grade problem-6`, and its ratio to the bare numpy import (target: at most 3 times);
* a whole submission: `grade problem-6 ... problem-36` in one command, every problem of 6-36 that has checks
  (29 problems; target 4 s), with the default workers (two on two cores or more) and, as the baseline, with
  `--workers 1`;
* each of `--problems` on its own (default 7, 15, 16 and 25, target 2.5 s each; the MuJoCo models of 2 and 3,
  3 s each; and the simulations of Exercises VI-VII, 37, 38, 44 and 46, 4 s each, with the reference's
  simulations cached).

The first run of each command is a warm-up (it fills the reference cache, e.g. the reference's long simulations)
and is not counted.  The graded submission is the reference itself, so a simulation problem includes the
reference's own simulations run as the student's (in the sandbox), once per grading.  The seed is fixed
(`--seed 1`) so that every run grades the same inputs; nothing is cached between runs but the reference's
persisted results.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: at most this many times the bare numpy import, for `grade problem-6`
RATIO_TARGET = 3.0
#: seconds for the whole submission (problems 6-36)
WHOLE_TARGET = 4.0
#: seconds for a single problem of ``--problems``: 2.5 s, and more for the simulations (the robot's, the walker's,
#: the bar's and problem 46: 4 s; the ball of 42 and the symbolic answers of 45, with sympy: 3 s; the MuJoCo
#: models of 2 and 3: 3 s)
SINGLE_TARGET = 2.5
TARGETS = {2: 3.0, 3: 3.0, 37: 4.0, 38: 4.0, 42: 3.0, 44: 4.0, 45: 3.0, 46: 4.0}
WHOLE = range(6, 37)

#: the grader of this checkout (not whichever copy the ``grade`` script was installed from), its modules compiled
#: once (in the warm-up run) as in an installed grader, whatever PYTHONDONTWRITEBYTECODE says
ENV = {**{k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"},
       "PYTHONPATH": os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH", "")]))}


def timed(argv: list[str], runs: int) -> list[float]:
    subprocess.run(argv, capture_output=True, cwd=tempfile.gettempdir(), env=ENV)  # warm-up
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        done = subprocess.run(argv, capture_output=True, cwd=tempfile.gettempdir(), env=ENV)
        times.append(time.perf_counter() - start)
        if done.returncode not in (0, 1):
            raise SystemExit(f"{' '.join(argv)} failed ({done.returncode}):\n{done.stderr.decode()[-2000:]}")
    return times


def row(label: str, times: list[float], base: float, target: str = "", verdict: str = "") -> str:
    median = statistics.median(times)
    return (f"{label:<46}{median:>8.3f}s{min(times):>8.3f}s{max(times):>8.3f}s{median / base:>9.1f}x"
            f"{target:>9} {verdict}").rstrip()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7, help="timed runs of each single problem and of numpy")
    parser.add_argument("--whole-runs", type=int, default=5, help="timed runs of the whole submission")
    parser.add_argument("--problems", type=int, nargs="*", default=[2, 3, 7, 15, 16, 25, 37, 38, 44, 46])
    args = parser.parse_args()
    grade = [sys.executable, "-m", "grader.cli"]  # what the `grade` script runs, from this checkout
    listed = subprocess.run([*grade, "list"], capture_output=True, text=True, cwd=tempfile.gettempdir(), env=ENV)
    available = {int(line.split()[0]) for line in listed.stdout.splitlines() if line.split()[:1] != []
                 and line.split()[0].isdigit()}
    mode = subprocess.run([sys.executable, "-c", "from grader.sandbox import sandbox_mode; "
                           "print(sandbox_mode().note)"], capture_output=True, text=True, env=ENV).stdout.strip()
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}; sandbox: {mode}")
    print(f"runs: {args.runs} each, {args.whole_runs} of the whole submission (medians; a warm-up run first)")

    def grade_argv(numbers) -> list[str]:
        return [*grade, *(f"problem-{n}" for n in numbers), "--submission", str(ROOT / "reference"), "--seed", "1"]

    base_times = timed([sys.executable, "-c", "import numpy"], args.runs)
    base = statistics.median(base_times)
    print(f"{'command':<46}{'median':>9}{'min':>9}{'max':>9}{'/ numpy':>10}{'target':>9}")
    print(row('python -c "import numpy"', base_times, base))
    status = 0

    times = timed(grade_argv([6]), args.runs)
    ratio = statistics.median(times) / base
    status |= ratio > RATIO_TARGET
    print(row("grade problem-6 (reference)", times, base, f"{RATIO_TARGET:g}x",
              "ok" if ratio <= RATIO_TARGET else "OVER"))

    whole = [n for n in WHOLE if n in available]
    label = f"grade problem-{whole[0]} ... problem-{whole[-1]} ({len(whole)} problems)"
    times = timed(grade_argv(whole), args.whole_runs)
    median = statistics.median(times)
    status |= median > WHOLE_TARGET
    print(row(label, times, base, f"{WHOLE_TARGET:g}s", "ok" if median <= WHOLE_TARGET else "OVER"))
    alone = timed([*grade_argv(whole), "--workers", "1"], args.whole_runs)  # the baseline: one worker
    print(row("  the same with --workers 1", alone, base))
    print(f"  {'default workers / one worker':<44}{median / statistics.median(alone):>8.2f}  "
          f"(the default is {min(2, len(os.sched_getaffinity(0)))} workers for several problems on this machine)")

    for number in args.problems:
        if number not in available:
            print(f"{'grade problem-' + str(number):<46}  (no checks for this problem yet)")
            continue
        times = timed(grade_argv([number]), args.runs)
        median = statistics.median(times)
        target = TARGETS.get(number, SINGLE_TARGET)
        status |= median > target
        print(row(f"grade problem-{number} (reference)", times, base, f"{target:g}s",
                  "ok" if median <= target else "OVER"))
    return int(status)


if __name__ == "__main__":
    sys.exit(main())
