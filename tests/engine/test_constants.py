"""The formula tier on module constants (``grader.diagnosis.mutants``: ``constant_mutants``): the data a student
types from the sheet into the constants of a problem's module or of the library (lengths, masses, gains, gravity)
may be typed otherwise (a number's sign, a factor 2, ten or a thousand, degrees for radians, a square root, an
entry of a table exchanged or written 0, a matrix written out transposed, two constants exchanged); those slips are
tried after every slip of the code, where none reproduced the student's value.

The test plants a mistake into a copy of the reference and asks the tier on two inputs, as
``tests/engine/test_mutants.py`` does: the library's gravity typed a tenth of itself reaches problem 24's triple
pendulum through the name its module imports and the constant it computes from it (``I_GRAV``).  The near miss is
the gravity three times itself, which no slip of typing gives: nothing is named.  A joint frame's rotation of
problem 32's table typed with its rows as columns is a transpose; with two rows changed otherwise, it is none.
"""

import numpy as np

from grader.diagnosis import mutants
from grader.private import drop_private

from .test_mutants import evidence, planted_package, scene

#: two states of the triple pendulum (angles, rates) at which its right-hand side is compared
STATES = [[(0.0, [0.3, -0.5, 0.8, 0.2, -0.1, 0.4])], [(0.0, [-0.7, 0.4, 0.1, -0.3, 0.6, 0.0])]]


def planted_slips(tmp_path, file: str, old: str, new: str, probe: str, inputs, parts, check: str):
    """The formula tier's slips for a package with ``old`` written as ``new`` in ``file``, on two inputs of
    ``probe`` (each a tuple of its arguments) that the slip changes."""
    student = planted_package(tmp_path, file, old, new)
    try:
        evidences = [evidence(probe, args, parts, student) for args in inputs]
        assert all(not np.allclose(e.got, e.expected) for e in evidences)
        return mutants.mutant_slips(scene(check), evidences)
    finally:
        drop_private(student)


def pendulum_slips(tmp_path, new: str):
    return planted_slips(tmp_path, "conventions.py", "GRAVITY = 9.81", new, "problem_24.pendulum_ode",
                         [(cases,) for cases in STATES], (0,), "p24.pendulum_ode")


def test_a_library_constant_typed_otherwise_is_named(tmp_path):
    found = pendulum_slips(tmp_path, "GRAVITY = 0.981")
    assert {h.name for h in found} == {"wrong_factor"}, [(h.name, h.detail) for h in found]
    assert any("`GRAVITY` is a tenth" in h.detail for h in found), [h.detail for h in found]


def test_a_constant_off_by_a_factor_no_typing_gives_names_nothing(tmp_path):
    assert pendulum_slips(tmp_path, "GRAVITY = 3.0 * 9.81") == []


def arm_slips(tmp_path, new: str):
    """The tier on problem 32's arm with its second joint frame's constant matrix written as ``new``."""
    old = "np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]),"
    return planted_slips(tmp_path, "problem_32.py", old, new, "problem_32.robot",
                         [([0.3, -0.6, 0.9],), ([-0.8, 0.4, 1.3],)], ("end_effector",), "p32.end_effector")


def test_a_constant_matrix_written_transposed_is_a_transpose(tmp_path):
    """A joint frame's rotation typed into the module's table with its rows as columns: a transpose."""
    found = arm_slips(tmp_path, "np.array([[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]),")
    assert {h.name for h in found} == {"transpose"}, [(h.name, h.detail) for h in found]
    assert any("`_A_PDP` is written transposed" in h.detail for h in found), [h.detail for h in found]


def test_a_constant_matrix_with_two_rows_changed_names_no_transpose(tmp_path):
    """The near miss: the rotation's first row negated and its last exchanged with the middle one (no transpose)."""
    found = arm_slips(tmp_path, "np.array([[0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]),")
    assert "transpose" not in {h.name for h in found}, [(h.name, h.detail) for h in found]
