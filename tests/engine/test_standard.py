"""A value held to the student's own results (``engine._standard``): problem 35's subspace checks hold the
student's ``omega_rel`` to their own ``R @ qd``, a value no reference call gives.  Where that consistency fails and
the student's ``omega_rel`` is other than the reference's at the same call, the engine explains it against the
reference's value there (before, it found no source for the expected value and named nothing).

* Graded as ``grade batch`` grades: a new planted mistake, ``omega_rel`` returned as the skew matrix's entries read
  the other way round while ``R`` is taken from the right vector, is named (the whole vector's sign).
* Near miss: the slip in ``R`` instead (taken along the accelerations: zero), where the student's ``omega_rel`` is
  the reference's; the consistency fails all the same, and no cause is told.

A value the check derives from the student's reply itself (problem 17's centre of gravity of their points), which
neither side's calls hold, is explained by the reply: the student's call against the reference's on the same
arguments, each result that differs explained (``engine.judged``): a stand-in reply with one point mirrored through
the centre is named; one with a point moved off its axis, which no slip makes, is not.
"""

import numpy as np
import pytest

import grader.diagnosis as engine
from grader.checking import Tol
from grader.diagnosis import Evidence, explain
from tests.engine.stand_ins import StandInChild, StandInOracle
from tests.kit_support import (  # noqa: F401 (fixtures)
    assert_told,
    failed_alike,
    warm_slot,
)
from tests.submissions import Planted

#: the returned vector read from the transposed entries of the skew matrix, R from the vector computed right
SKEW_READ_TRANSPOSED = Planted(
    name="standard-p35-omega-read-transposed", problem=35, file="problem_35.py",
    old='        "omega_rel": omega_rel,\n',
    new='        "omega_rel": sp.Matrix([W[1, 2], W[2, 0], W[0, 1]]),\n',
    check="p35.rotational_subspaces", diagnosis="sign_flip", message="")
#: R differentiated along the accelerations: zero, while omega_rel is right
R_ALONG_THE_ACCELERATIONS = Planted(
    name="standard-p35-r-along-qdd", problem=35, file="problem_35.py",
    old='        "R": omega_rel.jacobian(qd),\n', new='        "R": omega_rel.jacobian(qdd),\n',
    check="p35.rotational_subspaces", diagnosis="", message="")


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot([35])


@pytest.mark.parametrize("mistake", [SKEW_READ_TRANSPOSED, R_ALONG_THE_ACCELERATIONS], ids=lambda m: m.name)
def test_a_value_held_to_the_students_own_results_is_explained_against_the_reference(mistake, tmp_path,
                                                                                      kit_oracle, deferred_ids,
                                                                                      slot):
    target = failed_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    assert_told(mistake, target)



# ------------------------------------------------------------------------------------------ stand-ins


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
