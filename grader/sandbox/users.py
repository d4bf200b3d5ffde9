"""The unprivileged uids that children run under when the grader runs as root.

Every child gets a uid that no other child uses at the same time, in this grader process or in any other: the
uid is claimed by an exclusive ``flock`` on a lock file in a directory only root can write, and the kernel
releases the claim when the grader exits, however it exits.  After every grading the uid is swept: every
process still running under it is killed (a short forked helper switches to the uid and signals every process
that uid may signal), and the files it left in the world-writable directories are removed.  A uid is swept when
it is claimed as well, in case a grader died before it could sweep.
"""

from __future__ import annotations

import os
import shutil
import signal
import stat
import time
from dataclasses import dataclass

from ..errors import SandboxError

__all__ = ["BASE_UID", "UID_COUNT", "SCRATCH_DIRS", "UidClaim", "claim_uid", "sweep", "processes_of",
           "kill_processes", "remove_files"]

#: the uids of children: BASE_UID, BASE_UID + 1, ... (below 65534, "nobody"); above 61000 + the parallel slots
#: of earlier versions, which used fixed uids without claiming them
BASE_UID = 62000
UID_COUNT = 3000
#: directories every user may write to: swept after every grading
SCRATCH_DIRS = ("/tmp", "/var/tmp", "/dev/shm")
#: root-only directories for the lock files, the first that can be used
LOCK_DIRS = ("/run/mbd-autograder", "/tmp/.mbd-autograder-uids")


@dataclass
class UidClaim:
    """A claimed uid; held until ``release``."""

    uid: int
    fd: int
    sweeps: bool = True  # whether processes and files may be left behind (plain-process mode)

    def release(self) -> None:
        if self.fd >= 0:
            os.close(self.fd)  # drops the flock
            self.fd = -1


def _lock_dir() -> str:
    for path in LOCK_DIRS:
        try:
            os.makedirs(path, mode=0o700, exist_ok=True)
            info = os.lstat(path)
        except OSError:
            continue
        if stat.S_ISDIR(info.st_mode) and info.st_uid == 0 and not info.st_mode & 0o077:
            return path
    raise SandboxError(f"no directory for the uid locks: one of {', '.join(LOCK_DIRS)} must be a directory "
                       "of root with mode 0700")


def _account_exists(uid: int) -> bool:
    import pwd  # POSIX only: imported where a uid is claimed (as root), never on a student's laptop

    try:
        pwd.getpwuid(uid)
    except KeyError:
        return False
    return True


#: where this process looks for a free uid next: consecutive children (the students of one batch slot) get
#: different uids, so that nothing a student might have left under its uid could ever meet the next student
_next_offset = 0


def claim_uid(sweeps: bool = True) -> UidClaim:
    """A uid for one child, unused by every other child and by every account of the system."""
    global _next_offset
    import fcntl  # POSIX only, as pwd above

    directory = _lock_dir()
    for offset in range(UID_COUNT):
        uid = BASE_UID + (_next_offset + offset) % UID_COUNT
        if _account_exists(uid):
            continue
        fd = os.open(os.path.join(directory, f"uid-{uid}.lock"), os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW | os.O_CLOEXEC,
                     0o600)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            continue
        claim = UidClaim(uid, fd, sweeps)
        _next_offset = (uid - BASE_UID + 1) % UID_COUNT
        try:
            sweep(uid, files=sweeps)
        except BaseException:
            claim.release()
            raise
        return claim
    raise SandboxError(f"all {UID_COUNT} uids from {BASE_UID} are in use by other children")


# ------------------------------------------------------------------------------------------ sweeping


def processes_of(uid: int) -> list[int]:
    """The processes (zombies excepted) whose real, effective or saved uid is ``uid``."""
    found = []
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open(f"/proc/{name}/status", encoding="ascii", errors="replace") as handle:
                status = handle.read()
        except OSError:
            continue
        fields = dict(line.split(":", 1) for line in status.splitlines() if ":" in line)
        uids = fields.get("Uid", "").split()
        if str(uid) in uids[:3] and not fields.get("State", "").strip().startswith(("Z", "X")):
            found.append(int(name))
    return found


def _kill_as(uid: int) -> None:
    """Fork a helper that becomes ``uid`` and sends SIGKILL to every process that uid may signal."""
    pid = os.fork()
    if pid == 0:  # pragma: no cover - the helper
        code = 1
        try:
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
            for _ in range(64):
                os.kill(-1, signal.SIGKILL)
        except ProcessLookupError:
            code = 0
        except BaseException:  # noqa: BLE001
            code = 2
        os._exit(code)
    os.waitpid(pid, 0)


def kill_processes(uid: int, seconds: float = 10.0) -> None:
    """Kill every process of ``uid`` (forks and daemons included); raise when some survive ``seconds``."""
    deadline = time.monotonic() + seconds
    pause = 0.002
    while processes_of(uid):
        if time.monotonic() > deadline:
            raise SandboxError(f"processes of uid {uid} survive SIGKILL: {processes_of(uid)}")
        _kill_as(uid)
        time.sleep(pause)
        pause = min(0.1, pause * 2)


def _remove(path: str, info: os.stat_result) -> None:
    try:
        if stat.S_ISDIR(info.st_mode):
            shutil.rmtree(path, ignore_errors=True)
        else:
            os.unlink(path)
    except OSError:
        pass


def remove_files(uid: int, roots=SCRATCH_DIRS, depth: int = 6) -> None:
    """Remove what ``uid`` owns in ``roots``, descending only where it could have written (directories open to
    every user, as /tmp itself)."""
    for root in roots:
        _sweep_dir(root, uid, depth)


def _sweep_dir(directory: str, uid: int, depth: int) -> None:
    try:
        entries = list(os.scandir(directory))
    except OSError:
        return
    for entry in entries:
        try:
            info = entry.stat(follow_symlinks=False)
        except OSError:
            continue
        if info.st_uid == uid:
            _remove(entry.path, info)
        elif stat.S_ISDIR(info.st_mode) and info.st_mode & stat.S_IWOTH and depth > 0:
            _sweep_dir(entry.path, uid, depth - 1)


def sweep(uid: int, files: bool = True) -> None:
    """Kill every process of ``uid``; with ``files``, remove what it left in the scratch directories."""
    kill_processes(uid)
    if files:
        remove_files(uid)
