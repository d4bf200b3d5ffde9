"""The diagnosis engine on the states and times of a run's events.

A value read from the state at an event (the state before an impact, the positions where a bar lands) is a slice
of that state: read from another start (one entry off, the halves exchanged), it is the reference's state at the
event read there, where the event itself is found where the reference's is.  Each planted mistake below is graded
as ``grade batch`` grades (a warm fork), live and from the kit's answer key (the same verdicts); the stand-ins
show what the engine does with each piece alone.
"""

import numpy as np
import pytest

from checks._diagnoses import families_of
from grader.checking import Tol
from grader.diagnosis import Declaration, Evidence, Source
from grader.diagnosis.runs import event_state, event_state_slips

from tests.kit_support import (  # noqa: F401 (fixtures)
    assert_told,
    failed_alike,
    warm_slot,
)
from tests.submissions import Planted

#: the angles before the impact read one entry on: two angles and the first rate; the impact keeps them (q_plus)
ANGLES_ONE_ENTRY_ON = Planted(
    name="run-events-p46-angles-one-entry-on", problem=46, file="problem_46.py",
    old='''t_event, q_minus, qd_minus = free["t_event"], free["y_event"][:3], free["y_event"][3:]''',
    new='''t_event, q_minus, qd_minus = free["t_event"], free["y_event"][1:4], free["y_event"][3:]''',
    check="p46.event_and_impact", diagnosis="state_row", message="y_event[1:4]")
#: a near miss: the angles before the impact negated are no slice of the state there
ANGLES_NEGATED = Planted(
    name="run-events-p46-angles-negated", problem=46, file="problem_46.py",
    old='''t_event, q_minus, qd_minus = free["t_event"], free["y_event"][:3], free["y_event"][3:]''',
    new='''t_event, q_minus, qd_minus = free["t_event"], -free["y_event"][:3], free["y_event"][3:]''',
    check="p46.event_and_impact")


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot([46])


def test_a_state_at_an_event_read_from_another_start_is_told(tmp_path, kit_oracle, deferred_ids, slot):
    target = failed_alike(ANGLES_ONE_ENTRY_ON, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    assert_told(ANGLES_ONE_ENTRY_ON, target)


def test_a_state_at_an_event_negated_is_no_row(tmp_path, kit_oracle, deferred_ids, slot):
    target = failed_alike(ANGLES_NEGATED, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    assert "state_row" not in families_of(target.diagnosis), (target.diagnosis, target.hint)


# ------------------------------------------------------------------------------------------ stand-ins


MOTION = {"time": "t", "states": ("q", "qd"), "events": ("t_event",),
          "at_events": {"q_event": ("t_event", "q"), "qd_event": ("t_event", "qd")}}


def _run(t_event=1.0):
    t = np.linspace(0.0, 1.0, 11)
    q = np.column_stack([t, 2 * t * t, 3 - t])
    qd = np.column_stack([np.ones_like(t), 4 * t, -np.ones_like(t)])
    return {"t": t, "q": q, "qd": qd, "t_event": t_event, "q_event": q[-1].copy(), "qd_event": qd[-1].copy()}


def _evidence(key, value, t_event=1.0):
    ours = _run()
    mine = dict(_run(t_event), **{key: np.asarray(value, dtype=float)})
    return Evidence(mine[key], ours[key], Tol("at the event", 1e-3), key,
                    source=Source("stub.run", (), (key,), ours), student=Source("stub.run", (), (key,), mine))


def test_the_whole_state_at_an_event_is_its_states_in_order():
    y, offsets = event_state(_run(), MOTION, "t_event", 1.0)
    assert np.allclose(y, [1.0, 2.0, 2.0, 1.0, 4.0, -1.0]) and offsets == {"q": 0, "qd": 3}


def test_a_slice_of_the_state_at_an_event_from_another_start_is_a_row():
    decl = Declaration(motion=MOTION)
    found = event_state_slips(_evidence("q_event", [2.0, 2.0, 1.0]), decl)  # y_event[1:4]
    assert [h.name for h in found] == ["state_row"] and "y_event[1:4]" in found[0].detail, found
    found = event_state_slips(_evidence("qd_event", [1.0, 2.0, 2.0]), decl)  # the halves exchanged
    assert [h.name for h in found] == ["state_row"], found


def test_no_slice_is_told_where_the_event_is_elsewhere_or_the_value_no_slice():
    decl = Declaration(motion=MOTION)
    assert event_state_slips(_evidence("q_event", [2.0, 2.0, 1.0], t_event=0.9), decl) == []
    assert event_state_slips(_evidence("q_event", [2.0, 1.0, 2.0]), decl) == []  # entries in another order
    assert event_state_slips(_evidence("q_event", [-1.0, -2.0, -2.0]), decl) == []  # negated


# ------------------------------------------------------------------------------------------ loose tolerances


#: solve_ivp at rtol 1e-2 with an atol of its own (the band's run at rtol 1e-2 and atol 1e-6 is the nearest the
#: engine re-runs): the bar's random runs leave the band by a few tolerances only
LOOSE_RANDOM_BAR = Planted(
    name="run-events-p44-rtol-1e-2-atol-1e-7", problem=44, file="problem_44.py",
    old="events=[make_contact_event(s, d)], rtol=1e-10, atol=1e-12)",
    new="events=[make_contact_event(s, d)], rtol=1e-2, atol=1e-7)",
    check="p44.event_random", diagnosis="step_size", message="rtol = 0.01")


@pytest.fixture(scope="module")
def bar_slot():
    yield from warm_slot([44])


def test_a_run_just_outside_its_band_at_loose_tolerances_is_told(tmp_path, kit_oracle, deferred_ids, bar_slot):
    target = failed_alike(LOOSE_RANDOM_BAR, tmp_path / "pkg", kit_oracle, deferred_ids, bar_slot)
    assert_told(LOOSE_RANDOM_BAR, target)


class _Scene:
    """The reference's runs by their variant argument (None: its own); a variant it lacks is its own run."""

    def __init__(self, runs):
        self.runs = runs

    def reference(self, probe, args, persist=False):
        return self.runs.get(None if args[-1] is None else tuple(args[-1]), self.runs[None])


def _exp_run(rate, t_event):
    t = np.linspace(0.0, 1.0, 21)
    return {"t": t, "y": np.exp(rate * t)[:, None], "t_event": t_event}


def _loose(student):
    """The student's run against the reference's (``exp(t)``, its event at 1.0) and a run at looser tolerances
    that errs by 0.3 % of the value (``exp(1.003 t)``), within a band of 1e-3."""
    from grader.diagnosis.runs import parameter_slips

    motion = {"time": "t", "states": ("y",), "events": ("t_event",), "variants": {"arg": 0, "tolerances": True}}
    ours, loose = _exp_run(1.0, 1.0), _exp_run(1.003, 1.0)
    scene = _Scene({None: ours, ("tolerance", 1e-2, 1e-2): loose})
    evidence = Evidence(student["y"], ours["y"], Tol("band", 1e-3), "y",
                        source=Source("stub.run", (None,), ("y",), ours),
                        student=Source("stub.run", (None,), ("y",), student))
    return parameter_slips(scene, evidence, Declaration(motion=motion))


def test_a_run_nearer_a_looser_solve_than_the_reference_is_its_tolerance():
    """The student's run differs from the reference's by a few tolerances (no run clearly another than the
    reference's): it is told at loose tolerances where the looser run is far nearer to it than the reference's,
    and not where the student's run is as far from both (another rate)."""
    found = _loose(_exp_run(1.0031, 1.0))
    assert [h.name for h in found] == ["step_size"], found
    assert _loose(_exp_run(1.0015, 1.0)) == []  # halfway: as near to the reference's run as to the loose one
    assert _loose(_exp_run(0.997, 1.0)) == []  # off the other way
