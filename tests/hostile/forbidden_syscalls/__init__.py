"""At import, tries each class of system call that a container's default profile refuses, each in a child process
of its own (so that what it changes ends there): tracing, new namespaces, mounting, BPF, performance counters,
userfaultfd, io_uring."""
import ctypes
import os
import struct

_libc = ctypes.CDLL(None, use_errno=True)
_libc.syscall.restype = ctypes.c_long
_NR = {"x86_64": {"ptrace": 101, "unshare": 272, "mount": 165, "bpf": 321, "perf_event_open": 298,
                  "userfaultfd": 323, "io_uring_setup": 425},
       "aarch64": {"ptrace": 117, "unshare": 97, "mount": 40, "bpf": 280, "perf_event_open": 241,
                   "userfaultfd": 282, "io_uring_setup": 425}}[os.uname().machine]
_NEWNS, _NEWUSER = 0x00020000, 0x10000000


def _call(name, *args):
    result = _libc.syscall(ctypes.c_long(_NR[name]), *[a if isinstance(a, ctypes._SimpleCData) or
                                                        isinstance(a, ctypes.Array) else ctypes.c_long(a)
                                                        for a in args])
    return result, ctypes.get_errno()


def _ptrace():
    return _call("ptrace", 0, 0, 0, 0)  # PTRACE_TRACEME


def _unshare():
    return _call("unshare", _NEWUSER)


def _mount():
    _call("unshare", _NEWUSER | _NEWNS)  # root of a user namespace of its own, where mounting is allowed
    return _call("mount", ctypes.c_char_p(b"tmpfs"), ctypes.c_char_p(os.getcwd().encode()),
                 ctypes.c_char_p(b"tmpfs"), 0, ctypes.c_char_p(b"size=4k"))


def _bpf():
    attr = ctypes.create_string_buffer(struct.pack("=IIII", 2, 4, 4, 1), 72)  # BPF_MAP_TYPE_ARRAY of one int
    return _call("bpf", 0, attr, 72)  # BPF_MAP_CREATE


def _perf():
    # a software clock of this process, user space only: what an unprivileged user may open where allowed
    attr = ctypes.create_string_buffer(struct.pack("=IIQQQQQIIQ", 1, 64, 0, 0, 0, 0, (1 << 5) | (1 << 6), 0, 0, 0),
                                       64)
    return _call("perf_event_open", attr, 0, -1, -1, 0)


def _userfaultfd():
    return _call("userfaultfd", 1 | os.O_CLOEXEC)  # UFFD_USER_MODE_ONLY: what an unprivileged user may open


def _io_uring():
    params = ctypes.create_string_buffer(120)
    return _call("io_uring_setup", 4, params)


for _name, _try in (("ptrace", _ptrace), ("unshare", _unshare), ("mount", _mount), ("bpf", _bpf),
                    ("perf_event_open", _perf), ("userfaultfd", _userfaultfd), ("io_uring", _io_uring)):
    _read, _write = os.pipe()
    _pid = os.fork()
    if _pid == 0:
        _result, _errno = _try()
        os.write(_write, b"ALLOWED" if _result >= 0 else os.strerror(_errno).encode())
        os._exit(0)
    os.close(_write)
    _said = os.read(_read, 200).decode()
    os.close(_read)
    os.waitpid(_pid, 0)
    print(f"system call {_name}: {_said if _said == 'ALLOWED' else 'refused (' + _said + ')'}")
