"""One gate for every answer: what a check receives from the student has the type, shape and keys it needs, or the
check fails saying that the answer cannot be graded (the student's error, never an internal grader error); every
natural way of writing a correct answer passes it."""

from __future__ import annotations

import pytest

from checks._answers import option_number
from grader import grade_submission
from grader.results import Status

from .submissions import copy_reference

# ---------------------------------------------------------------------------------------------- choices


@pytest.mark.parametrize("written, number", [
    (4, 4), (4.0, 4), ("4", 4), (" 4 ", 4), ("4.0", 4), (1, 1),
    (True, None), (False, None), (4.5, None), ("four", None), ("", None), (None, None), ([4], None),
    (float("nan"), None), (float("inf"), None),
])
def test_an_option_is_a_whole_number_however_written(written, number):
    assert option_number(written) == number


#: (answers.toml section, key, the reference's option): one multiple-choice answer of every problem that has them
CHOICES = [("problem_10", "a", 4, "p10.a"), ("problem_20", "a", 3, "p20.part_a"),
           ("problem_27", "a", 4, "p27.choice_a"), ("problem_41", "a", 4, "p41.choice_a"),
           ("problem_42", "b", 2, "p42.direction_choice")]


def _answered(tmp_path, written: dict):
    """A reference copy whose answers.toml writes the chosen options as given (``{(section, key): text}``)."""
    submission = copy_reference(tmp_path / "pkg")
    path = submission / "answers.toml"
    lines, section = [], ""
    for line in path.read_text().splitlines():
        if line.startswith("["):
            section = line.strip("[]")
        key = line.partition("=")[0].strip()
        if (section, key) in written:
            line = f"{key} = {written[section, key]}"
        lines.append(line)
    path.write_text("\n".join(lines) + "\n")
    return submission


@pytest.mark.parametrize("form", ["{n}.0", '"{n}"', '" {n} "', '"{n}.0"'])
def test_every_way_of_writing_the_right_option_passes(form, tmp_path):
    """``a = 4.0`` crashed problem 41's check (KeyError '4.0', an internal grader error) and a digit string failed
    problem 10: the same option, however written, passes every multiple-choice check."""
    submission = _answered(tmp_path, {(section, key): form.format(n=n) for section, key, n, _ in CHOICES})
    reports = grade_submission(submission, [10, 20, 27, 41, 42], seed=3)
    results = {r.check_id: r for report in reports for r in report.results}
    for *_, check_id in CHOICES:
        assert results[check_id].status is Status.PASSED, (check_id, results[check_id].message)


@pytest.mark.parametrize("written", ["true", "4.5", '"four"', "5", "[4]"])
def test_an_answer_that_is_no_option_is_the_students_error(written, tmp_path):
    submission = _answered(tmp_path, {(section, key): written for section, key, *_ in CHOICES})
    reports = grade_submission(submission, [10, 20, 27, 41, 42], seed=3)
    results = {r.check_id: r for report in reports for r in report.results}
    for *_, check_id in CHOICES:
        result = results[check_id]
        assert result.status is Status.FAILED and result.diagnosis == "format", (check_id, result.message)
        assert "must be the number of one option, 1 to 4" in result.message
    assert not [r.check_id for r in results.values() if r.status is Status.GRADER_ERROR]
