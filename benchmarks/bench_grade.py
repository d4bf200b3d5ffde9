"""Wall time of `grade problem-N` on a finished submission (the reference), next to a bare
`python -c "import numpy"` measured in the same run.

    python benchmarks/bench_grade.py [--runs 7] [--problems 6 15 31 32 37 38 44 46]

Prints the median (and min/max) of each, and the ratio to the baseline.  The first run of each command is a
warm-up (it fills the reference cache, e.g. the reference's long simulations) and is not counted.  The graded
submission is the reference itself, so a simulation problem includes the reference's own simulations run as the
student's (in the sandbox), once per grading.
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
#: targets from the design: non-simulation problems 1 s, kinematic trees 1.5 s, simulations 3 s; the robot's and
#: walker's simulations (exercise VI), the bar's (problem 44) and problem 46 4 s; the ball's simulation (42) and the
#: symbolic answers of 45 (sympy) 3 s
TARGETS = {6: 1.0, 7: 3.0, 15: 3.0, 12: 3.0, 31: 1.5, 32: 1.5, 37: 4.0, 38: 4.0, 42: 3.0, 44: 4.0, 45: 3.0, 46: 4.0}


#: the grader of this checkout (not whichever copy the ``grade`` script was installed from)
ENV = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH", "")]))}


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


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--problems", type=int, nargs="+", default=[6, 15, 31, 32, 37, 38, 44, 46])
    args = parser.parse_args()
    sys.path.insert(0, str(ROOT))
    grade = [sys.executable, "-m", "grader.cli"]  # what the `grade` script runs, from this checkout
    from grader import problems
    from grader.sandbox import sandbox_mode

    available = {p.number for p in problems()}
    print(f"machine: {os.cpu_count()} cores; sandbox: {sandbox_mode().note}; {args.runs} runs each")
    base = timed([sys.executable, "-c", "import numpy"], args.runs)
    base_median = statistics.median(base)
    print(f"{'command':<44}{'median':>9}{'min':>9}{'max':>9}{'/ numpy':>10}{'target':>9}")
    label = 'python -c "import numpy"'
    print(f"{label:<44}{base_median:>8.3f}s{min(base):>8.3f}s{max(base):>8.3f}s{1:>10.1f}")
    status = 0
    for number in args.problems:
        if number not in available:
            print(f"{'grade problem-' + str(number):<44}  (no checks for this problem yet)")
            continue
        times = timed([*grade, f"problem-{number}", "--submission", str(ROOT / "reference"), "--seed", "1"],
                      args.runs)
        median = statistics.median(times)
        target = TARGETS.get(number, 1.0)
        verdict = "ok" if median <= target else "OVER"
        status |= median > target
        print(f"{'grade problem-' + str(number) + ' (reference)':<44}{median:>8.3f}s{min(times):>8.3f}s"
              f"{max(times):>8.3f}s{median / base_median:>10.1f}{target:>7.1f}s {verdict}")
    return status


if __name__ == "__main__":
    sys.exit(main())
