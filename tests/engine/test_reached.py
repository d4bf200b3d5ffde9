"""Slips the engine reaches beyond the grammar's first ones, graded as ``grade batch`` grades.

* ``tests/engine/reach.toml``: a slip of precision inside a formula (``grader.diagnosis.mutants``), a whole value in
  other units (1000 or 1/1000 times the expected one: a mass in grams; ``grader.diagnosis.grammar``), the state at an
  event read from the run's last output before it (``grader.diagnosis.runs``), a module's constant typed in other
  units where the value compared does not change with the call's arguments (one input is all there is); near misses:
  a factor 100 of a whole inertia, a value off by a relative 3e-7, the state two outputs before the event, the
  constant at another value.
* ``tests/engine/operators.toml``: the formula tier's operators (``grader.diagnosis.mutants``): a name bound to a sine
  read as the cosine of its angle, an entry of a matrix written 0, a solve that divides by the matrix's diagonal alone;
  near misses: the sine of twice the angle, the entry a tenth of its value, a division by the trace.
* ``tests/engine/names.toml``: one read of a name for another of its kind (``grader.diagnosis.mutants``): an angle
  for another angle of the function, a parameter read as its default's constant, a gravity read as the Earth's; near
  misses: the sine of the sum of both angles, a division by the mean of the argument and the constant.

Live the check names the slip, the kit names the same or nothing, with the engine off no catalogue names it; each
near miss names no cause of its family.
"""

from pathlib import Path

import pytest

from checks._diagnoses import families_of
from grader.results import Status

from ..kit_support import (  # noqa: F401 (fixtures)
    assert_named_live_and_alike,
    engine_mistakes,
    grade_live_and_kit,
    warm_slot,
)
from ..submissions import Planted, build_planted

ROOT = Path(__file__).resolve().parents[2]
#: the tables of slips and their near misses
TABLES = [ROOT / "tests" / "engine" / name for name in ("reach.toml", "operators.toml", "names.toml")]
PLANTED, FAMILIES = [], {}
for _table in TABLES:
    _planted, _families = engine_mistakes(_table)
    PLANTED += _planted
    FAMILIES.update(_families)


def near_misses(table) -> list:
    import tomllib

    entries = tomllib.loads(table.read_text())["near"]
    return [(Planted(name=e["name"], problem=e["problem"], file=e["file"], old=e["old"], new=e["new"], check=e["check"],
                     diagnosis=e["diagnosis"], message=e["message"], also=tuple(e.get("also", ()))), e["family"])
            for e in entries]


NEAR = [near for table in TABLES for near in near_misses(table)]


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({m.problem for m in PLANTED} | {m.problem for m, _ in NEAR}))


@pytest.mark.parametrize("mistake", PLANTED, ids=lambda m: m.name)
def test_a_slip_is_named_live_and_alike_in_the_kit(
        mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch):
    assert families_of(mistake.diagnosis) == FAMILIES[mistake.name]
    assert_named_live_and_alike(mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch)


@pytest.mark.parametrize("near", NEAR, ids=lambda n: n[0].name)
def test_a_near_miss_is_not_named(near, tmp_path, kit_oracle, slot):
    mistake, family = near
    submission = build_planted(mistake, tmp_path / "pkg")
    live, kit = grade_live_and_kit(mistake.problem, submission, kit_oracle, zygote=slot)
    for report in (live, kit):
        target = {r.check_id: r for r in report.results}[mistake.check]
        assert target.status is Status.FAILED, target.message
        assert family not in families_of(target.diagnosis), (target.diagnosis, target.hint)
