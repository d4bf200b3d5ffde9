"""The benchmarks run: a small class through ``benchmarks/bench_batch.py`` prints its figures, and a mistyped problem
is a usage error before anything is built.  (The figures themselves are measurements, not asserted here.)"""

import re
import subprocess
import sys

from .submissions import ROOT

BENCH_BATCH = ROOT / "benchmarks" / "bench_batch.py"


def _bench(*args, timeout=300):
    return subprocess.run([sys.executable, str(BENCH_BATCH), *args], capture_output=True, text=True, timeout=timeout,
                          cwd=ROOT)


def test_bench_batch_prints_rates_cpu_and_the_bound_of_the_speed_up():
    done = _bench("--students", "4", "--jobs", "1", "2", "--cluster", "0", "--problems", "6", "--profile")
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    rows = {m.group(1): m for m in re.finditer(
        r"^(--jobs \d)\s+([\d.]+) s\s+([\d.]+)/min\s+[\d.]+ s\s+[\d.]+ s\s+[\d.]+ s\s+([\d.]+) s\s+([\d.]+)$",
        done.stdout, re.MULTILINE)}
    assert set(rows) == {"--jobs 1", "--jobs 2"}, done.stdout
    for row in rows.values():
        assert float(row.group(3)) > 0 and float(row.group(4)) > 0 and float(row.group(5)) > 0
    assert "speed-up --jobs 2 / --jobs 1" in done.stdout
    assert re.search(r"--jobs 1 kept [\d.]+ cores busy: on \d+ cores --jobs 2 can be at most [\d.]+x faster",
                     done.stdout), done.stdout
    profile = done.stdout[done.stdout.index("where one whole submission's"):]
    for line in ("waiting for the student's worker", "the reference's probes in the grader",
                 "the grader's own work outside the worker", "slowest problems: 6 "):
        assert line in profile, profile
    alone = re.search(r"the students' code alone \(3 more reference submissions .* its (\d+) calls replayed .*\): "
                      r"([\d.]+) CPU-s \(median; [\d.]+-[\d.]+\)\n"
                      r"  their gradings took ([\d.]+) CPU-s .*: the students' code is (\d+)% of a grading .*\n"
                      r"  heaviest probes: problem_06\.\w+ [\d.]+ s.*\n"
                      r"  even a grader that cost nothing would grade at most ([\d.]+) such students/min on \d+ cores",
                      profile)
    assert alone, profile
    assert int(alone.group(1)) > 0 and float(alone.group(3)) > 0 and float(alone.group(5)) > 0, profile


def test_bench_batch_refuses_a_problem_without_checks_and_expands_ranges():
    for words, message in ((["23"], "problem 23 has no checks"), (["x"], "neither a number nor a range"),
                           (["23-23"], "no graded problem in 23-23")):
        done = _bench("--problems", *words, timeout=60)
        assert done.returncode == 2 and message in done.stderr, (words, done.stderr)
    sys.path.insert(0, str(ROOT / "benchmarks"))
    try:
        import argparse

        import bench_batch
        chosen = bench_batch.chosen_problems(argparse.ArgumentParser(), ["6-36"])
    finally:
        sys.path.remove(str(ROOT / "benchmarks"))
    assert chosen[0] == 6 and chosen[-1] == 36 and len(chosen) == 29 and 23 not in chosen and 29 not in chosen


def test_bench_similarity_prints_its_time_and_ranks_the_copied_folders_first():
    done = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_similarity.py"), "--students", "8",
                           "--recording", "0"], capture_output=True, text=True, timeout=600, cwd=ROOT)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    timing = re.search(r"^grade similarity: ([\d.]+) s wall, ([\d.]+) CPU-s \(its processes\) for 8 students "
                       r"\(28 pairs, (\d+) with any evidence, code of 8 compared\); target under 60 s: (met|NOT met)$",
                       done.stdout, re.MULTILINE)
    assert timing and float(timing.group(1)) > 0 and float(timing.group(2)) > 0, done.stdout
    assert "the 3 copied folders rank [1, 2, 3] of" in done.stdout, done.stdout


def test_bench_diagnosis_prints_the_engines_cost_on_passing_and_failing_gradings():
    done = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_diagnosis.py"), "--runs", "1", "--cases",
                           "problem 6", "engine-inverse-rate-matrix", "engine-state-row-bar"],
                          capture_output=True, text=True, timeout=600, cwd=ROOT)
    assert done.returncode in (0, 1), done.stdout[-2000:] + done.stderr[-2000:]
    assert re.search(r"^reference, problem 6\s+[\d.]+s\s+[\d.]+s\s+[\d.]+\s+0\.000s\s+0\.0%\s+0$", done.stdout, re.M)
    assert re.search(r"^engine-inverse-rate-matrix\s+[\d.]+s\s+[\d.]+s\s+[\d.]+\s+[\d.]+s\s+[\d.]+%\s+[1-9]",
                     done.stdout, re.M), done.stdout
    assert "passing gradings: the engine was asked 0 times" in done.stdout
    assert re.search(r"failing gradings: the engine's share [\d.]+% of the time", done.stdout), done.stdout
