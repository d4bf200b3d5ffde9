"""The formula tier's argument of zeros passed as a name (``grader.diagnosis.mutants``: ``zeros_filled``):
``accelerations(q, qd, qd)`` for ``accelerations(q, qd, np.zeros(2))``, the rates passed where the torques of an
unactuated system belong, drive it with torques equal to its rates: a term that does not belong, added.

A mistake planted into a made-up problem (a bar's right-hand side that calls a given function with no torque) that
the tier names on two inputs, with near misses it must not name so: the torques passed as the rates halved (a
value that no name of the function holds), and zeros inside a list (the rates of a state at rest), which are no
argument of a call."""

import numpy as np

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene
from grader.diagnosis import mutants

SOURCE = '''"""A made-up problem for an argument of zeros passed as a name."""

import numpy as np


def accelerations(q, qd, tau, m=2.0, g=9.81):
    """A made-up bar's accelerations under the torques ``tau`` (given)."""
    return np.array([(tau[0] - 0.3 * qd[0] - m * g * np.sin(q[0])) / m, (tau[1] - q[1] * qd[0] ** 2) / (m + 1)])


def bar_rhs(t, y):
    """The right-hand side of the made-up bar, unactuated."""
    # BEGIN SOLUTION problem 71
    q, qd = y[:2], y[2:]
    return np.concatenate([qd, accelerations(q, qd, np.zeros(2))])
    # END SOLUTION


def at_rest(q):
    """The made-up bar's state at rest at ``q``."""
    # BEGIN SOLUTION problem 71
    return np.concatenate([q, np.zeros(2)])
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 71, "zeros_filled")

INPUTS = [(0.0, np.array([0.3, -0.7, 1.2, 0.4])), (0.5, np.array([-1.1, 0.5, -0.6, 2.0]))]


def found(package, student):
    return mutants.mutant_slips(scene("p71.bar_rhs"), made_up_evidences(package, "bar_rhs", student, INPUTS,
                                                                        number=71))


def given(q, qd, tau, m=2.0, g=9.81):
    return np.array([(tau[0] - 0.3 * qd[0] - m * g * np.sin(q[0])) / m, (tau[1] - q[1] * qd[0] ** 2) / (m + 1)])


def test_the_rates_passed_as_the_torques_add_a_term(made_up):
    def student(t, y):
        q, qd = y[:2], y[2:]
        return np.concatenate([qd, given(q, qd, qd)])

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"extra_term"}, [(h.name, h.detail) for h in hypotheses]
    assert any("passes a value where an array of zeros belongs" in h.detail for h in hypotheses), \
        [h.detail for h in hypotheses]


def test_the_torques_as_the_rates_halved_are_no_name_passed(made_up):
    def student(t, y):
        q, qd = y[:2], y[2:]
        return np.concatenate([qd, given(q, qd, qd / 2)])

    hypotheses = found(made_up, student)
    assert not any("array of zeros" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_zeros_in_a_list_are_no_argument_of_a_call():
    import ast

    tree = ast.parse(SOURCE)
    functions = {f.name: f for f in tree.body if isinstance(f, ast.FunctionDef)}
    assert mutants._zero_arguments(functions["at_rest"]) == {}
    (names,) = mutants._zero_arguments(functions["bar_rhs"]).values()
    assert names == ("q", "qd", "t", "y"), names
