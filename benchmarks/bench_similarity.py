"""``grade similarity`` on a whole-course class, and what the batch's recording for it costs a grading.

    python benchmarks/bench_similarity.py [--students 300] [--recording N] [--problems N ...] [--reach]

The class (built fresh): ``--students`` whole-course submissions, each the reference with a few planted mistakes
and correct variants drawn from every problem's catalogue (every student different; a few pairs copy each other's
folder), and a gradebook holding each of them graded on every problem, synthesized rather than graded (45 problems
for 300 students would take hours): every check passed but those of the student's planted mistakes, failed with
the mistake's diagnosis and with wrong answers that students of the same mistake share.  The time printed is that
of ``grade similarity``'s work on it (reading the gradebook and the students' code, fingerprinting, ranking,
writing similarity.csv and similarity.html).  Target (issue 30): under a minute for 300 students.

``--recording N`` also grades N times, alternately, a whole-course submission with planted mistakes on a batch
slot's warm process with and without the recording of wrong answers (``grade batch`` records; ``grade problem-N``
does not) and prints the medians: the extra cost of a batch.  0 skips it.  ``--reach`` grades every planted mistake
of the problems alone and says how many leave a wrong answer for ``grade similarity`` to compare.
"""

from __future__ import annotations

import argparse
import hashlib
import random
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from grader.answers import Answer  # noqa: E402
from grader.batch.gradebook import Gradebook  # noqa: E402
from grader.checking import checks_of  # noqa: E402
from grader.loader import submission_digest  # noqa: E402
from grader.results import CheckResult, ProblemReport, Status  # noqa: E402
from grader.problems import check_id, problem_module, problems as all_problems  # noqa: E402
from grader.sources import grader_version  # noqa: E402
from tests.submissions import Planted, copy_reference, correct_variants, plant, planted_mistakes  # noqa: E402

#: per student: planted mistakes and correct variants drawn from the whole catalogue
MISTAKES, VARIANTS = 3, 2
#: pairs of students where one copied the other's folder
COPIES = 3
TARGET = 60.0


def _variant(entry: dict) -> Planted:
    return Planted(entry["name"], entry["problem"], entry["file"], entry["old"], entry["new"], "")


def build_class(dest: Path, students: int, seed: int = 30) -> dict[str, list[Planted]]:
    """``students`` whole-course submissions in ``dest``; returns each student's planted mistakes."""
    import shutil

    rng = random.Random(seed)
    mistakes, variants = planted_mistakes(), [_variant(v) for v in correct_variants()]
    dest.mkdir(parents=True)
    planted: dict[str, list[Planted]] = {}
    for index in range(students - COPIES):
        name = f"student_{index:03d}"
        folder = copy_reference(dest / name)
        applied = []
        for mistake in rng.sample(mistakes, MISTAKES):
            if plant(mistake, folder, strict=False):
                applied.append(mistake)
        for variant in rng.sample(variants, VARIANTS):
            plant(variant, folder, strict=False)
        _own_hand(folder, name)
        planted[name] = applied
    for index in range(COPIES):
        original = f"student_{index:03d}"
        copy = f"copy_of_{index:03d}"
        shutil.copytree(dest / original, dest / copy)
        planted[copy] = planted[original]
    return planted


def _own_hand(folder: Path, name: str) -> None:
    """Every line the student writes (the reference's solution regions) made their own, as a real student's lines
    differ from the reference's: a comment of theirs at its end.  Its tokens stay the reference's (comments do not
    count), so the class shares no code by accident, but ``grade similarity`` reads and tokenizes every such line,
    as it would a real class's."""
    for module in folder.glob("*.py"):
        inside, lines = False, []
        for line in module.read_text().splitlines():
            if line.strip().startswith("# END SOLUTION"):
                inside = False
            elif inside and line.strip() and not line.rstrip().endswith(("\\", '"""')):
                line = f"{line}  # {name}"
            elif line.strip().startswith("# BEGIN SOLUTION"):
                inside = True
            lines.append(line)
        module.write_text("\n".join(lines) + "\n")


def _digest(text: str) -> str:
    return hashlib.blake2b(text.encode(), digest_size=12).hexdigest()


def synthesize(results: Path, submissions: Path, planted: dict[str, list[Planted]]) -> float:
    """A gradebook in ``results`` with every student graded on every problem (see the module); seconds taken."""
    began = time.monotonic()
    numbers = [p.number for p in all_problems()]
    versions = {n: grader_version(n) for n in numbers}
    modules = {n: problem_module(n) for n in numbers}
    with Gradebook.in_folder(results) as book:
        run = book.start_run(str(submissions), numbers, 2, sandbox="synthesized")
        for student, mistakes in sorted(planted.items()):
            path = submissions / student
            failing = {m.check: m for m in mistakes}
            reports = []
            for number in numbers:
                results_ = []
                answers = []
                for spec in checks_of(modules[number]):
                    name = check_id(number, spec.name)
                    mistake = failing.get(name)
                    if mistake is None:
                        results_.append(CheckResult(name, number, spec.title, Status.PASSED, spec.points,
                                                    spec.points, visibility=spec.visibility, stage=spec.stage))
                        continue
                    results_.append(CheckResult(name, number, spec.title, Status.FAILED, 0.0, spec.points,
                                                f"got ..., expected ... ({mistake.name})", diagnosis=mistake.diagnosis,
                                                visibility=spec.visibility, stage=spec.stage))
                    answers += [Answer(name, f"{name}.probe({i})", _digest(f"{name}:{i}"),
                                       _digest(f"{mistake.name}:{i}"), f"[{i}.0, ...] ({mistake.name})",
                                       f"[{i}.5, ...]")
                                for i in range(2)]
                reports.append(ProblemReport(number, modules[number].TITLE, tuple(results_), seed=1,
                                             submission=str(path), sandbox="synthesized",
                                             wrong_answers=tuple(answers)))
            book.record(student, submission_digest(path), versions, run, reports)
        book.finish_run(run, "finished", 0)
    return time.monotonic() - began


def _cpu() -> float:
    """CPU-seconds of this process and of its children that have ended (the fingerprinting processes)."""
    import resource

    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def bench_similarity(students: int) -> None:
    from grader.similarity import write_similarity

    with tempfile.TemporaryDirectory(prefix="bench-similarity-") as scratch:
        submissions, results = Path(scratch) / "submissions", Path(scratch) / "results"
        began = time.monotonic()
        planted = build_class(submissions, students)
        built = time.monotonic() - began
        made = synthesize(results, submissions, planted)
        print(f"class: {students} whole-course students ({len(all_problems())} problems), built in {built:.1f} s; "
              f"gradebook synthesized in {made:.1f} s ({(results / 'gradebook.sqlite').stat().st_size / 2**20:.0f} MB)")
        cpu = _cpu()
        began = time.monotonic()
        found = write_similarity(results)
        seconds = time.monotonic() - began
        cpu = _cpu() - cpu
        copies = {frozenset((f"student_{i:03d}", f"copy_of_{i:03d}")) for i in range(COPIES)}
        ranks = sorted(index + 1 for index, pair in enumerate(found.pairs)
                       if frozenset((pair.first, pair.second)) in copies)
        print(f"grade similarity: {seconds:.1f} s wall, {cpu:.1f} CPU-s (its processes) for {found.students} students "
              f"({found.compared} pairs, {len(found.pairs)} with any evidence, code of {found.with_code} compared); "
              f"target under {TARGET:.0f} s: {'met' if seconds < TARGET else 'NOT met'}")
        print(f"  the {COPIES} copied folders rank {ranks} of {len(found.pairs)}")
        print(f"  similarity.html {(results / 'similarity.html').stat().st_size / 2**10:.0f} KiB, similarity.csv "
              f"{(results / 'similarity.csv').stat().st_size / 2**10:.0f} KiB")


def bench_recording(repeats: int, numbers: list[int]) -> None:
    from grader.runner import grade_submission
    from grader.workers import Forked
    from grader.sandbox import Limits, sandbox_mode
    from grader.sandbox.zygote import Zygote, warm_modules

    rng = random.Random(7)
    by_problem: dict[int, list[Planted]] = {}
    for mistake in planted_mistakes():
        if mistake.problem in numbers:
            by_problem.setdefault(mistake.problem, []).append(mistake)
    chosen = [rng.choice(items) for _, items in sorted(by_problem.items())][::3]
    with tempfile.TemporaryDirectory(prefix="bench-recording-") as scratch:
        folder = copy_reference(Path(scratch) / "mistakes")
        applied = [m.name for m in chosen if plant(m, folder, strict=False)]
        times: dict[bool, list[float]] = {False: [], True: []}
        own: dict[bool, list[float]] = {False: [], True: []}  # the grader's own CPU: checks, reference, recording
        answers = 0
        with Zygote(Limits(), sandbox_mode(), warm_modules(numbers)) as zygote:
            zygote.start()
            grade_submission(folder, numbers, seed=1, workers=Forked(zygote))  # the reference's fixed cases cached
            for index in range(repeats):
                for record in ((False, True) if index % 2 == 0 else (True, False)):
                    began, cpu = time.monotonic(), time.process_time()
                    reports = grade_submission(folder, numbers, seed=1, workers=Forked(zygote), record_answers=record)
                    times[record].append(time.monotonic() - began)
                    own[record].append(time.process_time() - cpu)
                    if record:
                        answers = sum(len(r.wrong_answers) for r in reports)
        plain, recording = statistics.median(times[False]), statistics.median(times[True])
        cpu_plain, cpu_recording = statistics.median(own[False]), statistics.median(own[True])
        print(f"recording for grade similarity: a whole-course submission with {len(applied)} planted mistakes, "
              f"{len(numbers)} problems, {repeats} gradings each way (medians): {plain:.2f} s without, "
              f"{recording:.2f} s with ({(recording - plain) / plain * 100:+.1f}%); the grader's own CPU "
              f"{cpu_plain:.2f} s without, {cpu_recording:.2f} s with "
              f"({(cpu_recording - cpu_plain) / cpu_plain * 100:+.1f}%); "
              f"{answers} wrong answers recorded")


def bench_reach(numbers: list[int]) -> None:
    """How far the recording reaches: each planted mistake of ``numbers`` graded alone with the recording, and the
    share of those caught by their check that leave a wrong answer to compare (``grade similarity``'s answers
    evidence; the rest are compared by their diagnoses alone)."""
    from grader.runner import grade_submission
    from grader.workers import Forked
    from grader.sandbox import Limits, sandbox_mode
    from grader.sandbox.zygote import Zygote, warm_modules

    mistakes = [m for m in planted_mistakes() if m.problem in numbers]
    caught = recorded = 0
    by_problem: dict[int, list[int]] = {}
    with tempfile.TemporaryDirectory(prefix="bench-reach-") as scratch, \
            Zygote(Limits(), sandbox_mode(), warm_modules(numbers)) as zygote:
        zygote.start()
        for index, mistake in enumerate(mistakes):
            folder = copy_reference(Path(scratch) / f"m{index}")
            plant(mistake, folder)
            report, = grade_submission(folder, [mistake.problem], seed=1, workers=Forked(zygote), record_answers=True)
            if not any(r.check_id == mistake.check and not r.passed for r in report.results):
                continue
            caught += 1
            hit = bool(report.wrong_answers)
            recorded += hit
            by_problem.setdefault(mistake.problem, [0, 0])
            by_problem[mistake.problem][0] += 1
            by_problem[mistake.problem][1] += hit
    missing = ", ".join(f"{n} ({total - hit} of {total})" for n, (total, hit) in sorted(by_problem.items())
                        if hit < total)
    print(f"reach of the recording: {recorded} of the {caught} planted mistakes of {len(numbers)} problems caught by "
          f"their check leave a wrong answer to compare ({recorded / max(caught, 1) * 100:.0f}%); the others, by "
          f"problem: {missing or 'none'}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--students", type=int, default=300)
    parser.add_argument("--recording", type=int, default=3, metavar="N",
                        help="gradings each way to measure the recording's cost (0: skip)")
    parser.add_argument("--problems", type=int, nargs="+", default=None,
                        help="the problems of the recording's gradings (default: every problem with checks)")
    parser.add_argument("--reach", action="store_true",
                        help="also grade every planted mistake of --problems alone and say how many leave a wrong "
                             "answer to compare")
    args = parser.parse_args(argv)
    if args.students < 2 * COPIES:
        parser.error(f"--students must be at least {2 * COPIES}")
    bench_similarity(args.students)
    if args.recording:
        bench_recording(args.recording, args.problems or [p.number for p in all_problems()])
    if args.reach:
        bench_reach(args.problems or [p.number for p in all_problems()])
    return 0


if __name__ == "__main__":
    sys.exit(main())
