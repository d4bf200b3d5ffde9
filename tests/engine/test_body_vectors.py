"""The formula tier's slip of a vector in a body's coordinates turned into inertial ones (``grader.diagnosis.mutants``:
``_frame_slips``, ``inertial_vector``): ``A_IB @ B_v_B`` where ``B_v_B`` belongs, in a function that has the rotation
``A_IB`` at hand, told as a wrong frame.  A read turned already (``A_IB @ B_omega_B``) is not turned twice.

Planted into a made-up problem that the tier names on two inputs, with the near miss of a vector turned the other way
(``A_IB.T @ B_v_B``), which is not that slip."""

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for the slips of a body's coordinates."""

import numpy as np


def drift(A_IB, B_v_B, B_omega_B, dt):
    """A body's step of position in its own coordinates over ``dt``, and its velocity in inertial ones."""
    # BEGIN SOLUTION problem 93
    B_step = dt * (B_v_B - np.cross(B_omega_B, B_v_B))
    return np.concatenate([B_step, A_IB @ B_v_B])
    # END SOLUTION
'''


made_up = made_up_fixture(SOURCE, 93, "body")


def turn(axis, angle):
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    K = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + np.sin(angle) * K + (1.0 - np.cos(angle)) * K @ K


INPUTS = [(turn([1.0, 2.0, 0.5], 0.7), np.array([0.3, -1.0, 0.5]), np.array([0.2, 0.4, -0.6]), 0.1),
          (turn([-0.3, 1.0, 1.5], -1.1), np.array([-0.8, 0.2, 1.1]), np.array([-0.5, 0.1, 0.3]), 0.05)]


def found(package, student):
    evidences = made_up_evidences(package, "drift", student, INPUTS, number=93)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    return mutants.mutant_slips(scene("p93.drift"), evidences)


def test_a_body_vector_turned_into_inertial_coordinates_is_a_wrong_frame(made_up):
    def student(A_IB, B_v_B, B_omega_B, dt):
        return np.concatenate([dt * (A_IB @ B_v_B - np.cross(B_omega_B, B_v_B)), A_IB @ B_v_B])

    hypotheses = found(made_up, student)
    assert {DIAGNOSES[h.name].family for h in hypotheses} == {"frame"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`drift` turns a vector of body coordinates into inertial ones" in h.detail for h in hypotheses)


def test_a_body_vector_turned_the_other_way_is_not_that_slip(made_up):
    def student(A_IB, B_v_B, B_omega_B, dt):
        return np.concatenate([dt * (A_IB.T @ B_v_B - np.cross(B_omega_B, B_v_B)), A_IB @ B_v_B])

    hypotheses = found(made_up, student)
    assert not any("into inertial ones" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_a_vector_turned_already_is_not_turned_twice():
    import ast

    statement = ast.parse("v = A_IB @ B_omega_B + B_v_B").body[0]
    turned = [slip for slip, _ in mutants._frame_slips(statement, frozenset({"A_IB", "B_omega_B", "B_v_B"}),
                                                       frozenset())]
    assert turned == ["inertial_vector"]  # B_v_B alone: B_omega_B is turned already
