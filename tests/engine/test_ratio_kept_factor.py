"""The formula tier's ratio upside down with a factor kept on top (``grader.diagnosis.mutants``): a ratio that
scales a quantity, ``-m J v / (m a**2 + J)``, written ``-(m a**2 + J) v / (m J)``, the ratio turned and the
quantity ``v`` left where it was.

A mistake planted into a made-up problem (an impulse at a lever) that the tier names on two inputs, with a near miss
it must not name so: the denominator's sum taken as a difference."""

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene
from grader.diagnosis import mutants

SOURCE = '''"""A made-up problem for a ratio upside down with the quantity it scales kept on top."""


def impulse(v, m, J, a):
    """A made-up impulse of a body of mass ``m`` and inertia ``J`` struck at the lever ``a`` at the speed ``v``."""
    # BEGIN SOLUTION problem 78
    return -m * J * v / (m * a ** 2 + J)
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 78, "ratio_kept_factor")

INPUTS = [(1.3, 2.0, 0.4, 0.7), (-0.8, 3.5, 1.1, -0.3)]


def found(package, student):
    return mutants.mutant_slips(scene("p78.impulse"), made_up_evidences(package, "impulse", student, INPUTS,
                                                                        number=78))


def test_the_ratio_turned_with_the_speed_kept_on_top_is_a_ratio_upside_down(made_up):
    def student(v, m, J, a):
        return -(m * a ** 2 + J) * v / (m * J)

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"ratio_inverted"}, [(h.name, h.detail) for h in hypotheses]
    assert all("upside down" in h.detail for h in hypotheses)


def test_the_denominators_sum_as_a_difference_is_no_ratio_upside_down(made_up):
    def student(v, m, J, a):
        return -m * J * v / (m * a ** 2 - J)

    hypotheses = found(made_up, student)
    assert not any(h.name == "ratio_inverted" for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
