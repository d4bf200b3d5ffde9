"""A factor left out of a product that leaves the answer no multiple of the expected one is a term missing too.

The formula tier names ``missing_factor`` (a slip of scale) where one factor of a product left out reproduces the
student's value.  A factor that is a number (a time step, a density) scales the value it is left out of; one that
is a quantity of the formula of its own (the cosine of an angle in some entries, an inverse mass matrix) leaves a
part of the formula out, and the answer is then no multiple of the expected one.  There the engine tells a term
left out beside the factor (``engine._unscaled``), as a twin: where it would take the families told past two it is
left out.  Planted in a made-up problem: a friction force's normal load without its cosine (no multiple of the
expected force); near misses: a weight without its mass (a multiple of the expected one on every input) keeps its
factor alone, and so does a number, which is a multiple of any other.
"""

import numpy as np
import pytest

from grader.diagnosis import mutants
from grader.diagnosis.engine import _told, _unscaled

from .stand_ins import made_up_package
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem of a block on a slope."""

import numpy as np


def slope_forces(m, g, theta, mu):
    """The block's weight along and across the slope, and the friction force at its normal load."""
    # BEGIN SOLUTION problem 96
    weight = m * g * np.array([np.sin(theta), -np.cos(theta)])
    friction = mu * m * g * np.cos(theta)
    return np.array([weight[0], weight[1], friction])
    # END SOLUTION


def load(m, g):
    """The weight of a block."""
    # BEGIN SOLUTION problem 96
    return m * g
    # END SOLUTION
'''

BLOCKS = [(2.0, 9.81, 0.4, 0.3), (0.7, 3.7, 1.1, 0.6)]


@pytest.fixture
def made_up(tmp_path, monkeypatch):
    with made_up_package(tmp_path, monkeypatch, SOURCE, 96, "unscaled") as package:
        yield package


def _finding(package, name, student, inputs):
    """The formula tier's hypotheses for ``student`` where the made-up ``name`` belongs, as the engine tells them."""
    evidences = made_up_evidences(package, name, student, inputs, number=96)
    found = mutants.mutant_slips(scene("p96.made_up"), evidences)
    assert {h.name for h in found} == {"missing_factor"}, [(h.name, h.detail) for h in found]
    return _told([_unscaled(found, evidences)], "here")


def test_a_factor_that_is_a_quantity_of_the_formula_left_out_is_also_a_term_missing(made_up):
    def without_cosine(m, g, theta, mu):
        return np.array([m * g * np.sin(theta), -m * g * np.cos(theta), mu * m * g])

    finding = _finding(made_up, "slope_forces", without_cosine, BLOCKS)
    assert finding is not None and set(finding.names) == {"missing_factor", "missing_term"}, finding
    assert "no multiple of the expected one" in finding.hint


def test_a_factor_left_out_that_scales_the_answer_is_a_factor_only(made_up):
    def without_mass(m, g, theta, mu):
        return np.array([g * np.sin(theta), -g * np.cos(theta), mu * g * np.cos(theta)])

    assert _finding(made_up, "slope_forces", without_mass, BLOCKS).names == ("missing_factor",)
    assert _finding(made_up, "load", lambda m, g: np.array(g), [(2.0, 9.81), (0.7, 3.7)]).names == ("missing_factor",)
