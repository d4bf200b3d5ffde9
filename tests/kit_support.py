"""Shared by the tests of the student kit: one answer key per test session (recorded from the reference), and
the comparison of a live report with a kit report."""

from __future__ import annotations

import copy
import fcntl
import pickle
import re
from pathlib import Path

import pytest

from grader.oracle import KeyOracle
from grader.results import Status

#: the kit seed of the tests' answer key
KIT_SEED = 2024
#: the seed of the live gradings the kit is compared with
SEED = 12345

#: (submission, check id) → why its verdict may differ between the live reference and the kit.
KNOWN_DIVERGENT: dict[tuple[str, str], str] = {
    # This forged submission answers each joint function rightly on its first call and emptily after: the live
    # grading's subspace check gets the right answer and its values check the empty one; the kit's draws are other
    # points, so in the same child (live and kit share it) both of the kit's calls come after the first.
    **{("p35-values-reply-emptied", f"p35.{kind}_{part}"): "answers by call count; live and kit share one child"
       for kind in ("rotational", "translational", "virtual_3dof", "rolling_contact")
       for part in ("subspaces", "values")},
    # The live engine traces this value to the reference's answer on the student's own fixed case, which the key
    # must not hold (a lookup of it would answer the student's call: grader.kit._answers_to_the_student); the kit
    # fails alike and names no cause.
    ("located-p12-rotation-backwards", "p12.sheet_cases"): "the reference's answer to the student's fixed case",
    ("alternatives-p12-omega-skew-transposed", "p12.sheet_cases"):
        "the reference's answer to the student's fixed case",
    ("engine-bearing-moment-over-the-whole-distance", "p39.bearing_forces"):
        "the reference's answer to the student's fixed case",
    # A run just outside its band fails on few inputs: of the kit's three recorded random inputs one fails, and a
    # single failing input names no cause; the live grading's draws fail on two, which name it alike.
    ("run-events-p44-rtol-1e-2-atol-1e-7", "p44.event_random"): "one failing input among the kit's recorded ones",
}

@pytest.fixture(autouse=True)
def strict(monkeypatch):
    """A defect of the diagnosis engine fails the test instead of naming no cause (imported by the engine's tests)."""
    import grader.diagnosis as engine

    monkeypatch.setattr(engine, "STRICT", True)


def shared_key_path(folder: Path) -> Path:
    """Where a parallel run keeps its one recording of the key: ``folder`` is the run's shared temporary folder."""
    return folder / f"kit-answer-key-{KIT_SEED}.pickle"


def shared_key(path: Path):
    """The key kept at ``path``: recorded there by the first process to take its lock (the run's controller starts
    one for it, ``tests/conftest.py``), loaded by the others, which wait for it rather than record it again."""
    from grader.kit import record_key

    with open(path.with_suffix(".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if path.exists():
            return pickle.loads(path.read_bytes())
        key, _ = record_key(seed=KIT_SEED)
        partial = path.with_suffix(".partial")
        partial.write_bytes(pickle.dumps(key, protocol=pickle.HIGHEST_PROTOCOL))
        partial.replace(path)
        return key


@pytest.fixture(scope="session")
def answer_key(request, tmp_path_factory):
    """The kit's key, recorded once per run (``shared_key`` in a parallel run, pytest-xdist)."""
    from grader.kit import record_key

    if not hasattr(request.config, "workerinput"):  # a run in one process
        return record_key(seed=KIT_SEED)[0]
    return shared_key(shared_key_path(tmp_path_factory.getbasetemp().parent))


@pytest.fixture(scope="session")
def kit_oracle(answer_key):
    return KeyOracle(answer_key)


@pytest.fixture(scope="session")
def deferred_ids(answer_key):
    """The checks the kit does not grade: secret and hidden ones, and public ones that share their values."""
    from grader.problems import secret_check_ids

    return secret_check_ids() | set(answer_key.withheld)


class SharedChild:
    """One sandboxed child for the live and the kit grading of one submission: a probe call with the same
    arguments (the sheet's cases, say) is answered once; the planted submissions are deterministic."""

    def __init__(self, child):
        self.child = child
        self.answers: dict = {}

    def call(self, probe, *args, timeout=None):
        from grader.errors import StudentFault
        from probes import call_key

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


def grade_live_and_kit(problem: int, source, kit_oracle, seed: int = SEED, zygote=None):
    """The live report and the kit's report of one problem of one submission, graded as ``grade_problem`` does
    (materialized once, one sandboxed child), first with the live reference, then with the answer key.  With
    ``zygote`` (a batch slot's warm process), the child is forked from it, as ``grade batch`` grades."""
    from grader.sandbox import Child
    from grader.context import Context
    from grader.loader import cleanup, materialize
    from grader.oracle import LiveOracle
    from grader.results import ProblemReport
    from grader.runner import _manual_items, _run_checks
    from grader.problems import problem_module

    module = problem_module(problem)
    submission = materialize(source, zygote.staging if zygote is not None else None)
    reports = []
    try:
        with Child(submission.path, zygote=zygote) as child:
            child.start()
            shared = SharedChild(child)
            for oracle in (LiveOracle(), kit_oracle):
                ctx = Context(problem, shared, submission.answers, submission.answers_error, seed, oracle)
                results = _run_checks(module, ctx, problem)
                reports.append(ProblemReport(problem, module.TITLE, tuple(results),
                                             tuple(_manual_items(module, ctx, problem)), seed=seed))
    finally:
        cleanup(submission)
    return reports


def public_verdicts(report) -> dict:
    return {r.check_id: (r.status.value, r.diagnosis) for r in report.results if r.status is not Status.DEFERRED}


#: how the kit begins the message of a check it leaves to the graded submission because the check is judged on the
#: student's own functions of earlier problems, which differ from the reference's (``grader.upstream``)
JUDGED_ON_SUBMISSION = re.compile(r"^judged on your own .* when you submit")
#: how a message names the check of another problem (``problem 6's check “…”``) or of its own problem (``see “…”``,
#: a passing check's pointer at the failing check of the same problem that finds the mistake): the check's title
CHECK_NAMED = re.compile(r"(?:problem \d+'s check|see) (“[^”]*”)")


def judged_on_submission(result) -> bool:
    return result.status is Status.DEFERRED and bool(JUDGED_ON_SUBMISSION.match(result.message))


def assert_judged_alike(name: str, live, kit) -> None:
    """Parity where the kit cannot judge: a check that the kit leaves to the graded submission because it is judged on
    the student's own functions of earlier problems is, live, judged on them: it passed with the error carried
    forward or failed judged on them (or with nothing to carry), and both name the same check of the earlier
    problem."""
    pointed = set(CHECK_NAMED.findall(kit.message))
    assert pointed, (name, kit.check_id, kit.message)
    text = f"{live.message}\n{live.hint}"
    if live.status is Status.PASSED:
        assert live.hint.startswith("Judged on your own") or "\nJudged on your own" in live.hint, (name, live.hint)
    else:
        assert live.status is Status.FAILED and ("judged on your own" in live.message
                                                 or "nothing is carried forward" in live.message), (name, text)
    assert pointed & set(CHECK_NAMED.findall(text)), (name, kit.check_id, kit.message, text)


#: how the kit says that a check compared with values its key holds at the sheet's digits only
AT_SHEET_DIGITS = ("at the sheet's digits in the student kit", "Matches the sheet's digits")


def at_sheet_digits(result) -> bool:
    return any(mark in result.message or mark in result.hint for mark in AT_SHEET_DIGITS)


def assert_alike_at_sheet_digits(name: str, live, kit) -> bool:
    """Parity where the kit compares with the sheet's digits (its key holds the fixed cases at the sheet's precision
    only): the kit never fails what the full precision passes; where the live grading fails, the kit fails too, naming
    the live diagnosis or none (or the check's own name where live tells a rival beside it: ``rival``), or passes saying
    that it matched the sheet's digits (a difference below them, such as the sheet's printed numbers typed in, shows at
    full precision only).  False when ``kit`` did not compare at the sheet's digits."""
    if not at_sheet_digits(kit):
        return False
    if live.status is Status.PASSED:
        assert kit.status is Status.PASSED, (name, kit.check_id, kit.message[:400])
    elif kit.status is not Status.PASSED:
        from grader.diagnosis import effect

        beside = kit.status is live.status and effect(kit.diagnosis) \
            and live.diagnosis.startswith(f"{kit.diagnosis} or ")  # live tells a rival beside the check's name
        assert beside or (kit.status, kit.diagnosis) in ((live.status, live.diagnosis), (live.status, "")), (
            name, kit.check_id, (live.status.value, live.diagnosis), (kit.status.value, kit.diagnosis))
    return True


def assert_alike_on_formulas(name: str, live, kit) -> bool:
    """Parity where the live grading names a slip inside a formula (``grader.diagnosis.mutants``: its hint names the
    student's function in backquotes): the kit holds no reference code to mutate, so it fails alike and names the same
    cause or none (saying, where it can tell, that the graded submission may say more: the tier's own tests hold that);
    where the check names an effect its value shows (``grader.diagnosis.effect``: a sign, a term not there) and the live
    grading tells a slip inside a formula beside it (``grader.diagnosis.rival``), the kit names the check's alone.
    False when the live diagnosis is not of that tier."""
    from grader.diagnosis import effect
    from grader.diagnosis.mutants import NAMES_A_FUNCTION

    if live.status is not Status.FAILED or not live.diagnosis or not NAMES_A_FUNCTION.search(live.hint):
        return False
    assert kit.status is live.status, (name, kit.check_id, kit.message[:400])
    beside = effect(kit.diagnosis) and live.diagnosis.startswith(f"{kit.diagnosis} or ")
    assert kit.diagnosis in (live.diagnosis, "") or beside, (name, kit.check_id, live.diagnosis, kit.diagnosis)
    return True


def assert_alike_left_to_live(name: str, live, kit) -> bool:
    """Parity where the kit says that the graded submission may say more (``grader.diagnosis.mutants.KIT_NOTE``):
    the live grading also hears the tier of formulas, which the kit cannot (it holds no reference code), and may
    tell a slip inside a formula beside the cause the kit's own tiers found; so the kit fails alike and names the
    same cause or none.  False when the kit did not say so."""
    from grader.diagnosis.mutants import KIT_NOTE

    if kit.status is not Status.FAILED or KIT_NOTE not in kit.hint:
        return False
    assert kit.status is live.status, (name, kit.check_id, live.status.value, kit.message[:400])
    assert kit.diagnosis in (live.diagnosis, ""), (name, kit.check_id, live.diagnosis, kit.diagnosis)
    return True


def assert_alike_beside_symptom(name: str, live, kit) -> bool:
    """Parity where the check names a symptom (``grader.diagnosis.SYMPTOMS``: a matrix that is not orthonormal, a
    body in the wrong orientation) and the live grading tells the cause beside it, found by comparing the
    student's call with the reference's (``grader.diagnosis.judge``), which the kit's key may not hold: the kit
    fails alike with the same message (its first line: the symptom) and tells the symptom alone (the same cause or none).  False when the kit
    named no symptom alone."""
    from grader.diagnosis import symptom

    if kit.status is not Status.FAILED or not symptom(kit.diagnosis) or live.diagnosis == kit.diagnosis:
        return False
    assert live.status is kit.status, (name, kit.check_id, live.status.value, kit.message[:400])
    assert live.message.partition("\n")[0] == kit.message.partition("\n")[0], (name, kit.check_id,
                                                                                live.message[:400], kit.message[:400])
    assert not symptom(live.diagnosis), (name, kit.check_id, live.diagnosis, kit.diagnosis)
    return True


def assert_same_verdicts(name: str, live, kit, secret: set[str]) -> None:
    """The kit gives every public check of ``live`` the same status and diagnosis (at the sheet's digits: as
    ``assert_alike_at_sheet_digits`` says), and defers exactly the ones named in ``secret`` (secret, hidden,
    withheld) and the ones it cannot judge on the student's own functions of earlier problems
    (``assert_judged_alike``)."""
    judged = {r.check_id: r for r in kit.results if judged_on_submission(r) and r.check_id not in secret}
    deferred = {r.check_id for r in kit.results if r.status is Status.DEFERRED} - set(judged)
    assert deferred == {r.check_id for r in live.results if r.check_id in secret}, name
    mine = {r.check_id: r for r in live.results}
    for check_id, result in judged.items():
        assert_judged_alike(name, mine[check_id], result)
    different = []
    theirs = {r.check_id: r for r in kit.results}
    for check_id, verdict in public_verdicts(kit).items():
        if (name, check_id) in KNOWN_DIVERGENT or check_id in judged:
            continue
        if assert_alike_beside_symptom(name, mine[check_id], theirs[check_id]):
            continue
        if assert_alike_at_sheet_digits(name, mine[check_id], theirs[check_id]):
            continue
        if assert_alike_on_formulas(name, mine[check_id], theirs[check_id]):
            continue
        if assert_alike_left_to_live(name, mine[check_id], theirs[check_id]):
            continue
        expected = (mine[check_id].status.value, mine[check_id].diagnosis)
        if verdict != expected:
            kit_message = next(r.message for r in kit.results if r.check_id == check_id)
            different.append(f"{check_id}: live {expected}, kit {verdict}\n  live: {mine[check_id].message[:400]}"
                             f"\n  kit: {kit_message[:400]}")
    assert not different, f"{name}: the kit's verdicts differ from the live reference's:\n" + "\n".join(different)


def warm_slot(problems):
    """A batch slot's warm process with the modules of ``problems`` imported, as ``grade batch`` starts one: a
    module fixture's body (``yield from warm_slot(...)``)."""
    from grader.sandbox import Limits, sandbox_mode
    from grader.sandbox.zygote import Zygote, warm_modules

    with Zygote(Limits(), sandbox_mode(), warm_modules(sorted(problems))) as zygote:
        zygote.start()
        yield zygote


def assert_told(mistake, target):
    """The check's result ``target`` names the mistake's diagnosis and has its message in the hint."""
    assert target.diagnosis == mistake.diagnosis, (target.diagnosis, target.hint)
    assert mistake.message in target.hint, target.hint


def assert_named_failure(mistake, report):
    """The result of ``mistake.check`` in ``report``: failed, with the mistake's diagnosis and its message in the
    hint, and no other check failed than those the mistake names (``also``)."""
    target = {r.check_id: r for r in report.results}[mistake.check]
    assert target.status is Status.FAILED, target.message
    assert_told(mistake, target)
    unexpected = [r.check_id for r in report.results if r.status not in (Status.PASSED, Status.SKIPPED)
                  and r.check_id not in (mistake.check, *mistake.also)]
    assert not unexpected, f"checks failed that the mistake should not touch: {unexpected}"
    return target


def graded_alike(mistake, dest, kit_oracle, deferred_ids, zygote):
    """``mistake`` planted in a copy of the reference at ``dest`` and graded as ``grade batch`` grades, live and from
    the kit's answer key, which gives the same verdicts (and the same cause or none).  The submission and the two
    reports."""
    from .submissions import build_planted

    submission = build_planted(mistake, dest)
    live, kit = grade_live_and_kit(mistake.problem, submission, kit_oracle, zygote=zygote)
    assert_same_verdicts(mistake.name, live, kit, deferred_ids)
    return submission, live, kit


def failed_alike(mistake, dest, kit_oracle, deferred_ids, zygote):
    """The live result of ``mistake.check`` (``graded_alike``), which fails."""
    _, live, _ = graded_alike(mistake, dest, kit_oracle, deferred_ids, zygote)
    target = {r.check_id: r for r in live.results}[mistake.check]
    assert target.status is Status.FAILED, target.message
    return target


def assert_told_alike(mistake, dest, kit_oracle, deferred_ids, zygote):
    """``graded_alike``, and live ``mistake.check`` fails with the mistake's diagnosis and message
    (``assert_named_failure``).  The submission and the two reports."""
    submission, live, kit = graded_alike(mistake, dest, kit_oracle, deferred_ids, zygote)
    assert_named_failure(mistake, live)
    return submission, live, kit


def engine_mistakes(path) -> tuple[list, dict[str, tuple]]:
    """The planted mistakes of one of the diagnosis engine's tables (``tests/engine/*.toml``) and the families each
    is told with, by name: its ``family``, or a list of them where it is told "could be" either (a state of another
    time that is also an event's state read otherwise)."""
    import tomllib

    from tests.submissions import Planted

    entries = tomllib.loads(Path(path).read_text()).get("mistake", [])
    mistakes = [Planted(name=e["name"], problem=e["problem"], file=e["file"], old=e["old"], new=e["new"],
                        check=e["check"], diagnosis=e["diagnosis"], message=e["message"],
                        also=tuple(e.get("also", ()))) for e in entries]
    return mistakes, {e["name"]: tuple(e["family"]) if isinstance(e["family"], list) else (e["family"],)
                      for e in entries}


def graded_table(path) -> tuple:
    """What a module that grades one of the engine's tables needs: its mistakes and their families
    (``engine_mistakes``), a fixture ``slot`` (a warm process of the mistakes' problems, for the module) and the test
    that each mistake's diagnosis is of its family.  A module binds the fixture as ``slot`` and the test under a
    name that starts with ``test_``."""
    from checks._diagnoses import families_of

    mistakes, families = engine_mistakes(path)

    @pytest.fixture(scope="module")
    def slot():
        yield from warm_slot(sorted({mistake.problem for mistake in mistakes}))

    def test_the_graded_mistakes_are_of_their_families():
        for mistake in mistakes:
            assert families_of(mistake.diagnosis) == families[mistake.name], mistake.name

    return mistakes, families, slot, test_the_graded_mistakes_are_of_their_families


def assert_named_live_and_alike(mistake, tmp_path, kit_oracle, deferred_ids, zygote, monkeypatch) -> tuple:
    """``mistake`` planted and graded live and with the kit's answer key: live, its check fails with its diagnosis
    and a hint containing its message (``assert_named_failure``); the kit fails it alike and names the same cause or
    none; every other check agrees (``assert_same_verdicts``); with the engine off no cause of its families is named
    (``assert_no_catalogue_names_it``).  ``(live result, kit result)`` of the check, for a test's own asserts."""
    from tests.submissions import build_planted

    submission = build_planted(mistake, tmp_path / "pkg")
    live, kit = grade_live_and_kit(mistake.problem, submission, kit_oracle, zygote=zygote)
    target = assert_named_failure(mistake, live)
    theirs = {r.check_id: r for r in kit.results}[mistake.check]
    assert theirs.status is Status.FAILED and theirs.diagnosis in ("", mistake.diagnosis), theirs.diagnosis
    assert_same_verdicts(mistake.name, live, kit, deferred_ids)
    assert_no_catalogue_names_it(mistake, submission, zygote, monkeypatch)
    return target, theirs


def assert_no_catalogue_names_it(mistake, submission, zygote, monkeypatch) -> None:
    """With the diagnosis engine off, ``mistake.check`` still fails and names no cause of the mistake's families:
    only the engine names it."""
    import grader.diagnosis as engine
    from checks._diagnoses import families_of
    from grader import grade_problem
    from grader.workers import Forked

    monkeypatch.setattr(engine, "ENABLED", False)
    off = grade_problem(mistake.problem, submission, seed=SEED, workers=Forked(zygote))
    unexplained = {r.check_id: r for r in off.results}[mistake.check]
    assert unexplained.status is Status.FAILED, unexplained.message
    assert not set(families_of(unexplained.diagnosis)) & set(families_of(mistake.diagnosis)), unexplained.diagnosis


if __name__ == "__main__":  # python -m tests.kit_support PATH: record the key at PATH, unless a process did
    import sys

    shared_key(Path(sys.argv[1]))
