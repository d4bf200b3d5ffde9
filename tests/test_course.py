"""A course's deadlines: course.toml read and refused with its line and the fix, the late policy (started days, cap,
cut-off, grace days, extensions), and a class of three graded by `grade batch` whose final scores follow the policy
and change with the due date on `grade export`, without grading anyone again."""

import csv
import json
import os
import re
import sqlite3
from datetime import datetime, timedelta, timezone
from pathlib import Path

import pytest

from grader.batch.course import (
    Assignment,
    Course,
    CourseError,
    LatePolicy,
    SubmissionTime,
    days_late,
    late_share,
    parse_course,
    standings,
)
from grader.cli import main

from .submissions import build_planted, copy_reference, planted_mistakes

CET = timezone(timedelta(hours=1))
DUE = datetime(2026, 12, 1, 23, 59, tzinfo=CET)
ISSUE_EXAMPLE = """\
[[assignment]]
name = "Exercise II"
problems = [6, 7, 8, 9, 10]
due = 2026-12-01T23:59:00+01:00

[late]
per_day = 0.10     # share of the score lost per started day late
max_days = 5       # later than this, the score is 0

[extensions]
carol = 2026-12-04T23:59:00+01:00   # the student's own due date
"""


# ------------------------------------------------------------------------------------------ the file


def test_the_issues_example_reads_as_written():
    course = parse_course(ISSUE_EXAMPLE, known_problems=set(range(1, 48)))
    assert course.assignments == (Assignment("Exercise II", (6, 7, 8, 9, 10), DUE),)
    assert course.late == LatePolicy(per_day=0.10, max_days=5)
    assert course.extensions == {("carol", "Exercise II"): datetime(2026, 12, 4, 23, 59, tzinfo=CET)}
    assert course.problems == [6, 7, 8, 9, 10]


def test_an_extension_date_extends_the_assignment_due_last_before_it():
    text = """\
timezone = "Europe/Berlin"
[[assignment]]
name = "Exercise II"
problems = [6]
due = 2026-12-01T23:59:00+01:00
[[assignment]]
name = "Exercise III"
problems = [11]
due = 2026-12-08T23:59:00          # in the course's time zone
[extensions]
carol = 2026-12-04T23:59:00+01:00
dave = 2026-12-10T12:00:00+01:00
erin = { "Exercise II" = 2026-12-10T12:00:00+01:00 }
[excused]
frank = ["Exercise III"]
"""
    course = parse_course(text)
    assert course.assignments[1].due.utcoffset() == timedelta(hours=1)  # Berlin in December
    assert sorted(course.extensions) == [("carol", "Exercise II"), ("dave", "Exercise III"), ("erin", "Exercise II")]
    assert course.excused == {("frank", "Exercise III")}


WRONG = [
    # (what the file says, the line said, what the message says)
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\ndue = 2026-12-01\n", 4, "is a date without a time"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\ndue = 2026-12-01T23:59:00\n", 4, "has no time zone"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\ndue = \"2026-12-01T23:59:00+01:00\"\n", 4, "is text, not a date"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\n\n[late]\nper_day = 10\n", 6, "per_day is 10. Write a number from 0"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\n\n[late]\nperday = 0.1\n", 6, "[late] has no key 'perday'"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\n\n[late]\nmax_days = 2.5\n", 6, "Write a whole number"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\n[[assignment]]\nname = \"B\"\nproblems = [7, 6]\n", 6,
     "problem 6 is in 'A' and in 'B'"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\n[[assignment]]\nname = \"A\"\nproblems = [7]\n", 5,
     "two assignments are named 'A'"),
    ("[[assignment]]\nname = \"A\"\nproblems = [23]\n", 3, "problem 23 of 'A' has no checks"),
    ("[[assignment]]\nname = \"A\"\nproblems = []\n", 3, "Write the problem numbers in brackets"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\ndue = 2026-12-01T23:59:00+01:00\n[extensions]\n"
     "bob = 2026-11-30T23:59:00+01:00\n", 6, "is not later than any assignment's due date"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\ndue = 2026-12-01T23:59:00+01:00\n[extensions]\n"
     "bob = { \"B\" = 2026-12-05T23:59:00+01:00 }\n", 6, "names 'B', which is not an assignment"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\n[excused]\nbob = [\"Exercise 2\"]\n", 5, "which is not an assignment"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6]\ndue = 2026-12-01T23:59:00+01:00\nlate = 3\n", 5,
     "an [[assignment]] has no key 'late'"),
    ("[[assignment]]\nname = \"A\"\nproblems = [6\ndue = 2026-12-01T23:59:00+01:00\n", 4, "TOML syntax"),
    ("timezone = \"Mars/Olympus\"\n[[assignment]]\nname = \"A\"\nproblems = [6]\n", 1, "not a time zone"),
    ("[late]\nper_day = 0.1\n", None, "the file has no [[assignment]]"),
]


@pytest.mark.parametrize("text, line, said", WRONG, ids=[w[2][:30] for w in WRONG])
def test_a_wrong_course_file_is_refused_with_its_line_and_the_fix(text, line, said):
    with pytest.raises(CourseError) as error:
        parse_course(text, Path("course.toml"), known_problems={6, 7, 8})
    message = str(error.value)
    where = f"course.toml, line {line}" if line else "course.toml:"
    assert message.startswith(where) and said in message, message


def test_a_wrong_course_file_stops_the_batch_before_anyone_is_graded_and_is_said_once(tmp_path, capsys):
    subs = tmp_path / "subs"
    copy_reference(subs / "alice")
    (subs / "course.toml").write_text("[[assignment]]\nname = \"II\"\nproblems = [6]\ndue = 2026-12-01\n")
    assert main(["batch", str(subs), "--out", str(tmp_path / "out"), "-q"]) == 2
    err = capsys.readouterr().err
    assert err.count("course.toml, line 4: 2026-12-01 is a date without a time. Write the time too") == 1, err
    assert "Traceback" not in err and not (tmp_path / "out").exists()


# ------------------------------------------------------------------------------------------ the policy


def test_a_day_late_is_any_part_of_a_day():
    assert days_late(DUE, DUE) == 0 and days_late(DUE - timedelta(hours=5), DUE) == 0
    assert days_late(DUE + timedelta(minutes=1), DUE) == 1
    assert days_late(DUE + timedelta(hours=24), DUE) == 1
    assert days_late(DUE + timedelta(hours=24, seconds=1), DUE) == 2
    # the same instant in another zone is the same lateness
    assert days_late(datetime(2026, 12, 2, 0, 30, tzinfo=timezone.utc), DUE) == 1


def test_the_share_lost_grows_per_day_up_to_the_cap_and_is_everything_past_max_days():
    policy = LatePolicy(per_day=0.1, max_days=5, cap=0.3)
    assert [late_share(d, policy) for d in range(8)] == [0, 0.1, 0.2, 0.3, 0.3, 0.3, 1.0, 1.0]
    assert late_share(3, LatePolicy(per_day=0.5)) == 1.0  # never more than the score


def test_grace_days_are_spent_in_the_order_of_the_due_dates():
    first = Assignment("Exercise II", (6,), DUE)
    second = Assignment("Exercise III", (11,), DUE + timedelta(days=7))
    course = Course((second, first), LatePolicy(per_day=0.1, grace_days=2))  # listed out of order
    times = {"Exercise II": SubmissionTime(DUE + timedelta(hours=30), "files"),  # 2 days late: both grace days
             "Exercise III": SubmissionTime(second.due + timedelta(hours=1), "files")}  # 1 day late: none left
    rows = {s.assignment: s for s in standings(course, "bob", {6: 8.0, 11: 5.0}, {6: 10.0, 11: 7.0}, times)}
    assert (rows["Exercise II"].days_late, rows["Exercise II"].grace_days, rows["Exercise II"].final) == (2, 2, 8.0)
    assert (rows["Exercise III"].days_late, rows["Exercise III"].grace_days) == (1, 0)
    assert (rows["Exercise III"].penalty, rows["Exercise III"].final) == (0.5, 4.5)


# ------------------------------------------------------------------------------------------ a class of three


def _submitted_at(folder: Path, moment: datetime) -> None:
    """Give every file of a submission this modification time (as a download or an unpacked archive would)."""
    stamp = moment.timestamp()
    for path in [*folder.rglob("*"), folder]:
        os.utime(path, (stamp, stamp))


def _grades(out: Path) -> dict[str, dict]:
    with open(out / "grades.csv", newline="", encoding="utf-8") as handle:
        return {row["student"]: row for row in csv.DictReader(handle)}


def _graded_rows(out: Path) -> list:
    with sqlite3.connect(out / "gradebook.sqlite") as db:
        return db.execute("SELECT student_id, problem, run_id, graded_at, score FROM submissions ORDER BY id").fetchall()


COURSE = """\
[[assignment]]
name = "Exercise II"
problems = [6]
due = {due}

[late]
per_day = 0.10
max_days = 5

[extensions]
carol = 2026-12-04T23:59:00+01:00
"""


@pytest.fixture(scope="module")
def three(tmp_path_factory):
    """alice on time, bob two days late (with the transposed-vectors mistake: 9 of 10 points), carol late but within
    her extension, erin on time by Gradescope's metadata (her files were touched later): graded by `grade batch`
    with course.toml in the submissions folder."""
    root = tmp_path_factory.mktemp("three")
    subs = root / "subs"
    copy_reference(subs / "alice")
    build_planted(next(m for m in planted_mistakes(6) if m.name == "p06-vectors-transpose"), subs / "bob")
    copy_reference(subs / "carol")
    copy_reference(subs / "erin" / "submission")
    (subs / "erin" / "submission_metadata.json").write_text(json.dumps(
        {"id": 123456, "created_at": "2026-12-01T14:00:00.123456-08:00", "users": [{"name": "Erin"}]}))
    _submitted_at(subs / "alice", datetime(2026, 12, 1, 20, 0, tzinfo=CET))
    _submitted_at(subs / "bob", datetime(2026, 12, 3, 23, 0, tzinfo=CET))  # 47 h late: two started days
    _submitted_at(subs / "carol", datetime(2026, 12, 3, 12, 0, tzinfo=CET))
    _submitted_at(subs / "erin" / "submission", datetime(2026, 12, 9, 9, 0, tzinfo=CET))
    (subs / "course.toml").write_text(COURSE.format(due="2026-12-01T23:59:00+01:00"))
    out = root / "results"
    code = main(["batch", str(subs), "--out", str(out), "--jobs", "2", "-q"])
    return subs, out, code


def test_a_class_of_three_gets_the_policys_final_scores(three):
    subs, out, code = three
    assert code == 0
    grades = _grades(out)
    assert list(next(iter(grades.values())))[:9] == [
        "student", "problem_6", "Exercise II raw", "Exercise II late penalty", "Exercise II", "total", "possible",
        "status", "submitted"]
    got = {name: (row["Exercise II raw"], row["Exercise II late penalty"], row["Exercise II"], row["total"],
                  row["possible"]) for name, row in grades.items()}
    assert got == {"alice": ("10", "0", "10", "10", "10"),
                   "bob": ("9", "1.8", "7.2", "7.2", "10"),  # 2 started days at 10% a day
                   "carol": ("10", "0", "10", "10", "10"),  # after the due date, within her extension
                   "erin": ("10", "0", "10", "10", "10")}
    assert grades["alice"]["status"] == "graded"
    assert grades["bob"]["status"] == "graded; late: Exercise II by 2 days (20% off)"
    assert grades["carol"]["status"] == "graded; extension: Exercise II to 2026-12-04 23:59 +01:00"
    # where each submission time comes from, in the course's offset
    assert (grades["bob"]["submitted"], grades["bob"]["submitted from"]) == (
        "2026-12-03 23:00 +01:00", "the newest file's time")
    assert (grades["erin"]["submitted"], grades["erin"]["submitted from"]) == (
        "2026-12-01 23:00 +01:00", "Gradescope's submission metadata")
    # each student's report says when the work was submitted, how that is known, and what being late cost
    def deadlines(name):
        html = (out / "students" / name / "report.html").read_text()
        return re.search(r'<section id="deadlines">(.*?)</section>', html, re.S).group(1)

    assert ("Exercise II: submitted 2026-12-03 23:00 +01:00 (the newest file&#39;s time), 2 days after the due date "
            "2026-12-01 23:59 +01:00: 20% off: -1.8 points, 7.2 points.") in deadlines("bob")
    assert "by the due date 2026-12-04 23:59 +01:00 (your extension)." in deadlines("carol")
    assert ("submitted 2026-12-01 23:00 +01:00 (Gradescope&#39;s submission metadata), by the due date"
            in deadlines("erin"))
    # the gradebook keeps them
    with sqlite3.connect(out / "gradebook.sqlite") as db:
        kept = dict(((s, (r, p, f)) for s, r, p, f in db.execute(
            "SELECT student, raw, penalty, final FROM assignment_scores")))
    assert kept["bob"] == (9.0, 1.8, 7.2) and kept["alice"] == (10.0, 0.0, 10.0)


def test_changing_the_due_date_and_exporting_changes_the_scores_without_grading_again(three, tmp_path, capsys):
    subs, out, _ = three
    before = _graded_rows(out)
    runs = sqlite3.connect(out / "gradebook.sqlite").execute("SELECT count(*) FROM runs").fetchone()[0]
    course = subs / "course.toml"
    original = course.read_text()
    try:
        course.write_text(COURSE.format(due="2026-12-02T23:59:00+01:00"))  # a day later for everyone
        assert main(["export", str(out)]) == 0
        grades = _grades(out)
        assert (grades["bob"]["Exercise II late penalty"], grades["bob"]["Exercise II"]) == ("0.9", "8.1")
        assert grades["bob"]["status"] == "graded; late: Exercise II by 1 day (10% off)"
        assert "1 day after the due date 2026-12-02 23:59 +01:00: 10% off: -0.9 points, 8.1 points." in \
            (out / "students" / "bob" / "report.html").read_text()
        assert grades["alice"]["Exercise II"] == grades["carol"]["Exercise II"] == "10"
        # another course file given on the command line, and a policy with a cap and grace days
        other = tmp_path / "strict.toml"
        other.write_text(original.replace("max_days = 5", "max_days = 1"))
        assert main(["export", str(out), "--course", str(other)]) == 0
        assert (_grades(out)["bob"]["Exercise II"]) == "0"  # 2 days: past max_days
        other.write_text(original.replace("max_days = 5", "max_days = 5\ngrace_days = 1"))
        assert main(["export", str(out), "--course", str(other)]) == 0
        assert _grades(out)["bob"]["status"] == "graded; late: Exercise II by 2 days (10% off, 1 grace day used)"
        other.write_text(original.replace("carol =", "karol ="))  # a misspelt name is said, not silently ignored
        capsys.readouterr()
        assert main(["export", str(out), "--course", str(other)]) == 0
        assert f"{other} names karol (an extension or an excuse), who has no submission" in capsys.readouterr().err
        assert _grades(out)["carol"]["status"] == "graded; late: Exercise II by 2 days (20% off)"
    finally:
        course.write_text(original)
    assert main(["export", str(out), "--course", str(course)]) == 0
    assert _grades(out)["bob"]["Exercise II"] == "7.2"
    assert _graded_rows(out) == before  # nobody graded again
    assert sqlite3.connect(out / "gradebook.sqlite").execute("SELECT count(*) FROM runs").fetchone()[0] == runs
    assert "submission times: 3 from the newest file's time, 1 from Gradescope's submission metadata" in \
        capsys.readouterr().err


def test_a_roster_column_gives_the_submission_times(three, tmp_path):
    """The LMS's own record of when each student submitted, in a CSV beside course.toml, stands before the files'
    times; a time without an offset is read in the course's time zone."""
    subs, out, _ = three
    (tmp_path / "submitted.csv").write_text("Student,Submitted\nbob,2026-12-01 23:30\nalice,2026-12-02 10:00\n")
    course = tmp_path / "course.toml"
    course.write_text('timezone = "Europe/Berlin"\n' + COURSE.format(due="2026-12-01T23:59:00+01:00")
                      + '\n[submission_times]\nroster = "submitted.csv"\nstudent = "Student"\ntime = "Submitted"\n')
    try:
        assert main(["export", str(out), "--course", str(course)]) == 0
        grades = _grades(out)
        assert (grades["bob"]["Exercise II"], grades["bob"]["submitted from"]) == ("9", "the roster's column")
        assert (grades["alice"]["Exercise II"], grades["alice"]["submitted"]) == ("9", "2026-12-02 10:00 +01:00")
        assert grades["carol"]["submitted from"] == "the newest file's time"  # not in the roster
        (tmp_path / "submitted.csv").write_text("Student,Submitted\nbob,yesterday\n")
        assert main(["export", str(out), "--course", str(course)]) == 2
    finally:
        assert main(["export", str(out), "--course", str(subs / "course.toml")]) == 0


def test_the_gradescope_metadata_is_read_beside_the_submission_never_from_the_students_files(tmp_path):
    """A student who puts a submission_metadata.json of their own among their files does not set their time."""
    from grader.batch.course import entry_time
    from grader.batch.discover import discover

    subs = tmp_path / "subs"
    copy_reference(subs / "mallory")
    (subs / "mallory" / "submission_metadata.json").write_text('{"created_at": "2020-01-01T00:00:00+00:00"}')
    copy_reference(subs / "erin" / "submission")
    (subs / "erin" / "submission_metadata.json").write_text('{"created_at": "2026-12-01T14:00:00-08:00"}')
    entries = {e.name: e for e in discover(subs)[0]}
    assert entries["mallory"].metadata is None and entry_time(entries["mallory"]).source == "files"
    assert entries["erin"].path == subs / "erin" / "submission"
    assert entry_time(entries["erin"]) == SubmissionTime(datetime(2026, 12, 1, 22, 0, tzinfo=timezone.utc),
                                                         "gradescope")


# ------------------------------------------------------------------------------------------ to Canvas and back


CANVAS_EXPORT = """\
Student,ID,SIS User ID,SIS Login ID,Section,Exercise II (4711),Exercise III (4712),Current Score,Unposted Current Score,Final Score,Current Grade,Final Grade
    Points Possible,,,,,10.00,12.00,(read only),(read only),(read only),(read only),(read only)
"Smith, Alice",1101,S1001,alice@uni.example,Mechanics 1,,,0.00,0.00,0.00,F,F
"Jones, Bob",1102,bob,bjones,Mechanics 2,,,0.00,0.00,0.00,F,F
"Lee, Carol",1103,S1003,carol,Mechanics 1,,,0.00,0.00,0.00,F,F
Erin,1105,S1005,ekim,Mechanics 2,,,0.00,0.00,0.00,F,F
"Absent, Dana",1104,S1004,dana,Mechanics 2,,,0.00,0.00,0.00,F,F
Test Student,1199,,a1b2c3d4e5,Mechanics 1,,,0.00,0.00,0.00,F,F
"""


def canvas_users(export: str) -> list[dict]:
    """The students of a Canvas course, as its gradebook export lists them."""
    rows = list(csv.DictReader(export.splitlines()))
    return [r for r in rows if r["Student"].strip() != "Points Possible"]


def canvas_import(text: str, users: list[dict]) -> tuple[dict, dict]:
    """canvas.csv read as Canvas's gradebook import reads it: the five columns that name a student, assignment
    columns "NAME (ID)" (an existing assignment) or "NAME" (a new one), the "Points Possible" row, then each row's
    student found by ID, else SIS User ID, else SIS Login ID; a cell is a score, "EX" (excused) or empty (no grade
    imported).  Returns the points possible and the grades, both by assignment (its id, else its name)."""
    rows = list(csv.reader(text.splitlines()))
    header = rows[0]
    assert header[:5] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"], header
    assignments = []
    for title in header[5:]:
        name, number = re.fullmatch(r"(.+?)(?: \((\d+)\))?", title).groups()
        assignments.append(number or name)
    assert rows[1][0] == "Points Possible" and not any(rows[1][1:5]), rows[1]
    points = dict(zip(assignments, (float(c) for c in rows[1][5:])))
    grades = {}
    for row in rows[2:]:
        assert len(row) == len(header), row
        user = next((u for key, cell in (("ID", row[1]), ("SIS User ID", row[2]), ("SIS Login ID", row[3]))
                     for u in users if cell and u[key] == cell), None)
        assert user is not None, f"Canvas finds no student for {row[:5]}"
        for assignment, cell in zip(assignments, row[5:]):
            if cell == "":
                continue
            grades[(user["ID"], assignment)] = "EX" if cell == "EX" else float(cell)
    return points, grades


def test_a_canvas_export_as_roster_matches_every_student_and_canvas_reads_their_grades(three, tmp_path, capsys):
    subs, out, _ = three
    roster = tmp_path / "canvas-export.csv"
    roster.write_text(CANVAS_EXPORT, encoding="utf-8")
    assert main(["export", str(out), "--canvas", "--roster", str(roster)]) == 0
    err = capsys.readouterr().err
    assert (f"canvas.csv: roster {roster}: 4 matched (2 by SIS login, 1 by SIS id, 1 by name), 0 ambiguous, "
            "0 unmatched") in err, err
    assert "in the roster without a submission (not written): Absent, Dana, Test Student" in err
    points, grades = canvas_import((out / "canvas.csv").read_text(encoding="utf-8"), canvas_users(CANVAS_EXPORT))
    assert points == {"4711": 10.0}  # the roster's assignment id: Canvas updates that assignment
    finals = {name: float(row["Exercise II"]) for name, row in _grades(out).items()}
    ids = {"alice": "1101", "bob": "1102", "carol": "1103", "erin": "1105"}
    assert grades == {(ids[name], "4711"): final for name, final in finals.items()}
    assert finals["bob"] == 7.2
    with open(out / "canvas.csv", newline="", encoding="utf-8") as handle:
        by_id = {row[1]: row for row in csv.reader(handle)}
    assert by_id["1102"][:5] == ["Jones, Bob", "1102", "bob", "bjones", "Mechanics 2"]
    # the later exports keep writing it (grade import-manual, a changed course file)
    (out / "canvas.csv").unlink()
    assert main(["export", str(out)]) == 0 and (out / "canvas.csv").is_file()


def test_the_guides_course_file_reads_as_it_says():
    guide = (Path(__file__).resolve().parents[1] / "docs" / "instructors.md").read_text()
    text = re.search(r"```toml\n(.*?)```", guide, re.S).group(1)
    course = parse_course(text, Path("course.toml"), set(range(1, 48)))
    assert [a.name for a in course.assignments] == ["Exercise II", "Exercise III"]
    assert course.late == LatePolicy(per_day=0.10, max_days=5, cap=0.30, grace_days=2)
    assert course.extensions[("carol", "Exercise II")] == datetime(2026, 12, 4, 23, 59, tzinfo=CET)
    assert course.excused == {("erin", "Exercise II")} and course.times.time == "submitted"
