"""The diagnosis engine traces comparisons whose values a check derived from a probe's result.

* A copy of the student's result compared up to the tolerance (the check set entries within the tolerance to the
  expected ones, or reshaped it): the student's call of the reference's probe on the same arguments is its source.
* A symbolic answer evaluated at several points, one value per point: the student's value is a row of their call's
  result, the expected one the reference's call at that point, and the same comparison at another point the check
  asked the reference at is the second input (never drawn, never guessed).
* A printed value of a run's final state: the reference's run on the student's arguments stands for it when it
  holds that value within the tolerance.

Each planted mistake below is one no catalogue lists and the engine named nothing for before; graded as ``grade
batch`` grades (a warm fork), live and from the kit's answer key (the same verdicts, or the kit leaves the formula
to the graded submission).  The near-misses show what stays unexplained.
"""

import numpy as np
import pytest

import grader.diagnosis as engine
from grader.checking import Tol
from grader.diagnosis import Declaration, Evidence, explain
from grader.diagnosis.evidence import Source, counterpart, evaluated, sibling
from tests.engine.stand_ins import StandInChild, StandInOracle

from tests.kit_support import (  # noqa: F401 (fixtures)
    assert_told_alike,
    warm_slot,
)
from tests.submissions import Planted

#: a symbolic answer (problem 16's ellipsoid) with one entry's sign slipped, evaluated at the check's points
SYMBOLIC_ENTRY_SIGN = Planted(
    name="located-p16-symbolic-ellipsoid-entry-sign", problem=16, file="inertia.py",
    old="ha**2 + hc**2, ha**2 + hb**2)", new="ha**2 - hc**2, ha**2 + hb**2)",
    check="p16.symbolic_ellipsoid", diagnosis="sign_flip", message="on the input shown and on a second one")
#: the walker of problem 25 with the leg's length added, where it is subtracted, to the stance foot's offset: the
#: sheet's values are compared on a copy of the student's x with the leg angles set to the printed ones
STANCE_LENGTH_SIGN = Planted(
    name="located-p25-stance-length-sign", problem=25, file="problem_25.py",
    old="S_r_SDs=(-DX, DY - l + r, 0.0),", new="S_r_SDs=(-DX, DY + l + r, 0.0),",
    check="p25.sheet_values", diagnosis="sign_flip", message="on the input shown and on a second one",
    also=("p25.walker_random",))
#: problem 12's body turned backwards each step: the sheet's final A_IB is the transpose of the reference's (the
#: rotation of the negated angle: both told), and the formula tier, on the run's steps, finds the step's sign
ROTATION_BACKWARDS = Planted(
    name="located-p12-rotation-backwards", problem=12, file="rigid_body.py",
    old="self.A_IB = expm_skew(dt * I_Om) @ self.A_IB", new="self.A_IB = expm_skew(-dt * I_Om) @ self.A_IB",
    check="p12.sheet_cases", diagnosis="transpose or angle_sign or sign_flip", message="transpose",
    also=("p12.wheel",))

MISTAKES = [SYMBOLIC_ENTRY_SIGN, STANCE_LENGTH_SIGN, ROTATION_BACKWARDS]


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({m.problem for m in MISTAKES}))


@pytest.mark.parametrize("mistake", MISTAKES, ids=lambda m: m.name)
def test_a_derived_comparison_is_told_its_cause(mistake, tmp_path, kit_oracle, deferred_ids, slot):
    assert_told_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)


# ------------------------------------------------------------------------------------------ stand-ins

TIGHT = Tol("tight", 1e-9, 1e-9)
POINTS = np.array([[1.5, 0.5], [2.0, -1.25], [0.75, 3.0]])


def _value(m, a):
    return np.array([m * a, m - 2 * a])


def _explain_points(monkeypatch, rows, asked=(0, 1, 2)):
    """A check that evaluates the student's symbolic answer at ``POINTS`` (``stub.symbolic``: one row per point)
    and compares each row with the reference's ``stub.value`` at that point (asked at the points ``asked``); the
    first point fails.  ``rows(point index, expected)``: the student's row."""
    monkeypatch.setitem(engine.DECLARATIONS, "stub.value",
                        Declaration(args=("scalar", "scalar"), names=("m", "a")))
    monkeypatch.setitem(engine.DECLARATIONS, "stub.symbolic", None)
    batch = np.array([rows(i, _value(*p)) for i, p in enumerate(POINTS)])
    calls = [("reference", "stub.value", tuple(POINTS[i]), _value(*POINTS[i])) for i in asked]
    calls.append(("student", "stub.symbolic", (POINTS,), batch))

    class Ctx:
        check_id = "p99.symbolic"
        oracle = StandInOracle({"stub.value": _value})
        child = StandInChild({})
        seed = 1

    Ctx.calls = calls
    expected = calls[0][3]
    evidence = Evidence(batch[0].copy(), expected, TIGHT, "value", batch[0].copy(), expected)
    return explain(Ctx(), [evidence])


def entry_sign(i, value):
    """The value at the ``i``-th point with its second entry's sign slipped."""
    return value * np.array([1.0, -1.0])


def assert_told_on_a_second_point(explain_points, monkeypatch):
    """A slip at every point (``explain_points(monkeypatch, rows)``: the engine's finding where the student's value
    at point ``i`` is ``rows(i, expected)``) is told, on the point shown and a second one."""
    finding = explain_points(monkeypatch, entry_sign)
    assert finding is not None and finding.names == ("sign_flip",), finding
    assert "on the input shown and on a second one" in finding.hint, finding.hint


def assert_ruled_out_by_a_second_point(explain_points, monkeypatch):
    """A slip at the first point only (the others' values are twice the expected ones) is no cause."""
    finding = explain_points(monkeypatch, lambda i, value: entry_sign(i, value) if i == 0 else 2 * value)
    assert finding is None or not finding.names, finding


def test_a_value_at_one_of_several_points_is_compared_at_a_second_point(monkeypatch):
    assert_told_on_a_second_point(_explain_points, monkeypatch)


def test_a_slip_that_the_second_point_does_not_show_is_no_cause(monkeypatch):
    """The first point's value is the expected one with an entry's sign slipped, the second point's is not: one
    point alone would tell the slip, the second rules it out."""
    assert_ruled_out_by_a_second_point(_explain_points, monkeypatch)


def test_a_point_the_check_never_asked_the_reference_at_is_no_second_input(monkeypatch):
    monkeypatch.setitem(engine.DECLARATIONS, "stub.value", Declaration(args=("scalar", "scalar"), names=("m", "a")))
    batch = np.array([entry_sign(i, _value(*p)) for i, p in enumerate(POINTS)])
    log = [("reference", "stub.value", tuple(POINTS[0]), _value(*POINTS[0])),
           ("student", "stub.symbolic", (POINTS,), batch)]
    student = evaluated(log, batch[0].copy(), TIGHT)
    assert student == Source("stub.symbolic", (POINTS,), (0,), batch)
    evidence = Evidence(batch[0].copy(), _value(*POINTS[0]), TIGHT, "value",
                        source=Source("stub.value", tuple(POINTS[0]), (), _value(*POINTS[0])), student=student)
    assert sibling(log, evidence) is None
    log.append(("reference", "stub.value", tuple(POINTS[2]), _value(*POINTS[2])))
    other = sibling(log, evidence)
    assert other is not None and other.student.path == (2,)
    assert np.array_equal(other.got, batch[2]) and np.array_equal(other.expected, _value(*POINTS[2]))


def test_a_value_two_results_hold_is_traced_to_neither():
    same = np.array([1.0, 2.0])
    log = [("student", "stub.a", (1.0,), {"x": same.copy(), "y": same.copy()})]
    assert evaluated(log, same, TIGHT) is None
    log = [("student", "stub.a", (1.0,), {"x": same.copy(), "y": np.array([3.0, 4.0])})]
    assert evaluated(log, same, TIGHT) == Source("stub.a", (1.0,), ("x",), log[0][3])


def test_a_copy_of_the_students_result_is_theirs_only_within_the_tolerance():
    """The check compared a copy of the student's x with its angle set to the printed one: their call on the
    reference's arguments holds it within the tolerance; a value beyond the tolerance is not theirs, nor a value
    of a call on other arguments."""
    sheet = Tol("sheet", 6e-4)
    theirs = {"x": [0.4551, 0.7348, -0.5235987755982988]}
    log = [("student", "stub.walker", (-0.5236, 1.0472), theirs)]
    source = Source("stub.walker", (-0.5236, 1.0472), ("x",), None)
    copy = np.array([0.4551, 0.7348, -0.5236])
    assert counterpart(log, copy, source, sheet) == Source("stub.walker", (-0.5236, 1.0472), ("x",), theirs)
    assert counterpart(log, np.array([0.4551, 0.7348, -0.52]), source, sheet) is None
    other = Source("stub.walker", (0.1, 1.0472), ("x",), None)
    assert counterpart(log, copy, other, sheet) is None
    assert counterpart(log, copy.reshape(3, 1), source, sheet) is not None


def test_a_value_of_zero_that_stays_zero_is_no_ignored_argument(monkeypatch):
    """The student's ``a * b`` for the reference's ``a + b`` is zero at a = 0 and stays zero when b changes: that
    tells nothing of b (a product vanishes there); where their value is not zero, an argument it does not follow
    is told ignored."""
    monkeypatch.setitem(engine.DECLARATIONS, "stub.sum",
                        Declaration(args=("scalar", "scalar"), names=("a", "b"), draw=False))

    def explain_at(args, student):
        expected, got = np.array([sum(args)]), np.array([student(*args)])

        class Ctx:
            check_id = "p99.sum"
            oracle = StandInOracle({"stub.sum": lambda a, b: np.array([a + b])})
            child = StandInChild({"stub.sum": lambda a, b: np.array([student(a, b)])})
            seed = 1
            calls = [("reference", "stub.sum", args, expected), ("student", "stub.sum", args, got)]

        return explain(Ctx(), [Evidence(got, expected, TIGHT, "a + b", got, expected)])

    finding = explain_at((0.0, 1.0), lambda a, b: a * b)
    assert finding is None or "ignored_argument" not in finding.names, finding
    finding = explain_at((0.7, 2.9), lambda a, b: 2 * a)
    assert finding is not None and finding.names == ("ignored_argument",), finding


def test_a_value_is_located_only_where_one_call_and_path_hold_it():
    """``locate`` traces a value to a call only where one call and one path of it hold the value: the same call
    logged twice (its arguments equal, or the very objects) is one; two paths, two probes or other arguments are
    several, and name no call."""
    from grader.diagnosis.evidence import locate

    A = np.array([[0.0, -1.0], [1.0, 0.0]])
    value = np.array([0.25, -0.5])
    twice = [("reference", "p98.f", (A,), {"r": value}), ("reference", "p98.f", (A.copy(),), {"r": value.copy()})]
    found = locate(twice, value.copy(), "reference")
    assert found is not None and found.probe == "p98.f" and found.path == ("r",)
    same_objects = [("reference", "p98.f", (A,), {"r": value}), ("reference", "p98.f", (A,), {"r": value.copy()})]
    assert locate(same_objects, value.copy(), "reference") is not None
    for log in ([("reference", "p98.f", (A,), {"r": value, "s": value.copy()})],
                [("reference", "p98.f", (A,), {"r": value}), ("reference", "p98.g", (A,), {"r": value.copy()})],
                [("reference", "p98.f", (A,), {"r": value}), ("reference", "p98.f", (2 * A,), {"r": value.copy()})]):
        assert locate(log, value.copy(), "reference") is None
