"""The system-call filter of every worker that runs student code, and the fresh session keyring it joins first.

What no mount hides is filtered by system call.  Docker's default profile is the anchor: a container without
capabilities cannot use the kernel's keyrings, trace or read other processes, mount or change namespaces, load
BPF programs or kernel modules, open performance counters or userfaultfd, reboot, swap, set the clock or use the
new mount API; ``clone3`` answers ENOSYS (the C library then falls back to ``clone``, whose namespace flags are
refused); ``personality`` takes only the values Docker allows.  Beyond Docker's profile, for a grader whose plain
processes share the host's file system: no ``socket(AF_UNIX)`` (no connection to a Unix socket of the host,
named or abstract) and only stream or sequenced-packet ``socketpair`` (a datagram pair could be connected
elsewhere), and no io_uring (its operations never pass through this filter).  Refused calls fail with EPERM; a
call of another architecture's table (i386 through ``int 0x80``, x32, 32-bit ARM) kills the process.

Standard library only: it runs inside the sandbox, copied next to ``worker.py``.  The filter is a classic BPF
program built here (``program``) and installed with ``seccomp(SECCOMP_SET_MODE_FILTER, TSYNC)`` after
``PR_SET_NO_NEW_PRIVS`` (``install``); it is never removed, and every process the worker starts inherits it.
Supported: x86_64 and aarch64.  Elsewhere ``install`` raises ``FilterError``: the grader then refuses to run the
submission (a fault of the installation, never a silent pass).
"""

from __future__ import annotations

import os
import struct

__all__ = ["ARCHES", "DENIED", "NOT_IMPLEMENTED", "FilterError", "Arch", "arch_of", "program", "install",
           "join_fresh_session_keyring", "EPERM", "ENOSYS", "RET_ALLOW", "RET_KILL_PROCESS", "RET_ERRNO"]


class FilterError(OSError):
    """The filter could not be built or installed here."""


class Arch:
    """One architecture: its audit token (``AUDIT_ARCH_*``) and its system-call numbers."""

    def __init__(self, name: str, audit: int, numbers: dict[str, int], x32_bit: int | None = None):
        self.name, self.audit, self.numbers, self.x32_bit = name, audit, numbers, x32_bit


# System-call numbers: (x86_64, aarch64); None where the architecture has no such call.  Calls numbered from 424
# on are the same on every architecture.
_NUMBERS = {
    # keyrings
    "keyctl": (250, 219), "add_key": (248, 217), "request_key": (249, 218),
    # other processes
    "ptrace": (101, 117), "process_vm_readv": (310, 270), "process_vm_writev": (311, 271), "kcmp": (312, 272),
    "pidfd_getfd": (438, 438), "process_madvise": (440, 440),
    # mounts and namespaces (the new mount API included)
    "mount": (165, 40), "umount2": (166, 39), "unshare": (272, 97), "setns": (308, 268), "pivot_root": (155, 41),
    "chroot": (161, 51), "open_tree": (428, 428), "move_mount": (429, 429), "fsopen": (430, 430),
    "fsconfig": (431, 431), "fsmount": (432, 432), "fspick": (433, 433), "mount_setattr": (442, 442),
    "statmount": (457, 457), "listmount": (458, 458), "open_tree_attr": (467, 467),
    # the kernel itself
    "bpf": (321, 280), "perf_event_open": (298, 241), "userfaultfd": (323, 282), "kexec_load": (246, 104),
    "kexec_file_load": (320, 294), "init_module": (175, 105), "finit_module": (313, 273),
    "delete_module": (176, 106), "create_module": (174, None), "query_module": (178, None),
    "get_kernel_syms": (177, None), "reboot": (169, 142), "swapon": (167, 224), "swapoff": (168, 225),
    "acct": (163, 89), "syslog": (103, 116), "lookup_dcookie": (212, 18), "quotactl": (179, 60),
    "quotactl_fd": (443, 443), "nfsservctl": (180, 42), "uselib": (134, None), "ustat": (136, None),
    "sysfs": (139, None), "_sysctl": (156, None), "vhangup": (153, 58), "iopl": (172, None),
    "ioperm": (173, None), "settimeofday": (164, 170), "clock_settime": (227, 112), "clock_adjtime": (305, 266),
    "sethostname": (170, 161), "setdomainname": (171, 162), "fanotify_init": (300, 262),
    "open_by_handle_at": (304, 265),
    # memory placement (Docker: CAP_SYS_NICE only)
    "get_mempolicy": (239, 236), "set_mempolicy": (238, 237), "mbind": (237, 235), "move_pages": (279, 239),
    "migrate_pages": (256, 238), "set_mempolicy_home_node": (450, 450),
    # io_uring: its operations (open, connect, ...) are not system calls and never reach a filter
    "io_uring_setup": (425, 425), "io_uring_enter": (426, 426), "io_uring_register": (427, 427),
    # allowed with conditions on their arguments (below)
    "clone": (56, 220), "clone3": (435, 435), "socket": (41, 198), "socketpair": (53, 199),
    "personality": (135, 92),
    # used here to install the filter and join the keyring
    "seccomp": (317, 277),
}

#: refused with EPERM, whatever their arguments (each where the architecture has it)
DENIED = tuple(name for name in _NUMBERS
               if name not in ("clone", "clone3", "socket", "socketpair", "personality", "seccomp"))
#: refused with ENOSYS, as Docker does, so that the C library falls back to ``clone``, whose flags are checked
NOT_IMPLEMENTED = ("clone3",)

ARCHES = {
    "x86_64": Arch("x86_64", 0xC000003E, {n: v[0] for n, v in _NUMBERS.items() if v[0] is not None},
                   x32_bit=0x40000000),
    "aarch64": Arch("aarch64", 0xC00000B7, {n: v[1] for n, v in _NUMBERS.items() if v[1] is not None}),
}

EPERM, ENOSYS = 1, 38
RET_KILL_PROCESS, RET_ERRNO, RET_ALLOW = 0x80000000, 0x00050000, 0x7FFF0000
#: clone's namespace flags (NEWNS, NEWCGROUP, NEWUTS, NEWIPC, NEWUSER, NEWPID, NEWNET), refused as Docker does
CLONE_NAMESPACES = 0x7E020000
AF_UNIX, AF_VSOCK = 1, 40
SOCK_STREAM, SOCK_SEQPACKET, SOCK_TYPE_MASK = 1, 5, 0xF
#: personality values Docker allows: PER_LINUX, PER_LINUX32, UNAME26, UNAME26 | PER_LINUX32, and the query
PERSONALITIES = (0x0, 0x8, 0x20000, 0x20008, 0xFFFFFFFF)

# classic BPF (linux/filter.h, linux/bpf_common.h) and seccomp_data's layout (linux/seccomp.h)
_LD_W_ABS, _JEQ_K, _JGE_K, _JSET_K, _AND_K, _RET_K = 0x20, 0x15, 0x35, 0x45, 0x54, 0x06
_NR, _ARCH = 0, 4


def _arg(index: int) -> int:
    """The offset of the low 32 bits of argument ``index`` (little-endian: both architectures)."""
    return 16 + 8 * index


def arch_of(machine: str | None = None) -> Arch:
    """The architecture of this process (``os.uname().machine``), or ``FilterError`` where it is not supported."""
    machine = machine or os.uname().machine
    if machine not in ARCHES or struct.calcsize("P") != 8:
        raise FilterError(f"the system-call filter supports x86_64 and aarch64 (64-bit Python); this is {machine} "
                          f"with {8 * struct.calcsize('P')}-bit Python")
    return ARCHES[machine]


def _assemble(code: list) -> list[tuple[int, int, int, int]]:
    """Instructions ``(op, k)``, ``(op, k, true_label, false_label)`` or label strings, to ``(op, jt, jf, k)``
    with each label replaced by its forward distance."""
    labels, position = {}, 0
    for item in code:
        if isinstance(item, str):
            labels[item] = position
        else:
            position += 1
    out, position = [], 0
    for item in code:
        if isinstance(item, str):
            continue
        op, k, *targets = item
        jumps = []
        for target in targets or (None, None):
            distance = 0 if target is None else labels[target] - position - 1
            if not 0 <= distance <= 255:
                raise FilterError(f"jump to {target} out of range ({distance})")
            jumps.append(distance)
        out.append((op, jumps[0], jumps[1], k & 0xFFFFFFFF))
        position += 1
    return out


def _errno(number: int) -> int:
    return RET_ERRNO | number


def instructions(arch: Arch) -> list[tuple[int, int, int, int]]:
    """The filter of ``arch`` as ``(op, jt, jf, k)`` instructions."""
    nr = arch.numbers
    code: list = [(_LD_W_ABS, _ARCH), (_JEQ_K, arch.audit, "native", "foreign"), "foreign", (_RET_K, RET_KILL_PROCESS),
                  "native", (_LD_W_ABS, _NR)]
    if arch.x32_bit is not None:  # the x32 ABI: the same audit token, numbers with this bit set
        code += [(_JGE_K, arch.x32_bit, "x32", "calls"), "x32", (_RET_K, RET_KILL_PROCESS)]
    code += ["calls"]
    for name in DENIED:
        if name in nr:
            code += [(_JEQ_K, nr[name], f"deny-{name}", f"after-{name}"), f"deny-{name}", (_RET_K, _errno(EPERM)),
                     f"after-{name}"]
    code += [(_JEQ_K, nr["clone3"], "clone3", "clone"), "clone3", (_RET_K, _errno(ENOSYS)), "clone",
             # clone: no new namespace
             (_JEQ_K, nr["clone"], "clone-flags", "socket"), "clone-flags", (_LD_W_ABS, _arg(0)),
             (_JSET_K, CLONE_NAMESPACES, "deny", "allow"),
             # socket: no Unix socket (a named one of the host, or an abstract one), no VSOCK
             "socket", (_JEQ_K, nr["socket"], "socket-domain", "socketpair"), "socket-domain", (_LD_W_ABS, _arg(0)),
             (_JEQ_K, AF_UNIX, "deny", "not-unix"), "not-unix", (_JEQ_K, AF_VSOCK, "deny", "allow"),
             # socketpair: connected for good (a datagram pair could be connected to another socket)
             "socketpair", (_JEQ_K, nr["socketpair"], "pair-type", "personality"), "pair-type", (_LD_W_ABS, _arg(1)),
             (_AND_K, SOCK_TYPE_MASK), (_JEQ_K, SOCK_STREAM, "allow", "not-stream"),
             "not-stream", (_JEQ_K, SOCK_SEQPACKET, "allow", "deny"),
             "personality", (_JEQ_K, nr["personality"], "persona", "allow"), "persona", (_LD_W_ABS, _arg(0))]
    for index, value in enumerate(PERSONALITIES):
        code += [(_JEQ_K, value, "allow", f"persona-{index + 1}"), f"persona-{index + 1}"]
    code += [(_RET_K, _errno(EPERM)),
             "deny", (_RET_K, _errno(EPERM)), "allow", (_RET_K, RET_ALLOW)]
    return _assemble(code)


def program(arch: Arch) -> bytes:
    """The filter of ``arch`` as the array of ``struct sock_filter`` that the kernel takes."""
    return b"".join(struct.pack("=HBBI", *instruction) for instruction in instructions(arch))


def _libc():
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    libc.syscall.restype = ctypes.c_long
    return libc


PR_SET_NO_NEW_PRIVS = 38
SECCOMP_SET_MODE_FILTER, SECCOMP_FILTER_FLAG_TSYNC = 1, 1
KEYCTL_JOIN_SESSION_KEYRING = 1


def join_fresh_session_keyring(libc=None, arch: Arch | None = None) -> int:
    """Leave the session keyring inherited from the grader (and whatever it holds) for a new, empty, anonymous
    one; returns its serial number (0 where the kernel has no keyrings)."""
    import ctypes

    libc = libc or _libc()
    arch = arch or arch_of()
    serial = libc.syscall(ctypes.c_long(arch.numbers["keyctl"]), ctypes.c_long(KEYCTL_JOIN_SESSION_KEYRING),
                          ctypes.c_void_p(None))
    if serial < 0:
        errno = ctypes.get_errno()
        if errno == ENOSYS:
            return 0
        raise FilterError(errno, f"a fresh session keyring could not be joined: {os.strerror(errno)}")
    return serial


def install(libc=None, arch: Arch | None = None) -> dict:
    """Install the filter on this process (every thread) and everything it starts; raises ``FilterError`` when it
    cannot be installed.  Returns what the grader's report says about it."""
    import ctypes

    libc = libc or _libc()
    arch = arch or arch_of()
    code = program(arch)

    class Program(ctypes.Structure):
        _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]

    buffer = ctypes.create_string_buffer(code, len(code))
    fprog = Program(len(code) // 8, ctypes.cast(buffer, ctypes.c_void_p))
    if libc.prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
        errno = ctypes.get_errno()
        raise FilterError(errno, f"PR_SET_NO_NEW_PRIVS failed: {os.strerror(errno)}")
    done = libc.syscall(ctypes.c_long(arch.numbers["seccomp"]), ctypes.c_long(SECCOMP_SET_MODE_FILTER),
                        ctypes.c_long(SECCOMP_FILTER_FLAG_TSYNC), ctypes.byref(fprog))
    if done != 0:
        errno = ctypes.get_errno() if done < 0 else 0
        detail = os.strerror(errno) if errno else f"thread {done} could not take it"
        raise FilterError(errno, f"the system-call filter could not be installed: {detail}")
    return {"arch": arch.name, "instructions": len(code) // 8,
            "denied": sorted(name for name in DENIED if name in arch.numbers)}
