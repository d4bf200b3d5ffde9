"""The fork server: the warm process of a batch slot (the grader's handle on it is ``grader.sandbox.zygote``).

    python -I -B forkserver.py CONTROL_FD SLOT CONFIG_JSON

It imports the dependencies and what the batch's probes need (numpy, scipy, sympy, mujoco, the probes), never any
submission, and on each request of the grader forks one student's worker, which confines itself exactly as a fresh
worker does (its own mount and IPC namespaces with an empty ``/tmp`` and ``/dev/shm`` and only its submission at
``/submission`` under bubblewrap; limits; its uid; Landlock; its keyring and system-call filter) before it says
ready and serves with ``worker.serve``.  Nothing of an earlier student is in the fork: the fork server never ran
student code, and whatever a student started is killed before the next one is forked.

Standard library only, plus ``worker.py``, ``confinement.py`` and ``protocol.py``, which the grader copies next to it.
"""

from __future__ import annotations

import importlib
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

try:
    from . import confinement, protocol, worker
except ImportError:  # run as a script from the runtime directory, next to worker.py
    import confinement  # type: ignore[no-redef]
    import protocol  # type: ignore[no-redef]
    import worker  # type: ignore[no-redef]

#: the mount point of the slot's staging folder inside the fork server's sandbox (bubblewrap)
SLOT = "/slot"
#: seconds the fork server spends killing what a student left before it gives up
SWEEP_SECONDS = 10.0


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



def _close_other_fds(keep: set[int]) -> None:
    for name in os.listdir("/proc/self/fd"):
        fd = int(name)
        if fd not in keep:
            try:
                os.close(fd)
            except OSError:
                pass


def _forked(request_fd: int, reply_fd: int, out_fd: int, err_fd: int, config: dict) -> int:
    """One student's worker, in the child of a fork of the fork server: confine, forget the fork server, say ready,
    serve."""
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
        libc = confinement.load_libc()
        submission = config["submission"]
        if config.get("bind"):
            confinement.own_mounts(libc, config["bind"], SLOT)
        if os.geteuid() != 0:
            confinement.drop_capabilities(libc)
        info = confinement.confine(config)
        if config.get("uid") is None:  # as a fresh worker of the grader's own uid is (the fork server is not)
            libc.prctl(confinement.PR_SET_DUMPABLE, 1, 0, 0, 0)
        info["warm"] = True
        numpy = sys.modules.get("numpy")
        if numpy is not None:  # the fork server's global random state is every fork's: a fresh child draws its own
            numpy.random.seed()
        os.environ.clear()
        os.environ.update(config.get("env", {}))
        os.environ["GRADER_SUBMISSION"] = submission
        os.chdir(config.get("cwd", "/"))
        sys.argv = [os.path.join(worker.RUNTIME, "worker.py"), str(request_fd), str(reply_fd), submission,
                    json.dumps(config)]
        protocol.write_message(reply_fd, {"id": 0, "ok": True, "op": "ready", "info": info})
        started = True
        return worker.serve(request_fd, reply_fd, submission)
    except BaseException as exc:  # noqa: BLE001 - before ready: a fault of the set-up; after: the student's end
        if not started:
            try:
                protocol.write_message(reply_fd, worker.error_reply(0, "setup", exc, f"{type(exc).__name__}: {exc}"))
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


class ForkServer:
    """The fork server's state: the control socket and the forked students' workers (pid -> fork id, pidfd)."""

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


def main(argv: list[str]) -> int:
    """The warm process of a slot (``forkserver.py CONTROL_FD SLOT CONFIG_JSON``): import what the students'
    workers need, then fork one per request."""
    import socket
    import threading

    control_fd, config = int(argv[1]), json.loads(argv[3])
    control = socket.socket(fileno=control_fd)
    sys.stdin.close()
    state = ForkServer(control, config)
    try:
        libc = confinement.load_libc()
        confinement.die_with_parent(libc)
        libc.prctl(confinement.PR_SET_DUMPABLE, 0, 0, 0, 0)  # no process of the same uid may read or write its memory
        if not config.get("pid_namespace"):  # what its workers leave comes back to it when orphaned
            libc.prctl(confinement.PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
        worker.import_dependencies(config.get("require", []))
        missing = _preload(config.get("preload", []))
        threads = len(os.listdir("/proc/self/task"))
        if threads != 1 or threading.active_count() != 1:
            raise RuntimeError(f"the warm process runs {threads} threads after its imports: it cannot fork safely")
    except BaseException as exc:  # noqa: BLE001 - reported to the grader as a fault of the set-up
        state.send(worker.setup_fault(exc))
        return 70
    worker.seal()
    state.send({"id": 0, "ok": True, "op": "ready",
                "info": {"python": sys.executable, "version": sys.version.split()[0], "uid": os.getuid(),
                         "preloaded": [n for n in config.get("preload", []) if n not in missing]}})
    return state.serve()


if __name__ == "__main__":
    sys.exit(main(sys.argv))
