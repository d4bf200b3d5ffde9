"""The one door to the reference (that check modules never import it is ``test_one_door``): the oracle's disk cache
verifies what it reads back, and randomized comparisons in kit mode show the simplest failing input of the recorded pool."""

import json
from pathlib import Path

import numpy as np
import pytest

from grader.context import simplicity
from grader.oracle import AnswerKey, KeyOracle, LiveOracle, call_key
from grader.errors import GraderFault

ROOT = Path(__file__).resolve().parents[1]
# ---------------------------------------------------------------------------------------------- the disk cache


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("GRADER_CACHE", str(tmp_path / "cache"))
    return tmp_path / "cache"


def _entry(cache):
    entries = list(cache.rglob("*.json"))
    assert len(entries) == 1
    return entries[0]


def test_disk_cache_round_trip_and_poisoned_payload_is_recomputed(cache):
    value = LiveOracle().reference("problem_06.frames", (), persist=True)
    path = _entry(cache)
    entry = json.loads(path.read_text())
    assert entry["key"] == call_key("problem_06.frames", ())
    # A poisoned payload (the digest no longer matches): discarded and recomputed, never trusted.
    forged = json.loads(entry["payload"])
    forged["A_IC1"]["data"] = [0.0] * 9
    entry["payload"] = json.dumps(forged)
    path.write_text(json.dumps(entry))
    again = LiveOracle().reference("problem_06.frames", (), persist=True)
    assert np.allclose(again["A_IC1"], value["A_IC1"]) and not np.allclose(again["A_IC1"], 0.0)
    # The recomputed entry was written back and verifies.
    assert json.loads(_entry(cache).read_text())["payload"] != entry["payload"]


def test_disk_cache_entry_moved_to_another_call_is_not_trusted(cache):
    LiveOracle().reference("problem_06.cardan", (0.1, 0.2, 0.3), persist=True)
    source = _entry(cache)
    other = LiveOracle()._entry_path(call_key("problem_06.cardan", (0.4, 0.5, 0.6)))
    source.rename(other)  # a valid entry of another call, under this call's name
    value = LiveOracle().reference("problem_06.cardan", (0.4, 0.5, 0.6), persist=True)
    expected = LiveOracle().reference("problem_06.cardan", (0.4, 0.5, 0.6))
    assert np.allclose(value, expected)


def test_disk_cache_unreadable_entry_is_recomputed(cache):
    LiveOracle().reference("problem_06.frames", (), persist=True)
    path = _entry(cache)
    path.write_text("{not json")
    value = LiveOracle().reference("problem_06.frames", (), persist=True)
    assert set(value) == {"A_IC1", "A_IC2", "A_IC3"}
    json.loads(_entry(cache).read_text())


def test_disk_cache_digest_needs_the_private_secret(cache):
    LiveOracle().reference("problem_06.frames", (), persist=True)
    secret = cache / "cache.secret"
    assert secret.stat().st_mode & 0o077 == 0  # readable by its owner only
    secret.write_bytes(b"x" * 32)  # another secret: every entry becomes unverifiable
    path = _entry(cache)
    before = path.read_text()
    LiveOracle().reference("problem_06.frames", (), persist=True)
    assert _entry(cache).read_text() != before


def test_memory_keeps_the_most_recently_used_results_and_no_more(monkeypatch):
    """A batch's slot lives for the whole class: its memory of reference results is bounded, and the calls every
    student repeats (the sheet's cases) stay while each student's random inputs pass through."""
    import grader.oracle as oracle_module

    monkeypatch.setattr(oracle_module, "MEMORY_ENTRIES", 3)
    oracle = LiveOracle()
    runs = []
    real = oracle._run
    monkeypatch.setattr(oracle, "_run", lambda probe, args: runs.append(args) or real(probe, args))
    sheet = (0.1, 0.2, 0.3)
    for student in range(6):  # the sheet's case, then two random inputs of this student
        oracle.reference("problem_06.cardan", sheet)
        for k in range(2):
            oracle.reference("problem_06.cardan", (0.01 * student, 0.02 * k, 0.5))
    assert len(oracle._memory) == 3
    assert runs.count(sheet) == 1  # computed once, then remembered across the students
    assert len(runs) == 1 + 6 * 2
    oracle.reference("problem_06.cardan", (0.0, 0.0, 0.5))  # the first student's input: dropped long ago
    assert len(runs) == 14 and len(oracle._memory) == 3


# ---------------------------------------------------------------------------------------------- the key


def test_key_oracle_answers_recorded_calls_and_refuses_others():
    key = AnswerKey(seed=1, fingerprint="x")
    key.calls[call_key("problem_06.cardan", (0.0, 0.0, 0.0))] = {"value": {"__array__": [3, 3],
                                                                            "data": list(np.eye(3).ravel())},
                                                                  "checks": ["p06.cardan_rotation"]}
    oracle = KeyOracle(key, check_fingerprint=False)
    assert np.allclose(oracle.reference("problem_06.cardan", (0.0, 0.0, 0.0)), np.eye(3))
    with pytest.raises(GraderFault, match="no value"):
        oracle.reference("problem_06.cardan", (0.0, 0.0, 0.1))
    again = AnswerKey.loads(key.dumps())
    assert again.calls == key.calls and again.seed == 1


def test_key_recorded_with_other_checks_is_refused():
    with pytest.raises(GraderFault, match="other checks"):
        KeyOracle(AnswerKey(seed=1, fingerprint="not these checks"))


def test_simplicity_prefers_fewer_then_smaller_numbers():
    short = ([np.eye(3)], 0.1)
    longer = ([np.eye(3), np.eye(3)], 0.1)
    small = ({"B_omega_B": np.array([0.0, 0.0, 1.0])}, 0.01, 1)
    large = ({"B_omega_B": np.array([0.0, 3.0, 1.0])}, 0.01, 1)
    assert simplicity(short) < simplicity(longer)
    assert simplicity(small) < simplicity(large)
    assert sorted([large, small], key=simplicity) == [small, large]


# ---------------------------------------------------------------------------------------------- item 12


def test_grading_writes_nothing_where_it_runs(tmp_path):
    """Hypothesis keeps an example database and a cache of the constants it collects from local source files (the
    reference's included) in ``.hypothesis/`` of the current folder; grading must leave the folder untouched."""
    import os
    import subprocess
    import sys

    from .submissions import copy_reference

    work = tmp_path / "mywork"
    copy_reference(work)
    before = sorted(p.relative_to(work) for p in work.rglob("*"))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]),
               GRADER_ORACLE="live")
    done = subprocess.run([sys.executable, "-m", "grader.cli", "problem-6", "problem-7", "--seed", "5"],
                          cwd=work, env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "Problem 6" in done.stdout
    after = sorted(p.relative_to(work) for p in work.rglob("*"))
    assert after == before, f"grading wrote into the folder: {sorted(set(after) - set(before))}"
