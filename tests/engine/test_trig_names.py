"""The formula tier's reads of a sine's values for a cosine's (``grader.diagnosis.mutants._related``): ``sin_coeffs``
read where ``cos_coeffs`` belongs (names alike but for ``sin`` and ``cos``), sine and cosine exchanged as a name
read for another is.

A mistake planted into a made-up problem (a wave of harmonics) that the tier names on two inputs, with a near miss
it must not name so: the cosine's coefficients doubled."""

import numpy as np

from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for a sine's coefficients read where the cosine's belong."""

import numpy as np


def wave(t, a, b):
    """A made-up wave of three harmonics at the times ``t``."""
    # BEGIN SOLUTION problem 79
    sin_coeffs = np.array([a, 0.5 * b, -0.2 * a])
    cos_coeffs = np.array([b, 0.7 * a, 0.3])
    k = np.arange(3)
    return np.sin(np.outer(t, k)) @ sin_coeffs + np.cos(np.outer(t, k)) @ cos_coeffs
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 79, "trig_names")

INPUTS = [(np.array([0.1, 0.6, 1.3]), 0.8, -0.4), (np.array([0.2, 0.9, 2.1]), -1.2, 0.5)]


def found(package, student):
    return mutants.mutant_slips(scene("p79.wave"), made_up_evidences(package, "wave", student, INPUTS, number=79))


def _coefficients(a, b):
    return np.array([a, 0.5 * b, -0.2 * a]), np.array([b, 0.7 * a, 0.3])


def test_a_sines_coefficients_read_where_the_cosines_belong_is_sin_for_cos(made_up):
    def student(t, a, b):
        s, _ = _coefficients(a, b)
        k = np.arange(3)
        return np.sin(np.outer(t, k)) @ s + np.cos(np.outer(t, k)) @ s

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"sin_cos_swapped"}, [(h.name, h.detail) for h in hypotheses]
    assert any("reads a sine's values where the cosine's belong" in h.detail for h in hypotheses)


def test_the_cosines_coefficients_doubled_are_no_sine_read(made_up):
    def student(t, a, b):
        s, c = _coefficients(a, b)
        k = np.arange(3)
        return np.sin(np.outer(t, k)) @ s + np.cos(np.outer(t, k)) @ (2.0 * c)

    hypotheses = found(made_up, student)
    assert not any("sine's values" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
