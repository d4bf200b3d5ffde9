"""The formula tier's argument of a call passed as its neighbour (``grader.diagnosis.mutants``:
``argument_repeated``): ``accelerations(q, qd, m, m, g)`` for ``accelerations(q, qd, m, theta, g)``, the mass passed
where the inertia belongs, leaves the inertia, read nowhere else, unused: one value read where another belongs.

A mistake planted into a made-up problem (a bar's right-hand side that passes its parameters to a given function)
that the tier names on two inputs, with a near miss it must not name so: the inertia passed doubled."""

import numpy as np

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene
from grader.diagnosis import mutants

SOURCE = '''"""A made-up problem for an argument of a call passed as its neighbour."""

import numpy as np


def accelerations(q, qd, m, theta, g):
    """A made-up bar's accelerations: its fall under ``g``, its turn slowed by its inertia ``theta`` (given)."""
    return np.array([-g - 0.3 * qd[0] / m, -q[1] * m * g / (theta + m)])


def bar_rhs(q, qd, m=2.0, theta=0.4, g=9.81):
    """The right-hand side of the made-up bar."""
    # BEGIN SOLUTION problem 74
    qdd = accelerations(q, qd, m, theta, g)
    return np.concatenate([qd, qdd])
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 74, "argument_repeated")

INPUTS = [(np.array([0.3, -0.7]), np.array([1.2, 0.4]), 1.5, 0.3, 9.81),
          (np.array([-1.1, 0.5]), np.array([-0.6, 2.0]), 3.2, 0.9, 3.7)]


def found(package, student):
    return mutants.mutant_slips(scene("p74.bar_rhs"), made_up_evidences(package, "bar_rhs", student, INPUTS,
                                                                         number=74))


def given(q, qd, m, theta, g):
    return np.array([-g - 0.3 * qd[0] / m, -q[1] * m * g / (theta + m)])


def test_the_mass_passed_for_the_inertia_leaves_the_inertia_unused(made_up):
    def student(q, qd, m, theta, g):
        return np.concatenate([qd, given(q, qd, m, m, g)])

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"value_unused"}, [(h.name, h.detail) for h in hypotheses]
    assert any("passes one argument of a call as its neighbour" in h.detail for h in hypotheses), \
        [h.detail for h in hypotheses]


def test_the_inertia_passed_doubled_is_no_argument_repeated(made_up):
    def student(q, qd, m, theta, g):
        return np.concatenate([qd, given(q, qd, m, 2 * theta, g)])

    hypotheses = found(made_up, student)
    assert not any(h.name == "value_unused" for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
