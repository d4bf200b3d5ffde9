"""A slip of precision judged beside the other values of the same call (``grader.diagnosis.mutants._precise``).

The engine holds a slip of the formula tier to the student's whole result of the call behind the compared value: the
values they have right as well as the one they have wrong (``engine._siblings``).  A slip of precision leaves some of
those values as they are (a state's positions where only its velocities were converted to float32).  Such a value is
the expected one exactly, as the mutant's own is, and does not refute the slip; a value of the same call off by more
than a slip of precision makes does.

An array given no dtype (``np.array([x, y])``) is tried created in single precision too, and no slip of precision is
tried where the student's value is beyond the band of precision on the input shown (none would be told there).

Each is a mistake planted into a made-up problem, graded on two inputs (and on the value the slip leaves alone)."""

import numpy as np

from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for the slips of precision beside the values they leave alone."""

import numpy as np


def kicked(q, qd, m):
    """The state after a made-up kick: the positions as they were, the velocities changed by an impulse over m."""
    # BEGIN SOLUTION problem 89
    qd = np.asarray(qd, dtype=float)
    return np.array(q, dtype=float), qd + np.array([0.3, -1.7, 0.45]) / m
    # END SOLUTION


def spread(x, y, m):
    """Made-up distances of two points from their centre, from their second moments ``x``, ``y`` and the mass."""
    # BEGIN SOLUTION problem 89
    return np.sqrt(3.0 * np.array([x, y]) / m)
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 89, "siblings")

INPUTS = [(np.array([0.2, -0.13, 1.1]), np.array([-0.7517, -3.3067, 0.3277]), 1.78),
          (np.array([-0.19, 0.26, 0.0097]), np.array([1.4685, -3.2003, -0.2223]), 1.57)]


def single(q, qd, m):
    qd = np.asarray(qd, dtype=np.float32)
    return np.array(q, dtype=float), qd + np.array([0.3, -1.7, 0.45]) / m


def slips(package, student):
    """The slips named for the velocities on both inputs, beside the positions on the first."""
    compared = made_up_evidences(package, "kicked", student, INPUTS, path=(1,), number=89)
    alone = made_up_evidences(package, "kicked", student, INPUTS[:1], path=(0,), number=89)
    assert all(not np.allclose(e.got, e.expected, rtol=1e-12, atol=0.0) for e in compared)
    return mutants.mutant_slips(scene("p89.kicked"), compared + alone)


def test_velocities_in_float32_beside_positions_left_as_they_are_are_named_float32(made_up):
    found = slips(made_up, single)
    assert {h.name for h in found} == {"float32"}, [(h.name, h.detail) for h in found]


def test_velocities_in_float32_beside_positions_far_off_are_not_named_float32(made_up):
    """The near miss: the positions the student returns are moved as well, by far more than float32 makes; the
    float32 mutant leaves them as they are and is refuted."""
    def moved(q, qd, m):
        positions, velocities = single(q, qd, m)
        return positions + 0.5, velocities

    assert "float32" not in {h.name for h in slips(made_up, moved)}


SPREAD = [(0.37, 1.21, 1.9), (2.3, 0.71, 0.6)]


def test_an_array_given_no_dtype_created_in_float32_is_named_float32(made_up):
    def student(x, y, m):
        return np.sqrt(3.0 * np.array([x, y], dtype=np.float32) / m)

    found = mutants.mutant_slips(scene("p89.spread"), made_up_evidences(made_up, "spread", student, SPREAD, number=89))
    assert {h.name for h in found} == {"float32"}, [(h.name, h.detail) for h in found]


def test_a_value_beyond_the_band_of_precision_is_no_slip_of_precision(made_up):
    """The near miss: the points' distances doubled are far outside the band; no slip of precision is told."""
    found = mutants.mutant_slips(scene("p89.spread"), made_up_evidences(
        made_up, "spread", lambda x, y, m: 2.0 * np.sqrt(3.0 * np.array([x, y], dtype=np.float32) / m), SPREAD,
        number=89))
    assert not {h.name for h in found} & {"float32", "rounded"}, [(h.name, h.detail) for h in found]
