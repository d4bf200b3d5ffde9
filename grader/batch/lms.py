"""Grades for a learning-management system: ``canvas.csv`` in Canvas's gradebook import format, ``moodle.csv`` in
the shape of Moodle's CSV grade import, and the roster that names each student as the LMS knows them.

Canvas (Grades > Import): the columns ``Student``, ``ID``, ``SIS User ID``, ``SIS Login ID``, ``Section``, then one
column per assignment titled ``NAME (ID)`` with Canvas's assignment id where the roster gives it (the title alone
otherwise: Canvas then makes a new assignment), a second row whose first cell is ``Points Possible``, then one row per
student: the final score, ``EX`` where the student is excused, an empty cell where there is no grade.  The roster is
the CSV that Canvas exports from its gradebook (Grades > Export): its students, their ids and sections, and its
assignment columns ``NAME (ID)``.

Moodle (Grades > Import > CSV file): one row per student; identifier columns that the import maps to a user
(``Email address``, ``Username``, ``ID number``); per assignment a grade column ``NAME`` and a feedback column
``NAME (feedback)``, mapped in the import to the grade item and its feedback.  The roster (optional) is Moodle's own
grade export, or any CSV with those columns.

Students are matched to roster rows by login (Canvas's SIS Login ID, Moodle's username or e-mail address, with or
without its domain), then by SIS id (Moodle's ID number), then by the Canvas user id within the submission's name (as
in Canvas's download of submissions), then by name (in any order of its words, with or without separators).  A student
two rows match at the same step, or two students the same row, is ambiguous: said, and not written.
"""

from __future__ import annotations

import csv
import itertools
import re
import unicodedata
from dataclasses import dataclass, field
from pathlib import Path

__all__ = [
    "RosterRow",
    "Roster",
    "Matching",
    "RosterError",
    "CANVAS_COLUMNS",
    "POINTS_POSSIBLE",
    "EXCUSED",
    "read_roster",
    "match",
    "canvas_title",
    "canvas_rows",
    "moodle_rows",
    "matching_summary",
]

#: the columns that name a student in Canvas's gradebook, in its order
CANVAS_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")
#: the first cell of the row of each assignment's points in Canvas's gradebook
POINTS_POSSIBLE = "Points Possible"
#: what Canvas reads as "excused" in an assignment's cell
EXCUSED = "EX"
#: columns of a roster, by what they hold: Canvas's names first, then Moodle's and common ones
ALIASES = {
    "name": ("Student", "Full name", "Name", "Student name"),
    "first": ("First name",),
    "last": ("Last name", "Surname"),
    "canvas_id": ("ID",),
    "sis_user_id": ("SIS User ID", "ID number", "Student ID", "Student number"),
    "sis_login_id": ("SIS Login ID", "Username", "Login"),
    "email": ("Email address", "Email", "E-mail"),
    "section": ("Section", "Group", "Groups"),
}
#: the ways of matching, in the order they are tried
STEPS = ("SIS login", "SIS id", "Canvas id", "name")


class RosterError(ValueError):
    """A roster that cannot be read: the file, what is wrong, and the fix."""


@dataclass(frozen=True)
class RosterRow:
    """A student as the LMS knows them."""

    line: int
    name: str = ""
    canvas_id: str = ""
    sis_user_id: str = ""
    sis_login_id: str = ""
    email: str = ""
    section: str = ""

    @property
    def said(self) -> str:
        return f"line {self.line} ({self.name or self.sis_login_id or self.email or self.canvas_id})"


@dataclass(frozen=True)
class Roster:
    path: Path
    rows: tuple[RosterRow, ...]
    #: Canvas's assignment ids by the assignment's name (its gradebook's column titles "NAME (ID)")
    assignments: dict = field(default_factory=dict)
    #: identifier columns the roster has, by what they hold
    columns: frozenset = frozenset()


@dataclass(frozen=True)
class Matching:
    """Students matched to roster rows (with the step that matched them), ambiguous ones (the rows that would do),
    those no row matched, and the rows that no student matched."""

    matched: dict  # student -> (RosterRow, step)
    ambiguous: dict  # student -> tuple of RosterRow
    unmatched: tuple
    absent: tuple  # RosterRow without a submission


# ------------------------------------------------------------------------------------------ reading a roster


def _column(fieldnames: list[str], wanted: tuple[str, ...]) -> str | None:
    folded = {name.strip().casefold(): name for name in fieldnames}
    return next((folded[w.casefold()] for w in wanted if w.casefold() in folded), None)


_ASSIGNMENT_TITLE = re.compile(r"^(?P<name>.*\S)\s*\((?P<id>\d+)\)$")
#: Canvas's own columns that look like assignments but are not graded by import
_CANVAS_READ_ONLY = re.compile(r"(current|final|unposted) (score|grade|points)|assignments|imported", re.I)


def read_roster(path: str | Path) -> Roster:
    """The students of a roster CSV (Canvas's gradebook export, Moodle's grade export, or any CSV with a column of
    names, logins, e-mail addresses or ids) and Canvas's assignment ids in its column titles."""
    path = Path(path)
    try:
        with open(path, encoding="utf-8-sig", newline="") as handle:
            reader = csv.reader(handle)
            table = [row for row in reader]
    except FileNotFoundError:
        raise RosterError(f"{path}: no such file") from None
    except (OSError, UnicodeDecodeError, csv.Error) as exc:
        raise RosterError(f"{path}: cannot be read as CSV: {exc}") from None
    if not table:
        raise RosterError(f"{path}: the file is empty (export the gradebook from the LMS as CSV)")
    header = [cell.strip() for cell in table[0]]
    columns = {what: _column(header, names) for what, names in ALIASES.items()}
    if not any(columns[k] for k in ("name", "first", "last", "canvas_id", "sis_user_id", "sis_login_id", "email")):
        raise RosterError(f"{path}: no column names a student (its columns are {', '.join(header[:12])}): export "
                          "the gradebook from Canvas (Grades > Export) or Moodle (Grades > Export > Plain text file)")
    index = {name: header.index(name) for name in header if name}
    assignments = {}
    for title in header[len(CANVAS_COLUMNS):] if header[:1] == ["Student"] else ():
        found = _ASSIGNMENT_TITLE.match(title)
        if found and not _CANVAS_READ_ONLY.search(found.group("name")):
            assignments[found.group("name")] = found.group("id")

    def cell(row: list[str], what: str) -> str:
        column = columns[what]
        position = index.get(column) if column else None
        return row[position].strip() if position is not None and position < len(row) else ""

    rows = []
    for line, row in enumerate(table[1:], start=2):
        first = row[0].strip() if row else ""
        if not any(c.strip() for c in row) or first == POINTS_POSSIBLE or (
                not first and any(c.strip() == "Manual Posting" for c in row)):
            continue  # Canvas's rows of points and posting policies
        name = cell(row, "name") or " ".join(p for p in (cell(row, "first"), cell(row, "last")) if p)
        rows.append(RosterRow(line, name, cell(row, "canvas_id"), cell(row, "sis_user_id"), cell(row, "sis_login_id"),
                              cell(row, "email"), cell(row, "section")))
    return Roster(path, tuple(rows), assignments, frozenset(k for k, v in columns.items() if v))


# ------------------------------------------------------------------------------------------ matching


def _folded(text: str) -> str:
    """Case and accents folded: "Zoë" and "zoe" are one."""
    decomposed = unicodedata.normalize("NFKD", text.casefold())
    return "".join(c for c in decomposed if not unicodedata.combining(c)).strip()


def _words(text: str) -> list[str]:
    return [w for w in re.split(r"[^0-9a-z]+", _folded(text)) if w]


def _logins(row: RosterRow) -> set[str]:
    keys = set()
    for value in (row.sis_login_id, row.email):
        if value:
            keys.add(_folded(value))
            keys.add(_folded(value.split("@")[0]))
    return keys


def _name_keys(name: str, orders: bool) -> set[str]:
    """A name's words in any order: sorted and spaced, and (``orders``: a roster's name) written together in each
    order ("Smith, Alice" is "alice smith", "alicesmith" and "smithalice")."""
    words = _words(name)
    if not words:
        return set()
    keys = {" ".join(sorted(words))}
    if orders and len(words) <= 4:
        keys |= {"".join(p) for p in itertools.permutations(words)}
    elif not orders:
        keys.add("".join(words))
    return keys


def _step_rows(student: str, step: str, rows: tuple[RosterRow, ...]) -> list[RosterRow]:
    folded = _folded(student)
    if step == "SIS login":
        return [r for r in rows if folded in _logins(r)]
    if step == "SIS id":
        return [r for r in rows if r.sis_user_id and _folded(r.sis_user_id) == folded]
    if step == "Canvas id":
        tokens = set(re.findall(r"\d+", student))
        return [r for r in rows if r.canvas_id and r.canvas_id in tokens]
    keys = _name_keys(student, orders=False)
    return [r for r in rows if keys & _name_keys(r.name, orders=True)]


def match(students: list[str], roster: Roster) -> Matching:
    """Each student's roster row: the first step (``STEPS``) at which rows match decides, one row a match, more an
    ambiguity; a row that two students match is ambiguous for both."""
    matched, ambiguous = {}, {}
    for student in students:
        for step in STEPS:
            found = _step_rows(student, step, roster.rows)
            if len(found) == 1:
                matched[student] = (found[0], step)
                break
            if len(found) > 1:
                ambiguous[student] = tuple(found)
                break
    by_row: dict[int, list[str]] = {}
    for student, (row, _) in matched.items():
        by_row.setdefault(row.line, []).append(student)
    for students_of_row in by_row.values():
        if len(students_of_row) > 1:
            for student in students_of_row:
                ambiguous[student] = (matched.pop(student)[0],)
    used = {row.line for row, _ in matched.values()} | {r.line for rows in ambiguous.values() for r in rows}
    unmatched = tuple(s for s in students if s not in matched and s not in ambiguous)
    return Matching(matched, ambiguous, unmatched, tuple(r for r in roster.rows if r.line not in used))


def matching_summary(matching: Matching, roster: Roster) -> list[str]:
    """What ``grade export`` says of the roster: matched (by which step), ambiguous, unmatched, absent."""
    steps = {}
    for _, step in matching.matched.values():
        steps[step] = steps.get(step, 0) + 1
    how = ", ".join(f"{steps[s]} by {s}" for s in STEPS if s in steps)
    lines = [f"roster {roster.path}: {len(matching.matched)} matched" + (f" ({how})" if how else "")
             + f", {len(matching.ambiguous)} ambiguous, {len(matching.unmatched)} unmatched"]
    for student, rows in sorted(matching.ambiguous.items()):
        lines.append(f"  ambiguous, not written: {student}: roster {', '.join(r.said for r in rows)}")
    for student in matching.unmatched:
        lines.append(f"  unmatched, not written: {student}: no roster row has this login, SIS id or name")
    if matching.absent:
        shown = ", ".join(r.name or r.sis_login_id or str(r.line) for r in matching.absent[:10])
        more = f" and {len(matching.absent) - 10} more" if len(matching.absent) > 10 else ""
        lines.append(f"  in the roster without a submission (not written): {shown}{more}")
    return lines


# ------------------------------------------------------------------------------------------ the files' rows


def _folded_title(name: str) -> str:
    return " ".join(_folded(name).split())


def canvas_title(name: str, roster: Roster | None) -> str:
    """An assignment's column title: "NAME (ID)" with the id of the roster's column of that name, else NAME."""
    if roster is not None:
        ids = {_folded_title(title): number for title, number in roster.assignments.items()}
        number = ids.get(_folded_title(name))
        if number is not None:
            return f"{name} ({number})"
    return name


def _points(x: float | None) -> str:
    return "" if x is None else f"{x:g}"


def canvas_rows(assignments: list[str], possible: dict[str, float], grades: dict[str, dict[str, object]],
                roster: Roster | None, matching: Matching | None) -> list[list[str]]:
    """canvas.csv's rows: the header, the points possible, and a row per student written (``grades``: student ->
    assignment -> final score, ``EXCUSED`` or None).  Without a roster, a student is named by their submission's
    name, as Student and SIS Login ID."""
    rows = [[*CANVAS_COLUMNS, *[canvas_title(a, roster) for a in assignments]],
            [POINTS_POSSIBLE, "", "", "", "", *[_points(possible.get(a)) for a in assignments]]]
    for student, cells in grades.items():
        if roster is None:
            who = [student, "", "", student, ""]
        elif student in matching.matched:
            row = matching.matched[student][0]
            who = [row.name, row.canvas_id, row.sis_user_id, row.sis_login_id, row.section]
        else:
            continue
        rows.append([*who, *[cells.get(a) if cells.get(a) == EXCUSED else _points(cells.get(a))
                             for a in assignments]])
    return rows


#: Moodle's names of the identifier columns, by what they hold
MOODLE_IDENTIFIERS = {"email": "Email address", "sis_login_id": "Username", "sis_user_id": "ID number"}


def moodle_rows(assignments: list[str], grades: dict[str, dict[str, object]], feedback: dict[str, dict[str, str]],
                roster: Roster | None, matching: Matching | None) -> list[list[str]]:
    """moodle.csv's rows: identifier columns (the roster's e-mail address, username and ID number where it has
    them; without a roster the submission's name as Username), then a grade and a feedback column per assignment."""
    kinds = [k for k in MOODLE_IDENTIFIERS if roster is not None and k in roster.columns] or ["sis_login_id"]
    rows = [[*(MOODLE_IDENTIFIERS[k] for k in kinds),
             *itertools.chain.from_iterable((a, f"{a} (feedback)") for a in assignments)]]
    for student, cells in grades.items():
        if roster is None:
            ids = [student]
        elif student in matching.matched:
            row = matching.matched[student][0]
            ids = [getattr(row, k) for k in kinds]
        else:
            continue
        values = []
        for a in assignments:
            grade = cells.get(a)
            values += ["" if grade == EXCUSED else _points(grade), feedback.get(student, {}).get(a, "")]
        rows.append([*ids, *values])
    return rows

