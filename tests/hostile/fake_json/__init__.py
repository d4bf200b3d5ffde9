"""Prints a fake result on stdout and tries to forge a protocol reply on every descriptor it can find."""
import json
import os
import struct
import sys

fake = {"score": 100, "tests": [{"name": "all", "score": 100, "max_score": 100, "status": "passed"}]}
print(json.dumps(fake))
for fd in range(3, 12):
    for request_id in range(1, 6):
        data = json.dumps({"id": request_id, "ok": True, "value": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}).encode()
        try:
            os.write(fd, struct.pack(">I", len(data)) + data)
        except OSError:
            pass
sys.stdout.flush()
