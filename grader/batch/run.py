"""Running a batch: the students to grade, the workers (or a Dask cluster) that grade them, and the gradebook that
records each student in one transaction as their result arrives."""

from __future__ import annotations

import fcntl
import os
import signal
import threading
import time
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path

from ..errors import SandboxError, SubmissionError
from ..faults import stored
from ..results import Status
from ..sandbox import BWRAP_FIX, Limits, canary, sandbox_mode
from ..sources import grader_version
from .course import Course, entry_time
from .discover import discover, student_seed
from .exports import COURSE_META, RECORDED, StudentExporter, export_results
from .gradebook import Gradebook
from .pool import Task, run_pool, stopped_reports
from .progress import Progress

__all__ = ["BatchReport", "BatchLocked", "NotInstructorInstallation", "run_batch", "default_student_timeout",
           "instructor_installation"]


class BatchLocked(RuntimeError):
    """Another process is writing to the results folder."""


class NotInstructorInstallation(RuntimeError):
    """The grader was asked to grade a class where the reference solution is not (the student kit)."""


#: what a batch run from the student kit is told: it would grade with the kit's answer key, which holds neither the
#: multiple-choice and predicted-output keys nor the hidden checks, and score those 0 as if graded
NEEDS_INSTRUCTOR = (
    "{command} needs the instructor's installation (the full project, with the reference solution): {why}, so "
    "the multiple-choice, predicted-output and hidden checks could not be graded. Run {command} where the course's "
    "project is installed (`pip install -e .` in its folder); students check their own work with "
    "`grade problem-N`."
)


def instructor_installation(command: str = "grade batch") -> str | None:
    """None where submissions can be graded (the live reference); else what to tell the instructor."""
    from ..oracle import current, reference_available

    if not reference_available():
        return NEEDS_INSTRUCTOR.format(command=command, why="this is the student kit, which has no reference")
    if current().mode == "kit":
        return NEEDS_INSTRUCTOR.format(command=command, why="the student kit's answer key is installed here and "
                                                            "would stand in for the reference")
    return None


@dataclass
class BatchReport:
    run_id: int
    students: int
    graded: int = 0  # recorded in this run, including those stopped at the time limit
    skipped: int = 0
    timed_out: list[str] = field(default_factory=list)  # recorded in this run as stopped at the time limit
    skipped_timed_out: list[str] = field(default_factory=list)  # unchanged, and stopped when they were graded
    not_graded: dict[str, str] = field(default_factory=dict)  # grader faults: retried on the next run
    ignored: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)  # what the exports had to say (submission times, roster)
    interrupted: bool = False
    seconds: float = 0.0
    student_exports: float = 0.0  # seconds spent writing students' files as they were recorded (its own process)
    final_exports: float = 0.0  # seconds spent writing the class's files at the end

    @property
    def end_line(self) -> str:
        """Every student counted once: graded, unchanged, stopped at the time limit, not graded (and, when
        interrupted, not reached)."""
        stopped = len(self.skipped_timed_out)
        one = stopped == 1
        before = (f"; {stopped} of them {'was' if one else 'were'} stopped at the time limit when graded: --force "
                  f"grades {'it' if one else 'them'} again") if stopped else ""
        reached = self.graded + self.skipped + len(self.not_graded)
        left = f", {self.students - reached} not reached" if self.interrupted and reached < self.students else ""
        return (f"{self.students} students: {self.graded - len(self.timed_out)} graded, {self.skipped} unchanged "
                f"(skipped{before}), {len(self.timed_out)} stopped at the time limit, {len(self.not_graded)} not "
                f"graded{left} in {self.seconds:.1f} s.")

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


@contextmanager
def _cluster_client(address: str | None, credentials=None):
    """A Dask client of the cluster at ``address`` for the batch (None: no cluster), with ``credentials``
    (``grader.batch.cluster.Credentials``)."""
    if address is None:
        yield None
        return
    from .cluster import Credentials, open_client

    client, cluster = open_client(address, credentials or Credentials())
    try:
        yield client
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _interrupt(signum, frame):
    """SIGTERM during a batch: it stops as after Ctrl-C.  Later SIGTERMs are ignored from then on (a supervisor or an
    operator may repeat the signal), so that the clean-up that follows (the workers stopped, the run's state
    recorded, the temporary folders removed) is not cut short, nor the process's end that it leads to."""
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    raise KeyboardInterrupt


def _time(entry) -> tuple[str, str]:
    when = entry_time(entry)
    return when.at.isoformat(), when.source


def empty_folder(submissions, ignored: list[str]) -> str:
    """What a batch over a folder without a submission says: what it found, and what a student's entry is."""
    found = f" (it holds only {', '.join(ignored[:5])}{', ...' if len(ignored) > 5 else ''})" if ignored else ""
    return (f"{submissions} holds no submission{found}: put one entry per student in it, a folder, a .zip "
            "archive or a .ipynb notebook named after the student, and run the command again")


def default_student_timeout(limits: Limits, problems: list[int]) -> float:
    """The import time-out plus twice the call time-out per check."""
    from ..checking import checks_of
    from ..problems import problem_module

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
    cluster: str | None = None,
    course: Course | None = None,
    credentials=None,
) -> BatchReport:
    """Grade every student of ``submissions`` into the gradebook in ``out``, then write the exports.

    Without bubblewrap, students' code runs as plain processes: only with ``no_sandbox`` (recorded in the run and
    in every report), else ``SandboxError``.  One worker is started first (a canary): when it cannot start, the
    batch stops with ``SandboxError`` before anyone is graded.  With ``cluster`` (a Dask scheduler's address, or
    ``local:N``), the students are graded on that cluster's workers (``grader.batch.cluster``), which must all
    have the same grader and, unless ``no_sandbox``, bubblewrap; ``credentials`` (``grader.batch.cluster.
    Credentials``) say how the client authenticates, or that the instructor chose plain TCP (recorded in the run).

    Each student's submission time (``grader.batch.course.entry_time``) is recorded for the deadlines of a course;
    ``course`` (its file recorded in the gradebook for the exports that follow) gives the exports its assignments'
    scores.

    In the main thread, SIGTERM stops the batch as Ctrl-C does (``interrupted`` in the report); the process
    ignores SIGTERM from then on, as it is asked to end."""
    from ..problems import problems as all_problems

    start = time.monotonic()
    out = Path(out)
    entries, ignored = _students(submissions, out)
    numbers = sorted(problems or [p.number for p in all_problems()])
    limits = limits or Limits()
    jobs = max(1, jobs or len(os.sched_getaffinity(0)))
    student_timeout = student_timeout or default_student_timeout(limits, numbers)
    mode, reached = _sandbox(cluster, credentials, no_sandbox)
    with _locked(out), Gradebook.in_folder(out) as book, _cluster_client(cluster, credentials) as client:
        entries = _seeded(entries, book)
        versions = {n: grader_version(n) for n in numbers}
        if client is not None:
            sandbox, jobs = _cluster_sandbox(client, cluster, reached, numbers, versions, no_sandbox)
        else:
            sandbox = _local_sandbox(limits, mode)
        run_id = _start_run(book, submissions, numbers, jobs, force, sandbox, entries, course)
        report = BatchReport(run_id, len(entries), ignored=ignored)
        tasks = _tasks(entries, numbers, book, versions, force, report)
        bar = Progress(len(tasks), report.skipped, enabled=progress)
        exporter = StudentExporter(out, course.with_problems(numbers) if course else None) \
            if export and tasks else None
        record = _Recorder(book, versions, run_id, force, student_timeout, report, bar, exporter)
        with _sigterm_stops():
            state = "interrupted"
            try:
                _grade(tasks, record, client, cluster, jobs, limits, mode, numbers, student_timeout, no_sandbox)
                state = "finished"
            except KeyboardInterrupt:
                report.interrupted = True
            finally:
                _close_run(book, run_id, state, report, bar, exporter)
        if export and not report.interrupted:
            _export_class(out, book, course, report)
        report.seconds = time.monotonic() - start
    _sweep_slots()
    return report


#: how long [s] the end of a batch waits for its own slots that are still ending to remove their folders
SLOTS_ENDING = 10.0


def _sweep_slots() -> None:
    """The staging folders of this machine's grading slots that ended without removing them (a slot killed before
    its clean-up ran): the workers are stopped by now, though a process of this batch may still be ending (waited
    for, ``SLOTS_ENDING``, then swept again).  Looked for where the slots made them, the temporary folder of a
    process started now (``TMPDIR`` as it is set; this process's own may have been fixed before)."""
    from ..sandbox.zygote import ending_slots, sweep_orphans

    folder = os.environ.get("TMPDIR")
    where = Path(folder) if folder and Path(folder).is_dir() else None
    deadline = time.monotonic() + SLOTS_ENDING
    sweep_orphans(where)
    while ending_slots(where) and time.monotonic() < deadline:
        time.sleep(0.1)
        sweep_orphans(where)


# ---------------------------------------------------------------------------------------------- run_batch's steps


def _students(submissions, out: Path) -> tuple[list, list[str]]:
    """The students' entries of ``submissions`` and the names it ignored; refused (``NotInstructorInstallation``,
    ``SubmissionError``) where there is no reference to grade with or no student to grade."""
    refused = instructor_installation()
    if refused is not None:
        raise NotInstructorInstallation(refused)
    if not Path(submissions).is_dir():
        raise SubmissionError(f"{submissions} is not a folder")
    entries, ignored = discover(submissions, exclude=out)
    if not entries:
        raise SubmissionError(empty_folder(submissions, ignored))
    return entries, ignored


def _sandbox(cluster: str | None, credentials, no_sandbox: bool):
    """The sandbox mode of a batch on this machine (None on a cluster) and, on a cluster, how it is reached
    (refused before anything is opened); a machine without bubblewrap grades only with ``no_sandbox``."""
    mode = sandbox_mode() if cluster is None else None
    reached = None
    if cluster is not None:
        from .cluster import Credentials, transport

        reached = transport(cluster, credentials or Credentials())
    if mode is not None and not mode.isolated and not no_sandbox:
        raise SandboxError(f"bubblewrap is not available, so students' code would run without a sandbox: install "
                           f"it ({BWRAP_FIX}), or pass --no-sandbox to grade without one (recorded in the gradebook "
                           "and in every report)")
    return mode, reached


def _seeded(entries: list, book: Gradebook) -> list:
    """Each student's seed: from their submission and the results folder's secret."""
    secret = book.seed_secret()
    return [replace(entry, seed=student_seed(entry.content_hash, secret)) for entry in entries]


def _cluster_sandbox(client, cluster: str, reached, numbers, versions, no_sandbox: bool) -> tuple[str, int]:
    """What the run records of the cluster's sandbox, once its workers are checked, and its number of workers."""
    from .cluster import check_workers

    note, isolated = check_workers(client, numbers, versions, no_sandbox)
    sandbox = f"Dask cluster {cluster} ({reached}): {note}"
    return (sandbox if isolated else f"--no-sandbox: {sandbox}"), len(client.scheduler_info()["workers"])


def _local_sandbox(limits: Limits, mode) -> str:
    """What the run records of this machine's sandbox, once a canary worker has started in it."""
    canary(limits, mode)
    return mode.note if mode.isolated else f"--no-sandbox: {mode.note}"


def _start_run(book: Gradebook, submissions, numbers, jobs: int, force: bool, sandbox: str, entries,
               course: Course | None) -> int:
    """Record the run in the gradebook, with the students' submission times and the course's file."""
    run_id = book.start_run(str(submissions), numbers, jobs, force, sandbox=sandbox)
    book.note_submission_times([(e.name, e.content_hash, *_time(e)) for e in entries])
    if course is not None and course.path is not None:
        book.set_meta(COURSE_META, str(Path(course.path).resolve()))
    return run_id


def _tasks(entries, numbers, book: Gradebook, versions, force: bool, report: BatchReport) -> list[Task]:
    """A task for each student with a problem to grade (all of them with ``force``; else those whose submission
    or grading code changed); the others are counted as skipped in ``report``."""
    tasks = []
    for entry in entries:
        todo = set(numbers)
        if not force:
            todo -= book.graded_problems(entry.name, entry.content_hash, versions)
        if todo:
            tasks.append(Task(entry, tuple(sorted(todo))))
        elif book.stopped(entry.name):
            report.skipped_timed_out.append(entry.name)
    report.skipped = len(entries) - len(tasks)
    return tasks


@dataclass
class _Recorder:
    """What happens to each student's result as it arrives (``done`` of the pool and the cluster): recorded in
    the gradebook in one transaction, their files exported, the progress advanced; a grader fault is never a
    grade (``grader.faults``): the student is graded again on the next run."""

    book: Gradebook
    versions: dict
    run_id: int
    force: bool
    student_timeout: float
    report: BatchReport
    bar: Progress
    exporter: StudentExporter | None

    def __call__(self, task: Task, kind: str, payload, seconds: float) -> None:
        name = task.entry.name
        if kind == "ok" and not stored(payload):  # the grader's fault is never a grade (grader.faults): the
            faults = [r for rep in payload for r in rep.results if r.status is Status.GRADER_ERROR]
            kind, payload = "fault", faults[0].message.splitlines()[0]  # student is graded on the next run
        if kind == "ok":
            reports, outcome = payload, "graded"
        elif kind == "timeout":
            load = f" (and {payload:.0f} s more for the machine's load)" if payload and payload >= 0.5 else ""
            message = (f"grading this submission took longer than the batch's limit of {self.student_timeout:g} s "
                       f"per student{load} and was stopped: look for very slow or endless loops.")
            reports, outcome = stopped_reports(task, Status.TIMEOUT, message, seconds), "timeout"
            self.report.timed_out.append(name)
        else:
            self.report.not_graded[name] = str(payload).strip().splitlines()[-1] if payload else kind
            self.bar.advance(name, f"not graded ({self.report.not_graded[name]}); retried on the next run")
            return
        self.book.record(name, task.entry.content_hash, self.versions, self.run_id, reports, outcome,
                         replace_existing=self.force)
        self.report.graded += 1
        if self.exporter is not None:  # the student's own files now, while the workers grade the next students
            self.exporter.submit(name, self.book)
        score = sum(r.score for r in reports)
        self.bar.advance(name, f"{score:g}/{sum(r.max_score for r in reports):g} ({seconds:.1f} s)")


def _grade(tasks: list[Task], record: _Recorder, client, cluster: str | None, jobs: int, limits: Limits, mode,
           numbers, student_timeout: float, no_sandbox: bool) -> None:
    """Grade ``tasks`` on the cluster's workers (``client``) or on ``jobs`` slots of this machine, each student's
    result handed to ``record`` as it arrives."""
    if tasks and client is not None:
        from .cluster import run_cluster

        run_cluster(client, tasks, limits=limits, problems=tuple(numbers), student_timeout=student_timeout,
                    no_sandbox=no_sandbox, ship=not cluster.startswith("local:"), done=record)
    elif tasks:
        run_pool(tasks, jobs, limits, mode, tuple(numbers), student_timeout, record)


def _close_run(book: Gradebook, run_id: int, state: str, report: BatchReport, bar: Progress,
               exporter: StudentExporter | None) -> None:
    """End the run (``finished`` or ``interrupted``): the progress closed, the students' exports finished (their
    seconds in ``report``), the run's state recorded."""
    bar.close()
    if exporter is not None:
        report.student_exports = exporter.close(finish=state == "finished")
    book.finish_run(run_id, state, report.skipped)


def _export_class(out: Path, book: Gradebook, course: Course | None, report: BatchReport) -> None:
    """The class's files at the end of a finished run (their seconds in ``report``)."""
    began = time.monotonic()
    export_results(out, book, students=None, course=course or RECORDED, notes=report.notes)
    report.final_exports = time.monotonic() - began


@contextmanager
def _sigterm_stops():
    """In the main thread, SIGTERM inside the block stops the batch as Ctrl-C does (``_interrupt``); after it, the
    previous handler is back, unless a SIGTERM came (the process then ignores the ones that follow)."""
    in_main = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGTERM, _interrupt) if in_main else None
    try:
        yield
    finally:
        if in_main and signal.getsignal(signal.SIGTERM) is _interrupt:  # else a SIGTERM stopped the batch
            signal.signal(signal.SIGTERM, previous)
