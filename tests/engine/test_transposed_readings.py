"""The formula tier's readings of one transpose (``grader.diagnosis.mutants.TRANSPOSED_READINGS``): ``v @ A`` is
``A.T @ v``, and a rotation read the other way round (``A_DpDs`` for ``A_DsDp``) is its transpose, so where a matrix
transposed reproduces the answer as well, they are told beside it as twins rather than counted as rivals of other
families: three readings of one value do not make the engine name nothing.

A mistake planted into a made-up problem (a vector mapped into a successor's frame) that the tier names on two
inputs, and the reads of names and rotations that tell the readings apart."""

import numpy as np
from scipy.spatial.transform import Rotation

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for a rotation transposed, read as a factor exchanged or as the rotation the other
way."""

import numpy as np


def successor_vector(A_DsDp, Dp_v, Dp_w):
    """A made-up vector of a successor frame: ``Dp_v`` mapped into it, and ``Dp_w`` mapped back."""
    # BEGIN SOLUTION problem 76
    A_DpDs = A_DsDp.T
    Ds_v = A_DsDp @ Dp_v
    return Ds_v + 0.5 * (A_DpDs @ (A_DsDp @ Dp_w))
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 76, "transposed_readings")

INPUTS = [(Rotation.from_rotvec([0.3, -0.5, 0.8]).as_matrix(), np.array([0.4, -1.2, 0.7]),
           np.array([1.0, 0.2, -0.3])),
          (Rotation.from_rotvec([1.1, 0.2, -0.4]).as_matrix(), np.array([-0.9, 0.5, 1.3]),
           np.array([0.1, -0.8, 0.6]))]


def found(package, student):
    return mutants.mutant_slips(scene("p76.successor_vector"),
                                made_up_evidences(package, "successor_vector", student, INPUTS, number=76))


def test_the_rotation_the_other_way_round_is_read_by_its_names():
    assert mutants._turned_round("A_IB", "A_BI") and mutants._turned_round("A_DsDp", "A_DpDs")
    assert mutants._turned_round("A_IC2", "A_C2I")
    assert not mutants._turned_round("A_IC2", "A_IC3") and not mutants._turned_round("A_II", "A_II")
    assert not mutants._turned_round("B_v_B", "I_v_B")
    assert mutants._related("A_DsDp", "A_DpDs") == "frames_turned" and mutants._related("A_IC2", "A_IC3") == "frames"


def test_a_transposed_rotation_is_told_with_its_readings_as_twins(made_up):
    def student(A_DsDp, Dp_v, Dp_w):
        return A_DsDp.T @ Dp_v + 0.5 * Dp_w

    hypotheses = found(made_up, student)
    told = {h.name for h in hypotheses if not h.twin}
    assert told == {"transpose"}, [(h.name, h.detail, h.twin) for h in hypotheses]
    twins = {h.name for h in hypotheses if h.twin}
    assert twins and {DIAGNOSES[name].family for name in twins} <= {"order", "frame"}, twins


def test_readings_without_a_transpose_kept_are_no_twins():
    made = [mutants.Mutant("problem_98", ("f",), slip, None) for slip in ("factors", "frames_turned", "square")]
    assert not any(h.twin for h in mutants._hypotheses(made[:2]))
    assert mutants._hypotheses(made) == []  # three families, no transpose among them: nothing is told
    transposed = made + [mutants.Mutant("problem_98", ("f",), "transpose", None)]
    hypotheses = mutants._hypotheses(transposed[1:])
    assert {h.name for h in hypotheses if not h.twin} == {"transpose", "wrong_factor"}
    assert {h.name for h in hypotheses if h.twin} == {"wrong_frame"}
