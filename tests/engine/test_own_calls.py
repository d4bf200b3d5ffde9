"""The calls the tier of formulas runs its mutants on (``grader.diagnosis.mutants``).

* A comparison whose expected value came from a stand-in of the reference's (a probe for the reference alone:
  problem 7's ``expressions`` evaluates the package's numeric rotations, where the student's ``symbolic`` evaluates
  their derivation; or the numeric twin of a symbolic answer, problem 16's ``body``) has its mutants run on the
  student's own call, the code that call runs on the reference
  (``own_calls``), but only where the reference's value of that call is the expected one.
* The other values of a comparison's call (``_siblings``) are read from one reply of that call per mutant
  (``_reproduced``), not by calling it again for each.
* Graded as ``grade batch`` grades (``tests/engine/stand_ins.toml``): the slip is named live, the kit names the same
  or nothing, and with the engine off no cause of that family is named.
"""

import dataclasses
import sys
import types
from pathlib import Path

import numpy as np
import pytest

from grader.checking import Tol
from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, Source

from ..kit_support import (  # noqa: F401 (fixtures)
    assert_named_live_and_alike,
    graded_table,
)

ROOT = Path(__file__).resolve().parents[2]
TIGHT = Tol("tight", 1e-9, 1e-9)


@pytest.fixture
def stand_in_probes(monkeypatch):
    """Made-up probes (``probes.stub_own``): ``stand_in`` (for the reference alone) and ``own`` (the student's
    call), whose values on the private reference package are set by the test, and a count of the calls of ``own``."""
    from probes import probe
    from probes._forms import ANY

    replies = {"stand_in": {"x": np.array([1.0, 2.0])}, "own": {"x": np.array([1.0, 2.0]), "y": np.array([3.0])}}
    calls = []
    stub = types.ModuleType("probes.stub_own")

    def own(pkg, n):
        calls.append(n)
        return replies["own"]

    stub.stand_in = probe(returns=ANY, reference_only=True)(lambda pkg, n: replies["stand_in"])
    stub.own = probe(returns=ANY)(own)
    monkeypatch.setitem(sys.modules, "probes.stub_own", stub)
    return replies, calls


def _evidence(source_probe: str, got) -> Evidence:
    return Evidence(np.asarray(got, dtype=float), np.array([1.0, 2.0]), TIGHT, "x",
                    source=Source(source_probe, (1,), ("x",)), student=Source("stub_own.own", (1,), ("x",)))


def test_a_stand_in_gives_way_to_the_students_own_call_where_the_reference_agrees(stand_in_probes):
    evidence = _evidence("stub_own.stand_in", [1.0, 5.0])
    (own,) = mutants.own_calls([evidence])
    assert own.source == Source("stub_own.own", (1,), ("x",))
    assert own.got is evidence.got and own.expected is evidence.expected and own.student == evidence.student


def test_a_column_of_the_students_own_call_is_read_as_the_vector_the_check_compared(stand_in_probes):
    """Problem 35's joint function gives its rates as columns where the stand-in gives vectors: the own call holds,
    and its column is read in the shape of the student's value; a value of another shape than one of axes of one
    entry more or fewer is no value of the comparison."""
    replies, _ = stand_in_probes
    replies["own"] = {"x": np.array([[1.0], [2.0]])}
    evidence = _evidence("stub_own.stand_in", [1.0, 2.0])
    (own,) = mutants.own_calls([evidence])
    assert own.source.probe == "stub_own.own"
    values = mutants._reproduced(None, [own], [("stub_own.own", mutants._kept_once((1,)))])
    assert values is not None and values[0].shape == (2,)
    replies["own"] = {"x": np.array([[1.0, 2.0], [3.0, 4.0]])}
    assert mutants._reproduced(None, [own], [("stub_own.own", mutants._kept_once((1,)))]) is None


def test_a_stand_in_stays_where_the_reference_gives_the_students_call_another_value(stand_in_probes):
    replies, _ = stand_in_probes
    replies["own"] = {"x": np.array([1.0, 2.5])}  # the reference's own call is not what the stand-in says
    evidence = _evidence("stub_own.stand_in", [1.0, 5.0])
    assert mutants.own_calls([evidence]) == [evidence]


def test_a_comparison_of_the_students_own_call_stays_as_it_is(stand_in_probes):
    evidence = _evidence("stub_own.own", [1.0, 5.0])  # the reference's value of the same probe: no stand-in
    assert mutants.own_calls([evidence]) == [evidence]


def test_the_reference_keeps_what_its_own_call_computes_once_and_a_mutants_call_makes_it_anew(monkeypatch):
    """The own call runs the reference's own code: what its probe computes once (``probes.remembered``: problem 7's
    derivation, simplified in seconds) is kept for the next grading's own call; a mutant's call makes it anew."""
    from probes import probe, remembered
    from probes._forms import ANY

    made, store = [], {}

    def derived(pkg, n):
        return remembered(store, n, lambda: made.append(n) or {"x": np.array([1.0, 2.0])})

    stub = types.ModuleType("probes.stub_kept")
    stub.stand_in = probe(returns=ANY, reference_only=True)(lambda pkg, n: {"x": np.array([1.0, 2.0])})
    stub.own = probe(returns=ANY)(derived)
    monkeypatch.setitem(sys.modules, "probes.stub_kept", stub)
    evidence = Evidence(np.array([1.0, 5.0]), np.array([1.0, 2.0]), TIGHT, "x",
                        source=Source("stub_kept.stand_in", (1,), ("x",)),
                        student=Source("stub_kept.own", (1,), ("x",)))
    for _ in range(2):
        (own,) = mutants.own_calls([evidence])
        assert own.source.probe == "stub_kept.own"
    assert made == [1]  # made once, for both gradings' own calls
    mutants._call(None, "stub_kept.own", mutants._kept_once((1,)), ("x",))
    assert made == [1, 1]  # a mutant's call (its code may differ) hears nothing kept


def test_a_numeric_twin_gives_way_to_the_students_symbolic_call_read_at_its_point(monkeypatch):
    """A symbolic answer evaluated at several points (one array, one row per point) is compared with the
    reference's numeric twin at one of them: the twin is a stand-in too (though the student writes it as well), and
    the own call's row of that point is read, where the reference's value of it is the twin's."""
    from probes import probe
    from probes._forms import ANY

    stub = types.ModuleType("probes.stub_twin")
    stub.numeric = probe(returns=ANY)(lambda pkg, m: np.array([m, 2 * m]))
    stub.symbolic = probe(returns=ANY)(lambda pkg, points: np.array([[p, 2 * p] for p in points]))
    monkeypatch.setitem(sys.modules, "probes.stub_twin", stub)
    evidence = Evidence(np.array([3.0, 3.0]), np.array([3.0, 6.0]), TIGHT, "x",
                        source=Source("stub_twin.numeric", (3.0,), ()),
                        student=Source("stub_twin.symbolic", ((1.0, 3.0),), (1,)))
    (own,) = mutants.own_calls([evidence])
    assert own.source == Source("stub_twin.symbolic", ((1.0, 3.0),), (1,))
    elsewhere = dataclasses.replace(evidence, student=Source("stub_twin.symbolic", ((1.0, 3.0),), (0,)))
    assert mutants.own_calls([elsewhere]) == [elsewhere]  # the reference's row there is not the twin's value


def test_the_stand_ins_code_is_mutated_where_the_own_calls_reproduces_nothing(stand_in_probes, monkeypatch):
    """The own call's code first; where none of its slips reproduces the student's value, the stand-in's code, as
    where the own call does not hold (a slip of problem 25's symbolic pass that its numeric walker shares)."""
    from grader.diagnosis.evidence import Hypothesis

    seen, found = [], Hypothesis("k", "sign_flip", 1, "a sign")
    monkeypatch.setattr(mutants, "_slips_on", lambda scene, evidences, *rest: seen.append(
        evidences[0].source.probe) or ([] if len(seen) == 1 else [found]))
    evidence = _evidence("stub_own.stand_in", [1.0, 5.0])
    live = types.SimpleNamespace(ctx=types.SimpleNamespace(oracle=types.SimpleNamespace(mode="live")))
    assert mutants.mutant_slips(live, [evidence]) == [found]
    assert seen == ["stub_own.own", "stub_own.stand_in"]


def test_the_other_values_of_one_call_are_read_from_one_reply(stand_in_probes):
    replies, calls = stand_in_probes
    args = mutants._kept_once((1,))
    first = Evidence(np.array([1.0, 2.0]), np.array([1.0, 2.0]), TIGHT, "x",
                     source=Source("stub_own.own", (1,), ("x",)))
    sibling = Evidence(np.array([3.0]), np.array([3.0]), TIGHT, "y", source=Source("stub_own.own", (1,), ("y",)))
    values = mutants._reproduced(None, [first, sibling], [("stub_own.own", args), ("stub_own.own", args)])
    assert [v.tolist() for v in values] == [[1.0, 2.0], [3.0]]
    assert calls == [1]  # one call for both values
    other = mutants._kept_once((2,))
    mutants._reproduced(None, [first, sibling], [("stub_own.own", args), ("stub_own.own", other)])
    assert calls == [1, 1, 2]  # another call's arguments: called anew, and a later comparison calls anew


TABLE = ROOT / "tests" / "engine" / "stand_ins.toml"
STAND_INS, _, slot, test_the_graded_mistakes_are_of_their_families = graded_table(TABLE)


@pytest.mark.parametrize("mistake", STAND_INS, ids=lambda m: m.name)
def test_a_slip_behind_a_stand_in_is_named(mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch):
    assert_named_live_and_alike(mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch)
