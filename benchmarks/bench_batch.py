"""Whole-course throughput of ``grade batch``: every problem with checks, a class of 40 submissions, graded at
``--jobs 1``, ``--jobs 2`` and on a two-worker Dask ``LocalCluster``, in the same run.

    python benchmarks/bench_batch.py [--students 40] [--jobs 1 2] [--cluster 2] [--problems N|N-M ...] [--profile]

The class (built fresh for the run): copies of the reference (folders, zip archives, notebooks), untouched
templates, planted mistakes drawn from every problem's catalogue, and two hostile submissions (an endless loop in
a call, a submission that tries to kill every process).  Each configuration grades the class from scratch with
the exports (each student's files as they are recorded, the class's at the end), and the figures are printed
with the per-student medians and the ratios between configurations.  ``--profile`` also grades one reference
submission in this process under cProfile and says where its time goes, then replays that submission's calls on
the reference alone in a fresh process: the students' own computations, whose CPU time bounds the rate.
Targets (issue 13): >= 20 students/min at --jobs 2, a speed-up >= 1.8x over --jobs 1, and the cluster within 15%
of --jobs 2.

The machine's speed of the day is printed first: a bare numpy import and a loop of small-array operations (the
kind of work the students' code does), so that runs on different days or machines can be compared.  The CPU time
is read from /proc/stat around each configuration (every process counts, so run it on an otherwise quiet
machine): "cpu/student" is the CPU-seconds a student costs, "cores" the mean number of busy cores.
While a student costs the same CPU time, a batch that keeps c cores busy at one job can be sped up by at most
(cores of the machine) / c.
``--problems 6-36`` grades the graded problems of a range (here the 29 of Exercises II-V).
"""

from __future__ import annotations

import argparse
import contextlib
import os
import random
import sqlite3
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from bench_grade import timed  # noqa: E402
from grader.batch import run_batch  # noqa: E402
from grader.gradebook import GRADEBOOK_NAME  # noqa: E402
from grader.problems import problems as all_problems  # noqa: E402
from grader.sandbox import Limits, sandbox_mode  # noqa: E402
from tests.batch_fixtures import BATCH_LIMITS, notebook_submission, zip_folder  # noqa: E402
from tests.submissions import (build_hostile, build_planted, copy_reference, copy_template,  # noqa: E402
                               planted_mistakes)

HOSTILE = ("infinite_loop_call", "kill_everything")
#: pairs of a grading and the replay of its calls alone (--profile)
REPLAYS = 3


def build_course_class(dest: Path, students: int, seed: int = 13) -> dict[str, str]:
    """``students`` submissions of the whole course into ``dest``; returns each student's kind."""
    rng = random.Random(seed)
    dest.mkdir(parents=True)
    kinds: dict[str, str] = {}
    templates = max(1, students // 10)
    planted = students * 2 // 5
    references = students - templates - planted - len(HOSTILE)
    mistakes = planted_mistakes()
    by_problem: dict[int, list] = {}
    for mistake in mistakes:
        by_problem.setdefault(mistake.problem, []).append(mistake)
    chosen = [rng.choice(items) for _, items in sorted(by_problem.items())]
    rng.shuffle(chosen)
    with tempfile.TemporaryDirectory() as scratch:
        for i in range(references):
            name = f"ref_{i:02d}"
            if i % 8 == 7:
                notebook_submission(dest / name)  # problem 6 as notebooks, the rest from the template
            elif i % 4 == 3:
                folder = copy_reference(Path(scratch) / name)
                zip_folder(folder, dest / f"{name}.zip", top=name)
            else:
                copy_reference(dest / name)
            kinds[name] = "reference" if i % 8 != 7 else "notebook"
        for i in range(templates):
            copy_template(dest / f"template_{i:02d}")
            kinds[f"template_{i:02d}"] = "template"
        for i in range(planted):
            mistake = chosen[i % len(chosen)]
            name = f"planted_{i:02d}_{mistake.name}"
            build_planted(mistake, dest / name)
            kinds[name] = "planted"
        for name in HOSTILE:
            build_hostile(name, dest / f"hostile_{name}")
            kinds[f"hostile_{name}"] = "hostile"
    for name in kinds:  # every copy its own content (hence its own seed)
        path = dest / name if (dest / name).is_dir() else None
        if path is not None and (path / "answers.toml").exists():
            with open(path / "answers.toml", "a") as handle:
                handle.write(f"\n# {name}\n")
    return kinds


def durations(results: Path) -> dict[str, float]:
    with sqlite3.connect(results / GRADEBOOK_NAME) as db:
        return dict(db.execute("SELECT st.name, sum(s.duration) FROM submissions s JOIN students st "
                               "ON st.id = s.student_id GROUP BY st.name"))


#: a fixed workload of small numpy arrays in a Python loop, like the students' code (the machine's compute speed:
#: the numpy import measures mostly start-up and the file cache)
SMALL_ARRAYS = "\n".join([
    "import time", "import numpy as np", "R, w = np.eye(3), np.array([0.1, 0.2, 0.3])", "start = time.perf_counter()",
    "for _ in range(20000):", "    R = R @ np.eye(3) + np.outer(np.cross(w, R[0]), w) * 0",
    "print(time.perf_counter() - start)"])


def small_array_seconds(runs: int = 7) -> float:
    """The median time of ``SMALL_ARRAYS`` in a fresh interpreter (its own loop timed, not the start-up)."""
    import subprocess

    times = []
    for _ in range(runs):
        done = subprocess.run([sys.executable, "-c", SMALL_ARRAYS], capture_output=True, text=True, check=True)
        times.append(float(done.stdout))
    return statistics.median(times)


def busy_cpu_seconds() -> float | None:
    """The machine's busy CPU time since boot (all cores, every process), or None where /proc/stat is missing."""
    try:
        with open("/proc/stat") as handle:
            fields = [int(x) for x in handle.readline().split()[1:]]
    except (OSError, ValueError):
        return None
    # user, nice, system, irq, softirq: not idle, iowait, the hypervisor's steal, nor guest (counted in user)
    return sum(fields[i] for i in (0, 1, 2, 5, 6) if i < len(fields)) / os.sysconf("SC_CLK_TCK")


def run(label: str, scratch: Path, problems: list[int], limits: Limits, **options) -> dict:
    out = scratch / f"results-{label.replace(' ', '-')}"
    cpu = busy_cpu_seconds()
    start = time.perf_counter()
    report = run_batch(scratch / "class", out, problems=problems, limits=limits, progress=False,
                       student_timeout=None, **options)
    seconds = time.perf_counter() - start
    cpu = None if cpu is None else busy_cpu_seconds() - cpu
    if report.graded != report.students or report.not_graded:
        raise SystemExit(f"{label}: {report}")
    per_student = durations(out)
    figures = {"label": label, "seconds": seconds, "rate": 60 * report.graded / seconds,
               "median": statistics.median(per_student.values()), "exports": report.student_exports,
               "tail": report.final_exports, "work": sum(per_student.values()), "students": report.graded,
               "cores": None if cpu is None else cpu / seconds}
    usage = "" if cpu is None else f"{cpu / report.graded:>10.2f} s{cpu / seconds:>7.2f}"
    print(f"{label:<22}{seconds:>8.1f} s{figures['rate']:>9.1f}/min{figures['median']:>10.2f} s"
          f"{figures['exports']:>10.1f} s{figures['tail']:>8.1f} s{usage}", flush=True)
    return figures


def profile_one(problems: list[int], limits: Limits, scratch: Path) -> None:
    """Grade one reference submission (warm path) under cProfile and say where the time goes."""
    import cProfile
    import pstats

    from grader.runner import grade_submission
    from grader.workers import Forked
    from grader.sandbox.zygote import Zygote, warm_modules

    submission = copy_reference(scratch / "profiled")
    with Zygote(limits, sandbox_mode(), warm_modules(problems)) as zygote:
        zygote.start()
        grade_submission(submission, problems, seed=1, workers=Forked(zygote, limits))  # warm the caches
        profiler = cProfile.Profile()
        start = time.perf_counter()
        profiler.enable()
        reports = grade_submission(submission, problems, seed=2, workers=Forked(zygote, limits))
        profiler.disable()
        total = time.perf_counter() - start
        # then, alternately, a grading without the profiler (other random inputs, the CPU time of every process)
        # and the replay of its calls alone: the machine's speed drifts within a minute, so each pair is close
        pairs = []
        for seed in range(3, 3 + REPLAYS):
            cpu = busy_cpu_seconds()
            with recorded_calls() as calls:
                grade_submission(submission, problems, seed=seed, workers=Forked(zygote, limits))
            cpu = None if cpu is None else busy_cpu_seconds() - cpu
            pairs.append((cpu, len(calls), *replay_alone(calls, warm_modules(problems))))
    stats = pstats.Stats(profiler).stats

    def cumulative(fragment: str, name: str, required: bool = True) -> float:
        found = [entry[3] for (file, _, func), entry in stats.items() if fragment in file and func == name]
        if required and not found:  # a renamed function must not read as "no time spent"
            raise SystemExit(f"bench_batch: the profile holds no {name}() of {fragment}: update profile_one")
        return max(found, default=0.0)

    waiting = cumulative("sandbox/protocol.py", "read")
    engine = cumulative("hypothesis/core.py", "run_engine", required=False)  # only where a comparison fails
    reference = cumulative("grader/oracle.py", "_run")
    student = cumulative("grader/sandbox/child.py", "call")
    print(f"\nwhere one whole submission's {total:.1f} s go (the reference graded on the warm path, this process "
          "profiled):")
    print(f"  waiting for the student's worker (its computations, its imports, the pipe): {waiting:6.1f} s")
    print(f"  the reference's probes in the grader (on this student's random inputs):        {reference:6.1f} s")
    print(f"  hypothesis's engine around the randomized comparisons (calls included):       {engine:6.1f} s")
    print(f"  the grader's own work outside the worker: {total - waiting:6.1f} s "
          f"(student calls {student:.1f} s in all, waiting included)")
    slowest = sorted(reports, key=lambda r: -r.duration)[:6]
    print("  slowest problems: " + ", ".join(f"{r.problem} {r.duration:.1f} s" for r in slowest))
    print_replays(pairs)


@contextlib.contextmanager
def recorded_calls():
    """Every call a grading sends to the student's worker, as ``(probe, encoded arguments)``."""
    from grader.sandbox.child import Child, probe_name
    from probes._codec import encode

    calls: list[tuple[str, object]] = []
    original = Child.call_later

    def call_later(self, probe, *args, **options):
        calls.append((probe_name(probe), encode(list(args))))
        return original(self, probe, *args, **options)

    Child.call_later = call_later
    try:
        yield calls
    finally:
        Child.call_later = original


def _replay(calls: list[tuple[str, object]], modules: list[str]) -> tuple[float, dict[str, float]]:
    """In a fresh interpreter: the CPU time of importing the reference, then of each call run on it directly."""
    import importlib

    from probes._codec import decode

    for name in modules:  # what a grading worker has imported before a submission arrives
        importlib.import_module(name)
    start = time.process_time()
    package = importlib.import_module("reference")
    imported = time.process_time() - start
    spent: dict[str, float] = {}
    for probe, args in calls:
        module_name, _, func_name = probe.rpartition(".")
        func = getattr(importlib.import_module(f"probes.{module_name}"), func_name)
        start = time.process_time()
        func(package, *decode(args))
        spent[probe] = spent.get(probe, 0.0) + time.process_time() - start
    return imported, spent


def replay_alone(calls: list[tuple[str, object]], modules: list[str]) -> tuple[float, dict[str, float]]:
    """The students' own computations of one submission without the grader, the sandbox or the pipe: its calls
    replayed on the reference in a fresh process.  Returns the CPU time of the import and of each probe."""
    import multiprocessing

    from grader.sandbox.launch import child_env

    # one thread per numerical library, as in a student's worker (else idle BLAS threads count as CPU time)
    threads = {name: value for name, value in child_env().items() if name.endswith("_NUM_THREADS")}
    saved = {name: os.environ.get(name) for name in threads}
    os.environ.update(threads)
    try:
        with multiprocessing.get_context("spawn").Pool(1) as pool:
            return pool.apply(_replay, (calls, modules))
    finally:
        for name, value in saved.items():
            if value is None:
                os.environ.pop(name)
            else:
                os.environ[name] = value


def print_replays(pairs: list[tuple[float | None, int, float, dict[str, float]]]) -> None:
    """``(CPU time of a grading, its calls, the replay's import, the replay's time per probe)`` for each pair:
    the share of the students' code in a grading, and the rate that its CPU time allows at best."""
    alone = [imported + sum(spent.values()) for _, _, imported, spent in pairs]
    graded = [cpu for cpu, *_ in pairs if cpu]
    cores = os.cpu_count() or 1
    spent = pairs[alone.index(statistics.median_low(alone))][3]
    top = sorted(spent.items(), key=lambda item: -item[1])[:6]
    print(f"\nthe students' code alone ({len(pairs)} more reference submissions graded without the profiler, each "
          f"followed by its {pairs[0][1]} calls replayed on the reference in a fresh process, no grader, sandbox or "
          f"pipe): {statistics.median(alone):.1f} CPU-s (median; {min(alone):.1f}-{max(alone):.1f})")
    if graded:
        shares = [a / cpu for (cpu, *_), a in zip(pairs, alone) if cpu]
        print(f"  their gradings took {statistics.median(graded):.1f} CPU-s (median; every process): the students' "
              f"code is {statistics.median(shares):.0%} of a grading (median of the pairs; "
              f"{min(shares):.0%}-{max(shares):.0%})")
    print("  heaviest probes: " + ", ".join(f"{probe} {seconds:.1f} s" for probe, seconds in top))
    print(f"  even a grader that cost nothing would grade at most {60 * cores / statistics.median(alone):.1f} such "
          f"students/min on {cores} cores at the machine's speed of these measurements")


def chosen_problems(parser: argparse.ArgumentParser, words: list[str] | None) -> list[int]:
    """The graded problems that ``words`` name (numbers and ranges N-M); a usage error for anything else."""
    graded = [p.number for p in all_problems()]
    if not words:
        return graded
    chosen: list[int] = []
    for word in words:
        low, _, high = word.partition("-")
        try:
            span = range(int(low), int(high or low) + 1)
        except ValueError:
            parser.error(f"--problems: {word!r} is neither a number nor a range N-M")
        inside = [n for n in graded if n in span]
        if not high and not inside:
            parser.error(f"--problems: problem {word} has no checks (see `grade list`)")
        chosen += [n for n in inside if n not in chosen]
    if not chosen:
        parser.error("--problems: no graded problem in " + " ".join(words))
    return chosen


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--students", type=int, default=40)
    parser.add_argument("--jobs", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--cluster", type=int, default=2, help="workers of the LocalCluster (0: none)")
    parser.add_argument("--problems", nargs="+", default=None, metavar="N|N-M",
                        help="problems or ranges of problems (default: every problem with checks)")
    parser.add_argument("--profile", action="store_true")
    args = parser.parse_args()
    problems = chosen_problems(parser, args.problems)
    limits = Limits(call_timeout=BATCH_LIMITS["call_timeout"], import_timeout=BATCH_LIMITS["import_timeout"])
    with tempfile.TemporaryDirectory() as scratch:
        scratch = Path(scratch)
        kinds = build_course_class(scratch / "class", args.students)
        counts = {kind: sum(1 for k in kinds.values() if k == kind) for kind in dict.fromkeys(kinds.values())}
        numpy_import = statistics.median(timed([sys.executable, "-c", "import numpy"], 7))
        print(f"machine: {os.cpu_count()} cores, load {os.getloadavg()[0]:.1f}; sandbox {sandbox_mode().kind}; "
              f'the machine\'s speed today: python -c "import numpy" {numpy_import:.3f} s, 20,000 steps of 3x3 '
              f"arrays {small_array_seconds():.3f} s (medians of 7)")
        print(f"class: {len(kinds)} submissions ({', '.join(f'{n} {k}' for k, n in counts.items())}); "
              f"{len(problems)} problems ({sum(p.points for p in all_problems() if p.number in problems):g} points)")
        print(f"limits: {limits.call_timeout:g} s per call, {limits.import_timeout:g} s per import")
        print(f"\n{'configuration':<22}{'wall':>10}{'rate':>13}{'median/student':>16}{'exports':>8}{'tail':>10}"
              f"{'cpu/student':>12}{'cores':>7}")
        results = [run(f"--jobs {jobs}", scratch, problems, limits, jobs=jobs) for jobs in args.jobs]
        if args.cluster:
            results.append(run(f"LocalCluster {args.cluster}", scratch, problems, limits,
                               cluster=f"local:{args.cluster}"))
        print("\nratios (same run):")
        by_label = {r["label"]: r for r in results}
        one, two = by_label.get("--jobs 1"), by_label.get("--jobs 2")
        if one and two:
            print(f"  speed-up --jobs 2 / --jobs 1: {two['rate'] / one['rate']:.2f}x (target >= 1.8x); "
                  f"--jobs 2: {two['rate']:.1f} students/min (target >= 20)")
            if one["cores"]:
                print(f"  --jobs 1 kept {one['cores']:.2f} cores busy: on {os.cpu_count()} cores --jobs 2 can be at "
                      f"most {os.cpu_count() / one['cores']:.2f}x faster while a student costs the same CPU time")
        cluster = by_label.get(f"LocalCluster {args.cluster}")
        if cluster and two:
            print(f"  LocalCluster {args.cluster} / --jobs 2: {cluster['rate'] / two['rate']:.2f} of its rate "
                  f"(target >= 0.85)")
        print("  exports: each student's files written as they are recorded (the 'exports' column, overlapping "
              "the grading), the class's files at the end (the 'tail')")
        if args.profile:
            profile_one(problems, limits, scratch)
    return 0


if __name__ == "__main__":
    sys.exit(main())
