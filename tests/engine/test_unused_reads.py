"""A read of one value for another that leaves a value the function computes unread
(``grader.diagnosis.mutants.rivals``: ``UNUSED_READS``): ``return q, qd, qd`` for ``return q, qd, qdd`` reads a rate
where its own rate belongs, and leaves the acceleration the function computed read nowhere.  Both are told: a state
read from the wrong row, or a value left unused.

A mistake planted into a made-up problem (a motion that returns its position, rate and acceleration), named on two
inputs; the near misses: the same kind of read of a parameter (``M @ qd_des`` for ``M @ qdd_des``), whose value the
caller passes, adds no value left unused (the test of an ignored argument is the measure of arguments), and a slip of
another kind that leaves a value unread (its term dropped) adds none either."""

import importlib

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.checking import Tol
from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, Source, array_of
from .stand_ins import made_up_fixture
from .test_mutants import scene

TIGHT = Tol("tight", 1e-9, 1e-9)

SOURCE = '''"""A made-up problem for a read that leaves a value passed in unused."""

import numpy as np


def controller(M, qd_des, qdd_des):
    """A made-up controller's torques."""
    # BEGIN SOLUTION problem 73
    return M @ qdd_des + 0.5 * qd_des
    # END SOLUTION


def motion(t):
    """A made-up motion's position, rate and acceleration at ``t``."""
    # BEGIN SOLUTION problem 73
    q = np.sin(t)
    qd = np.cos(t)
    qdd = -np.sin(t)
    return np.array([q, qd, qdd])
    # END SOLUTION


def rhs(M, q_des, qd_des, qdd_des):
    """A made-up right-hand side: the torques less a spring's pull."""
    # BEGIN SOLUTION problem 73
    return controller(M, qd_des, qdd_des) - 2.0 * q_des
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 73, "unused_reads")

INPUTS = [(np.array([[2.0, 0.3], [0.3, 1.5]]), np.array([0.2, -0.4]), np.array([1.1, 0.6]), np.array([-0.7, 2.2])),
          (np.array([[3.1, -0.2], [-0.2, 0.9]]), np.array([-1.3, 0.8]), np.array([0.4, -1.9]), np.array([1.6, 0.3]))]


def probe_of(name):
    def probe(pkg, *args):
        return getattr(importlib.import_module(f"{pkg.__name__}.problem_73"), name)(*args)

    probe.__name__ = name  # the compared call's own function, by its name
    return probe


def found(package, name, student):
    inputs = INPUTS if name == "rhs" else [(M, qd_des, qdd_des) for M, _, qd_des, qdd_des in INPUTS]
    return found_of(package, name, student, inputs)


def found_of(package, name, student, inputs):
    probe = probe_of(name)
    evidences = [Evidence(array_of(student(*args)), array_of(probe(package, *args)), TIGHT, "value",
                          source=Source(probe, args, ())) for args in inputs]
    return mutants.mutant_slips(scene(f"p73.{name}"), evidences)


def families(hypotheses) -> set:
    return {DIAGNOSES[h.name].family for h in hypotheses}


def test_a_rate_read_for_its_rate_in_a_parameter_adds_no_value_unused(made_up):
    def student(M, q_des, qd_des, qdd_des):
        return M @ qd_des + 0.5 * qd_des - 2.0 * q_des

    hypotheses = found(made_up, "rhs", student)
    assert "state_row" in families(hypotheses), [(h.name, h.detail) for h in hypotheses]
    assert not any(h.name == "value_unused" for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_a_term_dropped_in_the_controller_adds_no_value_unused(made_up):
    def student(M, q_des, qd_des, qdd_des):
        return 0.5 * qd_des - 2.0 * q_des

    hypotheses = found(made_up, "rhs", student)
    assert not any("the value passed as" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_a_rate_returned_for_its_rate_leaves_the_value_computed_unused(made_up):
    hypotheses = [h for h in found_of(made_up, "motion", lambda t: np.array([np.sin(t), np.cos(t), np.cos(t)]),
                                      [(0.4,), (1.3,)])]
    assert families(hypotheses) == {"state_row", "ignored_argument"}, [(h.name, h.detail) for h in hypotheses]
    assert any("the value it computes as `qdd` is never used" in h.detail for h in hypotheses), \
        [h.detail for h in hypotheses]
