"""The kernel's keyrings, as the tests use them (ctypes, no keyutils): join a session keyring, add a key, list a
keyring, and take a key away again."""

from __future__ import annotations

import ctypes
import os
import struct

__all__ = ["SESSION", "USER", "join_session", "add_key", "keys_in", "invalidate"]

#: the special keyring ids of the calling process (linux/keyctl.h)
SESSION, USER = -3, -4
_KEYCTL, _ADD_KEY = {"x86_64": (250, 248), "aarch64": (219, 217)}.get(os.uname().machine, (None, None))
_JOIN_SESSION_KEYRING, _READ, _INVALIDATE = 1, 11, 21


def _libc():
    libc = ctypes.CDLL(None, use_errno=True)
    libc.syscall.restype = ctypes.c_long
    return libc


def _checked(result: int, what: str) -> int:
    if result < 0:
        errno = ctypes.get_errno()
        raise OSError(errno, f"{what}: {os.strerror(errno)}")
    return result


def join_session(name: str) -> int:
    """Join a new session keyring called ``name`` (this process and what it starts from now on)."""
    return _checked(_libc().syscall(ctypes.c_long(_KEYCTL), ctypes.c_long(_JOIN_SESSION_KEYRING),
                                    ctypes.c_char_p(name.encode())), "join a session keyring")


def add_key(description: str, payload: bytes, keyring: int = SESSION) -> int:
    """A ``user`` key in ``keyring``."""
    return _checked(_libc().syscall(ctypes.c_long(_ADD_KEY), ctypes.c_char_p(b"user"),
                                    ctypes.c_char_p(description.encode()), ctypes.c_char_p(payload),
                                    ctypes.c_long(len(payload)), ctypes.c_long(keyring)), "add a key")


def keys_in(keyring: int = SESSION) -> list[int]:
    """The serial numbers of the keys that ``keyring`` holds."""
    buffer = ctypes.create_string_buffer(4096)
    size = _checked(_libc().syscall(ctypes.c_long(_KEYCTL), ctypes.c_long(_READ), ctypes.c_long(keyring), buffer,
                                    ctypes.c_long(len(buffer))), "list a keyring")
    return list(struct.unpack(f"={min(size, len(buffer)) // 4}i", buffer.raw[:min(size, len(buffer)) // 4 * 4]))


def invalidate(key: int) -> None:
    _libc().syscall(ctypes.c_long(_KEYCTL), ctypes.c_long(_INVALIDATE), ctypes.c_long(key))
