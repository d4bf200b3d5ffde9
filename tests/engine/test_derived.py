"""A value the check derives from the student's reply itself (problem 17's centre of gravity of their points, the
first coordinates of a joint's anchor in problem 4's model), which neither side's calls hold, is explained by the
reply: the student's last call of the check against the reference's on the same arguments, each result that
differs explained (``engine.judged``).  Before, the engine found no call behind either value and named nothing.

* A stand-in reply with one point mirrored through the centre is told a sign (one row of the reply).
* Near miss: one with a point moved off its axis, which no slip makes, is told nothing.
"""

import numpy as np

import grader.diagnosis as engine
from grader.checking import Tol
from grader.diagnosis import Evidence, explain
from tests.engine.stand_ins import StandInChild, StandInOracle


def _points(m):
    """A stand-in reply: four points of a body of mass ``m``, about their centre of gravity."""
    return {"points": m * np.array([[1.0, 0.0, -0.5], [-1.0, 0.0, -0.5], [0.0, -0.7, 0.5], [0.0, 0.7, 0.5]])}


def _explain_centre(monkeypatch, student):
    """The centre of gravity of the student's points (``student(m)``: their reply), which a check derives itself
    and holds to zero: neither side's calls hold that value."""
    from grader.diagnosis import Declaration

    monkeypatch.setitem(engine.DECLARATIONS, "stub.points", Declaration(args=("scalar",), names=("m",)))
    got_root = student(2.0)

    class Ctx:
        calls = [("student", "stub.points", (2.0,), got_root)]
        check_id = "p99.points"
        oracle = StandInOracle({"stub.points": _points})
        child = StandInChild({"stub.points": student})
        seed = 1

    centre = np.asarray(got_root["points"]).mean(axis=0)
    evidence = Evidence(centre, np.zeros(3), Tol("exact", 1e-9, 1e-9), "the centre of gravity", centre, None)
    return explain(Ctx(), [evidence])


def test_a_value_derived_from_the_students_reply_is_explained_by_their_reply(monkeypatch):
    """One point mirrored through the centre (a row of the reply with the opposite sign): the centre of gravity
    the check derives fails, and the engine tells the sign from the reply against the reference's."""

    def mirrored(m):
        reply = _points(m)
        reply["points"][1] *= -1.0
        return reply

    finding = _explain_centre(monkeypatch, mirrored)
    assert finding is not None and finding.names == ("sign_flip",), finding
    assert "row 2 has the opposite sign" in finding.hint, finding.hint


def test_a_derived_value_whose_reply_no_slip_makes_is_not_explained(monkeypatch):
    """Near miss: one point moved off its axis by a length of its own; the reply differs from the reference's, but
    no slip reproduces it, and no cause is told."""

    def moved(m):
        reply = _points(m)
        reply["points"][1, 1] += 0.3 * m
        return reply

    finding = _explain_centre(monkeypatch, moved)
    assert finding is None or not finding.names, finding
