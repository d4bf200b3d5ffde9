"""Shared by the tests of the student kit: one answer key per test session (recorded from the reference), and
the comparison of a live report with a kit report."""

from __future__ import annotations

import copy

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


class SharedChild:
    """One sandboxed child for the live and the kit grading of one submission: a probe call with the same
    arguments (the sheet's cases, say) is answered once; the planted submissions are deterministic."""

    def __init__(self, child):
        self.child = child
        self.answers: dict = {}

    def call(self, probe, *args, timeout=None):
        from grader.errors import StudentFault
        from grader.oracle import call_key

        key = call_key(probe, args)
        if key not in self.answers:
            try:
                self.answers[key] = (False, self.child.call(probe, *args, timeout=timeout))
            except StudentFault as exc:
                self.answers[key] = (True, exc)
        raised, value = self.answers[key]
        if raised:
            raise value
        return copy.deepcopy(value)

    def output(self):
        return self.child.output()


def grade_live_and_kit(problem: int, source, kit_oracle, seed: int = SEED):
    """The live report and the kit's report of one problem of one submission, graded as ``grade_problem`` does
    (materialized once, one sandboxed child), first with the live reference, then with the answer key."""
    from grader.sandbox import Child
    from grader.context import Context
    from grader.loader import cleanup, materialize, read_answers
    from grader.oracle import LiveOracle
    from grader.results import ProblemReport
    from grader.runner import _manual_items, _run_checks, problem_module

    module = problem_module(problem)
    submission = materialize(source)
    answers, answers_error = read_answers(submission.path)
    reports = []
    try:
        with Child(submission.path) as child:
            child.start()
            shared = SharedChild(child)
            for oracle in (LiveOracle(), kit_oracle):
                ctx = Context(problem, shared, answers, answers_error, seed, oracle)
                results = _run_checks(module, ctx, problem)
                reports.append(ProblemReport(problem, module.TITLE, tuple(results),
                                             tuple(_manual_items(module, ctx, problem)), seed=seed))
    finally:
        cleanup(submission)
    return reports


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
