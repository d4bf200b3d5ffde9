"""Starting the child process that runs a submission: limits, environment, what it may see, and under which uid.

With bubblewrap (``bwrap``) the child runs in new namespaces with no network, a private empty ``/tmp``, and
read-only views of exactly three things: the Python runtime (interpreter, standard library, installed
dependencies, wherever they live, ``/tmp`` included), the grader's runtime directory (the worker and the probes)
and the submission copy.  The grader's own packages (``reference``, ``checks``, ``grader``, ...) and the reference
cache are masked wherever they live: a source checkout, an editable install or a wheel in site-packages.

Without bubblewrap the child is a plain process with the same resource limits, and the report says so.  Student
code never runs as root: a grader running as root starts the worker under an unprivileged uid of its own (see
``users``), or refuses when that uid could not read the Python runtime.
"""

from __future__ import annotations

import atexit
import functools
import importlib
import importlib.util
import json
import os
import shutil
import stat
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import SandboxError
from . import users

__all__ = [
    "Limits",
    "SandboxMode",
    "sandbox_mode",
    "runtime_dir",
    "child_env",
    "interpreter_layout",
    "visible_paths",
    "hidden_paths",
    "cache_root",
    "Launch",
    "prepare",
    "prepare_zygote",
    "ForkConfig",
    "prepare_fork",
    "renew_home",
    "plain_mode",
    "is_root",
    "refusal",
    "HIDDEN_PACKAGES",
    "BWRAP_FIX",
]

#: the grader's packages: the child never sees them
HIDDEN_PACKAGES = ("reference", "checks", "grader", "tests", "student_template", "tools")
#: what the child imports at start-up before it says ready (the first is imported, the others looked up)
REQUIRED = ("numpy", "scipy", "sympy")
#: the command that installs the sandbox
BWRAP_FIX = "apt-get install bubblewrap"
#: system directories shown read-only inside bubblewrap
SYSTEM_DIRS = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/etc/ld.so.cache", "/etc/alternatives")
#: what a plain-process child may read besides the Python runtime, the worker and the submission (Landlock): the
#: system's programs and libraries, its processes (as root, only its own: a PID namespace and /proc of its own),
#: and of /etc and /sys only what the runtime reads (measured with strace over a grading of every problem and over
#: student code that plots: the dynamic loader's cache, the time zone, the number of CPUs)
READABLE_SYSTEM = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/proc", "/etc/ld.so.cache",
                   "/etc/localtime", "/sys/devices/system/cpu/online", "/sys/devices/system/cpu/possible")
#: devices a plain-process child may read and write (Landlock)
DEVICES = ("/dev/null", "/dev/zero", "/dev/full", "/dev/random", "/dev/urandom")


@dataclass(frozen=True)
class Limits:
    """Resource limits of one child process."""

    call_timeout: float = 10.0  # seconds for one probe call
    import_timeout: float = 20.0  # seconds for importing the submission
    setup_timeout: float = 60.0  # seconds for the worker to start and import its dependencies (trusted code)
    memory_mb: int = 2048  # address space
    cpu_seconds: int = 300  # CPU time over the child's life
    file_size_mb: int = 16  # largest file the child may write (its stdout and stderr are files)
    processes: int = 32  # processes of the child's uid (enforced when the grader runs as root)

    def for_worker(self) -> dict:
        return {
            "memory": self.memory_mb * 2**20,
            "cpu": self.cpu_seconds,
            "file_size": self.file_size_mb * 2**20,
            "processes": self.processes,
            "core": 0,
        }


#: the size of the private /tmp of a bubblewrap child [MiB] (a tmpfs, held in memory)
TMP_SIZE_MB = 64


@dataclass(frozen=True)
class SandboxMode:
    """How children are isolated: ``"bwrap"`` or ``"process"`` (limits only, under an unprivileged uid when
    the grader runs as root)."""

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


def _process_note(reason: str) -> str:
    if is_root():
        return (f"{reason}: the submission ran as a plain process under an unprivileged uid of its own, with "
                "resource limits")
    return (f"{reason}: not sandboxed; the submission ran as your own user with resource limits (install "
            f"bubblewrap to isolate it: {BWRAP_FIX})")


def plain_mode(reason: str = "bubblewrap not used") -> SandboxMode:
    """The plain-process mode, its note saying why and how the submission runs."""
    return SandboxMode("process", _process_note(reason))


def is_root() -> bool:
    """Whether the grader runs as root.  A system without uids (Windows: no ``os.geteuid``) has no root whose
    rights student code could use."""
    geteuid = getattr(os, "geteuid", None)
    return geteuid is not None and geteuid() == 0


def sandbox_mode(prefer: str = "auto") -> SandboxMode:
    """Pick the isolation: ``prefer`` is ``"auto"``, ``"bwrap"`` or ``"process"``.

    ``GRADER_SANDBOX=process`` in the environment forces the plain-process mode.  The portable mode is never
    chosen here (see ``portable.student_mode``: a student's own grading only), whatever ``GRADER_SANDBOX`` says."""
    return _sandbox_mode(os.environ.get("GRADER_SANDBOX", prefer), 0 if is_root() else -1)


@functools.lru_cache(maxsize=8)
def _sandbox_mode(prefer: str, euid: int) -> SandboxMode:
    if prefer == "process":
        return plain_mode()
    bwrap = shutil.which("bwrap")
    if bwrap and _bwrap_works(bwrap):
        return SandboxMode("bwrap", "bubblewrap: no network, no access to the reference or other submissions")
    if prefer == "bwrap":
        raise SandboxError(f"bubblewrap was requested but is not installed or cannot create namespaces "
                           f"(install it: {BWRAP_FIX})")
    return plain_mode("bubblewrap is not available")


# ------------------------------------------------------------------------------------------ what the child runs


def _make_readable(root: Path) -> None:
    """World-readable, so that a child running under its own uid can read it."""
    os.chmod(root, 0o755)
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames:
            os.chmod(os.path.join(dirpath, name), 0o755)
        for name in filenames:
            os.chmod(os.path.join(dirpath, name), 0o644)


@functools.lru_cache(maxsize=1)
def runtime_dir() -> Path:
    """A private directory holding the worker (its serving loop, its confinement and the fork server of a batch
    slot, with the modules they use) and the probes (the package this process imports): the only grader code the
    child sees."""
    root = Path(tempfile.mkdtemp(prefix="grader-runtime-"))
    atexit.register(shutil.rmtree, root, True)
    here = Path(__file__).parent
    for name in ("worker.py", "confinement.py", "forkserver.py", "protocol.py", "notebook.py", "seccomp.py",
                 "portable_worker.py"):
        shutil.copy2(here / name, root / name)
    probes = Path(importlib.import_module("probes").__file__).parent
    shutil.copytree(probes, root / "probes", ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    _make_readable(root)
    return root


def child_env(home: str = "/tmp") -> dict[str, str]:
    """A minimal environment: no secrets of the grader's environment leak into the child."""
    return {
        "PATH": "/usr/local/bin:/usr/bin:/bin",
        "HOME": home,
        "TMPDIR": home,
        "LANG": "C.UTF-8",
        "PYTHONHASHSEED": "0",
        "PYTHONDONTWRITEBYTECODE": "1",
        "PYTHONIOENCODING": "utf-8",
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
        "MKL_NUM_THREADS": "1",
        "MPLBACKEND": "Agg",
    }


# ------------------------------------------------------------------------------------------ what the child sees


def interpreter_layout() -> dict:
    """Where the running interpreter's files are, as it finds them when started with ``-I`` (no user site, no
    PYTHONPATH): its executable, prefixes, standard library, site directories and the directories that ``.pth``
    files of those add.  Standard library only: also run in another interpreter to learn its layout."""
    import os
    import site
    import sys
    import sysconfig

    paths = {sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix,
             os.path.dirname(sys.executable), os.path.dirname(os.path.realpath(sys.executable))}
    paths |= {sysconfig.get_paths()[key] for key in ("stdlib", "platstdlib", "purelib", "platlib")}
    sites = [p for p in site.getsitepackages() if os.path.isdir(p)]
    paths |= set(sites)
    for directory in sites:
        for name in sorted(os.listdir(directory)):
            if not name.endswith(".pth"):
                continue
            try:
                with open(os.path.join(directory, name), encoding="utf-8") as handle:
                    lines = handle.read().splitlines()
            except (OSError, UnicodeDecodeError):
                continue
            for line in lines:
                line = line.strip()
                if line and not line.startswith(("#", "import ", "import\t")):
                    paths.add(os.path.join(directory, line))
    real = sorted({os.path.realpath(p) for p in paths if p and os.path.isdir(p)})
    return {"executable": sys.executable, "paths": real, "sites": [os.path.realpath(p) for p in sites]}


@functools.lru_cache(maxsize=4)
def _layout_of(python: str) -> dict:
    if python == sys.executable:
        return interpreter_layout()
    import inspect
    import textwrap

    code = textwrap.dedent(inspect.getsource(interpreter_layout))
    code += "\nimport json\nprint(json.dumps(interpreter_layout()))\n"
    try:
        done = subprocess.run([python, "-I", "-c", code], capture_output=True, text=True, timeout=60)
        return json.loads(done.stdout)
    except (OSError, subprocess.SubprocessError, ValueError) as exc:
        raise SandboxError(f"the Python interpreter {python} cannot be started: {exc}") from exc


def _inside(path: str, base: str) -> bool:
    return path == base or path.startswith(base.rstrip("/") + "/")


def _source_root() -> str | None:
    """The grader's source checkout, when it runs from one (not from site-packages)."""
    root = os.path.dirname(os.path.dirname(os.path.realpath(importlib.import_module("grader").__file__)))
    return None if os.path.basename(root) in ("site-packages", "dist-packages") else root


def cache_root() -> Path:
    """The reference cache of the grader (``$GRADER_CACHE``, else ``~/.cache/mbd-autograder``)."""
    base = os.environ.get("GRADER_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")), "mbd-autograder")
    return Path(os.path.realpath(base))


def _package_dirs(name: str) -> list[str]:
    try:
        spec = importlib.util.find_spec(name)
    except (ImportError, ValueError):
        return []
    if spec is None:
        return []
    if spec.submodule_search_locations:
        return [os.path.realpath(p) for p in spec.submodule_search_locations]
    return [os.path.realpath(spec.origin)] if spec.origin else []


def visible_paths(python: str | None = None) -> list[str]:
    """The directories the child's interpreter needs, minimal (none inside another).  A virtual environment
    inside the grader's checkout is shown without the checkout; one that holds the checkout (or a ``.pth`` file
    naming it) shows it masked (``hidden_paths``)."""
    layout = _layout_of(python or sys.executable)
    kept: list[str] = []
    for path in sorted(set(layout["paths"]), key=len):
        if not any(_inside(path, k) for k in kept):
            kept.append(path)
    return kept


def hidden_paths(bound: list[str], python: str | None = None) -> list[str]:
    """What must be masked inside the bound directories: the grader's packages wherever they are installed
    (source, editable, wheel), its source checkout and the reference cache."""
    layout = _layout_of(python or sys.executable)
    candidates = set()
    for name in HIDDEN_PACKAGES:
        candidates.update(_package_dirs(name))
        candidates.update(os.path.join(directory, name) for directory in layout["paths"])
    source = _source_root()
    if source:
        candidates.add(source)
    candidates.add(str(cache_root()))
    hidden = []
    for path in sorted(candidates):
        if os.path.isdir(path) and any(_inside(path, b) for b in bound) and not any(_inside(path, h) for h in hidden):
            hidden.append(path)
    return hidden


# ------------------------------------------------------------------------------------------ the launch


@dataclass
class Launch:
    """How one child is started, and what to clean after it: its argv, environment and working directory,
    the uid it runs under (when the grader is root) and that uid's private directory."""

    argv: list[str]
    env: dict[str, str]
    cwd: str
    claim: users.UidClaim | None = None
    home: str | None = None

    def with_pipes(self, request_fd: int, reply_fd: int) -> list[str]:
        """The argv for a worker whose protocol pipes are these descriptors: a worker started again (after one that
        timed out or crashed) has new pipes, whose numbers are whatever is free in the grader by then."""
        return [*self.argv[:-4], str(request_fd), str(reply_fd), *self.argv[-2:]]

    def after_exit(self, again: bool = True) -> None:
        """After the worker ended: kill every process left under its uid and remove the files that uid wrote;
        remove its private home, and with ``again`` make a fresh one for the next worker."""
        if self.claim is not None and self.claim.sweeps:
            users.sweep(self.claim.uid)
        if self.home is None:
            return
        shutil.rmtree(self.home, ignore_errors=True)
        if again:
            home = _private_home(self.claim.uid if self.claim else None)
            self.argv = [arg.replace(self.home, home) for arg in self.argv]
            self.home = self.cwd = home
            self.env = dict(self.env, HOME=home, TMPDIR=home)
        else:
            self.home = None

    def release(self) -> None:
        """After the last worker: sweep, and give the uid back."""
        self.after_exit(again=False)
        if self.claim is not None:
            self.claim.release()
            self.claim = None


def _mode_bits(path: str) -> int | None:
    try:
        return os.stat(path).st_mode
    except OSError:
        return None


def _unreadable_by_others(path: str) -> str | None:
    """The first directory on the way to ``path`` (included) that an unprivileged user cannot enter or list."""
    current = Path(path)
    for directory in [*reversed(current.parents), current]:
        mode = _mode_bits(str(directory))
        if mode is None or not mode & stat.S_IXOTH or (directory == current and not mode & stat.S_IROTH):
            return str(directory)
    return None


def refusal(python: str | None = None) -> str | None:
    """Why a grader running as root without bubblewrap cannot run student code under an unprivileged uid
    (None when it can)."""
    if os.geteuid() != 0:
        return None
    for path in [*visible_paths(python), str(runtime_dir())]:
        blocked = _unreadable_by_others(path)
        if blocked is not None:
            mode = _mode_bits(blocked)
            shown = f"mode {stat.S_IMODE(mode):04o}" if mode is not None else "missing"
            return (
                "refusing to run student code: the grader runs as root and bubblewrap is not available, and "
                "student code never runs as root. It would run under an unprivileged uid, but that uid cannot "
                f"read {path} ({blocked} is {shown}, closed to other users).\n"
                f"Fix: install bubblewrap ({BWRAP_FIX}), or install the grader into a Python that every user "
                "can read (for example a virtual environment of /usr/bin/python3 outside /root)."
            )
    return None


def _guard_cache() -> None:
    """The reference cache belongs to the grader and is closed to every other user (created so if missing)."""
    root = cache_root()
    try:
        root.mkdir(parents=True, exist_ok=True, mode=0o700)
        info = os.lstat(root)
    except OSError as exc:
        raise SandboxError(f"the reference cache {root} cannot be prepared: {exc}") from exc
    if info.st_uid != os.geteuid() or not stat.S_ISDIR(info.st_mode):
        raise SandboxError(f"the reference cache {root} does not belong to the grader (owner uid {info.st_uid}): "
                           "remove it, or point GRADER_CACHE to a folder of the grader's own")
    if info.st_mode & 0o077:
        os.chmod(root, 0o700)


def _share_with(path: Path, gid: int) -> None:
    """The submission copy becomes readable (not writable) by the child's group and by no other user."""
    for dirpath, dirnames, filenames in os.walk(path):
        os.chown(dirpath, 0, gid, follow_symlinks=False)
        os.chmod(dirpath, 0o750)
        for name in filenames:
            full = os.path.join(dirpath, name)
            if not os.path.islink(full):
                os.chown(full, 0, gid, follow_symlinks=False)
                os.chmod(full, 0o640)


def _private_home(uid: int | None) -> str:
    """The child's home, temporary folder and working directory: the only place it may write to."""
    home = tempfile.mkdtemp(prefix="grader-child-")
    if uid is not None:
        os.chown(home, uid, uid)
    return home


def _landlock_rules(python: str, submission: Path, home: str) -> dict:
    """What a plain-process child may use: read the system, the Python runtime (without the grader's packages),
    the worker and the submission; write its home and a few devices."""
    read = [*READABLE_SYSTEM, *visible_paths(python), str(runtime_dir()), str(submission)]
    return {"read": read, "hidden": hidden_paths(read, python), "write": [home], "devices": list(DEVICES)}


def _bwrap_argv(python: str, submission: Path, worker_args: list[str], root: bool, zygote: bool = False) -> list[str]:
    """The bubblewrap command of a worker for ``submission`` (shown at /submission); with ``zygote``, of the warm
    process of a slot, ``submission`` being the slot's staging folder (shown at /slot, from which each forked
    worker binds its own student's package at /submission)."""
    bound = [p for p in visible_paths(python) if not any(_inside(p, s) for s in SYSTEM_DIRS)]
    shared = [p for p in bound if p in ("/", "/tmp")]
    if shared:
        raise SandboxError(f"the Python runtime lives directly in {shared[0]}: the sandbox cannot show it without "
                           "showing everything there; install it in a folder of its own")
    namespaces = ["--unshare-pid", "--unshare-net", "--unshare-ipc", "--unshare-uts", "--unshare-cgroup-try"]
    if not root:  # as root, the worker switches to its uid itself (a user namespace would leave it unmapped)
        namespaces.append("--unshare-user")
        if zygote:  # the mounts of each forked worker, in the user namespace only; dropped before the student runs
            namespaces += ["--cap-add", "CAP_SYS_ADMIN"]
    argv = [shutil.which("bwrap") or "bwrap", *namespaces, "--die-with-parent", "--new-session"]
    for system_dir in SYSTEM_DIRS:
        argv += ["--ro-bind-try", system_dir, system_dir]
    # The private /tmp first: a runtime that lives under /tmp is bound on top of it afterwards.
    # Writable by the child's uid (its HOME: matplotlib and others need one), and bounded: a tmpfs is memory.
    argv += ["--proc", "/proc", "--dev", "/dev", "--perms", "1777", "--size", str(TMP_SIZE_MB * 2**20), "--tmpfs",
             "/tmp"]
    made = {"/", "/tmp", "/proc", "/dev"}
    for path in bound:  # parents traversable by the child's uid even where the host's are not (e.g. /root)
        for parent in reversed(Path(path).parents):
            if str(parent) not in made:
                made.add(str(parent))
                argv += ["--perms", "0755", "--dir", str(parent)]
    for path in bound:
        argv += ["--ro-bind", path, path]
    for path in hidden_paths(bound, python):
        argv += ["--tmpfs", path]
    runtime = runtime_dir()
    argv += ["--ro-bind", str(runtime), "/grader"]
    if zygote:
        argv += ["--ro-bind", str(submission), "/slot", "--dir", "/submission", "--chdir", "/tmp"]
        return [*argv, "--", python, "-I", "-B", "/grader/forkserver.py", worker_args[0], "/slot", worker_args[1]]
    argv += ["--ro-bind", str(submission), "/submission", "--chdir", "/tmp"]
    return [*argv, "--", python, "-I", "-B", "/grader/worker.py", *worker_args[:2], "/submission", worker_args[2]]


def _worker_argv(python: str, submission: Path, request_fd: int, reply_fd: int, config: dict) -> list[str]:
    worker = runtime_dir() / "worker.py"
    return [python, "-I", "-B", str(worker), str(request_fd), str(reply_fd), str(submission), json.dumps(config)]


def prepare(submission: Path, request_fd: int, reply_fd: int, limits: Limits, mode: SandboxMode,
            python: str | None = None) -> Launch:
    """The launch of a worker for ``submission``; the two fds are the protocol pipes.

    As root, claims a uid no other child uses (released by ``Launch.release``).  Raises ``SandboxError`` when
    the child cannot be started safely."""
    python = python or sys.executable
    root = is_root()
    required = [name for name in REQUIRED if importlib.util.find_spec(name) is not None]
    config = {"limits": limits.for_worker(), "require": required}
    if not mode.isolated and not root:  # a student's own machine: their own uid, Landlock where available
        home = _private_home(None)
        config["landlock"] = _landlock_rules(python, submission, home)
        return Launch(_worker_argv(python, submission, request_fd, reply_fd, config), child_env(home), home, None,
                      home)
    if not mode.isolated:
        _refuse_unsafe(python)
    # as root, a uid of the child's own: its own files and its own process count
    claim = users.claim_uid(sweeps=not mode.isolated) if root else None
    try:
        config["uid"] = claim.uid if claim else None
        if mode.isolated:
            argv = _bwrap_argv(python, submission, [str(request_fd), str(reply_fd), json.dumps(config)], root)
            return Launch(argv, child_env("/tmp"), tempfile.gettempdir(), claim)
        _share_with(submission, claim.uid)
        home = _private_home(claim.uid)
        config.update(own_namespaces=True, landlock=_landlock_rules(python, submission, home))
        return Launch(_worker_argv(python, submission, request_fd, reply_fd, config), child_env(home), home, claim,
                      home)
    except BaseException:
        if claim is not None:
            claim.release()
        raise


def _refuse_unsafe(python: str) -> None:
    """As root without bubblewrap: refuse when an unprivileged uid could not read the runtime; guard the cache."""
    reason = refusal(python)
    if reason:
        raise SandboxError(reason)
    _guard_cache()


# ------------------------------------------------------------------------------------------ warm forks


def prepare_zygote(staging: Path, control_fd: int, mode: SandboxMode, preload: list[str],
                   python: str | None = None) -> Launch:
    """The launch of a slot's warm process (``grader.sandbox.zygote``), ``control_fd`` its end of the control
    socket.  It runs no student code and keeps the grader's uid (or root, inside bubblewrap's namespaces or as a
    plain process), so that it can confine each worker it forks."""
    python = python or sys.executable
    root = os.geteuid() == 0
    required = [name for name in REQUIRED if importlib.util.find_spec(name) is not None]
    config = {"require": required, "preload": list(preload), "pid_namespace": mode.isolated}
    if mode.isolated:
        argv = _bwrap_argv(python, staging, [str(control_fd), json.dumps(config)], root, zygote=True)
        return Launch(argv, child_env("/tmp"), tempfile.gettempdir())
    if root:
        _refuse_unsafe(python)
    forkserver = runtime_dir() / "forkserver.py"
    argv = [python, "-I", "-B", str(forkserver), str(control_fd), str(staging), json.dumps(config)]
    return Launch(argv, child_env(str(staging)), str(staging))


@dataclass
class ForkConfig:
    """What one worker forked from a zygote is given (its ``config``: limits, uid, mounts, Landlock, environment),
    and what to clean after it: the uid it runs under (when the grader is root) and that uid's private home."""

    config: dict
    claim: users.UidClaim | None = None
    home: str | None = None


def prepare_fork(submission: Path, staging: Path, limits: Limits, mode: SandboxMode,
                 python: str | None = None) -> ForkConfig:
    """The confinement of one student's worker forked from a zygote: the same as ``prepare`` gives a fresh worker.
    Under bubblewrap, ``submission`` lies inside the zygote's ``staging`` folder."""
    python = python or sys.executable
    root = os.geteuid() == 0
    config: dict = {"limits": limits.for_worker()}
    if mode.isolated:
        relative = Path(os.path.realpath(submission)).relative_to(os.path.realpath(staging))
        config.update(bind=f"/slot/{relative.as_posix()}", submission="/submission", cwd="/tmp",
                      env=child_env("/tmp"))
        claim = users.claim_uid(sweeps=False) if root else None
        config["uid"] = claim.uid if claim else None
        return ForkConfig(config, claim)
    if not root:
        home = _private_home(None)
        config.update(submission=str(submission), cwd=home, env=child_env(home), uid=None,
                      landlock=_landlock_rules(python, submission, home))
        return ForkConfig(config, None, home)
    _refuse_unsafe(python)
    claim = users.claim_uid(sweeps=True)
    try:
        _share_with(submission, claim.uid)
        home = _private_home(claim.uid)
        config.update(submission=str(submission), cwd=home, env=child_env(home), uid=claim.uid,
                      own_namespaces=True, landlock=_landlock_rules(python, submission, home))
        return ForkConfig(config, claim, home)
    except BaseException:
        claim.release()
        raise


def renew_home(fork: ForkConfig, python: str | None = None) -> None:
    """A fresh private home for the next worker of the same student (plain processes)."""
    if fork.home is None:
        return
    shutil.rmtree(fork.home, ignore_errors=True)
    home = _private_home(fork.claim.uid if fork.claim else None)
    fork.home = home
    fork.config.update(cwd=home, env=child_env(home),
                       landlock=_landlock_rules(python or sys.executable, Path(fork.config["submission"]), home))
