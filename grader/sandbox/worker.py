"""The child side of the grader: sets up its own confinement, imports its dependencies, then imports a submission
and runs probes on it.

This file runs inside the sandbox with the untrusted submission and must stay importable on its own: standard
library only, plus ``protocol.py``, ``notebook.py``, ``seccomp.py`` and the ``probes`` package, which the grader
copies next to it.  It never sees the reference, the checks or the scoring code: it receives probe calls on a
dedicated pipe and sends back plain data (see ``protocol`` for the messages).

    python -I -B worker.py REQUEST_FD REPLY_FD SUBMISSION CONFIG_JSON

Start-up, before any code of the submission runs: resource limits; as root without bubblewrap, new network, IPC,
UTS, mount and PID namespaces with a ``/proc`` of its own (where the kernel allows) and the switch to the
unprivileged uid the grader claimed; Landlock; a fresh session keyring and the system-call filter (``seccomp``);
then the imports of the dependencies (the probes package, numpy).  Only then does the worker say ready: a failure
up to that point is a fault of the installation, never of the submission.

    python -I -B worker.py zygote CONTROL_FD SLOT CONFIG_JSON

The warm process of a batch slot (see ``grader.sandbox.zygote``): it imports the dependencies and what the batch's
probes need (numpy, scipy, sympy, mujoco, the probes), never any submission, and on each request of the grader
forks one student's worker, which confines itself exactly as a fresh worker does (its own mount and IPC namespaces
with an empty ``/tmp`` and ``/dev/shm`` and only its submission at ``/submission`` under bubblewrap; limits; its
uid; Landlock; its keyring and system-call filter) before it says ready.  Nothing of an earlier student is in the
fork: the zygote never ran student code, and whatever a student started is killed before the next one is forked.
"""

from __future__ import annotations

import importlib
import importlib.util
import json
import os
import sys
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

try:
    from . import notebook, protocol, seccomp
except ImportError:  # run as a script from the runtime directory, next to protocol.py
    import notebook  # type: ignore[no-redef]
    import protocol  # type: ignore[no-redef]
    import seccomp  # type: ignore[no-redef]

PACKAGE = "submission"
RUNTIME = os.path.dirname(os.path.abspath(__file__))
#: the grader's own packages: never importable here (the sandbox hides their files as well)
BLOCKED = ("reference", "checks", "grader", "tests", "student_template", "tools")

_codec = None  # probes._codec, imported at start-up


# ---------------------------------------------------------------- replies


def _student_traceback(exc: BaseException) -> str:
    """The traceback restricted to frames of the submission."""
    root = os.environ.get("GRADER_SUBMISSION", "")
    frames = [f for f in traceback.extract_tb(exc.__traceback__) if root and f.filename.startswith(root)]
    lines = traceback.format_list(frames[-8:])
    lines += traceback.format_exception_only(type(exc), exc)
    text = "".join(lines)
    if root:
        text = text.replace(root + os.sep, "")
    return text[-4000:]


def _error(req_id, kind: str, exc: BaseException, text: str | None = None) -> dict:
    return {
        "id": req_id,
        "ok": False,
        "kind": kind,
        "type": type(exc).__name__,
        "message": (str(exc) if text is None else text)[:2000],
        "traceback": _student_traceback(exc),
    }


class ProbeLookupError(LookupError):
    """The requested probe does not exist (or is not marked as one): a fault of the grader's checks."""


def _raised_in_probes(exc: BaseException) -> bool:
    """True when the innermost frame of ``exc`` is the grader's probe code, not the submission's."""
    frames = traceback.extract_tb(exc.__traceback__)
    probes_dir = os.path.join(RUNTIME, "probes") + os.sep
    return bool(frames) and frames[-1].filename.startswith(probes_dir)


# ---------------------------------------------------------------- the submission and the probes


class _OwnModules:
    """Jupyter-style imports of the submission's own modules: ``import rotations`` or ``from rotations import R1``
    (as a notebook or a script run inside the work folder writes them) find ``submission.rotations``.  Asked only
    for names that no other finder knows (it comes last), never for the grader's own packages."""

    def __init__(self, root: str):
        self.root = root

    def internal(self, name: str) -> bool:
        top = name.partition(".")[0]
        return bool(top) and top.isidentifier() and top not in BLOCKED and top != PACKAGE and (
            os.path.isfile(os.path.join(self.root, top + ".py"))
            or os.path.isfile(os.path.join(self.root, top, "__init__.py")))

    def find_spec(self, fullname, path=None, target=None):
        if path is not None or "." in fullname or not self.internal(fullname):
            return None
        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec):
        return importlib.import_module(f"{PACKAGE}.{spec.name}")

    def exec_module(self, module):
        pass


def _import_submission(path: str):
    """Import the submission as the package ``submission``; returns it and what the report should say about its
    notebooks (the definitions of a notebook that raised)."""
    own = _OwnModules(path)
    if not any(isinstance(f, _OwnModules) for f in sys.meta_path):
        sys.meta_path.append(own)
    spec = importlib.util.spec_from_file_location(
        PACKAGE, os.path.join(path, "__init__.py"), submodule_search_locations=[path]
    )
    module = importlib.util.module_from_spec(spec)
    sys.modules[PACKAGE] = module
    spec.loader.exec_module(module)
    return module, _place_notebooks(path, own)


#: written by the loader next to the submission's modules (students cannot submit .json files)
NOTEBOOK_MANIFEST = "_notebooks.json"


def _place_notebooks(path: str, own: _OwnModules) -> list[str]:
    """Run the definitions of the submission's notebooks (each as a module of its own) and put each name into
    the template's modules the loader chose; a function or class of the template that a module had imported
    from another (``from .rotations import R1``) is replaced there too."""
    manifest = os.path.join(path, NOTEBOOK_MANIFEST)
    if not os.path.isfile(manifest):
        return []
    import types

    with open(manifest, encoding="utf-8") as handle:
        books = json.load(handle)["notebooks"]
    notes: list[str] = []
    replaced: dict[int, tuple[object, object]] = {}
    for book in books:
        file = str(book["file"])
        name = f"{PACKAGE}.{book['module']}"
        module = types.ModuleType(name, f"The definitions of the notebook {file}.")
        module.__package__ = PACKAGE
        module.__file__ = os.path.join(path, file)
        sys.modules[name] = module
        cells = [(int(number), str(code)) for number, code in book["cells"]]
        notes += [f"notebook {file}: {note}" for note in notebook.run_cells(
            cells, module.__dict__, set(book["defined"]), lambda n, f=file: os.path.join(path, f"{f}, cell {n}"),
            own.internal)]
        for defined, targets in book["placed"].items():
            if defined not in module.__dict__:
                notes.append(f"notebook {file}: {defined} is not defined after its cells ran (see above), so the "
                             "template's stays")
                continue
            value = module.__dict__[defined]
            for target in targets:
                target_module = importlib.import_module(f"{PACKAGE}.{target}")
                old = target_module.__dict__.get(defined)
                if isinstance(old, (types.FunctionType, type)) and old is not value:
                    replaced[id(old)] = (old, value)
                setattr(target_module, defined, value)
    for module_name, module in list(sys.modules.items()):
        if module is None or not (module_name == PACKAGE or module_name.startswith(PACKAGE + ".")):
            continue
        for key, value in list(vars(module).items()):
            entry = replaced.get(id(value))
            if entry is not None and entry[0] is value:
                setattr(module, key, entry[1])
    return notes


def _probe(name: str):
    module_name, _, func_name = str(name).rpartition(".")
    if not module_name or not func_name:
        raise ProbeLookupError(f"{name!r} does not name a probe (module.function)")
    try:
        probe_module = importlib.import_module(f"probes.{module_name}")
    except ImportError as exc:
        raise ProbeLookupError(f"the probe module probes.{module_name} cannot be imported: {exc}") from exc
    probe = getattr(probe_module, func_name, None)
    if probe is None or not getattr(probe, "is_probe", False):
        raise ProbeLookupError(f"probes.{module_name} has no probe {func_name!r}")
    return probe


def _handle(request: dict, package, submission: str):
    """The reply to ``request`` and the (possibly just imported) package."""
    req_id = request.get("id")
    phase = "import" if package is None else "call"
    op = request.get("op")
    try:
        if op == "import":
            package, notes = _import_submission(submission)
            reply = {"id": req_id, "ok": True, "value": {"notes": notes[:50]}}
        elif op == "call":
            try:
                probe = _probe(request.get("probe", ""))
                args = _codec.decode(request.get("args", []))
            except ProbeLookupError as exc:
                return _error(req_id, "probe", exc), package
            if package is None:
                package, _ = _import_submission(submission)
            phase = "call"
            value = probe(package, *args)
            try:
                reply = {"id": req_id, "ok": True, "value": _codec.encode(value)}
            except (TypeError, ValueError) as exc:
                reply = _error(req_id, "bad_value", exc)
        else:
            reply = _error(req_id, "probe", ValueError(f"unknown operation {op!r}"))
    except NotImplementedError as exc:
        reply = _error(req_id, "not_implemented", exc)
    except SystemExit as exc:
        reply = _error(req_id, "exit", exc)
    except ImportError as exc:
        # a probe importing a dependency the sandbox lacks is the installation's fault; the submission's own
        # imports are the student's
        kind = "probe" if _raised_in_probes(exc) else "exception"
        reply = _error(req_id, kind, exc)
    except BaseException as exc:  # noqa: BLE001 - every failure of student code is reported, not raised
        reply = _error(req_id, "exception", exc)
    reply["phase"] = phase
    return reply, package


def serve(request_fd: int, reply_fd: int, submission: str) -> int:
    package = None
    while True:
        request = protocol.read_message(request_fd)
        if request is None or request.get("op") == "exit":
            return 0
        reply, package = _handle(request, package, submission)
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        try:
            protocol.write_message(reply_fd, reply)
        except protocol.ProtocolError as exc:  # a value too large to send
            protocol.write_message(reply_fd, dict(_error(reply.get("id"), "bad_value", exc), phase=reply["phase"]))


# ---------------------------------------------------------------- confinement


def _libc():
    import ctypes

    return ctypes.CDLL(None, use_errno=True)


def _die_with_parent(libc) -> None:
    """Ask the kernel to kill this process when the grader that started it dies (Linux prctl)."""
    import signal

    PR_SET_PDEATHSIG = 1
    libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)


_CLONE_NEWNET, _CLONE_NEWUTS, _CLONE_NEWPID, _CLONE_NEWNS, _CLONE_NEWIPC = \
    0x40000000, 0x04000000, 0x20000000, 0x00020000, 0x08000000


def _unshare_network(libc) -> bool:
    """New network, IPC and UTS namespaces: no interface but a loopback of its own (needs root)."""
    return libc.unshare(_CLONE_NEWNET | _CLONE_NEWIPC | _CLONE_NEWUTS) == 0


def _own_namespaces(libc) -> dict:
    """As root, a plain process's own network, IPC, UTS, mount and PID namespaces: this process forks, and the
    child, the first process of the new PID namespace, goes on with a ``/proc`` of its own (it sees no process but
    its own and those it starts, which all end with it); the parent stays outside and only waits (``_stand_in``).
    Where the kernel refuses a PID and mount namespace (a container), the network, IPC and UTS namespaces alone."""
    if libc.unshare(_CLONE_NEWNET | _CLONE_NEWIPC | _CLONE_NEWUTS | _CLONE_NEWNS | _CLONE_NEWPID) != 0:
        return {"network_isolated": _unshare_network(libc), "pid_namespace": False}
    pid = os.fork()
    if pid != 0:
        _stand_in(pid)
    _die_with_parent(libc)
    _check(libc.mount(b"none", b"/", None, _MS_REC | _MS_PRIVATE, None), "private mounts")
    _check(libc.mount(b"proc", b"/proc", b"proc", _MS_NOSUID | _MS_NODEV | _MS_NOEXEC, None), "a /proc of its own")
    return {"network_isolated": True, "pid_namespace": True}


def _stand_in(pid: int) -> None:
    """The parent that the worker leaves outside its PID namespace: it keeps none of the worker's descriptors (the
    grader sees the worker's pipes close when the worker ends), waits for it, and ends as it ended: with its exit
    code, or killed by the same signal.  Killing it kills the worker (its parent-death signal)."""
    import resource
    import signal

    os.closerange(3, resource.getrlimit(resource.RLIMIT_NOFILE)[0])  # (its /proc is now the new namespace's)
    for number in (signal.SIGINT, signal.SIGTERM):
        signal.signal(number, signal.SIG_IGN)
    _, status = os.waitpid(pid, 0)
    if os.WIFSIGNALED(status):
        number = os.WTERMSIG(status)
        try:
            signal.signal(number, signal.SIG_DFL)
        except (OSError, ValueError):  # SIGKILL and SIGSTOP keep their default
            pass
        os.kill(os.getpid(), number)
        os._exit(128 + number)
    os._exit(os.waitstatus_to_exitcode(status))


def _apply_limits(limits: dict, uid: int | None) -> None:
    import resource
    import signal

    names = {
        "memory": resource.RLIMIT_AS,
        "cpu": resource.RLIMIT_CPU,
        "file_size": resource.RLIMIT_FSIZE,
        "processes": resource.RLIMIT_NPROC,
        "core": resource.RLIMIT_CORE,
    }
    for key, value in limits.items():
        if key in names and value is not None:
            if key == "processes" and uid is None:
                continue  # counted per user: only meaningful for a dedicated uid
            resource.setrlimit(names[key], (value, value))
    # Writes beyond the file-size limit fail with an OSError instead of killing the process.
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)


# Landlock (Linux 5.13+): the kernel restricts which files this process and its children may use, for any uid.
_FS_EXECUTE, _FS_WRITE_FILE, _FS_READ_FILE, _FS_READ_DIR = 1 << 0, 1 << 1, 1 << 2, 1 << 3
_FS_TRUNCATE, _FS_IOCTL_DEV = 1 << 14, 1 << 15
_FS_READ = _FS_EXECUTE | _FS_READ_FILE | _FS_READ_DIR
_FILE_RIGHTS = _FS_EXECUTE | _FS_WRITE_FILE | _FS_READ_FILE | _FS_TRUNCATE | _FS_IOCTL_DEV
_SYS_CREATE_RULESET, _SYS_ADD_RULE, _SYS_RESTRICT_SELF = 444, 445, 446
_PR_SET_NO_NEW_PRIVS = 38


def _readable_rules(roots: list[str], hidden: list[str]) -> list[tuple[str, int]]:
    """Read rights on ``roots``, except below the ``hidden`` paths: a root that holds a hidden path may be listed,
    and each of its entries is granted on its own (recursively where a hidden path lies deeper)."""
    rules: list[tuple[str, int]] = []
    hidden = [os.path.realpath(h) for h in hidden]
    seen: set[str] = set()

    def inside(path: str, base: str) -> bool:
        return path == base or path.startswith(base.rstrip("/") + "/")

    def grant(path: str) -> None:
        path = os.path.realpath(path)  # a rule holds for the inode: a symbolic link grants its target
        if path in seen or any(inside(path, h) for h in hidden):
            return
        seen.add(path)
        deeper = [h for h in hidden if inside(h, path) and h != path]
        if not deeper:
            rules.append((path, _FS_READ))
            return
        rules.append((path, _FS_READ_DIR))
        try:
            entries = sorted(os.listdir(path))
        except OSError:
            return
        for name in entries:
            grant(os.path.join(path, name))

    for root in roots:
        if os.path.exists(root):
            grant(root)
    return rules


def _landlock(rules: dict, libc) -> dict | None:
    """Restrict this process (and what it starts) to reading ``rules["read"]`` (minus ``rules["hidden"]``),
    writing ``rules["write"]`` and the ``rules["devices"]``; no TCP and no signals outside (where the kernel's
    Landlock knows these).  None where the kernel has no Landlock."""
    import ctypes

    syscall = libc.syscall
    syscall.restype = ctypes.c_long
    abi = syscall(ctypes.c_long(_SYS_CREATE_RULESET), None, ctypes.c_size_t(0), ctypes.c_uint32(1))
    if abi < 1:
        return None
    handled = (1 << 13) - 1 | (1 << 13 if abi >= 2 else 0) | (_FS_TRUNCATE if abi >= 3 else 0) | \
        (_FS_IOCTL_DEV if abi >= 5 else 0)

    class RulesetAttr(ctypes.Structure):
        _fields_ = [("fs", ctypes.c_uint64), ("net", ctypes.c_uint64), ("scoped", ctypes.c_uint64)]

    class PathBeneath(ctypes.Structure):
        _pack_ = 1
        _fields_ = [("allowed", ctypes.c_uint64), ("parent_fd", ctypes.c_int32)]

    attr = RulesetAttr(handled, 0b11 if abi >= 4 else 0, 0b11 if abi >= 6 else 0)
    size = 8 if abi < 4 else 16 if abi < 6 else 24
    ruleset = syscall(ctypes.c_long(_SYS_CREATE_RULESET), ctypes.byref(attr), ctypes.c_size_t(size),
                      ctypes.c_uint32(0))
    if ruleset < 0:
        raise OSError(ctypes.get_errno(), "landlock_create_ruleset failed")
    try:
        grants = _readable_rules(rules.get("read", []), rules.get("hidden", []))
        grants += [(path, handled) for path in rules.get("write", [])]
        grants += [(path, _FS_READ_FILE | _FS_WRITE_FILE) for path in rules.get("devices", [])]
        for path, access in grants:
            try:
                fd = os.open(path, os.O_PATH | os.O_CLOEXEC)
            except OSError:
                continue
            try:
                if not os.path.isdir(path):
                    access &= _FILE_RIGHTS
                rule = PathBeneath(access & handled, fd)
                if syscall(ctypes.c_long(_SYS_ADD_RULE), ctypes.c_int(ruleset), ctypes.c_int(1), ctypes.byref(rule),
                           ctypes.c_uint32(0)) != 0:
                    raise OSError(ctypes.get_errno(), f"landlock_add_rule failed for {path}")
            finally:
                os.close(fd)
        if libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
            raise OSError(ctypes.get_errno(), "PR_SET_NO_NEW_PRIVS failed")
        if syscall(ctypes.c_long(_SYS_RESTRICT_SELF), ctypes.c_int(ruleset), ctypes.c_uint32(0)) != 0:
            raise OSError(ctypes.get_errno(), "landlock_restrict_self failed")
    finally:
        os.close(ruleset)
    return {"abi": abi, "files": True, "tcp": abi >= 4, "signals": abi >= 6}


def _drop_privileges(uid: int) -> None:
    os.setgroups([])
    os.setgid(uid)
    os.setuid(uid)
    if os.geteuid() != uid or os.getuid() != uid:
        raise OSError(f"could not switch to uid {uid}")
    try:
        os.setuid(0)
    except PermissionError:
        return
    raise OSError("root privileges could be regained after dropping them")


def confine(config: dict) -> dict:
    """Everything that happens before the submission is imported; returns facts for the grader's report."""
    info: dict = {"python": sys.executable, "version": sys.version.split()[0]}
    uid = config.get("uid")
    _apply_limits(config.get("limits", {}), uid)
    libc = _libc()
    _die_with_parent(libc)
    if config.get("own_namespaces") and os.geteuid() == 0:
        info.update(_own_namespaces(libc))
    if uid is not None and os.geteuid() == 0:
        _drop_privileges(uid)
    elif os.geteuid() == 0:
        raise OSError("the worker runs as root and was given no uid to switch to")
    info["uid"] = os.getuid()
    if config.get("landlock"):
        info["landlock"] = _landlock(config["landlock"], libc)
    # last, once nothing more needs these calls: a keyring of its own, then the system-call filter
    info["keyring"] = seccomp.join_fresh_session_keyring(libc)
    info["syscalls"] = seccomp.install(libc)
    return info


def _import_dependencies(required: list[str]) -> None:
    """Import what the probes need, so that a missing dependency shows now and not as the student's error."""
    global _codec
    importlib.import_module("probes")
    _codec = importlib.import_module("probes._codec")
    numpy = importlib.import_module("numpy")
    if getattr(numpy, "__file__", None) is None:  # an empty folder of that name: not numpy
        raise ModuleNotFoundError("No module named 'numpy' (only an empty folder of that name)", name="numpy")
    missing = [name for name in required if getattr(importlib.util.find_spec(name), "origin", None) is None]
    if missing:
        raise ModuleNotFoundError(f"No module named {missing[0]!r} (missing: {', '.join(missing)})", name=missing[0])


# ---------------------------------------------------------------- the warm process of a slot

#: the mount point of the slot's staging folder inside the zygote's sandbox (bubblewrap)
SLOT = "/slot"
#: seconds the zygote spends killing what a student left before it gives up
SWEEP_SECONDS = 10.0
_MS_RDONLY, _MS_NOSUID, _MS_NODEV, _MS_NOEXEC, _MS_REMOUNT, _MS_BIND, _MS_REC, _MS_PRIVATE = \
    1, 2, 4, 8, 32, 4096, 16384, 1 << 18
_PR_SET_DUMPABLE, _PR_CAP_AMBIENT, _PR_CAP_AMBIENT_CLEAR_ALL, _PR_SET_CHILD_SUBREAPER = 4, 47, 4, 36


def _check(result: int, what: str) -> None:
    if result != 0:
        import ctypes

        errno = ctypes.get_errno()
        raise OSError(errno, f"{what}: {os.strerror(errno)}")


def _mount_points() -> set[str]:
    points = set()
    with open("/proc/self/mountinfo", encoding="utf-8", errors="surrogateescape") as handle:
        for line in handle:
            fields = line.split()
            if len(fields) > 4:
                points.add(fields[4].replace("\\040", " ").replace("\\011", "\t").replace("\\012", "\n"))
    return points


def _wipe(root: str) -> None:
    """Remove everything in ``root`` but the mount points below it and the folders that lead to them (a Python
    runtime under /tmp is bound there by bubblewrap)."""
    import shutil
    import stat

    points = {p for p in _mount_points() if p.startswith(root.rstrip("/") + "/")}
    keep = set(points)
    for point in points:
        parent = os.path.dirname(point)
        while parent.startswith(root.rstrip("/") + "/"):
            keep.add(parent)
            parent = os.path.dirname(parent)

    def writable(function, path, _):
        try:  # a folder its owner closed (chmod 000): open it again, then retry
            os.chmod(os.path.dirname(path), 0o700)
            os.chmod(path, 0o700)
            function(path)
        except OSError:
            pass

    try:
        entries = list(os.scandir(root))
    except OSError:
        return
    for entry in entries:
        if entry.path in points:
            continue
        if entry.path in keep:
            _wipe(entry.path)
            continue
        try:
            if stat.S_ISDIR(entry.stat(follow_symlinks=False).st_mode):
                shutil.rmtree(entry.path, onerror=writable)
            else:
                os.unlink(entry.path)
        except OSError:
            pass


def _own_mounts(libc, submission: str) -> None:
    """In a mount and an IPC namespace of this process's own: the student's package (inside the slot's staging
    folder) read-only at /submission, the staging folder itself covered by an empty read-only tmpfs, no IPC
    object of anyone else.  (/tmp and /dev/shm are the slot's, emptied by the zygote after every student: a fresh
    tmpfs over /tmp would hide a Python runtime that bubblewrap bound below it.)"""
    _check(libc.unshare(_CLONE_NEWNS | _CLONE_NEWIPC), "unshare")
    _check(libc.mount(b"none", b"/", None, _MS_REC | _MS_PRIVATE, None), "private mounts")
    _check(libc.mount(submission.encode(), b"/submission", None, _MS_BIND | _MS_REC, None), "bind the submission")
    _check(libc.mount(b"none", b"/submission", None, _MS_REMOUNT | _MS_BIND | _MS_RDONLY | _MS_NOSUID | _MS_NODEV,
                      None), "read-only submission")
    # Covered rather than unmounted: in the user namespace of an unprivileged zygote, the mounts that bubblewrap
    # made are locked together and cannot be taken apart, but may be covered (and nothing can uncover them).
    _check(libc.mount(b"tmpfs", SLOT.encode(), b"tmpfs", _MS_RDONLY | _MS_NOSUID | _MS_NODEV, b"mode=0,size=4k"),
           "hide the staging folder")


def _drop_capabilities(libc) -> None:
    """No capability left (a zygote in a user namespace of its own keeps CAP_SYS_ADMIN for the mounts above), and
    none to be gained by executing anything."""
    import ctypes

    class Header(ctypes.Structure):
        _fields_ = [("version", ctypes.c_uint32), ("pid", ctypes.c_int)]

    class Data(ctypes.Structure):
        _fields_ = [("effective", ctypes.c_uint32), ("permitted", ctypes.c_uint32), ("inheritable", ctypes.c_uint32)]

    libc.prctl(_PR_CAP_AMBIENT, _PR_CAP_AMBIENT_CLEAR_ALL, 0, 0, 0)
    data = (Data * 2)()
    _check(libc.capset(ctypes.byref(Header(0x20080522, 0)), data), "capset")
    _check(libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0), "no new privileges")


def _close_other_fds(keep: set[int]) -> None:
    for name in os.listdir("/proc/self/fd"):
        fd = int(name)
        if fd not in keep:
            try:
                os.close(fd)
            except OSError:
                pass


def _forked(request_fd: int, reply_fd: int, out_fd: int, err_fd: int, config: dict) -> int:
    """One student's worker, in the child of a fork of the zygote: confine, forget the zygote, say ready, serve."""
    import signal

    started = False
    try:
        os.setsid()
        devnull = os.open("/dev/null", os.O_RDONLY)
        for source, target in ((devnull, 0), (out_fd, 1), (err_fd, 2)):
            os.dup2(source, target)
        _close_other_fds({0, 1, 2, request_fd, reply_fd})
        for number in (signal.SIGINT, signal.SIGTERM, signal.SIGCHLD, signal.SIGPIPE):
            signal.signal(number, signal.SIG_DFL if number != signal.SIGPIPE else signal.SIG_IGN)
        libc = _libc()
        submission = config["submission"]
        if config.get("bind"):
            _own_mounts(libc, config["bind"])
        if os.geteuid() != 0:
            _drop_capabilities(libc)
        info = confine(config)
        if config.get("uid") is None:  # as a fresh worker of the grader's own uid is (the zygote is not)
            libc.prctl(_PR_SET_DUMPABLE, 1, 0, 0, 0)
        info["warm"] = True
        numpy = sys.modules.get("numpy")
        if numpy is not None:  # the zygote's global random state is every fork's: a fresh child draws its own
            numpy.random.seed()
        os.environ.clear()
        os.environ.update(config.get("env", {}))
        os.environ["GRADER_SUBMISSION"] = submission
        os.chdir(config.get("cwd", "/"))
        sys.argv = [os.path.join(RUNTIME, "worker.py"), str(request_fd), str(reply_fd), submission, json.dumps(config)]
        protocol.write_message(reply_fd, {"id": 0, "ok": True, "op": "ready", "info": info})
        started = True
        return serve(request_fd, reply_fd, submission)
    except BaseException as exc:  # noqa: BLE001 - before ready: a fault of the set-up; after: the student's end
        if not started:
            try:
                protocol.write_message(reply_fd, _error(0, "setup", exc, f"{type(exc).__name__}: {exc}"))
            except BaseException:  # noqa: BLE001
                pass
            return 70
        return 1


def _preload(names: list[str]) -> list[str]:
    """Import what the batch's probes and submissions will need; the names that could not be imported."""
    missing = []
    for name in names:
        try:
            importlib.import_module(name)
        except Exception:  # noqa: BLE001 - imported again (and reported) where it is needed, if ever
            missing.append(name)
    return missing


def _others(keep: set[int]) -> list[int]:
    """The live processes of this pid namespace other than ``keep``."""
    found = []
    for name in os.listdir("/proc"):
        if not name.isdigit() or int(name) in keep:
            continue
        try:
            with open(f"/proc/{name}/stat", encoding="ascii", errors="replace") as handle:
                state = handle.read().rsplit(")", 1)[1].split()[0]
        except (OSError, IndexError):
            continue
        if state not in ("Z", "X"):
            found.append(int(name))
    return found


class _Zygote:
    """The zygote's state: the control socket and the forked students' workers (pid -> fork id, pidfd)."""

    def __init__(self, control, config: dict):
        self.control = control
        self.config = config
        self.children: dict[int, tuple[int, int]] = {}

    def send(self, message: dict, fds: list[int] = ()) -> None:
        import socket

        socket.send_fds(self.control, [json.dumps(message).encode()], list(fds))

    def fork(self, message: dict, fds: list[int]) -> None:
        request_fd, reply_fd, out_fd, err_fd = fds
        for stream in (sys.stdout, sys.stderr):
            stream.flush()
        pid = os.fork()
        if pid == 0:
            code = 70
            try:
                self.control.close()
                for _, pidfd in self.children.values():
                    os.close(pidfd)
                code = _forked(request_fd, reply_fd, out_fd, err_fd, message["config"])
            finally:
                for stream in (sys.stdout, sys.stderr):
                    try:
                        stream.flush()
                    except BaseException:  # noqa: BLE001
                        pass
                os._exit(code)
        for fd in fds:
            os.close(fd)
        pidfd = os.pidfd_open(pid)
        self.children[pid] = (message["id"], pidfd)
        self.send({"op": "forked", "id": message["id"], "pid": pid}, [pidfd])

    def reap(self) -> None:
        """Collect every ended child: the forked workers (their exit codes go to the grader) and, as the subreaper
        of its plain-process workers, whatever they left that ended."""
        while True:
            try:
                pid, status = os.waitpid(-1, os.WNOHANG)
            except ChildProcessError:
                return
            if pid == 0:
                return
            if pid in self.children:
                fork_id, pidfd = self.children.pop(pid)
                os.close(pidfd)
                self.send({"op": "exited", "id": fork_id, "code": os.waitstatus_to_exitcode(status)})

    def _descendants(self) -> list[int]:
        """The live processes below this one (all of them: as subreaper, this process inherits every orphan)."""
        parents: dict[int, list[int]] = {}
        for name in os.listdir("/proc"):
            if not name.isdigit():
                continue
            try:
                with open(f"/proc/{name}/stat", encoding="ascii", errors="replace") as handle:
                    fields = handle.read().rsplit(")", 1)[1].split()
            except (OSError, IndexError):
                continue
            if fields[0] not in ("Z", "X"):
                parents.setdefault(int(fields[1]), []).append(int(name))
        found, todo = [], [os.getpid()]
        while todo:
            children = parents.get(todo.pop(), [])
            found += children
            todo += children
        return found

    def sweep(self) -> int:
        """Kill what the students left: in a pid namespace of the slot's own (bubblewrap), every process but this
        one and the namespace's init; otherwise every process below this one (orphans come back to it: it is
        their subreaper).  Returns how many processes were left when it gave up (0: all gone)."""
        import signal
        import time

        keep = {1, os.getpid()}
        deadline = time.monotonic() + SWEEP_SECONDS
        pause = 0.001
        while True:
            left = _others(keep) if self.config.get("pid_namespace") else self._descendants()
            if left and self.config.get("pid_namespace"):
                try:
                    os.kill(-1, signal.SIGKILL)  # every process of this namespace but this one and its init
                except ProcessLookupError:
                    pass
            else:
                for pid in left:
                    try:
                        os.kill(pid, signal.SIGKILL)
                    except (ProcessLookupError, PermissionError):
                        pass
            self.reap()
            if not left or time.monotonic() > deadline:
                if self.children:  # a forked worker that is gone without a word cannot stay pending
                    time.sleep(0.01)
                    self.reap()
                if not left and self.config.get("pid_namespace"):  # the slot's own /tmp and /dev/shm
                    for folder in ("/tmp", "/dev/shm"):
                        _wipe(folder)
                return len(left)
            time.sleep(pause)
            pause = min(0.05, pause * 2)

    def serve(self) -> int:
        import select
        import socket

        while True:
            pidfds = {pidfd: pid for pid, (_, pidfd) in self.children.items()}
            ready, _, _ = select.select([self.control, *pidfds], [], [])
            if any(fd in pidfds for fd in ready):
                self.reap()
            if self.control not in ready:
                continue
            data, fds, _, _ = socket.recv_fds(self.control, 1 << 16, 8)
            if not data:  # the grader is gone
                self.sweep()
                return 0
            message = json.loads(data)
            op = message.get("op")
            if op == "fork" and len(fds) == 4:
                self.fork(message, fds)
            elif op == "sweep":
                left = self.sweep()
                self.send({"op": "swept", "id": message.get("id"), "left": left})
            elif op == "exit":
                self.sweep()
                return 0
            else:
                for fd in fds:
                    os.close(fd)
                self.send({"op": "error", "id": message.get("id"), "message": f"unknown request {op!r}"})


def zygote(control_fd: int, slot: str, config: dict) -> int:
    """The warm process of a slot: import what the students' workers need, then fork one per request."""
    import socket
    import threading

    control = socket.socket(fileno=control_fd)
    sys.stdin.close()
    state = _Zygote(control, config)
    try:
        libc = _libc()
        _die_with_parent(libc)
        libc.prctl(_PR_SET_DUMPABLE, 0, 0, 0, 0)  # no process of the same uid may read or write its memory
        if not config.get("pid_namespace"):  # what its workers leave comes back to it when orphaned
            libc.prctl(_PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
        _import_dependencies(config.get("require", []))
        missing = _preload(config.get("preload", []))
        threads = len(os.listdir("/proc/self/task"))
        if threads != 1 or threading.active_count() != 1:
            raise RuntimeError(f"the warm process runs {threads} threads after its imports: it cannot fork safely")
    except BaseException as exc:  # noqa: BLE001 - reported to the grader as a fault of the set-up
        reply = _error(0, "setup", exc, f"{type(exc).__name__}: {exc}")
        reply["missing"] = getattr(exc, "name", None) if isinstance(exc, ImportError) else None
        state.send(reply)
        return 70
    sys.meta_path.insert(0, _BlockTrustedPackages())
    for name in [m for m in sys.modules if m.split(".")[0] in BLOCKED]:
        del sys.modules[name]
    sys.setrecursionlimit(3000)
    state.send({"id": 0, "ok": True, "op": "ready",
                "info": {"python": sys.executable, "version": sys.version.split()[0], "uid": os.getuid(),
                         "preloaded": [n for n in config.get("preload", []) if n not in missing]}})
    return state.serve()


class _BlockTrustedPackages:
    """Refuses imports of the grader's trusted packages."""

    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in BLOCKED:
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        return None


def main(argv: list[str]) -> int:
    if argv[1:2] == ["zygote"]:
        return zygote(int(argv[2]), argv[3], json.loads(argv[4]))
    request_fd, reply_fd = int(argv[1]), int(argv[2])
    submission = argv[3]
    config = json.loads(argv[4]) if len(argv) > 4 else {}
    sys.stdin.close()
    try:
        info = confine(config)
        _import_dependencies(config.get("require", []))
    except BaseException as exc:  # noqa: BLE001 - reported to the grader as a fault of the set-up
        reply = _error(0, "setup", exc, f"{type(exc).__name__}: {exc}")
        reply["missing"] = getattr(exc, "name", None) if isinstance(exc, ImportError) else None
        protocol.write_message(reply_fd, reply)
        return 70
    sys.meta_path.insert(0, _BlockTrustedPackages())
    for name in [m for m in sys.modules if m.split(".")[0] in BLOCKED]:
        del sys.modules[name]
    os.environ["GRADER_SUBMISSION"] = submission
    sys.setrecursionlimit(3000)
    protocol.write_message(reply_fd, {"id": 0, "ok": True, "op": "ready", "info": info})
    return serve(request_fd, reply_fd, submission)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
