"""A value held to the student's own results (``engine._standard``): problem 35's subspace checks hold the
student's ``omega_rel`` to their own ``R @ qd``, a value no reference call gives.  Where that consistency fails and
the student's ``omega_rel`` is other than the reference's at the same call, the engine explains it against the
reference's value there (before, it found no source for the expected value and named nothing).

* Graded as ``grade batch`` grades: a new planted mistake, ``omega_rel`` returned as the skew matrix's entries read
  the other way round while ``R`` is taken from the right vector, is named (the whole vector's sign).
* Near miss: the slip in ``R`` instead (taken along the accelerations: zero), where the student's ``omega_rel`` is
  the reference's; the consistency fails all the same, and no cause is told.
"""

import pytest

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
