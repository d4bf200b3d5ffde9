"""The vocabulary of check modules: the ``check`` decorator, the context a check receives, tolerances, and
assertion helpers that fail with a message a student can act on.

A check is a function ``check_<property>(ctx)`` decorated with ``@check(points, stage=...)``.  It returns
nothing when the property holds and raises ``CheckFailure`` (through the helpers below) when it does not.  The
student's code is reached only through ``ctx.student(probe, *args)`` (sandboxed child); the reference through
``ctx.reference(probe, *args)`` (same probe, run in the grader).  Checks never mutate what they receive.
"""

from __future__ import annotations

import math
import threading
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from checks._diagnoses import DIAGNOSES, families_of, student_phrase, unknown_names

from .errors import GraderFault, StudentFault, ends_grading
from .results import Figure, Series
from .values import Tol, format_array

__all__ = [
    "Tol",
    "EXACT",
    "SHEET",
    "SHEET_COARSE",
    "STRUCTURE",
    "STAGE_DEFINED",
    "STAGE_SHAPE",
    "STAGE_STRUCTURE",
    "STAGE_VALUES",
    "STAGE_RANDOM",
    "CheckSpec",
    "check",
    "checks_of",
    "CheckFailure",
    "NotAnswered",
    "known_diagnosis",
    "JudgedOnSubmission",
    "Mistake",
    "diagnose",
    "fail",
    "as_array",
    "assert_close",
    "assert_close_each",
    "confirmed",
    "property_of",
    "assert_rotation",
    "is_rotation",
    "rotation_twins",
    "close",
    "format_array",
    "mismatch_table",
    "figure",
    "SHEET_DIGITS",
    "SHEET_RELATIVE",
    "SHEET_NOTE",
    "random_input",
    "in_random_input",
    "at_sheet_digits",
    "round_to_sheet",
    "engine_on",
    "transposed_shape_hint",
]


# ---------------------------------------------------------------------------------------------- tolerances


#: the same computation as the reference, up to floating-point rounding
EXACT = Tol("exact", 1e-8, 1e-8)
#: numbers printed on the sheet with four decimals
SHEET = Tol("sheet, 4 decimals", 6e-4)
#: numbers printed on the sheet with three or fewer decimals, or read off a figure
SHEET_COARSE = Tol("sheet, 3 decimals", 6e-3)
#: structural properties (orthonormality, symmetry) of a computed matrix
STRUCTURE = Tol("structure", 1e-6)

#: the decimals a failure shows of the expected values of a fixed case (the sheet's precision): the same on every
#: attempt, whatever the student's answer, so that the messages cannot be read for more digits attempt by attempt
SHEET_DIGITS = 4
#: the student kit's key holds the fixed cases at the sheet's precision, four significant digits
#: (``round_to_sheet``); the kit compares with them to ``SHEET_RELATIVE`` of each value and of the size of the
#: values compared
SHEET_SIGNIFICANT = 4
SHEET_RELATIVE = 1e-3
#: what a check that the kit passed on values held at the sheet's digits says
SHEET_NOTE = "matches the sheet's digits; full precision and new cases are graded on submission"

# ---------------------------------------------------------------------------------------------- stages

STAGE_DEFINED = 1  # it runs and returns something
STAGE_SHAPE = 2  # type, shape, finite
STAGE_STRUCTURE = 3  # orthonormal, det = +1, symmetric positive-definite, ...
STAGE_VALUES = 4  # the sheet's numbers
STAGE_RANDOM = 5  # randomized comparison with the reference


# ---------------------------------------------------------------------------------------------- registry


@dataclass(frozen=True)
class CheckSpec:
    func: object
    name: str
    title: str
    points: float
    stage: int
    group: str
    visibility: str
    secret: bool = False


def check(points: float, *, title: str, stage: int = STAGE_VALUES, group: str = "", visibility: str = "visible",
          secret: bool = False):
    """Declare a check.  ``title`` states the property (first line of every message); checks of one ``group``
    run in stage order and stop at the first failing stage.  ``secret`` marks a check whose key must stay with the
    instructor (a multiple-choice key, a predicted output): the student kit records the answer and leaves the
    verdict to the graded submission."""
    if visibility not in ("visible", "hidden"):
        raise ValueError(f"visibility must be 'visible' or 'hidden', not {visibility!r}")

    def decorate(func):
        name = func.__name__.removeprefix("check_")
        func.check_spec = CheckSpec(func, name, title, float(points), stage, group or name, visibility, secret)
        return func

    return decorate


def checks_of(module) -> list[CheckSpec]:
    """The checks of a check module, in definition order."""
    specs = [obj.check_spec for obj in vars(module).values() if hasattr(obj, "check_spec")]
    order = {name: i for i, name in enumerate(vars(module))}
    return sorted(specs, key=lambda s: order[s.func.__name__])


# ---------------------------------------------------------------------------------------------- failures


def known_diagnosis(diagnosis: str) -> str:
    """``diagnosis`` when every name of it is in the vocabulary (``checks._diagnoses``); a name that is not is a
    defect of the checks, refused as the grader's fault (never the student's)."""
    unknown = unknown_names(diagnosis)
    if unknown:
        raise GraderFault(f"the check names a diagnosis that is not in the vocabulary (checks/_diagnoses.py): "
                          f"{', '.join(map(repr, unknown))}")
    return diagnosis


class CheckFailure(Exception):
    """The property does not hold.  ``message`` explains got/expected; ``hint`` names the likely mistake.
    ``candidates``: the known mistakes whose value the student's matched (None when no catalogue was consulted),
    which a randomized comparison narrows down with a second failing input.  ``diagnosis`` is a name of the
    vocabulary (or names joined by " or "): an unknown one is refused as the grader's fault.  ``evidence``: the
    failing comparison (``grader.diagnosis.Evidence``) for the diagnosis engine, which names a cause when no
    catalogued mistake does; ``explained`` once it has been asked."""

    def __init__(self, message: str, hint: str = "", diagnosis: str = "", candidates: tuple | None = None,
                 evidence=None, explained: bool = False):
        known_diagnosis(diagnosis)
        super().__init__(message)
        self.message = message
        self.hint = hint
        self.diagnosis = diagnosis
        self.candidates = candidates
        self.evidence = evidence
        self.explained = explained


class NotAnswered(Exception):
    """A question in answers.toml is still blank."""


class JudgedOnSubmission(Exception):
    """The student kit cannot grade this check: the student's own functions of earlier problems differ from the
    reference's, and the check judges the answer on them through the reference's code, which only a graded
    submission has (``grader.upstream``).  ``message`` names those functions and the checks that grade them."""

    def __init__(self, message: str):
        super().__init__(message)
        self.message = message


def fail(message: str, hint: str = "", diagnosis: str = "", candidates: tuple | None = None, evidence=None):
    """Raise ``CheckFailure``.  Where a check words anew a failure it caught, it passes the caught one's
    ``evidence`` along: without it the diagnosis engine is never asked about the comparison that failed."""
    raise CheckFailure(message, hint, diagnosis, candidates, evidence)


@dataclass(frozen=True)
class Mistake:
    """A known mistake: what a student would get by making it, and what to tell them.  ``name`` is a name of the
    vocabulary (``checks._diagnoses``): an unknown one is refused as the grader's fault."""

    name: str
    value: object
    hint: str

    def __post_init__(self):
        if self.name not in DIAGNOSES:
            raise GraderFault(f"a known mistake is named {self.name!r}, which is not one name of the vocabulary "
                              f"(checks/_diagnoses.py)")


def diagnose(matches) -> tuple[str, str]:
    """``(hint, diagnosis)`` for the known mistakes that match: none, the one that matches, or, when several
    different mistakes give the student's value, all of them ("could be X or Y") rather than the first."""
    unique: dict[str, Mistake] = {}
    for mistake in matches:
        unique.setdefault(mistake.name, mistake)
    if not unique:
        return "", ""
    if len(unique) == 1:
        mistake = next(iter(unique.values()))
        return mistake.hint, mistake.name
    names = list(unique)
    hint = (f"{len(names)} known mistakes give exactly your value here, so it could be "
            f"{' or '.join(student_phrase(n) for n in names)}:\n"
            + "\n".join(f"- {m.hint}" for m in unique.values()))
    return hint, " or ".join(names)


# ---------------------------------------------------------------------------------------------- formatting


_COMPARING = threading.local()


@contextmanager
def random_input():
    """While comparisons run on a randomized input (``Context.compare_random``): a failure may show as many decimals
    as its difference needs, since the next grading asks other inputs.  Outside, every comparison is of a fixed
    case, and its failure shows the expected values at ``SHEET_DIGITS`` and no difference finer than that."""
    before = getattr(_COMPARING, "random", False)
    _COMPARING.random = True
    try:
        yield
    finally:
        _COMPARING.random = before


def in_random_input() -> bool:
    """True while comparisons run on a randomized input (see ``random_input``)."""
    return getattr(_COMPARING, "random", False)


def _fixed_case() -> bool:
    return not in_random_input()


def at_sheet_digits(on: bool = True) -> None:
    """In the student kit, from the moment a check used a value its key holds at the sheet's digits until the next
    check begins: every comparison of the check allows ``SHEET_RELATIVE`` of the expected value's size."""
    _COMPARING.sheet = on


def _sheet() -> bool:
    return getattr(_COMPARING, "sheet", False)


def round_to_sheet(x: float) -> float:
    """``x`` at the sheet's precision: ``SHEET_SIGNIFICANT`` significant digits."""
    if not math.isfinite(x) or x == 0:
        return x
    return round(x, SHEET_SIGNIFICANT - 1 - int(math.floor(math.log10(abs(x)))))


def _digits(got, expected, tol: Tol) -> int:
    """Enough decimals for the smallest difference outside the tolerance to be visible (4 at least, 10 at most)."""
    diffs = np.abs(got - expected)[~_within(got, expected, tol)]
    smallest = float(diffs[diffs > 0].min()) if np.any(diffs > 0) else 1.0
    return int(min(10, max(4, np.ceil(-np.log10(smallest)) + 1)))


def mismatch_table(got, expected, tol: Tol, digits: int | None = None, differences: bool = True) -> str:
    """Side-by-side table of the entries, marking those outside the tolerance (with ``differences``, their
    differences too: not for a fixed case, where they would tell the expected value to more digits)."""
    got = np.atleast_1d(np.asarray(got, dtype=float))
    expected = np.atleast_1d(np.asarray(expected, dtype=float))
    bad = ~_within(got, expected, tol)
    if digits is None:
        digits = _digits(got, expected, tol)
    rows = ["  index        got          expected" + ("     |diff|" if differences else "")]
    for index in np.ndindex(expected.shape):
        mark = "  ✘" if bad[index] else ""
        label = ",".join(str(i) for i in index)
        g, e = got[index], expected[index]
        diff = f"  {abs(g - e):>9.2e}" if differences else ""
        rows.append(f"  [{label:>5}]  {g:>+11.{digits}f}  {e:>+11.{digits}f}{diff}{mark}")
    if len(rows) > 40:
        shown = [rows[0]] + [r for r in rows[1:] if r.endswith("✘")][:30]
        rows = shown + [f"  ... {int(bad.sum())} of {bad.size} entries outside the tolerance"]
    return "\n".join(rows)


# ---------------------------------------------------------------------------------------------- helpers


def _within(got, expected, tol: Tol):
    atol, rtol = tol.atol, tol.rtol
    if _sheet():  # the kit's value of a fixed case holds the sheet's digits only
        scale = float(np.max(np.abs(expected))) if np.size(expected) else 0.0
        atol, rtol = max(atol, SHEET_RELATIVE * scale), max(rtol, SHEET_RELATIVE)
    return np.abs(got - expected) <= atol + rtol * np.abs(expected)


def _tolerance(tol: Tol) -> str:
    return (f"{tol}, at the sheet's digits in the student kit ({SHEET_RELATIVE:g} of the values' size)"
            if _sheet() else str(tol))


def _compared(expected, tol, got=None) -> None:
    """While the student kit's answer key is recorded, each comparison makes the reference calls the diagnosis
    engine may need (``grader.diagnosis.recording``)."""
    from .diagnosis import RECORDING, note_comparison

    ctx = getattr(RECORDING, "ctx", None)
    if ctx is not None:
        note_comparison(ctx, expected, tol, got)


def close(got, expected, tol: Tol) -> bool:
    """True when ``got`` has the shape of ``expected`` and matches it entrywise within ``tol``."""
    _compared(expected, tol, got)
    try:
        got = np.asarray(got, dtype=float)
        expected = np.asarray(expected, dtype=float)
    except (TypeError, ValueError):
        return False
    return got.shape == expected.shape and bool(np.all(np.isfinite(got))) and bool(np.all(_within(got, expected, tol)))


def as_array(value, name: str, shape: tuple | None = None) -> np.ndarray:
    """``value`` as a finite float array of the given shape, or a failure that says what is wrong."""
    if value is None:
        fail(f"{name} is None: the function returned nothing.", "Did you forget a return statement?", "none")
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        fail(f"{name} must be numeric, got a value of type {type(value).__name__}: {str(value)[:200]}")
    if shape is not None and array.shape != tuple(shape):
        if len(shape) == 2 and shape[0] != shape[1] and array.shape == tuple(shape)[::-1] and engine_on():
            fail(f"{name} must have shape {tuple(shape)}, got shape {array.shape}: the transposed shape.",
                 transposed_shape_hint(shape), "transpose")
        if array.size == int(np.prod(shape)):
            fail(
                f"{name} must have shape {tuple(shape)}, got shape {array.shape}.",
                f"Reshape it, e.g. np.reshape(x, {tuple(shape)}).",
                "shape",
            )
        fail(f"{name} must have shape {tuple(shape)}, got shape {array.shape}.", diagnosis="shape")
    if not np.all(np.isfinite(array)):
        fail(f"{name} contains NaN or infinite entries:\n{format_array(array)}", diagnosis="not_finite")
    return array


def assert_close(got, expected, name: str, tol: Tol, mistakes=(), context: str = "", note: str = ""):
    """Fail unless ``got`` matches ``expected`` within ``tol``; name the known mistake that matches (every one
    that matches, when several do).  The failure carries the comparison as evidence for the diagnosis engine,
    which names a cause when no known mistake matches."""
    raw_got, raw_expected = got, expected
    _compared(raw_expected, tol, raw_got)
    expected = np.asarray(expected, dtype=float)
    _transposed(got, expected, name, tol)
    got = as_array(got, name, expected.shape)
    if close(got, expected, tol):
        return got
    where = f" {context}" if context else ""
    lines = [f"{name} is not the expected value{where}.", f"tolerance: {_tolerance(tol)}"]
    if note:
        lines.append(note)
    fixed = _fixed_case()
    digits = SHEET_DIGITS if fixed else _digits(got, expected, tol)
    lines += ["got:", format_array(got, digits), "expected:", format_array(expected, digits),
              mismatch_table(got, expected, tol, digits, differences=not fixed)]
    if fixed:
        lines.append(f"(the values are shown to {SHEET_DIGITS} decimals, the sheet's precision; they are compared "
                     "with the tolerance above)")
    mistakes = list(mistakes or ())
    matches = rotation_twins(got, expected, tol,
                             tuple(mistake for mistake in mistakes if _matches(got, mistake, tol)))
    hint, diagnosis = diagnose(matches)
    from .diagnosis import Evidence

    raise CheckFailure("\n".join(lines), hint, diagnosis, matches if mistakes else None,
                       Evidence(got, expected, tol, name, raw_got, raw_expected))


def assert_close_each(cases) -> None:
    """Compare the ``cases`` of one check, each ``(got, expected, name, tol, mistakes, context)`` as ``assert_close``
    takes them, and fail at the first that does not match.  A known mistake is named only where it reproduces the
    student's answer on every case compared, not on the first alone (a slip that a special input, such as the
    sheet's, makes give the student's value by chance): on each later case that fails, a mistake of that name
    must match again, and on each that passes, the mistake of that name, where the case lists one, must give the
    expected value too.  Where no known mistake holds on every case, the failure names none (and the diagnosis
    engine may)."""
    first, results = None, []
    for got, expected, name, tol, mistakes, context in cases:
        try:
            assert_close(got, expected, name, tol, mistakes, context=context)
        except CheckFailure as exc:
            first = exc if first is None else first
            results.append((exc, list(mistakes or ()), expected, tol))
        else:
            results.append((None, list(mistakes or ()), expected, tol))
    if first is None:
        return
    kept = tuple(mistake for mistake in first.candidates or () if all(
        _holds(mistake.name, failure, mistakes, expected, tol) for failure, mistakes, expected, tol in results))
    if first.candidates is None or len(kept) == len(first.candidates):
        raise first
    hint, diagnosis = diagnose(kept)
    raise CheckFailure(first.message, hint, diagnosis, kept, first.evidence)


def confirmed(compare, again) -> None:
    """``compare(True)``, a comparison of the input shown with its catalogue of known mistakes; where it fails
    naming one, ``again()`` makes the same comparison, with that input's catalogue, on a second input the check
    chooses, and a known mistake is named only where one of its name reproduces the student's value there as well:
    a mistake that reproduces the value on one input may do so by that input's chance (a body's position in its
    own frame that equals its inertial position at the sheet's angles), which a second input does not repeat.
    Where the second input fails another property (the first line of its message, numbers aside), passes, or the
    student's code raises on it, no name holds, and ``compare(False)`` (the comparison without its catalogue) gives
    the failure, unnamed, for the diagnosis engine; a time-out or a crash there stops the grading, as anywhere."""
    try:
        compare(True)
    except CheckFailure as shown:
        if not shown.diagnosis or not shown.candidates:
            raise
        names: set = set()
        try:
            again()
        except CheckFailure as other:
            if property_of(other) == property_of(shown):
                names = {mistake.name for mistake in other.candidates or ()}
        except StudentFault as exc:
            if ends_grading(exc):
                raise  # as everywhere: the grading of the submission stops there
        kept = tuple(mistake for mistake in shown.candidates if mistake.name in names)
        if len(kept) == len(shown.candidates):
            raise
        if not kept:
            compare(False)
            raise  # the comparison without its catalogue passed: the failure shown stands as it was
        hint, diagnosis = diagnose(kept)
        raise CheckFailure(shown.message, hint, diagnosis, kept, shown.evidence) from None


def property_of(failure: CheckFailure) -> str:
    """What a failure is about: the first line of its message without the numbers and spaces in it (a comparison's
    name often shows its input, as in ``walker_ode at y = [...]``)."""
    import re

    return "".join(re.sub(r"[-+]?\d+(\.\d*)?([eE][-+]?\d+)?", "#", failure.message.partition("\n")[0]).split())


def _holds(name: str, failure, mistakes: list, expected, tol: Tol) -> bool:
    """A known mistake named ``name`` is consistent with one case: it matches the student's value where the case
    failed, and gives the expected value where the case passed (or the case lists no mistake of that name)."""
    if failure is not None:
        return any(m.name == name for m in failure.candidates or ())
    return all(_matches(np.asarray(expected, dtype=float), m, tol) for m in mistakes if m.name == name)


def engine_on() -> bool:
    """Whether the diagnosis engine's grammar is used (a transposed shape is one of its slips)."""
    from . import diagnosis

    return diagnosis.ENABLED


def transposed_shape_hint(shape) -> str:
    """The hint for an array of the transposed shape of the ``rows x columns`` one asked for (``shape``)."""
    rows, columns = shape
    return (f"Your {columns} x {rows} array looks like the transpose of the {rows} x {columns} one asked for: swap "
            "its rows and columns (build it the other way round, or return its .T).")


def _transposed(got, expected, name: str, tol: Tol) -> None:
    """Fail with ``transpose`` when ``got`` has the transposed shape of a non-square ``expected`` and is its
    transpose: the cause of the wrong shape, not only the shape."""
    if expected.ndim != 2 or expected.shape[0] == expected.shape[1] or not engine_on():
        return
    try:
        array = np.asarray(got, dtype=float)
    except (TypeError, ValueError):
        return
    if array.shape == expected.shape[::-1] and close(array.T, expected, tol):
        fail(f"{name} must have shape {expected.shape}, got shape {array.shape}: it is the transpose of the expected "
             f"value.\ngot:\n{format_array(array)}\nexpected:\n{format_array(expected)}",
             f"Your {array.shape[0]} x {array.shape[1]} array is the transpose of the expected {expected.shape[0]} x "
             f"{expected.shape[1]} one: swap its rows and columns (build it the other way round, or return its .T).",
             "transpose")


#: what is told beside a known mistake of one family where the answer is a rotation's transpose (``rotation_twins``)
TWIN_HINTS = {
    "angle_sign": "A rotation's transpose is the rotation by the negated angle (R(a).T == R(-a)): your matrix is "
                  "the expected one turned the other way.",
    "transpose": "A rotation by the negated angle is the transposed rotation (R(-a) == R(a).T): your matrix is the "
                 "transpose of the expected one.",
}


def rotation_twins(got, expected, tol: Tol, matches: tuple) -> tuple:
    """The known mistakes that match, with the twin a rotation cannot tell apart: where the expected value is a
    proper rotation and the student's is its transpose, that is also the rotation by the negated angle, so a
    catalogue's ``transpose`` is told with ``angle_sign`` and a sign slip with ``transpose`` ("could be X or Y"):
    the answer shows both alike, and naming one would pick a family it does not show."""
    if not matches:
        return matches
    try:
        answer, turn = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    except (TypeError, ValueError):
        return matches
    if answer.shape != (3, 3) or not is_rotation(turn) or close(turn, turn.T, tol):
        return matches
    if not close(answer, turn.T, tol):
        return matches
    families = {family for mistake in matches for family in families_of(mistake.name)}
    twins = [Mistake(name, turn.T, TWIN_HINTS[name]) for name, family, other in
             (("angle_sign", "sign", "transpose"), ("transpose", "transpose", "sign"))
             if other in families and family not in families]
    return matches + tuple(twins)


def is_rotation(A: np.ndarray) -> bool:
    """True when the array ``A`` is a proper rotation: 3 x 3, orthonormal to ``STRUCTURE`` and of determinant +1."""
    return bool(A.shape == (3, 3) and close(A.T @ A, np.eye(3), STRUCTURE) and abs(np.linalg.det(A) - 1.0) < 1e-6)


def _matches(got, mistake: Mistake, tol: Tol) -> bool:
    try:
        return close(got, mistake.value, tol)
    except Exception:  # noqa: BLE001 - a candidate that cannot be compared simply does not match
        return False


def assert_rotation(A, name: str, tol: Tol = STRUCTURE):
    """Fail unless ``A`` is a proper rotation: orthonormal and with determinant +1."""
    A = as_array(A, name, (3, 3))
    defect = float(np.max(np.abs(A.T @ A - np.eye(3))))
    if defect > tol.atol:
        fail(
            f"{name} is not orthonormal: max |A.T @ A - E| = {defect:.3g} > {tol.atol:g}.\n"
            f"got:\n{format_array(A)}\nA.T @ A =\n{format_array(A.T @ A)}",
            "A rotation matrix keeps lengths and angles: its columns are orthogonal unit vectors. "
            "Check the entries (sin/cos swapped? a missing or extra term?).",
            "not_orthonormal",
        )
    det = float(np.linalg.det(A))
    if abs(det - 1.0) > 10 * tol.atol:
        fail(
            f"{name} is a reflection, not a rotation: det = {det:+.6f} (a rotation has det = +1).\n"
            f"got:\n{format_array(A)}",
            "One axis points the wrong way, or two axes are in each other's place: check the signs of the sin "
            "terms and the order of the rows and columns (either turns a rotation into a reflection).",
            "reflection",
        )
    return A


def figure(title: str, xlabel: str, ylabel: str, student, reference, equal_axes: bool = False) -> Figure:
    """A figure with the student's curves over the reference's; each of ``student`` and ``reference`` is a
    list of ``(label, x, y)``."""
    series = [Series(f"yours: {label}", tuple(map(float, x)), tuple(map(float, y)), "student")
              for label, x, y in student]
    series += [Series(f"reference: {label}", tuple(map(float, x)), tuple(map(float, y)), "reference")
               for label, x, y in reference]
    return Figure(title, xlabel, ylabel, tuple(series), equal_axes)

