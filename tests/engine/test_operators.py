"""Slips inside a formula that the formula tier's operators reproduce (``tests/engine/operators.toml``), graded as
``grade batch`` grades: a name bound to a sine read as the cosine of its angle, an entry of a matrix written 0, a solve
that divides by the matrix's diagonal alone (``grader.diagnosis.mutants``).  Live the check names the slip, the kit
names the same or nothing, with the engine off no catalogue names it; each has a near miss that names no cause of its
family (the sine of twice the angle, the entry a tenth of its value, a division by the trace).
"""

from pathlib import Path

import pytest

from checks._diagnoses import families_of
from grader.results import Status

from ..kit_support import (  # noqa: F401 (fixtures)
    assert_named_failure,
    assert_no_catalogue_names_it,
    assert_same_verdicts,
    engine_mistakes,
    grade_live_and_kit,
    warm_slot,
)
from ..submissions import Planted, build_planted

ROOT = Path(__file__).resolve().parents[2]
TABLE = ROOT / "tests" / "engine" / "operators.toml"
PLANTED, FAMILIES = engine_mistakes(TABLE)


def near_misses() -> list:
    import tomllib

    entries = tomllib.loads(TABLE.read_text())["near"]
    return [(Planted(name=e["name"], problem=e["problem"], file=e["file"], old=e["old"], new=e["new"], check=e["check"],
                     diagnosis=e["diagnosis"], message=e["message"], also=tuple(e.get("also", ()))), e["family"])
            for e in entries]


NEAR = near_misses()


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({m.problem for m in PLANTED} | {m.problem for m, _ in NEAR}))


@pytest.mark.parametrize("mistake", PLANTED, ids=lambda m: m.name)
def test_a_slip_is_named_live_and_alike_in_the_kit(
        mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch):
    submission = build_planted(mistake, tmp_path / "pkg")
    live, kit = grade_live_and_kit(mistake.problem, submission, kit_oracle, zygote=slot)
    assert_named_failure(mistake, live)
    assert families_of(mistake.diagnosis) == (FAMILIES[mistake.name],)
    theirs = {r.check_id: r for r in kit.results}[mistake.check]
    assert theirs.status is Status.FAILED and theirs.diagnosis in ("", mistake.diagnosis), theirs.diagnosis
    assert_same_verdicts(mistake.name, live, kit, deferred_ids)
    assert_no_catalogue_names_it(mistake, submission, slot, monkeypatch)


@pytest.mark.parametrize("near", NEAR, ids=lambda n: n[0].name)
def test_a_near_miss_is_not_named(near, tmp_path, kit_oracle, slot):
    mistake, family = near
    submission = build_planted(mistake, tmp_path / "pkg")
    live, kit = grade_live_and_kit(mistake.problem, submission, kit_oracle, zygote=slot)
    for report in (live, kit):
        target = {r.check_id: r for r in report.results}[mistake.check]
        assert target.status is Status.FAILED, target.message
        assert family not in families_of(target.diagnosis), (target.diagnosis, target.hint)
