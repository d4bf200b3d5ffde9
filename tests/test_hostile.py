"""Hostile submissions: each yields a clear student-facing error or a 0 for the attacked checks, within its
limits, and the grader itself carries on; nothing the submission started or wrote outlives the grading.

Every attack runs four ways: a fresh worker and a worker forked from a batch slot's warm process (``-warm``: one
zygote per mode for the whole module, so that the attacks also follow one another in the same slot), each in
bubblewrap and as a plain process.  The attacks on other processes, files, pipes and time limits run once more
in bubblewrap beside a second worker that grades another problem of the same submission (``BESIDE``).

Every outcome is asserted, never a duration: the bounds on time are generous (a loaded machine passes), and the
speed of the grader is measured by the benchmarks.  In the plain-process mode, a grader running as root whose
Python runtime an unprivileged uid cannot read (e.g. under /root) must refuse: there the tests assert the refusal.
"""

import json
import os
import random
import re
import secrets
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import pytest

from grader import grade_problem, grade_submission
from grader.workers import Forked, Fresh
from grader.errors import SandboxError
from grader.results import Status
from grader.sandbox import BWRAP_FIX, Limits, SandboxMode, plain_mode, portable_mode, refusal, sandbox_mode, users
from grader.sandbox.zygote import Zygote, warm_modules

from . import keyrings
from .processes import descendants, new_processes, processes_with
from .submissions import ROOT, build_hostile, copy_reference, hostile_expectation, hostile_names

LIMITS = Limits(call_timeout=3.0, import_timeout=5.0, memory_mb=1024)
MODES = [pytest.param(kind, id=kind) for kind in ("bwrap", "process", "bwrap-warm", "process-warm")]
#: seconds that the processes of a finished grading get to disappear (they are killed: this is only the kernel's)
GONE_WITHIN = 20.0
#: how a report says that Landlock restricted the files of a plain process
LANDLOCK_FILES = "Landlock let it read only"
#: how a report says that a plain process had a PID namespace of its own
OWN_PID_NAMESPACE = "its own PID and mount namespaces"


def hostile_mode(kind: str) -> SandboxMode:
    if kind == "portable":
        return portable_mode()
    if kind.startswith("bwrap"):
        if not sandbox_mode().isolated:
            pytest.skip("bubblewrap is not available here")
        return SandboxMode("bwrap", "bubblewrap: no network, no access to the reference or other submissions")
    return plain_mode("bubblewrap not used (test)")


def assert_refused(grade) -> None:
    """As root, without bubblewrap, with a runtime that no other uid can read: a refusal that names the fix."""
    with pytest.raises(SandboxError) as refused:
        grade()
    text = str(refused.value)
    assert "never runs as root" in text and BWRAP_FIX in text and "cannot" in text, text


# ------------------------------------------------------------------------------------------ processes







def wait_until(condition, seconds: float = GONE_WITHIN) -> bool:
    deadline = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


# ------------------------------------------------------------------------------------------ the target


class Target:
    """What a ``target`` submission attacks: a nonce to name its leftovers, a port this test listens on, a Unix
    socket of this machine that every user may connect to and an abstract one, and a reference cache opened to
    every user (a careless installation), with one planted entry."""

    def __init__(self, submission: Path, monkeypatch):
        self.nonce = f"{random.randrange(10**6, 10**7)}.{random.randrange(10**5, 10**6)}"  # a `sleep` duration
        self.base = Path(tempfile.mkdtemp(prefix="grader-test-cache-"))
        os.chmod(self.base, 0o755)
        self.cache = self.base / "cache"
        self.entry = self.cache / "0123456789abcdef" / "entry.json"
        self.entry.parent.mkdir(parents=True)
        self.entry.write_text('{"value": 1.0}')
        for path, mode in ((self.cache, 0o777), (self.entry.parent, 0o777), (self.entry, 0o666)):
            os.chmod(path, mode)
        monkeypatch.setenv("GRADER_CACHE", str(self.cache))
        self.server = socket.socket()
        self.server.bind(("127.0.0.1", 0))
        self.server.listen(8)
        self.server.setblocking(False)
        self.unix = socket.socket(socket.AF_UNIX)
        self.unix.bind(str(self.base / "host.sock"))
        os.chmod(self.base / "host.sock", 0o777)
        self.abstract_name = f"mbd-test-{secrets.token_hex(8)}"
        self.abstract = socket.socket(socket.AF_UNIX)
        self.abstract.bind("\0" + self.abstract_name)
        for server in (self.unix, self.abstract):
            server.listen(8)
            server.setblocking(False)
        (submission / "target.txt").write_text(json.dumps(
            {"nonce": self.nonce, "port": self.server.getsockname()[1], "cache": str(self.cache),
             "unix": str(self.base / "host.sock"), "abstract": self.abstract_name}))

    @staticmethod
    def _accepted(server) -> bool:
        try:
            server.accept()[0].close()
        except BlockingIOError:
            return False
        return True

    def connected(self) -> bool:
        return self._accepted(self.server)

    def unix_connected(self) -> bool:
        return self._accepted(self.unix) or self._accepted(self.abstract)

    def leftover_files(self) -> list[str]:
        return [str(p) for folder in ("/tmp", "/var/tmp", "/dev/shm") if os.path.isdir(folder)
                for p in Path(folder).glob(f"*{self.nonce}*")]

    def verify(self, note: str) -> None:
        """Nothing left, the cache untouched, the network as the report says, no Unix socket of the host reached."""
        assert wait_until(lambda: not processes_with(self.nonce)), processes_with(self.nonce)
        assert not self.leftover_files(), self.leftover_files()
        files = sorted(p for p in self.cache.rglob("*"))
        assert files == [self.entry.parent, self.entry], files
        assert self.entry.read_text() == '{"value": 1.0}'
        claims_isolation = "no network" in note or "network isolated" in note
        assert not (claims_isolation and self.connected()), note
        assert not self.unix_connected(), note

    def close(self) -> None:
        for server in (self.server, self.unix, self.abstract):
            server.close()
        for pid in processes_with(self.nonce):  # only after a failed test: never leave them running
            os.kill(pid, 9)
        for path in self.leftover_files():
            shutil.rmtree(path, ignore_errors=True) if os.path.isdir(path) else os.unlink(path)
        shutil.rmtree(self.base, ignore_errors=True)


# ------------------------------------------------------------------------------------------ the tests


class GraderKeyring:
    """The session keyring of this test process, as a login session's holds tokens: joined before any worker or
    warm process starts (they inherit it), with a secret in it."""

    def __init__(self):
        self.serial = keyrings.join_session(f"mbd-test-{secrets.token_hex(4)}")
        self.secret = secrets.token_hex(16)
        self.key = keyrings.add_key("mbd-grader-secret", self.secret.encode())

    def verify(self, stdout: str) -> None:
        """The secret did not reach the student, and the keyring holds nothing but it."""
        assert self.secret not in stdout, stdout
        assert keyrings.keys_in(keyrings.SESSION) == [self.key]

    def close(self) -> None:
        keyrings.invalidate(self.key)


@pytest.fixture(scope="module")
def grader_keyring():
    keyring = GraderKeyring()
    yield keyring
    keyring.close()


class SpyTarget:
    """A process of the grading machine that a ``spy_process`` submission looks for (named in ``spy.txt``)."""

    def __init__(self, submission: Path):
        self.marker = f"{random.randrange(10**6, 10**7)}.{random.randrange(10**5, 10**6)}"  # a `sleep` duration
        self.process = subprocess.Popen(["sleep", self.marker])
        (submission / "spy.txt").write_text(self.marker)

    def close(self) -> None:
        self.process.kill()
        self.process.wait()


@pytest.fixture(scope="module")
def zygotes(grader_keyring):
    """One warm process per mode, started when first needed and shared by every test of the module (after the test
    process joined the session keyring that they inherit)."""
    started: dict[str, Zygote] = {}

    def get(kind: str) -> Zygote:
        if kind not in started:
            zygote = Zygote(LIMITS, hostile_mode(kind), warm_modules(sorted(HOSTILE_PROBLEMS)))
            try:
                zygote.start()
            except BaseException:
                zygote.close()
                raise
            started[kind] = zygote
        return started[kind]

    yield get
    for zygote in started.values():
        zygote.close()


HOSTILE_PROBLEMS = {hostile_expectation(name).get("problem", 6) for name in hostile_names()}


@pytest.mark.parametrize("kind", MODES)
@pytest.mark.parametrize("name", hostile_names())
def test_hostile_submission(name, kind, tmp_path, monkeypatch, zygotes, grader_keyring):
    _grade_hostile(name, kind, tmp_path, monkeypatch, zygotes, keyring=grader_keyring)


@pytest.mark.parametrize("kind", MODES)
def test_a_key_that_one_student_leaves_never_reaches_the_next_under_the_same_uid(kind, tmp_path, monkeypatch,
                                                                                  zygotes):
    """Two students graded one after the other under the same uid, as a second ``grade`` run or a batch slot
    started again claims the first free uid anew: what the first leaves in the user keyring of that uid (which
    outlives its processes) never reaches the second, because neither may use a keyring."""
    mode = hostile_mode(kind)
    warm = kind.endswith("-warm")
    if kind.startswith("process") and refusal() is not None:
        assert_refused(lambda: grade_problem(6, build_hostile("keyring_user", tmp_path / "first"), seed=7,
                                             workers=Forked(zygotes(kind), LIMITS) if warm else Fresh(LIMITS, mode)))
        return
    offset = random.randrange(users.UID_COUNT // 2, users.UID_COUNT - 100)  # away from other test processes' uids
    outputs = []
    for name in ("first", "second"):
        monkeypatch.setattr(users, "_next_offset", offset)
        submission = build_hostile("keyring_user", tmp_path / name)
        report = grade_problem(6, submission, seed=7,
                               workers=Forked(zygotes(kind), LIMITS) if warm else Fresh(LIMITS, mode))
        assert report.score == report.auto_max_score, report.results
        outputs.append(report.stdout)
    uids = [next(line for line in out.splitlines() if line.startswith("uid: ")) for out in outputs]
    assert uids[0] == uids[1], uids  # the same uid: the case of a second run
    assert "found a note" not in outputs[1], outputs[1]
    assert "left a note" not in outputs[0], outputs[0]


#: attacks graded once more in bubblewrap with a second worker grading another problem beside them (``grade
#: problem-6 problem-8`` on two cores): the ones that reach for other processes, files, pipes and time limits
BESIDE = ("cache_poison", "closed_pipe_loop", "fork_bomb", "kill_everything", "leftovers", "partial_reply",
          "steal_reference_files", "wrong_id_flood")


@pytest.mark.parametrize("name", BESIDE)
def test_hostile_submission_beside_another_worker(name, tmp_path, monkeypatch, zygotes):
    _grade_hostile(name, "bwrap", tmp_path, monkeypatch, zygotes, beside=True)


#: attacks on the grading itself (hangs, crashes, exits, floods, forged or broken replies): the portable mode of a
#: student's own machine protects the grading from these, and from nothing else (no confinement: the student's code
#: runs as the student)
PORTABLE_ATTACKS = ("closed_pipe_loop", "fake_json", "forged_deep_reply", "import_exception", "infinite_loop_call",
                    "infinite_loop_import", "memory_bomb", "os_exit", "partial_reply", "print_flood", "sys_exit",
                    "syntax_error", "wrong_id_flood")


@pytest.mark.parametrize("name", PORTABLE_ATTACKS)
def test_hostile_submission_portable(name, tmp_path, monkeypatch, zygotes):
    _grade_hostile(name, "portable", tmp_path, monkeypatch, zygotes)


def _grade_hostile(name, kind, tmp_path, monkeypatch, zygotes, beside=False, keyring=None):
    """Grade the attack's problem (``beside``: with another problem, two workers side by side) and assert what
    its ``expect.toml`` says."""
    expect = hostile_expectation(name)
    mode = hostile_mode(kind)
    submission = build_hostile(name, tmp_path / "pkg")
    limits = replace(LIMITS, **expect.get("limits", {}))
    problem = expect.get("problem", 6)
    warm = kind.endswith("-warm")
    if kind.startswith("process") and "load_error" not in expect:  # refused before any child starts
        if refusal() is not None:
            assert_refused(lambda: grade_problem(
                problem, submission, seed=7, workers=Forked(zygotes(kind), limits) if warm else Fresh(limits, mode)))
            return
        if expect.get("other_uid") and os.geteuid() != 0:
            pytest.skip("without bubblewrap and without root, the child runs as the user who runs the tests")
    warm = warm and "load_error" not in expect  # a submission refused by the loader starts no child at all
    zygote = zygotes(kind) if warm else None
    target = Target(submission, monkeypatch) if expect.get("target") else None
    spy = SpyTarget(submission) if expect.get("spy_process") else None
    before = set(descendants(os.getpid()))
    try:
        start = time.monotonic()
        if beside:
            partner = 8 if problem != 8 else 6
            report, other = grade_submission(submission, [problem, partner], seed=7,
                                             workers=Fresh(limits, mode, count=2))
            alone = grade_problem(partner, submission, seed=7, workers=Fresh(limits, mode))
            # the other worker's problem is graded as it is alone
            assert [(r.check_id, r.status, r.score) for r in other.results] == [
                (r.check_id, r.status, r.score) for r in alone.results]
        else:
            report = grade_problem(problem, submission, seed=7,
                                   workers=Forked(zygote, limits) if zygote is not None else Fresh(limits, mode))
        if warm:
            assert zygote.starts == 1, "the slot's warm process was killed"
        elapsed = time.monotonic() - start
        if expect.get("isolated_only") and not report.isolated and LANDLOCK_FILES not in report.sandbox:
            pytest.skip("only a file-system sandbox (bubblewrap, or Landlock where the kernel has it) hides the "
                        "reference's files; the report says that there was none")
        if expect.get("own_pid_namespace") and not report.isolated:
            if os.geteuid() != 0:
                pytest.skip("only a PID namespace of the child's own (bubblewrap, or a plain process as root) hides "
                            "the machine's processes; without root a plain process has none, and its report says so")
            assert OWN_PID_NAMESPACE in report.sandbox, report.sandbox
        by_id = {r.check_id: r for r in report.results}
        statuses = expect["status"] if isinstance(expect["status"], list) else [expect["status"]]
        targets = expect.get("checks") or [r.check_id for r in report.results if r.status is not Status.SKIPPED]
        for check_id in targets:
            result = by_id[check_id]
            assert result.status.value in statuses, (check_id, result.status, result.message)
            if result.status is not Status.PASSED:
                assert result.score == 0
            if "message" in expect:
                assert expect["message"] in result.message, result.message
        assert not any(r.status is Status.GRADER_ERROR for r in report.results), report.results
        if "load_error" in expect:  # said once, for the problem: not under every check
            assert expect["load_error"] in report.load_error, report.load_error
            assert not any(r.message for r in report.results), report.results
        else:
            assert not report.load_error, report.load_error
        if "note" in expect:
            assert any(expect["note"] in note for note in report.notes), report.notes
        if "max_score" in expect:
            assert report.score <= expect["max_score"]
        if "stdout" in expect:
            assert expect["stdout"] in report.stdout, report.stdout
        for text in expect.get("stdout_not", ()):
            assert text not in report.stdout, report.stdout
        # bounded: every call stops at its limit (the bound is generous: a loaded machine passes)
        bound = limits.setup_timeout + limits.import_timeout + len(report.results) * (limits.call_timeout + 5)
        assert elapsed < 2 * bound, elapsed
        # contained: nothing the grading started is left
        assert wait_until(lambda: not new_processes(before)), new_processes(before)
        if target is not None:
            target.verify(report.sandbox)
        if expect.get("keyring"):
            keyring.verify(report.stdout)
    finally:
        if target is not None:
            target.close()
        if spy is not None:
            spy.close()


def test_fallback_is_reported(tmp_path):
    """Without bubblewrap: full marks under a uid of the child's own, or a refusal that says why; the report
    says plainly how the submission ran."""
    submission = copy_reference(tmp_path / "pkg")
    mode = plain_mode("bubblewrap is not available")
    if refusal() is not None:
        assert_refused(lambda: grade_problem(6, submission, seed=1, workers=Fresh(mode=mode)))
        return
    report = grade_problem(6, submission, seed=1, workers=Fresh(mode=mode))
    assert report.score == report.auto_max_score
    assert not report.isolated and "bubblewrap" in report.sandbox
    if os.geteuid() == 0:
        assert "unprivileged uid" in report.sandbox and "network" in report.sandbox
    else:
        assert "not sandboxed" in report.sandbox and "your own user" in report.sandbox


# ------------------------------------------------------------------------------------------ the terminal

#: characters a terminal acts on (or that reorder a line): C0 but tab and newline, DEL, C1, the bidirectional
#: controls; none may reach the terminal raw
ACTING = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]")


def raw_controls(output: bytes) -> list[str]:
    """The characters of ``output`` (UTF-8) that a terminal would act on."""
    return [repr(m.group()) for m in ACTING.finditer(output.decode("utf-8", "surrogateescape"))]


def terminal_submission(folder: Path) -> Path:
    """The ``terminal_escapes`` attack, plus a notebook whose name and cell text hold control sequences."""
    from .notebooks import write_notebook

    build_hostile("terminal_escapes", folder)
    write_notebook(folder / "\x1b]0;title\x07\x1b[2J.ipynb", ["def helper():\n    return 1",
                                                            "x = '\x1b[31m\x9b1;1H\u202e' +"])
    return folder


def test_no_raw_control_character_of_a_submission_reaches_grades_output(tmp_path):
    """`grade problem-6` on a submission that prints 25 control characters (clear screen, a forged "10 / 10 points"
    line with cursor moves, the window's title, the clipboard), raises them and returns them in a string, and a
    notebook whose name and text hold more: every one is shown escaped, none reaches the terminal raw."""
    submission = terminal_submission(tmp_path / "pkg")
    done = subprocess.run([sys.executable, "-m", "grader.cli", "problem-6", "--submission", str(submission),
                           "--seed", "3"], cwd=ROOT, capture_output=True, timeout=600)
    output = done.stdout + done.stderr
    assert done.returncode == 1, output.decode("utf-8", "replace")
    assert raw_controls(output) == [], raw_controls(output)
    text = output.decode()
    for shown in ("\\x1b]52;c;Y3Vyb", "\\x1b[2J\\x1b[H", "\\x9b2J", "\\u202e", "\\x0d\\x1b[1A"):
        assert text.count(shown) >= 3, (shown, text)  # printed, raised, returned: shown, escaped
    assert "notebook \\x1b]0;title\\x07\\x1b[2J.ipynb" in text, text
    forged = [line for line in text.splitlines() if line.startswith("Problem 6: Euler") and "10 / 10" in line]
    assert forged == [], forged


def test_the_terminal_report_in_colour_holds_only_the_graders_own_escape_sequences(tmp_path):
    from grader.report.text import render_terminal

    report = grade_problem(6, terminal_submission(tmp_path / "pkg"), seed=3, workers=Fresh(LIMITS))
    text = render_terminal([report], colour=True)
    sequences = re.findall("\x1b[^m]*m", text)
    assert sequences and set(sequences) <= {"\x1b[1m", "\x1b[0m", "\x1b[32m", "\x1b[31m", "\x1b[36m"}, sequences
    assert raw_controls(re.sub("\x1b\\[[0-9;]*m", "", text).encode()) == []


@pytest.mark.slow
def test_grade_demo_shows_the_terminal_attack_inert():
    done = subprocess.run([sys.executable, "-m", "grader.cli", "demo", "--problems", "6"], cwd=ROOT,
                          capture_output=True, timeout=900)
    output = done.stdout + done.stderr
    assert done.returncode == 0, output.decode("utf-8", "replace")
    assert raw_controls(output) == [], raw_controls(output)
    row = next(line for line in done.stdout.decode().splitlines() if line.startswith("hostile: terminal_escapes"))
    assert "must be numeric, got a value of type str: \\x1bc\\x1b[?10" in row, row
