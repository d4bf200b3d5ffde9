"""The engine's second input by a problem's constants drawn anew: a function that reads its module's named constants
(the sheet's angles, lengths, masses, a point's coordinates) rather than taking them as arguments has nothing to
draw, so the engine runs the same call on the reference and on the student's package with those constants bound to
drawn values for its duration (``probes._rebound``).  A probe declares the constants its functions read
(``rebind``); the values are drawn near the sheet's (a factor in ``FACTORS``, away from the special angles), each
number its own (each of a row's numbers but its zeros).  A student who typed the numbers in rather than reading the
constants gives the same value there: no slip of a formula reproduces that, so nothing is told of it.  The student
kit's key holds none of these calls: a call that reads the module's constants is one of the sheet's fixed cases,
which the key holds at the sheet's digits only, and the engine names nothing there (``engine._at_sheet_digits``)."""

from __future__ import annotations

import numpy as np

from probes import ProbeLookupError, lookup

from ..errors import GraderFault
from . import trace
from .evidence import array_of, at, distinct, Evidence, Source
from .scene import evidence_at

__all__ = ["REBOUND", "CONSTANTS", "rebinding", "rebound_input", "rebound_with", "rebound_drawn"]

#: the probe that runs another one with constants bound (``probes._rebound``), and the one of the sheet's values
REBOUND = "_rebound.rebound"
CONSTANTS = "_rebound.constants"
#: the range of the factor on a constant's sheet value, and the least change a factor makes
FACTORS = (0.6, 1.4)
LEAST_CHANGE = 0.1
#: a drawn value this near a multiple of 15 degrees [rad] is drawn again (a special angle makes sines and cosines
#: coincide, and a slip with them), as is one this near another constant's drawn value (relative)
SPECIAL = np.deg2rad(3.0)
APART = 0.05
#: the draws of the constants before the engine gives up (a degenerate value, or one that does not change)
ATTEMPTS = 3


def rebinding(probe) -> tuple | None:
    """``(module, names)`` of the constants the probe declares its functions read (``rebind``), or None."""
    if not isinstance(probe, str):
        return None
    try:
        declared = getattr(lookup(probe), "declared", None) or {}
    except ProbeLookupError:
        return None
    found = declared.get("rebind")
    if not found:
        return None
    return str(found["module"]), tuple(found["names"])


def _special(value: float) -> bool:
    step = np.pi / 12
    return abs(value) < 4 * np.pi and abs(value - step * round(value / step)) < SPECIAL


def _value(rng, sheet: float, taken: list) -> float:
    """A value near ``sheet``: a factor of ``FACTORS`` that changes it, away from the special angles and from the
    values drawn before (the last try is kept where none is)."""
    value = sheet
    for _ in range(32):
        factor = rng.uniform(*FACTORS)
        if abs(factor - 1.0) < LEAST_CHANGE:
            continue
        value = sheet * factor
        if not _special(value) and all(abs(value - other) > APART * abs(other) for other in taken):
            break
    return float(value)


def _bindings(scene, probe: str, seed, attempt: int) -> list | None:
    """The ``attempt``-th draw of the constants ``probe`` declares (``[[module, name, value], ...]``, a row's
    value a list: each of its numbers drawn, a zero kept), or None: none declared, or none of them a number other
    than zero."""
    declared = rebinding(probe)
    if declared is None:
        return None
    module, names = declared
    sheet = scene.reference(CONSTANTS, (module, list(names)))
    rng = np.random.default_rng([*seed, 0x7EB0, attempt])
    bindings, taken = [], []
    for name in names:
        value = sheet.get(name) if isinstance(sheet, dict) else None
        row = np.asarray(value, dtype=float) if value is not None else None
        if row is None or row.ndim > 1 or not np.all(np.isfinite(row)) or not np.any(row):
            continue
        drawn = []
        for number in row.ravel():
            drawn.append(0.0 if number == 0.0 else _value(rng, float(number), taken))
            if number != 0.0:
                taken.append(drawn[-1])
        bindings.append([module, name, drawn if row.ndim else drawn[0]])
    return bindings or None


def rebound_with(scene, evidence: Evidence, args, root, plain: Evidence | None) -> Evidence | None:
    """The same comparison at the arguments the engine drew (``args``, where the reference's answer is ``root``)
    with the constants the probe declares drawn anew as well (the formula tier's third input), or None (none
    declared, or no draw usable: the value does not change with them).  Constants related on the sheet stay so at
    every draw of the arguments alone (problem 25's leg is twice its foot's radius, so a sum without the leg's length
    gives what one with the two terms' signs turned does): drawn as well, such a coincidence no longer reproduces
    the student's value.  A student who typed the sheet's numbers rather than reading the constants gives at the
    constants drawn what they give at the arguments alone (``plain``, that comparison): no slip of a formula
    reproduces that, so their input stays ``plain`` (None here), where a slip of theirs can still be named."""
    source, student = evidence.source, evidence.student
    if rebinding(source.probe) is None or plain is None:
        return None
    drawn_source = Source(source.probe, tuple(args), source.path, root)
    value = array_of(at(root, source.path))
    if value is None:
        return None
    drawn = rebound_drawn(scene, drawn_source, value, evidence.tol)
    if drawn is None:
        return None
    rebound = _at_constants(scene, evidence, drawn, (source.probe, list(args)), (student.probe, list(args)),
                            drawn=True)
    if rebound is not None and not distinct(rebound.got, plain.got, evidence.tol):
        trace.note("rebound", reason="the student's value does not change with the constants")
        return None
    return rebound


def _inner(source: Source) -> tuple[str, list, int]:
    """``(probe, args, round)`` of a call: a call already at constants drawn is drawn again at the next round."""
    if source.probe == REBOUND:
        probe, _, args = source.args
        return probe, list(args), ATTEMPTS
    return source.probe, list(source.args), 0


def _scaled(value: np.ndarray, expected: np.ndarray, tol) -> bool:
    """The value at the constants drawn is the shown one times a number (a length drawn anew scales every position
    it sets): such an input confirms any slip that scales the value, whatever its cause, and tells nothing."""
    norm = float(np.vdot(expected, expected))
    if norm == 0.0:
        return False
    factor = float(np.vdot(expected, value)) / norm
    return not distinct(value, factor * expected, tol)


def rebound_drawn(scene, source: Source, expected: np.ndarray, tol):
    """``(bindings, root)``: the first draw of the constants of ``source``'s probe at which the reference's value at
    ``source.path`` is usable (of the same shape, not zeros where ``expected`` has none, changed, and not merely
    scaled: ``_scaled``), or None.  A call the reference cannot answer is no draw."""
    probe, args, first = _inner(source)
    if rebinding(probe) is None:
        return None
    try:
        seed = scene.draw_seed(Source(probe, tuple(args), source.path))
        for attempt in range(first, first + ATTEMPTS):
            bindings = _bindings(scene, probe, seed, attempt)
            if bindings is None:
                return None
            root = scene.reference(REBOUND, (probe, bindings, args))
            value = array_of(at(root, source.path))
            if value is None or value.shape != expected.shape:
                return None
            zeros = np.zeros_like(value)
            if not distinct(value, zeros, tol) and distinct(expected, zeros, tol):
                continue
            if not distinct(value, expected, tol):
                trace.note("rebound", reason="the value does not change with the constants")
                return None
            if _scaled(value, expected, tol):
                trace.note("rebound", reason="the value only scales with the constants")
                return None
            return bindings, root
    except GraderFault:
        trace.note("rebound", reason="the reference cannot answer")
        return None
    trace.note("rebound", reason="no usable draw")
    return None


def rebound_input(scene, evidence: Evidence) -> Evidence | None:
    """The same comparison with the problem's constants drawn anew (``rebound_drawn``), where the probes of both
    sides declare the same module's constants: the student's value there and the reference's, or None."""
    source, student = evidence.source, evidence.student
    if source is None or student is None or evidence.motion:
        return None
    probe, args, _ = _inner(source)
    student_probe, student_args, _ = _inner(student)
    declared, theirs = rebinding(probe), rebinding(student_probe)
    if declared is None or theirs is None or declared[0] != theirs[0]:
        return None
    drawn = rebound_drawn(scene, source, evidence.expected, evidence.tol)
    if drawn is None:
        return None
    return _at_constants(scene, evidence, drawn, (probe, args), (student_probe, student_args))


def _at_constants(scene, evidence: Evidence, draw: tuple, call: tuple, student_call: tuple, **noted):
    """The comparison of ``evidence`` at the constants drawn (``draw``: ``(bindings, root)``, ``rebound_drawn``'s),
    of the reference's ``call`` and the student's ``student_call`` (each ``(probe, args)``), the draw traced with
    ``noted``."""
    bindings, expected_root = draw
    trace.note("rebound", bindings=[[name, np.round(number, 6).tolist()] for _, name, number in bindings], **noted)
    return evidence_at(scene, evidence, Source(REBOUND, (call[0], bindings, call[1]), evidence.source.path,
                                               expected_root),
                       (REBOUND, (student_call[0], bindings, student_call[1])), "rebound")

