"""The formula tier's slip of a weighted sum taken unweighted (``grader.diagnosis.mutants``: ``unweighted``):
``points.sum(axis=0) / masses.sum()`` for ``masses @ points / masses.sum()``, the weights ignored in the sum though
they are read elsewhere, told as the weights left out (an argument ignored).  Planted into a made-up problem that the
tier names on two inputs, with the near miss of the plain mean of the points, which no sum of the rows gives."""

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem of a weighted sum."""

import numpy as np


def balance(masses, points):
    """A made-up balance point of point masses: ``sum m_i r_i / sum m_i``."""
    # BEGIN SOLUTION problem 85
    masses, points = np.asarray(masses, dtype=float), np.asarray(points, dtype=float)
    return masses @ points / masses.sum()
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 85, "unweighted")

INPUTS = [(np.array([1.0, 2.5, 0.5]), np.array([[0.3, -1.2, 0.7], [1.1, 0.4, -0.9], [-0.6, 0.8, 0.2]])),
          (np.array([0.7, 1.3, 3.0, 0.9]), np.array([[1.0, 0.2, 0.1], [-0.4, 0.9, 0.6], [0.3, -0.7, 1.2],
                                                    [0.8, 0.5, -0.3]]))]


def found(package, student):
    evidences = made_up_evidences(package, "balance", student, INPUTS, number=85)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    return mutants.mutant_slips(scene("p85.balance"), evidences)


def test_a_weighted_sum_taken_unweighted_is_the_weights_left_out(made_up):
    hypotheses = found(made_up, lambda masses, points: np.sum(points, axis=0) / np.sum(masses))
    assert {h.name for h in hypotheses} == {"weights_left_out"}, [(h.name, h.detail) for h in hypotheses]
    assert DIAGNOSES["weights_left_out"].family == "ignored_argument"
    assert any("`balance` sums the rows of a product unweighted" in h.detail for h in hypotheses)


def test_the_plain_mean_is_no_sum_of_the_rows_over_the_weights(made_up):
    hypotheses = found(made_up, lambda masses, points: np.mean(points, axis=0))
    assert not any(h.name == "weights_left_out" for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
