"""The engine's access to the reference (through the grading context's oracle) and to the student's code, with
budgets on both, and the problem's named constants."""

from __future__ import annotations

import zlib
from contextlib import nullcontext

import numpy as np

from ..errors import GraderFault, StudentFault
from . import trace
from .evidence import array_of, at, call_key, Declaration, Evidence, part_of, Source, text_key
from .grammar import EARTH_GRAVITY, label_of, leaves_of

__all__ = [
    "MAX_REFERENCE_CALLS",
    "MAX_STUDENT_CALLS",
    "STUDENT_TIMEOUT",
    "Budget",
    "Scene",
    "constants_of",
    "evidence_at",
]


#: the distinct reference calls one explanation may make (inputs transformed, terms, a second input and its
#: variants); a call asked again (the same input slips of the results of one call, explained one by one) is
#: answered from the scene and not counted twice
MAX_REFERENCE_CALLS = 80
#: the student's calls one explanation may make (a second input, an argument changed, the formula tier's third
#: input); the later tiers are heard where an earlier one explained the answer, and the test of an ignored argument
#: (``engine.IGNORED_CALLS`` at most, leaving one) with the formula tier's third input then both ask
MAX_STUDENT_CALLS = 8
#: how long one of the engine's calls of the student's code may take [s]
STUDENT_TIMEOUT = 5.0


class Budget(Exception):
    """The engine ran out of calls: what it found so far is not enough to name a cause."""


class Scene:
    """The engine's access to the reference (through the grading context's oracle) and to the student's code, with
    its budgets."""

    def __init__(self, ctx):
        self.ctx = ctx
        self.reference_calls = 0
        self.student_calls = 0
        self._answers: dict[str, tuple] = {}  # call key -> (value, None) or (None, the grader fault it raised)

    def reference(self, probe: str, args: tuple, persist: bool = False):
        try:
            key = call_key(probe, tuple(args))
        except Exception:  # noqa: BLE001 - arguments that cannot be keyed are asked every time
            key = None
        if key is not None and key in self._answers and not persist:
            value, fault = self._answers[key]
            if fault is not None:
                raise fault
            return value
        if key is None or key not in self._answers:
            self.reference_calls += 1
            if self.reference_calls > MAX_REFERENCE_CALLS:
                raise Budget(f"{MAX_REFERENCE_CALLS} reference calls")
        oracle = self.ctx.oracle
        asking = getattr(oracle, "diagnosing", None)  # a value the diagnosis needs: the kit's key holds it in full
        try:
            with asking() if asking is not None else nullcontext():
                value = oracle.reference(probe, tuple(args), persist, check=self.ctx.check_id)
        except GraderFault as exc:
            if key is not None:
                self._answers[key] = (None, exc)
            raise
        if key is not None:
            self._answers[key] = (value, None)
        return value

    def reference_at(self, probe: str, args: tuple, path: tuple):
        """The reference's value at ``path`` of ``probe(*args)`` (an array, or None), with the live reference through
        the cheaper call the probe declares to hold it (``part``); the student kit's key holds the probe's own
        calls."""
        part = part_of(Source(probe, tuple(args), tuple(path))) if getattr(self.ctx.oracle, "mode", "") == "live" \
            else None
        if part is not None:
            probe, args = part
        return array_of(at(self.reference(probe, args), path))

    def student_at(self, probe: str, args: tuple, path: tuple):
        """The student's value at ``path`` of ``probe(*args)`` (an array, or None), through the cheaper call the
        probe declares to hold it (``part``), as ``reference_at`` takes the reference's: the probe's own code makes
        the part's value alike from any package's functions."""
        part = part_of(Source(probe, tuple(args), tuple(path)))
        if part is not None:
            probe, args = part
        return array_of(at(self.student(probe, args), path))

    def student(self, probe: str, args: tuple):
        self.student_calls += 1
        if self.student_calls > MAX_STUDENT_CALLS:
            raise Budget(f"{MAX_STUDENT_CALLS} student calls")
        return self.ctx.child.call(probe, *args, timeout=STUDENT_TIMEOUT)

    def draw_seed(self, source: Source) -> list:
        """The seed of the engine's own second input for a source: the oracle's draw of a site named after the
        call (live from the run's seed; in the kit the draw recorded with the key)."""
        site = f"{self.ctx.check_id}~engine~{zlib.crc32(text_key(source.probe, source.args).encode()):08x}"
        drawn = self.ctx.oracle.draw(site, lambda rng: [int(x) for x in rng.integers(0, 2**32, 2)],
                                     self.ctx.seed, check=self.ctx.check_id)
        return [int(x) for x in drawn]


#: the course's constants a value of any problem may be scaled by: the Earth's gravity of the course (a force
#: multiplied by g once more, a gravity vector normalised to its direction)
COURSE_CONSTANTS = {"g": EARTH_GRAVITY}


def constants_of(scene: Scene, decl: Declaration | None, args: tuple) -> dict:
    """The problem's named constants a value may be scaled by: the declared scalar arguments (a mass, g, a length:
    by their names), the numbers of the declared probe of constants, and the course's (``COURSE_CONSTANTS``) where
    none of those is one of them."""
    found = {}
    for path, role, value in leaves_of(decl.args, list(args)) if decl is not None else ():
        array = array_of(value)
        if role == "scalar" and len(path) == 1 and array is not None and array.ndim == 0:
            found[label_of(decl, path)] = float(array)
    if decl is not None and decl.constants:
        value = scene.reference(decl.constants, ())
        for key, item in (value.items() if isinstance(value, dict) else ()):
            if isinstance(item, (int, float)) and not isinstance(item, bool) and np.isfinite(item):
                found.setdefault(key, float(item))
    for key, item in COURSE_CONSTANTS.items():
        if key not in found and not any(abs(item - other) < 1e-9 for other in found.values()):
            found[key] = item
    return found


def evidence_at(scene: Scene, evidence: Evidence, reference: Source, student: tuple, what: str) -> Evidence | None:
    """The comparison of ``evidence`` at another input: the reference's value there (``reference``, whose root is
    the reference's answer) and the student's, from the call ``student`` (``(probe, args)``), each at its side's
    path of ``evidence``; None where the student's code raises on it (traced under ``what``) or the two values do
    not compare."""
    probe, args = student
    try:
        got_root = scene.student(probe, args)
    except StudentFault:
        trace.note(what, reason="the student's code raised on it")
        return None
    expected = array_of(at(reference.root, evidence.source.path))
    got = array_of(at(got_root, evidence.student.path))
    if expected is None or got is None or got.shape != expected.shape:
        return None
    return Evidence(got, expected, evidence.tol, evidence.name, None, None,
                    Source(reference.probe, tuple(reference.args), evidence.source.path, reference.root),
                    Source(probe, tuple(args), evidence.student.path, got_root))
