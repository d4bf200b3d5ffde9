"""Starting the child process that runs a submission: limits, environment and the bubblewrap sandbox.

With bubblewrap (``bwrap``) the child runs in new namespaces with no network, a read-only view of the Python
runtime, the grader's runtime directory (the worker and the probes) and the submission copy; the project's
``reference/``, ``checks/``, ``grader/`` and ``tests/`` are not visible, nor is any other submission.  Without
bubblewrap the child runs as a plain process with the same resource limits, and reports say so.
"""

from __future__ import annotations

import functools
import os
import shutil
import subprocess
import sys
import tempfile
import atexit
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Limits", "SandboxMode", "sandbox_mode", "runtime_dir", "child_command", "child_env"]

PROJECT_ROOT = Path(__file__).resolve().parents[1]
#: packages that the child must never see
HIDDEN_PACKAGES = ("reference", "checks", "grader", "tests", "student_template", "tools")
#: first uid used for children when the grader runs as root (one uid per parallel slot)
BASE_UID = 61000


@dataclass(frozen=True)
class Limits:
    """Resource limits of one child process."""

    call_timeout: float = 10.0  # seconds for one probe call
    import_timeout: float = 20.0  # seconds for importing the submission
    memory_mb: int = 2048  # address space
    cpu_seconds: int = 300  # CPU time over the child's life
    file_size_mb: int = 16  # largest file the child may write (its stdout and stderr are files)
    processes: int = 32  # processes of the child's user (enforced when the grader runs as root)
    slot: int = 0  # parallel slot: selects the child's uid when running as root

    def for_worker(self, drop_uid: bool = True) -> dict:
        uid = BASE_UID + self.slot if drop_uid and os.geteuid() == 0 else None
        return {
            "memory": self.memory_mb * 2**20,
            "cpu": self.cpu_seconds,
            "file_size": self.file_size_mb * 2**20,
            "processes": self.processes,
            "core": 0,
            "uid": uid,
        }


@dataclass(frozen=True)
class SandboxMode:
    """How children are isolated: ``"bwrap"`` or ``"process"`` (limits only)."""

    kind: str
    note: str = field(default="")

    @property
    def isolated(self) -> bool:
        return self.kind == "bwrap"


def _bwrap_works(bwrap: str) -> bool:
    try:
        done = subprocess.run(
            [bwrap, "--unshare-all", "--die-with-parent", "--ro-bind", "/", "/", "true"],
            capture_output=True,
            timeout=10,
        )
    except (OSError, subprocess.SubprocessError):
        return False
    return done.returncode == 0


@functools.lru_cache(maxsize=4)
def sandbox_mode(prefer: str = "auto") -> SandboxMode:
    """Pick the isolation: ``prefer`` is ``"auto"``, ``"bwrap"`` or ``"process"``.

    ``GRADER_SANDBOX=process`` in the environment forces the plain-process mode.
    """
    prefer = os.environ.get("GRADER_SANDBOX", prefer)
    if prefer == "process":
        return SandboxMode("process", "bubblewrap not used (plain process with resource limits)")
    bwrap = shutil.which("bwrap")
    if bwrap and _bwrap_works(bwrap):
        return SandboxMode("bwrap", "bubblewrap: no network, no access to the reference or other submissions")
    if prefer == "bwrap":
        raise RuntimeError("bubblewrap was requested but is not installed or cannot create namespaces")
    return SandboxMode(
        "process",
        "bubblewrap is not available: the submission ran as a plain process with resource limits only, "
        "without filesystem or network isolation",
    )


@functools.lru_cache(maxsize=1)
def runtime_dir() -> Path:
    """A private directory holding the worker and the probes: the only grader code the child sees."""
    root = Path(tempfile.mkdtemp(prefix="grader-runtime-"))
    atexit.register(shutil.rmtree, root, True)
    shutil.copy2(Path(__file__).with_name("worker.py"), root / "worker.py")
    shutil.copytree(
        PROJECT_ROOT / "probes" if (PROJECT_ROOT / "probes").is_dir() else _package_dir("probes"),
        root / "probes",
        ignore=shutil.ignore_patterns("__pycache__"),
    )
    _make_readable(root)
    return root


def _package_dir(name: str) -> Path:
    import importlib.util

    spec = importlib.util.find_spec(name)
    return Path(spec.origin).parent


def _make_readable(root: Path) -> None:
    """World-readable, so that a child running under its own uid can read it."""
    os.chmod(root, 0o755)
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames:
            os.chmod(os.path.join(dirpath, name), 0o755)
        for name in filenames:
            os.chmod(os.path.join(dirpath, name), 0o644)


def child_env() -> dict[str, str]:
    """A minimal environment: no secrets of the grader's environment leak into the child."""
    return {
        "PATH": "/usr/local/bin:/usr/bin:/bin",
        "HOME": "/tmp",
        "TMPDIR": "/tmp",
        "LANG": "C.UTF-8",
        "PYTHONHASHSEED": "0",
        "PYTHONDONTWRITEBYTECODE": "1",
        "PYTHONIOENCODING": "utf-8",
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
        "MKL_NUM_THREADS": "1",
        "MPLBACKEND": "Agg",
    }


def _python_paths() -> list[str]:
    """Directories the child's Python needs: its prefixes and the site directories on sys.path."""
    paths = {os.path.realpath(sys.base_prefix), os.path.realpath(sys.prefix)}
    paths.add(os.path.dirname(os.path.dirname(os.path.realpath(sys.executable))))
    root = str(PROJECT_ROOT)
    for entry in sys.path:
        real = os.path.realpath(entry) if entry else ""
        if real and os.path.isdir(real) and not (real == root or real.startswith(root + os.sep)):
            paths.add(real)
    ordered = sorted(paths, key=len)
    kept: list[str] = []
    for path in ordered:
        if not any(path == k or path.startswith(k + os.sep) for k in kept):
            kept.append(path)
    return kept


def _hidden_dirs(bound: list[str]) -> list[str]:
    """Directories inside the bound paths that hold the project's trusted code: masked with empty tmpfs."""
    hidden = []
    candidates = [str(PROJECT_ROOT)]
    for base in bound:
        candidates += [os.path.join(base, name) for name in HIDDEN_PACKAGES]
        candidates += [os.path.join(base, "site-packages", name) for name in HIDDEN_PACKAGES]
    for path in candidates:
        if os.path.isdir(path) and any(path == b or path.startswith(b + os.sep) for b in bound):
            hidden.append(path)
    return hidden


def _world_traversable(path: str) -> bool:
    """True when every directory from / down to ``path`` can be entered by any user."""
    current = Path(path)
    for directory in [current, *current.parents]:
        try:
            if not os.stat(directory).st_mode & 0o001:
                return False
        except OSError:
            return False
    return True


def child_command(submission: Path, request_fd: int, reply_fd: int, limits: Limits, mode: SandboxMode):
    """The argv that starts a worker for ``submission``; the two fds are the protocol pipes."""
    import json

    runtime = runtime_dir()
    worker_args = [str(request_fd), str(reply_fd)]
    limit_json = json.dumps(limits.for_worker())
    python = sys.executable
    if not mode.isolated:
        # Without a mount namespace the child can only drop to its own uid where that uid can reach Python.
        drop = all(_world_traversable(p) for p in _python_paths() + [str(runtime), str(submission)])
        limit_json = json.dumps(limits.for_worker(drop_uid=drop))
        return [python, "-I", "-B", str(runtime / "worker.py"), *worker_args, str(submission), limit_json]
    bound = _python_paths()
    # As root, the worker drops to its own uid itself (a user namespace would leave that uid unmapped).
    namespaces = ["--unshare-pid", "--unshare-net", "--unshare-ipc", "--unshare-uts", "--unshare-cgroup-try"]
    if os.geteuid() != 0:
        namespaces.append("--unshare-user")
    argv = [shutil.which("bwrap"), *namespaces, "--die-with-parent", "--new-session"]
    for system_dir in ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/etc/ld.so.cache", "/etc/alternatives"):
        argv += ["--ro-bind-try", system_dir, system_dir]
    ancestors = sorted({str(p) for path in bound for p in Path(path).parents if str(p) != "/"}, key=len)
    for directory in ancestors:  # traversable by the child's uid even where the host's is not (e.g. /root)
        argv += ["--perms", "0755", "--dir", directory]
    for path in bound:
        argv += ["--ro-bind", path, path]
    for path in _hidden_dirs(bound):
        argv += ["--tmpfs", path]
    argv += ["--ro-bind", str(runtime), "/grader", "--ro-bind", str(submission), "/submission"]
    argv += ["--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp", "--chdir", "/tmp"]
    argv += ["--", python, "-I", "-B", "/grader/worker.py", *worker_args, "/submission", limit_json]
    return argv
