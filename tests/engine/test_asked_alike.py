"""A compared value that came from another probe of the student's than the expected one (``engine._asked_alike``):
problem 21's and 26's Jacobians are judged against the central differences of the student's own chain, from one
reply that holds the Jacobian beside the chain's values; the expected value is traced to the reference's Jacobian.
The engine asks the student's code that same probe once, and where it gives the compared value again, the second
input and the formula tier ask both sides alike.

* Graded as ``grade batch`` grades: a new planted mistake in problem 26's Jacobian, which no check's catalogue
  names, is named live by the formula tier (before, the derivative check dropped its comparison's evidence and
  the engine was never asked); the kit names the same cause or none.
* Near miss: where the student's call of the expected value's probe gives another value than the one compared, the
  student's side stays the call it was found in.
"""

import types

import numpy as np
import pytest

from grader.checking import Tol
from grader.diagnosis.engine import _asked_alike
from grader.diagnosis.evidence import Evidence, Source

from ..kit_support import (  # noqa: F401 (fixtures)
    assert_no_catalogue_names_it,
    assert_told_alike,
    warm_slot,
)
from ..submissions import Planted

#: one factor of one entry of the Jacobian left out (cos(phi) in d z / d phi)
FACTOR_LEFT_OUT = Planted(
    name="asked-alike-p26-jacobian-factor-left-out", problem=26, file="problem_26.py",
    old="[-radius * sb, l3 * cp * cb],", new="[-radius * sb, l3 * cb],",
    check="p26.jacobian_derivative", diagnosis="missing_factor or missing_term",
    message="one factor of a product in `jacobian`")


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot([FACTOR_LEFT_OUT.problem])


def test_a_jacobian_judged_against_the_students_own_chain_is_explained(tmp_path, kit_oracle, deferred_ids, slot,
                                                                        monkeypatch):
    mistake = FACTOR_LEFT_OUT
    submission, _, _ = assert_told_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    assert_no_catalogue_names_it(mistake, submission, slot, monkeypatch)


J = np.array([[1.0, 0.5], [0.0, 0.3], [-0.2, 0.9]])
ARGS = ("b", [0.1, 0.2, 0.3, 0.4], 0.4)


def _evidence(got):
    return Evidence(np.asarray(got), J, Tol(1e-9, 1e-9), "J",
                    source=Source("problem_21.jacobian", ARGS, (), J),
                    student=Source("problem_21.jacobian_and_steps", (*ARGS, 1e-6), ("J",), {"J": got}))


def _scene(answer):
    asked = []

    def student(probe, args):
        asked.append((probe, tuple(args)))
        return answer

    return types.SimpleNamespace(student=student), asked


def test_the_students_call_of_the_expected_probe_stands_for_the_reply_it_was_found_in():
    got = J * np.array([1.0, 2.0])
    scene, asked = _scene(got.copy())
    found = _asked_alike(scene, _evidence(got))
    assert asked == [("problem_21.jacobian", ARGS)]
    assert found is not None and found.probe == "problem_21.jacobian" and found.args == ARGS and found.path == ()


def test_a_call_that_gives_another_value_is_not_taken_for_the_one_compared():
    got = J * np.array([1.0, 2.0])
    scene, asked = _scene(got + 0.01)
    assert _asked_alike(scene, _evidence(got)) is None
    assert len(asked) == 1
