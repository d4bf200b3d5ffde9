"""Shared by the tests of the student kit: one answer key per test session (recorded from the reference), and
the comparison of a live report with a kit report."""

from __future__ import annotations

import pytest

from grader.oracle import KeyOracle
from grader.results import Status

#: the kit seed of the tests' answer key
KIT_SEED = 2024
#: the seed of the live gradings the kit is compared with
SEED = 12345

#: (submission, check id) → why its verdict may differ between the live reference and the kit.  Each entry is a
#: randomized comparison whose failure the kit's fixed pool does not reproduce.
KNOWN_DIVERGENT: dict[tuple[str, str], str] = {}


@pytest.fixture(scope="session")
def answer_key():
    from grader.kit import record_key

    key, _ = record_key(seed=KIT_SEED)
    return key


@pytest.fixture(scope="session")
def kit_oracle(answer_key):
    return KeyOracle(answer_key)


@pytest.fixture(scope="session")
def deferred_ids(answer_key):
    """The checks the kit does not grade: secret and hidden ones, and public ones that share their values."""
    from grader.kit import secret_check_ids

    return secret_check_ids() | set(answer_key.withheld)


def public_verdicts(report) -> dict:
    return {r.check_id: (r.status.value, r.diagnosis) for r in report.results if r.status is not Status.DEFERRED}


def assert_same_verdicts(name: str, live, kit, secret: set[str]) -> None:
    """The kit gives every public check of ``live`` the same status and diagnosis, and defers exactly the ones
    named in ``secret`` (secret, hidden, withheld)."""
    deferred = {r.check_id for r in kit.results if r.status is Status.DEFERRED}
    assert deferred == {r.check_id for r in live.results if r.check_id in secret}, name
    mine = {r.check_id: r for r in live.results}
    different = []
    for check_id, verdict in public_verdicts(kit).items():
        if (name, check_id) in KNOWN_DIVERGENT:
            continue
        expected = (mine[check_id].status.value, mine[check_id].diagnosis)
        if verdict != expected:
            kit_message = next(r.message for r in kit.results if r.check_id == check_id)
            different.append(f"{check_id}: live {expected}, kit {verdict}\n  live: {mine[check_id].message[:400]}"
                             f"\n  kit: {kit_message[:400]}")
    assert not different, f"{name}: the kit's verdicts differ from the live reference's:\n" + "\n".join(different)
