"""The formula tier's name of one angle's sine (cosine) read for another's (``grader.diagnosis.mutants``:
``_trig_angles``): of a Jacobian written out with the short names of a chain (``s1``, ``s12``, ``c12``), ``s1`` read
in one entry where ``s12`` belongs reads the first joint's angle where the sum of the first two belongs, one angle
read where another belongs, with a term of the sum left out.

A mistake planted into a made-up problem (a three-link arm's Jacobian) that the tier names on two inputs, with a near
miss it must not name so: the entry's ``s12`` doubled."""

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for the sines of a chain's angles read for one another."""

import numpy as np


def arm_jacobian(q, l1=1.0, l2=0.7, l3=0.4):
    """A made-up planar three-link arm's Jacobian of its end point."""
    # BEGIN SOLUTION problem 99
    s1, c1 = np.sin(q[0]), np.cos(q[0])
    s12, c12 = np.sin(q[0] + q[1]), np.cos(q[0] + q[1])
    s123, c123 = np.sin(q[0] + q[1] + q[2]), np.cos(q[0] + q[1] + q[2])
    return np.array([
        [-l1 * s1 - l2 * s12 - l3 * s123, -l2 * s12 - l3 * s123, -l3 * s123],
        [l1 * c1 + l2 * c12 + l3 * c123, l2 * c12 + l3 * c123, l3 * c123],
    ])
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 99, "trig_angles")

INPUTS = [(np.array([0.3, -0.7, 1.1]),), (np.array([-1.2, 0.4, 0.5]),)]


def jacobian(q, second=lambda s12: s12, l1=1.0, l2=0.7, l3=0.4):
    s1, c1, s12, c12 = np.sin(q[0]), np.cos(q[0]), np.sin(q[0] + q[1]), np.cos(q[0] + q[1])
    s123, c123 = np.sin(q[0] + q[1] + q[2]), np.cos(q[0] + q[1] + q[2])
    return np.array([[-l1 * s1 - l2 * s12 - l3 * s123, -l2 * second(s12) - l3 * s123, -l3 * s123],
                     [l1 * c1 + l2 * c12 + l3 * c123, l2 * c12 + l3 * c123, l3 * c123]])


def found(package, student):
    evidences = made_up_evidences(package, "arm_jacobian", student, INPUTS, number=99)
    return mutants.mutant_slips(scene("p99.arm_jacobian"), evidences)


def test_the_first_angle_s_sine_read_for_the_sum_s_in_one_entry_is_one_angle_for_another(made_up):
    """``-l2 * s1 - l3 * s123`` for ``-l2 * s12 - l3 * s123`` (the second column's first entry)."""
    hypotheses = found(made_up, lambda q: jacobian(q, second=lambda s12: np.sin(q[0])))
    assert {h.name for h in hypotheses} == {"wrong_angle", "missing_term"}, [(h.name, h.detail) for h in hypotheses]
    assert {DIAGNOSES[h.name].family for h in hypotheses} == {"order", "missing_term"}


def test_the_sum_s_sine_doubled_there_is_no_angle_read_for_another(made_up):
    hypotheses = found(made_up, lambda q: jacobian(q, second=lambda s12: 2 * s12))
    assert not any(h.name == "wrong_angle" for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_the_names_of_a_chain_s_sines_and_cosines_are_read_for_their_own_kind_only():
    import ast

    function = ast.parse(SOURCE).body[2]
    angled = mutants._trig_angles(function)
    assert dict(angled["s12"]) == {"s1": "angle_part", "s123": "angle_sum"}
    assert dict(angled["c1"]) == {"c12": "angle_sum", "c123": "angle_sum"}
    assert not any(other.startswith("c") for other, _ in angled["s123"])
