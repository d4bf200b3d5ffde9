"""Catalogues of known mistakes computed when a comparison consults them (a failure), and at once while the kit's
answer key is recorded, so that the key holds them for every input the kit may grade."""

from grader.context import Context
from grader.kit import ReferenceChild, record_key
from grader.oracle import LiveOracle, RecordingOracle
from grader.runner import _run_checks
from grader.problems import problem_module
from grader.results import Status

MISTAKEN = "_trees.mistaken_states"


def test_a_catalogue_is_computed_once_when_first_consulted_and_at_once_while_recording():
    made = []

    def compute(tag):
        made.append(tag)
        return [tag]

    live = Context(31, None, {}, None, 1, LiveOracle())
    catalogue = live.catalogue(lambda: compute("live"))
    assert made == []
    assert list(catalogue) == ["live"] and len(catalogue) == 1 and catalogue[0] == "live" and catalogue
    assert made == ["live"]
    Context(31, None, {}, None, 1, RecordingOracle(1, "fingerprint")).catalogue(lambda: compute("recorded"))
    assert made == ["live", "recorded"]


class CountingOracle(LiveOracle):
    """The live reference, counting the probes asked of it."""

    def __init__(self):
        super().__init__()
        self.asked: list[str] = []

    def reference(self, probe, args, persist=False, check=None):
        self.asked.append(probe)
        return super().reference(probe, args, persist, check)


def test_passing_tree_comparisons_compute_no_mistaken_recursion_but_the_key_holds_them():
    oracle = CountingOracle()
    results = _run_checks(problem_module(31), Context(31, ReferenceChild(oracle), {}, None, 7, oracle), 31)
    assert all(r.status is Status.PASSED for r in results)
    assert oracle.asked and MISTAKEN not in oracle.asked
    key, _ = record_key(problems=[31], seed=7)
    recorded = [entry["checks"] for call, entry in key.calls.items() if call.startswith(MISTAKEN + "[")]
    pooled = len(key.pools["p31.random_trees#0"])
    assert sum("p31.random_trees" in checks for checks in recorded) >= pooled  # one catalogue per recorded input


def test_a_servo_too_soft_is_told_only_where_the_model_is_integrated_as_the_sheets():
    """Problem 3(c)'s joint 1 strays from q1 = t at the right average rate: a servo too soft does that, and so does
    a model stepped otherwise than the sheet's (RK4 at 1 ms).  The check names the servo only where the run says
    the model is integrated as the sheet's; otherwise it says what differs."""
    from checks._mujoco import stepped_otherwise

    assert stepped_otherwise({"integrator": "rk4", "timestep": 0.001}) == ""
    assert stepped_otherwise({"integrator": "rk4", "timestep": 0.002}) == "steps at 2 ms"
    assert stepped_otherwise({"integrator": "euler", "timestep": 0.001}) == "integrates with euler"
    assert stepped_otherwise({"integrator": "implicitfast", "timestep": 0.005}) == \
        "steps at 5 ms and integrates with implicitfast"


def test_a_start_in_single_precision_is_no_start_of_its_own_for_problem_37():
    """Problem 37's checks call a run's start that differs from the table's first row a wrong initial state, but not
    where its entries are that row's or their float32 roundings (a run returned in single precision, some of its
    states or all): there the diagnosis engine tells the rounding."""
    import numpy as np

    from checks.problem_37 import _single

    start = np.array([np.pi / 6, -np.pi / 4, np.pi / 3, 1e-17, 0.0, 0.0])
    angles_single = np.concatenate([start[:3].astype(np.float32), start[3:]])
    assert _single(angles_single, start)
    assert _single(start.astype(np.float32), start)
    assert not _single(np.round(start, 4), start)  # typed to four decimals: another start
    assert not _single(np.concatenate([start[:3], -start[3:4], start[4:]]) + [0, 0, 0.01, 0, 0, 0], start)


def test_a_start_with_its_halves_exchanged_is_a_wrong_start_or_an_exchange():
    """A run's start whose rates stand where its angles belong and the reverse (``simulate(..., qd0, q0)``, the
    sheet's start ``(0, 0, -0.1, 1)`` with two zeros) is a wrong start, and, "could be" beside it, its two halves
    exchanged (``checks._dynamics.wrong_start``, which hears ``engine.value_slips``): named even where the start's
    entries repeat, so that no permutation of single entries tells which went where.  The near miss, a start that
    is no order of the given one's entries, is a wrong start alone."""
    import numpy as np

    from checks._dynamics import wrong_start
    from grader.checking import EXACT
    from grader.diagnosis.engine import value_slips

    given = np.array([0.0, 0.0, -0.1, 1.0])
    hint, diagnosis = wrong_start(np.array([-0.1, 1.0, 0.0, 0.0]), given, "The run starts at the given start.")
    assert diagnosis == "initial_state or swapped", diagnosis
    assert "two halves are exchanged" in hint, hint
    assert wrong_start(np.array([-0.1, 1.0, 0.0, 0.5]), given, "The run starts at the given start.")[1] == \
        "initial_state"
    distinct = value_slips(np.array([-0.1, 1.0, 0.05, 0.3]), np.array([0.05, 0.3, -0.1, 1.0]), EXACT)
    assert [h.key for h in distinct] == ["swap:halves"], [(h.key, h.detail) for h in distinct]
