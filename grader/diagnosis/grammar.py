"""The grammar of slips on values and arguments: the expected value transformed (transpose, inverse, signs, swaps,
orders of rows, columns, axes and entries, factors, the other frame, rounding) and the arguments transformed
(swapped, as degrees, negated, transposed, in the other frame), the arguments changed one at a time (an argument
ignored) and a second input drawn from the declared roles.  A value typed into answers.toml has one input and
nothing behind it to vary: the output slips alone explain it, where it holds many numbers (``typed_slips``)."""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from ..values import Tol
from .evidence import array_of, at, Declaration, distinct, equal, Evidence, Hypothesis, within

__all__ = [
    "Equivalence",
    "EQUIVALENCES",
    "kinds_of",
    "equivalents",
    "ENTRYWISE",
    "EARTH_GRAVITY",
    "FACTORS",
    "UNIT_FACTORS",
    "ARGUMENT_FACTORS",
    "output_slips",
    "precision_slips",
    "TYPED_NUMBERS",
    "typed_slips",
    "leaves_of",
    "replaced",
    "label_of",
    "rotation_of",
    "input_slips",
    "perturbed",
    "changed_how",
    "unturned",
    "moved",
    "IGNORED_ARGUMENTS",
    "IGNORED_ROLES",
    "ignore_candidates",
    "perturbations",
    "redraw",
    "DRAWN_ENTRIES",
    "varied",
    "second_args",
]


#: arrays with more entries than this are not searched entry by entry (signs, swaps)
ENTRYWISE = 36
#: the other simple factors a whole value may be off by (a formula's 1/3 for 1/12, semi-axes for full axes, a
#: square root of 2, a turn in radians): (factor, how it is written)
FACTORS = (
    (3.0, "3"), (1 / 3, "1/3"), (4.0, "4"), (0.25, "1/4"), (6.0, "6"), (1 / 6, "1/6"), (12.0, "12"), (1 / 12, "1/12"),
    (np.sqrt(2.0), "sqrt(2)"), (1 / np.sqrt(2.0), "1/sqrt(2)"), (np.sqrt(3.0), "sqrt(3)"),
    (1 / np.sqrt(3.0), "1/sqrt(3)"), (np.pi, "pi"), (1 / np.pi, "1/pi"), (2 * np.pi, "2 pi"),
    (1 / (2 * np.pi), "1/(2 pi)"),
)
#: the Earth's gravity of the course, as a student types it [m/s^2]: a value may be off by it (a force multiplied by
#: g once more), and a gravity given may be read as it
EARTH_GRAVITY = 9.81
#: the factors of a unit a whole value may be off by (a density in g/cm^3 for kg/m^3, a length in mm for m, a mass in
#: g for kg): (factor, how it is written)
UNIT_FACTORS = ((1000.0, "1000"), (1e-3, "1/1000"))
#: the factors a number among the arguments may be off by (a full length for a half, a diameter for a radius)
ARGUMENT_FACTORS = ((2.0, "twice"), (0.5, "half"))
#: an array of more numbers than this among the arguments is data (a table, a time grid) that the general draw keeps
DRAWN_ENTRIES = 64
#: a monotonic run of at least this many numbers is a grid (times, steps) that the general draw keeps
GRID_ENTRIES = 8
#: the general draw scales a number by exp(+-u), u drawn in this range: clearly another value, of the same sign
DRAWN_SPREAD = (0.15, 0.45)
#: the general draw turns a rotation by an angle in this range [rad] about a drawn axis
DRAWN_TURN = (0.3, 0.9)


@dataclass(frozen=True)
class Equivalence:
    """Two slips that give one value by mathematics wherever the value (or the expression) is of ``kind``: what
    the student did cannot be told from the value, so a slip ``seen`` is told with its twin ``also`` ("could be X
    or Y"), whichever tier saw it."""

    seen: str  # the diagnosis of the slip a tier finds
    kind: str  # what the value or the expression must be (``kinds_of``; the formula tier's own: "cross")
    also: str  # the diagnosis of the twin slip
    detail: str  # what the twin is, for the hint


#: the slips that are one value by mathematics, declared once for every tier: a rotation transposed is the
#: rotation of the negated angle (or of the angular velocity integrated backwards); a skew matrix transposed is its
#: negative; a cross product (an antisymmetric product) with its operands exchanged is its negative, as a whole
#: difference with the opposite sign is the difference of its operands exchanged
EQUIVALENCES = (
    Equivalence("transpose", "rotation", "angle_sign",
                "a rotation transposed is the rotation the other way: an angle or an angular velocity with the "
                "opposite sign gives it"),
    Equivalence("transpose", "skew", "sign_flip", "a skew matrix transposed is the skew matrix negated"),
    Equivalence("sign_flip", "skew", "transpose", "a skew matrix negated is the skew matrix transposed"),
    Equivalence("sign_flip", "cross", "factor_order",
                "a cross product with the opposite sign is the cross product of its operands exchanged"),
)
#: how far a matrix may be from orthogonal, or from skew, and still be one (relative to its size)
KIND_TOL = 1e-9


def kinds_of(value) -> frozenset:
    """What a value is among the kinds of ``EQUIVALENCES``: "rotation" (a proper orthogonal matrix), "skew" (a
    nonzero skew-symmetric matrix)."""
    E = array_of(value)
    if E is None or E.ndim != 2 or E.shape[0] != E.shape[1] or E.shape[0] < 2 or not np.all(np.isfinite(E)):
        return frozenset()
    kinds = set()
    n = E.shape[0]
    if np.max(np.abs(E.T @ E - np.eye(n))) < KIND_TOL * n and np.linalg.det(E) > 0:
        kinds.add("rotation")
    scale = np.max(np.abs(E))
    if scale > 0 and np.max(np.abs(E + E.T)) <= KIND_TOL * scale:
        kinds.add("skew")
    return frozenset(kinds)


def equivalents(hypothesis: Hypothesis, kinds) -> list:
    """The twins of ``hypothesis`` (``EQUIVALENCES``) on a value or an expression of ``kinds``: hypotheses of the
    same key, cost and value under the other name."""
    return [Hypothesis(f"{hypothesis.key}={e.also}", e.also, hypothesis.cost, e.detail, twin=True)
            for e in EQUIVALENCES if e.seen == hypothesis.name and e.kind in kinds]


def _ordinal(i: int) -> str:
    return f"{i + 1}"


def output_slips(E: np.ndarray, constants: dict, rotation, got=None) -> list:
    """``(hypothesis, value)`` of the output slips of an expected value ``E``; ``got``: the student's value, where
    it may tell a vector's entries in another order than two exchanged (``_reordered``)."""
    out = []
    kinds = kinds_of(E)

    def add(slip, whole: bool = False):
        """A slip; a slip of the whole value with its twins (a row's sign of a skew matrix is no transpose)."""
        out.append(slip)
        if whole:
            out.extend((twin, slip[1]) for twin in equivalents(slip[0], kinds))

    if E.ndim == 2 and E.shape[0] == E.shape[1] and E.shape[0] > 1:
        add((Hypothesis("transpose", "transpose", 1, "your matrix is the transpose of the expected one"), E.T), True)
        if np.linalg.cond(E) < 1e8:
            add((Hypothesis("inverse", "inverse", 2, "your matrix is the inverse of the expected one"),
                 np.linalg.inv(E)))
    if E.size == 1 and abs(float(E.ravel()[0])) > 1e-9:
        add((Hypothesis("inverse", "inverse", 2, "your value is the reciprocal of the expected one"), 1.0 / E))
    add((Hypothesis("sign", "sign_flip", 1, "your value is the expected one with the opposite sign"), -E), True)
    for factor, name, words in ((2.0, "factor_two", "twice"), (0.5, "factor_half", "half")):
        add((Hypothesis(f"scale:{factor}", name, 1, f"your value is {words} the expected one"), factor * E))
    for factor, words in FACTORS:
        add((Hypothesis(f"scale:{words}", "wrong_factor", 2, f"your value is the expected one times {words}"),
             factor * E))
    for factor, words in UNIT_FACTORS:
        add((Hypothesis(f"scale:unit:{words}", "wrong_factor", 2, f"your value is the expected one times {words}: "
                         "a quantity in other units (g/cm^3 for kg/m^3, mm for m, g for kg)"), factor * E))
    add((Hypothesis("scale:deg", "degrees", 1, "your value is the expected one converted to degrees (times "
                     "180/pi)"), E * 180.0 / np.pi))
    add((Hypothesis("scale:rad", "degrees", 1, "your value is the expected one times pi/180 (converted from "
                     "degrees once too often)"), E * np.pi / 180.0))
    for cname, c in constants.items():
        if abs(c) > 1e-12 and not any(abs(abs(c) - v) < 1e-9 for v in (1.0, 2.0, 0.5)):
            mass = cname in ("m", "mass")  # a value without its mass: the vocabulary's missing_mass
            add((Hypothesis(f"const:*{cname}", "constant_factor", 2,
                             f"your value is the expected one times {cname} = {c:.6g}"), E * c))
            add((Hypothesis(f"const:/{cname}", "missing_mass" if mass else "constant_factor", 2,
                             f"your value is the expected one divided by {cname} = {c:.6g}"), E / c))
    if E.ndim == 2 and E.size <= ENTRYWISE:
        rows, cols = E.shape
        for i in range(rows if rows > 1 else 0):
            value = E.copy()
            value[i] *= -1
            add((Hypothesis(f"sign:row:{i}", "sign_flip", 2, f"row {_ordinal(i)} has the opposite sign"), value))
        for j in range(cols if cols > 1 else 0):
            value = E.copy()
            value[:, j] *= -1
            add((Hypothesis(f"sign:col:{j}", "sign_flip", 2, f"column {_ordinal(j)} has the opposite sign"),
                 value))
        for i, j in itertools.combinations(range(rows), 2):
            value = E.copy()
            value[[i, j]] = value[[j, i]]
            add((Hypothesis(f"swap:row:{i}:{j}", "swapped", 2, f"rows {_ordinal(i)} and {_ordinal(j)} are "
                             "swapped"), value))
        for i, j in itertools.combinations(range(cols), 2):
            value = E.copy()
            value[:, [i, j]] = value[:, [j, i]]
            add((Hypothesis(f"swap:col:{i}:{j}", "swapped", 2, f"columns {_ordinal(i)} and {_ordinal(j)} are "
                             "swapped"), value))
        for index in np.ndindex(E.shape):
            value = E.copy()
            value[index] *= -1
            add((Hypothesis(f"sign:entry:{index}", "sign_flip", 3,
                             f"the entry [{','.join(map(str, index))}] has the opposite sign"), value))
        for shift in (1, 2) if rows == 3 else ():
            add((Hypothesis(f"swap:row:cyclic:{shift}", "swapped", 3, "the rows are permuted cyclically"),
                 np.roll(E, shift, axis=0)))
        for shift in (1, 2) if cols == 3 else ():
            add((Hypothesis(f"swap:col:cyclic:{shift}", "swapped", 3, "the columns are permuted cyclically (the "
                             "axes in another order)"), np.roll(E, shift, axis=1)))
        if rows == cols:  # a tensor's axes in another order: its rows and its columns alike (P E P.T)
            for i, j in itertools.combinations(range(rows), 2):
                order = list(range(rows))
                order[i], order[j] = j, i
                add((Hypothesis(f"swap:axes:{i}:{j}", "axis_order", 2, f"axes {_ordinal(i)} and {_ordinal(j)} are "
                                 "exchanged (rows and columns alike: the moments and products of another order)"),
                     E[np.ix_(order, order)]))
            if rows == 3:
                for shift in (1, 2):
                    order = list(np.roll(np.arange(3), shift))
                    add((Hypothesis(f"swap:axes:cyclic:{shift}", "axis_order", 3, "the axes are permuted cyclically "
                                     "(rows and columns alike)"), E[np.ix_(order, order)]))
    if E.ndim == 1 and 1 < E.size <= ENTRYWISE:
        for i in range(E.size):
            value = E.copy()
            value[i] *= -1
            add((Hypothesis(f"sign:entry:{i}", "sign_flip", 2, f"entry {_ordinal(i)} has the opposite sign"),
                 value))
        for i, j in itertools.combinations(range(E.size), 2):
            value = E.copy()
            value[[i, j]] = value[[j, i]]
            add((Hypothesis(f"swap:entry:{i}:{j}", "swapped", 2, f"entries {_ordinal(i)} and {_ordinal(j)} are "
                             "swapped"), value))
        if E.size > 2:
            add((Hypothesis("swap:reversed", "swapped", 2, "the entries are in reverse order"), E[::-1].copy()))
        if E.size == 3:
            for shift in (1, 2):
                add((Hypothesis(f"swap:cyclic:{shift}", "swapped", 3, "the axes are permuted cyclically"),
                     np.roll(E, shift)))
        if E.size >= 4 and E.size % 2 == 0:  # ``(qd, q)`` for ``(q, qd)``: named even where entries repeat (zeros)
            add((Hypothesis("swap:halves", "swapped", 3, "its two halves are exchanged (the second half's entries "
                             "first: the rates where the coordinates belong, say)"), np.roll(E, E.size // 2)))
        order = _reordered(got, E) if got is not None and E.size > 3 else None
        if order is not None and not (E.size % 2 == 0 and list(order) == np.roll(np.arange(E.size), E.size // 2)
                                      .tolist()):  # the halves exchanged are named so above
            moved = ", ".join(f"{_ordinal(k)} holds the expected {_ordinal(j)}" for k, j in enumerate(order) if k != j)
            add((Hypothesis(f"swap:order:{','.join(map(str, order))}", "swapped", 3,
                             f"the entries are in another order (entry {moved})"), E[list(order)].copy()))
    if rotation is not None:
        A = rotation
        if E.shape == (3,):
            add((Hypothesis("frame:A", "wrong_frame", 2, "your vector is the expected one mapped with the "
                             "problem's rotation A (the other frame's coordinates)"), A @ E))
            add((Hypothesis("frame:AT", "wrong_frame", 2, "your vector is the expected one mapped with A.T "
                             "(the other frame's coordinates)"), A.T @ E))
        elif E.shape == (3, 3):
            add((Hypothesis("frame:A", "wrong_frame", 2, "your matrix is the expected one in the other frame "
                             "(A X A.T)"), A @ E @ A.T))
            add((Hypothesis("frame:AT", "wrong_frame", 2, "your matrix is the expected one in the other frame "
                             "(A.T X A)"), A.T @ E @ A))
    return out


#: how far apart (relative to the largest entry) a vector's entries must be for ``_reordered`` to tell which went
#: where
REORDER_GAP = 1e-3


def _reordered(got, E: np.ndarray):
    """The order of ``E``'s entries that the student's vector ``got`` holds (``got[k] = E[order[k]]`` to
    ``REORDER_GAP``), where three entries or more moved and no exchange of two or reversal gives it (those are
    slips of their own); None otherwise.  Each moved entry must be told apart from every other entry of ``E``, so
    that the order is the only one: entries of equal size stay where they are."""
    got = array_of(got)
    if got is None or got.shape != E.shape or E.ndim != 1:
        return None
    scale = float(np.max(np.abs(E))) if E.size else 0.0
    if scale == 0.0:
        return None
    gap = REORDER_GAP * scale
    order = []
    for k in range(E.size):
        if abs(got[k] - E[k]) <= gap:
            order.append(k)
            continue
        near = np.flatnonzero(np.abs(E - got[k]) <= gap)
        if near.size != 1 or np.sum(np.abs(E - E[near[0]]) <= 10 * gap) != 1:
            return None
        order.append(int(near[0]))
    if sorted(order) != list(range(E.size)):
        return None
    moved = [k for k, j in enumerate(order) if k != j]
    if len(moved) < 3 or order == list(range(E.size))[::-1]:
        return None
    return tuple(order)


#: the significant digits a rounding keeps of the answer's largest value for a student to have written it: values of
#: order 1 rounded to 0 decimals keep one digit or none, and many wrong answers (an offset, a factor) land on them
ROUNDED_DIGITS = 2


def precision_slips(got, E, tol: Tol) -> list:
    """Rounding slips: the student's value is the expected one in float32, or rounded to a few decimals that keep at
    least ``ROUNDED_DIGITS`` significant digits of the largest value."""
    found = []
    single = E.astype(np.float32).astype(float)
    if (np.all(got == got.astype(np.float32).astype(float)) and not np.all(E == single)
            and np.all(np.abs(got - E) <= 4 * np.finfo(np.float32).eps * np.maximum(np.abs(E), 1e-30))
            and not within(got, E, tol)):
        found.append(Hypothesis("float32", "float32", 1, "your values are the expected ones in single precision "
                                 "(float32): compute in float64 (numpy's default)"))
    largest = float(np.max(np.abs(E))) if E.size else 0.0
    for decimals in range(0, 7):
        rounded = np.round(E, decimals)
        if not np.any(rounded):
            continue  # rounded to nothing: an answer of zeros has not rounded anything
        if largest * 10.0 ** decimals < 10.0 ** (ROUNDED_DIGITS - 1):
            continue  # a rounding that keeps fewer digits than a student writes is a coincidence, not a slip
        if largest < 10.0 ** (ROUNDED_DIGITS - 1) and np.all(rounded == np.round(rounded)):
            continue  # whole numbers alone (a rotation's 0 and 1): rounded to no decimal, too few digits as well
        if np.all(np.abs(got - rounded) <= 1e-12 * np.maximum(1.0, np.abs(E))) and not within(rounded, E, tol):
            found.append(Hypothesis(f"rounded:{decimals}", "rounded", 1,
                                     f"your values are the expected ones rounded to {decimals} decimals: return "
                                     "them unrounded"))
            break
    return found


#: the numbers a typed answer must hold, each clearly other than zero, for the output grammar to explain it
TYPED_NUMBERS = 4


def typed_slips(evidence: Evidence) -> list:
    """The output slips (``output_slips``) that explain a value typed into answers.toml (``Evidence.typed``): no
    call stands behind it, so there is one input and no argument, term or formula to vary.  One input tells a slip
    only where the answer holds many numbers: the key and the slip's value must each have ``TYPED_NUMBERS``
    entries or more beyond the tolerance from zero (a 3 x 3 matrix read off a figure), and the slip must reproduce
    every number of the answer within the tolerance while it moves the key clearly (``evidence.DISTINCT``
    tolerances somewhere).  A scalar or a short vector is explained by nothing here: one number matched by one of
    the grammar's many factors says little, where many slips of the work behind it give a number too."""
    E, got, tol = evidence.expected, evidence.got, evidence.tol
    if E is None or got is None or got.shape != E.shape or not _many(E, tol):
        return []
    return [hypothesis for hypothesis, value in output_slips(E, {}, None)
            if value.shape == got.shape and within(got, value, tol) and distinct(value, E, tol) and _many(value, tol)]


def _many(value: np.ndarray, tol: Tol) -> bool:
    """``value`` holds ``TYPED_NUMBERS`` entries or more beyond the tolerance from zero."""
    return int(np.count_nonzero(np.abs(value) > tol.atol + tol.rtol * np.abs(value))) >= TYPED_NUMBERS


def leaves_of(roles, args, path=()):
    """``(path, role, value)`` of every declared argument (roles may be nested like the arguments: a dict of roles
    for a dict argument)."""
    if isinstance(roles, dict):
        for key, role in roles.items():
            if isinstance(args, dict) and key in args:
                yield from leaves_of(role, args[key], (*path, key))
    elif isinstance(roles, (list, tuple)):
        for i, role in enumerate(roles):
            if isinstance(args, (list, tuple)) and i < len(args):
                yield from leaves_of(role, args[i], (*path, i))
    elif roles:
        yield path, roles, args


def replaced(args, path, value):
    """``args`` with the leaf at ``path`` replaced (copies along the path; the rest shared)."""
    if not path:
        return value
    head, rest = path[0], path[1:]
    if isinstance(args, dict):
        return {**args, head: replaced(args[head], rest, value)}
    items = list(args)
    items[head] = replaced(items[head], rest, value)
    return tuple(items) if isinstance(args, tuple) else items


def label_of(decl: Declaration, path) -> str:
    head = decl.names[path[0]] if path and path[0] < len(decl.names) else f"argument {path[0] + 1}"
    return head + "".join(f"[{k!r}]" for k in path[1:])


def _same_kind(a, b) -> bool:
    """Two arguments that could be swapped: both numbers, or arrays of one shape."""
    first, second = array_of(a), array_of(b)
    return first is not None and second is not None and first.shape == second.shape


def _angle(value, f):
    if isinstance(value, (list, tuple)):
        return [f(float(v)) for v in value]
    array = np.asarray(value, dtype=float)
    return float(f(float(array))) if array.ndim == 0 else f(array)


def _negated(value):
    return [-float(v) for v in value] if isinstance(value, list) else -np.asarray(value, dtype=float)


def rotation_of(decl: Declaration, args):
    if decl.rotation is None:
        return None
    path = decl.rotation if isinstance(decl.rotation, tuple) else (decl.rotation,)
    value = at(list(args), path)
    A = array_of(value)
    if A is None or A.shape != (3, 3) or np.max(np.abs(A.T @ A - np.eye(3))) > 1e-6:
        return None
    return A


#: the slips of every angle at once: ``(key, name, transform, words)``
EVERY_ANGLE = (("deg", "degrees", np.deg2rad, "every angle is used as if it were in degrees (radians are given)"),
               ("neg", "angle_sign", np.negative, "every angle enters with the opposite sign (each rotation the other "
                                                  "way, as if its inverse were built)"))


def input_slips(decl: Declaration, args: tuple) -> list:
    """``(hypothesis, transformed args)`` of the input slips of a declared probe."""
    out = []
    leaves = [(path, role, value) for path, role, value in leaves_of(decl.args, list(args))]
    angles = [(path, value) for path, role, value in leaves if role in ("angle", "angles")]
    for path, value in angles:
        label = label_of(decl, path)
        out.append((Hypothesis(f"in:deg:{path}", "degrees", 2, f"{label} is used as if it were in degrees "
                                "(radians are given)"), replaced(args, path, _angle(value, np.deg2rad))))
        out.append((Hypothesis(f"in:neg:{path}", "angle_sign", 2, f"{label} enters with the opposite sign (a "
                                "rotation the other way)"), replaced(args, path, _angle(value, np.negative))))
    for key, name, f, words in EVERY_ANGLE if len(angles) > 1 else ():
        every = tuple(args)
        for path, value in angles:
            every = replaced(every, path, _angle(value, f))
        out.append((Hypothesis(f"in:{key}:all", name, 2, words), every))
    for (p1, r1, v1), (p2, r2, v2) in itertools.combinations(leaves, 2):
        if r1 == r2 and len(p1) == len(p2) == 1 and _same_kind(v1, v2) and not equal(v1, v2):
            swapped = replaced(replaced(args, p1, v2), p2, v1)
            out.append((Hypothesis(f"in:swap:{p1}:{p2}", "argument_order", 2, f"{label_of(decl, p1)} and "
                                    f"{label_of(decl, p2)} are swapped"), swapped))
    for path, role, value in leaves:
        array = array_of(value)
        if role == "scalar" and len(path) == 1 and array is not None and array.ndim == 0 and float(array) != 0.0:
            for factor, words in ARGUMENT_FACTORS:
                out.append((Hypothesis(f"in:scale:{factor}:{path}", "scaled_argument", 2,
                                       f"{label_of(decl, path)} enters at {words} its value"),
                            replaced(args, path, float(array) * factor)))
            label = label_of(decl, path)
            out.append((Hypothesis(f"in:reciprocal:{path}", "reciprocal_argument", 2,
                                   f"{label} enters as its reciprocal, 1/{label}"),
                        replaced(args, path, 1.0 / float(array))))
    A = rotation_of(decl, args)
    for path, role, value in leaves:
        array = array_of(value)
        if role == "vector" and array is not None and array.size > 1:
            out.append((Hypothesis(f"in:neg:{path}", "sign_flip", 2, f"{label_of(decl, path)} enters with the "
                                    "opposite sign"), replaced(args, path, _negated(value))))
        if role == "rotation" and array is not None and array.shape == (3, 3):
            out.append((Hypothesis(f"in:T:{path}", "transpose", 2, f"{label_of(decl, path)} is used transposed "
                                    "(A_BI for A_IB)"), replaced(args, path, array.T)))
        if role == "vector" and A is not None and array is not None and array.shape == (3,):
            out.append((Hypothesis(f"in:frame:A:{path}", "wrong_frame", 3, f"{label_of(decl, path)} is taken in "
                                    "the other frame (mapped with A)"), replaced(args, path, A @ array)))
            out.append((Hypothesis(f"in:frame:AT:{path}", "wrong_frame", 3, f"{label_of(decl, path)} is taken in "
                                    "the other frame (mapped with A.T)"), replaced(args, path, A.T @ array)))
    return out


#: the test of an ignored argument changes this many declared arguments at most (or, for a probe that declares
#: none, numeric arguments), in the order of the call
IGNORED_ARGUMENTS = 6
#: the roles of declared arguments that the test of an ignored argument changes
IGNORED_ROLES = ("angle", "angles", "scalar", "vector", "rotation", "inertia")
#: the two changes of the test of an ignored argument, independent of each other: a number ``x`` becomes
#: ``a x + b`` (a positive number stays positive, a zero changes), a rotation or a symmetric matrix is turned by
#: ``angle`` about the oblique ``axis`` (``R A`` and ``R A R.T``: a rotation stays one, an inertia keeps its
#: moments and loses its zeros), a unit vector is turned, any other array is scaled by ``a`` (its direction, signs
#: and ratios kept: masses stay positive, their centre where it is), or, where every argument is moved at once,
#: ``a x + b p`` with ``p`` a pattern of one sign (its zeros moved as well)
_CHANGES = (
    {"a": 1.37, "b": 0.29, "axis": (1.0, 2.0, 3.0), "angle": 0.61, "pattern": (0.31, 0.97)},
    {"a": 0.71, "b": 0.17, "axis": (3.0, -1.0, 2.0), "angle": -0.47, "pattern": (0.83, 0.23)},
)


def _oblique(n: int, change: dict) -> np.ndarray:
    c, s = np.cos(change["angle"]), np.sin(change["angle"])
    if n == 2:
        return np.array([[c, -s], [s, c]])
    axis = np.asarray(change["axis"]) / np.linalg.norm(change["axis"])
    K = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + s * K + (1.0 - c) * K @ K


def _kind(array: np.ndarray) -> str:
    """What ``perturbed`` keeps an array: "rotation", "symmetric", "unit", "grid" or "array"."""
    n = array.shape[0] if array.ndim else 0
    if array.ndim == 2 and array.shape == (n, n) and n in (2, 3):
        if np.max(np.abs(array.T @ array - np.eye(n))) < 1e-6:
            return "rotation"
        if np.allclose(array, array.T, rtol=0.0, atol=1e-12 * max(np.max(np.abs(array)), 1e-300)):
            return "symmetric"
    if array.ndim == 1 and array.size >= GRID_ENTRIES and (np.all(np.diff(array) > 0) or np.all(np.diff(array) < 0)):
        return "grid"
    if array.ndim == 1 and array.size > 1 and abs(np.linalg.norm(array) - 1.0) < 1e-9:
        return "unit"
    return "array"


def perturbed(value, change: int = 0, move: bool = False):
    """Another value of an argument, of the same kind (for the test of an ignored argument): the ``change``-th of
    two independent changes (``_CHANGES``; ``move``: an array's zeros moved too, where every argument is moved);
    None for a value that is not numbers, a table, a grid (times), or a value the change leaves as it is."""
    array = array_of(value)
    if array is None or array.size == 0 or array.size > DRAWN_ENTRIES or not np.all(np.isfinite(array)):
        return None
    c = _CHANGES[change]
    if array.ndim == 0:
        return float(array) * c["a"] + c["b"]
    kind = _kind(array)
    if kind == "grid":
        return None
    if kind == "rotation":
        changed = _oblique(array.shape[0], c) @ array
    elif kind == "symmetric":
        R = _oblique(array.shape[0], c)
        changed = R @ array @ R.T
    elif kind == "unit":
        turn = np.linspace(0.2, 0.6, array.size) * (1.0 if change == 0 else -1.0)
        changed = (array + turn) / np.linalg.norm(array + turn)  # a unit vector stays one
    elif move:
        changed = array * c["a"] + c["b"] * np.linspace(*c["pattern"], array.size).reshape(array.shape)
    else:
        changed = array * c["a"]
    if not np.any(np.abs(changed - array) > 1e-12 * np.max(np.abs(array))):
        return None
    return changed.tolist() if isinstance(value, (list, tuple)) else changed


def unturned(role: str, value):
    """The value of an angle (``role`` "angle" or "angles": zero) or of a rotation (the identity) that turns
    nothing, in the value's own form; None for any other argument.  Where a function ignores such an argument and
    gives the reference's value with it unturned, a rotation by it is left out: a slip of the frame as much as an
    argument ignored."""
    array = array_of(value)
    if array is None or not np.all(np.isfinite(array)):
        return None
    if role in ("angle", "angles"):
        zero = np.zeros_like(array, dtype=float)
    elif _kind(array) == "rotation" and np.linalg.det(array) > 0:
        zero = np.eye(array.shape[0])
    else:
        return None
    if not np.any(np.abs(zero - array) > 1e-12):
        return None
    if array.ndim == 0:
        return 0.0
    return zero.tolist() if isinstance(value, (list, tuple)) else zero


def changed_how(value) -> str:
    """How ``perturbed`` changes a value, for the hint: "does" (a number, a symmetric matrix), "turns" (a rotation,
    a direction) or "is scaled" (any other array)."""
    array = array_of(value)
    if array is None or array.ndim == 0:
        return "does"
    return {"rotation": "turns", "unit": "turns", "array": "is scaled"}.get(_kind(array), "does")


def ignore_candidates(decl: Declaration | None, args) -> list:
    """``(path, role, value)``: the arguments the test of an ignored argument changes, at most
    ``IGNORED_ARGUMENTS``: every declared angle, scalar, vector and rotation (a frame given by its rotation, a
    mass, a start), and every other argument that is real numbers (``_numbers``: not a count, a flag or a
    structure; role "")."""
    declared = [(path, role, value) for path, role, value in leaves_of(decl.args, list(args))
                if role in IGNORED_ROLES] if decl is not None and decl.args else []
    taken = {path[0] for path, _, _ in leaves_of(decl.args, list(args))} if decl is not None and decl.args else set()
    found = declared + [((i,), "", value) for i, value in enumerate(args)
                        if i not in taken and _numbers(value) is not None]
    found.sort(key=lambda leaf: leaf[0])
    return [(path, role, value) for path, role, value in found if perturbed(value) is not None][:IGNORED_ARGUMENTS]


def moved(decl: Declaration | None, args) -> tuple | None:
    """``args`` with every argument of the test of an ignored argument changed at once (the second change, zeros
    moved): an input where nothing of the shown one's special values is left (a zero that makes a term vanish, an
    axis an inertia happens to keep); None where nothing changes."""
    out, changed = tuple(args), False
    for path, _, value in ignore_candidates(decl, args):
        new = perturbed(value, 1, move=True)
        if new is not None:
            out, changed = replaced(out, path, new), True
    return out if changed else None


def perturbations(decl: Declaration | None, args) -> list:
    """The arguments of the test of an ignored argument: each changed alone on ``args``, every one moved at once
    (``moved``), and each changed again on the moved input; and, on both, each angle or rotation turning nothing
    (``unturned``: the rival of an angle ignored)."""
    if decl is not None and decl.motion:
        return []
    out = []
    for path, role, value in ignore_candidates(decl, args):
        for changed in (perturbed(value), unturned(role, value)):
            if changed is not None:
                out.append(replaced(tuple(args), path, changed))
    base = moved(decl, args)
    if base is not None:
        out.append(base)
        for path, role, value in ignore_candidates(decl, base):
            for changed in (perturbed(value), unturned(role, value)):
                if changed is not None:
                    out.append(replaced(base, path, changed))
    return out


def _draw_leaf(role, value, rng):
    array = array_of(value)
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
    if role == "inertia" and array.ndim == 2 and array.shape[0] == array.shape[1] in (2, 3):
        n = array.shape[0]
        scale = max(float(np.trace(array)) / n, 1e-12)  # the size of its moments, kept
        moments = scale * rng.uniform(0.5, 1.5, n)
        R = _turn(rng, n)
        return R @ np.diag(moments) @ R.T  # symmetric, definite, its axes other than the shown one's
    if role == "scalar":
        scale = max(abs(float(array.ravel()[0])), 0.1) if array.size else 1.0
        drawn = array * rng.uniform(0.6, 1.6, array.shape) if array.ndim else float(scale * rng.uniform(0.6, 1.6))
        return drawn
    return value


def redraw(decl: Declaration, args: tuple, seed_words) -> tuple | None:
    """A second input like ``args`` with every declared angle, vector, rotation, inertia and scalar drawn anew (None
    when the probe declares nothing to draw)."""
    if not decl.draw:
        return None
    leaves = [(path, role, value) for path, role, value in leaves_of(decl.args, list(args))
              if role in ("angle", "angles", "vector", "rotation", "scalar", "inertia")]
    if not leaves:
        return None
    rng = np.random.default_rng(seed_words)
    drawn = tuple(args)
    for path, role, value in leaves:
        drawn = replaced(drawn, path, _draw_leaf(role, value, rng))
    return drawn


def _factors(rng, shape):
    """Factors clearly other than 1, of either side, one per entry of ``shape``."""
    u = rng.uniform(*DRAWN_SPREAD, shape)
    return np.exp(np.where(rng.random(shape) < 0.5, -u, u))


def _turn(rng, n: int):
    """A rotation of ``n`` dimensions (2 or 3) by an angle of ``DRAWN_TURN``."""
    angle = rng.uniform(*DRAWN_TURN) * rng.choice((-1.0, 1.0))
    c, s = np.cos(angle), np.sin(angle)
    if n == 2:
        return np.array([[c, -s], [s, c]])
    axis = rng.normal(size=3)
    axis /= np.linalg.norm(axis)
    K = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + s * K + (1.0 - c) * K @ K


def _varied_array(a: np.ndarray, rng) -> np.ndarray:
    """Another array of the same kind: a rotation (an orthogonal 2 x 2 or 3 x 3 matrix) turned, a symmetric matrix
    changed by a congruence with a positive diagonal (symmetric, definite where it was, its zeros kept), a unit
    vector changed and normalized, any other array scaled entry by entry (signs and zeros kept); a table or a
    grid kept."""
    if a.size == 0 or a.size > DRAWN_ENTRIES or not np.all(np.isfinite(a)):
        return a
    if a.ndim == 0:
        return a * _factors(rng, ())
    if a.ndim == 1 and a.size >= GRID_ENTRIES and (np.all(np.diff(a) > 0) or np.all(np.diff(a) < 0)):
        return a
    if a.ndim == 2 and a.shape[0] == a.shape[1] and a.shape[0] in (2, 3) \
            and np.max(np.abs(a.T @ a - np.eye(a.shape[0]))) < 1e-9:
        return _turn(rng, a.shape[0]) @ a
    if a.ndim == 2 and a.shape[0] == a.shape[1] > 1 and np.allclose(a, a.T, rtol=0.0, atol=1e-12 * np.max(np.abs(a))):
        D = np.diag(np.sqrt(_factors(rng, a.shape[0])))
        return D @ a @ D
    changed = a * _factors(rng, a.shape)
    if a.ndim == 1 and a.size > 1 and abs(np.linalg.norm(a) - 1.0) < 1e-9:
        return changed / np.linalg.norm(changed)
    return changed


def _numbers(value):
    """The array of a (nested) list or tuple of real numbers with one float at least, or of a float array; else
    None (an integer, a flag, a string, a structure of other things)."""
    if isinstance(value, np.ndarray):
        return value.astype(float) if value.dtype.kind == "f" else None
    if isinstance(value, float):
        return np.asarray(value)
    if not isinstance(value, (list, tuple)) or not value:
        return None
    flat, stack = [], [value]
    while stack:
        item = stack.pop()
        if isinstance(item, (list, tuple)):
            stack.extend(item)
        elif isinstance(item, (bool, np.bool_)) or not isinstance(item, (int, float, np.integer, np.floating)):
            return None
        else:
            flat.append(item)
    if not any(isinstance(x, (float, np.floating)) for x in flat):
        return None
    try:
        return np.asarray(value, dtype=float)
    except ValueError:  # ragged
        return None


def _varied_value(value, rng):
    array = _numbers(value)
    if array is not None:
        changed = _varied_array(array, rng)
        if changed is array or np.array_equal(changed, array):
            return value
        if isinstance(value, np.ndarray):
            return changed
        if isinstance(value, (float, np.floating)):
            return float(changed)
        listed = changed.tolist()
        return tuple(listed) if isinstance(value, tuple) else listed
    if isinstance(value, dict):
        return {key: _varied_value(item, rng) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        items = [_varied_value(item, rng) for item in value]
        return tuple(items) if isinstance(value, tuple) else items
    return value


def varied(args: tuple, seed_words) -> tuple | None:
    """A second input like ``args`` for a probe whose arguments are not declared (or declare nothing to draw): every
    float among them changed but kept what it is (``_varied_array``: a rotation stays a rotation, a symmetric
    matrix symmetric, a positive mass positive, a unit vector a unit vector, a zero a zero), integers, flags,
    strings, tables and the structure untouched; None when nothing changes."""
    rng = np.random.default_rng(seed_words)
    drawn = tuple(_varied_value(item, rng) for item in args)
    from .evidence import call_key

    try:
        return None if call_key("", drawn) == call_key("", tuple(args)) else drawn
    except Exception:  # noqa: BLE001 - arguments that cannot be keyed are not drawn
        return None


def second_args(decl: Declaration | None, args: tuple, seed_words, attempt: int = 0) -> tuple | None:
    """The arguments of the engine's own second input, the ``attempt``-th draw: the declared roles drawn anew
    (``redraw``), else every float of the arguments varied (``varied``); None for a run, a probe that must not be
    drawn (``draw=False``) or arguments that hold no number to change."""
    if decl is not None and (decl.motion or not decl.draw):
        return None
    words = list(seed_words) if attempt == 0 else [*seed_words, attempt]
    if decl is not None:
        drawn = redraw(decl, args, words)
        if drawn is not None:
            return drawn
    return varied(tuple(args), words)
