"""The differential diagnosis engine: names the cause of a failing comparison that no catalogued mistake explains.

When a check's comparison fails and its catalogue of known mistakes has no match, the engine evaluates the
reference under a grammar of common slips on the same inputs and keeps the hypotheses that reproduce the
student's answer within the comparison's tolerance on the input shown *and* on a second, non-degenerate one (the
randomized comparison's second failing input, or an input the engine draws itself: the probe's declared roles
drawn anew, or else every float of its arguments varied but kept what it is, a rotation a rotation, a symmetric
matrix symmetric, a positive mass positive; a draw on which the reference raises or gives a degenerate value is
not used); it ranks them by simplicity and says "looks like X" (one family), "could be X or Y" (two) or nothing
(none, or more than two).  It never names a default cause.  Where it has one array on one input only (nothing to
draw), a slip of a number's size (a factor, a unit, a rounding) is told only where the array differs in
``evidence.ONE_INPUT_NUMBERS`` entries or more: one or two entries among zeros are matched by a factor by chance,
whatever made them (a full length for a half); beside a run's wrong start, which the answer proves, the slips of a
value found on fewer numbers are told as twins: "could be" either.

Every tier is heard (the run's, the outputs', the inputs', the declared terms', the test of an argument ignored,
the formulas'), even where an earlier one explained the answer: a slip that two tiers reproduce alike, with two
families, is told with both rather than with the one the first tier saw (an angular velocity integrated backwards
gives the transpose of the rotation: a transpose to the output tier, a sign to the student).  The rule of rank:

* within a tier the simplest hypotheses outrank the others: its costs compare slips of one kind on the same
  inputs (a whole value's sign before one entry's), and the named sets are told rightly so;
* across tiers no hypothesis outranks a rival for being simpler: the tiers' costs measure different things (an
  output transformed, an input transformed, a formula's code changed), and two slips that give the student's
  value on the same inputs cannot be told apart by them (a rival of the same family adds its name, as the names of
  one tier's simplest slips did: a gravity's sign beside a term's sign, which no tier can tell the more particular);
* nor for reproducing on more inputs: every tier is held to the inputs of the comparison (the formula tier to a
  third one as well, where it can draw one), and a hypothesis that fails one of them is not kept at all;
* where the hypotheses told span more than two families (``engine.MAX_FAMILIES``), nothing is named; nor where
  more than two unlike slips of the formula tier (``engine.MAX_UNLIKE``), of more than one family, reproduce the
  answer on every input: many unlike edits giving one value say that the inputs cannot tell causes apart (a term
  that a factor left out, a ratio upside down and a division for a product all make vanish within the tolerance);
* a later tier heard after an earlier one explained the answer that runs out of its budget (calls, the formula
  tier's time) leaves the earlier finding standing, as it stood before the later tier was heard; the formula tier
  so heard tries rivals of the families not told yet first, then those of the families told as time allows,
  within a budget of its own (``mutants.LATE_MUTANTS``, ``mutants.LATE_TIME_BUDGET``);
* the student kit cannot hear the formula tier (it holds no reference code): where its own tiers explain the
  answer it names no cause, says what they found and that the graded submission may say more.

Measured on the sets of realistic mistakes (``tests/diagnosis/score.py``, ``--set pool``, ``pool2``, ``pool3``):
hearing every tier, with the equivalences below, turned three wrong causes into "could be" with the true one and
took no right one; an order by cost across tiers had told the first tier's family alone.

Slips that are one value by mathematics (a rotation transposed and the rotation of the negated angle, a skew
matrix transposed and negated, a cross product with its operands exchanged and negated) are declared once with the
grammar (``grammar.EQUIVALENCES``) and told together by whichever tier finds one of them; such a twin adds a name,
not an explanation: where it would take the families told past two, it is left out rather than nothing named.
So is one edit or one finding that reads as a slip of another family as truly (``mutants.rivals``,
``engine._unturned``): a product with a quantity where the division by it belongs is a factor off and the quantity
used as its reciprocal; an angle or a rotation found ignored, where the student's value is the reference's with it
turning nothing, is a rotation left out as well, and an argument found ignored where the student's value is the
reference's with it zero is the terms it makes left out as well (``engine._zeroed``: an array so ignored is told even
where no other tier explains the answer, with both readings); where no argument of the call could be tested, a parameter
with a default that a slip of a formula leaves unused is an argument ignored, and so is an argument of the call that the
test of an ignored argument had no budget to change (a mass computed without its density: a factor left out, and the
density ignored); and a factor left out of a product that leaves the answer no multiple of the expected one (a cosine
left out of some entries, an inverse mass matrix) is a part of the formula left out, a term missing
(``engine._unscaled``).  A name more particular than another is
told alone only where the evidence proves it: two names unpacked from a run's state and exchanged read the state
from each other's rows (a state row, not entries swapped).

The grammar:

* outputs (the expected value transformed): transpose, inverse, the sign of the whole value, of a row, a column
  or an entry, rows, columns or entries swapped, three rows or columns permuted cyclically, a tensor's axes in
  another order (rows and columns alike: an inertia's moments exchanged), a vector's entries in any other order the
  student's value holds (its halves exchanged, say), a factor 2, 1/2, pi/180, 180/pi, 1000 or 1/1000 (a unit) or a
  named constant of the problem, float32 rounding, rounding to a few decimals that keep two significant digits of
  the largest value (``grammar.ROUNDED_DIGITS``: values of order one as whole numbers are no rounding a student
  writes; nor is a time of the student's own output grid, which its spacing rounds), held to every input, the output in
  the other frame (conjugation by the problem's rotation); a value typed into answers.toml and compared with its key
  (``checks._answers.typed_failure``) hears these alone, on its one input, and only where it holds many numbers
  (``grammar.typed_slips``: a 3 x 3 matrix read off a figure, not a scalar);
* inputs (the reference on transformed arguments): arguments swapped, angles as degrees, negated angles, a
  rotation argument transposed, a vector argument in the other frame, an argument ignored (the student's value
  does not change when it does, on the input shown and on one with every argument moved at once, while the
  reference's does: a value that does not follow an argument at all is the finding, not a guess);
* formulas: a declared term missing, sign-flipped or added (``terms``: the reference splits its result into named
  terms), found by least squares over the inputs; and ``mutants``' slips inside the reference's own code, among
  them slips of precision (float32, a constant typed short), tried on one input too where the value is within
  their band; where one input is all there is (``Evidence.alone``: the call has no arguments to draw, its value
  does not change with them, or it is a run counted in steps, the student's own step called again and again), all
  of them are tried there, held to the call's other values (the run's other states) as well;
* motions (``motion``: a run's times, states and events): a time shift, an output grid one sample off (as many times as
  asked, spaced as a grid of one more or one fewer), a constant offset, a state read from the wrong row (of the run, or
  of the state at an event: another of its rows, or a slice of the whole state there from another start, where the event
  itself is found where the reference's is), the state at an event read from the run's last output before it (and, its
  twin, a state of another time), a wrong initial state (and, beside it, the slip of a value that gives the student's
  start from the given one, where the start differs in ``evidence.ONE_INPUT_NUMBERS`` distinct numbers or more: a start
  typed rounded, cut to whole numbers (an integer dtype), its entries exchanged; on fewer numbers as a twin of the wrong
  start, "could be" either: one angle typed with the wrong sign), an event found late or early, an error that grows with
  the step, the run's parameters exchanged, scaled or ignored, its start's entries exchanged and solve_ivp at looser
  tolerances (the reference re-run so: a run clearly another than the reference's, or one far nearer to the student's
  than the reference's is); a randomized comparison's second failing run must show the same cause.

* models (``models``: a value of the student's MuJoCo model, which a check compares with the sheet's numbers or
  the reference's analytic values, so that no reference call stands behind it): the student's compiled model and
  the reference's on the same arguments, element by element; a body moved with what it carries (an offset, and a
  scale where it sits at a factor of the lever from its parent's joint), a body turned about its joint (the model
  built in another configuration, or the slip of the angle it was given), one attribute alone differing (the
  grammar of values), each only where it holds every difference and the compared value is among them.  The kit's
  key holds no reference's model for a call asked of the student alone: there the kit leaves the cause to the
  graded submission.

Before any cause of a run, the student's right-hand side is compared with the reference's along the run (where the
probe declares it): where they differ the mistake is in the model, its cause is sought on the right-hand sides,
and no cause that blames the integration is told, by the engine or by a check (``doubt``).

A check that judges the student's value by a property and names only its symptom (``SYMPTOMS``: a matrix that is not
orthonormal, a reflection, a body in the wrong orientation) asks the engine too (``judge``): the student's probe call
behind the value is compared with the reference's call on the same arguments, each result that differs is explained as a
failing comparison (on the input shown and the engine's own second input), and a cause found is told beside the symptom,
whose message stays.  A check that names an effect its value shows (``EFFECTS``: some entries with the wrong sign, found
by comparing the value with the expected one, whether its catalogue names the sign of a term or a sign alone) asks the
formula tier for the exchanges of two operands whose effect that sign is (``rival``, ``mutants.opposite_slips``: a
call's two points exchanged negate the lever arm between them; ``np.cross(r, w)`` for ``np.cross(w, r)``) and for a
matrix transposed (a system solved with its matrix transposed negates a multiplier); for a check that names a term that
is not there, the reorders of two factors of a product that make it vanish (``I (w x w)`` for ``w x (I w)``: the
gyroscopic term written, in an order in which it is zero); for a check that names a wrong start, the exchanges of two
operands that the start is made of (a signature's start values in another order); on the input shown alone where there
is no second one: a rival found is told beside the check's name, "could be" either; the kit, which holds no reference
code, tells the check's name alone.  A randomized comparison whose shown input has no comparison (the student's code
raised there) is explained on its failing inputs that have one, and the cause told beside it; one whose other failing
inputs fail at another place (another entry of a trace, another step) is explained on the input shown alone, and the
engine draws its second input itself.  A value the check derives from the student's reply itself (the centre of gravity
of their points, an anchor's first coordinates), which no call of either side holds, is explained alike, by the
student's last call of the check; the kit's key may not hold the reference's call: there the kit leaves the cause to the
graded submission.

What a probe's arguments and result are is declared beside ``@probe`` (``probes.probe(args=..., terms=..., rotation=...,
motion=..., constants=..., draw=...)``); the reference's values come through the oracle (the grading context), never
from ``reference`` itself.  Where a check takes its expected value from a stand-in of the reference's (a probe for the
reference alone: problem 7's numeric ``expressions`` for the student's symbolic ``derive``; or any other probe than the
student's: problem 16's numeric ``body`` for its ``symbolic``), the tier of formulas mutates the code of the student's
own call on the reference instead, where the reference's value of that call is the expected one (``mutants.own_calls``).
Every reference call the engine may need is a function of the probe's arguments alone, so the student kit's answer key
holds them: while the key is recorded, every comparison of a declared probe makes them (``prepare``).

The package: ``evidence`` (declarations, evidence, where values came from), ``grammar`` (slips of values and arguments),
``terms``, ``runs``, ``models``, ``scene`` (the reference and the student's code, with budgets), ``mutants`` (slips of
the reference's code; ``passes``: a tree's forward kinematics, computed once for the many mutants whose calls repeat
it alike) and ``engine`` (explaining, and recording the key).
"""

from __future__ import annotations

from ..errors import GraderFault
from .engine import (RECORDING, doubted, find, judged, note_comparison, prepare, prepare_call, prepared, recording,
                     rivalled)
from .evidence import DECLARATIONS, Declaration, Evidence, Finding, Source, declaration, locate
from .runs import remember_run
from .scene import MAX_REFERENCE_CALLS, Budget, Scene
from . import trace

__all__ = [
    "RECORDING",
    "Evidence",
    "Finding",
    "Source",
    "Declaration",
    "declaration",
    "explain",
    "doubt",
    "judge",
    "symptom",
    "SYMPTOMS",
    "rival",
    "EFFECTS",
    "effect",
    "prepare",
    "prepare_call",
    "prepared",
    "locate",
    "recording",
    "note_comparison",
    "remember_run",
    "MAX_REFERENCE_CALLS",
    "ENABLED",
    "STRICT",
]

#: raise the engine's own defects instead of naming no cause (the engine's tests set it)
STRICT = False
#: the engine is asked at all (its tests and the benchmark turn it off to compare)
ENABLED = True
#: the declarations of the probes, by name (the engine's tests add their own)
_DECLARATIONS = DECLARATIONS


def explain(ctx, evidences: list) -> Finding | None:
    """Name the cause of a failing comparison from its ``evidences`` (the input shown first; a randomized
    comparison gives its second failing input too), or None.  ``ctx`` is the grading context (its oracle, its
    child, its log of calls)."""
    evidences = [e for e in evidences if e is not None]
    if not evidences or not ENABLED:
        return None
    trace.begin(getattr(ctx, "check_id", ""), "explain")
    finding = _guarded(find, Scene(ctx), evidences)
    trace.end(finding)
    return finding


def doubt(ctx, evidence, diagnosis: str) -> Finding | None:
    """A check's ``diagnosis`` that blames the integration of a run (a step too large, an energy drift, an event
    found late or never) stands only where the run's right-hand side is the reference's: where it is not, the
    engine's finding on the right-hand sides (a cause, or no name and what differs) replaces it; None: the
    diagnosis stands.  ``evidence``: the failing comparison (None: the check's last run is the one)."""
    if not ENABLED or not _blames_integration(diagnosis):
        return None
    trace.begin(getattr(ctx, "check_id", ""), "doubt")
    finding = _guarded(doubted, Scene(ctx), evidence)
    trace.end(finding)
    return finding


#: the families of the vocabulary that say what a value shows (a property it lacks), not what slip made it: a check
#: that names one judged the student's value, which the engine may compare with the reference's (``judge``)
SYMPTOMS = ("not_orthonormal", "handedness", "orientation", "not_spd")


def judge(ctx, evidence) -> Finding | None:
    """The cause behind a value a check judged by a property rather than compared (``engine.judged``): the student's
    probe call the value came from compared with the reference's call on the same arguments, to be told beside the
    failure's own words; None: none found.  ``evidence``: the failure's comparison, if it carries one."""
    if not ENABLED:
        return None
    trace.begin(getattr(ctx, "check_id", ""), "judged")
    finding = _guarded(judged, Scene(ctx), evidence)
    trace.end(finding)
    return finding


#: the families of the names a check tells from what its value shows, which a slip of another family has as its
#: effect (``mutants.EFFECT_RIVALS``): some entries with the wrong sign, found by comparing the student's value with
#: the expected one (the catalogue's sign of a term as well as ``sign_flip``), the effect of two operands exchanged
#: that enter as a difference or of a matrix transposed; a term that is not there, the effect of two factors of a
#: product reordered so that it vanishes (``I (w x w)`` for ``w x (I w)``); a wrong start, the effect of two
#: arguments exchanged that the start is made of (a signature's start values in another order)
EFFECTS = ("sign", "missing_term", "initial_state")


def effect(diagnosis: str) -> bool:
    """Whether ``diagnosis`` names an effect the value shows (a name of a family of ``EFFECTS``), whose edit the
    formula tier may find (``rival``)."""
    from checks._diagnoses import DIAGNOSES

    return diagnosis in DIAGNOSES and DIAGNOSES[diagnosis].family in EFFECTS


def rival(ctx, evidence, diagnosis: str) -> Finding | None:
    """A check's ``diagnosis`` that names an effect its value shows (``effect``), with the rival of another
    family (``mutants.EFFECT_RIVALS``) that the engine finds on the failing comparison ``evidence`` (two arguments
    exchanged whose effect is that sign: the exchange is the edit, the sign its effect): the check's name and the
    rival's, "could be" either, and the engine's hint; None where the engine finds no such rival, or finds causes
    of a third family (the check's name stands)."""
    if not ENABLED or evidence is None or not effect(diagnosis) \
            or getattr(getattr(ctx, "oracle", None), "mode", "") != "live":  # the kit holds no reference code
        return None
    trace.begin(getattr(ctx, "check_id", ""), "rival")
    finding = _guarded(lambda scene, e: rivalled(scene, e, diagnosis), Scene(ctx), evidence)
    trace.end(finding)
    return finding if finding is not None and diagnosis in finding.names and len(finding.names) > 1 else None


def symptom(diagnosis: str) -> bool:
    """Whether ``diagnosis`` names only symptoms (``SYMPTOMS``), no cause."""
    from checks._diagnoses import DIAGNOSES

    names = [name for name in diagnosis.split(" or ") if name]
    return bool(names) and all(name in DIAGNOSES and DIAGNOSES[name].family in SYMPTOMS for name in names)


def _guarded(ask, scene: Scene, evidence) -> Finding | None:
    """``ask(scene, evidence)``, or None when the engine ran out of calls or the grader failed; a defect of the
    engine never costs the student the failure's message (``STRICT`` raises it instead)."""
    try:
        return ask(scene, evidence)
    except (Budget, GraderFault) as exc:
        trace.note("stopped", reason=type(exc).__name__, detail=str(exc)[:200])
        return None
    except Exception as exc:  # noqa: BLE001 - see above
        trace.note("defect", reason=type(exc).__name__, detail=str(exc)[:200])
        if STRICT:
            raise
        return None


def _blames_integration(diagnosis: str) -> bool:
    from checks._diagnoses import DIAGNOSES

    from .runs import INTEGRATION

    names = [name for name in diagnosis.split(" or ") if name]
    return bool(names) and all(name in INTEGRATION or name in DIAGNOSES and DIAGNOSES[name].family == "step_size"
                               for name in names)
