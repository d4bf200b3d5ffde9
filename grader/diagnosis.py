"""The differential diagnosis engine: names the cause of a failing comparison that no catalogued mistake explains.

When a check's comparison fails and its catalogue of known mistakes has no match, the engine evaluates the
reference under a grammar of common slips on the same inputs and keeps the hypotheses that reproduce the
student's answer within the comparison's tolerance on the input shown *and* on a second, non-degenerate one (the
randomized comparison's second failing input, or an input the engine draws itself); it ranks them by simplicity
and says "looks like X" (one), "could be X or Y" (several at the simplest level) or nothing (none).  It never
names a default cause.

The grammar:

* outputs (the expected value transformed): transpose, inverse, the sign of the whole value, of a row, a column
  or an entry, rows, columns or entries swapped, a factor 2, 1/2, pi/180, 180/pi or a named constant of the
  problem, float32 rounding, rounding to a few decimals, the output in the other frame (conjugation by the
  problem's rotation);
* inputs (the reference on transformed arguments): arguments swapped, angles as degrees, negated angles, a
  rotation argument transposed, a vector argument in the other frame, an argument ignored (the student's value
  does not change when it does);
* formulas: a declared term missing, sign-flipped or added (``terms``: the reference splits its result into named
  terms), found by least squares over the inputs;
* motions (``motion``: a run's times, states and events): a time shift, a constant offset, a state read from the
  wrong row, a wrong initial state, an event found late or early, an error that grows with the step.

What a probe's arguments and result are is declared beside ``@probe`` (``probes.probe(args=..., terms=...,
rotation=..., motion=..., constants=..., draw=...)``); the reference's values come through the oracle (the
grading context), never from ``reference`` itself.  Every reference call the engine may need is a function of the
probe's arguments alone, so the student kit's answer key holds them: while the key is recorded, every comparison
of a declared probe makes them (``prepare``).
"""

from __future__ import annotations

import inspect
import itertools
import zlib
from dataclasses import dataclass, field

import numpy as np

from checks._diagnoses import DIAGNOSES

from .checking import Tol, format_array
from .errors import GraderFault, StudentFault

__all__ = [
    "Evidence",
    "Finding",
    "Source",
    "Declaration",
    "declaration",
    "explain",
    "prepare",
    "locate",
    "recording",
    "note_comparison",
    "prepared",
    "remember_run",
    "MAX_REFERENCE_CALLS",
]

#: a hypothesis counts as another answer when it differs from the expected value by this many times the tolerance
#: (on one input at least); below that it is the expected value up to rounding
DISTINCT = 10.0
#: the reference calls one explanation may make (inputs transformed, terms, a second input and its variants)
MAX_REFERENCE_CALLS = 80
#: the student's calls one explanation may make (a second input, an argument changed)
MAX_STUDENT_CALLS = 6
#: how long one of the engine's calls of the student's code may take [s]
STUDENT_TIMEOUT = 5.0
#: arrays with more entries than this are not searched entry by entry (signs, swaps)
ENTRYWISE = 36
#: raise the engine's own defects instead of naming no cause (the engine's tests set it)
STRICT = False
#: the engine is asked at all (its tests and the benchmark turn it off to compare)
ENABLED = True
#: the steps of the reference's fixed-step runs that a run's error is compared with [s]
FIXED_STEPS = (0.005, 0.01, 0.02, 0.05)
#: a run's error is compared with a fixed-step run's while it is at most this many tolerances
STEP_WINDOW = 30.0
#: a run's error has the shape of a fixed-step integration's when what is left of it, once the best multiple of the
#: latter's error is taken away, is at most this fraction of it (root mean square)
STEP_SHAPE = 0.2


# ---------------------------------------------------------------------------------------------- declarations


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


_DECLARATIONS: dict[str, Declaration | None] = {}


def declaration(probe: str) -> Declaration | None:
    """The declaration of a probe (``"problem_06.cardan"``), or None when it declares nothing."""
    if probe in _DECLARATIONS:
        return _DECLARATIONS[probe]
    if "." not in probe:
        return None
    import importlib

    module_name, _, func_name = probe.rpartition(".")
    try:
        func = getattr(importlib.import_module(f"probes.{module_name}"), func_name)
    except (ImportError, AttributeError):
        _DECLARATIONS[probe] = None
        return None
    declared = getattr(func, "declared", None) or {}
    if not declared:
        _DECLARATIONS[probe] = None
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
    _DECLARATIONS[probe] = found
    return found


# ---------------------------------------------------------------------------------------------- evidence


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


@dataclass(frozen=True)
class Finding:
    """The engine's answer: the names it keeps (one, or several at the simplest level) and the hint."""

    names: tuple
    hint: str

    @property
    def diagnosis(self) -> str:
        return " or ".join(self.names)


@dataclass(frozen=True)
class _Hypothesis:
    key: str  # the same slip on every input (e.g. "sign:row:1")
    name: str  # its diagnosis
    cost: int  # simplicity: 1 simplest
    detail: str  # what it is, for the hint


# ---------------------------------------------------------------------------------------------- finding sources


def _walk(value, path=(), depth=0):
    """``(path, sub-value)`` of a probe's result, depth first (dicts, lists, tuples)."""
    yield path, value
    if depth >= 6:
        return
    if isinstance(value, dict):
        for key, item in value.items():
            yield from _walk(item, (*path, key), depth + 1)
    elif isinstance(value, (list, tuple)) and len(value) <= 64:
        for index, item in enumerate(value):
            yield from _walk(item, (*path, index), depth + 1)


def _equal(a, b) -> bool:
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
        for path, item in _walk(value):
            if item is raw:
                return Source(probe, tuple(args), path, value)
    found = []
    for _, probe, args, value in calls:
        for path, item in _walk(value):
            if not isinstance(item, (dict, str)) and _equal(item, raw):
                found.append(Source(probe, tuple(args), path, value))
    if len({(s.probe, repr(s.args)[:2000], s.path) for s in found}) == 1:
        return found[0]
    target = _array(raw)
    if tol is None or found or target is None or target.size == 0:
        return None
    near = []
    for _, probe, args, value in calls:
        for path, item in _walk(value):
            if isinstance(item, (dict, str)):
                continue
            candidate = _array(item)
            if candidate is not None and candidate.shape == target.shape and _within(candidate, target, tol):
                near.append(Source(probe, tuple(args), path, value))
    if len({(s.probe, repr(s.args)[:2000], s.path) for s in near}) == 1:
        return near[0]
    return None


def _at(value, path):
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


def _array(value):
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return None
    return array if np.all(np.isfinite(array)) else None


# ---------------------------------------------------------------------------------------------- the grammar: outputs


def _within(got, value, tol: Tol) -> bool:
    return got.shape == value.shape and bool(np.all(np.abs(got - value) <= tol.atol + tol.rtol * np.abs(value)))


def _distinct(value, expected, tol: Tol) -> bool:
    """``value`` differs from ``expected`` clearly (beyond ``DISTINCT`` tolerances somewhere)."""
    if value.shape != expected.shape:
        return True
    return bool(np.any(np.abs(value - expected) > DISTINCT * (tol.atol + tol.rtol * np.abs(expected))))


def _ordinal(i: int) -> str:
    return f"{i + 1}"


def _outputs(E: np.ndarray, constants: dict, rotation) -> list:
    """``(hypothesis, value)`` of the output slips of an expected value ``E``."""
    out = []
    add = out.append
    if E.ndim == 2 and E.shape[0] == E.shape[1] and E.shape[0] > 1:
        add((_Hypothesis("transpose", "transpose", 1, "your matrix is the transpose of the expected one"), E.T))
        if np.linalg.cond(E) < 1e8:
            add((_Hypothesis("inverse", "inverse", 2, "your matrix is the inverse of the expected one"),
                 np.linalg.inv(E)))
    if E.size == 1 and abs(float(E.ravel()[0])) > 1e-9:
        add((_Hypothesis("inverse", "inverse", 2, "your value is the reciprocal of the expected one"), 1.0 / E))
    add((_Hypothesis("sign", "sign_flip", 1, "your value is the expected one with the opposite sign"), -E))
    for factor, name, words in ((2.0, "factor_two", "twice"), (0.5, "factor_half", "half")):
        add((_Hypothesis(f"scale:{factor}", name, 1, f"your value is {words} the expected one"), factor * E))
    add((_Hypothesis("scale:deg", "degrees", 1, "your value is the expected one converted to degrees (times "
                     "180/pi)"), E * 180.0 / np.pi))
    add((_Hypothesis("scale:rad", "degrees", 1, "your value is the expected one times pi/180 (converted from "
                     "degrees once too often)"), E * np.pi / 180.0))
    for cname, c in constants.items():
        if abs(c) > 1e-12 and not any(abs(abs(c) - v) < 1e-9 for v in (1.0, 2.0, 0.5)):
            mass = cname in ("m", "mass")  # a value without its mass: the vocabulary's missing_mass
            add((_Hypothesis(f"const:*{cname}", "constant_factor", 2,
                             f"your value is the expected one times {cname} = {c:.6g}"), E * c))
            add((_Hypothesis(f"const:/{cname}", "missing_mass" if mass else "constant_factor", 2,
                             f"your value is the expected one divided by {cname} = {c:.6g}"), E / c))
    if E.ndim == 2 and E.size <= ENTRYWISE:
        rows, cols = E.shape
        for i in range(rows if rows > 1 else 0):
            value = E.copy()
            value[i] *= -1
            add((_Hypothesis(f"sign:row:{i}", "sign_flip", 2, f"row {_ordinal(i)} has the opposite sign"), value))
        for j in range(cols if cols > 1 else 0):
            value = E.copy()
            value[:, j] *= -1
            add((_Hypothesis(f"sign:col:{j}", "sign_flip", 2, f"column {_ordinal(j)} has the opposite sign"),
                 value))
        for i, j in itertools.combinations(range(rows), 2):
            value = E.copy()
            value[[i, j]] = value[[j, i]]
            add((_Hypothesis(f"swap:row:{i}:{j}", "swapped", 2, f"rows {_ordinal(i)} and {_ordinal(j)} are "
                             "swapped"), value))
        for i, j in itertools.combinations(range(cols), 2):
            value = E.copy()
            value[:, [i, j]] = value[:, [j, i]]
            add((_Hypothesis(f"swap:col:{i}:{j}", "swapped", 2, f"columns {_ordinal(i)} and {_ordinal(j)} are "
                             "swapped"), value))
        for index in np.ndindex(E.shape):
            value = E.copy()
            value[index] *= -1
            add((_Hypothesis(f"sign:entry:{index}", "sign_flip", 3,
                             f"the entry [{','.join(map(str, index))}] has the opposite sign"), value))
    if E.ndim == 1 and 1 < E.size <= ENTRYWISE:
        for i in range(E.size):
            value = E.copy()
            value[i] *= -1
            add((_Hypothesis(f"sign:entry:{i}", "sign_flip", 2, f"entry {_ordinal(i)} has the opposite sign"),
                 value))
        for i, j in itertools.combinations(range(E.size), 2):
            value = E.copy()
            value[[i, j]] = value[[j, i]]
            add((_Hypothesis(f"swap:entry:{i}:{j}", "swapped", 2, f"entries {_ordinal(i)} and {_ordinal(j)} are "
                             "swapped"), value))
        if E.size > 2:
            add((_Hypothesis("swap:reversed", "swapped", 2, "the entries are in reverse order"), E[::-1].copy()))
        if E.size == 3:
            for shift in (1, 2):
                add((_Hypothesis(f"swap:cyclic:{shift}", "swapped", 3, "the axes are permuted cyclically"),
                     np.roll(E, shift)))
    if rotation is not None:
        A = rotation
        if E.shape == (3,):
            add((_Hypothesis("frame:A", "wrong_frame", 2, "your vector is the expected one mapped with the "
                             "problem's rotation A (the other frame's coordinates)"), A @ E))
            add((_Hypothesis("frame:AT", "wrong_frame", 2, "your vector is the expected one mapped with A.T "
                             "(the other frame's coordinates)"), A.T @ E))
        elif E.shape == (3, 3):
            add((_Hypothesis("frame:A", "wrong_frame", 2, "your matrix is the expected one in the other frame "
                             "(A X A.T)"), A @ E @ A.T))
            add((_Hypothesis("frame:AT", "wrong_frame", 2, "your matrix is the expected one in the other frame "
                             "(A.T X A)"), A.T @ E @ A))
    return out


def _precision(got, E, tol: Tol) -> list:
    """Rounding slips: the student's value is the expected one in float32, or rounded to a few decimals."""
    found = []
    single = E.astype(np.float32).astype(float)
    if (np.all(got == got.astype(np.float32).astype(float)) and not np.all(E == single)
            and np.all(np.abs(got - E) <= 4 * np.finfo(np.float32).eps * np.maximum(np.abs(E), 1e-30))
            and not _within(got, E, tol)):
        found.append(_Hypothesis("float32", "float32", 1, "your values are the expected ones in single precision "
                                 "(float32): compute in float64 (numpy's default)"))
    for decimals in range(0, 7):
        rounded = np.round(E, decimals)
        if np.all(np.abs(got - rounded) <= 1e-12 * np.maximum(1.0, np.abs(E))) and not _within(rounded, E, tol):
            found.append(_Hypothesis(f"rounded:{decimals}", "rounded", 1,
                                     f"your values are the expected ones rounded to {decimals} decimals: return "
                                     "them unrounded"))
            break
    return found


# ---------------------------------------------------------------------------------------------- the grammar: inputs


def _leaves(roles, args, path=()):
    """``(path, role, value)`` of every declared argument (roles may be nested like the arguments: a dict of roles
    for a dict argument)."""
    if isinstance(roles, dict):
        for key, role in roles.items():
            if isinstance(args, dict) and key in args:
                yield from _leaves(role, args[key], (*path, key))
    elif isinstance(roles, (list, tuple)):
        for i, role in enumerate(roles):
            if isinstance(args, (list, tuple)) and i < len(args):
                yield from _leaves(role, args[i], (*path, i))
    elif roles:
        yield path, roles, args


def _replace(args, path, value):
    """``args`` with the leaf at ``path`` replaced (copies along the path; the rest shared)."""
    if not path:
        return value
    head, rest = path[0], path[1:]
    if isinstance(args, dict):
        return {**args, head: _replace(args[head], rest, value)}
    items = list(args)
    items[head] = _replace(items[head], rest, value)
    return tuple(items) if isinstance(args, tuple) else items


def _label(decl: Declaration, path) -> str:
    head = decl.names[path[0]] if path and path[0] < len(decl.names) else f"argument {path[0] + 1}"
    return head + "".join(f"[{k!r}]" for k in path[1:])


def _same_kind(a, b) -> bool:
    """Two arguments that could be swapped: both numbers, or arrays of one shape."""
    first, second = _array(a), _array(b)
    return first is not None and second is not None and first.shape == second.shape


def _angle(value, f):
    if isinstance(value, (list, tuple)):
        return [f(float(v)) for v in value]
    array = np.asarray(value, dtype=float)
    return float(f(float(array))) if array.ndim == 0 else f(array)


def _negated(value):
    return [-float(v) for v in value] if isinstance(value, list) else -np.asarray(value, dtype=float)


def _rotation_of(decl: Declaration, args):
    if decl.rotation is None:
        return None
    path = decl.rotation if isinstance(decl.rotation, tuple) else (decl.rotation,)
    value = _at(list(args), path)
    A = _array(value)
    if A is None or A.shape != (3, 3) or np.max(np.abs(A.T @ A - np.eye(3))) > 1e-6:
        return None
    return A


def _inputs(decl: Declaration, args: tuple) -> list:
    """``(hypothesis, transformed args)`` of the input slips of a declared probe."""
    out = []
    leaves = [(path, role, value) for path, role, value in _leaves(decl.args, list(args))]
    angles = [(path, value) for path, role, value in leaves if role in ("angle", "angles")]
    for path, value in angles:
        label = _label(decl, path)
        out.append((_Hypothesis(f"in:deg:{path}", "degrees", 2, f"{label} is used as if it were in degrees "
                                "(radians are given)"), _replace(args, path, _angle(value, np.deg2rad))))
        out.append((_Hypothesis(f"in:neg:{path}", "angle_sign", 2, f"{label} enters with the opposite sign (a "
                                "rotation the other way)"), _replace(args, path, _angle(value, np.negative))))
    if len(angles) > 1:
        every = tuple(args)
        for path, value in angles:
            every = _replace(every, path, _angle(value, np.deg2rad))
        out.append((_Hypothesis("in:deg:all", "degrees", 2, "every angle is used as if it were in degrees (radians "
                                "are given)"), every))
    for (p1, r1, v1), (p2, r2, v2) in itertools.combinations(leaves, 2):
        if r1 == r2 and len(p1) == len(p2) == 1 and _same_kind(v1, v2) and not _equal(v1, v2):
            swapped = _replace(_replace(args, p1, v2), p2, v1)
            out.append((_Hypothesis(f"in:swap:{p1}:{p2}", "argument_order", 2, f"{_label(decl, p1)} and "
                                    f"{_label(decl, p2)} are swapped"), swapped))
    A = _rotation_of(decl, args)
    for path, role, value in leaves:
        array = _array(value)
        if role == "vector" and array is not None and array.size > 1:
            out.append((_Hypothesis(f"in:neg:{path}", "sign_flip", 2, f"{_label(decl, path)} enters with the "
                                    "opposite sign"), _replace(args, path, _negated(value))))
        if role == "rotation" and array is not None and array.shape == (3, 3):
            out.append((_Hypothesis(f"in:T:{path}", "transpose", 2, f"{_label(decl, path)} is used transposed "
                                    "(A_BI for A_IB)"), _replace(args, path, array.T)))
        if role == "vector" and A is not None and array is not None and array.shape == (3,):
            out.append((_Hypothesis(f"in:frame:A:{path}", "wrong_frame", 3, f"{_label(decl, path)} is taken in "
                                    "the other frame (mapped with A)"), _replace(args, path, A @ array)))
            out.append((_Hypothesis(f"in:frame:AT:{path}", "wrong_frame", 3, f"{_label(decl, path)} is taken in "
                                    "the other frame (mapped with A.T)"), _replace(args, path, A.T @ array)))
    return out


def _perturbed(value):
    """Another value of an argument, of the same kind (for the test of an ignored argument)."""
    array = _array(value)
    if array is None:
        return None
    if array.ndim == 0:
        x = float(array)
        return x * 1.37 + 0.29
    if array.shape == (3, 3) and np.max(np.abs(array.T @ array - np.eye(3))) < 1e-6:
        turn = np.eye(3)  # a turn by 0.61 rad about the 3-axis
        turn[:2, :2] = [[np.cos(0.61), -np.sin(0.61)], [np.sin(0.61), np.cos(0.61)]]
        return turn @ array
    pattern = np.linspace(0.31, 0.97, array.size).reshape(array.shape)
    changed = array * 1.21 + pattern
    return changed.tolist() if isinstance(value, list) else changed


# ---------------------------------------------------------------------------------------------- drawing a second input


def _draw_leaf(role, value, rng):
    array = _array(value)
    if array is None:
        return value
    if role == "angle":
        return float(rng.uniform(-2.8, 2.8)) if array.ndim == 0 else rng.uniform(-2.8, 2.8, array.shape)
    if role == "angles":
        drawn = rng.uniform(-2.8, 2.8, array.shape)
        return drawn.tolist() if isinstance(value, list) else drawn
    if role == "vector":
        drawn = rng.uniform(-2.0, 2.0, array.shape)
        return drawn.tolist() if isinstance(value, list) else drawn
    if role == "rotation" and array.shape == (3, 3):
        w, x, y, z = rng.normal(size=4)
        n = np.sqrt(w * w + x * x + y * y + z * z)
        w, x, y, z = w / n, x / n, y / n, z / n
        return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    if role == "scalar":
        scale = max(abs(float(array.ravel()[0])), 0.1) if array.size else 1.0
        drawn = array * rng.uniform(0.6, 1.6, array.shape) if array.ndim else float(scale * rng.uniform(0.6, 1.6))
        return drawn
    return value


def _redraw(decl: Declaration, args: tuple, seed_words) -> tuple | None:
    """A second input like ``args`` with every declared angle, vector, rotation and scalar drawn anew (None when
    the probe declares nothing to draw)."""
    if not decl.draw:
        return None
    leaves = [(path, role, value) for path, role, value in _leaves(decl.args, list(args))
              if role in ("angle", "angles", "vector", "rotation", "scalar")]
    if not leaves:
        return None
    rng = np.random.default_rng(seed_words)
    drawn = tuple(args)
    for path, role, value in leaves:
        drawn = _replace(drawn, path, _draw_leaf(role, value, rng))
    return drawn


# ---------------------------------------------------------------------------------------------- the scene


class _Budget(Exception):
    """The engine ran out of calls: what it found so far is not enough to name a cause."""


class _Scene:
    """The engine's access to the reference (through the grading context's oracle) and to the student's code, with
    its budgets."""

    def __init__(self, ctx):
        self.ctx = ctx
        self.reference_calls = 0
        self.student_calls = 0

    def reference(self, probe: str, args: tuple, persist: bool = False):
        self.reference_calls += 1
        if self.reference_calls > MAX_REFERENCE_CALLS:
            raise _Budget()
        return self.ctx.oracle.reference(probe, tuple(args), persist, check=self.ctx.check_id)

    def student(self, probe: str, args: tuple):
        self.student_calls += 1
        if self.student_calls > MAX_STUDENT_CALLS:
            raise _Budget()
        return self.ctx.child.call(probe, *args, timeout=STUDENT_TIMEOUT)

    def draw_seed(self, source: Source) -> list:
        """The seed of the engine's own second input for a source: the oracle's draw of a site named after the
        call (live from the run's seed; in the kit the draw recorded with the key)."""
        from .oracle import call_key

        site = f"{self.ctx.check_id}~engine~{zlib.crc32(call_key(source.probe, source.args).encode()):08x}"
        drawn = self.ctx.oracle.draw(site, lambda rng: [int(x) for x in rng.integers(0, 2**32, 2)],
                                     self.ctx.seed, check=self.ctx.check_id)
        return [int(x) for x in drawn]


def _constants(scene: _Scene, decl: Declaration, args: tuple) -> dict:
    """The problem's named constants a value may be scaled by: the declared scalar arguments (a mass, g, a length:
    by their names) and the numbers of the declared probe of constants."""
    found = {}
    for path, role, value in _leaves(decl.args, list(args)):
        array = _array(value)
        if role == "scalar" and len(path) == 1 and array is not None and array.ndim == 0:
            found[_label(decl, path)] = float(array)
    if decl.constants:
        value = scene.reference(decl.constants, ())
        for key, item in (value.items() if isinstance(value, dict) else ()):
            if isinstance(item, (int, float)) and not isinstance(item, bool) and np.isfinite(item):
                found.setdefault(key, float(item))
    return found


# ---------------------------------------------------------------------------------------------- one input


@dataclass
class _Input:
    """One input's evidence and what the engine computed for it: hypothesis key -> predicted value."""

    evidence: Evidence
    predicted: dict = field(default_factory=dict)
    hypotheses: dict = field(default_factory=dict)
    terms: dict | None = None
    extras: dict | None = None


def _predict(scene: _Scene, evidence: Evidence, constants: dict, with_inputs: bool = True) -> _Input:
    """The hypotheses' predicted values on one input."""
    one = _Input(evidence)
    source = evidence.source
    decl = declaration(source.probe) if source is not None else None
    rotation = _rotation_of(decl, source.args) if decl is not None else None
    for hypothesis, value in _outputs(evidence.expected, constants, rotation):
        one.hypotheses[hypothesis.key] = hypothesis
        one.predicted[hypothesis.key] = value
    if decl is None or not with_inputs:
        return one
    for hypothesis, args in _inputs(decl, source.args):
        try:
            value = _array(_at(scene.reference(source.probe, args), source.path))
        except GraderFault:
            continue
        if value is not None:
            one.hypotheses[hypothesis.key] = hypothesis
            one.predicted[hypothesis.key] = value
    if decl.terms:
        try:
            split = scene.reference(decl.terms, source.args)
        except GraderFault:
            split = None
        if isinstance(split, dict):
            one.terms = _term_values(split.get("terms", {}), source.path, evidence.expected.shape)
            one.extras = _term_values(split.get("extra", {}), source.path, evidence.expected.shape)
    return one


def _term_values(terms: dict, path, shape) -> dict:
    found = {}
    for name, structure in (terms or {}).items():
        value = _array(_at(structure, path))
        if value is not None and value.shape == shape and np.any(value != 0):
            found[name] = value
    return found


# ---------------------------------------------------------------------------------------------- terms


def _term_hypotheses(inputs: list) -> list:
    """The declared terms' slips that reproduce every input: the coefficients of ``got - expected`` on the terms
    (each present term's change: -1 missing, -2 sign-flipped; each extra term's: +-1), found by least squares over
    the inputs and checked entrywise within the tolerance; several when the inputs cannot tell them apart."""
    if any(one.terms is None for one in inputs):
        return []
    present = sorted(set().union(*(set(one.terms) for one in inputs)))
    extra = sorted(set().union(*(set(one.extras or {}) for one in inputs)))
    columns = [("term", t) for t in present] + [("extra", t) for t in extra]
    if not columns or len(columns) > 8:
        return []
    for one in inputs:  # a term that is zero on an input (a flag off there, say) is a column of zeros
        zero = np.zeros_like(one.evidence.expected)
        one.terms = {t: one.terms.get(t, zero) for t in present}
        one.extras = {t: (one.extras or {}).get(t, zero) for t in extra}
    rows, rhs = [], []
    for one in inputs:
        ev = one.evidence
        rows.append(np.stack([(one.terms if kind == "term" else one.extras)[t].ravel() for kind, t in columns],
                             axis=1))
        rhs.append((ev.got - ev.expected).ravel())
    A, b = np.vstack(rows), np.concatenate(rhs)
    solution = np.linalg.lstsq(A, b, rcond=None)[0]
    allowed = {"term": (0.0, -1.0, -2.0), "extra": (0.0, 1.0, -1.0)}
    guess = tuple(min(allowed[kind], key=lambda v: abs(v - s)) for (kind, _), s in zip(columns, solution))
    candidates = {guess}
    for changes in itertools.product(*(allowed[kind] for kind, _ in columns)):
        if 0 < sum(c != 0 for c in changes) <= 2:
            candidates.add(changes)
    matching = []
    for changes in candidates:
        if not any(changes):
            continue
        ok = True
        for one in inputs:
            ev = one.evidence
            model = ev.expected + sum(c * (one.terms if kind == "term" else one.extras)[t]
                                      for c, (kind, t) in zip(changes, columns) if c)
            if not _within(ev.got, model, ev.tol):
                ok = False
                break
        if ok:
            matching.append(changes)
    if not matching:
        return []
    fewest = min(sum(c != 0 for c in changes) for changes in matching)
    found = []
    for changes in matching:
        if sum(c != 0 for c in changes) != fewest:
            continue
        for c, (kind, term) in zip(changes, columns):
            if not c:
                continue
            fit = "a least-squares fit of your values on the reference's terms over the inputs"
            if kind == "term" and c == -1.0:
                name, detail = f"missing_{term}", f"{fit} leaves it out and reproduces them"
            elif kind == "term":
                name, detail = f"{term}_sign", f"{fit} turns it around and reproduces them"
            else:
                name, detail = f"extra_{term}", f"{fit} adds it and reproduces them"
            if name in DIAGNOSES:
                found.append(_Hypothesis(f"term:{kind}:{term}:{c}", name, 1 + fewest, detail))
    return found


# ---------------------------------------------------------------------------------------------- motions


def _run_of(root, motion: dict):
    """``(t, {state key: 2-D array (samples x components)})`` of a run's result, or None."""
    if not isinstance(root, dict):
        return None
    t = _array(root.get(motion.get("time", "t")))
    if t is None or t.ndim != 1 or t.size < 3:
        return None
    states = {}
    for key in motion.get("states", ()):
        value = _array(root.get(key))
        if value is None or value.shape[0] != t.size:
            return None
        states[key] = value.reshape(t.size, -1)
    return (t, states) if states else None


def _aligned(evidence: Evidence, decl: Declaration):
    """The student's run and the reference's on the student's output times (the reference's interpolated there),
    from both runs' start to the first event or end of either: ``(t, {key: mine}, {key: ours}, reference's times,
    reference's run)``, or None."""
    motion = decl.motion
    mine = _run_of(evidence.student.root if evidence.student else None, motion)
    ours = _run_of(evidence.source.root, motion)
    if mine is None or ours is None:
        return None
    (t_s, G), (t_r, R) = mine, ours
    keys = [k for k in G if k in R and G[k].shape[1] == R[k].shape[1]]
    end = min([t_s[-1], t_r[-1], *_event_times(evidence.student.root, motion),
               *_event_times(evidence.source.root, motion)])
    inside = (t_s >= max(t_s[0], t_r[0]) - 1e-12) & (t_s <= end + 1e-12)
    if inside.sum() < 3 or not keys:
        return None
    t = t_s[inside]
    ours_at = {k: np.column_stack([np.interp(t, t_r, R[k][:, j]) for j in range(R[k].shape[1])]) for k in keys}
    return t, {k: G[k][inside] for k in keys}, ours_at, t_r, {k: R[k] for k in keys}


def _motion_hypotheses(evidence: Evidence, decl: Declaration) -> list:
    """The motion slips that reproduce the student's run: an event found late or early, a constant offset, a state
    read from the wrong row, a time shift, a wrong initial state."""
    motion = decl.motion
    tol = evidence.tol
    found = _event_hypotheses(evidence, decl)
    aligned = _aligned(evidence, decl)
    if aligned is None:
        return found
    t, G, R, t_r, R_full = aligned
    keys = list(G)
    wrong = [k for k in keys if not _within(G[k], R[k], tol)]
    if not wrong:
        return found
    # a constant offset
    offsets = {k: np.mean(G[k] - R[k], axis=0) for k in keys}
    if all(_within(G[k] - offsets[k], R[k], tol) for k in keys):
        words = "; ".join(f"{k}: {format_array(offsets[k])}" for k in wrong)
        found.append(_Hypothesis("motion:offset", "offset", 2, f"your run is the reference's plus a constant offset "
                                 f"({words})"))
        if abs(t[0] - t_r[0]) < 1e-9:  # a run from a start moved by the offset looks the same where the motion
            # does not depend on where it is (a height, say)
            found.append(_Hypothesis("motion:offset-start", "initial_state", 2, f"your run starts at {words} from "
                                     "the given state and keeps that offset"))
    # a state read from the wrong row
    columns = [(k, j) for k in keys for j in range(R[k].shape[1])]
    mapping, explained = {}, True
    for k in wrong:
        for i in range(G[k].shape[1]):
            if _within(G[k][:, i], R[k][:, i], tol):
                continue
            rows = [(k2, j) for k2, j in columns if (k2, j) != (k, i) and _within(G[k][:, i], R[k2][:, j], tol)
                    and _distinct(R[k2][:, j], R[k][:, i], tol)]
            if not rows:
                explained = False
                break
            mapping[(k, i)] = rows[0]
        if not explained:
            break
    if explained and mapping:
        words = ", ".join(f"{k}[{i}] is the reference's {k2}[{j}]" for (k, i), (k2, j) in mapping.items())
        found.append(_Hypothesis("motion:row", "state_row", 2, f"your run has a state from the wrong row: {words}"))
    # a time shift
    shift = _time_shift(t, G, t_r, R_full, tol)
    if shift is not None:
        found.append(_Hypothesis("motion:shift", "time_shift", 2, f"your run is the reference's shifted in time: "
                                 f"yours at t is the reference's at t {shift:+.4g}"))
    # a wrong initial state: the start differs from the given one
    start = [k for k in motion.get("states", ()) if k in G and abs(t[0] - t_r[0]) < 1e-9
             and not _within(G[k][0], R[k][0], tol)]
    if start:
        words = "; ".join(f"{k}(t0) = {format_array(G[k][0])}, expected {format_array(R[k][0])}" for k in start)
        found.append(_Hypothesis("motion:start", "initial_state", 3, f"your run starts from another state: {words}"))
    return found


def _event_hypotheses(evidence: Evidence, decl: Declaration) -> list:
    """An event found late or early: the student's event time differs from the reference's, while their run agrees
    with the reference's up to the earlier of the two."""
    motion = decl.motion
    tol = evidence.tol
    mine = _run_of(evidence.student.root if evidence.student else None, motion)
    ours = _run_of(evidence.source.root, motion)
    if mine is None or ours is None:
        return []
    (t_s, G), (t_r, R) = mine, ours
    found = []
    for key in motion.get("events", ()):
        mine_event, our_event = _array(_at(evidence.student.root, (key,))), _array(_at(evidence.source.root, (key,)))
        if mine_event is None or our_event is None or mine_event.size != 1 or our_event.size != 1:
            continue
        te, tr = float(mine_event), float(our_event)
        before = (t_s <= min(te, tr) + 1e-12) & (t_s >= t_r[0])
        if before.sum() < 3:
            continue
        agree = all(_within(G[k][before], np.column_stack([np.interp(t_s[before], t_r, R[k][:, j])
                                                           for j in range(R[k].shape[1])]), tol)
                    for k in G if k in R and G[k].shape[1] == R[k].shape[1])
        if agree and abs(te - tr) > tol.atol + tol.rtol * abs(tr):
            if te > tr:
                found.append(_Hypothesis(f"event:late:{key}", "event_late", 2,
                                         f"your run agrees with the reference's up to its event, but your {key} "
                                         f"is {te:.6g} where it is {tr:.6g}: the event is found {te - tr:.3g} s "
                                         "late (a coarse search for it, or a step that jumps over it)"))
            else:
                found.append(_Hypothesis(f"event:early:{key}", "event_early", 2,
                                         f"your run agrees with the reference's until it stops, but your {key} is "
                                         f"{te:.6g} where it is {tr:.6g}: the event is found {tr - te:.3g} s early"))
    return found


def _event_times(root, motion: dict) -> list:
    times = []
    for key in motion.get("events", ()):
        value = _array(_at(root, (key,)))
        if value is not None and value.size == 1:
            times.append(float(value))
    return times


def _step_size(scene: _Scene, evidence: Evidence, decl: Declaration) -> list:
    """An integration error that scales with the step: the student's run leaves the reference's as a fixed-step
    run of the reference's own right-hand side does (the probe ``motion["fixed_step"]``, at the steps
    ``FIXED_STEPS``), by a multiple of its error between 1/2 and 2 (the step, to first order), up to the first event
    of either run and while the error is still small (``STEP_WINDOW`` tolerances: past that, a chaotic or unstable
    run's error no longer scales)."""
    motion = decl.motion
    probe = motion.get("fixed_step")
    student, source = evidence.student, evidence.source
    if not probe or student is None:
        return []
    mine, ours = _run_of(student.root, motion), _run_of(source.root, motion)
    if mine is None or ours is None:
        return []
    (t_s, G), (t_r, R) = mine, ours
    keys = [key for key in G if key in R and G[key].shape[1] == R[key].shape[1]]
    if abs(t_s[0] - t_r[0]) > 1e-9 or not all(_within(G[k][0], R[k][0], evidence.tol) for k in keys):
        return []  # another start: a fixed-step run from the given one does not explain the run
    end = min([t_s[-1], t_r[-1], *_event_times(student.root, motion), *_event_times(source.root, motion)])
    inside = (t_s >= max(t_s[0], t_r[0])) & (t_s < end - 1e-12)
    t = t_s[inside]
    if t.size < 5 or not keys:
        return []
    ours_at = {key: np.column_stack([np.interp(t, t_r, R[key][:, j]) for j in range(R[key].shape[1])])
               for key in keys}
    error = np.concatenate([G[key][inside] - ours_at[key] for key in keys], axis=1)
    size = evidence.tol.atol + evidence.tol.rtol * np.abs(np.concatenate([ours_at[k] for k in keys], axis=1))
    beyond = np.any(np.abs(error) > size, axis=1)
    if not beyond.any():
        return []
    large = np.flatnonzero(np.any(np.abs(error) > STEP_WINDOW * size, axis=1))
    n = max(5, int(large[0])) if large.size else t.size
    e_s = error[:n].ravel()
    best = None
    for scheme in motion.get("schemes", ("euler",)):
        for h in motion.get("steps", FIXED_STEPS):
            fixed = _run_of(scene.reference(probe, (*source.args, h, scheme), persist=True), motion)
            if fixed is None or fixed[0][-1] < t[n - 1] - 1e-12:
                continue
            t_f, F = fixed
            e_h = np.concatenate([np.column_stack([np.interp(t[:n], t_f, F[key][:, j]) for j in range(F[key].shape[1])])
                                  - ours_at[key][:n] for key in keys], axis=1).ravel()
            if e_h.shape != e_s.shape or not np.any(e_h):
                continue
            scale = float(e_s @ e_h / (e_h @ e_h))
            rest = float(np.linalg.norm(e_s - scale * e_h) / np.linalg.norm(e_s))
            if 0.5 <= scale <= 2.0 and rest <= STEP_SHAPE and (best is None or rest < best[0]):
                best = (rest, scheme, scale * h)
    if best is None:
        return []
    _, scheme, step = best
    words = {"euler": "explicit Euler", "symplectic": "semi-implicit (symplectic) Euler"}.get(scheme, scheme)
    return [_Hypothesis("motion:step", "step_size", 2,
                        f"your run leaves the reference's as a fixed-step {words} integration does, with a step of "
                        f"about {step:.2g} s (its error grows with the step): integrate with "
                        "scipy.integrate.solve_ivp (any method at its default tolerances) or a far smaller step")]


def _interpolated(t, t_r, R):
    """The rows of ``R`` (samples at the times ``t_r``, increasing) linearly interpolated at the times ``t``."""
    k = np.clip(np.searchsorted(t_r, t) - 1, 0, t_r.size - 2)
    w = ((t - t_r[k]) / np.where(t_r[k + 1] > t_r[k], t_r[k + 1] - t_r[k], 1.0))[:, None]
    return (1.0 - w) * R[k] + w * R[k + 1]


def _time_shift(t, G, t_r, R, tol: Tol):
    """The shift ``tau`` (larger than half an output step) that makes the student's run at ``t`` the reference's
    at ``t + tau`` within the tolerance, on the times both cover (half of them at least); None when there is none."""
    span = t_r[-1] - t_r[0]
    if span <= 0 or t.size < 4 or t_r.size < 2:
        return None
    mine = np.concatenate([G[k] for k in G], axis=1)
    ours = np.concatenate([R[k] for k in G], axis=1)

    def residual(tau):
        inside = (t + tau >= t_r[0]) & (t + tau <= t_r[-1])
        if inside.sum() < max(3, t.size // 2):
            return np.inf
        moved = _interpolated(t[inside] + tau, t_r, ours)
        return float(np.max(np.abs(mine[inside] - moved) - (tol.atol + tol.rtol * np.abs(moved))))

    grid = np.linspace(-0.2 * span, 0.2 * span, 81)
    values = [residual(tau) for tau in grid]
    best = int(np.argmin(values))
    if not np.isfinite(values[best]):
        return None
    lo, hi = grid[max(best - 1, 0)], grid[min(best + 1, grid.size - 1)]
    for _ in range(30):
        a, b = lo + (hi - lo) / 3, hi - (hi - lo) / 3
        if residual(a) <= residual(b):
            hi = b
        else:
            lo = a
    tau = 0.5 * (lo + hi)
    step = float(np.median(np.diff(t)))
    return tau if residual(tau) <= 0.0 and abs(tau) > 0.5 * step else None


# ---------------------------------------------------------------------------------------------- explaining


def _sources(ctx, evidence: Evidence) -> None:
    log = getattr(ctx, "calls", ())
    if evidence.source is None:
        evidence.source = locate(log, evidence.raw_expected, "reference", evidence.tol)
    if evidence.student is None:
        evidence.student = locate(log, evidence.raw_got, "student")


def _second_input(scene: _Scene, evidence: Evidence) -> Evidence | None:
    """The same comparison on an input the engine draws (the probe's declared angles, vectors, rotations and
    scalars drawn anew): the student's value there and the reference's, or None."""
    source, student = evidence.source, evidence.student
    if source is None or student is None or source.probe != student.probe:
        return None
    if not _equal_args(source.args, student.args):
        return None
    decl = declaration(source.probe)
    if decl is None or decl.motion:
        return None
    args = _redraw(decl, source.args, scene.draw_seed(source))
    if args is None:
        return None
    expected_root = scene.reference(source.probe, args)
    try:
        got_root = scene.student(source.probe, args)
    except StudentFault:
        return None
    expected, got = _array(_at(expected_root, source.path)), _array(_at(got_root, student.path))
    if expected is None or got is None or got.shape != expected.shape:
        return None
    return Evidence(got, expected, evidence.tol, evidence.name, None, None,
                    Source(source.probe, tuple(args), source.path, expected_root),
                    Source(source.probe, tuple(args), student.path, got_root))


def _equal_args(a, b) -> bool:
    from .oracle import call_key

    try:
        return call_key("", tuple(a)) == call_key("", tuple(b))
    except Exception:  # noqa: BLE001
        return False


def _candidates(decl: Declaration, args) -> list:
    """The arguments the test of an ignored argument changes: the first four declared numbers (angles and scalars:
    a constant written in their place; a vector or a rotation that changes nothing points to a term left out,
    which the other slips name)."""
    return [(path, role, value) for path, role, value in _leaves(decl.args, list(args))
            if role in ("angle", "scalar") and len(path) == 1][:4]


def _perturbations(decl: Declaration, args) -> list:
    """The arguments of the test of an ignored argument, one changed at a time."""
    if decl.motion:
        return []
    out = []
    for path, _, value in _candidates(decl, args):
        changed = _perturbed(value)
        if changed is not None:
            out.append(_replace(tuple(args), path, changed))
    return out


def _ignored(scene: _Scene, evidence: Evidence) -> list:
    """An argument the student's function ignores: their value stays the same when the argument changes (every
    declared argument changes the reference's value)."""
    source, student = evidence.source, evidence.student
    if source is None or student is None or not _equal_args(source.args, student.args):
        return []
    decl = declaration(source.probe)
    if decl is None or decl.motion:
        return []
    leaves = _candidates(decl, source.args)
    found = []
    for path, role, value in leaves:
        changed = _perturbed(value)
        if changed is None:
            continue
        args = _replace(source.args, path, changed)
        theirs = _array(_at(scene.reference(source.probe, args), source.path))
        if theirs is None or theirs.shape != evidence.expected.shape \
                or not _distinct(theirs, evidence.expected, evidence.tol):
            continue  # the reference's value does not depend on it either
        try:
            other = _array(_at(scene.student(source.probe, args), student.path))
        except StudentFault:
            continue
        if other is not None and other.shape == evidence.got.shape and _within(other, evidence.got, evidence.tol):
            found.append(_Hypothesis(f"ignored:{path}", "ignored_argument", 3,
                                     f"your value does not change when {_label(decl, path)} does: the function "
                                     f"ignores it"))
    if len(leaves) > 1 and len(found) == len(leaves):  # nothing changes it: no use of the input at all
        return [_Hypothesis("ignored:all", "constant_answer", 3, "your value does not change when any of the "
                            f"arguments ({', '.join(_label(decl, p) for p, _, _ in leaves)}) does")]
    return found


def _keep(inputs: list, keys) -> list:
    """The hypotheses (keys) that reproduce the student's value on every input and give a value clearly other than
    the expected one, and clearly other than zero (which a loose tolerance lets a small value match), on one of them
    at least."""
    kept = []
    for key in keys:
        if not all(key in one.predicted for one in inputs):
            continue
        values = [one.predicted[key] for one in inputs]
        if not all(_within(one.evidence.got, v, one.evidence.tol) for one, v in zip(inputs, values)):
            continue
        if not any(_distinct(v, one.evidence.expected, one.evidence.tol) for one, v in zip(inputs, values)):
            continue
        if not any(_distinct(v, np.zeros_like(v), one.evidence.tol) for one, v in zip(inputs, values)):
            continue
        kept.append(inputs[0].hypotheses[key])
    return kept


def explain(ctx, evidences: list) -> Finding | None:
    """Name the cause of a failing comparison from its ``evidences`` (the input shown first; a randomized
    comparison gives its second failing input too), or None.  ``ctx`` is the grading context (its oracle, its
    child, its log of calls)."""
    evidences = [e for e in evidences if e is not None]
    if not evidences or not ENABLED:
        return None
    scene = _Scene(ctx)
    try:
        return _explain(scene, evidences)
    except (_Budget, GraderFault):
        return None
    except Exception:  # noqa: BLE001 - a defect of the engine never costs the student the failure's message
        if STRICT:
            raise
        return None


def _explain(scene: _Scene, evidences: list) -> Finding | None:
    for evidence in evidences:
        _sources(scene.ctx, evidence)
    first = evidences[0]
    run = first if _is_run(first) else _run_in_log(scene.ctx, first)
    found: list[_Hypothesis] = []
    if run is not None:
        decl = Declaration(motion=run.motion) if run.motion else declaration(run.source.probe)
        steps = _step_size(scene, run, decl)
        found += steps + [h for h in _motion_hypotheses(run, decl) if not (steps and h.name.startswith("event"))]
    if first.source is None:  # a value derived from the student's own: the engine names no cause for it
        return _finding(found, "here")
    decl = declaration(first.source.probe)
    constants = _constants(scene, decl, first.source.args) if decl is not None else {}
    if len(evidences) == 1 and decl is not None and not decl.motion:
        second = _second_input(scene, first)
        if second is not None:
            evidences = [first, second]
    inputs = [_predict(scene, e, constants) for e in evidences]
    if len(inputs) == 1:
        inputs[0] = _single(inputs[0])
    found += _keep(inputs, list(inputs[0].predicted))
    found += _term_hypotheses(inputs)
    if all(_same_shape(e) for e in evidences) and not (decl is not None and decl.motion):
        found += _precision(first.got, first.expected, first.tol)
    if not found or min(h.cost for h in found) >= 3:
        found += _ignored(scene, evidences[0])
    return _finding(found, "on the input shown and on a second one" if len(evidences) > 1 else "here")


def _is_run(evidence: Evidence) -> bool:
    if evidence.motion:
        return evidence.source is not None and evidence.student is not None
    decl = declaration(evidence.source.probe) if evidence.source is not None else None
    return decl is not None and bool(decl.motion) and evidence.student is not None


def _run_in_log(ctx, evidence: Evidence) -> Evidence | None:
    """The run behind a failing comparison of a check of a run that compares some other value (a constraint along
    the run, an end effector's position): the last probe of the check's log that declares ``motion`` and was asked
    of the reference and of the student with the same arguments, judged with the comparison's tolerance."""
    from .oracle import call_key

    calls = getattr(ctx, "calls", ())
    students = dict(getattr(ctx, "runs", {}))
    for side, probe, args, value in reversed(calls):
        decl = declaration(probe)
        if side != "reference" or decl is None or not decl.motion:
            continue
        theirs = students.get(call_key(probe, tuple(args)))
        if theirs is not None:
            return Evidence(evidence.got, evidence.expected, evidence.tol, evidence.name, None, None,
                            Source(probe, tuple(args), (), value), Source(probe, tuple(args), (), theirs))
    return None


def remember_run(ctx, probe: str, args: tuple, value) -> None:
    """Keep the student's runs (the values of probes that declare ``motion``) on the grading context for the
    problem's later checks, which may compare the run that an earlier check asked for."""
    decl = declaration(probe)
    if decl is not None and decl.motion:
        from .oracle import call_key

        ctx.__dict__.setdefault("runs", {})[call_key(probe, tuple(args))] = value


def _same_shape(evidence: Evidence) -> bool:
    return evidence.got.shape == evidence.expected.shape


def _single(one: _Input) -> _Input:
    """With a single input (nothing to draw), only hypotheses whose value is clearly another than the expected one
    are kept: a near-degenerate input tells little."""
    ev = one.evidence
    for key in list(one.predicted):
        if not _distinct(one.predicted[key], ev.expected, ev.tol):
            del one.predicted[key]
    return one


def _finding(found: list, where: str) -> Finding | None:
    """The simplest hypotheses found, by name, and the hint that says what they are and where they hold."""
    if not found:
        return None
    cost = min(h.cost for h in found)
    simplest = [h for h in found if h.cost == cost]
    by_name: dict[str, list[_Hypothesis]] = {}
    for h in simplest:
        by_name.setdefault(h.name, []).append(h)
    names = tuple(by_name)
    if len(names) == 1:
        name = names[0]
        details = "; ".join(dict.fromkeys(h.detail for h in by_name[name]))
        hint = f"Looks like {DIAGNOSES[name].student}: {details}. This reproduces your answer {where}."
        return Finding(names, hint)
    lines = [f"- {DIAGNOSES[name].student}: {'; '.join(dict.fromkeys(h.detail for h in hs))}"
             for name, hs in by_name.items()]
    hint = (f"Could be {' or '.join(DIAGNOSES[n].student for n in names)}: each reproduces your answer {where}.\n"
            + "\n".join(lines))
    return Finding(names, hint)


# ---------------------------------------------------------------------------------------------- recording the key


def recording(ctx) -> None:
    """While the kit's answer key is recorded, every comparison of a declared probe's value makes the engine's
    reference calls for it (``prepare``); ``ctx`` is the recording context of the check that runs (None: none)."""
    from .checking import _RECORDING

    _RECORDING.ctx = ctx


def note_comparison(ctx, expected, tol: Tol | None = None) -> None:
    """A comparison with ``expected`` (within ``tol``) is made while the key is recorded: prepare the engine's calls
    for the probe call it came from, found as ``explain`` finds it (only the calls of declared probes are
    searched)."""
    declared = [entry for entry in getattr(ctx, "calls", ()) if declaration(entry[1]) is not None]
    if not declared:
        return
    source = locate(declared, expected, "reference", tol if isinstance(tol, Tol) else None)
    if source is None:
        return
    seen = ctx.__dict__.setdefault("_engine_prepared", set())
    from .oracle import call_key

    key = call_key(source.probe, source.args)
    if key in seen:
        return
    seen.add(key)
    prepare(ctx, source)


def prepared(ctx, probe: str, args: tuple) -> None:
    """While the key is recorded: a run (a probe that declares ``motion``) is compared by the checks' own code
    rather than a comparison of its value, so the engine's calls for it are made as soon as it is asked for."""
    decl = declaration(probe)
    if decl is None or not decl.motion:
        return
    from .oracle import call_key

    key = call_key(probe, args)
    seen = ctx.__dict__.setdefault("_engine_prepared", set())
    if key not in seen:
        seen.add(key)
        prepare(ctx, Source(probe, tuple(args), ()))


def prepare(ctx, source: Source) -> None:
    """Make every reference call the engine may need to explain a failing comparison with a value of ``source``'s
    call: its inputs transformed, its terms, the problem's constants, and a second input drawn with its own
    variants (the kit's key then holds them)."""
    decl = declaration(source.probe)
    if decl is None:
        return
    scene = _Scene(ctx)
    try:
        _constants(scene, decl, source.args)
        for _, args in _inputs(decl, source.args):
            scene.reference(source.probe, args)
        for args in _perturbations(decl, source.args):
            scene.reference(source.probe, args)
        if decl.terms:
            scene.reference(decl.terms, source.args)
        if decl.motion.get("fixed_step"):
            for scheme in decl.motion.get("schemes", ("euler",)):
                for h in decl.motion.get("steps", FIXED_STEPS):
                    scene.reference(decl.motion["fixed_step"], (*source.args, h, scheme), persist=True)
        if not decl.motion and not getattr(ctx, "randomized", False):
            args = _redraw(decl, source.args, scene.draw_seed(source))
            if args is not None:
                scene.reference(source.probe, args)
                for _, variant in _inputs(decl, args):
                    scene.reference(source.probe, variant)
                if decl.terms:
                    scene.reference(decl.terms, args)
    except _Budget:
        pass
