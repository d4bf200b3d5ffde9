"""At import, reads the machine's accounts, its host name and its network interfaces."""
import os

for _path in ("/etc/passwd", "/etc/hostname", "/etc/hosts"):
    try:
        with open(_path) as _handle:
            print(f"system files: read {_path}: {_handle.read(40)!r}")
    except OSError as exc:
        print(f"system files: refused {_path} ({type(exc).__name__})")
try:
    print("system files: read /sys/class/net:", os.listdir("/sys/class/net"))
except OSError as exc:
    print(f"system files: refused /sys/class/net ({type(exc).__name__})")
