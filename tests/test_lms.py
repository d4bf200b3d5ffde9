"""Grades for Canvas and Moodle: the roster's matching (login, SIS id, Canvas id in a download's name, name in any
order; ambiguity said and not written), excused and blank cells, and moodle.csv read as Moodle's CSV import reads it,
with each assignment's feedback (the late penalty and the grader's comments)."""

import csv
import re
from pathlib import Path

import pytest

from grader.batch.exports import export_results
from grader.batch.gradebook import Gradebook
from grader.batch.lms import Roster, RosterError, RosterRow, match, read_roster
from grader.cli import main

from .batch_fixtures import synthetic_report
from .test_course import canvas_import

VERSIONS = {6: "test+6", 7: "test+7", 8: "test+8"}


def roster_of(*rows: RosterRow) -> Roster:
    return Roster(Path("roster.csv"), rows)


def test_students_are_matched_by_login_then_sis_id_then_canvas_id_then_name():
    rows = (RosterRow(2, "Smith, Alice", "1101", "S1001", "asmith", "alice.smith@uni.example"),
            RosterRow(3, "Lee, Carol", "1103", "S1003", "clee"),
            RosterRow(4, "Müller, Zoë", "1104", "S1004", "zm"),
            RosterRow(5, "John Smith", "1105", "S1005", "js"),
            RosterRow(6, "Bob Jones", "1106", "S1006", "bj"))
    students = ["asmith", "alice.smith", "S1003", "zoe_muller", "smithjohn_1105_998877_homework", "Jones Bob",
                "nobody"]
    found = match(students, roster_of(*rows))
    how = {student: (row.line, step) for student, (row, step) in found.matched.items()}
    assert how == {"S1003": (3, "SIS id"), "zoe_muller": (4, "name"),
                   "smithjohn_1105_998877_homework": (5, "Canvas id"), "Jones Bob": (6, "name")}
    # asmith (login) and alice.smith (the e-mail's name) are the same row: neither is written
    assert set(found.ambiguous) == {"asmith", "alice.smith"} and found.unmatched == ("nobody",)
    assert found.absent == ()


def test_a_name_that_two_roster_rows_share_is_ambiguous():
    rows = (RosterRow(2, "Lee, Carol", "1", "S1"), RosterRow(3, "Carol Lee", "2", "S2"))
    found = match(["carol_lee", "S2"], roster_of(*rows))
    assert {s: [r.line for r in rs] for s, rs in found.ambiguous.items()} == {"carol_lee": [2, 3]}
    assert found.matched["S2"][0].line == 3  # a login or SIS id decides before the name


def test_a_roster_that_cannot_be_read_is_refused_with_the_fix(tmp_path, capsys):
    bad = tmp_path / "roster.csv"
    bad.write_text("Course,Points\nMechanics,10\n")
    with pytest.raises(RosterError, match="no column names a student"):
        read_roster(bad)
    out = tmp_path / "results"
    with Gradebook.in_folder(out) as book:
        book.record("alice", "h", VERSIONS, book.start_run("subs", [6], 1), [synthetic_report(6)])
    assert main(["export", str(out), "--canvas", "--roster", str(bad)]) == 2
    assert capsys.readouterr().err.count("no column names a student") == 1
    assert main(["export", str(out), "--roster", str(bad)]) == 2
    assert "--roster names the students of --canvas or --moodle" in capsys.readouterr().err
    assert not (out / "canvas.csv").exists()


COURSE = """\
[[assignment]]
name = "Exercise II"
problems = [6, 7]
due = 2026-12-01T23:59:00+01:00

[[assignment]]
name = "Exercise III"
problems = [8]
due = 2026-12-08T23:59:00+01:00

[late]
per_day = 0.25

[excused]
carol = ["Exercise III"]
"""

MOODLE_EXPORT = """\
First name,Last name,ID number,Institution,Department,Email address,Assignment: Exercise II (Real),Last downloaded from this course
Alice,Smith,S1001,,,alice@uni.example,-,1764000000
Bob,Jones,S1002,,,bob@uni.example,-,1764000000
Carol,Lee,S1003,,,carol@uni.example,-,1764000000
"""


@pytest.fixture
def gradebook(tmp_path):
    """alice graded on problems 6-8 with a scored and commented free-text answer, bob on problems 6 and 7 only
    (Exercise III: no grade), carol excused from Exercise III; bob submitted a day late."""
    out = tmp_path / "results"
    (tmp_path / "course.toml").write_text(COURSE)
    with Gradebook.in_folder(out) as book:
        run = book.start_run("subs", [6, 7, 8], 1)
        book.record("alice", "ha", VERSIONS, run, [synthetic_report(6, manual=True), synthetic_report(7, checks=4),
                                                    synthetic_report(8, failed=(1,), checks=3)])
        book.record("bob", "hb", VERSIONS, run, [synthetic_report(6, failed=(0, 1), manual=True),
                                                  synthetic_report(7, checks=4)])
        book.record("carol", "hc", VERSIONS, run, [synthetic_report(6, manual=True), synthetic_report(7, checks=4),
                                                    synthetic_report(8, checks=3)])
        book.note_submission_times([("alice", "ha", "2026-12-01T20:00:00+01:00", "files"),
                                    ("bob", "hb", "2026-12-02T08:00:00+01:00", "gradescope"),
                                    ("carol", "hc", "2026-12-01T20:00:00+01:00", "files")])
        book.import_manual("student,problem,key,score,comment\n"
                           "alice,6,why,1.5,\"Right; say why the columns are orthogonal.\"\n")
    return tmp_path, out


def test_canvas_cells_are_scores_ex_for_excused_and_empty_for_no_grade(gradebook):
    folder, out = gradebook
    assert main(["export", str(out), "--course", str(folder / "course.toml"), "--canvas"]) == 0
    text = (out / "canvas.csv").read_text(encoding="utf-8")
    # without a roster: the titles alone (Canvas makes the assignments), each student named by their submission's
    # name as Student and SIS Login ID
    users = [{"ID": f"u-{name}", "SIS User ID": "", "SIS Login ID": name} for name in ("alice", "bob", "carol")]
    points, grades = canvas_import(text, users)
    assert points == {"Exercise II": 13.0, "Exercise III": 3.0}  # problem 6's free text counts once scored
    assert grades == {
        ("u-alice", "Exercise II"): 12.5, ("u-alice", "Exercise III"): 2.0,
        ("u-bob", "Exercise II"): 6.75,  # 9 points a day late at 25% a day; Exercise III: no grade, no cell
        ("u-carol", "Exercise II"): 11.0, ("u-carol", "Exercise III"): "EX"}
    cells = {row[3]: row[5:] for row in csv.reader(text.splitlines()[2:])}
    assert cells["bob"] == ["6.75", ""] and cells["carol"] == ["11", "EX"]


def moodle_import(text: str, identifier: str, users: dict[str, str]) -> dict:
    """moodle.csv read as Moodle's CSV grade import reads it once mapped: ``identifier`` mapped to the user field
    (the other identifier columns ignored), each assignment's column to its grade item and "NAME (feedback)" to its
    feedback; an empty grade cell is not imported.  Returns (user, item) -> (grade or None, feedback)."""
    rows = list(csv.DictReader(text.splitlines()))
    header = list(rows[0])
    items = [h for h in header if f"{h} (feedback)" in header]
    others = [h for h in header if h not in items and not h.endswith(" (feedback)")]
    assert identifier in others and set(others) <= {"Email address", "Username", "ID number"}  # the rest: ignored
    imported = {}
    for row in rows:
        user = users[row[identifier]]
        for item in items:
            grade = row[item].strip()
            imported[(user, item)] = (float(grade) if grade else None, row[f"{item} (feedback)"])
    return imported


def test_moodle_reads_each_grade_and_feedback_with_the_late_penalty_and_the_graders_comment(gradebook, tmp_path):
    folder, out = gradebook
    roster = tmp_path / "moodle-export.csv"
    roster.write_text(MOODLE_EXPORT)
    assert main(["export", str(out), "--course", str(folder / "course.toml"), "--moodle", "--roster",
                 str(roster)]) == 0
    text = (out / "moodle.csv").read_text(encoding="utf-8")
    assert text.splitlines()[0].startswith("Email address,ID number,Exercise II,Exercise II (feedback),Exercise III")
    imported = moodle_import(text, "Email address", {"alice@uni.example": 1, "bob@uni.example": 2,
                                                     "carol@uni.example": 3})
    grade, feedback = imported[(1, "Exercise II")]
    assert grade == 12.5 and feedback.startswith("12.5 of 13 points.")
    assert "Problem 6, Why? (1.5 of 2): Right; say why the columns are orthogonal." in feedback
    grade, feedback = imported[(2, "Exercise II")]
    assert grade == 6.75 and feedback.startswith("9 of 13 points.")
    assert ("Submitted 2026-12-02 08:00 +01:00 (Gradescope's submission metadata), 1 day after the due date "
            "2026-12-01 23:59 +01:00: 25% off: -2.25 points, 6.75 points.") in feedback
    assert imported[(2, "Exercise III")] == (None, "")
    assert imported[(3, "Exercise III")] == (None, "Excused from this assignment.")


def test_a_students_name_that_is_a_formula_stays_text_in_the_lms_files(tmp_path):
    out = tmp_path / "results"
    with Gradebook.in_folder(out) as book:
        book.record("=HYPERLINK(1)", "h", VERSIONS, book.start_run("subs", [6], 1), [synthetic_report(6)])
        book.set_meta("export.canvas", "")
        book.set_meta("export.moodle", "")
        export_results(out, book, students=False)
    for name in ("canvas.csv", "moodle.csv"):
        cells = [c for row in csv.reader((out / name).read_text().splitlines()) for c in row]
        assert "'=HYPERLINK(1)" in cells and not [c for c in cells if re.match(r"[=+@]", c)], name
