"""A symbolic answer compared by evaluation is compared at several points: the engine judges its hypotheses on two.

A check that evaluates the student's symbolic answer at points it draws (``ctx.student(probe, points)``) and asks
the reference's values at the very same points (``ctx.reference(values, points)``, a probe of another name) compares
one point after the other.  The failing point is the input shown; another point of the same two calls where the
student's value fails too is the second input (read from the two results, never drawn, no call made), so that the
grammar's slips and the formula tier's mutants are judged on both, as on a randomized comparison's two inputs.
Where the student's answer holds the compared value in two of its entries (their rate and acceleration came out
alike), the entry of the expected value's name is theirs.

The planted mistake is one no catalogue lists and the engine named nothing for before; graded as ``grade batch``
grades, live and from the kit's answer key (the same verdicts, or the kit leaves the formula to the graded
submission).  The near misses show what stays unexplained.
"""

import numpy as np
import pytest

import grader.diagnosis as engine
from grader.checking import Tol
from grader.diagnosis import Evidence, explain
from grader.diagnosis.evidence import Source, evaluated, sibling
from tests.engine.stand_ins import StandInChild, StandInOracle
from tests.engine.test_located import (assert_ruled_out_by_a_second_point, assert_told_on_a_second_point,
                                       entry_sign)

from tests.kit_support import (  # noqa: F401 (fixtures)
    assert_told_alike,
    warm_slot,
)
from tests.submissions import Planted

#: problem 35's time derivative along q(t) with the rates and the accelerations exchanged (d/dq @ qdd + d/dqd @ qd):
#: the acceleration comes out as the velocity, which only a slip of the formula reproduces at two points; the
#: formula tier mutates the code of the student's own call (``mutants.own_calls``), where a rate is read for the
#: acceleration (a state row), not the numeric stand-in's, whose arguments exchanged had been told beside it
RATES_EXCHANGED = Planted(
    name="points-p35-derivative-rates-exchanged", problem=35, file="problem_35.py",
    old="return expr.jacobian(q) @ qd + expr.jacobian(qd) @ qdd",
    new="return expr.jacobian(q) @ qdd + expr.jacobian(qd) @ qd",
    check="p35.translational_values", diagnosis="state_row",
    message="on the input shown and on a second one",
    also=("p35.rotational_values", "p35.virtual_3dof_values", "p35.rolling_contact_values", "p35.poses_values"))

MISTAKES = [RATES_EXCHANGED]


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({m.problem for m in MISTAKES}))


@pytest.mark.parametrize("mistake", MISTAKES, ids=lambda m: m.name)
def test_a_symbolic_answer_is_judged_at_a_second_point(mistake, tmp_path, kit_oracle, deferred_ids, slot):
    assert_told_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)


# ------------------------------------------------------------------------------------------ stand-ins

TIGHT = Tol("tight", 1e-9, 1e-9)
#: the check's points: dicts of the symbols' values, as a symbolic check draws them
POINTS = [{"m": 1.5, "a": 0.5}, {"m": 2.0, "a": -1.25}, {"m": 0.75, "a": 3.0}]


def _value(point):
    return np.array([point["m"] * point["a"], point["m"] - 2 * point["a"]])


def _values(points):
    """The reference's values at every point (a probe of its own, asked at the check's points)."""
    return {"x": [_value(p) for p in points]}


def _explain_points(monkeypatch, rows, points=POINTS):
    """A check that evaluates the student's symbolic answer at ``points`` (``stub.answer``: ``{"values": [{"x":
    value}, ...]}``) and compares each point's value with the reference's ``stub.values`` at the same points; the
    first point fails.  ``rows(point index, expected)``: the student's value there."""
    monkeypatch.setitem(engine.DECLARATIONS, "stub.values", None)
    monkeypatch.setitem(engine.DECLARATIONS, "stub.answer", None)
    expected_root = _values(POINTS)
    answer = {"values": [{"x": rows(i, _value(p))} for i, p in enumerate(POINTS)]}
    calls = [("reference", "stub.values", (POINTS,), expected_root), ("student", "stub.answer", (points,), answer)]

    class Ctx:
        check_id = "p99.symbolic"
        oracle = StandInOracle({"stub.values": _values})
        child = StandInChild({})
        seed = 1

    Ctx.calls = calls
    got, expected = answer["values"][0]["x"], expected_root["x"][0]
    return explain(Ctx(), [Evidence(np.array(got), expected, TIGHT, "x", np.array(got), expected)])


def test_a_slip_at_every_point_is_told_on_two_of_them(monkeypatch):
    assert_told_on_a_second_point(_explain_points, monkeypatch)


def test_a_slip_that_the_second_point_does_not_show_is_no_cause(monkeypatch):
    """The first point's value is the expected one with an entry's sign slipped, the others' are not: the first
    point alone would tell the slip, the second rules it out."""
    assert_ruled_out_by_a_second_point(_explain_points, monkeypatch)


def test_a_point_where_the_answer_holds_is_passed_over():
    answer = {"values": [{"x": entry_sign(0, _value(POINTS[0]))}, {"x": _value(POINTS[1])},
                         {"x": entry_sign(2, _value(POINTS[2]))}]}
    expected_root = _values(POINTS)
    evidence = Evidence(answer["values"][0]["x"], expected_root["x"][0], TIGHT, "x",
                        source=Source("stub.values", (POINTS,), ("x", 0), expected_root),
                        student=Source("stub.answer", (POINTS,), ("values", 0, "x"), answer))
    other = sibling([], evidence)
    assert other is not None and other.source.path == ("x", 2) and other.student.path == ("values", 2, "x")
    assert np.array_equal(other.got, answer["values"][2]["x"])
    assert np.array_equal(other.expected, expected_root["x"][2])


def test_calls_at_other_points_give_no_second_point():
    """The student's answer evaluated at points other than the reference's (or one probe on both sides, which the
    engine draws a second input for itself) is no second point."""
    elsewhere = [dict(p, a=p["a"] + 1.0) for p in POINTS]
    answer = {"values": [{"x": entry_sign(i, _value(p))} for i, p in enumerate(POINTS)]}
    expected_root = _values(POINTS)

    def second(student_points, student_probe="stub.answer"):
        return sibling([], Evidence(answer["values"][0]["x"], expected_root["x"][0], TIGHT, "x",
                                    source=Source("stub.values", (POINTS,), ("x", 0), expected_root),
                                    student=Source(student_probe, (student_points,), ("values", 0, "x"), answer)))

    assert second(POINTS) is not None
    assert second(elsewhere) is None
    assert second(POINTS, student_probe="stub.values") is None


def test_a_value_two_entries_hold_is_the_entry_of_the_expected_ones_name():
    same = np.array([0.5, -1.0])
    log = [("student", "stub.answer", (POINTS,), {"values": [{"rate": same.copy(), "acceleration": same.copy()}]})]
    assert evaluated(log, same, TIGHT) is None
    found = evaluated(log, same, TIGHT, (0, "acceleration"))
    assert found is not None and found.path == ("values", 0, "acceleration")
    assert evaluated(log, same, TIGHT, (0, "position")) is None
