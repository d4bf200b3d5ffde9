"""Batch grading on a Dask cluster: a LocalCluster of two worker processes, one killed in the middle of grading a
student; every student is graded exactly once, with the right grade, and the killed worker's sandbox goes with it.
Also the snapshot that carries a student's files to a worker that does not see them."""

import os
import signal
import sqlite3
import subprocess
import sys
import time
import zipfile

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
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    client = distributed.Client(cluster)
    try:
        command = [sys.executable, "-m", "grader.cli", "batch", str(subs), "--out", str(out), "--problems", "6",
                   "--cluster", cluster.scheduler_address, "--quiet"]
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
