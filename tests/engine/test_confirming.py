"""A screened mutant evaluated as it is (``grader.diagnosis.mutants``): a function that simplifies a symbolic answer
has its mutants screened without sympy's simplifications, and a mutant that reproduces the student's value so is
evaluated again as it is; that value decides.

* The evaluation is counted apart from the screening, against a budget of its own (``_Deadline.confirming``,
  ``CONFIRMING_TIME_BUDGET``): problem 40's bias forces, simplified, take longer than the screening of all its
  mutants, and the explanation had run out of its time on them.
* What a probe computes once for a package (``probes.remembered``) is computed once for one code of the package on
  all its inputs (``probes.kept_for_one_code``), and never heard by another code, nor by a call at constants bound
  to other values (``probes._rebound``).
* Graded as ``grade batch`` grades (``tests/engine/simplified.toml``): the slip is named live, the kit names the same
  or nothing, and with the engine off no cause of that family is named.
"""

import sys
import time
import types
from pathlib import Path

import pytest

from grader.diagnosis import mutants

from ..kit_support import (  # noqa: F401 (fixtures)
    assert_named_live_and_alike,
    graded_table,
)

ROOT = Path(__file__).resolve().parents[2]


def _busy(seconds: float) -> None:
    """Spends ``seconds`` of the thread's CPU time."""
    start = time.thread_time()
    while time.thread_time() - start < seconds:
        sum(range(1000))


# ------------------------------------------------------------------------------------------ the budgets


def test_the_work_of_confirming_is_not_counted_against_the_screening():
    with mutants._Deadline(0.2, confirming=5.0) as deadline:
        with deadline.confirming():
            _busy(0.6)  # three times the screening's budget
        screening, making = deadline.spent()
    assert not deadline.fired
    assert screening < 0.2 and making == 0.0


def test_confirming_past_its_own_budget_is_interrupted():
    with pytest.raises(mutants._Timeout):
        with mutants._Deadline(5.0, confirming=0.2) as deadline:
            with deadline.confirming():
                _busy(10.0)
    assert deadline.fired


def test_the_screening_past_its_budget_is_interrupted_whatever_was_confirmed():
    with pytest.raises(mutants._Timeout):
        with mutants._Deadline(0.2, confirming=5.0) as deadline:
            with deadline.confirming():
                _busy(0.1)
            _busy(10.0)



def test_the_machines_pace_is_measured_once_and_bounded():
    """The machine's pace (how many times slower than the machines where the budgets were set it does the engine's
    work) is measured once for the process, and is at least 1 and at most ``PACE_MOST``."""
    first = mutants.pace()
    assert 1.0 <= first <= mutants.PACE_MOST and mutants.pace() == first


@pytest.mark.parametrize("pace, fired", [(1.0, True), (4.0, False)])
def test_a_slow_machine_has_budgets_as_many_times_longer(monkeypatch, pace, fired):
    """On a machine four times slower the screening's budget of 0.2 s lets it spend 0.5 s of CPU time, which a
    machine of the budgets' own pace interrupts; on both, work past the widened budget is interrupted."""
    monkeypatch.setattr(mutants, "_PACE", [pace])
    interrupted = False
    try:
        with mutants._Deadline(0.2) as deadline:
            _busy(0.5)
    except mutants._Timeout:
        interrupted = True
    assert interrupted == fired == deadline.fired
    start = time.thread_time()
    with pytest.raises(mutants._Timeout):
        with mutants._Deadline(0.2):
            _busy(30.0)
    assert time.thread_time() - start < 10.0


# ------------------------------------------------------------------------------------------ what probes remember


@pytest.fixture
def counting_probe(monkeypatch):
    """A made-up probe (``probes.stub_kept.value``) that remembers, per package, a value read from its module's
    constant ``SCALE``, and counts how often it made it."""
    from probes import probe, remembered
    from probes._forms import ANY

    made, store = [], {}
    stub = types.ModuleType("probes.stub_kept")

    def value(pkg):
        def make():
            made.append(1)
            return float(pkg.SCALE) * 2.0
        return remembered(store, pkg.__name__, make)

    stub.value = probe(returns=ANY)(value)
    monkeypatch.setitem(sys.modules, "probes.stub_kept", stub)
    package = types.ModuleType("stub_kept_package")
    package.SCALE = 1.5
    package.__path__ = []
    monkeypatch.setitem(sys.modules, "stub_kept_package", package)
    return stub, package, made


def test_one_code_makes_what_a_probe_remembers_once_for_all_its_inputs(counting_probe):
    from probes import fresh, kept_for_one_code

    stub, package, made = counting_probe
    with fresh():
        assert stub.value(package) == stub.value(package) == 3.0
    assert len(made) == 2  # fresh alone: made anew at each call
    with kept_for_one_code():
        with fresh():
            stub.value(package)
        with fresh():
            stub.value(package)
    assert len(made) == 3  # one code: made once
    with kept_for_one_code():
        with fresh():
            stub.value(package)
    assert len(made) == 4  # another code hears nothing of the first


def test_a_call_at_other_constants_hears_nothing_kept_for_the_code(counting_probe, monkeypatch):
    from probes import fresh, kept_for_one_code
    from probes._rebound import rebound

    stub, package, made = counting_probe
    monkeypatch.setattr("probes.module", lambda pkg, name: pkg)  # the made-up package is its own module
    monkeypatch.setattr("probes._rebound.module", lambda pkg, name: pkg)
    with kept_for_one_code():
        with fresh():
            assert stub.value(package) == 3.0
        assert rebound(package, "stub_kept.value", [["stub_kept_package", "SCALE", 4.0]], []) == 8.0
        with fresh():
            assert stub.value(package) == 3.0  # the constants put back, the code's own value heard again
    assert package.SCALE == 1.5


# ------------------------------------------------------------------------------------------ graded


TABLE = ROOT / "tests" / "engine" / "simplified.toml"
SIMPLIFIED, _, slot, test_the_graded_mistakes_are_of_their_families = graded_table(TABLE)


@pytest.mark.parametrize("mistake", SIMPLIFIED, ids=lambda m: m.name)
def test_a_slip_whose_simplification_outlasts_the_screening_is_named(
        mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch):
    assert_named_live_and_alike(mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch)
