"""What the diagnosis engine costs a grading: nothing on a passing one, at most 10% on a failing one.

    python benchmarks/bench_diagnosis.py [--runs 5]

Grades, in one process and as ``grade batch`` grades (a worker forked from a warm slot, the live reference), the
reference on a few problems (every check passes: the engine is never asked) and mistakes that fail checks no
catalogue explains (the engine's development set, ``tests/engine/mistakes.toml``, and the planted fixed-step loops),
each with the engine on and off, in turns (on, off, on, off, ...) so that the machine's speed of the moment weighs
on both alike.  Every grading has a fresh in-memory reference (no result of an earlier grading is reused; the
reference's persisted long simulations and fixed-step runs are read from the disk cache, as they are after a
course's first student).  Prints each case's median wall time on and off and their ratio, and the ratio of the
sums of the medians for the passing and the failing gradings (targets: 1.00 within the noise, at most 1.10).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

#: the passing gradings: the reference on these problems
PASSING = (6, 8, 26, 37, 44)
#: the planted mistakes of tests/planted/ that the engine names (besides the development set)
PLANTED = ("p37-euler-at-a-large-step", "p42-euler-at-a-large-step", "p44-euler-at-a-large-step")
#: the failing gradings may cost at most this much more with the engine
FAILING_TARGET = 1.10
SEED = 1


def cases():
    """``(label, problem, submission)`` of the passing and the failing gradings."""
    from tests.submissions import Planted, build_planted, copy_reference, planted_mistakes

    folder = Path(tempfile.mkdtemp(prefix="bench-diagnosis-"))
    reference = copy_reference(folder / "reference")
    passing = [(f"reference, problem {n}", n, reference) for n in PASSING]
    entries = tomllib.loads((ROOT / "tests" / "engine" / "mistakes.toml").read_text())["mistake"]
    failing = []
    for e in entries:
        mistake = Planted(e["name"], e["problem"], e["file"], e["old"], e["new"], e["check"])
        failing.append((e["name"], e["problem"], build_planted(mistake, folder / e["name"])))
    for mistake in planted_mistakes():
        if mistake.name in PLANTED:
            failing.append((mistake.name, mistake.problem, build_planted(mistake, folder / mistake.name)))
    return passing, failing


def timed(grade, problem, submission, on: bool) -> float:
    import grader.diagnosis as engine
    from grader.oracle import LiveOracle

    engine.ENABLED = on
    start = time.perf_counter()
    grade(problem, submission, oracle=LiveOracle())
    return time.perf_counter() - start


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5, help="timed gradings of each case, with and without")
    args = parser.parse_args()
    from grader import grade_problem
    from grader.sandbox import Limits, sandbox_mode
    from grader.sandbox.zygote import Zygote, warm_modules

    passing, failing = cases()
    problems = sorted({p for _, p, _ in passing + failing})
    print(f"{'case':<44}{'on':>9}{'off':>9}{'on/off':>8}")
    sums = {}
    with Zygote(Limits(), sandbox_mode(), warm_modules(problems)) as slot:
        slot.start()

        def grade(problem, submission, oracle):
            return grade_problem(problem, submission, seed=SEED, zygote=slot, oracle=oracle)

        for group, items in (("passing", passing), ("failing", failing)):
            total_on = total_off = 0.0
            for label, problem, submission in items:
                for on in (True, False):  # warm-up: imports, the disk cache of the reference's long runs
                    timed(grade, problem, submission, on)
                times = {True: [], False: []}
                for _ in range(args.runs):
                    for on in (True, False):
                        times[on].append(timed(grade, problem, submission, on))
                on, off = statistics.median(times[True]), statistics.median(times[False])
                total_on, total_off = total_on + on, total_off + off
                print(f"{label[:43]:<44}{on:>8.3f}s{off:>8.3f}s{on / off:>8.3f}")
            sums[group] = total_on / total_off
            print(f"{'  all ' + group + ' gradings (sum of medians)':<44}{total_on:>8.3f}s{total_off:>8.3f}s"
                  f"{sums[group]:>8.3f}")
    print(f"passing gradings: on/off {sums['passing']:.3f} (the engine is not asked: 1 within the noise)")
    verdict = "ok" if sums["failing"] <= FAILING_TARGET else "over the target"
    print(f"failing gradings: on/off {sums['failing']:.3f} (target at most {FAILING_TARGET:.2f}): {verdict}")
    return 0 if sums["failing"] <= FAILING_TARGET else 1


if __name__ == "__main__":
    raise SystemExit(main())
