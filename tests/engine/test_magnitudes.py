"""The formula tier's slips of magnitudes (``grader.diagnosis.mutants``): an absolute value left out (``v * v`` for
``abs(v) * v``, a drag that no longer opposes the motion once it reverses), and a square root taken of a product's
last factor only (``12 / m * np.sqrt(S)`` for ``np.sqrt(12 / m * S)``), beside the first factor only that the tier
tried before; and a sum squared where the sum of the squares belongs (``(w + h)**2`` for ``w**2 + h**2``), a cross
term added.

Each is a mistake planted into a made-up problem that the tier names on two inputs, with a near miss it must not
name: an absolute value left out where every value it is taken of is positive on the inputs (the slip changes
nothing there), a root of the last factor whose first factor is then squared (no slip of one step), and a cross term
of another size than the square's."""

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for the slips of magnitudes."""

import numpy as np


def drag(velocities, c):
    """A made-up quadratic drag on each of ``velocities``: opposing each, of size ``c v^2``."""
    # BEGIN SOLUTION problem 88
    return -c * np.abs(velocities) * velocities
    # END SOLUTION


def section(w, h):
    """Made-up moments of a cross-section of width ``w`` and height ``h``."""
    # BEGIN SOLUTION problem 88
    return np.array([w**2 + h**2, 3.0 * w * h])
    # END SOLUTION


def edges(m, S):
    """Made-up edges of a box from the mass ``m`` and the second moments ``S``."""
    # BEGIN SOLUTION problem 88
    return np.sqrt(12.0 / m * S)
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 88, "magnitudes")


def found(package, name, student, inputs):
    evidences = made_up_evidences(package, name, student, inputs, number=88)
    return mutants.mutant_slips(scene(f"p88.{name}"), evidences)


def test_an_absolute_value_left_out_is_a_sign(made_up):
    inputs = [(np.array([1.5, -0.7, 2.2, -3.1]), 0.3), (np.array([-2.4, 0.9, -0.2, 1.1]), 0.45)]
    hypotheses = found(made_up, "drag", lambda v, c: -c * v * v, inputs)
    assert {h.name for h in hypotheses} == {"sign_flip"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`drag` leaves out an absolute value" in h.detail for h in hypotheses)
    assert DIAGNOSES["sign_flip"].family == "sign"


def test_an_absolute_value_left_out_where_every_value_is_positive_is_not_named(made_up):
    """The near miss: on velocities all positive the slip gives the reference's value; the student's drag, a third
    weaker, is no absolute value left out."""
    inputs = [(np.array([1.5, 0.7, 2.2]), 0.3), (np.array([2.4, 0.9, 0.2]), 0.45)]
    hypotheses = found(made_up, "drag", lambda v, c: -c * np.abs(v) * v / 1.5, inputs)
    assert not any("absolute value" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_a_root_of_the_last_factor_only_is_a_factor(made_up):
    inputs = [(2.5, np.array([0.4, 1.1, 0.9])), (0.8, np.array([1.3, 0.2, 0.6]))]
    hypotheses = found(made_up, "edges", lambda m, S: 12.0 / m * np.sqrt(S), inputs)
    assert {h.name for h in hypotheses} == {"wrong_factor"}, [(h.name, h.detail) for h in hypotheses]
    assert any("out of a square root" in h.detail for h in hypotheses)


def test_a_root_of_the_last_factor_with_the_first_squared_is_not_named(made_up):
    """The near miss: ``(12 / m) ** 2 * np.sqrt(S)`` is two slips at once, which the tier does not try."""
    inputs = [(2.5, np.array([0.4, 1.1, 0.9])), (0.8, np.array([1.3, 0.2, 0.6]))]
    hypotheses = found(made_up, "edges", lambda m, S: (12.0 / m) ** 2 * np.sqrt(S), inputs)
    assert not any("out of a square root" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


SECTIONS = [(0.3, 1.2), (2.0, 0.7)]


def test_a_sum_squared_where_the_sum_of_the_squares_belongs_is_a_term_added(made_up):
    """``(w + h)**2`` for ``w**2 + h**2``: the square of the sum adds the cross term ``2 w h``."""
    hypotheses = found(made_up, "section", lambda w, h: np.array([(w + h)**2, 3.0 * w * h]), SECTIONS)
    assert {h.name for h in hypotheses} == {"extra_term"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`section` squares a sum where the sum of the squares belongs" in h.detail for h in hypotheses)


def test_a_cross_term_of_another_size_is_no_sum_squared(made_up):
    """The near miss: ``w**2 + h**2 + w h``, a cross term half the square's, which no sum squared gives."""
    hypotheses = found(made_up, "section", lambda w, h: np.array([w**2 + h**2 + w * h, 3.0 * w * h]), SECTIONS)
    assert not any("squares a sum" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
