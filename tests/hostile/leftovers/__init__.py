"""At import, starts a daemon in a session of its own and leaves files in every folder that anyone may write to
(named with the nonce of target.txt, so that the test can look for them afterwards)."""
import json
import os
import subprocess

with open(os.path.join(os.path.dirname(__file__), "target.txt")) as _handle:
    _nonce = json.load(_handle)["nonce"]

try:
    subprocess.Popen(["sleep", _nonce], start_new_session=True, stdin=subprocess.DEVNULL,
                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
except OSError:
    pass
for _folder in ("/tmp", "/var/tmp", "/dev/shm"):
    try:
        with open(os.path.join(_folder, f"mbd-leftover-{_nonce}"), "wb") as _handle:
            _handle.write(b"x" * 2**20)
        os.makedirs(os.path.join(_folder, f"mbd-leftover-{_nonce}-dir", "inner"))
    except OSError:
        pass
print("leftovers planted")
