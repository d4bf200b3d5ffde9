"""Answers frames() with a stream of well-formed replies that carry another id, five a second, forever: each one
used to restart the grader's deadline, so the call never timed out."""
import json
import os
import struct
import sys
import time


def _reply(fd, request_id):
    data = json.dumps({"id": request_id, "ok": True, "value": None}).encode()
    os.write(fd, struct.pack(">I", len(data)) + data)


def frames():
    fd = int(sys.argv[2])
    while True:
        _reply(fd, 1_000_000)
        time.sleep(0.2)


def vectors():
    return frames()
