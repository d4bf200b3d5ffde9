"""Grading a batch on a Dask distributed cluster: ``grade batch --cluster ADDRESS`` (or ``--cluster local:N``).

Each task grades one student on a Dask worker, in that worker's own sandbox: the worker process keeps a grading
slot (a subprocess with the checks imported and a warm zygote, as a local batch's worker has, see ``pool``) and
hands it the student with the same per-student time bound.  The task returns plain results, ``(kind, payload,
seconds)`` exactly as a local worker does; the client alone writes the gradebook, one transaction per student, as
each result arrives, so that resume, ``--force`` and the exports work as in a local batch.

A worker lost in the middle of a task (a machine that goes away, a process killed) costs nothing but time: the
scheduler gives its tasks to another worker, and the client records each student once, when the student's one
future completes (a task that workers keep dying on is given up after Dask's ``allowed-failures`` and reported as
not graded, retried on the next run).

Every worker must have the project (the same checks, probes and reference: the client refuses workers whose grader
version differs) and bubblewrap installed.  Submissions are read where the client sees them when a worker sees the
same files (a shared file system, or ``local:N``); otherwise the task carries a snapshot of the student's entry.

A cluster runs whatever task its scheduler is given, as the user of its workers: it is authenticated.  ``local:N``
speaks TLS with temporary credentials that live in this process's memory and its workers' (Dask's
``Security.temporary``): no other client can connect.  A cluster a course starts itself is reached over ``tls://``
with the course's certificate files (``Credentials``); plain ``tcp://`` only when the instructor says so
(``--insecure``), which the batch's gradebook records.
"""

from __future__ import annotations

import io
import json
import os
import shutil
import tarfile
import tempfile
import threading
from dataclasses import dataclass, replace
from pathlib import Path

from .discover import Entry, submission_hash
from .pool import Slot, Task

__all__ = ["Credentials", "ClusterRefused", "transport", "open_client", "check_workers", "run_cluster",
           "grade_remote", "snapshot", "unpack"]

#: the longest a student's result may keep the client waiting beyond the per-student bound (a worker's start-up)
START_ALLOWANCE = 120.0


# ------------------------------------------------------------------------------------------ the submissions


def snapshot(path: Path) -> bytes:
    """A student's entry (a folder, an archive or a notebook) as a tar archive: names, contents and symbolic links
    as they are, for a worker that does not see the client's files."""
    buffer = io.BytesIO()
    with tarfile.open(fileobj=buffer, mode="w", format=tarfile.PAX_FORMAT, encoding="utf-8",
                      errors="surrogateescape") as tar:
        tar.add(path, arcname=path.name, recursive=True)
    return buffer.getvalue()


def unpack(data: bytes, dest: Path) -> Path:
    """Unpack a ``snapshot`` into ``dest`` and return the entry's path.  Names that leave ``dest`` are refused;
    symbolic links are restored as links (the loader then treats them as it would on the client), after every
    file, so that nothing is written through one."""
    links = []
    entry = None
    with tarfile.open(fileobj=io.BytesIO(data), mode="r", encoding="utf-8", errors="surrogateescape") as tar:
        for member in tar.getmembers():
            parts = Path(member.name).parts
            if not parts or Path(member.name).is_absolute() or ".." in parts:
                raise ValueError(f"a snapshot holds the name {member.name!r}")
            target = dest.joinpath(*parts)
            entry = entry or dest / parts[0]
            if member.isdir():
                target.mkdir(parents=True, exist_ok=True)
            elif member.issym():
                links.append((target, member.linkname))
            elif member.isfile():
                target.parent.mkdir(parents=True, exist_ok=True)
                with tar.extractfile(member) as source, open(target, "wb") as out:
                    shutil.copyfileobj(source, out)
    for target, link in links:
        target.parent.mkdir(parents=True, exist_ok=True)
        os.symlink(link, target)
    if entry is None:
        raise ValueError("an empty snapshot")
    return entry


# ------------------------------------------------------------------------------------------ the worker's side

_slots = threading.local()


def _slot(limits, mode, problems: tuple[int, ...]) -> Slot:
    """This thread's grading slot, started on first use (and again when the configuration changes)."""
    key = (limits, mode, problems)
    slot = getattr(_slots, "slot", None)
    if slot is not None and getattr(_slots, "key", None) != key:
        slot.stop()
        slot = None
    if slot is None:
        slot = Slot(None, threading.get_ident() % 1000, limits, mode, problems)
        _slots.slot, _slots.key = slot, key
    return slot


def _worker_facts(problems: list[int], no_sandbox: bool) -> dict:
    """What the client checks of a worker before it sends students: the grader versions and the sandbox."""
    from ..sandbox import sandbox_mode
    from ..sources import grader_version

    mode = sandbox_mode()
    return {"versions": {n: grader_version(n) for n in problems}, "isolated": mode.isolated, "note": mode.note,
            "host": os.uname().nodename}


def grade_remote(job: dict) -> tuple[str, object, float]:
    """A Dask task: grade one student in this worker's slot; ``(kind, payload, seconds)`` as a local worker sends
    it (``"ok"`` and the reports, ``"timeout"``, ``"crashed"`` or ``"fault"`` and why)."""
    from ..sandbox import sandbox_mode

    mode = sandbox_mode()
    if not mode.isolated and not job["no_sandbox"]:
        return "fault", f"bubblewrap is not available on the worker {os.uname().nodename}", 0.0
    entry: Entry = job["entry"]
    scratch = None
    try:
        path = entry.path
        if not (path.exists() and submission_hash(path) == entry.content_hash):
            if job.get("snapshot") is None:
                return "fault", f"the worker {os.uname().nodename} cannot read {path}", 0.0
            scratch = Path(tempfile.mkdtemp(prefix="grader-snapshot-"))
            path = unpack(job["snapshot"], scratch)
        task = Task(replace(entry, path=path), tuple(job["problems"]))
        slot = _slot(job["limits"], mode, tuple(job["all_problems"]))
        try:
            kind, payload, seconds = slot.outcome(task, job["student_timeout"])
        except RuntimeError as exc:  # the slot cannot start: this worker's installation
            return "fault", f"{os.uname().nodename}: {exc}", 0.0
        if kind == "ok":
            payload = [replace(report, submission=str(entry.path)) for report in payload]
        return kind, payload, seconds
    finally:
        if scratch is not None:
            shutil.rmtree(scratch, ignore_errors=True)


# ------------------------------------------------------------------------------------------ the client's side


#: Dask's own monitoring, quietened for a local grading cluster: its statistical profiler samples each worker's
#: running task every 10 ms (about 3 % of a core per worker, which the students' grading then lacks), and the
#: event-loop and memory monitors poll 50 and 10 times a second.  docs/instructors.md says how to set the same on
#: the workers of a cluster a course starts itself.
QUIET_MONITORING = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "5s",
    "distributed.worker.memory.monitor-interval": "1s",
}


@dataclass(frozen=True)
class Credentials:
    """How the batch's client proves itself to a cluster that a course started: the certificate authority's file,
    the client's certificate and its key (``--tls-ca-file``, ``--tls-cert``, ``--tls-key``, as ``dask scheduler``
    and ``dask worker`` take them); or ``insecure``, the instructor's choice of plain TCP (``--insecure``)."""

    ca_file: str | None = None
    cert: str | None = None
    key: str | None = None
    insecure: bool = False

    @property
    def files(self) -> tuple[str | None, str | None, str | None]:
        return self.ca_file, self.cert, self.key


class ClusterRefused(ValueError):
    """A cluster the batch will not use as asked: plain TCP without ``--insecure``, TLS without certificates."""


def _scheduler_address(address: str) -> str:
    """The scheduler's address: ``address`` itself, or the one a scheduler file (``dask scheduler
    --scheduler-file``) names."""
    if "://" in address or not os.path.isfile(address):
        return address
    try:
        return str(json.loads(Path(address).read_text(encoding="utf-8"))["address"])
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise ClusterRefused(f"{address} is not a scheduler file of Dask: {exc}") from exc


def transport(address: str, credentials: Credentials = Credentials()) -> str:
    """How the batch reaches the cluster at ``address``, as the gradebook records it; ``ClusterRefused`` for an
    unauthenticated cluster the instructor did not choose (``tcp://`` without ``insecure``) and for TLS without
    the three certificate files."""
    if address.startswith("local:"):
        if any(credentials.files) or credentials.insecure:
            raise ClusterRefused("a local cluster makes credentials of its own: --tls-* and --insecure are for "
                                 "--cluster ADDRESS")
        return "TLS with temporary credentials held in memory by this batch and its workers"
    scheduler = _scheduler_address(address)
    scheme = scheduler.split("://", 1)[0] if "://" in scheduler else "tcp"
    if scheme == "tls":
        missing = [option for option, path in zip(("--tls-ca-file", "--tls-cert", "--tls-key"), credentials.files)
                   if not path]
        if missing:
            raise ClusterRefused(f"the cluster {address} speaks TLS: give the certificate files {', '.join(missing)} "
                                 "(see the cluster section of docs/instructors.md)")
        unreadable = [path for path in credentials.files if not os.access(path, os.R_OK)]
        if unreadable:
            raise ClusterRefused(f"the certificate file {unreadable[0]} cannot be read")
        if credentials.insecure:
            raise ClusterRefused("--insecure is for a tcp:// cluster: this one speaks TLS")
        return f"TLS, authenticated by the certificate authority {credentials.ca_file}"
    if scheme == "tcp":
        if not credentials.insecure:
            raise ClusterRefused(f"the cluster {address} speaks plain TCP ({scheduler}): anyone who can reach its "
                                 "scheduler runs code as its workers' user. Start it with TLS and pass tls://... "
                                 "with --tls-ca-file, --tls-cert and --tls-key (see the cluster section of "
                                 "docs/instructors.md), or pass --insecure to use it as it is (recorded in the "
                                 "gradebook)")
        if any(credentials.files):
            raise ClusterRefused("--tls-* files are for a tls:// cluster: this one speaks plain TCP")
        return "--insecure: plain TCP, unauthenticated (the instructor's choice)"
    raise ClusterRefused(f"the cluster {address}: the grader speaks tls:// (or tcp:// with --insecure), not "
                         f"{scheme}://")


def open_client(address: str, credentials: Credentials = Credentials()):
    """A Dask client of the cluster at ``address`` (``tls://host:8786`` with ``credentials``, ``tcp://host:8786``
    with ``credentials.insecure``, a scheduler file's path), or of a local cluster of N worker processes for
    ``local:N``, with TLS and temporary credentials (and ``QUIET_MONITORING``); returns ``(client, cluster or
    None)``.  ``ClusterRefused`` as ``transport`` says."""
    import dask
    from distributed import Client, LocalCluster
    from distributed.security import Security

    transport(address, credentials)
    if address.startswith("local:"):
        count = int(address.split(":", 1)[1] or 1)
        with dask.config.set(QUIET_MONITORING):  # read as the scheduler and the workers start
            cluster = LocalCluster(n_workers=count, threads_per_worker=1, processes=True, dashboard_address=None,
                                   security=Security.temporary(), protocol="tls://", host="127.0.0.1")
        return Client(cluster), cluster
    security = None
    if not credentials.insecure:
        security = Security(tls_ca_file=credentials.ca_file, tls_client_cert=credentials.cert,
                            tls_client_key=credentials.key, require_encryption=True)
    if os.path.isfile(address):
        return Client(scheduler_file=address, security=security), None
    return Client(address, security=security), None


def check_workers(client, problems: list[int], versions: dict[int, str], no_sandbox: bool) -> tuple[str, bool]:
    """Refuse a cluster whose workers would grade differently (another grader version) or without a sandbox
    (unless ``no_sandbox``); return the sandbox note to record and whether every worker has bubblewrap."""
    from ..errors import SandboxError
    from ..sandbox import BWRAP_FIX

    facts = client.run(_worker_facts, problems, no_sandbox)
    if not facts:
        raise SandboxError("the Dask cluster has no workers")
    for address, fact in sorted(facts.items()):
        differing = sorted(n for n in problems if fact["versions"].get(n) != versions[n])
        if differing:
            raise SandboxError(f"the worker {address} ({fact['host']}) has another version of the grader for problems "
                               f"{differing}: install the same project on every worker")
        if not fact["isolated"] and not no_sandbox:
            raise SandboxError(f"bubblewrap is not available on the worker {address} ({fact['host']}): install it "
                               f"there ({BWRAP_FIX}), or pass --no-sandbox (recorded in the gradebook)")
    notes = sorted({fact["note"] for fact in facts.values()})
    return "; ".join(notes), all(fact["isolated"] for fact in facts.values())


def run_cluster(client, tasks: list[Task], *, limits, problems: tuple[int, ...], student_timeout: float,
                no_sandbox: bool, ship: bool, done) -> None:
    """Grade ``tasks`` on the cluster; ``done(task, kind, payload, seconds)`` is called here, once per student, as
    each result arrives.  ``ship``: send each student's snapshot along (workers that may not see the files)."""
    from distributed import as_completed

    futures = {}
    for index, task in enumerate(tasks):
        job = {"entry": task.entry, "problems": task.problems, "all_problems": problems, "limits": limits,
               "student_timeout": student_timeout, "no_sandbox": no_sandbox,
               "snapshot": snapshot(task.entry.path) if ship else None}
        future = client.submit(grade_remote, job, key=f"grade-{index}-{task.entry.content_hash[:16]}", pure=False)
        futures[future] = task
    pending = set(futures)
    try:
        for future in as_completed(futures):
            task = futures[future]
            pending.discard(future)
            try:
                kind, payload, seconds = future.result()
            except Exception as exc:  # noqa: BLE001 - a lost task (workers kept dying) or a fault: not graded
                kind, payload, seconds = "fault", f"{type(exc).__name__}: {exc}", 0.0
            done(task, kind, payload, seconds)
    finally:
        if pending:
            client.cancel(list(pending), force=True)
