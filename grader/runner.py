"""Grading: run a problem's checks against a submission and collect the results.

``grade_problem(problem, submission)`` is the API that the CLI and the batch grader call; ``grade_submission``
grades several problems of one submission with a single sandboxed worker.
"""

from __future__ import annotations

import random
import re
import time
from dataclasses import replace
from functools import lru_cache
from pathlib import Path

from . import __version__, problems
from .checking import SHEET_NOTE, CheckFailure, JudgedOnSubmission, NotAnswered, checks_of
from .context import Context, explained
from .errors import GraderFault, SandboxError, StudentCodeError, StudentTimeout, SubmissionError, WorkerCrash
from .faults import fault_of
from .problems import problem_module
from .results import CheckResult, ManualItem, ProblemReport, Status
from .sandbox import SandboxMode, sandbox_mode
from .workers import Fresh, Worker, Workers

__all__ = ["grade_problem", "grade_submission", "carry_forward", "unloadable_reports", "not_run"]


# ------------------------------------------------------------------------------------------ one check


def _student_error(exc) -> tuple[Status, str, str]:
    """Status, message and hint for a failure of the student's code."""
    if isinstance(exc, StudentTimeout):
        where = "importing your package" if exc.phase == "import" else "your code"
        return (
            Status.TIMEOUT,
            f"{where} did not finish within {exc.seconds:g} s.",
            "Look for an infinite loop or a loop that runs far more steps than asked.",
        )
    if isinstance(exc, WorkerCrash):
        where = " while importing your package" if exc.phase == "import" else ""
        return Status.ERROR, f"{exc.detail}{where}.", "Run your code locally: does it exit, or allocate huge arrays?"
    if not isinstance(exc, StudentCodeError):
        return Status.ERROR, str(exc), ""
    if exc.kind == "not_implemented":
        return Status.NOT_IMPLEMENTED, f"not implemented yet: {exc.message}", ""
    if exc.kind == "answers":
        return Status.ERROR, exc.message, "Fix the syntax of answers.toml (strings in quotes, one key per line)."
    if exc.kind == "exit":
        return (
            Status.ERROR,
            f"your code called sys.exit({exc.message}) {'at import' if exc.phase == 'import' else ''}".rstrip() + ".",
            "Remove calls to sys.exit()/exit()/quit() from the package.",
        )
    if exc.kind == "bad_value":
        return Status.ERROR, f"your function returned a value that cannot be graded: {exc.message}", (
            "Return numbers, numpy arrays, lists or dicts of them."
        )
    if exc.phase == "import":
        return (
            Status.ERROR,
            f"your package could not be imported: {exc.type_name}: {exc.message}\n{exc.traceback}".rstrip(),
            f"Fix {_where(exc.traceback) or 'this'} first: no check can run until the package imports.",
        )
    return Status.ERROR, f"your code raised {exc.type_name}: {exc.message}\n{exc.traceback}".rstrip(), ""


#: where a traceback of the submission points: its last frame's file and line
_FRAME = re.compile(r'File "([^"\n]{1,200})", line (\d+)')


def _where(traceback: str) -> str:
    """``line N of FILE`` for the last frame of a student's traceback (a cell of a notebook: ``FILE, cell K``), or
    ""."""
    frames = _FRAME.findall(traceback or "")
    return f"line {frames[-1][1]} of {frames[-1][0]}" if frames else ""


def _said_once(said: dict, title: str, message: str, hint: str) -> tuple[str, str]:
    """A failure of the submission's import is the same for every check that needs the package: the first check
    it stops says it in full (``said``: its first line -> that check's title), the others point there."""
    head = message.splitlines()[0] if message else ""
    if head not in said:
        said[head] = title
        return message, hint
    return f"not run: {head} (said in full at “{said[head]}”)", ""


def _run_check(spec, ctx: Context, problem: int, said: dict | None = None) -> CheckResult:
    ctx.begin(problems.check_id(problem, spec.name))
    start = time.perf_counter()
    hint = diagnosis = ""
    try:
        spec.func(ctx)
        status, message = Status.PASSED, ""
    except CheckFailure as exc:
        exc = explained(ctx, exc)  # no known mistake named it: the diagnosis engine's cause, if any
        status, message, hint, diagnosis = Status.FAILED, exc.message, exc.hint, exc.diagnosis
    except NotAnswered as exc:
        status, message = Status.NOT_IMPLEMENTED, str(exc)
    except JudgedOnSubmission as exc:
        status, message = Status.DEFERRED, exc.message
    except SandboxError:  # the installation's fault: no check can run, nothing is graded
        raise
    except Exception as exc:  # noqa: BLE001 - whose fault it is, is the table's (grader.faults)
        if fault_of(exc).student:
            status, message, hint = _student_error(exc)
            final = getattr(exc, "phase", "") == "import" and getattr(exc, "kind", "") != "not_implemented"
            if final and said is not None:  # the import's failure: the same for every check that follows
                message, hint = _said_once(said, spec.title, message, hint)
        else:  # a crashing check, a probe the worker cannot run, the reference raising: the grader's defect
            shown = str(exc) if isinstance(exc, GraderFault) else f"{type(exc).__name__}: {exc}"
            status, message = Status.GRADER_ERROR, f"internal grader error (not your fault): {shown}"
    if status is Status.PASSED and ctx.sheet_digits:  # the kit: the key held the sheet's cases at its digits only
        hint = _join(hint, SHEET_NOTE[0].upper() + SHEET_NOTE[1:] + ".")
    return CheckResult(
        check_id=problems.check_id(problem, spec.name),
        problem=problem,
        title=spec.title,
        status=status,
        score=spec.points if status is Status.PASSED else 0.0,
        max_score=spec.points,
        message=message,
        hint=hint,
        diagnosis=diagnosis,
        visibility=spec.visibility,
        stage=spec.stage,
        seed=ctx.last_seed,
        figures=tuple(ctx.figures),
        duration=time.perf_counter() - start,
    )


#: the message of a check that the student kit does not grade
DEFERRED_MESSAGE = ("graded when you submit: the key of this check stays with your instructor (your answer is "
                    "taken from your submission)")


def not_run(spec, problem: int, status: Status, message: str) -> CheckResult:
    """The result of a check that did not run (an earlier stage failed, the submission cannot be loaded, a batch
    stopped the student's grading)."""
    return CheckResult(
        check_id=problems.check_id(problem, spec.name),
        problem=problem,
        title=spec.title,
        status=status,
        score=0.0,
        max_score=spec.points,
        message=message,
        visibility=spec.visibility,
        stage=spec.stage,
    )


def _run_checks(module, ctx: Context, problem: int) -> list[CheckResult]:
    try:
        return _run_all(module, ctx, problem)
    finally:
        ctx.close()


def _run_all(module, ctx: Context, problem: int) -> list[CheckResult]:
    results = []
    blocked: dict[str, tuple[int, str, str, bool]] = {}  # group → (stage, title, check id, grader at fault)
    blockers: dict[str, str] = {}  # a skipped check -> the failed check that blocked it
    carried: dict[str, list[tuple[str, str]]] = {}  # a passed check -> its (upstream check, what) judged on
    said: dict[str, str] = {}  # a failure of the submission's import, said in full once
    for spec in checks_of(module):
        check_id = problems.check_id(problem, spec.name)
        if not ctx.oracle.runs(spec, check_id):
            results.append(not_run(spec, problem, Status.DEFERRED, DEFERRED_MESSAGE))
            continue
        block = blocked.get(spec.group)
        if block is not None and spec.stage > block[0]:
            if block[3]:  # the earlier check is the grader's fault: so is this one's not running
                results.append(not_run(spec, problem, Status.GRADER_ERROR, "internal grader error (not your "
                                        f"fault): not run, the earlier check could not run ({block[1]})"))
            else:
                results.append(not_run(spec, problem, Status.SKIPPED,
                                        f"not run: an earlier check failed first ({block[1]})"))
                blockers[check_id] = block[2]
            continue
        result = _run_check(spec, ctx, problem, said)
        ctx.end(result.passed)
        results.append(result)
        if result.passed and ctx.carried:
            carried[check_id] = list(ctx.carried)
        if not result.passed and result.status is not Status.DEFERRED and (block is None or spec.stage < block[0]):
            blocked[spec.group] = (spec.stage, spec.title, check_id, result.status is Status.GRADER_ERROR)
    return carry_forward(results, carried, blockers)


def carry_forward(results: list[CheckResult], carried: dict, blockers: dict) -> list[CheckResult]:
    """Error carried forward: a check that passed on the student's own upstream results (``carried``: check id
    -> ``[(upstream check id, what)]``) keeps its full credit and points at the failed check that finds the
    upstream mistake (its *root*: the upstream check itself, the check that blocked it when it was skipped, or
    the root of the upstream check when that one was carried forward too).  The root names the mistake once and
    lists the checks judged on it."""
    by_id = {r.check_id: r for r in results}

    def root_of(check_id: str, seen: frozenset = frozenset()) -> tuple[str, str] | None:
        """The failed check behind ``check_id`` and the upstream results named there, or None."""
        result = by_id.get(check_id)
        if result is None or check_id in seen:
            return None
        if result.status is Status.SKIPPED and check_id in blockers:
            return root_of(blockers[check_id], seen | {check_id})
        if result.passed:
            for upstream, what in carried.get(check_id, ()):
                found = root_of(upstream, seen | {check_id})
                if found is not None:
                    return found if found[1] else (found[0], what)
            return None
        return (check_id, "") if result.status is Status.FAILED or result.status is Status.ERROR else None

    followers: dict[str, list[str]] = {}
    names: dict[str, str] = {}
    notes: dict[str, str] = {}
    for check_id, hops in carried.items():
        what = hops[0][1]
        root = None
        for upstream, hop_what in hops:
            found = root_of(upstream)
            if found is not None:
                root, what = found[0], (found[1] or hop_what)
                break
        if root is None:
            elsewhere = [title for title in (_title_elsewhere(upstream, by_id) for upstream, _ in hops) if title]
            one = "," not in what
            notes[check_id] = (f"Judged on your own {what}, which {'differs' if one else 'differ'} from the "
                               "reference's (error carried forward: full credit here); " +
                               (f"{'it is' if one else 'they are'} graded by {elsewhere[0]}." if elsewhere else
                                f"compare {'it' if one else 'them'} with the reference's."))
            continue
        followers.setdefault(root, []).append(check_id)
        names.setdefault(root, what)
        notes[check_id] = (f"Judged on your own {what} (error carried forward: full credit). "
                           f"{'It is' if ',' not in what else 'They are'} wrong: see “{by_id[root].title}”.")
    out = []
    for result in results:
        if result.check_id in notes:
            result = replace(result, hint=_join(result.hint, notes[result.check_id]))
        elif result.check_id in followers:
            titles = "; ".join(f"“{by_id[c].title}”" for c in followers[result.check_id])
            result = replace(result, hint=_join(result.hint, (
                f"Later checks use your {names[result.check_id]}, so their values differ from the reference's "
                f"too: {titles}. They were judged on your {names[result.check_id]} and are otherwise right "
                f"(error carried forward: this mistake costs only the points of this check).")))
        out.append(result)
    return out


def _title_elsewhere(check_id: str, by_id: dict) -> str:
    """``problem N's check “title”`` for a check of another problem than the one graded, else ""."""
    return "" if check_id in by_id else problems.check_title(check_id)


def _join(first: str, second: str) -> str:
    return f"{first}\n{second}" if first else second


@lru_cache(maxsize=4)
def _model_answers(oracle) -> dict:
    """The reference's answers.toml, read once per process (it holds the model answers of free-text questions;
    the student kit has none)."""
    return oracle.model_answers()


def _manual_items(module, ctx: Context, problem: int) -> list[ManualItem]:
    manual = getattr(module, "MANUAL", {})
    if not manual:
        return []
    model = _model_answers(ctx.oracle).get(f"problem_{problem:02d}", {}).get("free_text", {})
    texts = ctx.free_text()
    return [
        ManualItem(problem, key, question, str(texts.get(key, "") or ""), str(model.get(key, "")), float(points))
        for key, (question, points) in manual.items()
    ]


# ------------------------------------------------------------------------------------------ public API


def grade_submission(
    source: str | Path,
    numbers: list[int],
    *,
    seed: int | None = None,
    workers: Workers | None = None,
    oracle=None,
    record_answers: bool = False,
) -> list[ProblemReport]:
    """Grade the given problems of one submission with the sandboxed workers of ``workers`` (``grader.workers``:
    ``Fresh``, the default, a new child; ``Forked`` from a batch slot's warm process; ``Started`` by the caller
    before its imports, as ``grade problem-N`` does); ``oracle`` answers for the reference (default: the
    process's, see ``grader.oracle.current``).  Each worker is ended as soon as the last check has its last reply.
    ``record_answers``: each report also holds the wrong answers on the inputs every student is asked
    (``grader.answers``), for ``grade similarity`` (a batch does).

    Where ``workers`` gives more than one worker (``Fresh(count=2)``), the problems are shared out among them,
    each with its own copy of the submission, and graded side by side (``_grade_side_by_side``); the reports come
    back in the order of ``numbers``.  A batch grades each student with one worker: its slots already keep the
    cores busy.

    Raises ``SandboxError`` (a ``GraderFault``) when the worker cannot be started or cannot import its
    dependencies: a fault of the installation, for which nothing is graded."""
    seed = random.randrange(2**31) if seed is None else seed
    workers = Fresh() if workers is None else workers
    if not isinstance(workers, Workers):
        raise TypeError(f"workers must be Fresh, Forked or Started (grader.workers), not {workers!r}")
    modules = {n: problem_module(n) for n in numbers}
    try:
        taken = workers.obtain(source, workers.side_by_side(len(numbers)))
    except SubmissionError as exc:
        return [_unloadable(n, modules[n], source, str(exc), workers.sandbox(), seed) for n in numbers]
    try:
        if len(taken) > 1:
            return _grade_side_by_side(taken, numbers, modules, seed, oracle, record_answers)
        queue = list(numbers)
        return _grade_in(taken[0], lambda: queue.pop(0) if queue else None, modules, seed, oracle, record_answers)
    finally:
        workers.release(taken)


def _grade_in(worker: Worker, take, modules, seed, oracle, record_answers=False) -> list[ProblemReport]:
    """The reports of the problems that ``take()`` hands out (None: no more), graded with ``worker``."""
    submission, child = worker.submission, worker.child
    reports = []
    with child:
        child.start()
        number = take()
        while number is not None:
            start = time.perf_counter()
            ctx = Context(number, child, submission.answers, submission.answers_error, seed, oracle,
                          record_answers)
            results = _run_checks(modules[number], ctx, number)
            ctx.ask_common({r.check_id for r in results if r.status is Status.FAILED})
            stdout, stderr = child.output()
            following = take()
            if following is None:
                child.close()  # its last reply is in: nothing more to ask it
            reports.append(
                ProblemReport(
                    problem=number,
                    title=modules[number].TITLE,
                    results=tuple(results),
                    manual=tuple(_manual_items(modules[number], ctx, number)),
                    sandbox=child.note,
                    isolated=child.mode.isolated,
                    seed=seed,
                    duration=time.perf_counter() - start,
                    stdout=stdout,
                    stderr=stderr,
                    submission=submission.source,
                    grader_version=__version__,
                    notes=submission.problem_notes(number) + child.import_notes,
                    wrong_answers=tuple(ctx.wrong_answers),
                )
            )
            number = following
    return reports


def _grade_side_by_side(taken: list[Worker], numbers, modules, seed, oracle, record_answers=False):
    """``grade_submission`` with the workers ``taken``, one thread of this process each (the student's code runs
    in the workers; the threads mostly wait for their replies).  Each worker takes the next problem of ``numbers``
    when it is free, so a long problem does not hold up the rest.  Every worker has a copy of its own and the same
    limits as a single one; a problem is graded the same in either: its checks' inputs come from the seed and the
    problem, not from the order.  A grader fault in one worker ends the grading with that fault, as with one
    worker; an interruption (Ctrl-C) kills every worker before it goes on."""
    import threading

    count = len(taken)
    queue, lock = list(numbers), threading.Lock()
    outcomes: list = [None] * count
    finished = threading.Semaphore(0)  # waited on rather than Thread.join: an interrupted join (3.11) can take a
    # thread that still runs for ended

    def take():
        with lock:
            return queue.pop(0) if queue else None

    def work(index: int) -> None:
        try:
            outcomes[index] = ("ok", _grade_in(taken[index], take, modules, seed, oracle, record_answers))
        except BaseException as exc:  # noqa: BLE001 - handed to the calling thread, raised there
            with lock:
                queue.clear()  # the other workers stop after their current problem
            outcomes[index] = ("raised", exc)
        finally:
            finished.release()

    threads = [threading.Thread(target=work, args=(i,), name=f"grade-worker-{i}", daemon=True)
               for i in range(count)]
    ended = 0
    try:
        for thread in threads:
            thread.start()
        while ended < count:
            finished.acquire()
            ended += 1
    except BaseException:  # Ctrl-C: every worker killed now, and the threads' waits for replies end with them
        with lock:
            queue.clear()
        for worker in taken:
            worker.child.interrupt()
        running = sum(1 for thread in threads if thread.ident is not None)
        for worker in taken[running:]:  # never handed to a thread
            worker.child.__exit__(None, None, None)
        deadline = time.monotonic() + 30
        while ended < running and finished.acquire(timeout=max(0.0, deadline - time.monotonic())):
            ended += 1
        raise
    for outcome in outcomes:
        if outcome is not None and outcome[0] == "raised":
            raise outcome[1]
    order = {n: i for i, n in enumerate(numbers)}
    return sorted((r for outcome in outcomes for r in outcome[1]), key=lambda r: order[r.problem])


def grade_problem(problem: int, source: str | Path, **options) -> ProblemReport:
    """Grade one problem of a submission (a directory, a zip archive or a notebook)."""
    return grade_submission(source, [problem], **options)[0]


def unloadable_reports(source, numbers: list[int], reason: str, *, seed: int,
                       mode: SandboxMode | None = None) -> list[ProblemReport]:
    """The reports of a submission that could not be loaded, for ``reason`` (see ``_unloadable``)."""
    mode = mode or sandbox_mode()
    return [_unloadable(n, problem_module(n), source, reason, mode, seed) for n in numbers]


def _unloadable(number, module, source, reason, mode, seed) -> ProblemReport:
    """The report of a submission that could not be loaded: the reason once, for the problem (``load_error``);
    every check scores 0 with the status of the student's error and no message of its own."""
    results = tuple(not_run(spec, number, Status.ERROR, "") for spec in checks_of(module))
    return ProblemReport(number, module.TITLE, results, sandbox=mode.note, isolated=mode.isolated, seed=seed,
                         submission=str(source), grader_version=__version__, load_error=reason)
