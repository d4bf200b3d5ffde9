"""Batch grading: every student of a folder, in parallel, into a gradebook that survives interruption.

    grade batch SUBMISSIONS --out RESULTS [--problems N ...] [--jobs N] [--force]
    grade import-manual RESULTS SCORES.csv
    grade export RESULTS

Each entry of SUBMISSIONS is one student: a folder, a .zip archive or a .ipynb notebook.  Students are graded on
``--jobs`` worker processes (spawned, each with its own sandbox uid); every worker grades one student at a time with
``grade_submission``, whose child enforces the per-call limits, and the parent bounds each student's total time as
well.  Workers send back plain reports; the parent alone writes the gradebook, one transaction per student.  A
student whose content and grader version are already in the gradebook is skipped unless ``--force``.

RESULTS receives the gradebook (``gradebook.sqlite``), ``grades.csv``, ``summary.html`` (the class summary),
``manual_answers.csv`` (free-text answers, with a score column to fill in and import) and, per student,
``students/NAME/results.json`` (Gradescope's format) and ``students/NAME/report.html`` (the student's view).
"""

from __future__ import annotations

import csv
import fcntl
import hashlib
import io
import json
import multiprocessing
import os
import signal
import statistics
import sys
import threading
import time
import traceback
from collections import Counter, defaultdict, deque
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from multiprocessing.connection import wait
from pathlib import Path

from .errors import GraderFault, SandboxError, SubmissionError
from .gradebook import (GRADEBOOK_NAME, Gradebook, Graded, ManualScoreError, grader_version, now,
                        spreadsheet_cell)
from .results import CheckResult, ProblemReport, Status
from .sandbox import BWRAP_FIX, Limits, SandboxMode, canary, sandbox_mode

__all__ = [
    "Entry",
    "BatchReport",
    "Progress",
    "BatchLocked",
    "discover",
    "submission_hash",
    "student_seed",
    "run_batch",
    "export_results",
    "class_summary",
    "add_batch_parser",
    "DIAGNOSES",
]

SUBMISSION_SUFFIXES = (".zip", ".ipynb")
#: seconds a worker has to stop after SIGTERM before it is killed
STOP_GRACE = 3.0
#: how the class summary words a diagnosis: "31% of students transposed a rotation matrix ..."
DIAGNOSES = {
    "transpose": "transposed a rotation matrix (A_BI for A_IB)",
    "degrees": "used degrees where radians are expected",
    "rotation_order": "multiplied the rotations in the wrong order",
    "argument_order": "swapped the arguments",
    "wrong_axis": "rotated about the wrong axis",
    "reflection": "built a reflection instead of a rotation (det = -1)",
    "sign": "flipped a sign",
    "shape": "returned an array of the wrong shape",
    "none": "returned nothing (a missing return)",
    "not_finite": "returned NaN or infinite values",
}
TROUBLE = (Status.ERROR, Status.TIMEOUT, Status.GRADER_ERROR)


class BatchLocked(RuntimeError):
    """Another process is writing to the results folder."""


# ------------------------------------------------------------------------------------------ the students


@dataclass(frozen=True)
class Entry:
    """One student's submission: a folder, a zip archive or a notebook."""

    name: str
    path: Path
    content_hash: str

    @property
    def seed(self) -> int:
        return student_seed(self.content_hash)


def student_seed(content_hash: str) -> int:
    """The seed of the randomized checks: fixed by the content, so that a regrade is reproducible."""
    return int(hashlib.sha256(content_hash.encode()).hexdigest()[:8], 16) & 0x7FFFFFFF


def submission_hash(path: Path) -> str:
    """The content hash of a submission (its files' names and contents), as the loader computes it."""
    from .loader import submission_digest

    try:
        return submission_digest(path)
    except SubmissionError as exc:
        data = path.read_bytes() if path.is_file() else str(exc).encode()
        return "unloadable-" + hashlib.sha256(data).hexdigest()


def discover(folder: str | Path, exclude: Path | None = None) -> tuple[list[Entry], list[str]]:
    """The students of ``folder`` and the names of the entries that are not submissions."""
    folder = Path(folder)
    if not folder.is_dir():
        raise SubmissionError(f"{folder} is not a folder")
    entries, ignored, seen = [], [], {}
    for path in sorted(folder.iterdir()):
        if path.name.startswith((".", "__")) or (exclude is not None and path.resolve() == exclude.resolve()):
            continue
        if not (path.is_dir() or path.suffix in SUBMISSION_SUFFIXES):
            ignored.append(path.name)
            continue
        name = path.name if path.is_dir() else path.stem
        if name in seen:
            raise SubmissionError(f"{seen[name]} and {path.name} would both be the student {name!r}")
        seen[name] = path.name
        entries.append(Entry(name, path, submission_hash(path)))
    return entries, ignored


# ------------------------------------------------------------------------------------------ workers


@dataclass(frozen=True)
class _Task:
    entry: Entry
    problems: tuple[int, ...]


def _die_with_parent(parent: int) -> None:
    """Receive SIGTERM when the parent dies, even by SIGKILL (Linux); exit now if it is gone already."""
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass
    if os.getppid() != parent:
        sys.exit(0)


class _Stopped(BaseException):
    """Raised in a worker by SIGTERM: not an Exception (nor SystemExit, which hypothesis takes for a failing
    example), so that nothing on the way catches it and the Child on the way kills the student's process."""


def _stop(signum, frame):
    raise _Stopped


def _serve(conn, slot: int, limits: Limits, mode: SandboxMode, problems: tuple[int, ...], parent: int) -> None:
    """A worker process: grade the tasks the parent sends, one at a time, and send back the reports."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    signal.signal(signal.SIGTERM, _stop)
    try:
        _die_with_parent(parent)
        _work(conn, slot, limits, mode, problems)
    except _Stopped:
        pass


def _work(conn, slot: int, limits: Limits, mode: SandboxMode, problems: tuple[int, ...]) -> None:
    try:
        from .runner import grade_submission, problem_module

        for number in problems:
            problem_module(number)
    except Exception:  # noqa: BLE001 - reported to the parent, which stops the batch
        conn.send(("fault", traceback.format_exc()))
        return
    conn.send(("ready", None))
    while True:
        try:
            task = conn.recv()
        except (EOFError, OSError):
            return
        if task is None:
            return
        try:
            reports = grade_submission(task.entry.path, list(task.problems), seed=task.entry.seed, limits=limits,
                                       mode=mode)
            conn.send(("ok", reports))
        except GraderFault as exc:  # this student is not recorded and is retried next run
            conn.send(("fault", str(exc).strip().splitlines()[0]))
        except Exception:  # noqa: BLE001 - a grader fault: this student is not recorded and is retried next run
            conn.send(("fault", traceback.format_exc()))


class _Slot:
    """One worker process and the task it grades."""

    def __init__(self, context, index: int, limits: Limits, mode: SandboxMode, problems: tuple[int, ...]):
        self.context, self.index, self.args = context, index, (limits, mode, problems)
        self.task: _Task | None = None
        self.deadline = self.started = 0.0
        self._start()

    def _start(self) -> None:
        self.conn, theirs = self.context.Pipe()
        self.process = self.context.Process(
            target=_serve, args=(theirs, self.index, *self.args, os.getpid()), name=f"grade-worker-{self.index}",
            daemon=True,
        )
        self.process.start()
        theirs.close()
        self.ready = False

    def restart(self) -> None:
        self.stop()
        self._start()

    def stop(self) -> None:
        if self.process.is_alive():
            self.process.terminate()
            self.process.join(STOP_GRACE)
        if self.process.is_alive():
            self.process.kill()
            self.process.join()
        self.conn.close()

    def submit(self, task: _Task, seconds: float) -> None:
        self.conn.send(task)
        self.task, self.started = task, time.monotonic()
        self.deadline = self.started + seconds

    def waitables(self) -> list:
        return [self.conn, self.process.sentinel]

    def poll(self) -> tuple[str, object] | None:
        """``(kind, payload)`` once the worker answered, died or ran out of time; None while it works."""
        if self.conn.poll():
            try:
                return self.conn.recv()
            except (EOFError, OSError):
                pass
        elif self.process.is_alive():
            if self.task is None or time.monotonic() < self.deadline:
                return None
            self.restart()
            return "timeout", None
        self.process.join(1)
        code = self.process.exitcode
        self.restart()
        return "crashed", f"the grading process ended with exit code {code}"


def _run_pool(tasks: list[_Task], jobs: int, limits: Limits, mode: SandboxMode, problems: tuple[int, ...],
              student_timeout: float, done) -> None:
    """Grade ``tasks`` on ``jobs`` workers; ``done(task, kind, payload, seconds)`` is called in this process."""
    context = multiprocessing.get_context("spawn")
    pending = deque(tasks)
    slots = [_Slot(context, index + 1, limits, mode, problems) for index in range(min(jobs, len(tasks)))]
    try:
        while pending or any(s.task for s in slots):
            for slot in slots:
                if slot.ready and slot.task is None and pending:
                    try:
                        slot.submit(pending[0], student_timeout)
                        pending.popleft()
                    except OSError:  # the idle worker died: start another
                        slot.restart()
            busy = [s for s in slots if s.task is not None]
            timeout = max(0.0, min(s.deadline for s in busy) - time.monotonic()) if busy else None
            wait([w for s in slots if s.task is not None or not s.ready for w in s.waitables()], timeout)
            for slot in slots:
                if not slot.ready:
                    if slot.conn.poll() or not slot.process.is_alive():
                        kind, payload = slot.poll() or ("crashed", "no answer")
                        if kind != "ready":
                            raise RuntimeError(f"a grading worker could not start: {payload}")
                        slot.ready = True
                    continue
                if slot.task is None:
                    continue
                task, started = slot.task, slot.started
                outcome = slot.poll()
                if outcome is not None:
                    slot.task = None
                    done(task, *outcome, time.monotonic() - started)
    finally:
        for slot in slots:
            slot.stop()


def _stopped(task: _Task, status: Status, message: str, seconds: float) -> list[ProblemReport]:
    """Reports for a student whose grading the batch stopped after ``seconds``: every check with ``status``."""
    from . import __version__
    from .checking import checks_of
    from .runner import problem_module

    reports = []
    for number in task.problems:
        module = problem_module(number)
        results = tuple(
            CheckResult(f"p{number:02d}.{spec.name}", number, spec.title, status, 0.0, spec.points, message,
                        visibility=spec.visibility, stage=spec.stage)
            for spec in checks_of(module)
        )
        reports.append(ProblemReport(number, module.TITLE, results, seed=task.entry.seed,
                                     duration=seconds / len(task.problems), submission=str(task.entry.path),
                                     grader_version=__version__))
    return reports


# ------------------------------------------------------------------------------------------ progress


def _clock(seconds: float) -> str:
    seconds = int(round(seconds))
    return f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}" if seconds >= 3600 else \
        f"{seconds // 60}:{seconds % 60:02d}"


class Progress:
    """Counts, rate and time left on stderr: one redrawn line on a terminal, a line per student otherwise."""

    WIDTH = 28

    def __init__(self, total: int, skipped: int = 0, stream=None, enabled: bool = True):
        self.stream = stream or sys.stderr
        self.total, self.skipped, self.done, self.enabled = total, skipped, 0, enabled
        self.tty = self.stream.isatty()
        self.start = time.monotonic()

    def line(self) -> str:
        elapsed = time.monotonic() - self.start
        rate = self.done / elapsed if elapsed > 0 else 0.0
        eta = _clock((self.total - self.done) / rate) if rate else "?"
        skipped = f" ({self.skipped} unchanged, skipped)" if self.skipped else ""
        return (f"{self.done}/{self.total} done{skipped} · {rate * 60:.1f}/min · {_clock(elapsed)} elapsed"
                f" · ETA {eta}")

    def advance(self, name: str, note: str) -> None:
        self.done += 1
        if not self.enabled:
            return
        if self.tty:
            filled = self.WIDTH * self.done // max(self.total, 1)
            bar = "█" * filled + "░" * (self.WIDTH - filled)
            self.stream.write(f"\r\033[K{bar} {self.line()}")
        else:
            self.stream.write(f"[{self.done}/{self.total}] {name}: {note} · {self.line()}\n")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled and self.tty and self.done:
            self.stream.write("\n")
            self.stream.flush()


# ------------------------------------------------------------------------------------------ the batch


@dataclass
class BatchReport:
    run_id: int
    students: int
    graded: int = 0
    skipped: int = 0
    timed_out: list[str] = field(default_factory=list)
    not_graded: dict[str, str] = field(default_factory=dict)  # grader faults: retried on the next run
    ignored: list[str] = field(default_factory=list)
    interrupted: bool = False
    seconds: float = 0.0

    @property
    def per_minute(self) -> float:
        return 60.0 * self.graded / self.seconds if self.seconds else 0.0


@contextmanager
def _locked(out: Path):
    """One writer per results folder at a time (released by the kernel if the process dies)."""
    out.mkdir(parents=True, exist_ok=True)
    with open(out / ".lock", "w") as handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise BatchLocked(f"another grade command is writing to {out}") from None
        yield


def _interrupt(signum, frame):
    raise KeyboardInterrupt


def default_student_timeout(limits: Limits, problems: list[int]) -> float:
    """The import time-out plus twice the call time-out per check."""
    from .checking import checks_of
    from .runner import problem_module

    checks = sum(len(checks_of(problem_module(n))) for n in problems)
    return limits.import_timeout + 2 * limits.call_timeout * max(checks, 1)


def run_batch(
    submissions: str | Path,
    out: str | Path,
    *,
    problems: list[int] | None = None,
    jobs: int | None = None,
    force: bool = False,
    limits: Limits | None = None,
    student_timeout: float | None = None,
    progress: bool = True,
    export: bool = True,
    no_sandbox: bool = False,
) -> BatchReport:
    """Grade every student of ``submissions`` into the gradebook in ``out``, then write the exports.

    Without bubblewrap, students' code runs as plain processes: only with ``no_sandbox`` (recorded in the run and
    in every report), else ``SandboxError``.  One worker is started first (a canary): when it cannot start, the
    batch stops with ``SandboxError`` before anyone is graded."""
    from .runner import problems as all_problems

    start = time.monotonic()
    out = Path(out)
    if not Path(submissions).is_dir():
        raise SubmissionError(f"{submissions} is not a folder")
    numbers = sorted(problems or [p.number for p in all_problems()])
    limits = limits or Limits()
    jobs = max(1, jobs or len(os.sched_getaffinity(0)))
    student_timeout = student_timeout or default_student_timeout(limits, numbers)
    mode = sandbox_mode()
    if not mode.isolated and not no_sandbox:
        raise SandboxError(f"bubblewrap is not available, so students' code would run without a sandbox: install "
                           f"it ({BWRAP_FIX}), or pass --no-sandbox to grade without one (recorded in the gradebook "
                           "and in every report)")
    with _locked(out), Gradebook.in_folder(out) as book:
        entries, ignored = discover(submissions, exclude=out)
        versions = {n: grader_version(n) for n in numbers}
        if entries:
            canary(limits, mode)
        sandbox = mode.note if mode.isolated else f"--no-sandbox: {mode.note}"
        run_id = book.start_run(str(submissions), numbers, jobs, force, sandbox=sandbox)
        report = BatchReport(run_id, len(entries), ignored=ignored)
        tasks = []
        for entry in entries:
            todo = set(numbers)
            if not force:
                todo -= book.graded_problems(entry.name, entry.content_hash, versions)
            if todo:
                tasks.append(_Task(entry, tuple(sorted(todo))))
        report.skipped = len(entries) - len(tasks)
        bar = Progress(len(tasks), report.skipped, enabled=progress)

        def done(task: _Task, kind: str, payload, seconds: float) -> None:
            name = task.entry.name
            faults = [r for rep in payload for r in rep.results if r.status is Status.GRADER_ERROR] \
                if kind == "ok" else []
            if faults:  # a grader fault is never stored as a grade: retried on the next run
                kind, payload = "fault", faults[0].message.splitlines()[0]
            if kind == "ok":
                reports, outcome = payload, "graded"
            elif kind == "timeout":
                message = (f"grading this submission took longer than the batch's limit of {student_timeout:g} s "
                           "per student and was stopped: look for very slow or endless loops.")
                reports, outcome = _stopped(task, Status.TIMEOUT, message, seconds), "timeout"
                report.timed_out.append(name)
            else:
                report.not_graded[name] = str(payload).strip().splitlines()[-1] if payload else kind
                bar.advance(name, f"not graded ({report.not_graded[name]}); retried on the next run")
                return
            book.record(name, task.entry.content_hash, versions, run_id, reports, outcome, replace_existing=force)
            report.graded += 1
            score = sum(r.score for r in reports)
            bar.advance(name, f"{score:g}/{sum(r.max_score for r in reports):g} ({seconds:.1f} s)")

        in_main = threading.current_thread() is threading.main_thread()
        previous = signal.signal(signal.SIGTERM, _interrupt) if in_main else None
        state = "interrupted"
        try:
            if tasks:
                _run_pool(tasks, jobs, limits, mode, tuple(numbers), student_timeout, done)
            state = "finished"
        except KeyboardInterrupt:
            report.interrupted = True
        finally:
            if in_main:
                signal.signal(signal.SIGTERM, previous)
            bar.close()
            book.finish_run(run_id, state, report.skipped)
        report.seconds = time.monotonic() - start
        if export and not report.interrupted:
            export_results(out, book)
    return report


# ------------------------------------------------------------------------------------------ exports


def _write(path: Path, text: str) -> None:
    """Write atomically: a reader (or a crash) never sees half a file."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


def _csv(rows: list[list]) -> str:
    """CSV text; every text cell is spreadsheet-safe (student names and answers are untrusted)."""
    buffer = io.StringIO()
    safe = [[spreadsheet_cell(cell) if isinstance(cell, str) else cell for cell in row] for row in rows]
    csv.writer(buffer, lineterminator="\r\n").writerows(safe)  # RFC 4180: a cell holding \r or \n is quoted
    return buffer.getvalue()


def _by_student(graded: list[Graded]) -> dict[str, list[Graded]]:
    students: dict[str, list[Graded]] = defaultdict(list)
    for g in graded:
        students[g.student].append(g)
    return dict(sorted(students.items()))


def export_results(out: str | Path, book: Gradebook | None = None) -> dict[str, Path]:
    """Write grades.csv, manual_answers.csv, summary.html and each student's results.json and report.html."""
    from .render import gradescope_results, render_html

    out = Path(out)
    if book is None:
        with Gradebook.in_folder(out) as own:
            return export_results(out, own)
    graded = book.current()
    students = _by_student(graded)
    numbers = sorted({g.report.problem for g in graded})
    rows = [["student", *[f"problem_{n}" for n in numbers], "total", "possible"]]
    for name, items in students.items():
        scores = {g.report.problem: g.report.score for g in items}
        rows.append([name, *[f"{scores[n]:g}" if n in scores else "" for n in numbers],
                     f"{sum(scores.values()):g}", f"{sum(g.report.max_score for g in items):g}"])
    paths = {"grades": out / "grades.csv", "manual": out / "manual_answers.csv", "summary": out / "summary.html"}
    _write(paths["grades"], _csv(rows))
    comments = book.manual_comments()
    manual = [["student", "problem", "key", "score", "max_score", "question", "answer", "comment"]]
    manual += [[g.student, m.problem, m.key, "" if m.score is None else f"{m.score:g}", f"{m.max_score:g}",
                m.question, m.answer, comments.get((g.student, m.problem, m.key), "")]
               for g in graded for m in g.report.manual]
    _write(paths["manual"], _csv(manual))
    for name, items in students.items():
        reports = [g.report for g in items]
        folder = out / "students" / name
        _write(folder / "results.json", json.dumps(gradescope_results(reports), indent=2) + "\n")
        _write(folder / "report.html", render_html(reports, title=f"Grading report: {name}"))
    _write(paths["summary"], class_summary(graded))
    return paths


# ------------------------------------------------------------------------------------------ class summary


def _png(draw, height: float = 3.4) -> str:
    from .render import png

    return png(draw, height)


def _histogram(scores: list[float], top: float, title: str, xlabel: str) -> str:
    def draw(ax):
        edges = [x - 0.5 for x in range(int(top) + 2)] if top <= 25 else 20
        ax.hist(scores, bins=edges, range=None if top <= 25 else (0, top), color="#4c72b0", edgecolor="white")
        ax.set_xlim(-0.5, top + 0.5)
        ax.set_title(title)
        ax.set_xlabel(xlabel)
        ax.set_ylabel("students")
        ax.yaxis.get_major_locator().set_params(integer=True)

    return _png(draw)


def _failure_bars(labels: list[str], rates: list[float]) -> str:
    def draw(ax):
        ax.barh(labels[::-1], [100 * r for r in rates[::-1]], color="#c44e52")
        ax.set_xlim(0, 100)
        ax.set_xlabel("students who did not pass (%)")
        ax.set_title("Checks failed most often")
        ax.tick_params(axis="y", labelsize=8)

    return _png(draw, height=1.2 + 0.32 * len(labels))


def _percent(n: int, total: int) -> str:
    return f"{100 * n / total:.0f}" if total else "0"


def _distributions(graded: list[Graded], images: dict) -> tuple[list[dict], float]:
    """Per problem: statistics and a histogram of the scores; and a histogram of the students' totals."""
    by_problem: dict[int, list[Graded]] = defaultdict(list)
    for g in graded:
        by_problem[g.report.problem].append(g)
    problems = []
    for number, items in sorted(by_problem.items()):
        scores = [g.report.score for g in items]
        top = max(g.report.max_score for g in items)
        problems.append({
            "number": number, "title": items[0].report.title, "students": len(items), "max": top,
            "mean": statistics.fmean(scores), "median": statistics.median(scores), "min": min(scores),
            "full": sum(1 for s in scores if s >= top), "image": f"problem-{number}",
        })
        images[f"problem-{number}"] = _histogram(scores, top, f"Problem {number}: score distribution", "points")
    students = _by_student(graded).values()
    possible = max((sum(g.report.max_score for g in items) for items in students), default=0.0)
    if students:
        totals = [sum(g.report.score for g in items) for items in students]
        images["totals"] = _histogram(totals, possible, "Total score distribution", "points")
    return problems, possible


def _failures(graded: list[Graded], images: dict, top: int) -> tuple[list[dict], list[dict]]:
    """The checks that students did not pass, most frequent first (with a bar chart), and the diagnosed mistakes
    behind them, per problem and diagnosis: "31% of students transposed ... in problem 6"."""
    checks: dict[str, dict] = {}
    diagnosed: dict[tuple[int, str], dict] = {}
    per_problem = Counter(g.report.problem for g in graded)
    for g in graded:
        for r in g.report.results:
            stat = checks.setdefault(r.check_id, {"check_id": r.check_id, "problem": r.problem, "title": r.title,
                                                  "visibility": r.visibility, "students": 0, "how": Counter()})
            stat["students"] += 1
            if not r.passed:
                stat["how"][r.status.value] += 1
            if r.diagnosis:
                entry = diagnosed.setdefault((r.problem, r.diagnosis), {"students": set(), "checks": Counter()})
                entry["students"].add(g.student)
                entry["checks"][r.check_id] += 1
    failing = sorted((c for c in checks.values() if c["how"]), key=lambda c: (-c["how"].total(), c["check_id"]))
    for c in failing:
        c["not_passed"] = c["how"].total()
        c["percent"] = _percent(c["not_passed"], c["students"])
        c["statuses"] = ", ".join(f"{status} {n}" for status, n in c["how"].most_common())
    if failing:
        shown = failing[:top]
        images["failures"] = _failure_bars([c["check_id"] for c in shown],
                                           [c["not_passed"] / c["students"] for c in shown])
    mistakes = [
        {"problem": problem, "diagnosis": diagnosis, "count": len(entry["students"]),
         "percent": _percent(len(entry["students"]), per_problem[problem]),
         "phrase": DIAGNOSES.get(diagnosis, f"made the mistake “{diagnosis.replace('_', ' ')}”"),
         "checks": [{"check_id": check_id, "title": checks[check_id]["title"], "count": n,
                     "percent": _percent(n, checks[check_id]["students"])}
                    for check_id, n in sorted(entry["checks"].items(), key=lambda item: (-item[1], item[0]))]}
        for (problem, diagnosis), entry in diagnosed.items()
    ]
    mistakes.sort(key=lambda m: (-m["count"], m["problem"], m["diagnosis"]))
    return failing, mistakes


def _trouble(graded: list[Graded]) -> list[dict]:
    """The results in which the student's code errored or timed out, or that the batch stopped."""
    trouble = []
    for g in graded:
        bad = [r for r in g.report.results if r.status in TROUBLE]
        if bad or g.outcome != "graded":
            message = bad[0].message.strip() if bad else ""
            trouble.append({
                "student": g.student, "problem": g.report.problem, "outcome": g.outcome,
                "statuses": ", ".join(sorted({r.status.value for r in bad})),
                "message": message.splitlines()[0] if message else "",
            })
    return trouble


def class_summary(graded: list[Graded], top_checks: int = 12) -> str:
    """The class summary (HTML): score distributions, the checks failed most often and their diagnoses, the
    students whose grading errored or timed out, the free-text answers to score, and the gradebook."""
    from jinja2 import Environment, PackageLoader, StrictUndefined

    images: dict[str, str] = {}
    problems, possible = _distributions(graded, images)
    failing, mistakes = _failures(graded, images, top_checks)
    table = [{"student": name, "scores": {g.report.problem: g.report.score for g in items},
              "total": sum(g.report.score for g in items)} for name, items in _by_student(graded).items()]
    env = Environment(loader=PackageLoader("grader", "templates"), autoescape=True, undefined=StrictUndefined)
    env.globals["fmt"] = lambda x: f"{x:g}"
    return env.get_template("class_summary.html.j2").render(
        generated=now(), students=len(table), problems=problems, numbers=[p["number"] for p in problems],
        possible=possible, images=images, failing=failing, mistakes=mistakes, trouble=_trouble(graded),
        answers=[{"student": g.student, "item": m} for g in graded for m in g.report.manual], table=table,
        versions=sorted({g.grader_version for g in graded}),
        sandboxes=sorted({g.report.sandbox for g in graded if not g.report.isolated}),
    )


# ------------------------------------------------------------------------------------------ the commands


def cmd_batch(args) -> int:
    from .cli import EXIT_GRADER, EXIT_OK, EXIT_USAGE
    from .runner import problem_module

    for number in args.problems or ():
        try:
            problem_module(number)
        except KeyError:
            print(f"error: problem {number} has no checks (see `grade list`)", file=sys.stderr)
            return EXIT_USAGE
    defaults = Limits()
    limits = Limits(
        call_timeout=args.timeout or defaults.call_timeout,
        import_timeout=args.import_timeout or defaults.import_timeout,
    )
    try:
        report = run_batch(args.submissions, args.out, problems=args.problems, jobs=args.jobs, force=args.force,
                           limits=limits, student_timeout=args.student_timeout, progress=not args.quiet,
                           no_sandbox=args.no_sandbox)
    except (SubmissionError, BatchLocked) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except RuntimeError as exc:  # the workers cannot start: a broken installation
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_GRADER
    for name in report.ignored:
        print(f"note: {name} is not a folder, a .zip archive or a .ipynb notebook: ignored", file=sys.stderr)
    print(f"{report.students} students: {report.graded} graded, {report.skipped} unchanged (skipped), "
          f"{len(report.timed_out)} stopped at the time limit, {len(report.not_graded)} not graded "
          f"in {report.seconds:.1f} s.", file=sys.stderr)
    for name, reason in report.not_graded.items():
        print(f"  not graded: {name}: {reason}", file=sys.stderr)
    if report.interrupted:
        print("interrupted: every student graded so far is saved; rerun the same command to finish.",
              file=sys.stderr)
        return 130
    print(f"results in {args.out}/: grades.csv, summary.html, manual_answers.csv, students/NAME/", file=sys.stderr)
    return EXIT_GRADER if report.not_graded else EXIT_OK


def cmd_import_manual(args) -> int:
    from .cli import EXIT_OK, EXIT_USAGE

    out = Path(args.results)
    if not (out / GRADEBOOK_NAME).exists():
        print(f"error: {out} holds no gradebook (run `grade batch` first)", file=sys.stderr)
        return EXIT_USAGE
    try:
        with _locked(out), Gradebook.in_folder(out) as book:
            with open(args.scores, encoding="utf-8-sig", newline="") as handle:  # csv reads its own line ends
                count = book.import_manual(handle.read(), source=str(args.scores))
            export_results(out, book)
    except (ManualScoreError, BatchLocked, OSError, UnicodeDecodeError) as exc:
        print(f"error: {args.scores}: nothing imported:\n{exc}", file=sys.stderr)
        return EXIT_USAGE
    print(f"imported {count} manual scores; the exports in {out}/ are updated", file=sys.stderr)
    return EXIT_OK


def cmd_export(args) -> int:
    from .cli import EXIT_OK, EXIT_USAGE

    out = Path(args.results)
    if not (out / GRADEBOOK_NAME).exists():
        print(f"error: {out} holds no gradebook (run `grade batch` first)", file=sys.stderr)
        return EXIT_USAGE
    try:
        with _locked(out):
            export_results(out)
    except BatchLocked as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    print(f"wrote the exports in {out}/", file=sys.stderr)
    return EXIT_OK


def add_batch_parser(sub) -> None:
    from .cli import _problem_number

    p = sub.add_parser(
        "batch",
        help="grade every submission of a folder",
        description="Grade every student of a folder (one folder, .zip or .ipynb per student) in parallel into a "
                    "gradebook; an interrupted batch resumes where it stopped when run again.",
    )
    p.add_argument("submissions", help="the folder of submissions")
    p.add_argument("--out", required=True, help="the results folder (gradebook, grades.csv, reports, summary)")
    p.add_argument("--problems", type=_problem_number, nargs="+", default=None, metavar="N",
                   help="problems to grade (default: every problem with checks)")
    p.add_argument("--jobs", "-j", type=int, default=None, metavar="N",
                   help="parallel workers (default: the number of CPUs)")
    p.add_argument("--force", action="store_true", help="regrade students whose submission is unchanged")
    p.add_argument("--timeout", type=float, default=None, help="seconds per call of a student's code (default 10)")
    p.add_argument("--import-timeout", type=float, default=None,
                   help="seconds for importing a student's package (default 20)")
    p.add_argument("--student-timeout", type=float, default=None,
                   help="seconds for grading one student in all (default: the import time-out plus twice the call "
                        "time-out per check)")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress display")
    p.add_argument("--no-sandbox", action="store_true",
                   help="grade even when bubblewrap is not available: students' code runs as plain processes "
                        "(under unprivileged uids when run as root); recorded in the gradebook and every report")
    p.set_defaults(func=cmd_batch)

    p = sub.add_parser("import-manual", help="merge a CSV of manual scores into a gradebook",
                       description="Merge manual scores (columns student, problem, key, score, optional comment; "
                                   "the file manual_answers.csv with its score column filled in) into the gradebook "
                                   "of RESULTS and update its exports.")
    p.add_argument("results", help="the results folder of `grade batch`")
    p.add_argument("scores", help="the CSV file of scores")
    p.set_defaults(func=cmd_import_manual)

    p = sub.add_parser("export", help="rewrite the exports of a gradebook",
                       description="Rewrite grades.csv, the class summary and the students' reports from the "
                                   "gradebook of RESULTS.")
    p.add_argument("results", help="the results folder of `grade batch`")
    p.set_defaults(func=cmd_export)
