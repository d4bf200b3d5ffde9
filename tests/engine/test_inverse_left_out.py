"""The formula tier's slip of an inverse factor left out of a product (``grader.diagnosis.mutants``:
``inverse_factor``): ``qd + J.T @ lam`` for ``qd + M_inv @ J.T @ lam``, told as an inverse left out and, beside it,
as a matrix factor left out (the slip is as truly of both families); and ``inv(A) @ b`` as ``b`` alike.  Planted
into a made-up problem that the tier names on two inputs, with the near miss of another matrix factor left out
(``J.T @ lam`` for ``K @ J.T @ lam``), told as a matrix factor left out only."""

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem of products with an inverse."""

import numpy as np


def jump(masses, J, qd, lam):
    """A made-up velocity after an impulse ``lam`` through the constraint's Jacobian ``J``."""
    # BEGIN SOLUTION problem 90
    M_inv = np.diag(1.0 / np.asarray(masses, dtype=float))
    return qd + M_inv @ J.T @ lam
    # END SOLUTION


def solved(A, b):
    """A made-up solution of ``A x = b`` by an inverse."""
    # BEGIN SOLUTION problem 90
    return np.linalg.inv(A) @ b
    # END SOLUTION


def stiffened(K, J, lam):
    """A made-up force of an impulse ``lam`` through ``J``, shaped by the stiffness ``K``."""
    # BEGIN SOLUTION problem 90
    return K @ J.T @ lam
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 90, "inverse")


def found(package, name, student, inputs):
    evidences = made_up_evidences(package, name, student, inputs, number=90)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    return mutants.mutant_slips(scene(f"p90.{name}"), evidences)


JACOBIANS = [np.array([[0.4, -1.1, 0.7]]), np.array([[1.3, 0.2, -0.6]])]


def test_an_inverse_mass_left_out_is_an_inverse_left_out_and_a_matrix_factor_left_out(made_up):
    inputs = [((2.0, 3.5, 0.8), JACOBIANS[0], np.array([0.3, -0.2, 1.1]), np.array([0.9])),
              ((1.2, 0.6, 2.4), JACOBIANS[1], np.array([-0.5, 0.8, 0.1]), np.array([-1.4]))]
    hypotheses = found(made_up, "jump", lambda masses, J, qd, lam: qd + J.T @ lam, inputs)
    names = {h.name for h in hypotheses}
    assert names == {"inverse_left_out", "missing_matrix_factor"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`jump` leaves an inverse factor out of a product" in h.detail for h in hypotheses)
    assert {DIAGNOSES[name].family for name in names} == {"inverse", "missing_term"}


def test_an_inverse_called_and_left_out_is_an_inverse_left_out(made_up):
    inputs = [(np.array([[2.0, 0.3], [0.1, 1.5]]), np.array([0.7, -1.2])),
              (np.array([[1.1, -0.4], [0.6, 2.2]]), np.array([-0.3, 0.9]))]
    hypotheses = found(made_up, "solved", lambda A, b: b, inputs)
    assert "inverse_left_out" in {h.name for h in hypotheses}, [(h.name, h.detail) for h in hypotheses]


def test_another_matrix_factor_left_out_is_no_inverse_left_out(made_up):
    K = [np.array([[2.0, 0.1, 0.0], [0.1, 1.5, 0.2], [0.0, 0.2, 3.0]]), np.diag([0.7, 1.9, 1.2])]
    inputs = [(K[0], JACOBIANS[0], np.array([0.9])), (K[1], JACOBIANS[1], np.array([-1.4]))]
    hypotheses = found(made_up, "stiffened", lambda K, J, lam: J.T @ lam, inputs)
    names = {h.name for h in hypotheses}
    assert "missing_matrix_factor" in names and "inverse_left_out" not in names, \
        [(h.name, h.detail) for h in hypotheses]
