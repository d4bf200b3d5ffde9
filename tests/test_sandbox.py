"""The sandbox around the student's code: deadlines the child cannot beat, what the child sees on any install,
faults of the set-up reported as the grader's, and the unprivileged uids of a grader running as root.

Outcomes are asserted with generous bounds, never durations (timing belongs to the benchmarks)."""

import json
import re
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import ModuleType

import pytest

from grader.checking import check
from grader.cli import main
from grader.errors import GraderFault, SandboxError, StudentCodeError, StudentTimeout, WorkerCrash
from grader.gradebook import GRADEBOOK_NAME
from grader.loader import materialize
from grader.results import Status
from grader.runner import grade_submission
from grader.workers import Fresh
from grader.sandbox import BWRAP_FIX, Child, Limits, SandboxMode, canary, plain_mode, protocol, refusal, sandbox_mode
from grader.sandbox import launch, users

from .submissions import ROOT, build_hostile, copy_reference
from .processes import descendants, new_processes
from .test_hostile import assert_refused, wait_until

LIMITS = Limits(call_timeout=3.0, import_timeout=10.0)
BWRAP = SandboxMode("bwrap", "bubblewrap (test)")
needs_bwrap = pytest.mark.skipif(not sandbox_mode().isolated, reason="bubblewrap is not available here")
needs_root = pytest.mark.skipif(os.geteuid() != 0, reason="children get uids of their own only when the grader "
                                                           "runs as root")


def run_cli(*args, env=None, timeout=300):
    """``python -m grader.cli ARGS`` from the project root; a hang fails the test instead of hanging it."""
    return subprocess.run([sys.executable, "-m", "grader.cli", *map(str, args)], cwd=ROOT, capture_output=True,
                          text=True, timeout=timeout, env={**os.environ, **(env or {})})


@pytest.fixture
def reference_copy(tmp_path):
    submission = materialize(copy_reference(tmp_path / "ref"))
    yield submission.path
    shutil.rmtree(submission.path.parent, ignore_errors=True)


@pytest.fixture
def tmp_venv():
    """A virtual environment under /tmp, in a folder that also holds a file the child must not see; a ``.pth``
    file adds the running interpreter's site-packages (numpy and the rest) to it."""
    import site

    base = Path(tempfile.mkdtemp(prefix="grader-test-venv-", dir="/tmp"))
    os.chmod(base, 0o755)
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(base / "venv")], check=True,
                   capture_output=True, timeout=120)
    (venv_site(base / "venv") / "dependencies.pth").write_text("\n".join(site.getsitepackages()) + "\n")
    (base / "secret.txt").write_text("next to the venv")
    yield base
    shutil.rmtree(base, ignore_errors=True)


def venv_site(venv: Path) -> Path:
    return next((venv / "lib").glob("python3*/site-packages"))


# ------------------------------------------------------------------------------------------ item 5: deadlines


def test_reader_gives_up_on_a_partial_body_at_the_deadline():
    read_fd, write_fd = os.pipe()
    try:
        os.write(write_fd, protocol.HEADER.pack(1000) + b'{"id": 2, ')
        reader = protocol.FrameReader(read_fd)
        start = time.monotonic()
        with pytest.raises(protocol.Deadline):
            reader.read(time.monotonic() + 0.5)
        assert time.monotonic() - start < 30
    finally:
        os.close(read_fd)
        os.close(write_fd)


def test_reader_refuses_an_oversized_header_before_the_body():
    read_fd, write_fd = os.pipe()
    try:
        os.write(write_fd, protocol.HEADER.pack(protocol.MAX_MESSAGE + 1))
        with pytest.raises(protocol.ProtocolError, match="exceeds the limit"):
            protocol.FrameReader(read_fd).read(time.monotonic() + 60)
    finally:
        os.close(read_fd)
        os.close(write_fd)


def test_reader_keeps_the_next_message_and_sees_the_end():
    read_fd, write_fd = os.pipe()
    os.write(write_fd, protocol.frame({"id": 1}) + protocol.frame({"id": 2}))
    os.close(write_fd)
    reader = protocol.FrameReader(read_fd)
    deadline = time.monotonic() + 60
    assert [reader.read(deadline), reader.read(deadline), reader.read(deadline)] == [{"id": 1}, {"id": 2}, None]
    os.close(read_fd)


def test_sending_to_a_child_that_does_not_read_stops_at_the_deadline():
    read_fd, write_fd = os.pipe()
    os.set_blocking(write_fd, False)
    try:
        with pytest.raises(protocol.Deadline):
            for _ in range(1000):  # far more than a pipe holds
                protocol.send_before(write_fd, {"data": "x" * 60_000}, time.monotonic() + 0.5)
    finally:
        os.close(read_fd)
        os.close(write_fd)


@pytest.mark.parametrize("name", ["wrong_id_flood", "partial_reply", "closed_pipe_loop"])
def test_grade_with_timeout_always_returns(name, tmp_path):
    """`grade problem-6 --timeout 2` returns whatever the child writes on the reply pipe (or if it closes it)."""
    if not sandbox_mode().isolated and refusal() is not None:
        result = run_cli("problem-6", "--submission", build_hostile(name, tmp_path / "pkg"), "--timeout", "2")
        assert result.returncode == 3 and "never runs as root" in result.stderr
        return
    result = run_cli("problem-6", "--submission", build_hostile(name, tmp_path / "pkg"), "--timeout", "2",
                     "--json", tmp_path / "report.json")
    assert result.returncode == 1, result.stderr
    (report,) = json.loads((tmp_path / "report.json").read_text())["reports"]
    checks = {c["check_id"]: c for c in report["results"]}
    for check_id in ("p06.frames", "p06.vectors"):
        assert checks[check_id]["status"] in ("timeout", "error"), checks[check_id]
        assert "grader error" not in checks[check_id]["message"]


# ------------------------------------------------------------------------------------------ item 6


def test_a_child_that_closes_its_pipe_and_loops_is_a_crash_and_is_killed(tmp_path):
    mode = sandbox_mode()
    if not mode.isolated and refusal() is not None:
        pytest.skip("covered by the refusal: no child runs here without bubblewrap")
    submission = materialize(build_hostile("closed_pipe_loop", tmp_path / "pkg"))
    before = set(descendants(os.getpid()))
    try:
        with Child(submission.path, Limits(call_timeout=2.0), mode) as child:
            with pytest.raises(WorkerCrash, match="closed its connection"):
                child.call("problem_06.frames")
            assert child._proc is None
            assert wait_until(lambda: not new_processes(before)), new_processes(before)
            assert child.call("problem_06.elementary", 1, 0.5).shape == (3, 3)  # a fresh worker answers
    finally:
        shutil.rmtree(submission.path.parent, ignore_errors=True)


def test_a_worker_started_again_gets_the_pipes_it_was_given(tmp_path):
    """After a time-out the next call starts a fresh worker with new pipes.  Their numbers are whatever is free
    in the grader then (another thread's worker, a file the grader opened): the worker must be told those, not
    the numbers of the first worker's pipes (it then wrote its 'ready' to a closed descriptor, a set-up fault)."""
    mode = sandbox_mode()
    if not mode.isolated and refusal() is not None:
        pytest.skip("covered by the refusal: no child runs here without bubblewrap")
    submission = materialize(build_hostile("infinite_loop_call", tmp_path / "pkg"))
    held = []
    try:
        with Child(submission.path, Limits(call_timeout=1.0), mode) as child:
            child.call("problem_06.elementary", 1, 0.5)
            with pytest.raises(StudentTimeout):
                child.call("problem_06.frames")
            held = [os.open(os.devnull, os.O_RDONLY) for _ in range(6)]  # the lowest free numbers, taken
            assert child.call("problem_06.elementary", 1, 0.5).shape == (3, 3)
    finally:
        for fd in held:
            os.close(fd)
        shutil.rmtree(submission.path.parent, ignore_errors=True)


# ------------------------------------------------------------------------------------------ items 1 and 2


@needs_bwrap
def test_a_venv_under_tmp_is_visible_while_tmp_stays_private(tmp_venv, tmp_path):
    python = str(tmp_venv / "venv" / "bin" / "python")
    info = canary(LIMITS, BWRAP, python=python)
    assert info["python"] == python
    submission = copy_reference(tmp_path / "pkg")
    (submission / "__init__.py").write_text(
        f"import os\nprint('secret visible:', os.path.exists({str(tmp_venv / 'secret.txt')!r}))\n"
        "print('tmp entries:', sorted(os.listdir('/tmp')))\n")
    copy = materialize(submission)
    try:
        with Child(copy.path, LIMITS, BWRAP, python=python) as child:
            assert child.call("problem_06.elementary", 3, 0.3).shape == (3, 3)
            stdout, _ = child.output()
        assert "secret visible: False" in stdout
        # the child's /tmp holds only the way to the Python runtime's folders (the venv's, and the folders its
        # .pth file names when those live under /tmp as well)
        shown = {Path(p).relative_to("/tmp").parts[0] for p in launch.visible_paths(python) if p.startswith("/tmp/")}
        assert os.path.basename(tmp_venv) in shown
        assert stdout.split("tmp entries:", 1)[1].strip() == repr(sorted(shown))
    finally:
        shutil.rmtree(copy.path.parent, ignore_errors=True)


@needs_bwrap
def test_site_packages_are_visible_and_the_graders_packages_in_them_are_not(tmp_venv, tmp_path):
    """A wheel installs the grader's packages into site-packages, next to its dependencies."""
    site = venv_site(tmp_venv / "venv")
    shutil.copytree(ROOT / "reference", site / "reference", ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(ROOT / "checks", site / "checks", ignore=shutil.ignore_patterns("__pycache__"))
    (site / "visible_marker.py").write_text("VISIBLE = True\n")
    submission = copy_reference(tmp_path / "pkg")
    (submission / "__init__.py").write_text(
        "import os, sys\n"
        "import visible_marker\n"
        f"print('reference files:', os.listdir({str(site / 'reference')!r}))\n"
        f"print('checks files:', os.listdir({str(site / 'checks')!r}))\n"
        "print('source visible:', any(os.path.exists(os.path.join(p, 'grader', 'runner.py')) for p in "
        f"[{str(ROOT)!r}] + sys.path))\n")
    copy = materialize(submission)
    try:
        with Child(copy.path, LIMITS, BWRAP, python=str(tmp_venv / "venv" / "bin" / "python")) as child:
            child.call("problem_06.elementary", 1, 0.1)
            stdout, stderr = child.output()
        assert "reference files: []" in stdout and "checks files: []" in stdout, (stdout, stderr)
        assert "source visible: False" in stdout
    finally:
        shutil.rmtree(copy.path.parent, ignore_errors=True)


@needs_bwrap
def test_a_venv_inside_the_checkout_is_visible_and_the_checkout_is_not(tmp_venv, tmp_path, monkeypatch):
    """``python -m venv .venv`` inside the project, the grader installed from it: the child sees the venv only."""
    monkeypatch.setattr(launch, "_source_root", lambda: str(tmp_venv))
    python = str(tmp_venv / "venv" / "bin" / "python")
    assert canary(LIMITS, BWRAP, python=python)["python"] == python
    assert str(tmp_venv) not in launch.visible_paths(python)


def test_the_source_checkout_and_the_cache_are_masked_wherever_they_are_shown():
    bound = launch.visible_paths()
    hidden = launch.hidden_paths(bound)
    for secret in (launch._source_root(), str(launch.cache_root())):
        if secret and any(launch._inside(secret, p) for p in bound):
            assert secret in hidden


# ------------------------------------------------------------------------------------------ item 3: set-up faults


@pytest.fixture
def numpy_hidden(monkeypatch):
    """A sandbox that does not show numpy: what a broken installation looks like from inside."""
    import numpy

    numpy_dir = os.path.dirname(os.path.realpath(numpy.__file__))
    original = launch.hidden_paths
    monkeypatch.setattr(launch, "hidden_paths", lambda bound, python=None: [*original(bound, python), numpy_dir])


@needs_bwrap
def test_a_worker_without_numpy_is_a_grader_fault_with_the_fix(numpy_hidden, reference_copy, tmp_path, capsys):
    with pytest.raises(SandboxError) as fault:
        grade_submission(reference_copy, [6], seed=1, workers=Fresh(LIMITS, BWRAP))
    text = str(fault.value)
    assert "installation" in text and "numpy" in text and "pip " in text and "not the submission" in text
    code = main(["problem-6", "--submission", str(reference_copy), "--json", str(tmp_path / "r.json")])
    assert code == 3
    assert "numpy" in capsys.readouterr().err
    assert not (tmp_path / "r.json").exists()


@needs_bwrap
def test_a_batch_whose_canary_fails_grades_nobody(numpy_hidden, tmp_path, capsys):
    for name in ("alice", "bob"):
        copy_reference(tmp_path / "class" / name)
    code = main(["batch", str(tmp_path / "class"), "--out", str(tmp_path / "out"), "--problems", "6", "-q"])
    assert code == 3
    err = capsys.readouterr().err
    assert "numpy" in err and "installation" in err
    book = tmp_path / "out" / GRADEBOOK_NAME
    if book.exists():
        import sqlite3

        with sqlite3.connect(book) as db:
            assert db.execute("SELECT count(*) FROM submissions").fetchone()[0] == 0
            assert db.execute("SELECT count(*) FROM runs").fetchone()[0] == 0


def test_a_worker_that_cannot_start_is_a_grader_fault(reference_copy):
    with pytest.raises(SandboxError, match="cannot be started"):
        canary(LIMITS, sandbox_mode(), python="/nonexistent/bin/python3")


def test_a_mistyped_probe_is_a_grader_fault_found_before_anything_runs(reference_copy):
    child = Child(reference_copy, LIMITS, sandbox_mode())
    with child:
        with pytest.raises(GraderFault, match="does not exist"):
            child.call("problem_06.framez")
        assert child._proc is None


def _typo_module():
    module = ModuleType("checks.problem_98")
    module.TITLE = "A check with a mistyped probe (test only)"

    @check(1, title="frames, asked for under a wrong name")
    def check_typo(ctx):
        ctx.student("problem_06.framez")

    module.check_typo = check_typo
    return module


def test_a_check_with_a_mistyped_probe_reports_a_grader_error(reference_copy, monkeypatch):
    import grader.runner

    monkeypatch.setattr(grader.runner, "problem_module", lambda n: _typo_module())
    (report,) = grade_submission(reference_copy, [98], seed=1, workers=Fresh(LIMITS, sandbox_mode()))
    (result,) = report.results
    assert result.status is Status.GRADER_ERROR and "framez" in result.message, result
    assert "your code" not in result.message


@pytest.fixture
def runtime_with_broken_probe(tmp_path, monkeypatch):
    runtime = tmp_path / "runtime"
    shutil.copytree(launch.runtime_dir(), runtime)
    (runtime / "probes" / "zz_broken.py").write_text(
        "from . import probe\n\n\n@probe\ndef needs(pkg):\n    import a_dependency_that_is_not_installed\n")
    launch._make_readable(runtime)
    monkeypatch.setattr(launch, "runtime_dir", lambda: runtime)
    return runtime


def test_the_worker_reports_a_probe_failure_as_the_graders(runtime_with_broken_probe, reference_copy):
    mode = sandbox_mode()
    if not mode.isolated and refusal() is not None:
        pytest.skip("covered by the refusal: no child runs here without bubblewrap")
    rotations = reference_copy / "rotations.py"
    rotations.write_text(rotations.read_text() + "\n\ndef R1(alpha):\n    import a_package_the_student_lacks\n")
    with Child(reference_copy, LIMITS, mode) as child:
        child._ensure_imported()
        with pytest.raises(GraderFault, match="zz_broken.needs"):  # the grader's probe lacks a dependency
            child._request({"op": "call", "probe": "zz_broken.needs", "args": []}, 30)
        with pytest.raises(GraderFault, match="no probe"):  # the worker's lookup, behind the parent's check
            child._request({"op": "call", "probe": "problem_06.framez", "args": []}, 30)
        with pytest.raises(StudentCodeError, match="a_package_the_student_lacks"):  # the student's own import
            child.call("problem_06.elementary", 1, 0.1)


# ------------------------------------------------------------------------------------------ item 13: no root


def test_without_bubblewrap_root_refuses_or_drops_to_its_own_uid(reference_copy, tmp_path):
    result = run_cli("problem-6", "--submission", reference_copy, "--json", tmp_path / "r.json",
                     env={"GRADER_SANDBOX": "process"})
    if refusal() is not None:
        assert result.returncode == 3, result.stdout
        assert "never runs as root" in result.stderr and BWRAP_FIX in result.stderr
        assert not (tmp_path / "r.json").exists()
    else:
        assert result.returncode == 0, result.stdout + result.stderr
        note = json.loads((tmp_path / "r.json").read_text())
        text = json.dumps(note)
        assert ("unprivileged uid" in text) if os.geteuid() == 0 else ("your own user" in text)


def test_a_batch_without_bubblewrap_needs_no_sandbox_and_records_it(tmp_path):
    copy_reference(tmp_path / "class" / "alice")
    out = tmp_path / "out"
    env = {"GRADER_SANDBOX": "process"}
    refused = run_cli("batch", tmp_path / "class", "--out", out, "--problems", "6", "-q", env=env)
    assert refused.returncode == 3
    assert "bubblewrap" in refused.stderr and "--no-sandbox" in refused.stderr
    assert not (out / GRADEBOOK_NAME).exists()
    chosen = run_cli("batch", tmp_path / "class", "--out", out, "--problems", "6", "-q", "--no-sandbox", env=env)
    import sqlite3

    if refusal() is not None:  # the canary refuses to run anyone as root: nobody is graded
        assert chosen.returncode == 3 and "never runs as root" in chosen.stderr
        with sqlite3.connect(out / GRADEBOOK_NAME) as db:
            assert db.execute("SELECT count(*) FROM submissions").fetchone()[0] == 0
        return
    assert chosen.returncode == 0, chosen.stderr
    with sqlite3.connect(out / GRADEBOOK_NAME) as db:
        (sandbox,) = db.execute("SELECT sandbox FROM runs").fetchone()
        assert sandbox.startswith("--no-sandbox")
        (note,) = db.execute("SELECT sandbox FROM submissions").fetchone()
        assert "bubblewrap" in note


@needs_root
def test_uids_are_unique_across_graders():
    mine = users.claim_uid()
    try:
        again = users.claim_uid()
        try:
            other = subprocess.run(
                [sys.executable, "-c", "from grader.sandbox import users; c = users.claim_uid(); print(c.uid)"],
                cwd=ROOT, capture_output=True, text=True, timeout=120, check=True)
            uids = {mine.uid, again.uid, int(other.stdout)}
            assert len(uids) == 3 and all(uid >= users.BASE_UID for uid in uids)
        finally:
            again.release()
    finally:
        mine.release()


@needs_root
def test_the_sweep_kills_every_process_and_removes_every_file_of_the_uid():
    claim = users.claim_uid()
    try:
        uid = claim.uid
        daemon = subprocess.Popen(["sleep", "1000"], user=uid, group=uid, extra_groups=[], start_new_session=True)
        planted = []
        for folder in users.SCRATCH_DIRS:
            if os.path.isdir(folder):
                path = Path(folder) / f"grader-test-sweep-{uid}-{os.getpid()}"
                path.mkdir()
                (path / "inner").write_text("x")
                for p in (path, path / "inner"):
                    os.chown(p, uid, uid)
                planted.append(path)
        assert users.processes_of(uid)
        users.sweep(uid)
        assert daemon.wait(timeout=30) == -signal.SIGKILL
        assert not users.processes_of(uid)
        assert not [p for p in planted if p.exists()]
    finally:
        claim.release()


def test_concurrent_children_run_under_different_unprivileged_uids(tmp_path):
    """Plain processes as root: each child under a uid of its own, never root; elsewhere: not root either."""
    mode = plain_mode()
    if refusal() is not None:
        assert_refused(lambda: canary(LIMITS, mode))
        return
    paths = [materialize(copy_reference(tmp_path / f"s{i}")).path for i in range(2)]
    with Child(paths[0], LIMITS, mode) as first, Child(paths[1], LIMITS, mode) as second:
        uids = [first.ready()["uid"], second.ready()["uid"]]
        assert first.call("problem_06.elementary", 2, 0.2).shape == (3, 3)
    if os.geteuid() == 0:
        assert 0 not in uids and uids[0] != uids[1]
        assert first.info.get("network_isolated") is not None
    for path in paths:
        shutil.rmtree(path.parent, ignore_errors=True)


@pytest.mark.parametrize("mode", ["bwrap", "process"])
def test_student_code_that_plots_can_import_matplotlib(reference_copy, mode):
    """The child's private /tmp (its HOME) is writable by its uid: matplotlib, which needs a writable config
    folder, imports in student code as it does on the student's machine."""
    if mode == "bwrap" and not sandbox_mode().isolated:
        pytest.skip("bubblewrap is not available here")
    chosen = sandbox_mode() if mode == "bwrap" else plain_mode()
    if mode == "process" and refusal():
        pytest.skip(refusal())
    rotations = reference_copy / "rotations.py"
    rotations.write_text("import matplotlib\nmatplotlib.use('Agg')\nimport matplotlib.pyplot as plt\n"
                         "plt.figure()\n" + rotations.read_text())
    (report,) = grade_submission(reference_copy, [6], seed=1, workers=Fresh(mode=chosen))
    failed = [(r.check_id, r.message[:300]) for r in report.results if not r.passed]
    assert not failed


def test_the_private_tmp_is_bounded(reference_copy):
    """The child's /tmp is writable, and a tmpfs holds memory: a submission that floods it stops at its size."""
    if not sandbox_mode().isolated:
        pytest.skip("bubblewrap is not available here")
    init = reference_copy / "__init__.py"
    init.write_text(init.read_text() + """
import os as _os
_written, _error = 0, "none"
try:
    while _written < 512:
        with open(_os.path.join("/tmp", f"flood-{_written}"), "wb") as _handle:
            _handle.write(b"x" * 2**20)
        _written += 1
except OSError as _exc:
    _error = _exc.__class__.__name__
print(f"flood: {_written} MiB, stopped by {_error}")
""")
    (report,) = grade_submission(reference_copy, [6], seed=1)
    assert "stopped by OSError" in report.stdout, report.stdout
    written = int(report.stdout.split("flood: ")[1].split(" MiB")[0])
    assert written <= launch.TMP_SIZE_MB, report.stdout
    assert report.score == report.auto_max_score


def test_the_test_run_says_how_student_code_runs_here(monkeypatch):
    """pytest's header: the sandbox of this machine, or the grader's refusal and its fix where it must refuse."""
    import grader.sandbox as sandbox

    from .conftest import sandbox_header

    monkeypatch.setattr(sandbox, "sandbox_mode", lambda: SandboxMode("bwrap", "bubblewrap: no network"))
    assert sandbox_header() == ["sandbox: bubblewrap: no network"]
    monkeypatch.setattr(sandbox, "sandbox_mode", lambda: SandboxMode("process", ""))
    monkeypatch.setattr(sandbox, "refusal", lambda: "refusing to run student code: ...\nFix: install bubblewrap")
    header = sandbox_header()
    assert "refuses to run student code" in header[0] and header[-1] == "  Fix: install bubblewrap"
    monkeypatch.setattr(sandbox, "refusal", lambda: None)
    assert sandbox_header() == ["sandbox: a plain process with resource limits (bubblewrap is not available)"]


# ------------------------------------------------------------------------------------------ what the guide says


def test_the_report_says_what_a_plain_process_had(tmp_path):
    """The report of a plain process names what it had, as its worker found at start-up: a PID namespace, Landlock,
    a network namespace, the filter; and says so plainly where one was missing."""
    child = Child(tmp_path, LIMITS, plain_mode("bubblewrap is not available"))
    try:
        child.info = {"pid_namespace": True, "network_isolated": True, "landlock": {"abi": 6, "tcp": True,
                      "signals": True}, "syscalls": {"arch": "x86_64"}}
        note = child.note
        assert "its own PID and mount namespaces" in note and "Landlock let it read only" in note
        assert "network isolated" in note and "system-call filter" in note and "no keyrings" in note
        child.info = {"landlock": None, "syscalls": {"arch": "x86_64"}}
        note = child.note
        assert "PID" not in note and "every file its user may read" in note and "NOT isolated" in note
        child.info = {"landlock": {"abi": 4, "tcp": True}, "syscalls": {"arch": "x86_64"}}
        assert "TCP connections blocked" in child.note
    finally:
        child.__exit__(None, None, None)


#: each sentence of the instructors' guide's sandbox section (docs/instructors.md), and what holds it: hostile
#: submissions (``tests/hostile/NAME``, graded in bubblewrap and as plain processes, fresh and warm) and tests
#: (``module::function``)
SANDBOX_SECTION = {
    "Student code never runs as root, and each report says how it ran.":
        ("kill_everything", "test_hostile::test_fallback_is_reported",
         "test_sandbox::test_concurrent_children_run_under_different_unprivileged_uids"),
    "Every student's process starts with a fresh, empty session keyring and a system-call filter, anchored on "
    "Docker's default profile: it cannot use the kernel's keyrings, trace other processes, mount file systems, make "
    "namespaces, load BPF programs, open performance counters or userfaultfd, use io_uring, or connect to a Unix "
    "socket.":
        ("keyring_session", "keyring_user", "forbidden_syscalls", "unix_socket_escape",
         "test_hostile::test_a_key_that_one_student_leaves_never_reaches_the_next_under_the_same_uid",
         "test_seccomp::test_every_call_a_container_is_refused_is_refused_with_eperm",
         "test_seccomp::test_the_filter_refuses_in_this_kernel_what_the_process_could_do_before"),
    "A call of another architecture's table (i386, x32) kills it.":
        ("test_seccomp::test_calls_of_another_architecture_kill_the_process",
         "test_seccomp::test_the_filter_refuses_in_this_kernel_what_the_process_could_do_before"),
    "Where the filter cannot be installed (a machine other than x86_64 or aarch64), nothing is graded (exit 3).":
        ("test_seccomp::test_no_student_code_runs_where_the_filter_cannot_be_installed",
         "test_seccomp::test_an_unsupported_machine_is_refused"),
    "With bubblewrap (`apt-get install bubblewrap`), it runs in namespaces of its own, with no network and no other "
    "process of the machine in view.":
        ("network_escape", "other_processes", "kill_everything"),
    "It sees, read-only, only the system's programs and libraries, the Python runtime, the worker and the submission "
    "(of `/etc`, only the dynamic loader's cache and its alternatives), and writes only a private `/tmp`: not the "
    "reference, the checks, the grader's cache, other submissions or `/sys`, wherever the grader is installed.":
        ("steal_reference_files", "steal_reference_import", "link_to_reference", "cache_poison", "leftovers",
         "read_system_files", "test_sandbox::test_the_source_checkout_and_the_cache_are_masked_wherever_they_are_shown",
         "test_sandbox::test_the_private_tmp_is_bounded"),
    "Without bubblewrap, as root, it runs as a plain process under an unprivileged uid of its own, with resource "
    "limits and its own network, PID and mount namespaces and a `/proc` of its own (where the kernel allows them).":
        ("other_processes", "network_escape", "kill_everything", "fork_bomb", "memory_bomb",
         "test_sandbox::test_without_bubblewrap_root_refuses_or_drops_to_its_own_uid"),
    "Where the kernel has Landlock, it reads only the system's programs and libraries, the Python runtime and the "
    "submission (of `/etc` and `/sys`, only the dynamic loader's cache, the time zone and the number of CPUs), and "
    "writes only a private folder.":
        ("read_system_files", "steal_reference_files", "cache_poison", "leftovers"),
    "Without Landlock, a plain process reads every file that its uid may read.":
        ("test_sandbox::test_the_report_says_what_a_plain_process_had",),
    "Without root, it runs as your own user with resource limits: it sees the machine's other processes and keeps "
    "the network (Landlock blocks TCP where the kernel has it).":
        ("test_sandbox::test_the_report_says_what_a_plain_process_had", "test_hostile::test_fallback_is_reported",
         "test_install::test_a_student_without_bubblewrap_is_told_plainly_and_keeps_their_cache"),
    "The student kit on a student's own machine without bubblewrap uses the portable mode instead (see "
    "[students.md](students.md#where-your-code-runs)): no filter and no confinement, only a guard of the grading "
    "against crashes and hangs.":
        ("test_portable::test_the_kit_on_a_laptop_chooses_the_portable_mode",
         "test_portable::test_a_portable_grading_says_what_it_protects", "test_hostile::test_hostile_submission_portable",
         "test_laptops::test_grade_init_and_problem_6_work_without_posix"),
    "As root without bubblewrap, `grade` refuses (exit 3) with the fix when the unprivileged uid could not read the "
    "Python runtime (e.g. a Python under `/root`).":
        ("test_sandbox::test_without_bubblewrap_root_refuses_or_drops_to_its_own_uid",
         "test_hostile::test_fallback_is_reported"),
    "`grade batch` without bubblewrap needs `--no-sandbox`, which the gradebook records.":
        ("test_sandbox::test_a_batch_without_bubblewrap_needs_no_sandbox_and_records_it",),
    "A broken installation (a worker that cannot start or import its dependencies) is reported as such, exit code 3, "
    "and nothing is graded.":
        ("test_sandbox::test_a_worker_without_numpy_is_a_grader_fault_with_the_fix",
         "test_sandbox::test_a_worker_that_cannot_start_is_a_grader_fault"),
}


def sandbox_sentences() -> list[str]:
    """The sentences of the sandbox section of docs/instructors.md (from "Student code never runs as root" to the
    next section, the student kit's)."""
    text = (ROOT / "docs" / "instructors.md").read_text(encoding="utf-8")
    section = text[text.index("Student code never runs as root"):text.index("## The student kit")]
    lines = [line.removeprefix("- ") for line in section.splitlines() if not line.rstrip().endswith(":")]
    flowing = " ".join(" ".join(lines).split())
    return re.split(r"(?<=[.)])\s+(?=[A-Z`])", flowing)


def test_each_sentence_of_the_guides_sandbox_section_is_held_by_a_test():
    import importlib

    from .submissions import hostile_names

    assert sandbox_sentences() == list(SANDBOX_SECTION)
    for sentence, holders in SANDBOX_SECTION.items():
        for holder in holders:
            if "::" in holder:
                module, function = holder.split("::")
                assert callable(getattr(importlib.import_module(f"tests.{module}"), function, None)), holder
            else:
                assert holder in hostile_names(), holder
