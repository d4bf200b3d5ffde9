"""The child side of the portable mode (see ``grader.sandbox.portable``): the worker of ``worker.py`` (its serving
loop and dispatch, the same probes), started on any platform with nothing of the confinement that needs Linux.

    python -I -B portable_worker.py CONFIG_JSON

Requests arrive on standard input and replies leave on standard output; before anything else the worker moves
both pipes to descriptors of their own and points standard input at the null device and standard output at the
file ``config["output"]``, so that what the student's code prints (from Python, C or a program it starts) can
never be taken for a reply.  Limits of ``resource`` are applied where the platform has that module.  Standard
library only, plus ``worker.py``, ``protocol.py`` and what ``worker.py`` imports (its confinement is never
called here), which the grader copies next to it.
"""

from __future__ import annotations

import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import protocol  # noqa: E402
import worker  # noqa: E402

#: the limits of ``Limits.for_worker`` and the ``resource`` names that apply them (per process, where they exist)
_LIMITS = (("memory", "RLIMIT_AS"), ("cpu", "RLIMIT_CPU"), ("file_size", "RLIMIT_FSIZE"), ("core", "RLIMIT_CORE"))


def _binary(fd: int) -> None:
    try:
        import msvcrt  # Windows: a descriptor in text mode would translate the frames' bytes
    except ImportError:
        return
    msvcrt.setmode(fd, os.O_BINARY)


def channels(output: str) -> tuple[int, int]:
    """The protocol's descriptors (copies of standard input and output); standard input becomes the null device
    and standard output the file ``output``."""
    request_fd, reply_fd = os.dup(0), os.dup(1)
    for fd in (request_fd, reply_fd):
        _binary(fd)
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.close(null)
    out = os.open(output, os.O_WRONLY | os.O_APPEND | os.O_CREAT | getattr(os, "O_BINARY", 0), 0o600)
    os.dup2(out, 1)
    os.close(out)
    return request_fd, reply_fd


def apply_limits(limits: dict) -> list[str]:
    """The limits that ``resource`` offers here, applied (none where it does not exist); the names applied."""
    try:
        import resource
    except ImportError:
        return []
    applied = []
    for key, name in _LIMITS:
        value, number = limits.get(key), getattr(resource, name, None)
        if value is None or number is None:
            continue
        try:
            _, hard = resource.getrlimit(number)
            value = value if hard == resource.RLIM_INFINITY else min(value, hard)
            resource.setrlimit(number, (value, hard))
        except (ValueError, OSError):
            continue
        applied.append(key)
    import signal

    if hasattr(signal, "SIGXFSZ"):  # a write beyond the file-size limit fails instead of ending the process
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    return applied


def main(argv: list[str]) -> int:
    config = json.loads(argv[1])
    request_fd, reply_fd = channels(config["output"])
    submission = config["submission"]
    # the shape of a worker's argv (worker.py REQUEST_FD REPLY_FD SUBMISSION CONFIG), as every mode gives it
    sys.argv = [os.path.join(os.path.dirname(os.path.abspath(__file__)), "worker.py"), str(request_fd),
                str(reply_fd), submission, argv[1]]
    try:
        info = {"python": sys.executable, "version": sys.version.split()[0], "portable": True,
                "limits": apply_limits(config.get("limits", {}))}
        worker.import_dependencies(config.get("require", []))
    except BaseException as exc:  # noqa: BLE001 - reported to the grader as a fault of the set-up
        protocol.write_message(reply_fd, worker.setup_fault(exc))
        return 70
    worker.seal()
    os.environ["GRADER_SUBMISSION"] = submission
    protocol.write_message(reply_fd, {"id": 0, "ok": True, "op": "ready", "info": info})
    return worker.serve(request_fd, reply_fd, submission)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
