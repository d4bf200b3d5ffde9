"""The grader installed as a wheel into a virtual environment under /tmp (not editable, not from this checkout)
grades the reference to full marks: in bubblewrap, and, as root, as a plain process under an unprivileged uid (the
path a Gradescope container takes).  The same environment then runs the plain-process tests as root: its Python
(Debian's /usr/bin/python3 where present) can be read by an unprivileged uid, unlike an interpreter under /root.

Slow: the wheel is built and installed once per session (pip's cache makes later installs fast)."""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from grader.sandbox import sandbox_mode

from .environments import base_python, public_tmp_dir
from .submissions import ROOT, build_hostile, copy_reference, hostile_expectation, hostile_names

pytestmark = pytest.mark.slow

def _run(argv, **kwargs):
    """Runs ``argv`` to its end, which must be a success; it sees none of the checkout through ``PYTHONPATH`` (a
    developer's run of the tests from a working tree may set it)."""
    kwargs.setdefault("timeout", 900)
    kwargs.setdefault("env", {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")})
    done = subprocess.run(argv, capture_output=True, text=True, **kwargs)
    assert done.returncode == 0, f"{argv}\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    return done


@pytest.fixture(scope="module")
def venv():
    """A wheel of the project, installed with its dependencies into a fresh virtual environment under /tmp."""
    with public_tmp_dir("grader-install-") as base:
        source = base / "source"  # a copy: building in place would leave build/ and *.egg-info in the checkout
        shutil.copytree(ROOT, source, ignore=shutil.ignore_patterns(
            ".git", "__pycache__", "*.egg-info", "build", "dist", ".hypothesis", "results", "mywork"))
        offline = ["--no-build-isolation"] if _has_setuptools() else []  # no download of the build backend
        _run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", *offline, "-w", str(base / "dist"),
              str(source)])
        (wheel,) = (base / "dist").glob("mbd_autograder-*.whl")
        _run([base_python(), "-m", "venv", str(base / "venv")])
        _run([str(base / "venv" / "bin" / "python"), "-m", "pip", "install", "-q", f"{wheel}[dev]"])
        shutil.rmtree(source)
        yield base / "venv"


def _has_setuptools() -> bool:
    """Whether this interpreter can build the wheel itself (else pip fetches the build backend)."""
    try:
        import setuptools  # noqa: F401
        import wheel  # noqa: F401
    except ImportError:
        return False
    return True


@pytest.fixture(scope="module")
def reference(venv):
    """A copy of the reference that every user may read."""
    folder = Path(tempfile.mkdtemp(prefix="grader-install-ref-", dir="/tmp"))
    os.chmod(folder, 0o755)
    copy_reference(folder / "ref")
    yield folder / "ref"
    shutil.rmtree(folder, ignore_errors=True)


def grade(venv: Path, submission: Path, env=None, user=None) -> tuple[subprocess.CompletedProcess, dict]:
    """``grade problem-6`` of the installed wheel, from a folder that holds nothing of the project."""
    cwd = Path(tempfile.mkdtemp(prefix="grader-install-cwd-", dir="/tmp"))
    os.chmod(cwd, 0o777)
    report = cwd / "report.json"
    argv = [str(venv / "bin" / "grade"), "problem-6", "--submission", str(submission), "--json", str(report)]
    if user is not None:
        argv = ["setpriv", f"--reuid={user}", f"--regid={user}", "--clear-groups", "--", *argv]
    environment = {"PATH": "/usr/bin:/bin", "HOME": str(cwd), "LANG": "C.UTF-8", **(env or {})}
    try:
        done = subprocess.run(argv, cwd=cwd, env=environment, capture_output=True, text=True, timeout=600)
        data = json.loads(report.read_text()) if report.exists() else {}
    finally:
        shutil.rmtree(cwd, ignore_errors=True)
    return done, data


def full_marks(done, data) -> dict:
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    (report,) = data["reports"]
    assert report["visible_score"] == sum(r["max_score"] for r in report["results"]) > 0
    assert all(r["status"] == "passed" for r in report["results"]), report["results"]
    return report


def test_the_wheel_is_what_runs(venv):
    done = _run([str(venv / "bin" / "python"), "-c",
                 "import grader, grader.sandbox.worker, probes; print(grader.__file__, probes.__file__)"],
                cwd="/")
    assert "site-packages" in done.stdout and str(ROOT) not in done.stdout


@pytest.mark.skipif(not sandbox_mode().isolated, reason="bubblewrap is not available here")
def test_the_wheel_grades_the_reference_in_bubblewrap(venv, reference):
    report = full_marks(*grade(venv, reference))
    assert report["isolated"] and "bubblewrap" in report["sandbox"]


def test_the_wheel_grades_the_reference_without_bubblewrap(venv, reference):
    report = full_marks(*grade(venv, reference, env={"GRADER_SANDBOX": "process"}))
    assert not report["isolated"]
    if os.geteuid() == 0:  # what a Gradescope container does: an unprivileged uid of the child's own
        assert "unprivileged uid" in report["sandbox"] and "network" in report["sandbox"]


@pytest.mark.skipif(os.geteuid() != 0 or not shutil.which("setpriv"), reason="needs root to act as another user")
def test_a_student_without_bubblewrap_is_told_plainly_and_keeps_their_cache(venv, reference):
    """A student on their own machine (not root, no bubblewrap): graded, and told that no sandbox isolated the
    code; the code, running as the student, still cannot write the student's reference cache (where the
    kernel has Landlock, which the report names)."""
    nobody = 65534
    report = full_marks(*grade(venv, reference, env={"GRADER_SANDBOX": "process"}, user=nobody))
    assert "not sandboxed" in report["sandbox"] and "your own user" in report["sandbox"]
    if "Landlock let it read only" not in report["sandbox"]:
        pytest.skip("this kernel has no Landlock: a plain process of the student's own uid can write what they can")
    attack = Path(tempfile.mkdtemp(prefix="grader-install-attack-", dir="/tmp"))
    try:
        os.chmod(attack, 0o755)
        submission = build_hostile("cache_poison", attack / "pkg")
        cache = attack / "cache"
        entry = cache / "0123456789abcdef" / "entry.json"
        entry.parent.mkdir(parents=True)
        entry.write_text('{"value": 1.0}')
        for path in (cache, entry.parent, entry):
            os.chown(path, nobody, nobody)
        (submission / "target.txt").write_text(json.dumps({"cache": str(cache), "nonce": "0", "port": 0}))
        done, data = grade(venv, submission, env={"GRADER_SANDBOX": "process", "GRADER_CACHE": str(cache)},
                           user=nobody)
        assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
        assert "cache writes: 0" in data["reports"][0]["stdout"]
        assert sorted(cache.rglob("*")) == [entry.parent, entry] and entry.read_text() == '{"value": 1.0}'
    finally:
        shutil.rmtree(attack, ignore_errors=True)


@pytest.mark.skipif(os.geteuid() != 0, reason="as another user the plain-process tests run in-tree already")
def test_the_plain_process_tests_run_as_root_with_a_readable_runtime(venv, tmp_path):
    """The hostile suite and the sandbox tests in plain-process mode, with the environment's Python: every
    submission runs under an unprivileged uid; only what needs bubblewrap's file-system view is skipped."""
    xml = tmp_path / "junit.xml"
    done = subprocess.run(
        [str(venv / "bin" / "python"), "-m", "pytest", "-q", "-p", "no:cacheprovider", f"--junitxml={xml}",
         "tests/test_hostile.py", "tests/test_sandbox.py", "tests/test_warm.py", "-k", "process or fallback or "
         "without_bubblewrap or uid or concurrent"],
        cwd=ROOT, capture_output=True, text=True, timeout=1800)
    assert done.returncode == 0, done.stdout[-5000:]
    cases = list(ET.parse(xml).getroot().iter("testcase"))
    skipped = {case.get("name"): case.find("skipped").get("message", "") for case in cases
               if case.find("skipped") is not None}
    isolated_only = {f"test_hostile_submission[{n}-{kind}]" for n in hostile_names() for kind in ("process",
                     "process-warm") if hostile_expectation(n).get("isolated_only")}
    assert set(skipped) <= isolated_only, skipped
    # the whole hostile suite ran as plain processes, fresh and warm
    hostile = {f"test_hostile_submission[{n}-{kind}]" for n in hostile_names() for kind in ("process", "process-warm")}
    hostile |= {f"test_a_key_that_one_student_leaves_never_reaches_the_next_under_the_same_uid[{kind}]"
                for kind in ("process", "process-warm")}
    assert hostile <= {case.get("name") for case in cases}, hostile - {case.get("name") for case in cases}
    assert "refusing" not in done.stdout


#: grades a leaver and then a spy twice on one warm process (``tests/warm/``) and prints what came out
SLOT_SCRIPT = """
import json, sys
from grader.runner import grade_submission
from grader.sandbox import Limits, plain_mode, sandbox_mode
from grader.workers import Forked
from grader.sandbox.zygote import Zygote, warm_modules
kind, leaver, spy = sys.argv[1:4]
mode = sandbox_mode("bwrap") if kind == "bwrap" else plain_mode("test")
with Zygote(Limits(call_timeout=5.0, import_timeout=10.0), mode, warm_modules([6])) as zygote:
    zygote.start()
    reports = [grade_submission(path, [6], seed=3, workers=Forked(zygote))[0] for path in (leaver, spy, spy)]
print(json.dumps([{"score": r.score, "max": r.auto_max_score, "stdout": r.stdout, "sandbox": r.sandbox,
                   "isolated": r.isolated} for r in reports]))
"""


@pytest.mark.skipif(os.geteuid() != 0 or not shutil.which("setpriv"), reason="needs root to act as another user")
@pytest.mark.parametrize("kind", ["bwrap", "process"])
def test_warm_forks_of_an_unprivileged_user_keep_students_apart(venv, kind):
    """The warm path of an instructor who is not root: the zygote in bubblewrap's user namespace (the mounts of
    each fork need its CAP_SYS_ADMIN there, dropped before the student runs), or a plain process under the
    instructor's uid with Landlock.  The next student sees nothing of the one before."""
    from .test_warm import assert_isolated, assert_nothing_left, nonce, student

    if kind == "bwrap" and not sandbox_mode().isolated:
        pytest.skip("bubblewrap is not available here")
    nobody = 65534
    base = Path(tempfile.mkdtemp(prefix="grader-install-warm-", dir="/tmp"))
    try:
        os.chmod(base, 0o755)
        marker = nonce()
        leaver, spy = student("leaver", base / "leaver", marker), student("spy", base / "spy", marker)
        home = base / "home"
        home.mkdir()
        os.chown(home, nobody, nobody)
        done = subprocess.run(
            ["setpriv", f"--reuid={nobody}", f"--regid={nobody}", "--clear-groups", "--",
             str(venv / "bin" / "python"), "-c", SLOT_SCRIPT, kind, str(leaver), str(spy)],
            cwd=home, env={"PATH": "/usr/bin:/bin", "HOME": str(home), "LANG": "C.UTF-8"}, capture_output=True,
            text=True, timeout=600)
        assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
        reports = json.loads(done.stdout.splitlines()[-1])
    finally:
        shutil.rmtree(base, ignore_errors=True)
    assert [r["isolated"] for r in reports] == [kind == "bwrap"] * 3
    for report in reports[1:]:
        assert report["score"] == report["max"] > 0, report
    assert_isolated(*[r["stdout"] for r in reports], isolated=kind == "bwrap", root=False)
    assert_nothing_left(marker)
