"""Error carried forward across problems: the reference's logic of a later problem applied to the student's own
functions of earlier problems (and, within a problem, to its own functions that another of its checks grades).

One mistake costs its points once, where it is checked.  A student whose ``R3`` is transposed fails problem 6's
check of ``R3``; problem 8's steps and runs use their ``R3`` too, so their values differ from the reference's even
where the student's own code of problem 8 is right.  To judge that code on its own, the grader computes what the
*reference's* code of problem 8 gives with the *student's* ``R3``: a fresh import of the reference under a private
name (a ``Hybrid``), in which every shared function that an earlier problem owns (``SHARED`` of
``checks/_upstream.py``: ``rotations.R3`` is problem 6's) calls the student's function through the sandbox (probe
``_upstream.call``) and hands the student's value back to the reference's code.  The reference never runs in the
student's process: only the student's own functions run there, one call at a time, on plain data.

Each forwarded call is also asked of the reference (``ctx.reference``) and compared: the result (``Upstream``) names
the student's functions whose values differ from the reference's, and the first value that is not *real* (the
check's predicate: finite, of the reference's shape, not zero or constant where the reference's is not, a rotation
orthonormal), after which nothing is carried forward.  A call whose arguments are not plain data (a tree object)
uses the reference's own function.

The student kit holds no reference code and cannot compose anything: while its key is recorded, every such run of
the reference on itself is recorded as the list of forwarded calls; in the kit the student's functions are asked at
those calls, and where one differs the check is left to the graded submission (``JudgedOnSubmission``).
"""

from __future__ import annotations

import inspect
import itertools
from dataclasses import dataclass, replace

from .checking import CheckFailure
from .errors import GraderFault, StudentFault
from .private import close_private, drop_private, private_import, reference_root

__all__ = ["UpstreamCall", "Upstream", "Hybrid", "same"]


@dataclass(frozen=True)
class UpstreamCall:
    """One call of a shared function: ``function`` (``"rotations.R3"``), its arguments, the student's value and the
    reference's (``mine`` is None when the student's function raised: ``error`` says how)."""

    function: str
    args: tuple
    mine: object
    reference: object
    error: str = ""
    #: the difference comes from the student's shared functions that this one calls (the reference's code of this
    #: function on them gives the student's value): those are named, not this one
    explained: bool = False
    #: the index of the call during whose reference code this one was made (-1: the probe's own code)
    parent: int = -1

    def shown(self) -> str:
        """The call as a message names it: ``R3(1.5708)``."""
        from .gate import describe_call

        return describe_call(self.function, self.args)


@dataclass(frozen=True)
class Upstream:
    """What the reference's logic gives on the student's own upstream functions.

    ``value``: the probe's result (None when it could not be computed); ``differing``: the first call of each
    function whose value differs from the reference's, in the order met; ``flaw``: why nothing can be carried
    forward ("" when the student's values are real and the reference's logic ran on them)."""

    value: object
    differing: tuple[UpstreamCall, ...]
    flaw: str = ""

    @property
    def functions(self) -> tuple[str, ...]:
        return tuple(call.function for call in self.differing)


def same(mine, reference) -> bool:
    """True when two plain-data values agree (numbers to ``EXACT``, everything else equal)."""
    import numpy as np

    from .checking import EXACT, close

    if isinstance(reference, dict) or isinstance(mine, dict):
        return (isinstance(mine, dict) and isinstance(reference, dict) and mine.keys() == reference.keys()
                and all(same(mine[k], reference[k]) for k in reference))
    if isinstance(reference, str) or isinstance(mine, str) or reference is None or mine is None:
        return type(mine) is type(reference) and mine == reference  # never ``None == array``: an array
    if isinstance(reference, bool) or isinstance(mine, bool):
        return type(mine) is type(reference) and mine == reference
    try:
        return close(mine, np.asarray(reference, dtype=float), EXACT)
    except (TypeError, ValueError):
        if isinstance(mine, (list, tuple)) and isinstance(reference, (list, tuple)):
            return len(mine) == len(reference) and all(same(a, b) for a, b in zip(mine, reference))
        return False


class _Stop(Exception):
    """Ends a hybrid run: a student's value that nothing can be carried forward on."""

    def __init__(self, flaw: str):
        super().__init__(flaw)
        self.flaw = flaw


_NUMBERS = itertools.count()
#: how the flaw of a run begins where the reference's code raised on the student's values
COULD_NOT_USE = "the reference's code could not use your values"


# ---------------------------------------------------------------------------------------------- the hybrid


class Hybrid:
    """The reference package with the student's own shared functions of problems before ``problem``, and, for a
    check of ``problem``, those of ``problem`` itself that other checks grade (problem 8's runs on the student's own
    ``cardan_rate_matrix``, which ``p08.rate_matrix`` grades): never the function that the check itself grades.

    ``student(probe, *args)`` and ``reference(probe, *args)`` are the grading context's doors; ``shared`` maps
    ``"module.function"`` to ``(the problem that owns it, the check that grades it)``; ``flaw(mine, reference)``
    says why a value of the student's is not real ("" when it is).  ``run(probe, args)`` runs a probe on a fresh
    import of the package (module-level values such as problem 8's ``A_IC0 = R3(pi / 2)`` are computed again, with
    the student's functions, in every run)."""

    def __init__(self, problem: int, shared: dict, student, reference, flaw):
        self.root = reference_root("error carried forward across problems")
        self.problem = problem
        self._shared = shared
        self.forwarded: set[str] = set()
        self._callees: set[str] = set()
        self._for_check(None)
        self._student = student
        self._reference = reference
        self._flaw = flaw
        self._calls: list[UpstreamCall] = []
        self._memo: dict = {}
        self._differences = 0  # values handed to the reference's code that differ from the reference's
        self._parent = -1  # the call whose reference code runs now (see ``_explained``)
        self._explore = False  # while a key is recorded: every forwarded call's own code is run too

    def _for_check(self, check: str | None) -> None:
        """Forward the shared functions of earlier problems, and those of this problem that a check other than
        ``check`` grades: a mistake in one of them costs the points of its own check, once."""
        self.forwarded = {name for name, (owner, grading) in self._shared.items()
                          if owner < self.problem or (owner == self.problem and check is not None
                                                      and grading != check)}
        self._callees = {name.rpartition(".")[2] for name in self.forwarded}

    # -------------------------------------------------------------- the package

    def _fresh(self):
        """A fresh import of the reference under a private name, whose shared functions call the student's."""
        return private_import(f"_carried_{self.problem:02d}_{next(_NUMBERS)}", self.root, self._patch)

    @staticmethod
    def _drop(package) -> None:
        drop_private(package)

    def _patch(self, module_name: str, module) -> None:
        for name in list(vars(module)):
            if f"{module_name}.{name}" in self.forwarded and callable(getattr(module, name)):
                setattr(module, name, self._proxy(module_name, name, getattr(module, name)))

    def _proxy(self, module_name: str, name: str, real):
        signature = inspect.signature(real)
        function = f"{module_name}.{name}"

        def proxy(*args, **kwargs):
            try:
                bound = signature.bind(*args, **kwargs)
                bound.apply_defaults()
                plain = not bound.kwargs and _plain(bound.args)
            except TypeError:
                plain = False
            if not plain:  # arguments that cannot travel (a tree object): the reference's own function
                return real(*args, **kwargs)
            return self._forward(function, tuple(bound.args), real)

        proxy.__name__ = name
        proxy.__doc__ = real.__doc__
        proxy.__wrapped__ = real
        return proxy

    def _forward(self, function: str, args: tuple, real):
        from probes import call_key

        key = call_key(function, args)
        if key not in self._memo:  # the same call again within a run (a constant inside a loop): asked once
            value, differs = self._forward_once(function, args, real)
            self._memo[key] = (value, differs, len(self._calls) - 1)
        else:
            value, differs, index = self._memo[key]
            if self._parent >= 0:  # made inside another call's code: recorded as its child too
                self._calls.append(replace(self._calls[index], parent=self._parent))
        self._differences += differs
        return value

    def _forward_once(self, function: str, args: tuple, real):
        module_name, _, name = function.rpartition(".")
        theirs = self._reference("_upstream.call", module_name, name, list(args))
        try:
            mine = self._student("_upstream.call", module_name, name, list(args))
        except (StudentFault, CheckFailure) as exc:
            call = UpstreamCall(function, args, None, theirs, _reason(exc))
            self._calls.append(call)
            raise _Stop(f"your {name} could not be called ({call.error})") from None
        call = UpstreamCall(function, args, mine, theirs, parent=self._parent)
        self._calls.append(call)
        if same(mine, theirs):
            if self._explore:
                self._explained(real, args, mine, len(self._calls) - 1)
            return theirs, 0
        flaw = self._flaw(mine, theirs, function)
        if flaw:
            raise _Stop(f"your {call.shown()} {flaw}")
        index = len(self._calls) - 1
        if self._explained(real, args, mine, index):
            self._calls[index] = UpstreamCall(function, args, mine, theirs, explained=True, parent=call.parent)
        return mine, 1

    def _explained(self, real, args, mine, index: int) -> bool:
        """True when the reference's code of the function, on the student's own functions it calls (``cardan`` on
        their ``R1``, ``R2``, ``R3``), gives the student's value: the difference is theirs, named at its root.  The
        calls it makes are recorded as the children of call ``index``."""
        if not set(getattr(getattr(real, "__code__", None), "co_names", ())) & self._callees:
            return False  # it calls none of the shared functions: its own difference
        before, parent, self._parent = self._differences, self._parent, index
        try:
            inner = real(*args)
        except _Stop:
            raise
        except Exception:  # noqa: BLE001 - the reference's code of it does not take the student's values
            return False
        finally:
            self._parent = parent
        return self._differences > before and same(mine, inner)

    # -------------------------------------------------------------- running

    def _run(self, probe: str, args: tuple, check: str | None = None):
        """``(value or None, flaw, calls)`` of ``probe(*args)`` on a fresh hybrid package, for the check ``check``."""
        from probes._codec import decode, encode

        func = _probe_function(probe)
        self._for_check(check)
        self._calls, self._memo, self._differences, self._parent = [], {}, 0, -1
        package = None
        try:
            package = self._fresh()
            value, flaw = decode(encode(func(package, *args))), ""
        except _Stop as stop:
            value, flaw = None, stop.flaw
        except (StudentFault, GraderFault):
            raise
        except Exception as exc:  # noqa: BLE001 - the reference's code could not use the student's values
            value, flaw = None, f"{COULD_NOT_USE} ({type(exc).__name__}: {exc})"
        finally:
            if package is not None:
                self._drop(package)
        calls, self._calls, self._memo = self._calls, [], {}
        return value, flaw, calls

    def run(self, probe: str, args: tuple, check: str | None = None) -> Upstream:
        """``probe(*args)`` on the hybrid package, for the check ``check``: its value, the student's calls that
        differ from the reference's (the first per function) and the flaw that stopped it."""
        value, flaw, calls = self._run(probe, args, check)
        first: dict[str, UpstreamCall] = {}
        for call in calls:
            if not call.explained and (call.error or not same(call.mine, call.reference)):
                first.setdefault(call.function, call)
        return Upstream(value, tuple(first.values()), flaw)

    def calls_of(self, probe: str, args: tuple, check: str | None = None) -> list[tuple[str, tuple, int]]:
        """The forwarded calls ``(function, arguments, parent)`` that ``probe(*args)`` makes on the hybrid package,
        in order, each once, and within each the calls its own reference code makes of the shared functions
        (``parent``: the index of the call they belong to, -1 for the probe's own): what the student kit's key
        records of it, to tell there which of the student's functions differ and which of them explain the
        others."""
        self._explore = True
        try:
            calls = self._run(probe, args, check)[2]
        finally:
            self._explore = False
        return [(call.function, call.args, call.parent) for call in calls]

    def close(self) -> None:
        close_private(self)


def _plain(args) -> bool:
    """True when the arguments travel to the sandbox as they are (numbers, arrays, text, lists and dicts of those)."""
    from probes._codec import encode

    try:
        encode(list(args))
    except (TypeError, ValueError):
        return False
    return True


def _probe_function(probe: str):
    from .gate import probe_function

    return probe_function(probe)


def _reason(exc) -> str:
    if isinstance(exc, CheckFailure):
        return exc.message.partition("\n")[0]
    return str(exc).partition("\n")[0][:200]
