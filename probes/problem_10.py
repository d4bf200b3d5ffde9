"""Probes of problem 10: the printed matrices and the keys of its multiple-choice questions.

The keys are computed by the package's reference-only functions, so these probes are meaningful on the reference
alone; the checks that use them are secret (graded on submission, never recorded in the student kit).
"""

from . import module, probe


@probe(reference_only=True)
def course_c(pkg):
    """The course's approximate A_IC of (c), as printed (not orthonormal)."""
    return module(pkg, "problem_10").COURSE_C


@probe(reference_only=True)
def key_a(pkg):
    """The key of (a) and the orthonormality defect of every option."""
    p10 = module(pkg, "problem_10")
    return {"key": p10.answer_a(), "defects": [p10.orthonormality_defect(A) for A in p10.MATRICES_A]}


@probe(reference_only=True)
def key_b(pkg):
    """The key of (b), and for every option whether it is orthonormal and its determinant."""
    import numpy as np

    p10 = module(pkg, "problem_10")
    return {"key": p10.answer_b(), "orthonormal": [bool(p10.is_orthonormal(A)) for A in p10.MATRICES_B],
            "det": [float(np.linalg.det(A)) for A in p10.MATRICES_B]}
