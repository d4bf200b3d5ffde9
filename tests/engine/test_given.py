"""The formula tier on the code that a problem's own module gives whole (``grader.diagnosis.mutants``: ``given``):
a function of ``problem_NN.py`` that holds no solution region is the student's file too, and its slips are tried
where no slip of a region reproduces the student's value.

Problem 34's biped and gait are such functions (its module has no region).  The test plants a mistake into a copy
of the reference and asks the tier on two inputs, as ``tests/engine/test_mutants.py`` does; the near miss is the
same mistake seen from a check of another problem, whose tier does not try problem 34's given code.
"""

from grader.diagnosis import mutants
from grader.private import drop_private

from .test_mutants import evidence, planted_package, scene

#: the biped at two times of its gait, and the body whose position is compared (the first thigh)
TIMES = [(0.37,), (1.13,)]
THIGH = ("bodies", 2, "B_r_IB")
BOBBING, BOBBING_LEFT_OUT = "[HIP_HEIGHT, 0.0, BOB]", "[HIP_HEIGHT, 0.0, 0.0]"


def biped_slips(tmp_path, check_id, old, new):
    student = planted_package(tmp_path, "problem_34.py", old, new)
    try:
        evidences = [evidence("problem_34.biped", args, THIGH, student) for args in TIMES]
        return mutants.mutant_slips(scene(check_id), evidences)
    finally:
        drop_private(student)


def named(found) -> set:
    return {h.name for h in found}


def test_a_slip_in_a_given_function_of_the_problems_module_is_named(tmp_path):
    """The hip's bobbing left out of the gait, ``[HIP_HEIGHT, 0.0, 0.0]``: an entry of a list in
    ``gait_coefficients``, which the template gives whole, written 0.  A number of data left out is told as a term
    left out and as an offset (``_ENTRIES``)."""
    found = biped_slips(tmp_path, "p34.biped", BOBBING, BOBBING_LEFT_OUT)
    assert named(found) == {"missing_term", "offset"}, [(h.name, h.detail) for h in found]
    assert all("`gait_coefficients`" in h.detail for h in found), [h.detail for h in found]


def test_the_given_code_of_another_problems_module_is_not_tried(tmp_path):
    """The near miss: the same slip seen from a check of problem 35 (a neighbour, whose regions problem 34 may
    share) names nothing: the code a module gives whole is tried for its own problem alone."""
    assert biped_slips(tmp_path, "p35.biped", BOBBING, BOBBING_LEFT_OUT) == []
