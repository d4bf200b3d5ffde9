"""The formula tier's vector written out with its sign turned (``grader.diagnosis.mutants._entry_slips``): ``(DX, -DY,
0.0)`` for ``(-DX, DY, 0.0)``, an offset of the course's constants typed the other way round, every entry's sign
turned at once (one entry's sign alone is a slip of its own).

A mistake planted into a made-up problem (a hip's position turned by an angle) that the tier names on two inputs,
with a near miss it must not name so: one entry's sign turned."""

import numpy as np

from grader.diagnosis import mutants

from .stand_ins import about_3, made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for a vector of constants written with its sign turned."""

import numpy as np

DX, DY = 0.3, 0.2


def hip(angle):
    """A made-up hip's position: its offset from the joint turned by ``angle``, beside a fixed one."""
    # BEGIN SOLUTION problem 80
    c, s = np.cos(angle), np.sin(angle)
    turned = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]) @ np.array((-DX, DY, 0.0))
    return turned + np.array([0.0, 1.0, 0.5])
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 80, "vector_sign")

INPUTS = [(0.4,), (-1.1,)]


def found(package, student):
    return mutants.mutant_slips(scene("p80.hip"), made_up_evidences(package, "hip", student, INPUTS, number=80))


def test_a_vector_of_constants_written_with_its_sign_turned_is_a_sign_slip(made_up):
    def student(angle):
        return about_3(angle) @ np.array((0.3, -0.2, 0.0)) + np.array([0.0, 1.0, 0.5])

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"sign_flip"}, [(h.name, h.detail) for h in hypotheses]
    assert any("every entry's sign turned" in h.detail for h in hypotheses), [h.detail for h in hypotheses]


def test_one_entry_of_it_with_its_sign_turned_is_not_the_whole_vectors(made_up):
    def student(angle):
        return about_3(angle) @ np.array((0.3, 0.2, 0.0)) + np.array([0.0, 1.0, 0.5])

    hypotheses = found(made_up, student)
    assert not any("every entry's sign turned" in h.detail for h in hypotheses), [h.detail for h in hypotheses]
