"""The next student of the same slot: reports, as one JSON line, whatever of an earlier student it can see."""
import json
import math
import os
import sys
import threading

import numpy as np

from . import _sysv

with open(os.path.join(os.path.dirname(__file__), "target.txt")) as _handle:
    _nonce = json.load(_handle)["nonce"]


def _listing(folder: str, everything: bool = False):
    """The earlier student's files in ``folder`` (all files), or why it cannot be listed (Landlock hides it)."""
    try:
        return sorted(p for p in os.listdir(folder) if everything or _nonce in p)
    except OSError as exc:
        return type(exc).__name__


def _daemons() -> list:
    found = []
    for pid in os.listdir("/proc"):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as handle:
                if _nonce.encode() in handle.read():
                    found.append(int(pid))
        except OSError:
            pass
    return found


seen = {
    "uid": os.getuid(),
    "math_patched": math.sqrt(4.0) != 2.0,
    "numpy_patched": bool(np.allclose(0.0, 1.0)) or float(np.linalg.norm([3.0, 4.0])) != 5.0,
    "leftover_module": "leftover_module" in sys.modules,
    "environment": os.environ.get("LEFTOVER"),
    "threads": threading.active_count(),
    "tasks": len(os.listdir("/proc/self/task")),
    "rng_is_seeded_12345": bool(np.all(np.random.get_state()[1][:8] == np.random.RandomState(12345).get_state()[1][:8])),
    "draw": float(np.random.random()),
    "files": {folder: _listing(folder) for folder in ("/tmp", "/dev/shm", "/var/tmp") if os.path.isdir(folder)},
    "daemons": _daemons(),
    "shm": _sysv.exists(),
    "package": sorted(os.listdir(os.path.dirname(os.path.abspath(__file__)))),
    "slot": _listing("/slot", everything=True) if os.path.isdir("/slot") else [],
    "fds": sorted(int(fd) for fd in os.listdir("/proc/self/fd")),
}
print("SPY " + json.dumps(seen), flush=True)
