"""Checks of problem 10: properties of rotation matrices (multiple choice and a matrix read off a figure).

The multiple-choice checks (a) and (b) are secret: their keys stay with the instructor (the student kit defers
them to the graded submission).
"""

import numpy as np

from checks._answers import choice as _choice, typed_failure
from grader.checking import STAGE_VALUES, Tol, as_array, check, fail, format_array
from probes import problem_10 as p10

TITLE = "Understanding rotation matrices"
MANUAL = {"why": ("10(a)/(b): why is your choice (not) orthonormal / a rotation?", 1)}

#: a matrix written with one or two decimals is orthonormal to about this
READ_OFF = 0.1
#: an entry of A_IC read off the figure is the course's orientation's to about this: the precision the diagnosis
#: engine holds a slip of the answer to (a slip moves an entry by ten times as much, as an axis reversed does)
READ_OFF_ENTRY = Tol("an entry read off the figure", READ_OFF)
#: how far (in degrees) an answer to (c) may be from the course's orientation
C_ANGLE_DEG = 25.0


@check(1, title="(a) the matrix that is NOT orthonormal", stage=STAGE_VALUES, secret=True)
def check_a(ctx):
    key = ctx.reference(p10.key_a)
    choice = _choice(ctx, "a", range(1, 5), "(a)")
    if choice != key["key"]:
        fail(f"option {choice} is orthonormal: max |A.T A - E| = {key['defects'][choice - 1]:.3f} "
             f"(zero up to the printed three decimals).",
             "Check A.T @ A for each option: only one has a column that is not a unit vector.", "wrong_choice")


@check(1, title="(b) the matrix that IS a rotation", stage=STAGE_VALUES, secret=True)
def check_b(ctx):
    key = ctx.reference(p10.key_b)
    choice = _choice(ctx, "b", range(1, 5), "(b)")
    if choice != key["key"]:
        orthonormal = key["orthonormal"][choice - 1]
        why = (f"it is orthonormal but det = {key['det'][choice - 1]:+.3f}: a reflection"
               if orthonormal else "it is not orthonormal")
        fail(f"option {choice} is not a rotation: {why}.",
             "A rotation is orthonormal AND has determinant +1.", "reflection" if orthonormal else "wrong_choice")


def nearest_rotation(A):
    """The rotation nearest to ``A`` (Frobenius norm): ``u @ vt`` of the singular value decomposition
    ``A = u s vt``, with the last left singular vector reversed when that product is a reflection."""
    u, _, vt = np.linalg.svd(np.asarray(A, dtype=float))
    if np.linalg.det(u @ vt) < 0:
        u[:, -1] = -u[:, -1]
    return u @ vt


@check(2, title="(c) A_IC read off the figure is a proper rotation close to the course's orientation",
       stage=STAGE_VALUES)
def check_c(ctx):
    target = nearest_rotation(ctx.reference(p10.course_c))
    A = as_array(ctx.answer("c"), "[problem_10] c", (3, 3))

    def failure(message, hint, diagnosis):  # the key stands beside every stage: a slip of the answer is told
        return typed_failure(ctx, message, hint, diagnosis, A, target, READ_OFF_ENTRY, "A_IC")

    defect = float(np.max(np.abs(A.T @ A - np.eye(3))))
    if defect > READ_OFF:
        raise failure(f"your A_IC is not orthonormal: max |A.T A - E| = {defect:.2f} > {READ_OFF} (allowed for "
                      f"values read off a figure).\ngot:\n{format_array(A, 2)}",
                      "Each column is an axis of C in I-coordinates: unit length and mutually perpendicular.",
                      "not_orthonormal")
    if np.linalg.det(A) < 0:
        raise failure(f"your A_IC is a reflection (det = {np.linalg.det(A):+.2f}), not a rotation.",
                      "C is a right-handed frame: one axis of yours points the wrong way, or two axes are in each "
                      "other's place.", "reflection")
    R = nearest_rotation(A)
    angle = np.degrees(np.arccos(np.clip((np.trace(target.T @ R) - 1) / 2, -1, 1)))
    if angle > C_ANGLE_DEG:
        raise failure(f"your A_IC is {angle:.0f}° away from the course's orientation (allowed {C_ANGLE_DEG:g}°).\n"
                      f"got:\n{format_array(A, 2)}\nthe course's orientation (the nearest rotation to its printed "
                      f"matrix, which itself is not orthonormal):\n{format_array(target, 2)}",
                      "Read each axis of C (purple) in the coordinates of I (green): it is a column of A_IC.",
                      "far_from_figure")
