"""Running submissions in a child process: the launch (what the child may see, under which uid), the parent's
handle on the child, the worker that runs inside it, and the protocol between the two.

    launch.py    modes (bubblewrap or a plain process), limits, the child's view of the file system
    users.py     unprivileged uids for children when the grader runs as root, and the sweep after each grading
    child.py     the parent's handle: probe calls with absolute deadlines, restarts, the start-up check
    zygote.py    the parent's handle on a batch slot's warm process, which forks each student's worker
    worker.py    the child side: its serving loop, the submission's import and the probes' dispatch (standard
                 library only, plus the modules below and the probes package)
    confinement.py  the worker's confinement before any student code runs: limits, namespaces, uid, Landlock, then
                 the keyring and the system-call filter of seccomp.py (standard library only)
    forkserver.py   the warm process itself: it imports what workers need, then forks and confines one per
                 student, which serves with worker.py's loop (standard library only)
    protocol.py  framing and deadline-bound reads and writes (standard library only)
    notebook.py  what of a notebook's code cells counts, and running it in the worker (standard library only)
    seccomp.py   the worker's system-call filter and fresh session keyring, installed last (standard library only)
    portable.py  the portable mode of a student's own machine: a subprocess on pipes, deadlines, no confinement
    portable_worker.py  its child side (standard library only, plus worker.py and what it imports)
"""

from .child import Child, canary, probe_name
from .launch import BWRAP_FIX, Limits, SandboxMode, child_env, plain_mode, refusal, runtime_dir, sandbox_mode
from .portable import portable_mode, student_mode

__all__ = ["Limits", "SandboxMode", "sandbox_mode", "plain_mode", "Child", "canary", "probe_name", "runtime_dir",
           "child_env", "refusal", "BWRAP_FIX", "portable_mode", "student_mode"]
