"""The formula tier's term of a sum halved (``grader.diagnosis.mutants``: ``term_halved``): a factor 1/2 put where
it does not belong, on one term of a sum (a drag force written as ``rho v**2 / 2`` is written where the sheet's
constant holds the half already), is a factor half.

A mistake planted into a made-up problem (a ball's acceleration under gravity and drag) that the tier names on two
inputs, with a near miss it must not name so: the drag taken a third of itself, which no factor 1/2 gives.  A term
that takes the step (``x + dt * E @ v / 2`` for ``x + dt * E @ v``, a matrix product as problem 8's) so halved is a
step of another size, not a factor."""

import numpy as np

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene
from grader.diagnosis import mutants

SOURCE = '''"""A made-up problem for a term of a sum halved."""

import numpy as np


def acceleration(v, k, g):
    """A made-up ball's acceleration at the speed ``v`` under gravity ``g`` and a drag of constant ``k``."""
    # BEGIN SOLUTION problem 75
    return -g - k * np.abs(v) * v
    # END SOLUTION


def euler_step(x, v, dt):
    """One made-up explicit Euler step of the position ``x`` at the speed ``v``."""
    # BEGIN SOLUTION problem 75
    return x + dt * np.eye(2) @ v
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 75, "term_halved")

INPUTS = [(1.3, 0.4, 9.81), (-2.8, 0.7, 3.7)]


def found(package, student):
    return mutants.mutant_slips(scene("p75.acceleration"), made_up_evidences(package, "acceleration", student,
                                                                              INPUTS, number=75))


def test_the_drag_halved_is_a_factor_half(made_up):
    def student(v, k, g):
        return -g - 0.5 * k * abs(v) * v

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"factor_half"}, [(h.name, h.detail) for h in hypotheses]
    assert any("one term of a sum halved" in h.detail for h in hypotheses), [h.detail for h in hypotheses]


def test_the_drag_taken_a_third_is_no_factor_half(made_up):
    def student(v, k, g):
        return -g - k * abs(v) * v / 3.0

    hypotheses = found(made_up, student)
    assert not any(h.name == "factor_half" for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_the_step_term_halved_is_a_step_of_another_size(made_up):
    evidences = made_up_evidences(made_up, "euler_step", lambda x, v, dt: x + dt * v / 2,
                                  [(np.array([0.3, 1.1]), np.array([1.7, -0.2]), 0.01),
                                   (np.array([-1.2, 0.5]), np.array([0.4, 2.3]), 0.05)], number=75)
    hypotheses = mutants.mutant_slips(scene("p75.euler_step"), evidences)
    assert {h.name for h in hypotheses} == {"step_typed"}, [(h.name, h.detail) for h in hypotheses]


def test_the_step_term_doubled_is_the_update_written_twice(made_up):
    """The step's term doubled (``x + 2 * dt * E @ v``) is as truly the update written twice: the term taken twice
    tells it, with the term added once more beside it."""
    evidences = made_up_evidences(made_up, "euler_step", lambda x, v, dt: x + 2 * dt * v,
                                  [(np.array([0.3, 1.1]), np.array([1.7, -0.2]), 0.01),
                                   (np.array([-1.2, 0.5]), np.array([0.4, 2.3]), 0.05)], number=75)
    hypotheses = mutants.mutant_slips(scene("p75.euler_step"), evidences)
    assert {h.name for h in hypotheses} >= {"factor_two", "extra_term"}, [(h.name, h.detail) for h in hypotheses]
    assert "step_typed" not in {h.name for h in hypotheses}, [(h.name, h.detail) for h in hypotheses]
