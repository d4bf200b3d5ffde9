"""Batch grading on a Dask cluster: a LocalCluster of two worker processes, one killed in the middle of grading a
student; every student is graded exactly once, with the right grade, and the killed worker's sandbox goes with it.
Also the snapshot that carries a student's files to a worker that does not see them."""

import json
import os
import re
import signal
import sqlite3
import subprocess
import sys
import time
import zipfile
from pathlib import Path

import pytest

from grader.batch.cluster import snapshot, unpack
from grader.batch.discover import submission_hash
from grader.gradebook import GRADEBOOK_NAME

from .processes import alive, descendants
from .submissions import ROOT, build_planted, copy_reference, planted_mistakes

distributed = pytest.importorskip("distributed")


def rows(path, query):
    with sqlite3.connect(path, timeout=30) as db:
        return db.execute(query).fetchall()


def committed(path) -> int:
    try:
        return rows(path, "SELECT count(*) FROM submissions")[0][0] if path.exists() else 0
    except sqlite3.OperationalError:
        return 0




def course_credentials(folder: Path):
    """The TLS credentials of a cluster a course starts (one certificate authority that signs the scheduler's, the
    workers' and the client's certificate: here one self-signed certificate for all), as files in a private folder,
    and the options of ``grade batch`` that name them."""
    from distributed.security import Security

    security = Security.temporary()
    folder.mkdir(mode=0o700)
    (folder / "ca.pem").write_text(security.tls_ca_file)
    (folder / "cert.pem").write_text(security.tls_client_cert)
    (folder / "key.pem").write_text(security.tls_client_key)
    os.chmod(folder / "key.pem", 0o600)
    return security, ["--tls-ca-file", str(folder / "ca.pem"), "--tls-cert", str(folder / "cert.pem"),
                      "--tls-key", str(folder / "key.pem")]


def test_an_unauthenticated_client_cannot_run_a_task_on_a_local_cluster(tmp_path):
    """`grade batch --cluster local:2`'s scheduler (it was plain TCP: any local user ran tasks on its workers, as
    their user, root for a batch run as root): a client without its credentials cannot run a task, over TCP, over
    TLS with credentials of its own, or over TLS trusting the scheduler's (public) certificate; the batch's own
    client can."""
    from distributed.security import Security

    from grader.batch.cluster import open_client

    client, cluster = open_client("local:2")[:2]
    ran = tmp_path / "ran"
    try:
        address = cluster.scheduler_address
        own = Security.temporary()
        strangers = [
            (address.replace("tls://", "tcp://"), None),
            (address, own),
            (address, Security(tls_ca_file=cluster.security.tls_ca_file, tls_client_cert=own.tls_client_cert,
                               tls_client_key=own.tls_client_key, require_encryption=True)),
        ]
        for where, security in strangers:
            with pytest.raises(Exception):  # noqa: B017 - refused whichever way: a handshake, a closed comm, a time-out
                stranger = distributed.Client(where, security=security, timeout="10s")
                try:
                    stranger.submit(ran.touch, pure=False).result(timeout=30)
                finally:
                    stranger.close()
        assert not ran.exists()
        assert client.submit(ran.touch, pure=False).result(timeout=60) is None and ran.exists()
    finally:
        client.close()
        cluster.close()


def test_a_cluster_is_reached_over_tls_or_tcp_only_when_the_instructor_says_so(tmp_path, capsys):
    from grader.batch.cluster import ClusterRefused, Credentials, transport
    from grader.cli import main

    _, files = course_credentials(tmp_path / "tls")
    ca, cert, key = files[1::2]
    assert transport("local:2").startswith("TLS with temporary credentials")
    assert transport("tls://host:8786", Credentials(ca, cert, key)) == f"TLS, authenticated by the certificate " \
                                                                        f"authority {ca}"
    assert transport("tcp://host:8786", Credentials(insecure=True)).startswith("--insecure: plain TCP")
    scheduler_file = tmp_path / "scheduler.json"
    scheduler_file.write_text('{"address": "tcp://host:8786"}')
    refused = {
        "tcp://host:8786": (Credentials(), "speaks plain TCP"),
        "host:8786": (Credentials(), "speaks plain TCP"),
        str(scheduler_file): (Credentials(), "speaks plain TCP (tcp://host:8786)"),
        "tls://host:8786": (Credentials(ca), "--tls-cert, --tls-key"),
        "ws://host:8786": (Credentials(insecure=True), "not ws://"),
        "local:2": (Credentials(insecure=True), "makes credentials of its own"),
    }
    for address, (credentials, reason) in refused.items():
        with pytest.raises(ClusterRefused, match=re.escape(reason)):
            transport(address, credentials)
    copy_reference(tmp_path / "subs" / "alice")
    for argv in (["--cluster", "tcp://127.0.0.1:9"], ["--cluster", "tls://127.0.0.1:9", "--tls-ca-file", ca],
                 ["--insecure"]):
        assert main(["batch", str(tmp_path / "subs"), "--out", str(tmp_path / "out"), *argv]) == 2
    err = capsys.readouterr().err
    assert "pass --insecure to use it as it is" in err and "give the certificate files --tls-cert, --tls-key" in err
    assert "are options of --cluster ADDRESS" in err


@pytest.mark.slow
def test_an_insecure_cluster_is_graded_on_and_recorded_as_such(tmp_path):
    from grader.batch import run_batch
    from grader.batch.cluster import Credentials

    copy_reference(tmp_path / "subs" / "alice")
    cluster = distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None)
    try:
        report = run_batch(tmp_path / "subs", tmp_path / "out", problems=[6], progress=False, export=False,
                           cluster=cluster.scheduler_address, credentials=Credentials(insecure=True))
    finally:
        cluster.close()
    assert report.graded == 1
    (sandbox,) = rows(tmp_path / "out" / GRADEBOOK_NAME, "SELECT sandbox FROM runs")[0]
    assert f"Dask cluster {cluster.scheduler_address} (--insecure: plain TCP, unauthenticated" in sandbox, sandbox


def test_a_snapshot_carries_names_contents_and_links(tmp_path):
    folder = copy_reference(tmp_path / "alice")
    (folder / "notes").mkdir()
    (folder / "notes" / "why.txt").write_text("because")
    os.symlink("/etc/passwd", folder / "stolen.py")  # the loader refuses or skips links: it must see this one
    archive = tmp_path / "bob.zip"
    with zipfile.ZipFile(archive, "w") as out:
        out.write(folder / "problem_06.py", "problem_06.py")
    for entry in (folder, archive):
        copy = unpack(snapshot(entry), tmp_path / f"unpacked-{entry.name}")
        assert copy.name == entry.name
        assert submission_hash(copy) == submission_hash(entry)
    assert os.readlink(tmp_path / "unpacked-alice" / "alice" / "stolen.py") == "/etc/passwd"


@pytest.mark.slow
def test_cluster_batch_with_a_worker_killed_midway_grades_every_student_once(tmp_path):
    subs = tmp_path / "subs"
    expected = {}
    for i in range(5):
        folder = copy_reference(subs / f"ref_{i}")
        with open(folder / "problem_06.py", "a") as handle:
            handle.write(f"\n# {i}\n")
        expected[f"ref_{i}"] = 10.0
    mistake = next(m for m in planted_mistakes(6) if m.name == "p06-vectors-transpose")
    build_planted(mistake, subs / "planted")
    expected["planted"] = 9.0  # the vectors check (1 point) fails, nothing else
    out = tmp_path / "results"
    db = out / GRADEBOOK_NAME
    security, files = course_credentials(tmp_path / "tls")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                       security=security, protocol="tls://")
    client = distributed.Client(cluster)
    try:
        command = [sys.executable, "-m", "grader.cli", "batch", str(subs), "--out", str(out), "--problems", "6",
                   "--cluster", cluster.scheduler_address, "--quiet", *files]
        batch = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            killed, sandbox = None, []
            deadline = time.monotonic() + 180
            while killed is None and batch.poll() is None and time.monotonic() < deadline:
                busy = [address for address, keys in client.processing().items() if keys]
                if committed(db) >= 1 and busy:
                    pid = client.run(os.getpid, workers=[busy[0]])[busy[0]]
                    sandbox = descendants(pid)  # its grading slot, the zygote and a student's worker
                    os.kill(pid, signal.SIGKILL)
                    killed = pid
                time.sleep(0.05)
            stdout, stderr = batch.communicate(timeout=300)
        finally:
            batch.kill()
        assert killed is not None, "the batch finished before a worker could be killed"
        assert sandbox, "the killed worker had no grading slot"
        assert batch.returncode == 0, stderr[-3000:]
        graded = rows(db, "SELECT st.name, s.score, s.outcome FROM submissions s JOIN students st "
                          "ON st.id = s.student_id")
        assert sorted(name for name, _, _ in graded) == sorted(expected)  # every student, exactly once
        assert {name: (score, outcome) for name, score, outcome in graded} == {
            name: (score, "graded") for name, score in expected.items()}
        assert rows(db, "SELECT state, graded FROM runs") == [("finished", len(expected))]
        deadline = time.monotonic() + 20
        while any(alive(pid) for pid in sandbox) and time.monotonic() < deadline:
            time.sleep(0.1)
        assert not [pid for pid in sandbox if alive(pid)], "the killed worker's sandbox outlived it"
        assert (out / "grades.csv").exists() and (out / "students" / "planted" / "report.html").exists()
    finally:
        client.close()
        cluster.close()


def test_a_local_cluster_starts_with_dask_monitoring_quietened():
    """``--cluster local:N``: Dask's profiler is off on the workers and its monitors poll slowly (they took about a
    tenth of a core from the students' grading on two workers)."""
    import dask

    from grader.batch.cluster import QUIET_MONITORING, open_client

    client, cluster = open_client("local:1")
    try:
        seen = client.run(lambda: {key: dask.config.get(key) for key in QUIET_MONITORING})
        assert list(seen.values()) == [QUIET_MONITORING]
        (callbacks,) = client.run(lambda dask_worker: {k: c.callback_time for k, c in
                                                       dask_worker.periodic_callbacks.items()}).values()
        assert "profile" not in callbacks and callbacks["tick"] == 1000, callbacks  # milliseconds
        tick = client.run_on_scheduler(lambda dask_scheduler: dask_scheduler.periodic_callbacks["tick"].callback_time)
        assert tick == 1000  # the scheduler, in this process, read the configuration as it started
    finally:
        client.close()
        cluster.close()
    assert dask.config.get("distributed.worker.profile.enabled") is True  # the caller's own config is left as it was


@pytest.mark.slow
@pytest.mark.parametrize("where", ["--jobs 2", "local:2"])
def test_a_batch_leaves_no_temporary_folders_behind(where, tmp_path, monkeypatch):
    """At the end of a batch its grading processes are stopped, and on a cluster their parent (the Dask worker)
    goes away right after, which signals them again: each still removes its staging folder and the folders of its
    sandbox.  (The second signal cut the clean-up short on every cluster batch, leaving a folder per worker.)"""
    from grader.batch import run_batch

    temporary = tmp_path / "tmp"
    temporary.mkdir()
    monkeypatch.setenv("TMPDIR", str(temporary))  # read by every process the batch starts
    (tmp_path / "class").mkdir()
    for name in ("ann", "bob", "cy"):
        copy_reference(tmp_path / "class" / name)
    options = {"jobs": 2} if where == "--jobs 2" else {"cluster": where}
    report = run_batch(tmp_path / "class", tmp_path / "out", problems=[6], progress=False, **options)
    assert report.graded == 3
    deadline = time.monotonic() + 20
    while [p for p in temporary.iterdir() if p.name.startswith("grader-")] and time.monotonic() < deadline:
        time.sleep(0.2)  # the processes finish their clean-up after the batch returned
    assert sorted(p.name for p in temporary.iterdir() if p.name.startswith("grader-")) == []


def _verdicts(reports):
    return {(r.problem, c.check_id): (c.status, c.score, c.diagnosis) for r in reports for c in r.results}


#: The problems the three ways grade each student on (every student the same ones, as a batch grades its class):
#: each planted student's own mistakes of every kind of work the course has, so that every kind of probe module
#: and library a slot's warm process preloads is used (the test holds it): a MuJoCo model simulated in the sandbox
#: (2 even, 5 odd); rotations, frames and bound vectors in modules that later problems import (6 even; 9, 11 odd);
#: inertia, symbolic in part (16 even, 17 odd); planar chains and Jacobians (21 odd; 22, 26 even); the answers file
#: (10 even; 27, 41 odd); kinematic trees and gravity compensation in the tree.py that both students break (31 odd;
#: 32, 34 even); symbolic answers (45 odd); equations of motion and simulations with events (38, 42, 44 even; 43, 47
#: odd).  A student graded after another on the same slot is graded on the same problems, where anything left
#: behind in the slot (its warm process killed, state of the grading process) would change a verdict; and in each
#: student's worker, later problems follow the earlier ones.  All 45 problems took four minutes (a third of it the
#: diagnosis of problem 37 and the simulations of 15, 24 and 46): more problems, but no other kind of work and no
#: other way for a verdict to leak.
VERDICT_PROBLEMS = (2, 5, 6, 9, 10, 11, 16, 17, 21, 22, 26, 27, 31, 32, 34, 38, 41, 42, 43, 44, 45, 47)


@pytest.mark.slow
def test_planted_and_hostile_submissions_get_the_verdicts_of_a_fresh_worker_on_warm_slots_and_a_cluster(tmp_path):
    """The warm path (a batch slot's zygote forks each student's worker) and the cluster path (the same slots in
    Dask workers) grade as a fresh worker does: two students carrying a planted mistake in every other problem
    each, a reference, and two attacks (one kills every process it can see, one leaves a daemon and files behind),
    graded by --jobs 2 and by a two-worker LocalCluster, against each student graded alone by grade_submission with
    the seed the batch gave them.  Graded on ``VERDICT_PROBLEMS``: each planted student's own mistakes of every kind
    of work, and the same problems for the students graded after them on a slot (see there)."""
    from grader.batch import run_batch
    from grader.batch.gradebook import Gradebook
    from grader.runner import grade_submission
    from grader.problems import problems as all_problems
    from grader.sandbox.zygote import warm_modules

    from .submissions import build_hostile, build_with_mistakes, hostile_expectation
    from .test_warm import nonce

    numbers = list(VERDICT_PROBLEMS)
    every = [p.number for p in all_problems()]
    assert set(numbers) <= set(every)
    preloaded = {m for m in warm_modules(every) if not m.startswith("probes.problem_")}
    assert preloaded <= set(warm_modules(numbers)), preloaded - set(warm_modules(numbers))  # every kind is used
    first = {}
    for mistake in planted_mistakes():
        first.setdefault(mistake.problem, mistake)
    subs = tmp_path / "subs"
    applied = {name: build_with_mistakes(subs / name, [m for p, m in sorted(first.items()) if p % 2 == parity],
                                         strict=False)
               for name, parity in (("odd", 1), ("even", 0))}
    assert all(len(names) >= 15 for names in applied.values()), applied
    graded_mistakes = {name: [m for m in first.values() if m.name in names and m.problem in numbers]
                       for name, names in applied.items()}
    assert all(len(mistakes) >= 8 for mistakes in graded_mistakes.values()), graded_mistakes
    copy_reference(subs / "reference")
    build_hostile("kill_everything", subs / "killer")
    build_hostile("leftovers", subs / "leaver")
    (subs / "leaver" / "target.txt").write_text(json.dumps({"nonce": nonce()}))  # what names its leftovers
    paths = {"--jobs 2": dict(jobs=2), "LocalCluster 2": dict(cluster="local:2", force=True)}
    graded = {}
    out = tmp_path / "results"  # one results folder, one secret: each student has one seed on both paths
    for label, how in paths.items():
        report = run_batch(subs, out, problems=numbers, progress=False, export=False, **how)
        assert report.graded == 5, (label, report)
        with Gradebook.in_folder(out) as book:
            rows = book.current()
        graded[label] = {name: [g.report for g in rows if g.student == name] for name in applied.keys()
                         | {"reference", "killer", "leaver"}}
    for name, reports in graded["--jobs 2"].items():
        assert sorted(r.problem for r in reports) == numbers, (name, [r.problem for r in reports])
        seeds = {r.seed for r in reports}
        assert len(seeds) == 1 and {r.seed for r in graded["LocalCluster 2"][name]} == seeds, (name, seeds)
        alone = _verdicts(grade_submission(subs / name, numbers, seed=seeds.pop()))
        for label in paths:
            assert _verdicts(graded[label][name]) == alone, (label, name)
    failed = {name: {c.check_id for r in graded["--jobs 2"][name] for c in r.results if not c.passed}
              for name in applied}
    for name, mistakes in graded_mistakes.items():  # every planted mistake graded still costs its intended check
        for mistake in mistakes:
            assert mistake.check in failed[name], (name, mistake.name)
    for name, attack in (("reference", None), ("killer", "kill_everything"), ("leaver", "leftovers")):
        for label in paths:  # the attacks ran, and cost nothing
            reports = graded[label][name]
            assert sum(r.score for r in reports) == sum(r.auto_max_score for r in reports) > 0, (label, name)
            if attack is not None:
                said = hostile_expectation(attack)["stdout"]
                assert any(said in r.stdout for r in reports), (label, name, reports[0].stdout[-2000:])
