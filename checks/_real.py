"""Credit is for work: the one rule for checks that judge the student on their own results.

A check gives credit on the student's own earlier results where it carries an error forward (``ctx.carry_forward``:
``cardan`` judged on their own ``R1, R2, R3``) or checks a property of their own model (the energy of their own
Jacobians, ``g`` from their own potential, ``J`` from their own constraint).  An answer that does nothing is
consistent with itself: zero Jacobians are the derivative of a constant position, a zero model satisfies Lagrange's
equations.  So such credit is given only where the results it is judged on are *real*:

* finite and of the right shape;
* not zero and not constant (every entry the same) where the reference's value of the same quantity is not;
* a rotation orthonormal, and not the identity where the reference's turns;
* a mass matrix positive-definite (every motion has kinetic energy);
* a Jacobian (or a gradient) of full rank where the reference's has it.

Otherwise the check fails and says which of the student's results is degenerate, with nothing to carry forward
(diagnosis ``degenerate_input``).  The same rule keeps an answer that does nothing from earning the points of a
shape or a property check on its own (``assert_real``, diagnosis ``degenerate``).

A *finding* is ``(name, flaw)``: the flaw is "" for a real result, else what is wrong with it in words ("is all
zeros").  The functions below make findings from the student's values and, where a zero or constant value may be
right, the reference's value of the same quantity (which the check has already asked for).
"""

from __future__ import annotations

import numpy as np

from grader.checking import STRUCTURE, as_array, close, fail, format_array

__all__ = [
    "DEGENERATE",
    "DEGENERATE_INPUT",
    "flaw",
    "rotation_flaw",
    "mass_matrix_flaw",
    "rank_flaw",
    "real",
    "first_flaw",
    "is_real",
    "require_real",
    "assert_real",
]

#: the diagnosis of a check whose own answer does nothing (all zeros, a constant)
DEGENERATE = "degenerate"
#: the diagnosis of a check whose credit would rest on degenerate results of the student's (nothing to carry forward)
DEGENERATE_INPUT = "degenerate_input"

#: relative size below which a singular value counts as zero (rank: above the error of central differences), and
#: the size of "zero"
RANK_TOL = 1e-7
ZERO_TOL = 1e-12

DEGENERATE_INPUT_HINT = (
    "Credit judged on your own earlier results (error carried forward, or a property of your own model) is given "
    "only where those results are real: finite, not all zeros, not one constant everywhere, a rotation orthonormal, "
    "a mass matrix positive-definite, a Jacobian of full rank. An answer that does nothing is consistent "
    "with itself and earns nothing: fix {what} first (its own check says how)."
)
DEGENERATE_HINT = (
    "An answer that does nothing (all zeros, one constant everywhere) earns nothing, even with the right shape. If "
    "your code computes it, look for what leaves it constant: an argument, a starting value or a term it never uses."
)


def _as_float(value):
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return None


def _flat(a: np.ndarray) -> bool:
    """True when every entry of ``a`` is the same number (a constant answer, zero included)."""
    return a.size > 1 and bool(np.all(np.abs(a - a.flat[0]) <= ZERO_TOL * max(1.0, float(np.abs(a).max()))))


def _zero(a: np.ndarray) -> bool:
    return bool(np.all(np.abs(a) <= ZERO_TOL))


def flaw(value, shape=None, reference=None) -> str:
    """What keeps ``value`` from being a real result ("" when nothing does): not numeric, another shape (``shape``,
    or the reference's), not finite, all zeros, or one constant in every entry.  With ``reference`` (the reference's
    value of the same quantity), zero and constant count only where the reference's value is not so."""
    a = _as_float(value)
    if a is None or a.dtype.kind not in "fiu":
        return f"is not numeric ({type(value).__name__})"
    ours = None if reference is None else _as_float(reference)
    if shape is None and ours is not None:
        shape = ours.shape
    if shape is not None and a.shape != tuple(shape):
        return f"has shape {a.shape}, not {tuple(shape)}"
    if not np.all(np.isfinite(a)):
        return "has NaN or infinite entries"
    if _zero(a) and (ours is None or not _zero(ours)):
        return "is all zeros"
    if _flat(a) and (ours is None or not _flat(ours)):
        return f"is one constant in every entry ({float(a.flat[0]):.6g})"
    return ""


def rotation_flaw(A, reference=None) -> str:
    """What keeps ``A`` from being a real rotation: ``flaw``, not orthonormal, or the identity where the reference's
    rotation (``reference``) turns.  A reflection (det = -1) of an orthonormal matrix is a wrong rotation, not a
    degenerate one: its own check charges it."""
    found = flaw(A, (3, 3))
    if found:
        return found
    a = np.asarray(A, dtype=float)
    defect = float(np.max(np.abs(a.T @ a - np.eye(3))))
    if defect > STRUCTURE.atol:
        return f"is not orthonormal (max |A.T @ A - E| = {defect:.3g})"
    if reference is not None and close(a, np.eye(3), STRUCTURE) and not close(reference, np.eye(3), STRUCTURE):
        return "is the identity, which does not turn (the reference's rotation does)"
    return ""


def mass_matrix_flaw(M) -> str:
    """What keeps ``M`` from being a real mass matrix: ``flaw`` (square), or not positive-definite (some motion
    without kinetic energy: ``qd.T M qd <= 0``).  Its symmetry is its own check's: a mass matrix made asymmetric by
    one mistake is wrong, not degenerate, and what is built on it is judged on it."""
    a = _as_float(M)
    if a is None or a.ndim != 2 or a.shape[0] != a.shape[1] or a.size == 0:
        return "is not a square numeric matrix"
    found = flaw(a, a.shape)
    if found:
        return found
    scale = max(1.0, float(np.abs(a).max()))
    if float(np.linalg.eigvalsh(0.5 * (a + a.T)).min()) <= 1e-9 * scale:
        return "is not positive-definite (some motion has no kinetic energy)"
    return ""


def _rank(a: np.ndarray) -> int:
    if a.size == 0:
        return 0
    singular = np.linalg.svd(a, compute_uv=False)
    return int(np.sum(singular > RANK_TOL * max(1.0, float(singular.max()))))


def rank_flaw(J, reference) -> str:
    """What keeps the Jacobian ``J`` (a gradient is a 1 x n one) from being real: ``flaw`` with the reference's
    shape, or a lower rank than the reference's Jacobian ``reference`` at the same configuration."""
    ours = np.atleast_2d(np.asarray(reference, dtype=float))
    mine = _as_float(J)
    found = flaw(J if mine is None else np.atleast_2d(mine), ours.shape, ours)
    if found:
        return found
    mine, full = _rank(np.atleast_2d(mine)), _rank(ours)
    if mine < full:
        return f"has rank {mine}, where the reference's has rank {full}"
    return ""


def real(name: str, value, shape=None, reference=None) -> tuple[str, str]:
    """The finding of an array: ``(name, flaw(value, shape, reference))``."""
    return name, flaw(value, shape, reference)


def first_flaw(findings) -> tuple[str, str] | None:
    """The first ``(name, flaw)`` of ``findings`` with a flaw, or None when all are real."""
    return next(((name, found) for name, found in findings if found), None)


def is_real(findings) -> bool:
    return first_flaw(findings) is None


def require_real(subject: str, what: str, findings) -> None:
    """Fail (``degenerate_input``) unless every finding is real: ``subject`` (the student's value, e.g.
    "cardan(0.4, -0.3, 1.1)") is judged on their own ``what`` (e.g. "R1, R2, R3"), and a degenerate one leaves
    nothing to carry forward."""
    found = first_flaw(findings)
    if found is None:
        return
    name, why = found
    fail(f"{subject} cannot be credited on your own {what}: {name} {why}. That input is degenerate, so there is "
         f"nothing to carry forward.", DEGENERATE_INPUT_HINT.format(what=what), DEGENERATE_INPUT)


def assert_real(value, name: str, shape=None, reference=None) -> np.ndarray:
    """``value`` as an array when it is a real result (``flaw``); else a failure (``degenerate``, or the shape's
    and finiteness' own diagnoses through ``as_array`` first)."""
    a = as_array(value, name, shape if shape is not None else (None if reference is None else np.shape(reference)))
    found = flaw(a, a.shape, reference)
    if found:
        fail(f"{name} {found}, where the expected value is not: it earns nothing.\ngot:\n{format_array(a)}",
             DEGENERATE_HINT, DEGENERATE)
    return a
