"""The diagnosis engine's second input by a problem's constants drawn anew (``grader.diagnosis.rebound``): a
function that reads its module's constants (the sheet's angles) rather than taking them as arguments is called again
with the constants its probe declares (``rebind``) bound to drawn values, on the reference and on the student's
package alike (``probes._rebound``).

* The probe binds the constants for the call only, and puts them back (one the module lacks is removed again).
* The drawn values are near the sheet's, each changed, away from the special angles and from each other; a value
  that only scales with them is no second input.
* Graded as ``grade batch`` grades (``tests/engine/rebound.toml``): a slip in a function of the sheet's frames is
  named live on the two inputs and nothing without the constants drawn; the kit names nothing (it holds the sheet's
  fixed case at the sheet's digits only, where the engine names nothing), with the same verdicts; with the engine
  off no cause of that family is named.  The same slip with the sheet's numbers typed in (its value at the sheet's
  angles the same) gives the same value at the drawn constants, and is not named as the slip.
"""

import dataclasses
import tomllib
from pathlib import Path

import numpy as np
import pytest

from checks._diagnoses import families_of
from grader.checking import Tol
from grader.diagnosis import engine as explaining
from grader.diagnosis import rebound
from grader.results import Status
from probes import _rebound

from ..kit_support import (  # noqa: F401 (fixtures)
    assert_named_failure,
    assert_no_catalogue_names_it,
    assert_same_verdicts,
    graded_table,
    grade_live_and_kit,
)
from ..submissions import Planted, build_planted

ROOT = Path(__file__).resolve().parents[2]
TABLE = ROOT / "tests" / "engine" / "rebound.toml"
TIGHT = Tol("tight", 1e-9, 1e-9)


def test_the_constants_are_bound_for_the_call_only():
    import reference
    from reference import problem_06

    sheet = problem_06.GAMMA
    bindings = [["problem_06", "GAMMA", 0.2], ["problem_06", "NOT_THERE", 1.0]]
    frames = _rebound.rebound(reference, "problem_06.frames", bindings, [])
    assert np.allclose(frames["A_IC1"], problem_06.R3(0.2))
    assert problem_06.GAMMA == sheet and not hasattr(problem_06, "NOT_THERE")
    assert _rebound.constants(reference, "problem_06", ["GAMMA", "C3_V", "R3", "NOT_THERE"]) == {
        "GAMMA": sheet, "C3_V": list(problem_06.C3_V)}  # a function, and a name the module lacks, are no constants


def test_a_row_of_numbers_is_bound_in_its_kind_and_put_back():
    """Problem 27's axis (a tuple) and problem 8's angular velocity (an array) are rows of numbers: the sheet's
    values are read as lists, bound as a tuple and an array for the call, and put back."""
    import reference
    from reference import problem_08, problem_27

    assert _rebound.constants(reference, "problem_27", ["AXIS_2", "JOINT_1"]) == {
        "AXIS_2": list(problem_27.AXIS_2), "JOINT_1": [0.0, 0.0]}
    sheet = problem_27.jacobian_a()
    turned = _rebound.rebound(reference, "problem_27.jacobian_a", [["problem_27", "AXIS_2", [0.6, 0.8]]], [])
    assert not np.allclose(turned, sheet)
    assert problem_27.AXIS_2 == (0.26, 0.97) and isinstance(problem_27.AXIS_2, tuple)
    seen = []
    real = problem_08._run

    def spy(step, x0, **kwargs):
        seen.append(problem_08.I_OMEGA)
        return real(step, x0, **kwargs)

    problem_08._run = spy
    try:
        _rebound.rebound(reference, "problem_08.part", [["problem_08", "I_OMEGA", [0.4, 0.7, 0.5]]], ["a"])
    finally:
        problem_08._run = real
    assert isinstance(seen[0], np.ndarray) and np.allclose(seen[0], [0.4, 0.7, 0.5])
    assert np.allclose(problem_08.I_OMEGA, np.sqrt(1.0 / 3.0))


def test_each_number_of_a_row_is_drawn_and_its_zeros_kept():
    import reference

    class Scene:
        def reference(self, probe, args):
            return getattr(_rebound, probe.rpartition(".")[2])(reference, *args)

    sheet = {"AXIS_2": (0.26, 0.97), "JOINT_3": (1.82, 6.61), "END_EFFECTOR": (5.17, 2.83)}
    for attempt in range(10):
        drawn = {name: value for _, name, value in rebound._bindings(Scene(), "problem_27.jacobian_a", [3, attempt],
                                                                     attempt)}
        assert set(drawn) == set(sheet), drawn  # JOINT_1 is (0, 0): nothing to draw
        for name, row in sheet.items():
            ratios = np.array(drawn[name]) / np.array(row)
            assert np.all((0.6 <= ratios) & (ratios <= 1.4)) and np.all(abs(ratios - 1.0) >= rebound.LEAST_CHANGE)
    angles = {name: value for _, name, value in rebound._bindings(Scene(), "problem_08.part", [3, 0], 0)}
    assert angles["ANGLES0"][:2] == [0.0, 0.0] and angles["ANGLES0"][2] != np.pi / 2


def test_the_drawn_constants_are_near_the_sheets_and_apart():
    import reference
    from reference import problem_06

    class Scene:
        def reference(self, probe, args):
            return getattr(_rebound, probe.rpartition(".")[2])(reference, *args)

    for attempt in range(20):
        drawn = rebound._bindings(Scene(), "problem_06.frames", [7, attempt], attempt)
        values = {name: value for _, name, value in drawn}
        assert set(values) == {"GAMMA", "BETA", "ALPHA"}
        for name, value in values.items():
            ratio = value / getattr(problem_06, name)
            assert 0.6 <= ratio <= 1.4 and abs(ratio - 1.0) >= rebound.LEAST_CHANGE
            assert not rebound._special(value)
        assert len({round(v, 3) for v in values.values()}) == 3


def test_a_value_that_only_scales_with_the_constants_is_no_second_input():
    """A position set by a length drawn anew is the shown one scaled: it would confirm any slip that scales it."""
    shown = np.array([0.5, -0.2, 0.0])
    assert rebound._scaled(1.3 * shown, shown, TIGHT)
    assert not rebound._scaled(1.3 * shown + np.array([0.0, 0.0, 0.1]), shown, TIGHT)


REBOUND, _, slot, test_the_graded_mistakes_are_of_their_families = graded_table(TABLE)
NEAR = {e["name"]: (e["near_old"], e["near_new"]) for e in tomllib.loads(TABLE.read_text())["mistake"]}


@pytest.mark.parametrize("mistake", REBOUND, ids=lambda m: m.name)
def test_a_slip_that_reads_the_constants_is_named_at_constants_drawn(
        mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch):
    from grader import grade_problem
    from grader.workers import Forked

    from ..kit_support import SEED

    submission = build_planted(mistake, tmp_path / "pkg")
    live, kit = grade_live_and_kit(mistake.problem, submission, kit_oracle, zygote=slot)
    target = assert_named_failure(mistake, live)
    assert "on the input shown and on a second one" in target.hint, target.hint
    theirs = {r.check_id: r for r in kit.results}[mistake.check]
    assert theirs.status is Status.FAILED and theirs.diagnosis == "", theirs.diagnosis
    assert_same_verdicts(mistake.name, live, kit, deferred_ids)
    with monkeypatch.context() as patched:  # without the constants drawn: one input, nothing named
        patched.setattr(explaining, "rebound_input", lambda scene, evidence: None)
        alone = grade_problem(mistake.problem, submission, seed=SEED, workers=Forked(slot))
    result = {r.check_id: r for r in alone.results}[mistake.check]
    assert result.status is Status.FAILED and result.diagnosis == "", result.diagnosis
    assert_no_catalogue_names_it(mistake, submission, slot, monkeypatch)


@pytest.mark.parametrize("mistake", REBOUND, ids=lambda m: m.name)
def test_the_slip_with_the_numbers_typed_in_is_not_named_as_it(mistake, tmp_path, kit_oracle, slot):
    old, new = NEAR[mistake.name]
    typed = dataclasses.replace(mistake, old=old, new=new)
    submission = build_planted(typed, tmp_path / "pkg")
    live, _ = grade_live_and_kit(mistake.problem, submission, kit_oracle, zygote=slot)
    result = {r.check_id: r for r in live.results}[mistake.check]
    assert result.status is Status.FAILED, result.message
    assert not set(families_of(result.diagnosis)) & set(families_of(mistake.diagnosis)), result.diagnosis
    assert mistake.message not in result.hint


#: problem 6's ``C2_v`` from ``C3_v`` through ``R1(alpha)`` taken the wrong way round, and its entries 2 and 3
#: exchanged: the sheet's ``C3_V = (1, 1, 1)`` has those entries alike, so the two give one value there
TRANSPOSED_ON_ALIKE = Planted(
    name="rebound-row-alike-transposed", problem=6, file="problem_06.py",
    old='"C2_v": A["A_IC2"].T @ I_v,', new='"C2_v": R1(ALPHA).T @ C3_V,', check="p06.vectors")
SWAPPED_ENTRIES = Planted(
    name="rebound-row-alike-swapped", problem=6, file="problem_06.py",
    old='"C2_v": A["A_IC2"].T @ I_v,', new='"C2_v": (A["A_IC2"].T @ I_v)[[0, 2, 1]],', check="p06.vectors",
    diagnosis="swapped", message="entries 2 and 3 are swapped")


def test_a_row_of_the_sheet_with_entries_alike_is_drawn_with_each_its_own(tmp_path, slot):
    """The sheet's vector ``C3_V`` has two entries alike: drawn with the angles only, every second input keeps them
    alike, and a rotation taken the wrong way round is told as two entries swapped on both inputs.  The vector is
    drawn too (each entry its own), where the wrong rotation is told nothing and two entries swapped are still told."""
    from grader import grade_problem
    from grader.workers import Forked

    from ..kit_support import SEED

    def graded(mistake):
        submission = build_planted(mistake, tmp_path / mistake.name)
        report = grade_problem(6, submission, seed=SEED, workers=Forked(slot))
        return {r.check_id: r for r in report.results}["p06.vectors"]

    transposed = graded(TRANSPOSED_ON_ALIKE)
    assert transposed.status is Status.FAILED, transposed.message
    assert transposed.diagnosis != "swapped", transposed.hint
    swapped = graded(SWAPPED_ENTRIES)
    assert swapped.status is Status.FAILED and swapped.diagnosis == "swapped", (swapped.diagnosis, swapped.hint)
    assert SWAPPED_ENTRIES.message in swapped.hint, swapped.hint
