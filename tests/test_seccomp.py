"""The system-call filter of the students' workers (``grader.sandbox.seccomp``): the BPF program run by an
interpreter of classic BPF for both architectures, its numbers against the kernel's headers, the filter and the
fresh session keyring in a real process of this machine, and the refusal to grade where it cannot be installed.

The hostile suite (``tests/test_hostile.py``: ``forbidden_syscalls``, ``keyring_*``, ``unix_socket_escape``) tries
the same calls from student code in every mode."""

import json
import os
import re
import shutil
import struct
import subprocess
import sys
from pathlib import Path

import pytest

from grader.cli import main
from grader.errors import SandboxError
from grader.runner import grade_submission
from grader.workers import Forked, Fresh
from grader.sandbox import Limits, refusal, sandbox_mode
from grader.sandbox import launch, seccomp
from grader.sandbox.zygote import Zygote, warm_modules

from .submissions import ROOT, copy_reference

#: the calls that the filter must refuse whatever their arguments: Docker's default profile for a container without
#: capabilities (keyrings, other processes, mounts and namespaces with the new mount API, the kernel itself)
DOCKER_REFUSES = ("keyctl", "add_key", "request_key", "ptrace", "process_vm_readv", "process_vm_writev", "mount",
                  "umount2", "unshare", "setns", "pivot_root", "chroot", "fsopen", "fsconfig", "fsmount", "fspick",
                  "move_mount", "open_tree", "mount_setattr", "bpf", "perf_event_open", "userfaultfd", "kexec_load",
                  "kexec_file_load", "init_module", "finit_module", "delete_module", "swapon", "swapoff", "reboot",
                  "open_by_handle_at", "iopl", "ioperm", "acct", "syslog", "settimeofday", "clock_settime",
                  "kcmp", "pidfd_getfd", "quotactl", "lookup_dcookie", "fanotify_init", "vhangup")
#: calls every worker makes, allowed on both architectures: (x86_64, aarch64)
EVERYDAY = {"read": (0, 63), "write": (1, 64), "openat": (257, 56), "mmap": (9, 222), "futex": (202, 98),
            "getpid": (39, 172), "exit_group": (231, 94), "wait4": (61, 260), "prctl": (157, 167),
            "kill": (62, 129), "execve": (59, 221), "landlock_restrict_self": (446, 446)}
#: clone's flags of a new thread (VM, FS, FILES, SIGHAND, THREAD, SYSVSEM, SETTLS, PARENT_SETTID, CHILD_CLEARTID)
THREAD_FLAGS = 0x3D0F00
NAMESPACE_FLAGS = {"NEWNS": 0x20000, "NEWCGROUP": 0x02000000, "NEWUTS": 0x04000000, "NEWIPC": 0x08000000,
                   "NEWUSER": 0x10000000, "NEWPID": 0x20000000, "NEWNET": 0x40000000}
AUDIT_I386, AUDIT_ARM = 0x40000003, 0x40000028


# ------------------------------------------------------------------------------------------ a classic-BPF machine


def run_filter(arch: seccomp.Arch, nr: int, args=(), audit: int | None = None) -> int:
    """The action the filter of ``arch`` returns for the call ``nr(args)`` made with ``audit`` (default: the
    filter's own architecture): an interpreter of the classic-BPF instructions the filter uses."""
    data = struct.pack("=iIQ6Q", nr, arch.audit if audit is None else audit, 0,
                       *[a & 0xFFFFFFFFFFFFFFFF for a in (*args, *[0] * (6 - len(args)))])
    program = seccomp.program(arch)
    code = [struct.unpack_from("=HBBI", program, offset) for offset in range(0, len(program), 8)]
    accumulator, pc = 0, 0
    for _ in range(len(code)):  # forward jumps only: at most one pass
        op, jt, jf, k = code[pc]
        if op == 0x20:  # LD | W | ABS
            accumulator = struct.unpack_from("=I", data, k)[0]
            pc += 1
        elif op == 0x54:  # ALU | AND | K
            accumulator &= k
            pc += 1
        elif op in (0x15, 0x35, 0x45):  # JMP | JEQ, JGE, JSET | K
            taken = {0x15: accumulator == k, 0x35: accumulator >= k, 0x45: bool(accumulator & k)}[op]
            pc += 1 + (jt if taken else jf)
        elif op == 0x06:  # RET | K
            return k
        else:
            raise AssertionError(f"instruction {op:#x} at {pc} is not one the interpreter knows")
    raise AssertionError("the program ran past its end")


EPERM = seccomp.RET_ERRNO | seccomp.EPERM
ARCHES = [pytest.param(arch, id=name) for name, arch in seccomp.ARCHES.items()]


@pytest.mark.parametrize("arch", ARCHES)
def test_every_call_a_container_is_refused_is_refused_with_eperm(arch):
    assert set(DOCKER_REFUSES) <= set(seccomp.DENIED)
    for name in seccomp.DENIED:
        if name in arch.numbers:
            assert run_filter(arch, arch.numbers[name], (0, 0, 0)) == EPERM, name
    for name in ("keyctl", "add_key", "request_key", "ptrace", "mount", "unshare", "setns", "bpf",
                 "perf_event_open", "userfaultfd", "io_uring_setup", "pidfd_getfd", "fsopen", "open_tree_attr"):
        assert name in arch.numbers, name  # present on both architectures
    assert run_filter(arch, arch.numbers["clone3"], (0, 88)) == seccomp.RET_ERRNO | seccomp.ENOSYS


@pytest.mark.parametrize("arch", ARCHES)
def test_everyday_calls_pass(arch):
    index = list(seccomp.ARCHES.values()).index(arch)
    for name, numbers in EVERYDAY.items():
        assert run_filter(arch, numbers[index], (3, 0, 0)) == seccomp.RET_ALLOW, name


@pytest.mark.parametrize("arch", ARCHES)
def test_clone_makes_threads_and_processes_but_no_namespace(arch):
    clone = arch.numbers["clone"]
    assert run_filter(arch, clone, (THREAD_FLAGS,)) == seccomp.RET_ALLOW
    assert run_filter(arch, clone, (17,)) == seccomp.RET_ALLOW  # fork: SIGCHLD
    for name, flag in NAMESPACE_FLAGS.items():
        assert run_filter(arch, clone, (17 | flag,)) == EPERM, name


@pytest.mark.parametrize("arch", ARCHES)
def test_no_unix_socket_but_a_connected_pair(arch):
    socket_nr, pair_nr = arch.numbers["socket"], arch.numbers["socketpair"]
    cloexec = 0x80000
    assert run_filter(arch, socket_nr, (2, 1 | cloexec, 0)) == seccomp.RET_ALLOW  # AF_INET
    assert run_filter(arch, socket_nr, (10, 2, 0)) == seccomp.RET_ALLOW  # AF_INET6, datagram
    assert run_filter(arch, socket_nr, (1, 1, 0)) == EPERM  # AF_UNIX
    assert run_filter(arch, socket_nr, (1 | 1 << 32, 1, 0)) == EPERM  # the kernel reads an int: the same AF_UNIX
    assert run_filter(arch, socket_nr, (40, 1, 0)) == EPERM  # AF_VSOCK
    assert run_filter(arch, pair_nr, (1, 1 | cloexec, 0)) == seccomp.RET_ALLOW
    assert run_filter(arch, pair_nr, (1, 5, 0)) == seccomp.RET_ALLOW  # sequenced packets
    assert run_filter(arch, pair_nr, (1, 2 | cloexec, 0)) == EPERM  # a datagram pair could connect elsewhere


@pytest.mark.parametrize("arch", ARCHES)
def test_personality_takes_only_what_docker_allows(arch):
    for value in seccomp.PERSONALITIES:
        assert run_filter(arch, arch.numbers["personality"], (value,)) == seccomp.RET_ALLOW
    assert run_filter(arch, arch.numbers["personality"], (0x0040000,)) == EPERM  # ADDR_NO_RANDOMIZE
    assert run_filter(arch, arch.numbers["personality"], (0x0400000,)) == EPERM  # READ_IMPLIES_EXEC


@pytest.mark.parametrize("arch", ARCHES)
def test_calls_of_another_architecture_kill_the_process(arch):
    other = next(a for a in seccomp.ARCHES.values() if a is not arch)
    for audit in (AUDIT_I386, AUDIT_ARM, other.audit):
        assert run_filter(arch, arch.numbers["read"] if "read" in arch.numbers else 0, (), audit) == \
            seccomp.RET_KILL_PROCESS
    if arch.x32_bit is not None:
        assert run_filter(arch, arch.x32_bit | 39, ()) == seccomp.RET_KILL_PROCESS  # x32's getpid


@pytest.mark.parametrize("arch", ARCHES)
def test_the_program_is_one_the_kernel_takes(arch):
    instructions = seccomp.instructions(arch)
    assert 0 < len(instructions) < 4096  # BPF_MAXINSNS
    for position, (op, jt, jf, _) in enumerate(instructions):
        if op & 0x07 == 0x05:  # a jump lands inside the program
            assert position + 1 + max(jt, jf) < len(instructions)
    assert instructions[-1][0] == 0x06  # it ends on a return


def test_an_unsupported_machine_is_refused():
    with pytest.raises(seccomp.FilterError, match="x86_64 and aarch64"):
        seccomp.arch_of("riscv64")


HEADERS = {"x86_64": Path("/usr/include/x86_64-linux-gnu/asm/unistd_64.h"),
           "aarch64": Path("/usr/include/asm-generic/unistd.h")}


@pytest.mark.parametrize("name", sorted(HEADERS))
def test_the_numbers_are_the_kernels(name):
    """Against the kernel's headers (Debian's linux-libc-dev): the generic table is aarch64's.  Calls newer than
    the headers are numbered alike on every architecture."""
    header = HEADERS[name]
    if not header.exists():
        pytest.skip(f"{header} is not installed (linux-libc-dev)")
    defined = {m[0]: int(m[1]) for m in re.findall(r"#define __NR(?:3264)?_(\w+)\s+(\d+)", header.read_text())}
    arch = seccomp.ARCHES[name]
    checked = 0
    for call, number in arch.numbers.items():
        if call in defined:
            assert defined[call] == number, call
            checked += 1
        else:
            assert number >= 424, f"{call} is missing from {header}"
    for call in ("create_module", "iopl", "ioperm", "uselib", "_sysctl"):
        assert (call in arch.numbers) == (call in defined), call
    assert checked >= 60


# ------------------------------------------------------------------------------------------ in a real process

PROBE = r"""
import ctypes, json, os, socket, struct, sys, tempfile, threading
sys.path.insert(0, sys.argv[1])
import seccomp

libc = ctypes.CDLL(None, use_errno=True)
libc.syscall.restype = ctypes.c_long
arch = seccomp.arch_of()
nr = arch.numbers
root = os.geteuid() == 0


def call(name, *args):
    args = [a if isinstance(a, (ctypes._SimpleCData, ctypes.Array)) else ctypes.c_long(a) for a in args]
    done = libc.syscall(ctypes.c_long(nr[name]), *args)
    return "ok" if done >= 0 else os.strerror(ctypes.get_errno())


def tries():
    target = tempfile.mkdtemp(dir=sys.argv[1])
    map_attr = ctypes.create_string_buffer(struct.pack("=IIII", 2, 4, 4, 1), 72)
    found = {
        "keyctl": call("keyctl", 0, -3, 0),  # KEYCTL_GET_KEYRING_ID of the session keyring
        "ptrace": call("ptrace", 0, 0, 0, 0),  # PTRACE_TRACEME
        "mount": call("mount", ctypes.c_char_p(b"tmpfs"), ctypes.c_char_p(target.encode()),
                      ctypes.c_char_p(b"tmpfs"), 0, ctypes.c_char_p(b"size=4k")),
        "unshare": call("unshare", 0x04000000),  # CLONE_NEWUTS
        "bpf": call("bpf", 0, map_attr, 72),  # BPF_MAP_CREATE
    }
    try:
        socket.socket(socket.AF_UNIX).close()
        found["unix socket"] = "ok"
    except OSError as exc:
        found["unix socket"] = exc.strerror
    return found


def in_child(function):
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.write(write, json.dumps(function()).encode())
        os._exit(0)
    os.close(write)
    data = os.read(read, 65536)
    return json.loads(data) if data else None, os.waitstatus_to_exitcode(os.waitpid(pid, 0)[1])


if root:  # what a process may do without the filter (its mounts stay in a mount namespace of its own)
    assert libc.unshare(0x00020000) == 0
    assert libc.mount(b"none", b"/", None, 16384 | (1 << 18), None) == 0
before, _ = in_child(tries)
inherited = libc.syscall(ctypes.c_long(nr["keyctl"]), ctypes.c_long(0), ctypes.c_long(-3), ctypes.c_long(0))
fresh = seccomp.join_fresh_session_keyring(libc)
fresh_id = libc.syscall(ctypes.c_long(nr["keyctl"]), ctypes.c_long(0), ctypes.c_long(-3), ctypes.c_long(0))
contents = ctypes.create_string_buffer(64)
held = libc.syscall(ctypes.c_long(nr["keyctl"]), ctypes.c_long(11), ctypes.c_long(-3), contents, ctypes.c_long(64))
installed = seccomp.install(libc)
after = tries()
forked, forked_code = in_child(tries)
thread = {}
worker = threading.Thread(target=lambda: thread.update(tries()))
worker.start()
worker.join()
pair = socket.socketpair()
pair[0].sendall(b"x")
paired = pair[1].recv(1) == b"x"
_, foreign_code = in_child(lambda: libc.syscall(ctypes.c_long((arch.x32_bit or 0) | nr["socket"])) or "alive")
print(json.dumps({"root": root, "before": before, "after": after, "forked": forked, "thread": thread,
                  "paired": paired, "inherited": inherited, "fresh": fresh, "fresh_id": fresh_id, "held": held,
                  "installed": installed, "foreign_code": foreign_code, "x32": arch.x32_bit is not None}))
"""


def test_the_filter_refuses_in_this_kernel_what_the_process_could_do_before(tmp_path):
    """In a process of this machine (root where the tests run as root, when even root is refused): before the
    filter, the calls do what they do; after it, in the process, its threads and its children, they fail with
    EPERM; the session keyring joined is a new, empty one; a call of the x32 table kills the process."""
    shutil.copy2(Path(seccomp.__file__), tmp_path / "seccomp.py")
    done = subprocess.run([sys.executable, "-I", "-c", PROBE, str(tmp_path)], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr[-3000:]
    found = json.loads(done.stdout)
    refused = {name: "Operation not permitted" for name in found["after"]}
    assert found["after"] == refused and found["forked"] == refused and found["thread"] == refused
    assert found["paired"] is True
    assert found["inherited"] > 0 and found["fresh"] == found["fresh_id"] > 0 and found["fresh"] != found["inherited"]
    assert found["held"] == 0  # the fresh keyring holds no key
    assert found["installed"]["arch"] == os.uname().machine and "keyctl" in found["installed"]["denied"]
    before = found["before"]
    assert before["keyctl"] == "ok" and before["unix socket"] == "ok"
    if found["root"]:  # what only the filter refuses to root
        assert before["mount"] == before["unshare"] == before["ptrace"] == "ok", before
    if found["x32"]:
        assert found["foreign_code"] == -31  # SIGSYS: the process is killed, not answered


# ------------------------------------------------------------------------------------------ no filter, no grading


@pytest.fixture
def runtime_without_filter(tmp_path, monkeypatch):
    """The worker's runtime on a machine whose architecture the filter does not know."""
    runtime = tmp_path / "runtime"
    shutil.copytree(launch.runtime_dir(), runtime)
    with open(runtime / "seccomp.py", "a", encoding="utf-8") as handle:
        handle.write("\nARCHES.clear()  # (test) a machine the filter does not know\n")
    launch._make_readable(runtime)
    monkeypatch.setattr(launch, "runtime_dir", lambda: runtime)
    return runtime


def test_no_student_code_runs_where_the_filter_cannot_be_installed(runtime_without_filter, tmp_path, capsys):
    mode = sandbox_mode()
    if not mode.isolated and refusal() is not None:
        pytest.skip("covered by the refusal: no child runs here without bubblewrap")
    submission = copy_reference(tmp_path / "pkg")
    marker = tmp_path / "ran"
    (submission / "__init__.py").write_text(f"open({str(marker)!r}, 'w').close()\n")
    with pytest.raises(SandboxError) as fault:
        grade_submission(submission, [6], seed=1, workers=Fresh(Limits(), mode))
    text = str(fault.value)
    assert "system-call filter" in text and "x86_64 and aarch64" in text and "not the submission" in text, text
    code = main(["problem-6", "--submission", str(submission), "--json", str(tmp_path / "r.json")])
    assert code == 3 and "system-call filter" in capsys.readouterr().err
    assert not (tmp_path / "r.json").exists()
    with Zygote(Limits(), mode, warm_modules([6])) as zygote:  # the warm path: each fork installs it, or none runs
        zygote.start()
        with pytest.raises(SandboxError, match="system-call filter"):
            grade_submission(submission, [6], seed=1, workers=Forked(zygote))
    assert not marker.exists()
