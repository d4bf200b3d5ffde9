"""The exports of a gradebook: grades.csv, manual_answers.csv, the class summary (summary.html, written by
``grader.report.summary``) and, per student, a Gradescope results.json (built by the autograder's own
``grader.report.gradescope_results.results_json``) and an HTML report (the student's view).

A batch writes each student's own files as soon as that student is recorded (``export_student``), and the files
about the whole class once at the end (``export_results(..., students=False)``); ``grade export`` and
``grade import-manual`` rewrite everything.
"""

from __future__ import annotations

import csv
import io
import os
from collections import Counter
from datetime import datetime
from pathlib import Path

from ..report.summary import class_summary
from ..results import Graded, possible, problem_possible, rows_by_student, scored_items
from .course import (
    COURSE_FILE,
    Assignment,
    Course,
    CourseError,
    Standing,
    SubmissionTime,
    load_course,
    roster_times,
    shown_time,
    standings,
)
from .gradebook import Gradebook, now, spreadsheet_cell
from .lms import EXCUSED, canvas_rows, match, matching_summary, moodle_rows, read_roster

__all__ = ["export_results", "export_student", "StudentExporter", "student_status", "student_deadlines",
           "resolve_course", "class_standings", "late_status", "lms_exports", "COURSE_META", "LMS_META", "RECORDED"]

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


def _student_files(out: Path, name: str, items: list[Graded], deadlines: list[str]) -> None:
    from ..report.gradescope_results import render_results
    from ..report.html import render_html

    reports = [g.report for g in items]
    folder = out / "students" / name
    _write(folder / "results.json", render_results(reports))
    _write(folder / "report.html", render_html(reports, title=f"Grading report: {name}", deadlines=deadlines))


def student_deadlines(course: Course | None, name: str, items: list[Graded], book: Gradebook) -> list[str]:
    """What a student's report says of the course's deadlines: per assignment with a due date, when the work was
    submitted (and how that is known), and what being late cost."""
    if course is None:
        return []
    times = _times(course, {name: items}, book)[name]
    rows = standings(course, name, {g.report.problem: g.report.score for g in items}, {}, times)
    return [f"{s.assignment}: {line}" for s in rows if (line := _deadline_sentence(s, course))]


def export_student(out: str | Path, book: Gradebook, name: str, course: Course | None = None) -> None:
    """Write one student's results.json and report.html from the gradebook (every problem's current result, the
    manual scores merged; the course's deadlines, with one): what a batch does as soon as it recorded the
    student."""
    items = book.current(student=name)
    if items:
        _student_files(Path(out), name, items, student_deadlines(course, name, items, book))


class StudentExporter:
    """Writes each recorded student's files in a process of its own, while the batch goes on: the batch's own
    process stays free to hand out students and record results (and, on a Dask client, to the scheduler's
    threads).  Students whose files it could not write are written by ``export_results(..., students=None)``."""

    def __init__(self, out: str | Path, course: Course | None = None):
        import multiprocessing

        context = multiprocessing.get_context("spawn")
        self.conn, theirs = context.Pipe()
        self.process = context.Process(target=_export_loop, args=(theirs, str(out), os.getpid(), course),
                                       daemon=True, name="grade-exporter")
        self.process.start()
        theirs.close()
        self.out, self.course, self.failed = Path(out), course, False

    def submit(self, name: str, book: Gradebook) -> None:
        if not self.failed:
            try:
                self.conn.send(name)
                return
            except OSError:  # the exporter died: this process writes the files from now on
                self.failed = True
        export_student(self.out, book, name, self.course)

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


def _export_loop(conn, out: str, parent: int, course: Course | None = None) -> None:
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
            export_student(out, book, name, course)
            busy += time.monotonic() - began


def _stale(out: Path, name: str, items: list[Graded]) -> bool:
    """Whether a student's files are missing or older than the student's latest result."""
    try:
        written = min((out / "students" / name / file).stat().st_mtime for file in ("results.json", "report.html"))
    except OSError:
        return True
    latest = max(datetime.fromisoformat(g.graded_at).timestamp() for g in items)
    return written < latest


#: the gradebook's record of the course file, and of the LMS files to keep rewritten (their roster, "" for none)
COURSE_META, LMS_META = "course_file", {"canvas": "export.canvas", "moodle": "export.moodle"}
#: stands for "the course file the gradebook records" (``resolve_course``)
RECORDED = "recorded"


def resolve_course(book: Gradebook, given: str | Path | None = RECORDED) -> Course | None:
    """The course to export with: ``given`` (a path: then recorded for the exports that follow), else the file the
    gradebook records (``grade batch --course``, or a batch's SUBMISSIONS/course.toml), else SUBMISSIONS/course.toml
    of the latest batch, else none.  ``CourseError`` when the file is wrong or gone."""
    from ..listing import problem_list

    known = {p["number"] for p in problem_list()}
    if given not in (RECORDED, None):
        course = load_course(given, known)
        book.set_meta(COURSE_META, str(Path(given).resolve()))
        return course
    recorded = book.meta(COURSE_META)
    if recorded:
        if not Path(recorded).is_file():
            raise CourseError(f"{recorded}: the course file of this gradebook is gone: give it with --course FILE")
        return load_course(recorded, known)
    row = book.db.execute("SELECT submissions_dir FROM runs ORDER BY id DESC LIMIT 1").fetchone()
    if row is not None and (Path(row["submissions_dir"]) / COURSE_FILE).is_file():
        return load_course(Path(row["submissions_dir"]) / COURSE_FILE, known)
    return None


def _times(course: Course, by_student: dict[str, list[Graded]], book: Gradebook) -> dict[str, dict]:
    """Each student's submission time per assignment: the roster column's where the course names one, else the
    time recorded for the content graded in the assignment's problems (the latest of them)."""
    recorded, roster = book.submission_times(), roster_times(course)
    times = {}
    for student, items in by_student.items():
        mine = {}
        for assignment in course.assignments:
            if student in roster:
                mine[assignment.name] = SubmissionTime(roster[student], "roster")
                continue
            found = [recorded[(student, g.content_hash)] for g in items
                     if g.report.problem in assignment.problems and (student, g.content_hash) in recorded]
            if found:
                at, source = max(found, key=lambda t: datetime.fromisoformat(t[0]))
                mine[assignment.name] = SubmissionTime(datetime.fromisoformat(at), source)
        times[student] = mine
    return times


def class_standings(course: Course, graded: list[Graded], book: Gradebook) -> dict[str, list[Standing]]:
    """Every student's standing in every assignment (``grader.batch.course.standings``), from the gradebook's
    scores and submission times; kept in the gradebook (``assignment_scores``)."""
    by_student = rows_by_student(graded)
    scored = scored_items(graded)
    points: dict[int, float] = {}
    for g in graded:
        points[g.report.problem] = max(points.get(g.report.problem, 0.0), problem_possible(g.report, scored))
    times = _times(course, by_student, book)
    result = {student: standings(course, student, {g.report.problem: g.report.score for g in items}, points,
                                 times[student])
              for student, items in by_student.items()}
    book.save_standings([
        (s.student, s.assignment, s.raw, s.possible, s.penalty, s.final, s.due.isoformat() if s.due else "",
         s.submitted.at.isoformat() if s.submitted else "", s.submitted.source if s.submitted else "", s.days_late,
         s.grace_days, int(s.excused))
        for rows in result.values() for s in rows], str(course.path or ""))
    return result


def _days(n: int) -> str:
    return f"{n} day{'s' if n != 1 else ''}"


def late_status(rows: list[Standing]) -> list[str]:
    """What grades.csv's status says of the deadlines: late (by how much, at what cost), extended, excused."""
    parts = []
    for s in rows:
        if s.excused:
            parts.append(f"excused: {s.assignment}")
            continue
        if s.extended:
            parts.append(f"extension: {s.assignment} to {shown_time(s.due)}")
        if s.late:
            grace = f", {_days(s.grace_days).replace('day', 'grace day')} used" if s.grace_days else ""
            cost = f"{100 * s.share:g}% off" if s.share else "no penalty"
            parts.append(f"late: {s.assignment} by {_days(s.days_late)} ({cost}{grace})")
    return parts


def _grades_rows(by_student: dict[str, list[Graded]], numbers: list[int], scored: dict, course: Course | None,
                 standing: dict[str, list[Standing]]) -> list[list]:
    """grades.csv: each problem's score; with a course, each assignment's raw score, late penalty and final score,
    and the submission time and where it comes from; the total, the possible points and the status."""
    names = [a.name for a in course.assignments] if course is not None else []
    header = ["student", *[f"problem_{n}" for n in numbers]]
    for name in names:
        header += [f"{name} raw", f"{name} late penalty", name]
    header += ["total", "possible", "status"] + (["submitted", "submitted from"] if course is not None else [])
    rows = [header]
    for student, items in by_student.items():
        scores = {g.report.problem: g.report.score for g in items}
        row = [student, *[f"{scores[n]:g}" if n in scores else "" for n in numbers]]
        status = student_status(items)
        if course is None:
            rows.append(row + [f"{sum(scores.values()):g}", f"{possible(items, scored):g}", status])
            continue
        mine = standing[student]
        for s in mine:
            row += ["" if s.raw is None else f"{s.raw:g}", "" if s.raw is None else f"{s.penalty:g}",
                    EXCUSED if s.excused else "" if s.final is None else f"{s.final:g}"]
        total = sum(s.final for s in mine if s.final is not None)
        top = sum(s.possible for s in mine if not s.excused)
        latest = max((s.submitted for s in mine if s.submitted is not None), key=lambda t: t.at, default=None)
        rows.append(row + [f"{_round(total):g}", f"{_round(top):g}", "; ".join([status, *late_status(mine)]),
                           _local(latest.at, course) if latest else "", latest.said if latest else ""])
    return rows


def _round(x: float) -> float:
    return round(x, 6) + 0.0


def _local(moment: datetime | None, course: Course) -> str:
    """A time as the course reads it: in its time zone, else in the offset of its first due date."""
    if moment is None:
        return ""
    zone = course.timezone or next((a.due.tzinfo for a in course.assignments if a.due is not None), None)
    return shown_time(moment.astimezone(zone) if zone is not None else moment)


def _deadline_sentence(s: Standing, course: Course) -> str:
    """When the work of an assignment was submitted (and how that is known) against its due date, and what being
    late cost: "" where the assignment has no due date or the time is not known."""
    if s.excused:
        return "excused."
    if s.submitted is None or s.due is None or s.raw is None:
        return ""
    own = " (your extension)" if s.extended else ""
    when = f"submitted {_local(s.submitted.at, course)} ({s.submitted.said})"
    if not s.late:
        return f"{when}, by the due date {shown_time(s.due)}{own}."
    grace = f", {_days(s.grace_days)} of them covered by grace days" if s.grace_days else ""
    cost = f"{100 * s.share:g}% off: -{s.penalty:g} points, {s.final:g} points" if s.share else "no penalty"
    return f"{when}, {_days(s.days_late)} after the due date {shown_time(s.due)}{own}{grace}: {cost}."


def _feedback(s: Standing, items: list[Graded], assignment, course: Course) -> str:
    """An assignment's feedback to the student (Moodle's feedback column): the points, the deadline's effect, the
    comments on free-text answers."""
    if s.excused:
        return "Excused from this assignment."
    if s.raw is None:
        return ""
    lines = [f"{s.raw:g} of {s.possible:g} points."]
    sentence = _deadline_sentence(s, course)
    if sentence:
        lines.append(sentence[:1].upper() + sentence[1:])
    for g in items:
        if g.report.problem in assignment.problems:
            for m in g.report.manual:
                if m.score is not None and m.comment:
                    lines.append(f"Problem {m.problem}, {m.question} ({m.score:g} of {m.max_score:g}): {m.comment}")
    return "\n".join(lines)


def lms_exports(out: Path, book: Gradebook, course: Course, by_student: dict[str, list[Graded]],
                standing: dict[str, list[Standing]], notes: list[str]) -> dict[str, Path]:
    """canvas.csv and moodle.csv, those the gradebook records as asked for (``grade export --canvas/--moodle``),
    each with its roster; what the roster matched is said in ``notes``."""
    paths = {}
    names = [a.name for a in course.assignments]
    grades = {student: {s.assignment: EXCUSED if s.excused else s.final for s in rows}
              for student, rows in standing.items()}
    possible_points = {s.assignment: s.possible for rows in standing.values() for s in rows}
    asked = {kind: book.meta(LMS_META[kind]) for kind in ("canvas", "moodle")}
    matchings = {}
    for roster_path in {p for p in asked.values() if p}:
        roster = read_roster(roster_path)
        matchings[roster_path] = roster, match(list(by_student), roster)
        files = " and ".join(f"{kind}.csv" for kind, p in asked.items() if p == roster_path)
        notes += [f"{files}: {line}" if not line.startswith("  ") else line
                  for line in matching_summary(matchings[roster_path][1], roster)]
    for kind, roster_path in asked.items():
        if roster_path is None:
            continue
        roster, matching = matchings.get(roster_path, (None, None))
        if kind == "canvas":
            rows = canvas_rows(names, possible_points, grades, roster, matching)
        else:
            feedback = {student: {s.assignment: _feedback(s, by_student[student], a, course)
                                  for s, a in zip(mine, course.assignments)}
                        for student, mine in standing.items()}
            rows = moodle_rows(names, grades, feedback, roster, matching)
        paths[kind] = out / f"{kind}.csv"
        _write(paths[kind], _csv(rows))
    return paths


def _time_sources(standing: dict[str, list[Standing]]) -> str:
    counts = Counter(s.submitted.said for rows in standing.values() for s in rows if s.submitted and s.due)
    return ", ".join(f"{n} from {source}" for source, n in counts.most_common())


def export_results(out: str | Path, book: Gradebook | None = None, students: bool | None = True,
                   course: Course | str | Path | None = RECORDED, notes: list[str] | None = None) -> dict[str, Path]:
    """Write grades.csv, manual_answers.csv, summary.html and each student's results.json and report.html; with a
    course (``resolve_course``: by default the one the gradebook records), the assignments' scores under its due
    dates and late policy in grades.csv, and canvas.csv and moodle.csv where they were asked for.

    ``students=None`` writes only the students' files that are missing or older than their latest result (a batch,
    which wrote each student's files as it recorded them); ``False`` none of them.  What there is to say (the
    roster's matching, where submission times come from) is added to ``notes``."""
    out = Path(out)
    notes = [] if notes is None else notes
    if book is None:
        with Gradebook.in_folder(out) as own:
            return export_results(out, own, students, course, notes)
    if not isinstance(course, Course):
        course = resolve_course(book, course)
    graded = book.current(figures=False)  # the class's files need no figures; a student's own are read below
    by_student = rows_by_student(graded)
    numbers = sorted({g.report.problem for g in graded})
    scored = scored_items(graded)
    standing = {}
    if course is not None:
        unassigned = [n for n in numbers if course.assignment_of(n) is None]
        if unassigned:
            notes.append(f"{_numbers(unassigned)} {'is' if len(unassigned) == 1 else 'are'} in no assignment of "
                         f"{course.path or COURSE_FILE}: each is an assignment of its own, without a due date")
        named = sorted({student for student, _ in [*course.extensions, *course.excused]} - set(by_student))
        if named:
            notes.append(f"{course.path or COURSE_FILE} names {', '.join(named)} (an extension or an excuse), who "
                         "has no submission in the gradebook: check the spelling against the submissions' names")
        course = course.with_problems(numbers)
        standing = class_standings(course, graded, book)
        sources = _time_sources(standing)
        if sources:
            notes.append(f"submission times: {sources}")
    paths = {"grades": out / "grades.csv", "manual": out / "manual_answers.csv", "summary": out / "summary.html"}
    _write(paths["grades"], _csv(_grades_rows(by_student, numbers, scored, course, standing)))
    manual = [["student", "problem", "key", "score", "max_score", "question", "answer", "comment"]]
    manual += [[g.student, m.problem, m.key, "" if m.score is None else f"{m.score:g}", f"{m.max_score:g}",
                m.question, m.answer, m.comment]
               for g in graded for m in g.report.manual]
    _write(paths["manual"], _csv(manual))
    if _lms_asked(book):  # without a course, each problem is an assignment without a due date
        if course is None:
            course = Course(tuple(Assignment(f"Problem {n}", (n,)) for n in numbers))
            standing = class_standings(course, graded, book)
        paths.update(lms_exports(out, book, course, by_student, standing, notes))
    if students is not False:
        for name, items in by_student.items():
            if students or _stale(out, name, items):
                export_student(out, book, name, course if standing else None)
    _write(paths["summary"], class_summary(graded, generated=now()))
    return paths


def _lms_asked(book: Gradebook) -> bool:
    return any(book.meta(key) is not None for key in LMS_META.values())
