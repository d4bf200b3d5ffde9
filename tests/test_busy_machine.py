"""A call's time limit on a busy machine: the time the student's code waited for a processor is the machine's, not
the student's (``grader.sandbox.queueing``).

Each case runs in a process of its own pinned to one processor, beside processes that keep that processor busy,
and calls problem 6's ``frames`` of a submission through a ``Child``.  Outcomes only, never durations."""

import json
import os
import subprocess
import sys
import textwrap
import time

import pytest

from grader.sandbox import refusal, sandbox_mode
from grader.sandbox.queueing import Queueing, waited

from .submissions import ROOT, build_hostile, copy_reference

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the scheduler's counts are Linux's")

#: the case's process: pinned to one processor with ``hogs`` busy processes, it calls ``frames`` once the worker
#: answered a first call, and prints what came of it
CASE = textwrap.dedent("""
    import json, os, subprocess, sys
    sys.path.insert(0, {root!r})
    from grader.errors import MachineBusy, StudentTimeout
    from grader.loader import materialize
    from grader.sandbox import Child, Limits, sandbox_mode
    os.sched_setaffinity(0, {{{cpu}}})
    hogs = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range({hogs})]
    submission = materialize({path!r})
    try:
        with Child(submission.path, Limits(call_timeout={limit}), sandbox_mode()) as child:
            child.call("problem_06.elementary", 1, 0.5)
            try:
                child.call("problem_06.frames")
                outcome = "answered"
            except StudentTimeout:
                outcome = "timeout"
            except MachineBusy as exc:
                outcome = "busy: " + str(exc)
    finally:
        for hog in hogs:
            hog.kill()
    print(json.dumps(outcome))
""")

#: problem 6's frames after 0.5 s of the processor's time: honest work that needs half its limit of 1 s
SLOW = '''
def _spend(seconds):
    import time
    end = time.process_time() + seconds
    while time.process_time() < end:
        pass


def frames():
    _spend(0.5)
    return _frames()
'''

#: problem 6's frames that keeps the processor busy with processes of its own and never answers
CROWD = '''
def frames():
    import os
    for _ in range(4):
        if os.fork() == 0:
            while True:
                pass
    while True:
        pass
'''


def _submission(tmp_path, text):
    folder = copy_reference(tmp_path / "pkg")
    source = folder / "problem_06.py"
    source.write_text(source.read_text().replace("def frames():", "def _frames():", 1) + text)
    return folder


def _outcome(path, hogs, limit=1.0, case=CASE, **values):
    """What the ``case`` script printed, run for the submission ``path`` beside ``hogs`` busy processes."""
    if not sandbox_mode().isolated and refusal() is not None:
        pytest.skip("covered by the refusal: no child runs here without bubblewrap")
    cpu = min(os.sched_getaffinity(0))
    script = case.format(root=str(ROOT), cpu=cpu, hogs=hogs, path=str(path), limit=limit, **values)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_the_counts_of_a_process_tree_are_read_and_of_no_process_none():
    here = waited(os.getpid())
    assert isinstance(here, Queueing) and here.cpu > 0 and here.wait >= 0
    assert waited(None) is None and waited(0) is None
    gone = subprocess.Popen([sys.executable, "-c", "pass"])
    gone.wait()
    assert waited(gone.pid) is None


def test_honest_work_that_waits_for_a_busy_processor_is_answered_not_timed_out(tmp_path):
    """Half a second of work under a limit of one second, on a processor shared with two busy processes: about 1.5 s
    of wall time, most of it waiting.  Before the wait was counted the machine's, this was the student's time-out."""
    outcome = _outcome(_submission(tmp_path, SLOW), hogs=2)
    assert outcome == "answered" or outcome.startswith("busy"), outcome


def test_code_that_never_answers_is_still_the_students_time_out_on_a_busy_processor(tmp_path):
    assert _outcome(build_hostile("infinite_loop_call", tmp_path / "pkg"), hogs=2) == "timeout"


def test_code_that_crowds_the_processor_with_its_own_processes_gets_no_more_time(tmp_path):
    """Its main process waits for its own busy children: it used that time, so it is granted none, and its time-out
    is the student's, not the machine's."""
    assert _outcome(_submission(tmp_path, CROWD), hogs=0) == "timeout"


#: the batch's case: pinned to one processor with ``hogs`` busy processes, a batch slot grades problem 6 of a
#: submission within a per-student bound of ``bound`` seconds, and prints what came of it
BATCH_CASE = textwrap.dedent("""
    import json, multiprocessing, os, subprocess, sys
    from pathlib import Path
    sys.path.insert(0, {root!r})
    from grader.batch.discover import Entry, submission_hash
    from grader.batch.pool import Slot, Task
    from grader.sandbox import Limits, sandbox_mode
    os.sched_setaffinity(0, {{{cpu}}})
    limits = Limits(call_timeout=2.0, import_timeout=2.0)
    slot = Slot(multiprocessing.get_context("spawn"), 1, limits, sandbox_mode(), (6,))
    slot.wait_ready()  # its start is not the student's time
    hogs = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range({hogs})]
    path = Path({path!r})
    try:
        kind, payload, seconds = slot.outcome(Task(Entry("student", path, submission_hash(path), seed=1), (6,)),
                                              {bound})
    finally:
        for hog in hogs:
            hog.kill()
        slot.stop()
    if kind == "ok":
        kind = "graded " + " ".join(sorted({{r.status.value for rep in payload for r in rep.results}}))
    print(json.dumps(kind))
""")

#: problem 6 whose import takes 0.6 s of the processor's time: honest, within its import limit of 2 s when it has
#: a processor, about three times that on a processor shared with two busy processes
SLOW_IMPORT = '''
import time as _time
_end = _time.process_time() + 0.6
while _time.process_time() < _end:
    pass
'''


def _batch_outcome(path, hogs, bound):
    return _outcome(path, hogs, case=BATCH_CASE, bound=bound)


@pytest.mark.slow
def test_a_batch_bound_of_a_students_time_moves_on_by_the_machines_load(tmp_path):
    """The bound of 1.5 s per student holds an import of 0.6 s with room to spare, and not the same import on a
    processor shared with two busy processes: before the bound moved on by the time the student's code and the
    worker waited for the processor, this honest work was stopped and filed as the student's time-out."""
    folder = copy_reference(tmp_path / "pkg")
    source = folder / "problem_06.py"
    source.write_text(SLOW_IMPORT + source.read_text())
    outcome = _batch_outcome(folder, hogs=2, bound=1.5)
    assert outcome == "graded passed" or outcome == "busy", outcome


@pytest.mark.slow
def test_a_batch_bound_still_stops_code_that_sleeps_on_a_busy_machine(tmp_path):
    """Half a second of sleep in every rotation: no wait for a processor, so no grace — the student's time-out."""
    folder = copy_reference(tmp_path / "pkg")
    rotations = folder / "rotations.py"
    rotations.write_text(rotations.read_text().replace(
        "    c, s = np.cos(alpha), np.sin(alpha)\n",
        "    import time\n    time.sleep(0.5)\n    c, s = np.cos(alpha), np.sin(alpha)\n", 1))
    assert _batch_outcome(folder, hogs=2, bound=1.5) == "timeout"


class _Line:
    """The parent's end of a worker's pipe, holding the messages the worker sent."""

    def __init__(self, *messages):
        self.messages = list(messages)

    def poll(self):
        return bool(self.messages)

    def recv(self):
        return self.messages.pop(0)

    def send(self, task):
        pass


class _Working:
    """A worker process that is alive and never answers (this process, for its scheduler counts)."""

    pid = os.getpid()

    def is_alive(self):
        return True


def _slot(*messages):
    """A batch slot over a worker that sent ``messages``, with no process of its own started or stopped."""
    from grader.batch.pool import Slot

    class Held(Slot):
        def _start(self):
            self.conn, self.process, self.ready = _Line(*messages), _Working(), True

        def restart(self):
            self.restarted = True

    return Held(None, 1, None, None, (6,))


def test_a_grant_the_worker_tells_moves_the_bound_of_the_student_on_within_its_grace():
    from grader.batch.pool import LOAD_GRACE

    slot = _slot(("grace", 0.5), ("grace", 100.0))
    slot.submit("task", 2.0)
    first = slot.deadline
    assert slot.poll() is None and slot.deadline == pytest.approx(first + 0.5)
    assert slot.poll() is None and slot.deadline == pytest.approx(first + LOAD_GRACE * 2.0)  # at most the grace


def test_a_student_still_running_when_the_grace_is_spent_is_the_machines_fault_not_a_time_out():
    slot = _slot(("grace", 100.0))
    slot.submit("task", 1.0)
    assert slot.poll() is None
    slot.deadline = 0.0  # the moved-on bound passed too
    kind, message = slot.poll()
    assert kind == "busy" and "too busy" in message and slot.restarted


def test_a_student_past_the_bound_with_no_grant_is_stopped_as_a_time_out():
    slot = _slot()
    slot.submit("task", 1.0)
    slot.deadline = slot.started = 0.0  # sent long ago: this process's counts since then, not a wait
    slot._counts = None  # and nothing read of them when it was sent: no grant can be computed
    assert slot.poll() == ("timeout", 0.0) and slot.restarted


def test_the_wait_of_a_students_process_that_ended_before_the_bound_still_moves_it_on(monkeypatch):
    """The student's process waits for a processor, answers and ends; the worker then writes its reports when the
    bound comes.  Read only at the bound, the tree has no process that waited and the honest student was stopped
    as a time-out; read while it works, the ended process keeps its wait."""
    from grader.batch import pool

    worker, student = 1, 2
    reads = iter([({worker: 0.0}, 0.0),  # when the task is sent
                  ({worker: 0.01, student: 1.2}, 0.4),  # while the student's process waits for a processor
                  ({worker: 0.02}, 0.6)])  # at the bound: the student's process ended
    monkeypatch.setattr(pool, "task_counts", lambda pid: next(reads))
    slot = _slot()
    slot.submit("task", 1.0)
    slot.read_counts()
    slot.started = time.monotonic() - 1.5  # sent 1.5 s ago: the bound of 1 s passed
    slot.deadline = slot.started + 1.0
    assert slot.poll() is None and slot.granted == pytest.approx(0.9, abs=0.05)  # min(1.2 waited, 1.5 - 0.6 off a processor)


def test_a_slot_reads_its_trees_counts_while_it_works_not_only_at_its_bound():
    slot = _slot()
    slot.submit("task", 60.0)
    assert slot.wakeup() <= slot.started + 1.0 and not slot.read_due()
    slot.read_at -= 1.0
    assert slot.read_due()
