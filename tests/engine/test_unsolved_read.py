"""The formula tier's read of a solve's right-hand side where the solved value belongs
(``grader.diagnosis.mutants._bound_solves``): ``J @ J.T`` for ``J @ Minv_JT`` of ``Minv_JT = solve(M, J.T)``, the
inverse left out of one product while the name keeps its value elsewhere, told as an inverse factor left out and,
beside it, a matrix factor left out.

A mistake planted into a made-up problem (a plastic impact) that the tier names on two inputs, with a near miss it
must not name so: the impulse's sign turned."""

import numpy as np

from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for a solve's right-hand side read where the solved value belongs."""

import numpy as np


def impact(M, J, v):
    """A made-up velocity after a plastic impact on the constraints ``J`` of a body of mass matrix ``M``."""
    # BEGIN SOLUTION problem 77
    Minv_JT = np.linalg.solve(M, J.T)
    Lam = -np.linalg.solve(J @ Minv_JT, J @ v)
    return v + Minv_JT @ Lam
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 77, "unsolved_read")

INPUTS = [(np.array([[2.0, 0.3, 0.0], [0.3, 1.5, 0.2], [0.0, 0.2, 0.8]]), np.array([[1.0, -0.4, 0.6]]),
           np.array([0.7, -1.1, 0.4])),
          (np.array([[3.0, -0.2, 0.1], [-0.2, 0.9, 0.0], [0.1, 0.0, 1.7]]), np.array([[0.2, 1.3, -0.5]]),
           np.array([-0.6, 0.9, 1.2]))]


def found(package, student):
    return mutants.mutant_slips(scene("p77.impact"), made_up_evidences(package, "impact", student, INPUTS,
                                                                       number=77))


def test_the_right_hand_side_read_where_the_solved_value_belongs_is_an_inverse_left_out(made_up):
    def student(M, J, v):
        Minv_JT = np.linalg.solve(M, J.T)
        Lam = -np.linalg.solve(J @ J.T, J @ v)
        return v + Minv_JT @ Lam

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"inverse_left_out", "missing_matrix_factor"}, \
        [(h.name, h.detail) for h in hypotheses]
    assert any("right-hand side of a solve" in h.detail for h in hypotheses)


def test_the_impulse_with_its_sign_turned_is_no_inverse_left_out(made_up):
    def student(M, J, v):
        Minv_JT = np.linalg.solve(M, J.T)
        Lam = np.linalg.solve(J @ Minv_JT, J @ v)
        return v + Minv_JT @ Lam

    hypotheses = found(made_up, student)
    assert not any(h.name == "inverse_left_out" for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
