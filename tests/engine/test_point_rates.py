"""The formula tier's reads of rates (``grader.diagnosis.mutants._read_slips``): a point's velocity where the position
whose end point it is belongs (by the course's notation ``B_v_B`` is the rate of ``B_r_IB``: the position from I to B,
the velocity of B, in the same frame's coordinates), and a list of names each read as its rate's quantity at once
(``[q1, q2]`` for ``[dq1, dq2]``): a state read from the wrong rows.

Each is a mistake planted into a made-up problem that the tier names on two inputs, with a near miss it must not name:
the angular velocity read where the position belongs (no rate of it), and the coordinates listed in the other order
where the rates belong (two slips at once)."""

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


def energy(q1, q2, dq1, dq2):
    """A made-up energy of two coordinates and their rates."""
    # BEGIN SOLUTION problem 87
    qd = np.array([dq1, dq2])
    return 0.5 * qd @ np.array([[2.0, 0.3], [0.3, 1.0]]) @ qd + np.cos(q1) * q2
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


ENERGY = [(0.4, -0.9, 1.3, 0.2), (-1.1, 0.6, -0.5, 0.8)]


def energy_of(qd):
    def student(q1, q2, dq1, dq2):
        rates = np.array(qd(q1, q2, dq1, dq2))
        return 0.5 * rates @ np.array([[2.0, 0.3], [0.3, 1.0]]) @ rates + np.cos(q1) * q2

    return student


def test_a_list_of_coordinates_read_where_their_rates_belong_is_a_state_read(made_up):
    hypotheses = mutants.mutant_slips(scene("p87.energy"), made_up_evidences(
        made_up, "energy", energy_of(lambda q1, q2, dq1, dq2: [q1, q2]), ENERGY, number=87))
    assert {h.name for h in hypotheses} == {"state_row"}, [(h.name, h.detail) for h in hypotheses]


def test_the_coordinates_in_the_other_order_where_the_rates_belong_are_no_state_read(made_up):
    hypotheses = mutants.mutant_slips(scene("p87.energy"), made_up_evidences(
        made_up, "energy", energy_of(lambda q1, q2, dq1, dq2: [q2, q1]), ENERGY, number=87))
    assert "state_row" not in {h.name for h in hypotheses}
