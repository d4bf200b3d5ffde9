"""The formula tier on the code that a problem's own module gives whole (``grader.diagnosis.mutants``: ``given``):
a function of ``problem_NN.py`` that holds no solution region is the student's file too, and its slips are tried
where no slip of a region reproduces the student's value; last of all, after the module constants, those of the
functions the library gives whole (a constructor), which the student's package holds as well.

Problem 34's biped and gait are such functions (its module has no region).  The test plants a mistake into a copy
of the reference and asks the tier on two inputs, as ``tests/engine/test_mutants.py`` does; the near miss is the
same mistake seen from a check of another problem, whose tier does not try problem 34's given code.
"""

import importlib

import numpy as np

from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, Source, array_of
from grader.private import drop_private

from .stand_ins import made_up_package
from .test_mutants import TIGHT, evidence, made_up_probe, planted_package, scene

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



SHAPES = '''
import numpy as np


class Box:
    """A box of edges ``size`` (a unit cube where none is given) and ``density``."""

    def __init__(self, size=None, density=1.0):
        self.size = np.ones(3) if size is None else np.asarray(size, dtype=float)
        self.density = float(density)
'''

BOXES = '''
import numpy as np

from .shapes import Box


def box_mass(size, density):
    """The box's mass and its longest edge."""
    box = Box(size, density)
    # BEGIN SOLUTION problem 96
    return np.array([box.density * np.prod(box.size), np.max(box.size)])
    # END SOLUTION
'''


def test_a_slip_in_a_constructor_the_library_gives_whole_is_named(tmp_path, monkeypatch):
    """``Box.__init__`` (a module of the library that holds no region) keeps the default edges whatever it is
    given: no slip of the region reproduces the mass and the edge, the constructor's (a default taken: the
    argument ignored) does.  The near miss: the region's own slip, the product of the edges left out, is named
    there, and the library's code is not tried."""
    with made_up_package(tmp_path, monkeypatch, BOXES, 96, "boxes", {"shapes.py": SHAPES}) as package:
        module = importlib.import_module(f"{package.__name__}.problem_96")

        def found(student):
            evidences = [Evidence(array_of(student(*args)), array_of(module.box_mass(*args)), TIGHT, "value",
                                  source=Source(made_up_probe("box_mass", 96), args, ()))
                         for args in (([0.5, 2.0, 1.5], 3.0), ([1.2, 0.7, 2.5], 0.4))]
            return mutants.mutant_slips(scene("p96.box_mass"), evidences)

        defaulted = found(lambda size, density: np.array([density, 1.0]))
        assert named(defaulted) == {"ignored_argument"}, [(h.name, h.detail) for h in defaulted]
        assert all("`__init__` takes the default whatever its argument" in h.detail for h in defaulted), \
            [h.detail for h in defaulted]
        unmultiplied = found(lambda size, density: np.array([density, max(size)]))
        assert unmultiplied and not any("`__init__`" in h.detail for h in unmultiplied), \
            [(h.name, h.detail) for h in unmultiplied]
