"""Numbers typed into answers.toml and the order of a value's entries and axes.

* A typed numeric answer compared with its key (problem 10's matrix read off a figure, problem 19's multiple of
  m/120) fails through ``checks._answers.typed_failure``, whatever stage found it: the engine hears the output
  grammar on the key (``grammar.typed_slips``), with one input and nothing behind it to vary.  One input tells a
  slip only where the answer holds many numbers (``grammar.TYPED_NUMBERS`` clearly other than zero): a 3 x 3
  matrix with one entry's sign slipped is named; a scalar at twice its key is not (one number matched by one of
  the grammar's many factors says little), and a matrix that no slip of the key gives keeps the check's verdict.
* The output grammar permutes a matrix's rows or columns cyclically, a tensor's axes (rows and columns alike: an
  inertia with its moments in another order), and a vector's entries in any order the student's value holds where
  each entry moved is told apart from the others (``grammar._reordered``).

The planted mistakes are none of a set's entries; graded as ``grade batch`` grades, live and from the kit's key.
"""

import numpy as np
import pytest

from checks._answers import typed_failure
from grader.checking import Tol
from grader.diagnosis import Evidence, explain
from grader.diagnosis.grammar import output_slips, typed_slips
from tests.engine.stand_ins import StandInChild, StandInOracle
from tests.kit_support import (  # noqa: F401 (fixtures)
    assert_told_alike,
    graded_alike,
    warm_slot,
)
from tests.submissions import Planted

MODEL_C = "c = [[0.09, 0.0, -1.0], [-0.13, 0.99, -0.01], [0.99, 0.13, 0.09]]"

#: the first axis of C read off the figure with its last component's sign slipped: no longer orthonormal, and the
#: key with that one entry's sign
ENTRY_SIGN = Planted(
    name="typed-p10-first-axis-last-component-sign", problem=10, file="answers.toml", old=MODEL_C,
    new="c = [[0.09, 0.0, -1.0], [-0.13, 0.99, -0.01], [-0.99, 0.13, 0.09]]", check="p10.c",
    diagnosis="sign_flip", message="the entry [2,0] has the opposite sign")
#: near miss: C read as turned a quarter turn about the figure's z-axis, which no slip of the key gives: the
#: verdict of the check stands, with no cause
QUARTER_TURN = Planted(
    name="typed-p10-quarter-turn-about-z", problem=10, file="answers.toml", old=MODEL_C,
    new="c = [[0.13, -0.99, 0.01], [0.09, 0.0, -1.0], [0.99, 0.13, 0.09]]", check="p10.c",
    diagnosis="far_from_figure", message="Read each axis of C")
MISTAKES = [ENTRY_SIGN, QUARTER_TURN]


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({m.problem for m in MISTAKES}))


@pytest.mark.parametrize("mistake", MISTAKES, ids=lambda m: m.name)
def test_a_typed_answer_is_explained_by_the_output_grammar(mistake, tmp_path, kit_oracle, deferred_ids, slot):
    assert_told_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)


# ------------------------------------------------------------------------------------------ the rule, directly

READ = Tol("read", 0.05)
#: a rotation of no special angle, the key of a typed answer
KEY = np.array([[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]])


def _typed(got, key=KEY, tol=READ):
    return [h.name for h in typed_slips(Evidence(np.asarray(got, dtype=float), np.asarray(key, dtype=float), tol,
                                                 "typed", typed=True)) if not h.twin]


def test_a_rich_typed_answer_is_told_by_its_slip():
    assert _typed(np.round(KEY.T, 2))[:1] == ["transpose"]
    assert _typed(KEY * np.array([1.0, -1.0, 1.0])) == ["sign_flip"]  # the second axis reversed
    assert _typed(np.roll(KEY, 1, axis=1)) == ["swapped"]  # the axes written in the order z, x, y


def test_a_scalar_or_a_short_typed_answer_tells_nothing():
    assert _typed([544.0], [272.0], Tol("integer", 0.5)) == []
    assert _typed([2.0, 0.0, -0.0], [1.0, 0.0, 0.0]) == []
    assert _typed(KEY @ np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])) == []


class _Ctx:
    check_id = "p99.typed"
    oracle = StandInOracle({})
    child = StandInChild({})
    calls = []
    seed = 1


def test_a_typed_failure_keeps_the_checks_words_beside_the_cause():
    failure = typed_failure(_Ctx(), "your matrix is a reflection", "One axis points the wrong way.", "reflection",
                            KEY * np.array([1.0, 1.0, -1.0]), KEY, READ, "A")
    assert failure.diagnosis == "sign_flip" and failure.explained, failure.diagnosis
    assert failure.hint.startswith("One axis points the wrong way.\n") and "column 3" in failure.hint, failure.hint
    kept = typed_failure(_Ctx(), "far from the figure", "Read each axis.", "far_from_figure", np.eye(3), KEY, READ,
                         "A")
    assert (kept.diagnosis, kept.hint) == ("far_from_figure", "Read each axis."), kept.diagnosis
    doubled = typed_failure(_Ctx(), "I3 / (m/120) is not the expected value", "", "", 544.0, 272.0,
                            Tol("integer answer", 0.5), "I3 / (m/120)")  # problem 19's answer typed at twice its key
    assert doubled.diagnosis == "" and doubled.explained, doubled.diagnosis


# ------------------------------------------------------------------------------------------ orders and axes

TIGHT = Tol("tight", 1e-9, 1e-9)


def _one_input(got, expected):
    """A comparison of a call without arguments (nothing to draw: one input) of a probe that declares nothing."""
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)

    class Ctx(_Ctx):
        calls = [("reference", "stub.v", (), {"v": expected}), ("student", "stub.v", (), {"v": got})]

    return explain(Ctx(), [Evidence(got, expected, TIGHT, "v", got, expected)])


@pytest.fixture
def undeclared(monkeypatch):
    import grader.diagnosis as engine

    monkeypatch.setitem(engine.DECLARATIONS, "stub.v", None)


def test_a_tensor_with_its_axes_exchanged(undeclared):
    """An inertia with its first and third moments in each other's place (rows and columns alike), where an
    exchange of rows alone or of columns alone gives another matrix."""
    inertia = np.array([[0.4, 0.05, 0.0], [0.05, 0.9, -0.1], [0.0, -0.1, 1.3]])
    finding = _one_input(inertia[np.ix_([2, 1, 0], [2, 1, 0])], inertia)
    assert finding is not None and finding.names == ("axis_order",), finding
    assert "axes 1 and 3 are exchanged" in finding.hint, finding.hint
    assert _one_input(inertia[[2, 1, 0]], inertia).names == ("swapped",)  # the rows alone: a swap of rows


def test_a_vector_in_another_order(undeclared):
    """A 6-vector with its halves exchanged is in an order no exchange of two entries gives, told as its halves
    exchanged; one whose entries are of equal size where they moved tells no order (near miss)."""
    spatial = np.array([0.3, -1.2, 0.7, 2.5, 0.1, -0.4])
    finding = _one_input(spatial[[3, 4, 5, 0, 1, 2]], spatial)
    assert finding is not None and finding.names == ("swapped",), finding
    assert "two halves are exchanged" in finding.hint, finding.hint
    alike = np.array([1.0, 1.0, 2.0, -3.0, 0.5, 4.0])
    keys = {h.key for h, _ in output_slips(alike, {}, None, alike[[2, 0, 1, 3, 4, 5]])}
    assert not any(k.startswith("swap:order") for k in keys), keys
