"""The exports of a gradebook: grades.csv, manual_answers.csv, the class summary (summary.html) and, per student,
a Gradescope results.json (built by the autograder's own ``grader.gradescope.results_json``) and an HTML report
(the student's view).

A batch writes each student's own files as soon as that student is recorded (``export_student``), and the files
about the whole class once at the end (``export_results(..., students=False)``); ``grade export`` and
``grade import-manual`` rewrite everything.
"""

from __future__ import annotations

import csv
import io
import os
import statistics
from collections import Counter, defaultdict
from datetime import datetime
from pathlib import Path

from ..results import Status
from .gradebook import Gradebook, Graded, now, spreadsheet_cell

__all__ = ["DIAGNOSES", "TROUBLE", "export_results", "export_student", "StudentExporter", "class_summary",
           "scored_items", "problem_possible", "possible", "student_status"]

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


def scored_items(graded: list[Graded]) -> dict[int, dict[str, float]]:
    """Per problem, the free-text answers that a person has scored for some student of the class, with their
    points: from then on they count in every student's possible points, before that in no one's."""
    items: dict[int, dict[str, float]] = defaultdict(dict)
    for g in graded:
        for m in g.report.manual:
            if m.score is not None:
                items[m.problem][m.key] = m.max_score
    return dict(items)


def problem_possible(report, scored: dict[int, dict[str, float]]) -> float:
    """A problem's possible points: its checks' (hidden ones included), and its free-text answers' once scored for
    someone (``scored_items``); the same for every student, whether their submission could be loaded or not."""
    return report.auto_max_score + sum(scored.get(report.problem, {}).values())


def possible(items: list[Graded], scored: dict[int, dict[str, float]]) -> float:
    """A student's possible points over the problems graded (``problem_possible``)."""
    return sum(problem_possible(g.report, scored) for g in items)


def _numbers(problems: list[int]) -> str:
    return f"problem{'s' if len(problems) > 1 else ''} {', '.join(map(str, sorted(problems)))}"


def student_status(items: list[Graded]) -> str:
    """How the student's work was graded, as the gradebook recorded it: "graded", "unloadable: REASON" (said once,
    whatever the number of problems), "timed out: problem N" (stopped at the batch's limit)."""
    parts = []
    unloadable = [g for g in items if g.report.load_error]
    if unloadable:
        reason = unloadable[0].report.load_error.strip().splitlines()[0]
        parts.append(f"unloadable: {reason}")
    stopped = [g.report.problem for g in items if g.outcome == "timeout"]
    if stopped:
        parts.append(f"timed out: {_numbers(stopped)}")
    crashed = [g.report.problem for g in items if g.outcome == "crashed"]
    if crashed:
        parts.append(f"crashed: {_numbers(crashed)}")
    return "; ".join(parts) or "graded"


def _by_student(graded: list[Graded]) -> dict[str, list[Graded]]:
    students: dict[str, list[Graded]] = defaultdict(list)
    for g in graded:
        students[g.student].append(g)
    return dict(sorted(students.items()))


def _student_files(out: Path, name: str, items: list[Graded]) -> None:
    from ..gradescope import render_results
    from ..render import render_html

    reports = [g.report for g in items]
    folder = out / "students" / name
    _write(folder / "results.json", render_results(reports))
    _write(folder / "report.html", render_html(reports, title=f"Grading report: {name}"))


def export_student(out: str | Path, book: Gradebook, name: str) -> None:
    """Write one student's results.json and report.html from the gradebook (every problem's current result, the
    manual scores merged): what a batch does as soon as it recorded the student."""
    items = book.current(student=name)
    if items:
        _student_files(Path(out), name, items)


class StudentExporter:
    """Writes each recorded student's files in a process of its own, while the batch goes on: the batch's own
    process stays free to hand out students and record results (and, on a Dask client, to the scheduler's
    threads).  Students whose files it could not write are written by ``export_results(..., students=None)``."""

    def __init__(self, out: str | Path):
        import multiprocessing

        context = multiprocessing.get_context("spawn")
        self.conn, theirs = context.Pipe()
        self.process = context.Process(target=_export_loop, args=(theirs, str(out), os.getpid()), daemon=True,
                                       name="grade-exporter")
        self.process.start()
        theirs.close()
        self.out, self.failed = Path(out), False

    def submit(self, name: str, book: Gradebook) -> None:
        if not self.failed:
            try:
                self.conn.send(name)
                return
            except OSError:  # the exporter died: this process writes the files from now on
                self.failed = True
        export_student(self.out, book, name)

    def close(self, finish: bool = True) -> float:
        """Wait until every submitted student is written (``finish``) or stop now; the exporter's busy seconds."""
        seconds = 0.0
        try:
            if finish and not self.failed:
                self.conn.send(None)
                seconds = self.conn.recv()
        except (OSError, EOFError):
            pass
        finally:
            if self.process.is_alive():
                self.process.terminate()
            self.process.join(5)
            self.conn.close()
        return seconds


def _export_loop(conn, out: str, parent: int) -> None:
    import signal
    import time

    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the batch's to handle
    from .pool import _die_with_parent

    _die_with_parent(parent)
    busy = 0.0
    with Gradebook.in_folder(out) as book:
        while True:
            try:
                name = conn.recv()
            except (EOFError, OSError):
                return
            if name is None:
                conn.send(busy)
                return
            began = time.monotonic()
            export_student(out, book, name)
            busy += time.monotonic() - began


def _stale(out: Path, name: str, items: list[Graded]) -> bool:
    """Whether a student's files are missing or older than the student's latest result."""
    try:
        written = min((out / "students" / name / file).stat().st_mtime for file in ("results.json", "report.html"))
    except OSError:
        return True
    latest = max(datetime.fromisoformat(g.graded_at).timestamp() for g in items)
    return written < latest


def export_results(out: str | Path, book: Gradebook | None = None, students: bool | None = True) -> dict[str, Path]:
    """Write grades.csv, manual_answers.csv, summary.html and each student's results.json and report.html.

    ``students=None`` writes only the students' files that are missing or older than their latest result (a batch,
    which wrote each student's files as it recorded them); ``False`` none of them."""
    out = Path(out)
    if book is None:
        with Gradebook.in_folder(out) as own:
            return export_results(out, own, students)
    graded = book.current(figures=False)  # the class's files need no figures; a student's own are read below
    by_student = _by_student(graded)
    numbers = sorted({g.report.problem for g in graded})
    scored = scored_items(graded)
    rows = [["student", *[f"problem_{n}" for n in numbers], "total", "possible", "status"]]
    for name, items in by_student.items():
        scores = {g.report.problem: g.report.score for g in items}
        rows.append([name, *[f"{scores[n]:g}" if n in scores else "" for n in numbers],
                     f"{sum(scores.values()):g}", f"{possible(items, scored):g}", student_status(items)])
    paths = {"grades": out / "grades.csv", "manual": out / "manual_answers.csv", "summary": out / "summary.html"}
    _write(paths["grades"], _csv(rows))
    comments = book.manual_comments()
    manual = [["student", "problem", "key", "score", "max_score", "question", "answer", "comment"]]
    manual += [[g.student, m.problem, m.key, "" if m.score is None else f"{m.score:g}", f"{m.max_score:g}",
                m.question, m.answer, comments.get((g.student, m.problem, m.key), "")]
               for g in graded for m in g.report.manual]
    _write(paths["manual"], _csv(manual))
    if students is not False:
        for name, items in by_student.items():
            if students or _stale(out, name, items):
                export_student(out, book, name)
    _write(paths["summary"], class_summary(graded))
    return paths


# ------------------------------------------------------------------------------------------ class summary


def _png(draw, height: float = 3.4) -> str:
    from ..render import png

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
    scored = scored_items(graded)
    problems = []
    for number, items in sorted(by_problem.items()):
        scores = [g.report.score for g in items]
        top = max(problem_possible(g.report, scored) for g in items)
        problems.append({
            "number": number, "title": items[0].report.title, "students": len(items), "max": top,
            "mean": statistics.fmean(scores), "median": statistics.median(scores), "min": min(scores),
            "full": sum(1 for s in scores if s >= top), "image": f"problem-{number}",
        })
        images[f"problem-{number}"] = _histogram(scores, top, f"Problem {number}: score distribution", "points")
    students = _by_student(graded).values()
    top = max((possible(items, scored) for items in students), default=0.0)
    if students:
        totals = [sum(g.report.score for g in items) for items in students]
        images["totals"] = _histogram(totals, top, "Total score distribution", "points")
    return problems, top


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
    """The results in which the student's code errored or timed out, or that the batch stopped; a submission that
    could not be loaded once, with the problems it stopped (the reason is the same for every problem)."""
    trouble, unloadable = [], {}
    for g in graded:
        if g.report.load_error:
            key = (g.student, g.report.load_error)
            if key in unloadable:
                unloadable[key]["numbers"].append(g.report.problem)
                continue
            message = g.report.load_error.strip()
            unloadable[key] = row = {
                "student": g.student, "numbers": [g.report.problem], "outcome": g.outcome,
                "statuses": "could not be loaded", "message": message.splitlines()[0] if message else "",
            }
            trouble.append(row)
            continue
        bad = [r for r in g.report.results if r.status in TROUBLE]
        if bad or g.outcome != "graded":
            message = bad[0].message.strip() if bad else ""
            trouble.append({
                "student": g.student, "numbers": [g.report.problem], "outcome": g.outcome,
                "statuses": ", ".join(sorted({r.status.value for r in bad})),
                "message": message.splitlines()[0] if message else "",
            })
    for row in trouble:
        row["problem"] = _ranges(sorted(row.pop("numbers")))
    return trouble


def _ranges(numbers: list[int]) -> str:
    """Problem numbers as runs: "1–5, 8, 10–12"."""
    runs: list[list[int]] = []
    for n in numbers:
        if runs and n == runs[-1][-1] + 1:
            runs[-1].append(n)
        else:
            runs.append([n])
    return ", ".join(f"{r[0]}–{r[-1]}" if len(r) > 2 else ", ".join(map(str, r)) for r in runs)


def _versions(graded: list[Graded]) -> dict:
    """The grader's versions, folded: the releases (what a reader needs), and per problem the versions of its
    checks (a digest each), flagging a problem whose students were graded by different versions of its checks."""
    by_problem: dict[int, Counter] = defaultdict(Counter)
    for g in graded:
        by_problem[g.report.problem][g.grader_version] += 1
    return {
        "releases": sorted({version.split("+")[0] for version in (g.grader_version for g in graded)}),
        "problems": [{"number": n, "versions": dict(sorted(c.items()))} for n, c in sorted(by_problem.items())],
        "mixed": [n for n, c in sorted(by_problem.items()) if len(c) > 1],
    }


def class_summary(graded: list[Graded], top_checks: int = 12, top_mistakes: int = 8) -> str:
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
    trouble = _trouble(graded)
    return env.get_template("class_summary.html.j2").render(
        generated=now(), students=len(table), problems=problems, numbers=[p["number"] for p in problems],
        problem_runs=_ranges([p["number"] for p in problems]),
        possible=possible, images=images, failing=failing, mistakes=mistakes, top_mistakes=top_mistakes,
        trouble=trouble, trouble_students=len({t["student"] for t in trouble}), version=_versions(graded),
        answers=[{"student": g.student, "item": m} for g in graded for m in g.report.manual], table=table,
        sandboxes=sorted({g.report.sandbox for g in graded if not g.report.isolated}),
    )

