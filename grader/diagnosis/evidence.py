"""What the diagnosis engine works on: the declarations of probes (``probes.probe(...)``), the evidence of a
failing comparison and the calls its values came from (``locate``), the hypotheses it tries and what it finds."""

from __future__ import annotations

import inspect
from dataclasses import dataclass, field, replace

import numpy as np

from probes import lookup, ProbeLookupError

from ..values import Tol

__all__ = [
    "DISTINCT",
    "call_key",
    "text_key",
    "Declaration",
    "DECLARATIONS",
    "SHORTCUTS",
    "part_of",
    "rows_of",
    "declaration",
    "stepped",
    "Source",
    "Evidence",
    "Finding",
    "Hypothesis",
    "walk",
    "equal",
    "locate",
    "counterpart",
    "evaluated",
    "at_point",
    "sibling",
    "at",
    "array_of",
    "within",
    "REPRODUCED_RTOL",
    "reproduces",
    "distinct",
    "ONE_INPUT_NUMBERS",
    "numbers_told",
]


#: a hypothesis counts as another answer when it differs from the expected value by this many times the tolerance
#: (on one input at least); below that it is the expected value up to rounding
DISTINCT = 10.0


@dataclass(frozen=True)
class Declaration:
    """What a probe declares for the engine (``probes.probe(...)``'s keywords), with the probe's argument names."""

    args: tuple = ()
    names: tuple = ()
    terms: str = ""
    rotation: object = None
    motion: dict = field(default_factory=dict)
    constants: str = ""
    draw: bool = True


DECLARATIONS: dict[str, Declaration | None] = {}
#: the declarations that only say how a value is computed more cheaply (``part_of``) or which module constants its
#: functions read (``rebind``): a probe that declares nothing else declares nothing to the engine's tiers
SHORTCUTS = frozenset({"part", "rebind", "rows"})


def declaration(probe: str) -> Declaration | None:
    """The declaration of a probe (``"problem_06.cardan"``), or None when it declares nothing.  A probe given by
    its function rather than its name (a test's own probe, held by the gate to its form) is none of the engine's."""
    if not isinstance(probe, str):
        return None
    if probe in DECLARATIONS:
        return DECLARATIONS[probe]
    try:
        func = lookup(probe)
    except ProbeLookupError:
        DECLARATIONS[probe] = None
        return None
    declared = {key: value for key, value in (getattr(func, "declared", None) or {}).items() if key not in SHORTCUTS}
    if not declared:
        DECLARATIONS[probe] = None
        return None
    names = tuple(list(inspect.signature(func).parameters)[1:])
    found = Declaration(
        args=tuple(declared.get("args", ())),
        names=names,
        terms=declared.get("terms", ""),
        rotation=declared.get("rotation"),
        motion=dict(declared.get("motion", {})),
        constants=declared.get("constants", ""),
        draw=bool(declared.get("draw", True)),
    )
    DECLARATIONS[probe] = found
    return found


def stepped(decl: Declaration | None) -> bool:
    """A run counted in steps (``"time": "step"``): the student's own step function called again and again, with no
    solver between it and the states, so that a slip inside it gives the run exactly, as a formula's slip gives a
    value; the formula tier tries its slips on the run's states."""
    return decl is not None and bool(decl.motion) and decl.motion.get("time") == "step"


def part_of(source) -> tuple | None:
    """``(probe, args)`` of the cheaper call whose result holds ``source``'s value at the same path (its probe's
    declared ``part``, ``probes.probe``), or None.  The probe may be given by its function (a test's own)."""
    try:
        func = source.probe if callable(source.probe) else lookup(source.probe)
        part = (getattr(func, "declared", None) or {}).get("part")
        if not part or not source.path or source.path[0] not in part["keys"]:
            return None
        return part["probe"], tuple(source.args[k] for k in part["args"])
    except (ProbeLookupError, AttributeError, LookupError, TypeError, ValueError):
        return None


#: the rows of a batch that a comparison of the whole result is first measured on (``rows_of``)
ROWS_SCREENED = 3


def rows_of(evidence) -> tuple | None:
    """``(evidence, (probe, args))`` of the same comparison on fewer rows of a batch, or None: where the probe
    declares ``rows`` (the index of its argument whose rows give its result's rows one each: problem 32's torques
    along 209 points of a trajectory), the rows of the whole result that differ (the first, the last and one
    between) or the one row a comparison reads, with the argument cut to them.  A value that is not the student's
    there is not the student's on the whole batch, and costs a few rows' work to refute."""
    source = evidence.source
    try:
        func = source.probe if callable(source.probe) else lookup(source.probe)
        index = (getattr(func, "declared", None) or {}).get("rows")
        if index is None:
            return None
        batch = source.args[index]
        count = len(batch)
    except (ProbeLookupError, AttributeError, LookupError, TypeError, ValueError):
        return None
    got, expected = evidence.got, evidence.expected
    if not source.path:
        if got.ndim < 1 or got.shape != expected.shape or got.shape[0] != count or count <= ROWS_SCREENED:
            return None
        differ = [k for k in range(count) if not within(got[k], expected[k], evidence.tol)]
        if not differ:
            return None
        pick = sorted({differ[0], differ[len(differ) // 2], differ[-1]})
        got, expected, path = got[pick], expected[pick], ()
    elif isinstance(source.path[0], int) and 0 <= source.path[0] < count and count > 1:
        pick, path = [source.path[0]], (0,) + tuple(source.path[1:])
    else:
        return None
    cut = np.asarray(batch)[pick] if isinstance(batch, np.ndarray) else [batch[k] for k in pick]
    args = tuple(cut if k == index else a for k, a in enumerate(source.args))
    screen = replace(evidence, got=got, expected=expected, source=replace(source, args=args, path=path))
    return screen, (source.probe, args)


@dataclass(frozen=True)
class Source:
    """Where a compared value came from: the probe, its arguments and the path into its result."""

    probe: str
    args: tuple
    path: tuple
    root: object = None  # the probe's whole result


@dataclass
class Evidence:
    """One failing comparison: the student's value, the expected one, the tolerance, and the very objects the check
    compared (to find the calls they came from)."""

    got: np.ndarray
    expected: np.ndarray
    tol: Tol
    name: str
    raw_got: object = None
    raw_expected: object = None
    source: Source | None = None
    student: Source | None = None
    #: a run compared by a check's own code, declared there (``{"time": ..., "states": (...)}``, with ``source`` and
    #: ``student`` holding the two runs): the check's traces of a MuJoCo model and of the reference's ODE, say
    motion: dict | None = None
    #: ``(probe, args, got, expected)``: the call whose results a randomized comparison's own ``compare`` judged
    #: (by a property of the student's result, say), when the values compared were derived from them
    call: tuple | None = None
    #: a value typed into answers.toml compared with its key (``typed_slips``): no call stands behind either side,
    #: and the one input there is tells a slip only where the answer holds many numbers
    typed: bool = False
    #: the call has no arguments to draw, or its value does not change with them (a tree built from a module's
    #: constants), or it is a run of the student's own steps: the one input shown is all there is, and the formula
    #: tier tries its slips there, with the call's other values
    alone: bool = False


@dataclass(frozen=True)
class Finding:
    """The engine's answer: the names it keeps (one, or several at the simplest level) and the hint."""

    names: tuple
    hint: str

    @property
    def diagnosis(self) -> str:
        return " or ".join(self.names)


@dataclass(frozen=True)
class Hypothesis:
    key: str  # the same slip on every input (e.g. "sign:row:1")
    name: str  # its diagnosis
    cost: int  # simplicity: 1 simplest
    detail: str  # what it is, for the hint
    twin: bool = False  # the same value as another hypothesis by mathematics (``grammar.EQUIVALENCES``)


def call_key(probe: str, args: tuple) -> str:
    """A key of a probe call, the engine's own (the calls its scene has asked, the calls it has prepared, the runs it
    keeps): the probe's name and a digest of its arguments as plain data, where two arguments are the same exactly
    where ``text_key`` writes them alike (arrays by their shape and entries as floats, lists and tuples alike, a
    dict's entries by their keys as text, ``1`` and ``1.0`` apart), without writing their numbers as text."""
    import hashlib

    parts: list = []
    try:
        _fed(list(args), parts, 0)
    except _Unkeyed:
        return "j" + text_key(probe, args)
    return "h" + probe + hashlib.blake2b(b"".join(parts), digest_size=16).hexdigest()


def text_key(probe: str, args: tuple) -> str:
    """A stable text key of a probe call, the oracle's (``probes.call_key``: the probe's name and its arguments as
    plain data, JSON), which names a draw site of the engine's (``Scene.draw_seed``) in the grading and in the
    student kit alike."""
    import probes

    return probes.call_key(probe, args)


class _Unkeyed(Exception):
    """An argument that ``call_key`` does not digest itself (``text_key`` writes it)."""


#: ``probes._codec``'s bound of integers kept as they are (larger ones are written as floats)
_EXACT = 2**53


def _fed(value, parts: list, depth: int) -> None:
    """The bytes of ``value`` for ``call_key``, appended to ``parts``, each tagged with its kind."""
    if depth > 20:
        raise _Unkeyed
    if isinstance(value, np.generic):
        value = value.item()
    kind = type(value)
    if kind is np.ndarray:
        if value.dtype.kind not in "biuf":
            raise _Unkeyed
        parts += [b"a", repr(value.shape).encode(), np.ascontiguousarray(value, dtype=float).tobytes()]
    elif kind is bool or value is None:
        parts.append(b"b" + repr(value).encode())
    elif isinstance(value, int) and abs(value) < _EXACT:  # a bool was told above
        parts.append(b"i" + repr(int(value)).encode() + b";")
    elif isinstance(value, (int, float)):
        parts.append(b"f" + np.float64(value).tobytes())
    elif isinstance(value, str):
        text = value.encode("utf-8", "surrogatepass")
        parts.append(b"s" + repr(len(text)).encode() + b":" + text)
    elif isinstance(value, (list, tuple)):
        parts.append(b"[" + repr(len(value)).encode() + b":")
        for item in value:
            _fed(item, parts, depth + 1)
    elif isinstance(value, dict):
        merged = {}  # keys as text, and of two keys alike as text the later entry, as the codec writes a dict
        for k, item in value.items():
            merged[str(k)] = item
        items = sorted(merged.items(), key=lambda entry: entry[0])
        parts.append(b"{" + repr(len(items)).encode() + b":")
        for k, item in items:
            _fed(k, parts, depth + 1)
            _fed(item, parts, depth + 1)
    else:
        raise _Unkeyed


def walk(value, path=(), depth=0):
    """``(path, sub-value)`` of a probe's result, depth first (dicts, lists, tuples)."""
    yield path, value
    if depth >= 6:
        return
    if isinstance(value, dict):
        for key, item in value.items():
            yield from walk(item, (*path, key), depth + 1)
    elif isinstance(value, (list, tuple)) and len(value) <= 64:
        for index, item in enumerate(value):
            yield from walk(item, (*path, index), depth + 1)


def equal(a, b) -> bool:
    try:
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    except (TypeError, ValueError):
        return False
    return a.shape == b.shape and a.size > 0 and bool(np.array_equal(a, b))


def locate(log, raw, side: str, tol: Tol | None = None) -> Source | None:
    """The call of ``log`` (``(side, probe, args, value)``, most recent last) whose result holds ``raw``: by
    identity first, else by equal value, else (with ``tol``: a printed number of the sheet, say) by a value within
    the tolerance, each only when one path of one call has it."""
    if raw is None:
        return None
    calls = [entry for entry in reversed(log) if entry[0] == side]
    for _, probe, args, value in calls:
        for path, item in walk(value):
            if item is raw:
                return Source(probe, tuple(args), path, value)
    found = []
    for _, probe, args, value in calls:
        for path, item in walk(value):
            if not isinstance(item, (dict, str)) and equal(item, raw):
                found.append(Source(probe, tuple(args), path, value))
    if _sole(found):
        return found[0]
    target = array_of(raw)
    if tol is None or found or target is None or target.size == 0:
        return None
    near = []
    for _, probe, args, value in calls:
        for path, item in walk(value):
            if isinstance(item, (dict, str)):
                continue
            candidate = array_of(item)
            if candidate is not None and candidate.shape == target.shape and within(candidate, target, tol):
                near.append(Source(probe, tuple(args), path, value))
    if _sole(near):
        return near[0]
    return None


def _sole(found: list[Source]) -> bool:
    """True when ``found`` names one call and path only: every source has the same probe, path and arguments (the
    same objects, or the same text of them).  Answered at the first that differs: a value found in many places of
    a long log (a zero of a tree's state, say) is not written out for each."""
    if not found:
        return False
    first = found[0]
    text = None
    for other in found[1:]:
        if other.probe != first.probe or other.path != first.path:
            return False
        if len(other.args) == len(first.args) and all(a is b for a, b in zip(other.args, first.args)):
            continue
        if text is None:
            text = repr(first.args)[:2000]
        if repr(other.args)[:2000] != text:
            return False
    return True


def counterpart(log, raw, source: Source | None, tol: Tol) -> Source | None:
    """The student's call of ``source``'s probe on its very arguments, when its result at ``source``'s path is
    ``raw`` up to the comparison's tolerance (the check compared a copy of it: reshaped, or with entries within the
    tolerance set to the expected ones), or None.  Only that one call is asked: a value within the tolerance of some
    other call's result is no trace."""
    target = array_of(raw)
    if source is None or target is None or target.size == 0:
        return None
    key = _args_key(source.args)
    if key is None:
        return None
    for side, probe, args, value in reversed(log):
        if side != "student" or probe != source.probe or _args_key(args) != key:
            continue
        candidate = array_of(at(value, source.path))
        if candidate is None or candidate.size != target.size:
            return None
        if candidate.shape != target.shape and np.squeeze(candidate).shape != np.squeeze(target).shape:
            return None
        if within(candidate.reshape(target.shape), target, tol):
            return Source(probe, tuple(args), source.path, value)
        return None
    return None


#: the most points of one call evaluated at several points (a symbolic answer evaluated at each) the engine reads
MAX_POINTS = 64


def at_point(value, path):
    """``at(value, path)``, where an integer key also indexes the first axis of an array (a call's result that holds
    one value per point as one array)."""
    for key in path:
        if isinstance(value, np.ndarray) and isinstance(key, int) and value.ndim and -len(value) <= key < len(value):
            value = value[key]
        else:
            value = at(value, (key,))
        if value is None:
            return None
    return value


def _points_of(value, path=()):
    """``(path, item)`` of a call's result and of each row of its arrays of two dimensions or more (one value per
    point)."""
    for inner, item in walk(value, path):
        yield inner, item
        if isinstance(item, np.ndarray) and item.ndim >= 2 and len(item) <= MAX_POINTS:
            for index in range(len(item)):
                yield (*inner, index), item[index]


def _alike(item, target, tol: Tol) -> bool:
    """``item`` holds the numbers of ``target`` within ``tol``, up to axes of length one."""
    candidate = array_of(item)
    return (candidate is not None and candidate.size == target.size and candidate.size > 0
            and np.squeeze(candidate).shape == np.squeeze(target).shape
            and within(candidate.reshape(target.shape), target, tol))


def evaluated(log, got, tol: Tol, named: tuple = ()) -> Source | None:
    """The student's call whose result holds ``got`` within the comparison's tolerance ``tol``, up to axes of length
    one, at one path (a row of an array counts: a symbolic answer evaluated at several points), or None when no one
    path of one call has it.  ``named``: the path of the expected value in the reference's result; where several
    paths hold ``got``, the one path whose names (its keys other than indices) end with those of ``named`` is taken (a
    symbolic answer whose rate and acceleration came out alike: the entry compared is the one of the same name)."""
    target = array_of(got)
    if target is None or target.size == 0:
        return None
    found = []
    for side, probe, args, value in reversed(log):
        if side != "student":
            continue
        for path, item in _points_of(value):
            if not isinstance(item, (dict, str)) and _alike(item, target, tol):
                found.append(Source(probe, tuple(args), path, value))
    distinct_found = {(s.probe, repr(s.args)[:2000], s.path): s for s in found}
    if len(distinct_found) == 1:
        return found[0]
    names = _names(named)
    if names:
        alike = {key: s for key, s in distinct_found.items() if _names(s.path)[-len(names):] == names}
        if len(alike) == 1:
            return next(iter(alike.values()))
    return None


def _names(path) -> tuple:
    """The keys of ``path`` that are names (not indices)."""
    return tuple(key for key in path if isinstance(key, str))


def _numbers(args) -> np.ndarray | None:
    """The numbers of a call's arguments, flat, or None when one of them is neither a number nor a string."""
    numbers = []
    for arg in args:
        if isinstance(arg, str):
            continue
        array = array_of(arg)
        if array is None:
            return None
        numbers += list(array.ravel())
    return np.array(numbers, dtype=float)


def _texts(args) -> list:
    return [arg for arg in args if isinstance(arg, str)]


def _batch(student: Source, source: Source):
    """``(position, points)``: where ``student``'s path indexes the points of its call (an integer key ``i``) and
    the argument whose row ``i`` holds the numbers of ``source``'s arguments (the point the reference was asked
    at), or None."""
    numbers = _numbers(source.args)
    if numbers is None or numbers.size == 0 or _texts(source.args) != _texts(student.args):
        return None
    for position, key in enumerate(student.path):
        if not isinstance(key, int) or isinstance(key, bool):
            continue
        for arg in student.args:
            points = None if isinstance(arg, str) else array_of(arg)
            if points is None or points.ndim != 2 or points.shape[1] != numbers.size or not 0 <= key < len(points):
                continue
            if np.array_equal(points[key], numbers):
                return position, points
    return None


def sibling(log, evidence: Evidence) -> Evidence | None:
    """Where the student's value is their call's value at one of several points (a symbolic answer evaluated at
    each) and the expected value the reference's call at that point: the same comparison at another point the check
    asked the reference at, where the student's value fails too (a second input, found in the log, never guessed),
    or None."""
    source, student = evidence.source, evidence.student
    if source is None or student is None:
        return None
    shared = _shared_points(source, student)
    if shared is not None:
        return _at_another_point(evidence, *shared)
    if source.probe == student.probe and _args_key(source.args) is not None \
            and _args_key(source.args) == _args_key(student.args):
        return None
    batch = _batch(student, source)
    if batch is None:
        return None
    position, points = batch
    here = _args_key(source.args)
    for index, point in enumerate(points):
        if index == student.path[position]:
            continue
        for side, probe, args, value in reversed(log):
            if side != "reference" or probe != source.probe or _args_key(args) == here:
                continue
            numbers = _numbers(args)
            if numbers is None or numbers.shape != point.shape or not np.array_equal(numbers, point) \
                    or _texts(args) != _texts(source.args):
                continue
            expected = array_of(at(value, source.path))
            path = (*student.path[:position], index, *student.path[position + 1:])
            got = array_of(at_point(student.root, path))
            failing = _failing(evidence, got, expected, Source(probe, tuple(args), source.path, value),
                               Source(student.probe, tuple(student.args), path, student.root))
            if failing is None:
                break  # no value, or the student's value holds at this point: another is looked for
            return failing
    return None


def _point_keys(path, count: int) -> list:
    """The positions of ``path`` whose key is an integer that can index ``count`` points."""
    return [position for position, key in enumerate(path)
            if isinstance(key, int) and not isinstance(key, bool) and 0 <= key < count]


def _shared_points(source: Source, student: Source):
    """``(count, at_source, at_student)`` where the reference's and the student's calls (of two probes: the reference's
    values and the student's answer evaluated) were asked at the very same points (one argument of each, a list of two
    points or more, equal: a symbolic answer and the reference's values evaluated at the points the check drew) and each
    path indexes them at one position, with the same index: the positions of that index in the two paths; or None."""
    if source.root is None or student.root is None or source.probe == student.probe:
        return None  # one probe on the same points: the engine draws its second input itself
    keys = {_args_key((arg,)) for arg in student.args if isinstance(arg, (list, tuple)) and 1 < len(arg) <= MAX_POINTS}
    for arg in source.args:
        if not isinstance(arg, (list, tuple)) or not 1 < len(arg) <= MAX_POINTS:
            continue
        key = _args_key((arg,))
        if key is None or key not in keys:
            continue
        at_source, at_student = _point_keys(source.path, len(arg)), _point_keys(student.path, len(arg))
        if len(at_source) == 1 and len(at_student) == 1 \
                and source.path[at_source[0]] == student.path[at_student[0]]:
            return len(arg), at_source[0], at_student[0]
    return None


def _at_another_point(evidence: Evidence, count: int, at_source: int, at_student: int) -> Evidence | None:
    """The same comparison at another of the points both calls were asked at (``_shared_points``), the first where
    the student's value fails too, or None: the values are read from the two calls' results, no call is made."""
    source, student = evidence.source, evidence.student
    shown = source.path[at_source]
    for index in range(count):
        if index == shown:
            continue
        path = (*source.path[:at_source], index, *source.path[at_source + 1:])
        theirs = (*student.path[:at_student], index, *student.path[at_student + 1:])
        expected, got = array_of(at_point(source.root, path)), array_of(at_point(student.root, theirs))
        failing = _failing(evidence, got, expected, Source(source.probe, tuple(source.args), path, source.root),
                           Source(student.probe, tuple(student.args), theirs, student.root))
        if failing is not None:  # else no value, or the student's value holds here: another is looked for
            return failing
    return None


def _failing(evidence: Evidence, got, expected, source: Source, student: Source) -> Evidence | None:
    """``evidence`` at another input: the student's value ``got`` beside the expected one, where both are there, of
    one size, and the student's fails (None where it holds: that input shows nothing)."""
    if expected is None or got is None or got.size != expected.size:
        return None
    got = got.reshape(expected.shape)
    if within(got, expected, evidence.tol):
        return None
    return Evidence(got, expected, evidence.tol, evidence.name, None, None, source, student)


def _args_key(args) -> str | None:
    try:
        return call_key("", tuple(args))
    except Exception:  # noqa: BLE001 - arguments that cannot be written as plain data are no key
        return None


def at(value, path):
    for key in path:
        if isinstance(value, dict):
            value = value.get(key if key in value else str(key))
        elif isinstance(value, (list, tuple)) and isinstance(key, int) and -len(value) <= key < len(value):
            value = value[key]
        else:
            return None
        if value is None:
            return None
    return value


def array_of(value):
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return None
    return array if np.all(np.isfinite(array)) else None


def within(got, value, tol: Tol) -> bool:
    return got.shape == value.shape and bool(np.all(np.abs(got - value) <= tol.atol + tol.rtol * np.abs(value)))


#: the relative difference within which two values are one computation's (the same operations, in another order),
#: whatever the check's tolerance: a run that grows far past the size its absolute tolerance was set for (a step that
#: does not scale a term by the step) is still reproduced by the slip that makes it
REPRODUCED_RTOL = 1e-9


def reproduces(got, value, tol: Tol) -> bool:
    """``value`` gives the student's ``got``: within the comparison's tolerance, or within ``REPRODUCED_RTOL`` of
    the larger of the two, entry by entry."""
    if within(got, value, tol):
        return True
    return got.shape == value.shape and bool(np.all(np.isfinite(got))) and bool(np.all(
        np.abs(got - value) <= REPRODUCED_RTOL * np.maximum(np.abs(got), np.abs(value))))


def distinct(value, expected, tol: Tol) -> bool:
    """``value`` differs from ``expected`` clearly (beyond ``DISTINCT`` tolerances somewhere)."""
    if value.shape != expected.shape:
        return True
    return bool(np.any(np.abs(value - expected) > DISTINCT * (tol.atol + tol.rtol * np.abs(expected))))


#: the numbers a value the engine has one of (a run's start) must differ in, each another value, for a slip of the
#: grammar found on it to be told
ONE_INPUT_NUMBERS = 3


def numbers_told(got, expected, tol: Tol) -> int:
    """How many numbers one value says of its slip: the distinct values among its entries that differ from the
    expected value beyond the tolerance (a value of another shape: the distinct values of all its entries).  A
    slip that reproduces the value reproduces these numbers and no others, so every slip found on it stands on
    them alike.  One number (one entry) or two (a pair exchanged) are matched by some of the grammar's many slips
    by chance (two entries exchanged are two entries of a 90 degree rotation's other sense), and entries that
    repeat one value say it once."""
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    if got.shape == expected.shape:
        off = np.abs(got - expected) > tol.atol + tol.rtol * np.abs(expected)
        values = got[off]
    else:
        values = got.ravel()
    values = np.sort(values[np.isfinite(values)])
    if values.size == 0:
        return 0
    gaps = np.diff(values) > tol.atol + tol.rtol * np.abs(values[1:])
    return 1 + int(np.count_nonzero(gaps))
