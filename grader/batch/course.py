"""A course's assignments, due dates and late policy: ``course.toml``.

    timezone = "Europe/Berlin"        # optional: for times written without an offset (a roster's column)

    [[assignment]]
    name = "Exercise II"
    problems = [6, 7, 8, 9, 10]
    due = 2026-12-01T23:59:00+01:00

    [late]
    per_day = 0.10                    # share of the score lost per started day late
    max_days = 5                      # later than this many days, the score is 0
    cap = 0.30                        # at most this share is lost (before max_days)
    grace_days = 2                    # days each student may be late over the term without a penalty

    [extensions]
    carol = 2026-12-04T23:59:00+01:00                   # carol's own due date of the assignment it extends
    dave = { "Exercise III" = 2026-12-20T23:59:00+01:00 }

    [excused]
    erin = ["Exercise II"]

    [submission_times]
    roster = "submitted.csv"          # a CSV beside course.toml: each student's submission time
    student = "student"               # its column naming the student (as the submissions folder does)
    time = "submitted"                # its column of times (2026-12-03T10:15:00+01:00)

The file is read with ``tomllib``: due dates are TOML offset date-times.  Whatever is wrong with it is said once, with
its line and the fix (``CourseError``).  The scores of an assignment are computed from the gradebook at every export
(``standings``): changing the file and running ``grade export`` again recomputes them without grading anyone again.
"""

from __future__ import annotations

import csv
import math
import re
import tomllib
from dataclasses import dataclass, field, replace
from datetime import date, datetime, time, timedelta, tzinfo
from pathlib import Path

__all__ = [
    "COURSE_FILE",
    "DAY",
    "Assignment",
    "LatePolicy",
    "TimesColumn",
    "Course",
    "CourseError",
    "Standing",
    "SubmissionTime",
    "SOURCES",
    "parse_course",
    "load_course",
    "roster_times",
    "entry_time",
    "days_late",
    "late_share",
    "standings",
    "shown_time",
]

COURSE_FILE = "course.toml"
#: a day late, or part of one
DAY = timedelta(days=1)
#: how each source of a submission time is named in the exports, the weakest last
SOURCES = {
    "roster": "the roster's column",
    "gradescope": "Gradescope's submission metadata",
    "files": "the newest file's time",
}
#: a time written without a date's offset
NAIVE_FIX = "write it with its offset, e.g. 2026-12-01T23:59:00+01:00, or set timezone = \"Europe/Berlin\" (say)"


class CourseError(ValueError):
    """A course file (or a file it names) that cannot be used: where, what, and how to fix it."""


@dataclass(frozen=True)
class Assignment:
    """An exercise or a problem, as the course grades it: its problems and its due date (None: none)."""

    name: str
    problems: tuple[int, ...]
    due: datetime | None = None


@dataclass(frozen=True)
class LatePolicy:
    """``per_day`` of the score lost per started day late, at most ``cap``; later than ``max_days``, all of it;
    ``grace_days`` each student may spend over the term without a penalty."""

    per_day: float = 0.0
    max_days: int | None = None
    cap: float = 1.0
    grace_days: int = 0


@dataclass(frozen=True)
class TimesColumn:
    """A CSV with each student's submission time: its path, the column naming the student, the column of times."""

    path: Path
    student: str = "student"
    time: str = "submitted"


@dataclass(frozen=True)
class Course:
    assignments: tuple[Assignment, ...]
    late: LatePolicy = LatePolicy()
    #: (student, assignment) -> the student's own due date
    extensions: dict = field(default_factory=dict)
    #: (student, assignment) pairs excused from the assignment
    excused: frozenset = frozenset()
    times: TimesColumn | None = None
    timezone: tzinfo | None = None
    path: Path | None = None

    @property
    def problems(self) -> list[int]:
        return sorted({n for a in self.assignments for n in a.problems})

    def assignment_of(self, problem: int) -> Assignment | None:
        return next((a for a in self.assignments if problem in a.problems), None)

    def with_problems(self, numbers) -> "Course":
        """The course with an assignment "Problem N" (no due date) for each graded problem that none holds."""
        extra = tuple(Assignment(f"Problem {n}", (n,)) for n in sorted(set(numbers)) if self.assignment_of(n) is None)
        if not extra:
            return self
        return replace(self, assignments=self.assignments + extra)


@dataclass(frozen=True)
class SubmissionTime:
    """When a student submitted, and how that is known (a key of ``SOURCES``)."""

    at: datetime
    source: str

    @property
    def said(self) -> str:
        return SOURCES.get(self.source, self.source)


@dataclass(frozen=True)
class Standing:
    """A student's score of one assignment under the course's deadline and late policy.  ``raw`` is None when no
    problem of the assignment was graded for the student (their cells stay blank); ``final`` is None when excused
    or not graded."""

    student: str
    assignment: str
    raw: float | None
    possible: float
    due: datetime | None = None  # the student's own (an extension's, when they have one)
    extended: bool = False
    submitted: SubmissionTime | None = None
    days_late: int = 0  # started days after the student's due date
    grace_days: int = 0  # of them, those that the student's grace days covered
    share: float = 0.0  # share of the raw score lost
    excused: bool = False

    @property
    def penalty(self) -> float:
        return 0.0 if self.raw is None or self.excused else _points(self.raw * self.share)

    @property
    def final(self) -> float | None:
        return None if self.raw is None or self.excused else _points(self.raw - self.penalty)

    @property
    def late(self) -> bool:
        return self.days_late > 0


def _points(x: float) -> float:
    """Points as exports show them: rounded to a millionth, so that 8.5 * 0.2 is 1.7."""
    return round(x, 6) + 0.0


# ------------------------------------------------------------------------------------------ the file


_TABLE = re.compile(r"^\s*(\[\[?)\s*([^\]]+?)\s*\]\]?\s*(#.*)?$")
_KEY = re.compile(r'^\s*((?:[A-Za-z0-9_-]+|"(?:[^"\\]|\\.)*"|\'[^\']*\')(?:\s*\.\s*(?:[A-Za-z0-9_-]+|"(?:[^"\\]|\\.)*"|\'[^\']*\'))*)\s*=')


def _key_parts(text: str) -> tuple[str, ...]:
    parts = re.findall(r'[A-Za-z0-9_-]+|"(?:[^"\\]|\\.)*"|\'[^\']*\'', text)
    return tuple(p[1:-1] if p[:1] in "\"'" else p for p in parts)


def _key_lines(text: str) -> dict[tuple, int]:
    """The line of each table and key of a TOML text: (table..., key) -> line; an array of tables' entries are
    numbered (("assignment", 0, "due")).  Enough to say where a value is wrong; a value that the text does not
    place (inside an inline table) is said at its parent's line."""
    lines: dict[tuple, int] = {}
    counts: dict[tuple, int] = {}
    table: tuple = ()
    for number, line in enumerate(text.splitlines(), start=1):
        header = _TABLE.match(line)
        if header and not _KEY.match(line):
            path = _key_parts(header.group(2))
            if header.group(1) == "[[":
                index = counts.get(path, 0)
                counts[path] = index + 1
                table = (*path, index)
            else:
                table = path
            lines.setdefault(table, number)
            continue
        key = _KEY.match(line)
        if key:
            lines.setdefault((*table, *_key_parts(key.group(1))), number)
    return lines


class _Where:
    """Says where a value of the file is: "course.toml, line 7"."""

    def __init__(self, path: Path | None, text: str):
        self.name = str(path) if path is not None else COURSE_FILE
        self.lines = _key_lines(text)

    def __call__(self, *key) -> str:
        for end in range(len(key), 0, -1):
            if key[:end] in self.lines:
                return f"{self.name}, line {self.lines[key[:end]]}"
        return self.name

    def error(self, key: tuple, what: str, fix: str = "") -> CourseError:
        return CourseError(f"{self(*key)}: {what}" + (f". {fix[:1].upper()}{fix[1:]}" if fix else ""))


_KEYS = {
    "": {"timezone", "assignment", "late", "extensions", "excused", "submission_times"},
    "assignment": {"name", "problems", "due"},
    "late": {"per_day", "max_days", "cap", "grace_days"},
    "submission_times": {"roster", "student", "time"},
}


def _unknown(table: dict, known: set, where: _Where, key: tuple, title: str) -> None:
    for name in table:
        if name not in known:
            raise where.error((*key, name), f"{title} has no key {name!r}",
                              f"its keys are {', '.join(sorted(known))}")


def _number(value, where: _Where, key: tuple, low: float, high: float | None, whole: bool = False) -> float:
    kinds = (int,) if whole else (int, float)
    what = "a whole number" if whole else "a number"
    if isinstance(value, bool) or not isinstance(value, kinds) or not math.isfinite(value) \
            or value < low or (high is not None and value > high):
        bounds = f"from {low:g} to {high:g}" if high is not None else f"of at least {low:g}"
        raise where.error(key, f"{key[-1]} is {value!r}", f"write {what} {bounds}")
    return value


def _moment(value, where: _Where, key: tuple, zone: tzinfo | None) -> datetime:
    """A TOML date-time with its offset (or, without one, in the course's time zone)."""
    if isinstance(value, datetime):
        if value.tzinfo is None:
            if zone is None:
                raise where.error(key, f"{value.isoformat()} has no time zone", NAIVE_FIX)
            return value.replace(tzinfo=zone)
        return value
    if isinstance(value, date):
        raise where.error(key, f"{value.isoformat()} is a date without a time",
                          f"write the time too, e.g. {value.isoformat()}T23:59:00+01:00")
    if isinstance(value, time):
        raise where.error(key, f"{value.isoformat()} is a time without a date", "write e.g. 2026-12-01T23:59:00+01:00")
    if isinstance(value, str):
        raise where.error(key, f"{value!r} is text, not a date and time",
                          "write it without quotes, e.g. 2026-12-01T23:59:00+01:00")
    raise where.error(key, f"{value!r} is not a date and time", "write e.g. 2026-12-01T23:59:00+01:00")


def _zone(value, where: _Where) -> tzinfo | None:
    if value is None:
        return None
    from zoneinfo import ZoneInfo, ZoneInfoNotFoundError

    if not isinstance(value, str) or not value:
        raise where.error(("timezone",), f"timezone is {value!r}", 'write a name such as "Europe/Berlin"')
    try:
        return ZoneInfo(value)
    except (ZoneInfoNotFoundError, ValueError):
        raise where.error(("timezone",), f"{value!r} is not a time zone this machine knows",
                          'write a name of the IANA database such as "Europe/Berlin" or "America/New_York"') from None


def _assignments(entries, where: _Where, zone: tzinfo | None, known: set[int] | None) -> tuple[Assignment, ...]:
    if entries is None:
        raise where.error((), "the file has no [[assignment]]",
                          'add one per exercise or problem: name = "Exercise II", problems = [6, 7, 8, 9, 10], '
                          "due = 2026-12-01T23:59:00+01:00")
    if not isinstance(entries, list) or not all(isinstance(e, dict) for e in entries):
        raise where.error(("assignment",), "assignment must be a table of its own per assignment",
                          "write each as [[assignment]] followed by its name, problems and due date")
    assignments, owner = [], {}
    for index, entry in enumerate(entries):
        key = ("assignment", index)
        _unknown(entry, _KEYS["assignment"], where, key, "an [[assignment]]")
        name = entry.get("name")
        if not isinstance(name, str) or not name.strip():
            raise where.error((*key, "name"), "an [[assignment]] has no name", 'write name = "Exercise II"')
        name = name.strip()
        if any(a.name == name for a in assignments):
            raise where.error((*key, "name"), f"two assignments are named {name!r}", "give each its own name")
        problems = entry.get("problems")
        if not isinstance(problems, list) or not problems or not all(
                isinstance(n, int) and not isinstance(n, bool) for n in problems):
            raise where.error((*key, "problems"), f"the problems of {name!r} are {problems!r}",
                              "write the problem numbers in brackets, e.g. problems = [6, 7, 8]")
        for number in problems:
            if known is not None and number not in known:
                raise where.error((*key, "problems"), f"problem {number} of {name!r} has no checks",
                                  "see `grade list` for the problems that are graded")
            if number in owner:
                raise where.error((*key, "problems"), f"problem {number} is in {owner[number]!r} and in {name!r}",
                                  "put each problem in one assignment")
            owner[number] = name
        due = _moment(entry["due"], where, (*key, "due"), zone) if "due" in entry else None
        assignments.append(Assignment(name, tuple(problems), due))
    return tuple(assignments)


def _late(table, where: _Where) -> LatePolicy:
    if table is None:
        return LatePolicy()
    if not isinstance(table, dict):
        raise where.error(("late",), "late must be a table", "write it as [late] followed by per_day = 0.10 ...")
    _unknown(table, _KEYS["late"], where, ("late",), "[late]")
    per_day = _number(table.get("per_day", 0.0), where, ("late", "per_day"), 0.0, 1.0)
    max_days = table.get("max_days")
    if max_days is not None:
        max_days = int(_number(max_days, where, ("late", "max_days"), 0, None, whole=True))
    cap = _number(table.get("cap", 1.0), where, ("late", "cap"), 0.0, 1.0)
    grace = int(_number(table.get("grace_days", 0), where, ("late", "grace_days"), 0, None, whole=True))
    return LatePolicy(float(per_day), max_days, float(cap), grace)


def _extended(student: str, moment: datetime, assignments, where: _Where) -> str:
    """The assignment that a bare extension date extends: the one due last before it."""
    before = [a for a in assignments if a.due is not None and a.due < moment]
    if not before:
        raise where.error(("extensions", student), f"{student}'s extension, {moment.isoformat()}, is not later "
                          "than any assignment's due date",
                          f'write the assignment it extends: {student} = {{ "{assignments[0].name}" = '
                          f"{moment.isoformat()} }}")
    return max(before, key=lambda a: a.due).name


def _extensions(table, where: _Where, assignments, zone) -> dict:
    if table is None:
        return {}
    if not isinstance(table, dict):
        raise where.error(("extensions",), "extensions must be a table", "write [extensions] then carol = DATE")
    names = {a.name for a in assignments}
    extensions = {}
    for student, value in table.items():
        key = ("extensions", student)
        if isinstance(value, dict):
            for name, moment in value.items():
                if name not in names:
                    raise where.error((*key, name), f"{student}'s extension names {name!r}, which is not an "
                                      "assignment", f"the assignments are {', '.join(sorted(names))}")
                extensions[(student, name)] = _moment(moment, where, (*key, name), zone)
        else:
            moment = _moment(value, where, key, zone)
            extensions[(student, _extended(student, moment, assignments, where))] = moment
    for (student, name), moment in extensions.items():
        due = next(a.due for a in assignments if a.name == name)
        if due is None:
            raise where.error(("extensions", student), f"{name!r} has no due date to extend",
                              f"give {name!r} a due date, or remove {student}'s extension")
    return extensions


def _excused(table, where: _Where, assignments) -> frozenset:
    if table is None:
        return frozenset()
    if not isinstance(table, dict):
        raise where.error(("excused",), "excused must be a table", 'write [excused] then erin = ["Exercise II"]')
    names = {a.name for a in assignments}
    pairs = set()
    for student, value in table.items():
        listed = [value] if isinstance(value, str) else value
        if not isinstance(listed, list) or not all(isinstance(v, str) for v in listed):
            raise where.error(("excused", student), f"{student} is excused from {value!r}",
                              f'write the assignments in brackets: {student} = ["Exercise II"]')
        for name in listed:
            if name not in names:
                raise where.error(("excused", student), f"{student} is excused from {name!r}, which is not an "
                                  "assignment", f"the assignments are {', '.join(sorted(names))}")
            pairs.add((student, name))
    return frozenset(pairs)


def _times(table, where: _Where, base: Path) -> TimesColumn | None:
    if table is None:
        return None
    if not isinstance(table, dict):
        raise where.error(("submission_times",), "submission_times must be a table",
                          'write [submission_times] then roster = "submitted.csv"')
    _unknown(table, _KEYS["submission_times"], where, ("submission_times",), "[submission_times]")
    for name in ("roster", "student", "time"):
        if name in table and (not isinstance(table[name], str) or not table[name]):
            raise where.error(("submission_times", name), f"{name} is {table[name]!r}", "write it as text in quotes")
    if "roster" not in table:
        raise where.error(("submission_times",), "[submission_times] names no roster",
                          'write roster = "submitted.csv" (a CSV with a column of students and one of times)')
    return TimesColumn(base / table["roster"], table.get("student", "student"), table.get("time", "submitted"))


def parse_course(text: str, path: Path | None = None, known_problems: set[int] | None = None) -> Course:
    """The course of a ``course.toml`` text; ``CourseError`` with the file's line and the fix for anything wrong.
    ``known_problems``: the problems that have checks (others are refused)."""
    where = _Where(path, text)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        message = str(exc)
        found = re.search(r"\(at line (\d+), column (\d+)\)", message)
        what = message[:found.start()].strip() if found else message
        at = f"{where.name}, line {found.group(1)}, column {found.group(2)}" if found else where.name
        raise CourseError(f"{at}: {what[:1].lower() + what[1:]} (TOML syntax). Dates are written without quotes "
                          "(due = 2026-12-01T23:59:00+01:00), text in quotes (name = \"Exercise II\"), lists in "
                          "brackets (problems = [6, 7])") from None
    _unknown(data, _KEYS[""], where, (), "the file")
    zone = _zone(data.get("timezone"), where)
    assignments = _assignments(data.get("assignment"), where, zone, known_problems)
    base = path.parent if path is not None else Path(".")
    return Course(assignments, _late(data.get("late"), where),
                  _extensions(data.get("extensions"), where, assignments, zone),
                  _excused(data.get("excused"), where, assignments), _times(data.get("submission_times"), where, base),
                  zone, path)


def load_course(path: str | Path, known_problems: set[int] | None = None) -> Course:
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise CourseError(f"{path}: no such file (give the course file with --course FILE)") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise CourseError(f"{path}: cannot be read: {exc}") from None
    return parse_course(text, path, known_problems)


def roster_times(course: Course) -> dict[str, datetime]:
    """Each student's submission time from the roster column that ``[submission_times]`` names ({} without one)."""
    if course.times is None:
        return {}
    spec = course.times
    try:
        with open(spec.path, encoding="utf-8-sig", newline="") as handle:
            reader = csv.DictReader(handle)
            columns, rows = list(reader.fieldnames or ()), list(reader)
    except FileNotFoundError:
        raise CourseError(f"{spec.path}: no such file ([submission_times] roster of {course.path or COURSE_FILE})") \
            from None
    except (OSError, UnicodeDecodeError, csv.Error) as exc:
        raise CourseError(f"{spec.path}: cannot be read: {exc}") from None
    missing = [c for c in (spec.student, spec.time) if c not in columns]
    if missing:
        raise CourseError(f"{spec.path}: no column {', '.join(map(repr, missing))} (its columns are "
                          f"{', '.join(map(repr, columns))}): set student = and time = in [submission_times]")
    times, errors = {}, []
    for line, row in enumerate(rows, start=2):
        student, text = (row.get(spec.student) or "").strip(), (row.get(spec.time) or "").strip()
        if not student or not text:
            continue
        try:
            moment = datetime.fromisoformat(text)
        except ValueError:
            errors.append(f"{spec.path}, line {line}: {text!r} is not a date and time: write e.g. "
                          "2026-12-03T10:15:00+01:00")
            continue
        if moment.tzinfo is None:
            if course.timezone is None:
                errors.append(f"{spec.path}, line {line}: {text} has no time zone: {NAIVE_FIX} in course.toml")
                continue
            moment = moment.replace(tzinfo=course.timezone)
        times[student] = moment
    if errors:
        raise CourseError("\n".join(errors[:10]) + (f"\n(and {len(errors) - 10} more)" if len(errors) > 10 else ""))
    return times


# ------------------------------------------------------------------------------------------ submission times

#: bytes of Gradescope's metadata read at most (a few kB in practice)
METADATA_BYTES = 1 << 20
#: files of a student's folder looked at for the newest one's time at most
NEWEST_FILES = 20_000


def _gradescope_time(path: Path) -> datetime | None:
    """``created_at`` of Gradescope's submission metadata, None when the file does not give one."""
    import json

    try:
        with open(path, "rb") as handle:
            data = json.loads(handle.read(METADATA_BYTES + 1)[:METADATA_BYTES])
        moment = datetime.fromisoformat(str(data["created_at"]).replace("Z", "+00:00"))
    except (OSError, ValueError, KeyError, TypeError):
        return None
    return moment if moment.tzinfo is not None else None


def _newest_file(path: Path) -> datetime:
    """The latest modification time of the submission's files (an archive's or notebook's own), links not
    followed."""
    import os

    newest, seen = os.lstat(path).st_mtime, 0
    if not path.is_symlink() and path.is_dir():
        newest = None
        stack = [path]
        while stack and seen < NEWEST_FILES:
            try:
                with os.scandir(stack.pop()) as entries:
                    for entry in entries:
                        seen += 1
                        if entry.is_dir(follow_symlinks=False):
                            stack.append(Path(entry.path))
                        elif entry.is_file(follow_symlinks=False):
                            mtime = entry.stat(follow_symlinks=False).st_mtime
                            newest = mtime if newest is None else max(newest, mtime)
            except OSError:
                continue
        if newest is None:  # no file at all: the folder's own time
            newest = os.lstat(path).st_mtime
    return datetime.fromtimestamp(newest).astimezone()


def entry_time(entry) -> SubmissionTime:
    """When a student's entry (``grader.batch.discover.Entry``) was submitted: ``created_at`` of Gradescope's
    metadata beside it, else the newest file's time (which an archive's author sets: the weakest source)."""
    if entry.metadata is not None:
        moment = _gradescope_time(entry.metadata)
        if moment is not None:
            return SubmissionTime(moment, "gradescope")
    return SubmissionTime(_newest_file(entry.path), "files")


# ------------------------------------------------------------------------------------------ the policy


def days_late(submitted: datetime, due: datetime) -> int:
    """Started days after the due date: a minute late is a day late, 24 hours and a minute two."""
    if submitted <= due:
        return 0
    return math.ceil((submitted - due) / DAY)


def late_share(days: int, policy: LatePolicy) -> float:
    """The share of the score lost for ``days`` late (grace days already taken off)."""
    if days <= 0:
        return 0.0
    if policy.max_days is not None and days > policy.max_days:
        return 1.0
    return min(policy.per_day * days, policy.cap, 1.0)


def standings(course: Course, student: str, scores: dict[int, float], points: dict[int, float],
              times: dict[str, SubmissionTime]) -> list[Standing]:
    """A student's standing in each assignment of ``course``: ``scores`` of the problems graded for them,
    ``points`` possible per problem (the class's), ``times`` their submission time per assignment (absent:
    unknown, never late).  Grace days are spent on the assignments in the order of their due dates."""
    grace_left = course.late.grace_days
    result = {}
    for assignment in sorted(course.assignments, key=lambda a: (a.due is None, a.due or datetime.min, a.name)):
        mine = [n for n in assignment.problems if n in scores]
        raw = _points(sum(scores[n] for n in mine)) if mine else None
        possible = _points(sum(points.get(n, 0.0) for n in assignment.problems))
        own = course.extensions.get((student, assignment.name))
        due = own or assignment.due
        submitted = times.get(assignment.name)
        days = days_late(submitted.at, due) if due is not None and submitted is not None and raw is not None else 0
        grace = min(grace_left, days)
        grace_left -= grace
        result[assignment.name] = Standing(
            student, assignment.name, raw, possible, due, own is not None, submitted, days, grace,
            late_share(days - grace, course.late), (student, assignment.name) in course.excused)
    return [result[a.name] for a in course.assignments]


def shown_time(moment: datetime | None) -> str:
    """A time as the exports show it: to the minute, with its offset ("2026-12-01 23:59 +01:00")."""
    if moment is None:
        return ""
    offset = moment.strftime("%z")
    return moment.strftime("%Y-%m-%d %H:%M") + (f" {offset[:3]}:{offset[3:]}" if offset else "")
