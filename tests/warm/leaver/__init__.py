"""The first student of a slot: leaves everything it can behind for the next student graded by the same slot —
a patched module and a patched numpy, a module of its own, an environment variable, a running thread, the numpy
random state seeded, files in /tmp and /dev/shm, a daemon in a session of its own, a System V shared memory
segment — and tries to kill the slot's warm process.  Prints what it left, as one JSON line, before that kill:
where the kill succeeds (the warm process of an unprivileged instructor under bubblewrap), the kernel kills this
process too (its parent-death signal), and a line printed after the kill was lost whenever the machine was loaded
enough to let the kernel act first.  The kill's outcome follows on a line of its own, which only a leaver whose
kill failed lives to print: it waits after a successful kill, so that this happens on every run, not only on a
loaded machine."""
import json
import math
import os
import signal
import subprocess
import sys
import threading
import time
import types

import numpy as np

from . import _sysv

with open(os.path.join(os.path.dirname(__file__), "target.txt")) as _handle:
    _nonce = json.load(_handle)["nonce"]

done = {"uid": os.getuid()}
math.sqrt = lambda x: -1.0
np.allclose = lambda *a, **k: True
np.linalg.norm = lambda *a, **k: 0.0
sys.modules["leftover_module"] = types.ModuleType("leftover_module")
os.environ["LEFTOVER"] = _nonce
threading.Thread(target=time.sleep, args=(3600,), name="leftover-thread", daemon=True).start()
done["threads"] = threading.active_count()
np.random.seed(12345)
for _folder in ("/tmp", "/dev/shm"):
    try:
        with open(os.path.join(_folder, f"leftover-{_nonce}"), "w") as _out:
            _out.write("left")
        done[_folder] = True
    except OSError as exc:
        done[_folder] = type(exc).__name__
try:
    subprocess.Popen(["sleep", _nonce], start_new_session=True, stdin=subprocess.DEVNULL,
                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    done["daemon"] = True
except OSError as exc:
    done["daemon"] = type(exc).__name__
done["shm"] = _sysv.create()
print("LEAVER " + json.dumps(done), flush=True)
_parent = os.getppid()
try:
    if _parent == 0:  # the first process of a PID namespace of its own: its parent is outside, and has no pid here
        killed = "no parent in its PID namespace"
    else:
        os.kill(_parent, signal.SIGKILL)
        killed = True
except OSError as exc:
    killed = type(exc).__name__
if killed is True:
    time.sleep(5)  # the kernel ends this process meanwhile
print("KILL " + json.dumps({"killed_parent": killed}), flush=True)
