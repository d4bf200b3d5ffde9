"""The child side of the grader: imports a submission and runs probes on it.

This file runs inside the sandbox with the untrusted submission and must stay importable on its own (standard
library only, plus the ``probes`` package copied next to it).  It never sees the reference, the checks or the
scoring code: it receives probe calls on a dedicated pipe and sends back plain data.

Framing, both directions: a 4-byte big-endian length, then that many bytes of UTF-8 JSON.
Requests:  {"id": n, "op": "import"} | {"id": n, "op": "call", "probe": "problem_06.vectors", "args": [...]}
           | {"id": n, "op": "exit"}
Replies:   {"id": n, "ok": true, "value": ...}
           | {"id": n, "ok": false, "kind": "not_implemented" | "exception" | "bad_value" | "exit",
              "phase": "import" | "call", "type": "...", "message": "...", "traceback": "..."}
"""

from __future__ import annotations

import importlib
import importlib.util
import json
import os
import struct
import sys
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from probes._codec import decode, encode  # noqa: E402  (the probes package is copied beside this file)

HEADER = struct.Struct(">I")
#: a reply larger than this is refused by the parent
MAX_MESSAGE = 8 * 1024 * 1024
PACKAGE = "submission"


# ---------------------------------------------------------------- framing (shared with the parent)


def _read_exact(fd: int, n: int) -> bytes | None:
    chunks = []
    while n:
        chunk = os.read(fd, n)
        if not chunk:
            return None
        chunks.append(chunk)
        n -= len(chunk)
    return b"".join(chunks)


def write_message(fd: int, message: dict) -> None:
    data = json.dumps(message, allow_nan=True, separators=(",", ":")).encode()
    payload = HEADER.pack(len(data)) + data
    view = memoryview(payload)
    while view:
        written = os.write(fd, view)
        view = view[written:]


def read_message(fd: int, limit: int = MAX_MESSAGE) -> dict | None:
    header = _read_exact(fd, HEADER.size)
    if header is None:
        return None
    (size,) = HEADER.unpack(header)
    if size > limit:
        raise ValueError(f"message of {size} bytes exceeds the limit of {limit}")
    data = _read_exact(fd, size)
    if data is None:
        return None
    return json.loads(data)


# ---------------------------------------------------------------- the worker


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


def _error(req_id, kind: str, exc: BaseException) -> dict:
    message = str(exc)
    return {
        "id": req_id,
        "ok": False,
        "kind": kind,
        "type": type(exc).__name__,
        "message": message[:2000],
        "traceback": _student_traceback(exc),
    }


def _import_submission(path: str):
    spec = importlib.util.spec_from_file_location(
        PACKAGE, os.path.join(path, "__init__.py"), submodule_search_locations=[path]
    )
    module = importlib.util.module_from_spec(spec)
    sys.modules[PACKAGE] = module
    spec.loader.exec_module(module)
    return module


def _call(package, name: str, args: list):
    module_name, _, func_name = name.rpartition(".")
    probe_module = importlib.import_module(f"probes.{module_name}")
    probe = getattr(probe_module, func_name)
    if not getattr(probe, "is_probe", False):
        raise LookupError(f"{name} is not a probe")
    return probe(package, *decode(args))


def serve(request_fd: int, reply_fd: int, submission: str) -> int:
    package = None
    while True:
        request = read_message(request_fd)
        if request is None or request.get("op") == "exit":
            return 0
        req_id = request.get("id")
        phase = "import" if package is None else "call"
        try:
            if request["op"] == "import":
                package = _import_submission(submission)
                reply = {"id": req_id, "ok": True, "value": None}
            elif request["op"] == "call":
                if package is None:
                    package = _import_submission(submission)
                value = _call(package, request["probe"], request.get("args", []))
                try:
                    reply = {"id": req_id, "ok": True, "value": encode(value)}
                except (TypeError, ValueError) as exc:
                    reply = _error(req_id, "bad_value", exc)
            else:
                raise ValueError(f"unknown operation {request['op']!r}")
        except NotImplementedError as exc:
            reply = _error(req_id, "not_implemented", exc)
        except SystemExit as exc:
            reply = _error(req_id, "exit", exc)
        except BaseException as exc:  # noqa: BLE001 - every failure of student code is reported, not raised
            reply = _error(req_id, "exception", exc)
        reply["phase"] = phase
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        write_message(reply_fd, reply)


def _die_with_parent() -> None:
    """Ask the kernel to kill this process when the grader that started it dies (Linux prctl)."""
    import ctypes
    import signal

    try:
        libc = ctypes.CDLL(None, use_errno=True)
        PR_SET_PDEATHSIG = 1
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):
        pass


def _apply_limits(limits: dict) -> None:
    """Set hard resource limits and, when started as root, drop to an unprivileged user.

    Runs before any student code, so the student cannot raise the limits again.
    """
    import resource
    import signal

    names = {
        "memory": resource.RLIMIT_AS,
        "cpu": resource.RLIMIT_CPU,
        "file_size": resource.RLIMIT_FSIZE,
        "processes": resource.RLIMIT_NPROC,
        "core": resource.RLIMIT_CORE,
    }
    uid = limits.get("uid")
    for key, value in limits.items():
        if key in names and value is not None:
            if key == "processes" and uid is None:
                continue  # counted per user: only meaningful for a dedicated uid
            resource.setrlimit(names[key], (value, value))
    # Writes beyond the file-size limit fail with an OSError instead of killing the process.
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    _die_with_parent()
    if uid is not None and os.geteuid() == 0:
        os.setgroups([])
        os.setgid(uid)
        os.setuid(uid)


class _BlockTrustedPackages:
    """Refuses imports of the grader's trusted packages (the sandbox hides their files as well)."""

    BLOCKED = ("reference", "checks", "grader", "tests", "student_template", "tools")

    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in self.BLOCKED:
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        return None


def main(argv: list[str]) -> int:
    request_fd, reply_fd = int(argv[1]), int(argv[2])
    submission = argv[3]
    _apply_limits(json.loads(argv[4]) if len(argv) > 4 else {})
    sys.meta_path.insert(0, _BlockTrustedPackages())
    for name in [m for m in sys.modules if m.split(".")[0] in _BlockTrustedPackages.BLOCKED]:
        del sys.modules[name]
    os.environ["GRADER_SUBMISSION"] = submission
    # Keep the protocol out of reach of print(): stdout/stderr are files the parent reads separately.
    sys.stdin.close()
    sys.setrecursionlimit(3000)
    return serve(request_fd, reply_fd, submission)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
