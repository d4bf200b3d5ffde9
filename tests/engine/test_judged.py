"""A check that judges the student's value by a property and names only its symptom (a matrix that is not
orthonormal, a reflection, a body in the wrong orientation: ``grader.diagnosis.SYMPTOMS``): the engine compares the
student's probe call behind the value with the reference's on the same arguments (``engine.judged``) and the cause
it finds there is told beside the symptom, whose message stays.

* Graded as ``grade batch`` grades: a new planted mistake in problem 6's R1 (one entry's sign), which the check of
  proper rotations tells as "not orthonormal" only, is named a sign slip live, with the symptom's message; the kit
  tells the symptom alone or the same cause; with the engine off no cause of that family is named.
* Near misses: where the student's call agrees with the reference's (the value judged is not that call's), and where
  no slip reproduces the student's call, the symptom stands alone; a failure that names a cause is not asked again.
"""

import numpy as np
import pytest

import grader.diagnosis as engine
from grader.checking import CheckFailure
from grader.context import explained
from grader.diagnosis import Declaration, judge
from grader.diagnosis.engine import judged_call

from ..kit_support import (  # noqa: F401 (fixtures)
    assert_no_catalogue_names_it,
    assert_told_alike,
    warm_slot,
)
from ..submissions import Planted
from .stand_ins import StandInChild, StandInOracle

#: one entry of the elementary rotation about the 1-axis with the wrong sign: no longer orthonormal
R1_ENTRY_SIGN = Planted(
    name="judged-p06-R1-entry-sign", problem=6, file="rotations.py",
    old="[0.0, s, c]])", new="[0.0, -s, c]])",
    check="p06.elementary_rotation", diagnosis="sign_flip", message="the entry [2,1] has the opposite sign",
    also=("p06.cardan_rotation", "p06.frames", "p06.vectors"))


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot([R1_ENTRY_SIGN.problem])


def test_a_rotation_judged_not_orthonormal_is_told_its_cause(tmp_path, kit_oracle, deferred_ids, slot,
                                                               monkeypatch):
    mistake = R1_ENTRY_SIGN
    submission, live, _ = assert_told_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    target = {r.check_id: r for r in live.results}[mistake.check]
    assert "is not orthonormal" in target.message, target.message  # the symptom's message stays
    assert target.hint.startswith("A rotation matrix keeps lengths and angles"), target.hint
    assert_no_catalogue_names_it(mistake, submission, slot, monkeypatch)


# ------------------------------------------------------------------------------------------ near misses


def _R1(alpha):
    c, s = np.cos(alpha), np.sin(alpha)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def _context(monkeypatch, student, calls_of_student):
    """A grading context whose reference and student answer the stub probe ``stub_judged.R1`` (declared: one
    angle), with the student's calls ``calls_of_student`` (angles) in its log."""
    probe = "stub_judged.R1"
    monkeypatch.setitem(engine.DECLARATIONS, probe, Declaration(args=("angle",), names=("alpha",)))

    class Ctx:
        check_id = "p99.stub"
        oracle = StandInOracle({probe: _R1})
        child = StandInChild({probe: student})
        seed = 7
        calls = [("student", probe, (a,), student(a)) for a in calls_of_student]

    return Ctx()


def _symptom_failure():
    return CheckFailure("R1(0.4) is not orthonormal", "A rotation matrix keeps lengths and angles.",
                        "not_orthonormal")


def test_an_entry_with_the_wrong_sign_is_named_beside_the_symptom(monkeypatch):
    """The mechanism itself on a stand-in: the student's R1 with one entry's sign flipped."""

    def student(alpha):
        A = _R1(alpha)
        A[2, 1] = -A[2, 1]
        return A

    told = explained(_context(monkeypatch, student, [0.4]), _symptom_failure())
    assert told.diagnosis == "sign_flip", (told.diagnosis, told.hint)
    assert told.message == "R1(0.4) is not orthonormal"
    assert told.hint.startswith("A rotation matrix keeps lengths and angles.\nLooks like a sign slip"), told.hint


def test_a_call_that_agrees_with_the_reference_names_nothing(monkeypatch):
    """The student's last call gives the reference's value: the value judged came from elsewhere, nothing to
    compare, and the symptom stands alone."""
    ctx = _context(monkeypatch, _R1, [0.4])
    assert judge(ctx, None) is None
    told = explained(ctx, _symptom_failure())
    assert told.diagnosis == "not_orthonormal" and told.hint == "A rotation matrix keeps lengths and angles."


def test_a_value_no_slip_reproduces_names_nothing(monkeypatch):
    """An entry off by an amount that no slip of the grammar gives, on any angle: the symptom stands alone."""

    def student(alpha):
        A = _R1(alpha)
        A[1, 2] += 0.3 + 0.1 * alpha**2
        return A

    told = explained(_context(monkeypatch, student, [0.4]), _symptom_failure())
    assert told.diagnosis == "not_orthonormal", (told.diagnosis, told.hint)


def test_a_failure_that_names_a_cause_is_not_asked(monkeypatch):
    """Only a symptom is told beside a cause: a failure that names one (a transpose) keeps it, and a run's call (a
    probe that declares a motion) is never the call judged."""

    def student(alpha):
        return _R1(alpha).T

    ctx = _context(monkeypatch, student, [0.4])
    failure = CheckFailure("R1(0.4) is not the expected value", "transposed", "transpose")
    assert explained(ctx, failure).diagnosis == "transpose"
    monkeypatch.setitem(engine.DECLARATIONS, "stub_judged.run", Declaration(motion={"time": 0}))
    assert judged_call([("student", "stub_judged.run", (1.0,), np.zeros(3))], None) is None


def test_a_run_counted_in_steps_is_a_call_the_engine_may_judge(monkeypatch):
    """A run counted in steps (``"time": "step"``: the student's own step called again and again, no solver between
    it and the states) is judged as a call is, its results the states it gives (a screw axis traced along the run,
    judged by a property of the student's own states); a run of a solver is not (the near miss above)."""
    monkeypatch.setitem(engine.DECLARATIONS, "stub_judged.steps", Declaration(motion={"time": "step"}))
    judged = judged_call([("student", "stub_judged.steps", (1.0,), np.zeros(3))], None)
    assert judged is not None and judged.probe == "stub_judged.steps"


def test_the_graders_own_call_of_an_earlier_problems_function_is_never_the_call_judged(monkeypatch):
    """A check that judges its value on what the reference's code makes of the student's earlier functions calls
    them last (``_upstream.call``): the call judged is the student's answer to the check, before them."""
    monkeypatch.setitem(engine.DECLARATIONS, "stub_judged.answer", Declaration())
    log = [("student", "stub_judged.answer", (0.4,), np.ones(3)),
           ("reference", "_upstream.call", ("problem_06", "R1", [0.4]), np.eye(3)),
           ("student", "_upstream.call", ("problem_06", "R1", [0.4]), np.eye(3))]
    judged = judged_call(log, None)
    assert judged is not None and judged.probe == "stub_judged.answer" and judged.args == (0.4,)
    assert judged_call(log[1:], None) is None


# ------------------------------------------------------------------------------------------ a shown input that raised


def _randomized(monkeypatch, student):
    """A context whose randomized comparison of the stub probe failed twice: on the input shown the student's code
    raised (a failure stated in words, no comparison), and on another input a check's own ``compare`` compared a
    value derived from the student's result with the reference's (the call it came from in ``Evidence.call``)."""
    from grader.checking import Tol
    from grader.context import Context
    from grader.diagnosis import Evidence

    ctx = _context(monkeypatch, student, [])
    context = Context(99, ctx.child, {}, None, 7, ctx.oracle)
    context.begin("p99.stub")
    shown = CheckFailure("R1(0.0) raised ValueError, but every angle has a rotation")
    alpha = 0.9
    got_root, expected_root = student(alpha), _R1(alpha)
    got, expected = got_root @ [0.0, 1.0, 0.0], expected_root @ [0.0, 1.0, 0.0]
    compared = CheckFailure("R1(0.9) @ e2 is not the expected value", "", "", None,
                            Evidence(got, expected, Tol("tight", 1e-9, 1e-9), "R1 @ e2", got, expected,
                                     call=("stub_judged.R1", (alpha,), got_root, expected_root)))
    return context, shown, [(0, (0.0,), shown), (3, (alpha,), compared)]


def test_a_shown_input_that_raised_is_told_the_cause_found_on_another(monkeypatch):
    def student(alpha):
        if alpha == 0.0:
            raise ValueError("no angle")
        A = _R1(alpha)
        A[2, 1] = -A[2, 1]
        return A

    context, shown, failures = _randomized(monkeypatch, student)
    told = context._narrowed(shown, failures)
    assert told.message == shown.message  # the failure shown stays
    assert told.diagnosis == "sign_flip", (told.diagnosis, told.hint)
    assert told.hint.startswith("On another input where your function returned a value: looks like a sign slip")


def test_a_shown_input_that_raised_names_nothing_where_no_slip_holds_on_another(monkeypatch):
    def student(alpha):
        A = _R1(alpha)
        A[2, 1] += 0.3 + 0.1 * alpha**2
        return A

    context, shown, failures = _randomized(monkeypatch, student)
    told = context._narrowed(shown, failures)
    assert told.diagnosis == "" and told.hint == "" and told.explained


def test_the_results_of_a_call_agree_on_the_causes_every_one_names():
    """A call's results explained apart (``_agreed``): one "could be X or Y" beside another's "X" is X, told with the
    hint of the result that names it alone; results that share no cause name none."""
    from grader.diagnosis.engine import Finding, _agreed

    either = Finding(("ignored_argument", "state_row"), "Could be an argument ignored or a rate for its quantity.")
    rows = Finding(("state_row",), "Looks like a rate read for its quantity.")
    agreed = _agreed([("qd_plus", either), ("Lam", rows)])
    assert agreed.names == ("state_row",)
    assert agreed.hint == "Your Lam: looks like a rate read for its quantity."
    assert _agreed([("qd_plus", either), ("Lam", Finding(("sign_flip",), "Looks like a sign."))]) is None
    assert _agreed([("Lam", rows)], labelled=False) is rows
