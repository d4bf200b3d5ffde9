"""Checks of problem 20: what makes an inertia matrix.

The student's ``is_inertia_matrix`` is tested on constructed matrices that violate exactly one property each
(symmetry, positive definiteness, the triangle inequality of the principal moments) and on valid ones.  Part (a)
follows the physics: as printed, options 2, 3 and 4 are all not inertia matrices, and any of them is accepted.
"""

import numpy as np

from checks._answers import choice
from checks._rigid import compact, quaternion_rotation
from grader.checking import STAGE_STRUCTURE, STAGE_VALUES, check, fail
from probes import problem_20 as p20

TITLE = "Understanding Inertia Matrices"
MANUAL = {"a": ("20(a): Why is the matrix you chose not an inertia matrix?", 1)}


def _rotation(seed):
    rng = np.random.default_rng(seed)
    return quaternion_rotation(rng.normal(size=4))


def _rotated(moments, seed):
    A = _rotation(seed)
    return A @ np.diag(moments) @ A.T


def _sheet(ctx, k):
    """The sheet's matrix of option ``k`` of (a), as printed (the package's constants)."""
    return ctx.reference(p20.sheet_matrices)[str(k)]


#: the principal moments of a small part, in kg m^2 (a bead of a gram and a few millimetres): a tolerance that is not
#: relative to the matrix's size judges them by the tolerance alone
SMALL_BODY = 1e-10

ABSOLUTE_TOLERANCE = ("Compare with a tolerance relative to the size of the matrix (tol times its largest entry), "
                      "not an absolute one: a small body's moments (1e-10 kg m^2 for a bead) are below any fixed "
                      "tolerance.", "absolute_tolerance")


def _option(ctx, key):
    """The chosen option of 20(``key``) as an integer (``3``, ``3.0`` or ``"3"``)."""
    return choice(ctx, key, (1, 2, 3, 4), f"20({key})")


#: judged with every set of matrices, with the opposite verdict expected: a constant answer cannot pass a check
CONTROLS = {
    True: ("a matrix with a negative principal moment, diag(-1, 2, 2)", np.diag([-1.0, 2.0, 2.0])),
    False: ("a valid inertia matrix, diag(2, 2.5, 3)", np.diag([2.0, 2.5, 3.0])),
}


def _judge(ctx, matrices, expected_ok, property_text, mistake=None):
    """Fail at the first matrix ``(label, I)`` that the student's ``is_inertia_matrix`` misjudges; ``mistake(label)``
    gives the ``(hint, diagnosis)`` for it.  A control matrix with the opposite verdict is judged too, so that an
    answer that does not depend on the matrix earns nothing."""
    control_label, control = CONTROLS[expected_ok]
    results = ctx.student(p20.is_inertia, [I for _, I in matrices] + [control])
    if not isinstance(results, list) or len(results) != len(matrices) + 1 or not all(
            isinstance(r, list) and len(r) == 2 for r in results):
        fail(f"is_inertia_matrix must return (ok, reason) for each matrix, got {str(results)[:200]}")
    judged = [(label, I, expected_ok, property_text, mistake) for label, I in matrices]
    judged.append((control_label, control, not expected_ok,
                   "is a valid inertia matrix" if not expected_ok else "is not an inertia matrix", None))
    for (label, I, expected, text, diagnose), (ok, reason) in zip(judged, results):
        if ok is expected:
            continue
        moments = np.linalg.eigvals(I).real if np.abs(I - I.T).max() > 0 else np.linalg.eigvalsh(I)
        message = (f"is_inertia_matrix(I) returned {ok} (reason: {reason!r}) for {label}, which {text}.\n"
                   f"I = {compact(I)}\neigenvalues: {compact(np.sort(moments))}\nexpected: {expected}")
        if label == control_label and len({ok for ok, _ in results}) == 1:
            fail(f"{message}\nIt returned {ok} for every matrix it was given.",
                 "The answer must depend on the matrix: test symmetry, positive definiteness and the triangle "
                 "inequality of the principal moments, and return True only when all three hold.",
                 "constant_answer")
        hint, diagnosis = diagnose(label) if diagnose else ("", "")
        fail(message, hint, diagnosis)


@check(1, title="is_inertia_matrix accepts valid inertia matrices (random orientations, the sheet's option 1, a "
       "flat plate with I3 = I1 + I2, a small body's)", stage=STAGE_STRUCTURE, group="accepts")
def check_accepts_valid(ctx):
    rng = np.random.default_rng(ctx.seed)
    matrices = [(f"a random inertia matrix (principal moments {compact(m)})", _rotated(m, rng.integers(2**31)))
                for m in (np.array([y + z, x + z, x + y]) for x, y, z in rng.uniform(0.2, 2.0, (4, 3)))]
    matrices += [("the sheet's option 1", _sheet(ctx, 1)), ("a flat plate diag(1, 1, 2)", np.diag([1.0, 1.0, 2.0])),
                 ("a rotated flat plate diag(1, 1.5, 2.5)", _rotated([1.0, 1.5, 2.5], 5)),
                 (f"a small body's inertia, a rotated diag(2, 2.5, 3) * {SMALL_BODY:g}",
                  _rotated(SMALL_BODY * np.array([2.0, 2.5, 3.0]), 13))]

    def mistake(label):
        if "small body" in label:
            return ABSOLUTE_TOLERANCE
        if "plate" in label:
            return ("For a flat body I3 = I1 + I2 exactly: the triangle inequality allows equality (I3 <= I1 + I2, "
                    "with a small tolerance for rounding).", "plate_rejected")
        return ("Check the properties of the principal moments (eigenvalues), with a tolerance relative to the "
                "largest entry for rounding.", "")

    _judge(ctx, matrices, True, "is a valid inertia matrix", mistake)


@check(1, title="is_inertia_matrix rejects matrices that are not symmetric (and otherwise fine)",
       stage=STAGE_STRUCTURE, group="symmetry")
def check_rejects_non_symmetric(ctx):
    skew = np.array([[0.0, -0.1, 0.05], [0.1, 0.0, -0.08], [-0.05, 0.08, 0.0]])
    matrices = [("a rotated diag(2, 2.5, 3) plus a small skew-symmetric part", _rotated([2.0, 2.5, 3.0], 7) + skew),
                ("the sheet's option 2", _sheet(ctx, 2))]
    hint = ("An inertia matrix is symmetric (I_ij = I_ji). np.linalg.eigvalsh reads only one triangle of the "
            "matrix, so test the symmetry first: np.allclose(I, I.T).")
    _judge(ctx, matrices, False, "is not symmetric", lambda label: (hint, "forgot_symmetry"))


@check(1, title="is_inertia_matrix rejects a matrix that is not positive definite (and otherwise fine)",
       stage=STAGE_STRUCTURE, group="positive_definite")
def check_rejects_not_positive_definite(ctx):
    matrices = [("diag(0, 2, 2)", np.diag([0.0, 2.0, 2.0])), ("diag(2, 0, 2)", np.diag([2.0, 0.0, 2.0])),
                ("a rotated diag(0, 2, 2) whose diagonal entries are all positive", _rotated([0.0, 2.0, 2.0], 11))]
    hint = ("An inertia matrix is positive definite: every principal moment is > 0 (a zero moment needs all mass on "
            "one line). The triangle inequality still holds here, so it must be tested separately.")

    def mistake(label):
        if label.startswith("diag"):
            return hint, "forgot_positive_definite"
        return ("Positive definiteness is a property of the PRINCIPAL moments (the eigenvalues): positive diagonal "
                "entries of a rotated matrix do not make it positive definite.", "definite_on_diagonal")

    _judge(ctx, matrices, False, "has a zero principal moment (symmetric, the triangle inequality holds)", mistake)


@check(1, title="is_inertia_matrix rejects matrices whose principal moments violate the triangle inequality",
       stage=STAGE_STRUCTURE, group="triangle")
def check_rejects_triangle(ctx):
    matrices = [("diag(1, 1.5, 3)", np.diag([1.0, 1.5, 3.0])),
                ("a rotated diag(1, 1.5, 3) whose diagonal entries satisfy the triangle inequality",
                 _rotated([1.0, 1.5, 3.0], 3)),
                ("the sheet's option 3", _sheet(ctx, 3)), ("the sheet's option 4", _sheet(ctx, 4)),
                (f"a small body's rotated diag(1, 1.5, 3) * {SMALL_BODY:g}",
                 _rotated(SMALL_BODY * np.array([1.0, 1.5, 3.0]), 17))]

    def mistake(label):
        if "small body" in label:
            return ABSOLUTE_TOLERANCE
        if label.startswith("diag"):
            return ("The principal moments of any mass distribution satisfy I3 <= I1 + I2 (I1 + I2 - I3 = "
                    "2 sum m z² >= 0): test it on the sorted eigenvalues.", "forgot_triangle_inequality")
        return ("The triangle inequality holds for the PRINCIPAL moments (the eigenvalues), not for the diagonal "
                "entries of a rotated matrix.", "triangle_on_diagonal")

    _judge(ctx, matrices, False, "violates the triangle inequality of the principal moments (symmetric, positive "
           "definite)", mistake)


@check(1, title="20(a): an option that is not an inertia matrix (as printed, options 2, 3 and 4 all qualify)",
       stage=STAGE_VALUES, group="part_a", secret=True)
def check_part_a(ctx):
    key = ctx.reference(p20.key_a)
    given = _option(ctx, "a")
    keys = key["keys"]
    if given in keys:
        return
    reasons = "; ".join(f"({k}) {reason}" for k, (ok, reason) in key["classify"].items())
    fail(f"[problem_20] a = {given} is not an option whose matrix fails to be an inertia matrix.\n"
         f"As printed, the matrices make several options correct (physics wins): any of {keys} is accepted.\n"
         f"{reasons}",
         "Test each matrix: symmetric? positive definite? principal moments (eigenvalues) satisfying "
         "I3 <= I1 + I2? Write the option as an integer, e.g. a = 3.")


@check(1, title="20(b): the statement that is not necessarily correct for the object of Figure 22",
       stage=STAGE_VALUES, group="part_b", secret=True)
def check_part_b(ctx):
    key = ctx.reference(p20.key_b)
    given = _option(ctx, "b")
    if given != key:
        fail(f"[problem_20] b = {given} is not the expected option.",
             "The statements about the diagonal (c > a, e < a) and about f follow from the object's shape and "
             "symmetry in Figure 22; which one does not? Write the option as an integer, e.g. b = 2.")
