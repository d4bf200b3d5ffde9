"""The formula tier gives up a measuring that cannot end within its budget (``grader.diagnosis.mutants._hopeless``):
after a few mutants, where the rest at the pace those took would need more than twice what remains of the budget,
the measuring ends as one whose time ran out (nothing named), without spending the rest of the budget first.

Problem 12's wheel (3001 steps) is such a run: its 167 mutants take about seven times the budget, and each of the
check's two compared values spent the whole budget naming nothing.  A made-up problem's long loop is given up the
same way; the same loop on a short input is measured to the end and its slip named."""

import dataclasses
import json
from types import SimpleNamespace

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants, trace

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for a measuring that cannot end within its budget."""

import numpy as np


def spiral(steps, rate):
    """A made-up point turned and pulled in ``steps`` small steps."""
    # BEGIN SOLUTION problem 72
    x = np.array([1.0, 0.0])
    for _ in range(int(steps)):
        c, s = np.cos(rate), np.sin(rate)
        x = np.array([c * x[0] - s * x[1], s * x[0] + c * x[1]])
        x = x * (1.0 - 1e-4 * rate)
    return x
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 72, "hopeless")


def _reference(steps, rate, sign=1.0):
    x = np.array([1.0, 0.0])
    for _ in range(int(steps)):
        c, s = np.cos(rate), np.sin(rate)
        x = np.array([c * x[0] - sign * s * x[1], sign * s * x[0] + c * x[1]])
        x = x * (1.0 - 1e-4 * rate)
    return x


def test_a_measuring_is_given_up_where_the_rest_would_overrun_the_budget_twice():
    left = [SimpleNamespace(name=f"m{k}") for k in range(100)]
    slow, fast = [0.1] * 4, [0.001] * 4
    assert mutants._hopeless(1.6, slow, left, None)  # 100 x 0.1 s > 2 x 1.6 s
    assert not mutants._hopeless(1.6, fast, left, None)  # 0.1 s: it ends
    assert mutants._hopeless(1.6, slow[:2], left, None)  # judged after two
    assert not mutants._hopeless(1.6, slow[:1], left, None)  # too few measured to judge
    assert not mutants._hopeless(1.6, slow[:3], left, None)  # judged at 2, 4, 8, 16, ... only
    assert not mutants._hopeless(1.6, slow + [0.1], left, None)
    assert not mutants._hopeless(1.6, slow, left[:30], None)  # 3 s <= 3.2 s: it may end
    assert not mutants._hopeless(1.6, [0.1, 0.1, 0.001, 0.001], left, None)  # the median, not the
    # slowest


def _traced(tmp_path, monkeypatch, work, whole=False):
    """What ``work`` found, and the trace's notes (their kinds, or ``whole`` notes)."""
    path = tmp_path / "trace.jsonl"
    path.unlink(missing_ok=True)
    monkeypatch.setenv(trace.VARIABLE, str(path))
    trace.begin("p72.spiral", "explain")
    try:
        found = work()
    finally:
        trace.end()
    notes = [note for line in path.read_text().splitlines() for note in json.loads(line)["notes"]]
    return found, (notes if whole else [note["what"] for note in notes])


def test_a_long_loop_no_mutant_can_be_measured_through_is_given_up(made_up, tmp_path, monkeypatch):
    """120000 steps a call: the loop's mutants cannot all be measured within the budget, and nothing the student
    gave is reproduced by the first ones either; the measuring is given up, and nothing named."""
    inputs = [(120_000, 0.01), (100_000, 0.013)]
    evidences = made_up_evidences(made_up, "spiral", lambda n, r: _reference(n, r) + 0.01, inputs, number=72)
    found, notes = _traced(tmp_path, monkeypatch, lambda: mutants.mutant_slips(scene("p72.spiral"), evidences))
    assert not found
    assert "hopeless" in notes and "timeout" in notes, notes


def test_the_same_loop_on_a_short_input_is_measured_through_and_its_slip_named(made_up, tmp_path, monkeypatch):
    """The rotation's sine with its sign turned, on 50 steps a call: every mutant is measured and the slip named."""
    inputs = [(50, 0.01), (40, 0.013)]
    evidences = made_up_evidences(made_up, "spiral", lambda n, r: _reference(n, r, sign=-1.0), inputs, number=72)
    found, notes = _traced(tmp_path, monkeypatch, lambda: mutants.mutant_slips(scene("p72.spiral"), evidences))
    assert "hopeless" not in notes and "timeout" not in notes, notes
    assert found and {DIAGNOSES[h.name].family for h in found} == {"sign"}, [(h.name, h.detail) for h in found]


def test_another_value_of_a_call_given_up_is_given_up_at_once_in_the_same_grading(made_up, tmp_path, monkeypatch):
    """Two explanations of one grading ask of the same long call (two compared values, as problem 12's wheel's
    body's point and contact's point from one run): once the first's measuring is given up, the second's is given
    up before any mutant is measured, at the pace the first measured; another grading (another context) measures its
    own."""
    inputs = [(120_000, 0.01), (100_000, 0.013)]
    first = made_up_evidences(made_up, "spiral", lambda n, r: _reference(n, r) + 0.01, inputs, number=72)
    values = [first, [dataclasses.replace(e, got=e.got + 0.01) for e in first]]  # the same calls of the same probe
    grading = scene("p72.spiral")

    def given_up(evidences, within):
        found, notes = _traced(tmp_path, monkeypatch, lambda: mutants.mutant_slips(within, evidences), whole=True)
        assert not found
        return [note for note in notes if note["what"] == "hopeless"]

    first = given_up(values[0], grading)
    assert len(first) == 1 and first[0]["measured"] >= mutants.PROJECTED_AFTER, first
    second = given_up(values[1], grading)
    assert len(second) == 1 and second[0]["measured"] == 0 and second[0]["each"] == first[0]["each"], second
    other = given_up(values[1], scene("p72.spiral"))
    assert len(other) == 1 and other[0]["measured"] >= mutants.PROJECTED_AFTER, other


def test_a_call_is_traced_once_in_a_grading_whose_explanations_ask_it_again(made_up, monkeypatch):
    """The codes a call runs are traced (``_traced_once``, a run under a profiler) once for the grading's two
    explanations of one call, and again in another grading."""
    inputs = [(50, 0.01), (40, 0.013)]
    first = made_up_evidences(made_up, "spiral", lambda n, r: _reference(n, r) + 0.01, inputs, number=72)
    values = [first, [dataclasses.replace(e, got=e.got + 0.01) for e in first]]
    traced = []
    once = mutants._traced_once
    monkeypatch.setattr(mutants, "_traced_once",
                        lambda *args, **kwargs: traced.append(args[2]) or once(*args, **kwargs))
    grading = scene("p72.spiral")
    for evidences in values:
        mutants.mutant_slips(grading, evidences)
    assert len(traced) == 1, traced
    mutants.mutant_slips(scene("p72.spiral"), values[1])
    assert len(traced) == 2, traced
