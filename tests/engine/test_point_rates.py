"""The formula tier's read of a point's velocity where the position whose end point it is belongs
(``grader.diagnosis.mutants._rate``): by the course's notation ``B_v_B`` is the rate of ``B_r_IB`` (the position from
I to B, the velocity of B, in the same frame's coordinates), a state read from the wrong rows.

A mistake planted into a made-up problem that the tier names on two inputs, with a near miss it must not name: the
angular velocity read where the position belongs (no rate of it)."""

import numpy as np

from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for a point's velocity read where its position belongs."""

import numpy as np


def stepped(B_r_IB, B_v_B, B_omega_B, dt):
    """A made-up step of a body's position in its own coordinates: its velocity less the transport of the
    position by the body's turn."""
    # BEGIN SOLUTION problem 87
    return B_r_IB + dt * (B_v_B - np.cross(B_omega_B, B_r_IB))
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 87, "point_rates")

INPUTS = [(np.array([0.3, -1.2, 0.8]), np.array([1.1, 0.4, -0.6]), np.array([0.2, 0.9, -0.5]), 0.1),
          (np.array([-0.7, 0.5, 1.4]), np.array([-0.3, 1.6, 0.2]), np.array([1.3, -0.4, 0.6]), 0.05)]


def found(package, student):
    return mutants.mutant_slips(scene("p87.stepped"), made_up_evidences(package, "stepped", student, INPUTS,
                                                                      number=87))


def test_a_velocity_read_where_the_position_belongs_is_a_state_read(made_up):
    def student(B_r_IB, B_v_B, B_omega_B, dt):
        return B_r_IB + dt * (B_v_B - np.cross(B_omega_B, B_v_B))

    hypotheses = found(made_up, student)
    assert "state_row" in {h.name for h in hypotheses}, [(h.name, h.detail) for h in hypotheses]
    assert any("reads a quantity where its rate belongs" in h.detail for h in hypotheses)


def test_the_angular_velocity_read_where_the_position_belongs_is_no_state_read(made_up):
    def student(B_r_IB, B_v_B, B_omega_B, dt):
        return B_r_IB + dt * (B_v_B - np.cross(B_omega_B, B_omega_B))

    assert "state_row" not in {h.name for h in found(made_up, student)}
