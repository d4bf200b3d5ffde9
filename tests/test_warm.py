"""Workers forked from a batch slot's warm process (``grader.sandbox.zygote``): one student cannot see or influence
the next one graded by the same slot, and every student is graded as a fresh worker would grade them.

The hostile suite runs on the warm path too (``tests/test_hostile.py``, modes ``*-warm``).
"""

import json
import os
import random
import shutil
import signal

import pytest

from grader.results import Status
from grader.runner import grade_submission
from grader.workers import Forked
from grader.problems import problems as all_problems
from grader.sandbox import Limits, plain_mode, refusal, sandbox_mode
from grader.sandbox.zygote import Zygote, warm_modules

from .processes import cmdline
from .submissions import ROOT, copy_reference

LIMITS = Limits(call_timeout=5.0, import_timeout=10.0)
WARM = ROOT / "tests" / "warm"


def slot_mode(kind: str):
    if kind == "bwrap":
        if not sandbox_mode().isolated:
            pytest.skip("bubblewrap is not available here")
        return sandbox_mode()
    if refusal() is not None:
        pytest.skip("as root, plain processes need a Python runtime that an unprivileged uid can read (the refusal "
                    "is tested by tests/test_hostile.py)")
    return plain_mode("bubblewrap not used (test)")


@pytest.fixture(params=["bwrap", "process"])
def zygote(request):
    with Zygote(LIMITS, slot_mode(request.param), warm_modules([6])) as slot:
        slot.start()
        yield slot


def student(name: str, dest, nonce: str):
    """A reference copy with the package files of ``tests/warm/NAME`` laid over it and a marker file of its own."""
    copy_reference(dest)
    for path in (WARM / name).iterdir():
        if path.is_file():
            shutil.copy2(path, dest / path.name)
    (dest / "target.txt").write_text(json.dumps({"nonce": nonce}))
    (dest / f"{name}.txt").write_text(name)
    return dest


def printed(output: str, tag: str) -> dict:
    """The JSON line a submission printed (the first: a leaver that killed its zygote is imported again)."""
    line = next((line for line in output.splitlines() if line.startswith(tag + " ")), None)
    assert line is not None, f"the submission printed no {tag} line; its output: {output[-2000:]!r}"
    return json.loads(line[len(tag) + 1:])


def nonce() -> str:
    return f"{random.randrange(10**6, 10**7)}.{random.randrange(10**5, 10**6)}"  # a `sleep` duration


def test_a_student_cannot_see_or_influence_the_next_one_in_the_same_slot(zygote, tmp_path):
    marker = nonce()
    leaver = student("leaver", tmp_path / "leaver", marker)
    spy = student("spy", tmp_path / "spy", marker)
    reports = [grade_submission(path, [6], seed=3, workers=Forked(zygote, LIMITS))[0] for path in (leaver, spy, spy)]
    assert zygote.starts == 1  # the same warm process forked all three
    for report in reports[1:]:  # the next students are graded as fresh workers grade them
        assert report.score == report.auto_max_score, [(r.check_id, r.message) for r in report.results
                                                       if r.status is not Status.PASSED]
    assert_isolated(*[r.stdout for r in reports], isolated=zygote.mode.isolated, root=os.geteuid() == 0)
    assert_nothing_left(marker)


def assert_nothing_left(marker: str) -> None:
    """No file of the leaver in the machine's shared folders, no process of it anywhere."""
    assert not [p for folder in ("/tmp", "/var/tmp", "/dev/shm") if os.path.isdir(folder)
                for p in os.listdir(folder) if marker in p]
    assert not [pid for pid in os.listdir("/proc") if pid.isdigit() and marker.encode() in cmdline(pid)]



def assert_isolated(leaver_output: str, spy_output: str, again_output: str, isolated: bool, root: bool) -> None:
    """What the spy saw after the leaver, in the same slot: nothing of it (also run by tests/test_install.py on the
    installed wheel, as root and as an unprivileged user)."""
    done = printed(leaver_output, "LEAVER")
    seen, again = printed(spy_output, "SPY"), printed(again_output, "SPY")
    # what the first student managed to leave behind (what its sandbox allowed it)
    assert done["threads"] >= 2 and done["daemon"] is True and done["shm"] is True
    # as root, the warm process is not the student's to signal: the kill fails, and the leaver lives to say so
    # (without root, the kill succeeds, and the warm process is started again for the next student)
    if root:
        assert printed(leaver_output, "KILL")["killed_parent"] != True  # noqa: E712
    assert seen["math_patched"] is False and seen["numpy_patched"] is False and seen["leftover_module"] is False
    assert seen["environment"] is None
    assert seen["threads"] == 1 and seen["tasks"] == 1
    assert seen["rng_is_seeded_12345"] is False and seen["draw"] != again["draw"]  # reseeded in every fork
    assert seen["daemons"] == []
    if isolated or root:  # an IPC namespace of its own (a plain process of the grader's own uid has none, fresh or
        assert seen["shm"] is False  # forked: a student's own machine, where the report says it is not sandboxed)
    assert all(found in ([], "PermissionError") for found in seen["files"].values()), seen["files"]
    assert "spy.txt" in seen["package"] and "leaver.txt" not in seen["package"]  # its own files only
    assert len(seen["fds"]) <= 6, seen["fds"]  # stdin, stdout, stderr, its two pipes (and the listing's own)
    if isolated:
        assert seen["slot"] in ([], "PermissionError")  # the slot's staging folder is covered: empty
    if root:  # a uid of each student's own, never root
        assert len({done["uid"], seen["uid"], again["uid"]}) == 3 and 0 not in (done["uid"], seen["uid"])


def test_a_killed_worker_is_forked_again_and_the_student_graded_to_the_end(zygote, tmp_path):
    """A crash in one call costs that call only: the next call forks a fresh worker from the same zygote."""
    submission = copy_reference(tmp_path / "pkg")
    rotations = submission / "rotations.py"
    text = rotations.read_text()
    old = "def cardan(alpha, beta, gamma):\n"
    assert text.count(old) == 1
    rotations.write_text(text.replace(old, old + "    import os\n\n    os._exit(3)\n"))
    (report,) = grade_submission(submission, [6], seed=3, workers=Forked(zygote, LIMITS))
    assert zygote.starts == 1
    by_id = {r.check_id: r for r in report.results}
    assert by_id["p06.cardan_rotation"].status is Status.ERROR
    assert "exit code 3" in by_id["p06.cardan_rotation"].message
    assert {by_id[c].status for c in ("p06.elementary_values", "p06.frames", "p06.vectors")} == {Status.PASSED}


def test_one_submission_is_graded_by_one_forked_worker(zygote, tmp_path):
    """Every problem of a submission in the same worker, as a fresh worker grades them: one fork, not one per
    problem."""
    submission = copy_reference(tmp_path / "pkg")
    before = zygote.forks
    reports = grade_submission(submission, [6, 8, 9], seed=3, workers=Forked(zygote, LIMITS))
    assert zygote.forks == before + 1
    assert [r.score for r in reports] == [r.auto_max_score for r in reports]


class _Interrupted(BaseException):
    """What a signal handler raises in the grader (as a batch worker's stop does) while the warm process starts."""


def test_a_warm_process_interrupted_while_it_starts_is_ended_at_once():
    """A batch stopped early stops its workers while their warm process may still be importing (about a second for
    the whole course, longer on a loaded machine).  That process is ended with the interruption instead of being
    left to finish its imports and notice, which could outlast the worker's grace and leave its folder behind."""
    mode = slot_mode("bwrap")

    def interrupt(signum, frame):
        if not zygote.alive:  # not started yet: the interruption must come while it imports
            signal.setitimer(signal.ITIMER_REAL, 0.01)
            return
        raise _Interrupted

    previous = signal.signal(signal.SIGALRM, interrupt)
    zygote = Zygote(LIMITS, mode, warm_modules([p.number for p in all_problems()]))
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.1)
        with pytest.raises(_Interrupted):
            zygote.start()
        assert not zygote.alive
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        zygote.close()
    assert not zygote.staging.exists()
