"""How the tier of formulas evaluates its mutants (``grader.diagnosis.mutants``): what it finds does not depend on
how cheaply it is found.

* A probe that computes more than the compared value may declare the cheaper call that holds it (``part``): each
  mutant is evaluated on the part, and on the whole probe only where the part reproduces the student's value;
  the slips kept are those the whole probe alone keeps (a mutant that reproduces on the part but raises in the
  rest of the probe is not kept), and the whole probe is called for the few mutants that pass the part only.
* The other tiers, which need the reference's value at a path only, ask the live reference for the part (the
  student kit's key holds the probe's own calls).
* The declaration holds on the reference: every probe that declares a part gives the part's values at its keys.
* The arguments of one input are copied for each call of a mutant (a mutant may change them in place) from one
  kept copy.
* A mutant's value reproduces the student's within the comparison's tolerance, or within a relative 1e-9
  (``evidence.REPRODUCED_RTOL``): a run that grows far past the size an absolute tolerance was set for is the same
  computation still; a value off by more, or not finite, is not reproduced.
"""

from __future__ import annotations

import importlib
import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import probes
from checks._diagnoses import DIAGNOSES
from grader.checking import Tol
from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, Source, array_of, at, declaration, reproduces, within
from probes._codec import decode, encode

from .stand_ins import made_up_package

TIGHT = Tol("tight", 1e-9, 1e-9)

SOURCE = '''"""A made-up problem for the tests of the tier's evaluation."""

import numpy as np


def halve(a, b):
    """``(a - b) / 2`` and ``a b``."""
    # BEGIN SOLUTION problem 97
    return np.array([(a - b) / 2.0, a * b])
    # END SOLUTION


def grow(items, x):
    """``items`` with ``2 x`` appended (in place), and their sum."""
    # BEGIN SOLUTION problem 97
    items.append(2.0 * x)
    return np.array([sum(items), x])
    # END SOLUTION
'''


@pytest.fixture
def made_up(tmp_path, monkeypatch):
    """A package of one made-up problem (97) that the tier mutates in place of the reference."""
    with made_up_package(tmp_path, monkeypatch, SOURCE, 97, "evaluation") as package:
        yield package


def scene(check_id: str):
    return SimpleNamespace(ctx=SimpleNamespace(check_id=check_id, oracle=SimpleNamespace(mode="live")))


def _halve(pkg, a, b):
    return importlib.import_module(f"{pkg.__name__}.problem_97").halve(a, b)


def probes_of(calls: dict, declared: bool):
    """The whole probe ``{"d": halve(a, b), "root": sqrt(halve(a, b)[0])}`` (the root only where ``rooted``: it
    raises for a negative half-difference) and its part ``{"d": halve(a, b)}``, counting their calls in
    ``calls``; ``declared``: the whole probe declares the part."""
    def part(pkg, a, b):
        calls["part"] += 1
        return {"d": _halve(pkg, a, b)}

    def whole(pkg, a, b, rooted):
        calls["whole"] += 1
        d = _halve(pkg, a, b)
        return {"d": d, "root": math.sqrt(d[0]) if rooted else 0.0}

    if declared:
        whole.declared = {"part": {"keys": ("d",), "probe": part, "args": (0, 1)}}
    return whole


def evidences_of(package, probe, student, inputs):
    return [Evidence(np.array(student(a, b), dtype=float), array_of(at(probe(package, a, b, rooted), ("d",))),
                     TIGHT, "value", source=Source(probe, (a, b, rooted), ("d",))) for a, b, rooted in inputs]


def found_with_and_without_the_part(package, student, inputs):
    """The tier's hypotheses with the whole probe declaring its part and without, and the calls each made."""
    told = []
    for declared in (True, False):
        calls = {"part": 0, "whole": 0}
        probe = probes_of(calls, declared)
        evidences = evidences_of(package, probe, student, inputs)
        calls.update(part=0, whole=0)  # the calls of the tier only
        found = mutants.mutant_slips(scene("p97.halve"), evidences)
        told.append((sorted((h.name, h.detail) for h in found), dict(calls)))
    return told


def test_a_mutant_is_evaluated_on_the_declared_part_first(made_up):
    """``(b - a) / 2``: the arguments exchanged (order), found alike with the part declared and without; with it,
    the whole probe is called only for the few mutants that the part kept, once per input, and the part once or
    twice for every mutant."""
    student = lambda a, b: [(b - a) / 2.0, a * b]  # noqa: E731
    inputs = [(1.0, 3.0, False), (2.5, -0.5, False)]
    (with_part, calls), (without, plain) = found_with_and_without_the_part(made_up, student, inputs)
    assert with_part == without and {DIAGNOSES[name].family for name, _ in with_part} == {"order"}
    tried = len(mutants.mutants_of(made_up, Path(made_up.__path__[0]), 97, probes_of({"whole": 0}, False),
                                   inputs[0][:2] + (False,)))
    assert plain["part"] == 0 and plain["whole"] >= tried
    assert tried <= calls["part"] <= 2 * tried
    assert 0 < calls["whole"] <= 2 * 4 < tried  # the mutants kept by the part (at most four slips), on two inputs


def test_a_mutant_that_raises_in_the_rest_of_the_probe_is_not_kept(made_up):
    """Where the whole probe takes the square root of the half-difference (``rooted``), the mutants that give the
    student's negative value on the part raise in the whole probe: not kept, as without the part."""
    student = lambda a, b: [(b - a) / 2.0, a * b]  # noqa: E731
    inputs = [(3.0, 1.0, True), (2.5, -0.5, True)]
    (with_part, calls), (without, _) = found_with_and_without_the_part(made_up, student, inputs)
    assert with_part == without == [] and calls["whole"] > 0


def test_the_arguments_are_copied_for_each_call(made_up):
    """``grow`` appends to its argument in place: every mutant gets a copy of the input's own list, so that the
    slip that reproduces the student's ``x`` for ``2 x`` (the number left out, or halved) is found whatever the
    mutants before it appended to their copies, and the inputs themselves are untouched."""
    def grown(pkg, items, x):
        return importlib.import_module(f"{pkg.__name__}.problem_97").grow(items, x)

    inputs = [([1.0, 2.0], 4.0), ([0.5, -1.5, 2.0], -3.0)]
    evidences = [Evidence(np.array([sum(items) + x, x]), array_of(grown(made_up, list(items), x)), TIGHT, "value",
                          source=Source(grown, (items, x), ())) for items, x in inputs]
    found = mutants.mutant_slips(scene("p97.grow"), evidences)
    assert sorted(h.detail for h in found) == ["a number in `grow` is halved",
                                               "a number in `grow` is left out of a product"]
    assert [items for items, _ in inputs] == [[1.0, 2.0], [0.5, -1.5, 2.0]]  # the inputs themselves untouched
    kept = mutants._kept_once(([1.0, np.arange(3.0)], {"m": 2.0}))
    first, second = mutants._copied(kept), mutants._copied(kept)
    assert first[0] is not second[0] and first[0][1] is not second[0][1]
    assert first[0][0] == 1.0 and np.array_equal(first[0][1], np.arange(3.0)) and first[1] == {"m": 2.0}
    unpicklable = (lambda: 1.0, [2.0])
    assert mutants._kept_once(unpicklable) == unpicklable and mutants._copied(unpicklable)[1] is not unpicklable[1]



def test_kept_arguments_are_copied_whole_for_each_call_and_are_the_same_call_as_equal_ones():
    """Each call of a mutant gets a copy of the input's arguments of its own, nested lists, dicts and arrays
    included, with an array shared twice shared in the copy as in the input; the kept arguments do not follow a
    change of the input made after they were kept; two inputs kept apart with equal arguments are the same call."""
    shared = np.arange(3.0)
    args = ({"bodies": [{"m": 1.0, "I": np.eye(3)}], "axis": shared}, shared, [1, (2.0, "x")])
    kept = mutants._kept_once(args)
    args[0]["bodies"][0]["I"][0, 0] = 5.0
    first, second = mutants._copied(kept), mutants._copied(kept)
    assert first[0]["bodies"][0]["I"][0, 0] == 1.0
    assert first[0]["axis"] is first[1] and first[1] is not second[1] and first[1] is not shared
    first[0]["bodies"][0]["m"] = 9.0
    first[1][0] = 7.0
    assert second[0]["bodies"][0]["m"] == 1.0 and second[1][0] == 0.0 and second[2] == [1, (2.0, "x")]
    again = mutants._kept_once(({"bodies": [{"m": 1.0, "I": np.eye(3)}], "axis": np.arange(3.0)}, np.arange(3.0),
                                [1, (2.0, "x")]))
    assert again == mutants._kept_once(({"bodies": [{"m": 1.0, "I": np.eye(3)}], "axis": np.arange(3.0)},
                                        np.arange(3.0), [1, (2.0, "x")]))
    assert len({again, mutants._kept_once((1.0,)), mutants._kept_once((1.0,))}) == 2


# ------------------------------------------------------------------------------------------ the declarations


def _lagrange_case():
    from checks._dynamics import H, rich_case

    return rich_case(extra=(H,))


#: the arguments on which each probe that declares a part is held to it (a new declaration adds its case)
PART_CASES = {"_dynamics.lagrange": _lagrange_case}


def _declaring_a_part():
    found = {}
    for path in sorted(Path(probes.__path__[0]).glob("*.py")):
        module = importlib.import_module(f"probes.{path.stem}")
        for name, func in vars(module).items():
            if getattr(func, "is_probe", False) and func.__module__ == module.__name__ and \
                    "part" in (getattr(func, "declared", None) or {}):
                found[f"{path.stem}.{name}"] = func
    return found


def test_every_declared_part_holds_on_the_reference():
    """The probes that declare a part give, on the reference, the part's values at its keys (bit for bit: the same
    code on the same arguments); and a part alone is no declaration to the other tiers."""
    import reference

    declaring = _declaring_a_part()
    assert declaring and set(declaring) == set(PART_CASES)
    for name, func in declaring.items():
        part = func.declared["part"]
        args = PART_CASES[name]()
        whole = decode(encode(func(reference, *args)))
        cheaper = decode(encode(probes.lookup(part["probe"])(reference, *(args[k] for k in part["args"]))))
        for key in part["keys"]:
            assert np.array_equal(np.asarray(whole[key]), np.asarray(cheaper[key])), (name, key)
        if set(func.declared) == {"part"}:
            assert declaration(name) is None


# ------------------------------------------------------------------------------------------ the reference's values


def test_the_live_reference_is_asked_for_the_declared_part(monkeypatch):
    """The engine's other tiers ask the reference for a value at a path (an argument changed, every argument
    moved, an input slip): live through the declared part (the same value, without the rest of the probe), in the
    student kit through the probe itself (its key holds the probe's calls); a path outside the part's keys, or a
    probe that declares none, is asked as it is."""
    import grader.diagnosis.scene as scene_module
    from grader.diagnosis.evidence import part_of
    from grader.diagnosis.scene import Scene

    from .stand_ins import StandInOracle

    asked = []

    def whole(a, b, rooted):
        asked.append("whole")
        return {"d": np.array([(a - b) / 2.0, a * b]), "root": math.sqrt(abs(a - b))}

    def part(a, b):
        asked.append("part")
        return {"d": np.array([(a - b) / 2.0, a * b])}

    whole.declared = {"part": {"keys": ("d",), "probe": "made_up.part", "args": (0, 1)}}
    oracle = StandInOracle({"made_up.whole": whole, "made_up.part": part})
    live = Scene(SimpleNamespace(oracle=oracle, check_id="p97.halve"))
    monkeypatch.setattr(scene_module, "part_of", lambda source: part_of(Source(whole, source.args, source.path)))
    value = live.reference_at("made_up.whole", (3.0, 1.0, True), ("d",))
    assert np.array_equal(value, [1.0, 3.0]) and asked == ["part"] and live.reference_calls == 1
    assert live.reference_at("made_up.whole", (3.0, 1.0, True), ("root",)) == math.sqrt(2.0)
    assert asked == ["part", "whole"]
    oracle.mode = "kit"
    kit = Scene(SimpleNamespace(oracle=oracle, check_id="p97.halve"))
    assert np.array_equal(kit.reference_at("made_up.whole", (3.0, 1.0, True), ("d",)), [1.0, 3.0])
    assert asked == ["part", "whole", "whole"]


def test_a_value_grown_past_an_absolute_tolerance_is_reproduced_to_its_relative_digits():
    sheet = Tol("sheet, 4 decimals", 6e-4)
    grown = np.array([3.2e15, -1.7e14, 5.0e-3])
    same = grown * (1.0 + np.array([4e-14, -2e-13, 0.0]))  # the same steps summed in another order
    assert not within(grown, same, sheet) and reproduces(grown, same, sheet)
    assert not reproduces(grown, grown * (1.0 + 1e-6), sheet)
    assert not reproduces(grown, grown[::-1], sheet)
    diverged = np.array([np.nan, 1.0, 2.0])
    assert not reproduces(diverged, diverged.copy(), sheet)
    small = np.array([0.1, 0.2, 0.3])
    assert reproduces(small, small + 5e-4, sheet) and not reproduces(small, small + 1e-3, sheet)
