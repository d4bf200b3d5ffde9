"""Answers frames() by writing a forged, deeply nested reply straight onto the protocol pipe."""
import os
import struct
import sys


def _forge(request_id):
    depth = 100_000
    data = ('{"id": %d, "ok": true, "value": ' % request_id + "[" * depth + '"x"' + "]" * depth + "}").encode()
    fd = int(sys.argv[2])
    os.write(fd, struct.pack(">I", len(data)) + data)


def frames():
    for request_id in range(1, 40):
        _forge(request_id)
    while True:
        pass


def vectors():
    return frames()
