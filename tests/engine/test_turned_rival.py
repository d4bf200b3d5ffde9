"""A sign a check tells from what the value shows (``diagnosis.rival``) hears, besides the exchanges of two operands,
a matrix transposed whose effect that sign is (``mutants.opposite_slips``, ``TRANSPOSED``): a rotation transposed
turns the other way, ``A @ R3(angle).T`` for ``A @ R3(angle)`` is ``A @ R3(-angle)``, the angle's sign as its
effect; where rivals of two families reproduce the sign (an exchange and a transpose), the check's name stands alone.
Planted into a made-up problem, with the near miss of a turn by twice the angle, which no transpose gives."""

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import about_3, made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem of a frame turned about its 3-axis."""

import numpy as np


def about_3(angle):
    """The rotation by ``angle`` about the 3-axis (given)."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def between(A, angle, offset):
    """A made-up orientation: ``A`` turned about its own 3-axis by ``angle`` less ``offset``."""
    # BEGIN SOLUTION problem 86
    return A @ about_3(angle - offset)
    # END SOLUTION


def turned(A, angle):
    """A made-up orientation: ``A`` turned by ``angle`` about its own 3-axis."""
    # BEGIN SOLUTION problem 86
    return A @ about_3(angle)
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 86, "turned")

INPUTS = [(about_3(0.4) @ np.diag([1.0, -1.0, -1.0]), 0.7), (about_3(-1.2), 1.1)]


def test_a_sign_a_check_told_has_the_rotation_transposed_that_makes_it_as_a_rival(made_up):
    evidences = made_up_evidences(made_up, "turned", lambda A, angle: A @ about_3(-angle), INPUTS, number=86)
    found = mutants.opposite_slips(scene("p86.turned"), evidences, "sign")
    assert {DIAGNOSES[h.name].family for h in found} == {"transpose"}, [(h.name, h.detail) for h in found]


def test_a_turn_by_twice_the_angle_has_no_transpose_as_a_rival(made_up):
    evidences = made_up_evidences(made_up, "turned", lambda A, angle: A @ about_3(2.0 * angle), INPUTS, number=86)
    assert mutants.opposite_slips(scene("p86.turned"), evidences, "sign") == []


def test_a_sign_whose_rivals_are_of_two_families_keeps_the_checks_name_alone(made_up):
    """``A @ R3(offset - angle)`` for ``A @ R3(angle - offset)``: the turn negated, which the angle and the offset
    exchanged (an order) and the rotation transposed (a transpose) both give.  With the check's sign that would be
    three families: the check's name stands alone."""
    from grader.diagnosis.engine import rivalled

    inputs = [(about_3(0.4), 1.3, 0.2), (about_3(-0.9), 0.2, -0.7)]
    evidences = made_up_evidences(made_up, "between", lambda A, angle, offset: A @ about_3(offset - angle), inputs,
                                  number=86)
    found = mutants.opposite_slips(scene("p86.between"), evidences, "sign")
    assert {DIAGNOSES[h.name].family for h in found} == {"order", "transpose"}, [(h.name, h.detail) for h in found]
    assert rivalled(scene("p86.between"), evidences[0], "sign_flip") is None
