"""Two slips of the formula tier with an inertia: its trace read as a whole sum (``mutants._call_slips``:
``np.sum(S)`` or ``S.sum()`` where ``np.trace(S)`` belongs, the off-diagonal entries added to the diagonal's: a term
added), and its product with a vector taken with its diagonal alone (``mutants._binop_slips``: ``np.diag(I) * w`` for
``I @ w``, the principal moments where the axes are not principal: the off-diagonal terms left out).

Each a mistake planted into a made-up problem (a body's inertia from its second moments, its angular momentum) that
the tier names on two inputs, with a near miss it must not name so: the trace counted twice (a factor, not the other
entries), and the momentum doubled."""

import numpy as np

from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for a trace read as the sum of every entry."""

import numpy as np


def inertia(masses, points):
    """The inertia of point masses about the origin from their second moments."""
    # BEGIN SOLUTION problem 81
    S = sum(m * np.outer(r, r) for m, r in zip(masses, points))
    return np.trace(S) * np.eye(3) - S
    # END SOLUTION


def momentum(I, w):
    """The angular momentum of a body of inertia ``I`` turning at ``w``."""
    # BEGIN SOLUTION problem 81
    return I @ w
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 81, "inertia_slips")

INPUTS = [(np.array([1.5, 0.7, 2.2]), np.array([[0.3, -1.2, 0.8], [1.1, 0.4, -0.6], [-0.5, 0.9, 0.2]])),
          (np.array([0.4, 1.9, 1.1]), np.array([[-0.7, 0.5, 1.4], [0.2, -1.3, 0.6], [1.0, 0.1, -0.8]]))]


def _moments(masses, points):
    return sum(m * np.outer(r, r) for m, r in zip(masses, points))


def found(package, student):
    return mutants.mutant_slips(scene("p81.inertia"), made_up_evidences(package, "inertia", student, INPUTS,
                                                                      number=81))


def test_a_trace_read_as_the_sum_of_every_entry_is_a_term_added(made_up):
    def student(masses, points):
        S = _moments(masses, points)
        return S.sum() * np.eye(3) - S

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"extra_term"}, [(h.name, h.detail) for h in hypotheses]
    assert any("where its trace (the diagonal's sum) belongs" in h.detail for h in hypotheses)


def test_a_trace_counted_twice_is_no_whole_sum(made_up):
    def student(masses, points):
        S = _moments(masses, points)
        return 2.0 * np.trace(S) * np.eye(3) - S

    hypotheses = found(made_up, student)
    assert not any("where its trace" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


INERTIAS = [(np.array([[2.0, 0.3, -0.1], [0.3, 1.5, 0.2], [-0.1, 0.2, 1.1]]), np.array([0.4, -1.2, 0.7])),
            (np.array([[1.2, -0.4, 0.2], [-0.4, 2.5, 0.1], [0.2, 0.1, 0.9]]), np.array([-0.8, 0.3, 1.5]))]


def found_momentum(package, student):
    return mutants.mutant_slips(scene("p81.momentum"), made_up_evidences(package, "momentum", student, INERTIAS,
                                                                       number=81))


def test_a_momentum_of_the_principal_moments_alone_leaves_a_term_out(made_up):
    hypotheses = found_momentum(made_up, lambda I, w: np.diag(I) * w)
    assert {h.name for h in hypotheses} == {"missing_term"}, [(h.name, h.detail) for h in hypotheses]
    assert any("its off-diagonal entries left out" in h.detail for h in hypotheses)


def test_a_momentum_doubled_is_no_diagonal_alone(made_up):
    hypotheses = found_momentum(made_up, lambda I, w: 2.0 * I @ w)
    assert not any("off-diagonal" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
