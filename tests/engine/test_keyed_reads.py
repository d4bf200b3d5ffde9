"""The formula tier's reads of a dict's entries (``grader.diagnosis.mutants._read_slips``): an entry read under the key
of another frame's quantity (``A["A_IC3"]`` for ``A["A_IC2"]``, by the course's notation two rotations), as a name so
read is.

A mistake planted into a made-up problem that the tier names on two inputs, with a near miss it must not name so: the
right frame's entry, doubled (no entry of another key gives it)."""

import numpy as np

from grader.diagnosis import mutants

from .stand_ins import about_3, made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for an entry of a dict read under another frame's key."""

import numpy as np


def _about_3(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _about_1(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def frames(alpha):
    """Two made-up frames' rotations, and a position (given whole)."""
    return {"A_IC1": _about_3(alpha), "A_IC2": _about_1(2.0 * alpha), "I_r_IC": np.ones(3)}


def coordinates(I_v, alpha):
    """A made-up point's position from the origin of C1 in C1's coordinates, and a vector's in C2's."""
    # BEGIN SOLUTION problem 82
    A = frames(alpha)
    return {"C1_r": A["A_IC1"].T @ (I_v - A["I_r_IC"]), "C2_v": A["A_IC2"].T @ I_v}
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 82, "keyed_reads")

INPUTS = [(np.array([0.3, -1.2, 0.8]), 0.4), (np.array([-0.7, 0.5, 1.4]), -1.1)]


def _about_1(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def found(package, student):
    return mutants.mutant_slips(scene("p82.coordinates"), made_up_evidences(package, "coordinates", student, INPUTS,
                                                                          path=("C2_v",), number=82))


def test_an_entry_read_under_another_frames_key_is_a_frame_slip(made_up):
    def student(I_v, alpha):
        return {"C1_r": about_3(alpha).T @ (I_v - 1.0), "C2_v": about_3(alpha).T @ I_v}

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"wrong_frame"}, [(h.name, h.detail) for h in hypotheses]
    assert any("reads a quantity in the coordinates of another frame" in h.detail for h in hypotheses)


def test_a_value_no_other_keys_entry_gives_is_not_named_a_frame(made_up):
    def student(I_v, alpha):
        return {"C1_r": about_3(alpha).T @ (I_v - 1.0), "C2_v": _about_1(2.0 * alpha).T @ I_v * 2.0}

    hypotheses = found(made_up, student)
    assert "wrong_frame" not in {h.name for h in hypotheses}, [(h.name, h.detail) for h in hypotheses]

