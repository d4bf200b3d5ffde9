"""Where a grading gets its sandboxed workers: one way for every caller.

A worker is a materialized submission (``grader.loader.Submission``) and the sandboxed child that imports it
(``grader.sandbox.Child``).  ``runner.grade_submission`` is handed one of three sources of workers:

    Fresh(limits, mode, workdir, count)   a new child for each copy of the submission (``count`` side by side)
    Forked(zygote, limits)                a child forked from a batch slot's warm process (``grader.sandbox.zygote``)
    Started.start(source, limits, mode, count)
                                          children started before the grader imports what grading needs, so that
                                          their start-up overlaps those imports (``grade problem-N`` does)

Each says which sandbox it grades in (``sandbox``), how many workers a grading of some problems takes
(``side_by_side``), hands them out (``obtain``: the submission materialized, the child not yet asked anything) and
removes the copies it made once the grading is done (``release``).  The copies of ``Started`` are its caller's: the
caller removes them.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from .errors import SubmissionError
from .loader import Submission, cleanup, materialize
from .sandbox import Child, Limits, SandboxMode, sandbox_mode

__all__ = ["Worker", "Workers", "Fresh", "Forked", "Started"]


@dataclass(frozen=True)
class Worker:
    """One submission's copy and the sandboxed child that grades it."""

    submission: Submission
    child: Child


class Workers:
    """A source of workers (``Fresh``, ``Forked`` or ``Started``)."""

    def sandbox(self) -> SandboxMode:
        """The sandbox its workers run in (said in the reports, also of a submission that cannot be loaded)."""
        raise NotImplementedError

    def side_by_side(self, problems: int) -> int:
        """How many workers grade ``problems`` problems of one submission side by side."""
        return 1

    def _ready(self) -> tuple[Worker, ...]:
        """The workers that exist before the grading asks for any (its caller's: never released here)."""
        return ()

    def _make(self, source) -> Worker:
        """A new worker for ``source``: its copy materialized, its child created but not started."""
        raise NotImplementedError

    def obtain(self, source: str | Path, count: int) -> list[Worker]:
        """``count`` workers for ``source``: those ready first, then new ones.  Raises ``SubmissionError`` when the
        submission cannot be loaded, after removing what it made."""
        workers = list(self._ready()[:count])
        made: list[Worker] = []
        try:
            while len(workers) + len(made) < count:
                made.append(self._make(source))
        except SubmissionError:
            for worker in made:
                worker.child.__exit__(None, None, None)
                cleanup(worker.submission)
            raise
        return workers + made

    def release(self, workers: list[Worker]) -> None:
        """Remove the copies of the submission that ``obtain`` made (the children are ended by their grading)."""
        ready = {id(worker) for worker in self._ready()}
        for worker in workers:
            if id(worker) not in ready:
                cleanup(worker.submission)


@dataclass(frozen=True)
class Fresh(Workers):
    """A fresh sandboxed child for each worker: with ``limits``, in ``mode`` (default: the machine's sandbox,
    ``grader.sandbox.sandbox_mode``), the submission copied under ``workdir`` (default: the system's temporary
    folder); ``count`` workers share out the problems of one submission (``runner.grade_submission``)."""

    limits: Limits | None = None
    mode: SandboxMode | None = None
    workdir: str | Path | None = None
    count: int = 1

    def sandbox(self) -> SandboxMode:
        return self.mode or sandbox_mode()

    def side_by_side(self, problems: int) -> int:
        return max(1, min(self.count, problems))

    def _make(self, source) -> Worker:
        submission = materialize(source, self.workdir)
        return Worker(submission, Child(submission.path, self.limits, self.mode))


@dataclass(frozen=True)
class Forked(Workers):
    """One child forked from ``zygote``, a batch slot's warm process (``grader.sandbox.zygote.Zygote``), in its
    mode, the submission copied into its staging folder; ``limits`` bound each call.  ``on_grace`` (if given) is
    told every second a call was granted because its worker waited for a processor (``grader.sandbox.queueing``):
    the batch's bound of a student's time moves on by as much."""

    zygote: object
    limits: Limits | None = None
    on_grace: object = None

    def sandbox(self) -> SandboxMode:
        return self.zygote.mode

    def _make(self, source) -> Worker:
        submission = materialize(source, self.zygote.staging)
        return Worker(submission, Child(submission.path, self.limits, zygote=self.zygote, on_grace=self.on_grace))


@dataclass(frozen=True)
class Started(Workers):
    """Workers already started (``start``), their children importing the submission while the caller goes on;
    ``count`` workers in all, those missing made fresh with ``limits`` in the started ones' mode.  The started
    workers' copies are the caller's to remove."""

    ready: tuple[Worker, ...]
    limits: Limits | None = None
    count: int = 1

    @classmethod
    def start(cls, source: str | Path, limits: Limits | None, mode: SandboxMode, count: int) -> Started | None:
        """Materialize ``source`` ``count`` times and start a child on each copy, in ``mode``.  None when the
        submission cannot be loaded at all (the grading then says why); after an interruption or a failure to
        start, every child is ended and every copy removed."""
        ready: list[Worker] = []
        try:
            for _ in range(count):
                try:
                    submission = materialize(source)
                except SubmissionError:
                    break
                worker = Worker(submission, Child(submission.path, limits, mode))
                ready.append(worker)
                worker.child.start()
        except BaseException:
            for worker in ready:
                worker.child.__exit__(None, None, None)
                cleanup(worker.submission)
            raise
        return cls(tuple(ready), limits, count) if ready else None

    @property
    def submissions(self) -> tuple[Submission, ...]:
        return tuple(worker.submission for worker in self.ready)

    def sandbox(self) -> SandboxMode:
        return self.ready[0].child.mode

    def side_by_side(self, problems: int) -> int:
        return max(1, min(self.count, problems))

    def _ready(self) -> tuple[Worker, ...]:
        return self.ready

    def _make(self, source) -> Worker:
        return Fresh(self.limits, self.sandbox())._make(source)
