"""The confinement of a worker, before any code of a submission runs: resource limits, namespaces, the switch to an
unprivileged uid, Landlock, and last the session keyring and the system-call filter (``seccomp``).

Standard library only: it runs inside the sandbox, copied next to ``worker.py``.  A fresh worker confines itself
(``confine``, from ``worker.main``); a worker forked from a batch slot's warm process confines itself in the fork
(``forkserver``), with the same ``confine`` after the mounts and capabilities that only a fork needs
(``own_mounts``, ``drop_capabilities``).  Every system call goes through ``ctypes``, imported where it is used, so
that the portable mode's worker, which imports ``worker.py`` on platforms without these calls, never needs them.
"""

from __future__ import annotations

import os
import sys

try:
    from . import seccomp
except ImportError:  # run as a script from the runtime directory, next to seccomp.py
    import seccomp  # type: ignore[no-redef]

__all__ = ["confine", "load_libc", "die_with_parent", "check_result", "own_mounts", "drop_capabilities",
           "PR_SET_DUMPABLE", "PR_SET_CHILD_SUBREAPER"]


def load_libc():
    import ctypes

    return ctypes.CDLL(None, use_errno=True)


def die_with_parent(libc) -> None:
    """Ask the kernel to kill this process when the grader that started it dies (Linux prctl)."""
    import signal

    PR_SET_PDEATHSIG = 1
    libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)


_CLONE_NEWNET, _CLONE_NEWUTS, _CLONE_NEWPID, _CLONE_NEWNS, _CLONE_NEWIPC = \
    0x40000000, 0x04000000, 0x20000000, 0x00020000, 0x08000000
_MS_RDONLY, _MS_NOSUID, _MS_NODEV, _MS_NOEXEC, _MS_REMOUNT, _MS_BIND, _MS_REC, _MS_PRIVATE = \
    1, 2, 4, 8, 32, 4096, 16384, 1 << 18
PR_SET_DUMPABLE, _PR_CAP_AMBIENT, _PR_CAP_AMBIENT_CLEAR_ALL, PR_SET_CHILD_SUBREAPER = 4, 47, 4, 36


def check_result(result: int, what: str) -> None:
    """Raise ``OSError`` with the system's message for a call of libc that returned ``result`` != 0."""
    if result != 0:
        import ctypes

        errno = ctypes.get_errno()
        raise OSError(errno, f"{what}: {os.strerror(errno)}")


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
    die_with_parent(libc)
    check_result(libc.mount(b"none", b"/", None, _MS_REC | _MS_PRIVATE, None), "private mounts")
    check_result(libc.mount(b"proc", b"/proc", b"proc", _MS_NOSUID | _MS_NODEV | _MS_NOEXEC, None),
                 "a /proc of its own")
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
    libc = load_libc()
    die_with_parent(libc)
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


# ---------------------------------------------------------------- what only a forked worker needs


def own_mounts(libc, submission: str, slot: str) -> None:
    """In a mount and an IPC namespace of this process's own: the student's package (inside the slot's staging
    folder, mounted at ``slot``) read-only at /submission, the staging folder itself covered by an empty read-only
    tmpfs, no IPC object of anyone else.  (/tmp and /dev/shm are the slot's, emptied by the fork server after every
    student: a fresh tmpfs over /tmp would hide a Python runtime that bubblewrap bound below it.)"""
    check_result(libc.unshare(_CLONE_NEWNS | _CLONE_NEWIPC), "unshare")
    check_result(libc.mount(b"none", b"/", None, _MS_REC | _MS_PRIVATE, None), "private mounts")
    check_result(libc.mount(submission.encode(), b"/submission", None, _MS_BIND | _MS_REC, None),
                 "bind the submission")
    check_result(libc.mount(b"none", b"/submission", None,
                            _MS_REMOUNT | _MS_BIND | _MS_RDONLY | _MS_NOSUID | _MS_NODEV, None),
                 "read-only submission")
    # Covered rather than unmounted: in the user namespace of an unprivileged fork server, the mounts that
    # bubblewrap made are locked together and cannot be taken apart, but may be covered (and nothing can uncover
    # them).
    check_result(libc.mount(b"tmpfs", slot.encode(), b"tmpfs", _MS_RDONLY | _MS_NOSUID | _MS_NODEV,
                            b"mode=0,size=4k"), "hide the staging folder")


def drop_capabilities(libc) -> None:
    """No capability left (a fork server in a user namespace of its own keeps CAP_SYS_ADMIN for the mounts above),
    and none to be gained by executing anything."""
    import ctypes

    class Header(ctypes.Structure):
        _fields_ = [("version", ctypes.c_uint32), ("pid", ctypes.c_int)]

    class Data(ctypes.Structure):
        _fields_ = [("effective", ctypes.c_uint32), ("permitted", ctypes.c_uint32), ("inheritable", ctypes.c_uint32)]

    libc.prctl(_PR_CAP_AMBIENT, _PR_CAP_AMBIENT_CLEAR_ALL, 0, 0, 0)
    data = (Data * 2)()
    check_result(libc.capset(ctypes.byref(Header(0x20080522, 0)), data), "capset")
    check_result(libc.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0), "no new privileges")

