"""Throughput of ``grade batch`` on the generated test class, at several ``--jobs`` in the same run.

    python benchmarks/bench_batch.py [--jobs 1 2] [--problems 6]

Builds the class of tests/batch_fixtures.py (correct work, the template, planted mistakes, hostile and slow
submissions; folders, zip archives and notebooks), grades it from scratch once per ``--jobs`` value, and prints
the submissions graded per minute, the speed-up over the first value, and what each hostile submission cost
against its limits.
"""

from __future__ import annotations

import argparse
import sqlite3
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from grader.batch import run_batch  # noqa: E402
from grader.gradebook import GRADEBOOK_NAME  # noqa: E402
from grader.sandbox import Limits, sandbox_mode  # noqa: E402
from tests.batch_fixtures import BATCH_LIMITS, build_class  # noqa: E402


def student_costs(results: Path) -> dict[str, tuple[float, str]]:
    with sqlite3.connect(results / GRADEBOOK_NAME) as db:
        return {name: (duration, outcome) for name, duration, outcome in db.execute(
            "SELECT st.name, sum(s.duration), s.outcome FROM submissions s JOIN students st ON st.id = s.student_id "
            "GROUP BY st.name")}


#: time allowed past the per-student bound to stop the worker and record the timed-out student
STOP_SLACK = 1.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--problems", type=int, nargs="+", default=[6])
    args = parser.parse_args()
    limits = Limits(call_timeout=BATCH_LIMITS["call_timeout"], import_timeout=BATCH_LIMITS["import_timeout"])
    bound = BATCH_LIMITS["student_timeout"]
    with tempfile.TemporaryDirectory() as scratch:
        scratch = Path(scratch)
        expected = build_class(scratch / "class")
        kinds = {kind: sum(1 for e in expected.values() if e.kind == kind) for kind in
                 dict.fromkeys(e.kind for e in expected.values())}
        print(f"class: {len(expected)} submissions ({', '.join(f'{n} {k}' for k, n in kinds.items())}); "
              f"problems {args.problems}; sandbox {sandbox_mode().kind}")
        print(f"limits: {limits.call_timeout:g} s per call, {limits.import_timeout:g} s per import, "
              f"{bound:g} s per student, {limits.memory_mb} MB")
        rates = {}
        for jobs in args.jobs:
            out = scratch / f"results-{jobs}"
            start = time.perf_counter()
            report = run_batch(scratch / "class", out, problems=args.problems, jobs=jobs, limits=limits,
                               student_timeout=bound, progress=False, export=False)
            seconds = time.perf_counter() - start
            assert report.graded == len(expected) and not report.not_graded, report
            rates[jobs] = 60 * report.graded / seconds
            costs = student_costs(out)
            work = sum(duration for duration, _ in costs.values())
            print(f"--jobs {jobs}: {report.graded} submissions in {seconds:.1f} s = {rates[jobs]:.1f} submissions/min"
                  f" (grading time {work:.1f} s: workers busy {100 * work / (jobs * seconds):.0f}% of the wall time)")
        first = args.jobs[0]
        for jobs in args.jobs[1:]:
            print(f"speed-up --jobs {jobs} / --jobs {first}: {rates[jobs] / rates[first]:.2f}x")
        print("hostile and slow submissions (last run): grading time against the limits")
        for name, (seconds, outcome) in sorted(costs.items()):
            if expected[name].kind in ("hostile", "slow"):
                print(f"  {name:32s} {seconds:5.1f} s  {outcome:8s} (bound {bound:g} s)")
        worst = max(seconds for name, (seconds, _) in costs.items() if expected[name].kind in ("hostile", "slow"))
        print(f"most expensive: {worst:.1f} s (per-student bound {bound:g} s; the worker is stopped at the bound "
              f"and its result written within {STOP_SLACK:g} s): {'ok' if worst <= bound + STOP_SLACK else 'OVER'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
