"""The messages between the grader and its worker: framing, limits and deadlines.  Standard library only: this
module is copied next to the worker and imported by it.

Framing, both directions: a 4-byte big-endian length, then that many bytes of UTF-8 JSON.

The worker speaks first, before it imports the submission (nothing untrusted has run yet):
    {"id": 0, "ok": true, "op": "ready", "info": {...}}             it started and imported its dependencies
    {"id": 0, "ok": false, "kind": "setup", "type": ..., "message": ...}   it could not: a fault of the set-up
Requests:  {"id": n, "op": "import"} | {"id": n, "op": "call", "probe": "problem_06.vectors", "args": [...]}
           | {"id": n, "op": "exit"}
Replies:   {"id": n, "ok": true, "value": ...}
           | {"id": n, "ok": false, "kind": one of STUDENT_KINDS or "probe", "phase": "import" | "call",
              "type": ..., "message": ..., "traceback": ...}

The parent trusts nothing it reads after the worker said ready: every read is bounded in size (checked before
anything is allocated) and in time (one absolute deadline per call, whatever arrives in between).
"""

from __future__ import annotations

import json
import os
import select
import struct
import time

__all__ = [
    "HEADER",
    "MAX_MESSAGE",
    "STUDENT_KINDS",
    "GRADER_KINDS",
    "ProtocolError",
    "Deadline",
    "frame",
    "write_message",
    "read_message",
    "send_before",
    "FrameReader",
]

HEADER = struct.Struct(">I")
#: the largest message either side accepts
MAX_MESSAGE = 8 * 1024 * 1024
#: why a request failed: the student's code ...
STUDENT_KINDS = ("not_implemented", "exception", "bad_value", "exit")
#: ... or the grader: a probe that cannot be found or cannot import what it needs, a worker that cannot start
GRADER_KINDS = ("probe", "setup")
#: bytes read at a time
CHUNK = 1 << 16


class ProtocolError(ValueError):
    """A message that breaks the framing or is not a JSON object."""


class Deadline(TimeoutError):
    """The deadline passed before a whole message could be read or written."""


def frame(message: dict) -> bytes:
    data = json.dumps(message, allow_nan=True, separators=(",", ":")).encode()
    if len(data) > MAX_MESSAGE:
        raise ProtocolError(f"message of {len(data)} bytes exceeds the limit of {MAX_MESSAGE}")
    return HEADER.pack(len(data)) + data


def _parse(data: bytes) -> dict:
    message = json.loads(data)
    if not isinstance(message, dict):
        raise ProtocolError(f"a message must be a JSON object, not {type(message).__name__}")
    return message


# ---------------------------------------------------------------- blocking: the worker's side (its peer is trusted)


def write_message(fd: int, message: dict) -> None:
    view = memoryview(frame(message))
    while view:
        view = view[os.write(fd, view):]


def _read_exact(fd: int, n: int) -> bytes | None:
    chunks = []
    while n:
        chunk = os.read(fd, min(n, CHUNK))
        if not chunk:
            return None
        chunks.append(chunk)
        n -= len(chunk)
    return b"".join(chunks)


def read_message(fd: int, limit: int = MAX_MESSAGE) -> dict | None:
    """The next message, or None at the end of the stream."""
    header = _read_exact(fd, HEADER.size)
    if header is None:
        return None
    (size,) = HEADER.unpack(header)
    if size > limit:
        raise ProtocolError(f"message of {size} bytes exceeds the limit of {limit}")
    data = _read_exact(fd, size)
    return None if data is None else _parse(data)


# ---------------------------------------------------------------- deadline-bound: the grader's side


def _left(deadline: float) -> float:
    left = deadline - time.monotonic()
    if left <= 0:
        raise Deadline("the deadline passed")
    return left


def send_before(fd: int, message: dict, deadline: float) -> None:
    """Write ``message`` on the non-blocking ``fd`` before ``deadline`` (``time.monotonic()``): a peer that does
    not read cannot block the writer."""
    view = memoryview(frame(message))
    while view:
        select.select([], [fd], [], _left(deadline))
        try:
            view = view[os.write(fd, view):]
        except BlockingIOError:
            continue


class FrameReader:
    """Reads messages from a non-blocking ``fd``, each before an absolute deadline.

    Bytes that arrive after one message stay buffered for the next; a header announcing more than ``limit``
    bytes is refused as soon as it is read, before its body is awaited or stored."""

    def __init__(self, fd: int, limit: int = MAX_MESSAGE):
        os.set_blocking(fd, False)
        self.fd = fd
        self.limit = limit
        self._buffer = bytearray()
        self.closed = False

    def _complete(self) -> dict | None:
        if len(self._buffer) < HEADER.size:
            return None
        (size,) = HEADER.unpack_from(self._buffer)
        if size > self.limit:
            raise ProtocolError(f"message of {size} bytes exceeds the limit of {self.limit}")
        end = HEADER.size + size
        if len(self._buffer) < end:
            return None
        data = bytes(self._buffer[HEADER.size:end])
        del self._buffer[:end]
        return _parse(data)

    def read(self, deadline: float) -> dict | None:
        """The next message; None when the peer closed its end first.  Raises ``Deadline`` when the deadline
        passes first, ``ProtocolError`` (or a ``ValueError`` of JSON) for a malformed message."""
        while True:
            message = self._complete()
            if message is not None:
                return message
            if self.closed:
                return None
            ready, _, _ = select.select([self.fd], [], [], _left(deadline))
            if not ready:
                continue
            try:
                want = CHUNK
                if len(self._buffer) >= HEADER.size:
                    want = max(1, min(CHUNK, HEADER.size + HEADER.unpack_from(self._buffer)[0] - len(self._buffer)))
                chunk = os.read(self.fd, want)
            except BlockingIOError:
                continue
            if not chunk:
                self.closed = True
                continue
            self._buffer += chunk
