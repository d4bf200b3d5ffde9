"""A batch's rows measured first (``probes.probe``'s ``rows``, ``grader.diagnosis.evidence.rows_of``): a probe whose
argument is a batch whose rows give its result's rows one each (problem 32's torques at the 209 points of the desired
trajectory) has each mutant of the formula tier measured on the few rows that differ first, and on the whole batch
only where those reproduce the student's value.  Measured on the whole batch, the arm's 590 slips of its code take
longer than the tier's budget and nothing is named; measured so, the tier reaches the slips of the module constants
that the check's own call reads, among them the library's gravity typed one decimal short (9.8 for 9.81, a slip of
precision), and a vector constant written as its direction alone.  The near miss, a gravity of 9.7, is no number typed
short: no slip of precision is named.

The screen itself: a comparison of the whole batch is cut to its first, middle and last rows that differ, and the
batch argument to the same rows; a comparison of one row, to that row; a probe that declares no rows, or a batch of
no more rows than the screen holds, is measured whole.
"""

import numpy as np

from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, ROWS_SCREENED, rows_of, Source
from grader.private import drop_private

from .test_mutants import evidence, planted_package, scene, TIGHT


def trajectory_slips(tmp_path, file: str, old: str, new: str):
    """The formula tier on problem 32's torques along the whole desired trajectory, as its check compares them, and
    along the same trajectory shifted, with ``old`` written as ``new`` in ``file``."""
    from reference import problem_32

    q = np.asarray(problem_32.desired_trajectory()["q"], dtype=float)
    student = planted_package(tmp_path, file, old, new)
    try:
        evidences = [evidence("problem_32.torques", (rows,), (), student) for rows in (q, q + 0.3)]
        assert all(e.got.shape == (q.shape[0], 3) and not np.allclose(e.got, e.expected) for e in evidences)
        return mutants.mutant_slips(scene("p32.gravity_trajectory"), evidences)
    finally:
        drop_private(student)


def test_the_library_gravity_typed_short_is_named_along_the_whole_trajectory(tmp_path):
    found = trajectory_slips(tmp_path, "conventions.py", "GRAVITY = 9.81", "GRAVITY = 9.8")
    assert {h.name for h in found} == {"rounded"}, [(h.name, h.detail) for h in found]
    assert any("`GRAVITY` is typed short" in h.detail for h in found), [h.detail for h in found]


def test_a_gravity_vector_written_as_its_direction_is_named_along_the_whole_trajectory(tmp_path):
    found = trajectory_slips(tmp_path, "problem_32.py", "I_GRAV = np.array([0.0, -GRAVITY, 0.0])",
                             "I_GRAV = np.array([0.0, -GRAVITY, 0.0]) / GRAVITY")
    assert "wrong_factor" in {h.name for h in found}, [(h.name, h.detail) for h in found]


def test_a_gravity_no_typing_gives_names_no_slip_of_precision(tmp_path):
    found = trajectory_slips(tmp_path, "conventions.py", "GRAVITY = 9.81", "GRAVITY = 9.7")
    assert "rounded" not in {h.name for h in found}, [(h.name, h.detail) for h in found]


def batch_evidence(rows: int, differ: list, path: tuple = (), probe: str = "problem_32.torques") -> Evidence:
    expected = np.arange(rows * 3, dtype=float).reshape(rows, 3)
    got = expected.copy()
    got[differ] += 1.0
    batch = np.arange(rows * 3, dtype=float).reshape(rows, 3) / 10
    if path:
        got, expected = got[path[0]], expected[path[0]]
    return Evidence(got, expected, TIGHT, "value", source=Source(probe, (batch,), path))


def test_a_whole_batch_is_screened_on_its_first_middle_and_last_rows_that_differ():
    screen, (probe, args) = rows_of(batch_evidence(20, [3, 5, 8, 12, 17]))
    assert probe == "problem_32.torques"
    np.testing.assert_array_equal(args[0], np.arange(60, dtype=float).reshape(20, 3)[[3, 8, 17]] / 10)
    np.testing.assert_array_equal(screen.expected, np.arange(60, dtype=float).reshape(20, 3)[[3, 8, 17]])
    np.testing.assert_array_equal(screen.got, screen.expected + 1.0)
    assert screen.source.path == () and screen.source.args is args


def test_one_row_compared_is_screened_on_that_row():
    screen, (_, args) = rows_of(batch_evidence(20, [7], path=(7,)))
    np.testing.assert_array_equal(args[0], np.arange(60, dtype=float).reshape(20, 3)[[7]] / 10)
    assert screen.source.path == (0,)
    np.testing.assert_array_equal(screen.got, np.arange(21, 24, dtype=float) + 1.0)


def test_no_screen_without_a_declaration_or_for_a_short_batch():
    assert rows_of(batch_evidence(20, [3], probe="problem_37.torques")) is None
    assert rows_of(batch_evidence(ROWS_SCREENED, [1])) is None
