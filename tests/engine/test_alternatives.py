"""Every family that reproduces the student's answer is heard: the diagnosis engine tells "could be X or Y" where two
tiers (or two slips that are one value by mathematics) reproduce it alike, "looks like X" where one family alone
does, and nothing where more than two do.

* Equivalences declared once with the grammar (``grammar.EQUIVALENCES``): a rotation transposed is the rotation of
  the negated angle, a skew matrix transposed is its negative, a cross product the other way round is its negative;
  whichever tier finds one tells both.
* The tiers after the one that explained the answer are heard (``engine._told``, ``engine._heard``): within a tier
  the simplest hypotheses outrank the others, across tiers none does; a later tier that runs out of its budget
  leaves the earlier finding standing.
* Graded as ``grade batch`` grades: a new planted mistake told with both families, and its near miss told with one.
"""

import numpy as np
import pytest

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import engine as explaining
from grader.diagnosis.evidence import Hypothesis
from grader.diagnosis.grammar import EQUIVALENCES, equivalents, kinds_of, output_slips
from grader.diagnosis.scene import Budget

from tests.kit_support import (  # noqa: F401 (fixtures)
    assert_told_alike,
    warm_slot,
)
from tests.submissions import Planted


def turn(axis, angle):
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    K = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + np.sin(angle) * K + (1.0 - np.cos(angle)) * K @ K


def reproducing(E, got, constants=None):
    """The names of the output slips of ``E`` whose value is ``got``, by cost."""
    found = {}
    for hypothesis, value in output_slips(E, constants or {}, None):
        if value.shape == got.shape and np.allclose(value, got, rtol=0.0, atol=1e-12):
            found.setdefault(hypothesis.cost, set()).add(hypothesis.name)
    return found


# ------------------------------------------------------------------------------------------ equivalences


def test_every_equivalence_joins_names_of_the_vocabulary_of_two_families():
    for e in EQUIVALENCES:
        assert e.seen in DIAGNOSES and e.also in DIAGNOSES, e
        assert DIAGNOSES[e.seen].family != DIAGNOSES[e.also].family, e
        assert e.detail


def test_a_rotation_transposed_is_told_as_a_transpose_or_a_negated_angle():
    """The rotation of the negated angle is the transpose: the output tier's simplest slips hold both names."""
    A = turn([0.3, -1.0, 0.5], 0.8)
    assert kinds_of(A) == {"rotation"}
    backwards = turn([0.3, -1.0, 0.5], -0.8)
    assert reproducing(A, backwards)[1] == {"transpose", "angle_sign"}


def test_a_matrix_transposed_that_is_no_rotation_is_a_transpose_alone():
    """Near miss: a transposed Jacobian, or a reflection (an orthogonal matrix of determinant -1), is no rotation
    the other way."""
    J = np.array([[0.3, 1.0, -0.2], [0.5, 0.1, 0.7], [-0.4, 0.6, 0.9]])
    assert kinds_of(J) == set()
    assert reproducing(J, J.T)[1] == {"transpose"}
    reflection = turn([1.0, 2.0, 0.5], 0.4) @ np.diag([1.0, 1.0, -1.0])
    assert reproducing(reflection, reflection.T)[1] == {"transpose"}


def test_a_skew_matrix_transposed_is_its_negative_but_one_row_negated_is_no_transpose():
    S = np.array([[0.0, -0.3, 0.2], [0.3, 0.0, -0.1], [-0.2, 0.1, 0.0]])
    assert kinds_of(S) == {"skew"}
    assert reproducing(S, S.T)[1] == {"transpose", "sign_flip"}
    row = S.copy()
    row[1] *= -1
    assert reproducing(S, row) == {2: {"sign_flip"}}


def test_a_twin_keeps_the_key_and_the_cost_of_the_slip_seen():
    seen = Hypothesis("transpose", "transpose", 1, "your matrix is the transpose of the expected one")
    [twin] = equivalents(seen, {"rotation"})
    assert (twin.name, twin.cost) == ("angle_sign", 1) and twin.key.startswith("transpose")
    assert equivalents(seen, set()) == []


# ------------------------------------------------------------------------------------------ the tiers heard


def H(name, cost, key=None):
    return Hypothesis(key or f"{name}:{cost}", name, cost, f"{name} at cost {cost}")


def test_within_a_tier_the_simplest_outranks_the_others():
    finding = explaining._told([[H("transpose", 1), H("swapped", 2)]], "here")
    assert finding.names == ("transpose",) and finding.hint.startswith("Looks like ")


def test_across_tiers_a_rival_of_another_family_is_told_beside_the_first():
    """An output's sign (cost 1) and the inputs' exchange (cost 2) reproduce the answer alike: both told."""
    finding = explaining._told([[], [H("sign_flip", 1)], [H("argument_order", 2)], []], "here")
    assert set(finding.names) == {"sign_flip", "argument_order"} and finding.hint.startswith("Could be ")


def test_a_rival_of_the_same_family_adds_its_name_not_a_family():
    """The run tier's gravity sign and the formula tier's sign of a term: one family, both names."""
    finding = explaining._told([[H("gravity_sign", 2)], [], [], [], [], [H("sign_flip", 4)]], "here")
    assert finding.names == ("gravity_sign", "sign_flip")
    assert {DIAGNOSES[n].family for n in finding.names} == {"sign"}


def test_a_familys_own_name_beside_a_name_of_that_family_that_says_more_is_left_out():
    """The terms tier's velocity terms left out and the formula tier's "a term left out": one slip, told once, by
    the name that says which term; the family's own name alone, or beside another family's, is still told."""
    finding = explaining._told([[], [], [], [H("missing_f", 2)], [], [H("missing_term", 4)]], "here")
    assert finding.names == ("missing_f",) and finding.hint.startswith("Looks like ")
    alone = explaining._told([[], [], [], [], [], [H("missing_term", 4)]], "here")
    assert alone.names == ("missing_term",)
    beside = explaining._told([[], [H("sign_flip", 1)], [], [], [], [H("missing_term", 4)]], "here")
    assert set(beside.names) == {"sign_flip", "missing_term"}


def test_more_than_two_families_name_nothing():
    assert explaining._told([[H("transpose", 1)], [H("argument_order", 2)], [H("missing_term", 4)]], "here") is None


def test_a_twin_that_would_take_the_families_past_two_is_left_out_rather_than_nothing_named():
    """A term's sign or a term left out (two families), and the sign's twin, the skew matrix transposed: the twin
    adds a name, not an explanation."""
    sign = H("sign_flip", 4, "mutant:sign")
    [twin] = equivalents(sign, {"skew"})
    finding = explaining._told([[], [], [], [], [], [H("missing_term", 4), sign, twin]], "here")
    assert set(finding.names) == {"missing_term", "sign_flip"}
    alone = explaining._told([[sign, twin]], "here")
    assert set(alone.names) == {"sign_flip", "transpose"} and alone.hint.startswith("Could be ")


def test_the_kit_names_nothing_where_the_graded_submission_would_hear_the_formulas_too():
    """The kit cannot hear the formula tier: what its own tiers found stays in the hint, with no name."""
    from grader.diagnosis.mutants import KIT_NOTE

    found = explaining._told([[H("transpose", 1)]], "here")
    kit = explaining._left_to_live(found)
    assert kit.names == () and found.hint in kit.hint and KIT_NOTE in kit.hint
    assert explaining._left_to_live(None).hint == KIT_NOTE


def test_a_later_tier_out_of_budget_leaves_the_earlier_finding_standing():
    def spent():
        raise Budget("8 student calls")

    assert explaining._heard(spent, True, "ignored") == []
    with pytest.raises(Budget):
        explaining._heard(spent, False, "ignored")


# ------------------------------------------------------------------------------------------ graded

#: problem 12's body with the skew matrix of omega transposed in the rotation's update: the body turns the other way,
#: the final A_IB is the transpose of the reference's (a skew matrix transposed is its negative, a rotation
#: transposed the rotation backwards); the formula tier, on the run's steps, finds the sign of the step's skew
#: matrix too
SKEW_TRANSPOSED = Planted(
    name="alternatives-p12-omega-skew-transposed", problem=12, file="rigid_body.py",
    old="I_Om = skew(self.A_IB @ self.B_omega_B)", new="I_Om = skew(self.A_IB @ self.B_omega_B).T",
    check="p12.sheet_cases", diagnosis="transpose or angle_sign or sign_flip",
    message="a rotation transposed is the rotation the other way", also=("p12.wheel",))

#: problem 8's exponential step with dt left out: dt does not change the student's value (the test of an ignored
#: argument), and the formula tier reproduces it with the step left out of the product: two tiers, two families,
#: both told
STEP_WITHOUT_DT = Planted(
    name="alternatives-p08-exponential-step-without-dt", problem=8, file="problem_08.py",
    old="return expm_skew(dt * skew(I_omega)) @ np.asarray(A_IC, dtype=float)",
    new="return expm_skew(skew(I_omega)) @ np.asarray(A_IC, dtype=float)",
    check="p08.exponential_step", diagnosis="ignored_argument or step_left_out", message="Could be ",
    also=("p08.part_c",))
#: near miss: the step taken twice as long: only the inputs' tier reproduces it (dt at twice its value), and the
#: formula tier, heard, adds nothing: one family, "looks like"
STEP_TWICE = Planted(
    name="alternatives-p08-exponential-step-twice", problem=8, file="problem_08.py",
    old="return expm_skew(dt * skew(I_omega)) @ np.asarray(A_IC, dtype=float)",
    new="return expm_skew(2.0 * dt * skew(I_omega)) @ np.asarray(A_IC, dtype=float)",
    check="p08.exponential_step", diagnosis="scaled_argument", message="Looks like ", also=("p08.part_c",))

MISTAKES = [SKEW_TRANSPOSED, STEP_WITHOUT_DT, STEP_TWICE]


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({m.problem for m in MISTAKES}))


@pytest.mark.parametrize("mistake", MISTAKES, ids=lambda m: m.name)
def test_a_planted_mistake_is_told_with_every_family_that_reproduces_it(mistake, tmp_path, kit_oracle,
                                                                        deferred_ids, slot):
    assert_told_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
