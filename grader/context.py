"""What a check receives: access to the student's code (sandboxed), the reference (same probe, in the grader),
the student's answers, the seed, and a randomized comparison driven by hypothesis."""

from __future__ import annotations

import hashlib
import importlib
import json
import os
from functools import lru_cache
from pathlib import Path

from .checking import CheckFailure, NotAnswered, Tol, assert_close, encode_key
from .errors import GraderFault, StudentCodeError, StudentFault, StudentTimeout, WorkerCrash

__all__ = ["Context", "reference_call"]

_MEMORY_CACHE: dict[str, object] = {}


@lru_cache(maxsize=1)
def _reference_package():
    return importlib.import_module("reference")


@lru_cache(maxsize=1)
def _source_hash() -> str:
    """A hash of the reference and probe sources: persisted reference results are valid for one hash only."""
    digest = hashlib.sha256()
    for package in ("reference", "probes"):
        root = Path(importlib.import_module(package).__file__).parent
        for path in sorted(root.glob("*.py")):
            digest.update(path.name.encode() + b"\0" + path.read_bytes())
    return digest.hexdigest()[:16]


def _cache_dir() -> Path:
    base = os.environ.get("GRADER_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")), "mbd-autograder"
    )
    return Path(base) / _source_hash()


def _run_probe(probe: str, args: tuple):
    module_name, _, func_name = probe.rpartition(".")
    func = getattr(importlib.import_module(f"probes.{module_name}"), func_name)
    return func(_reference_package(), *args)


def reference_call(probe: str, *args, persist: bool = False):
    """The probe's result on the reference, cached in memory (and on disk when ``persist``)."""
    from probes._codec import decode, encode

    key = encode_key(probe, args)
    if key in _MEMORY_CACHE:
        return _MEMORY_CACHE[key]
    path = _cache_dir() / (hashlib.sha256(key.encode()).hexdigest() + ".json") if persist else None
    if path is not None and path.exists():
        try:
            value = decode(json.loads(path.read_text()))
            _MEMORY_CACHE[key] = value
            return value
        except (OSError, ValueError):
            pass
    # Round-trip through the codec so that the reference's result has exactly the student's data types.
    try:
        encoded = encode(_run_probe(probe, args))
    except Exception as exc:  # noqa: BLE001 - any failure here is the grader's
        raise GraderFault(f"the reference failed on {probe}{args!r}: {type(exc).__name__}: {exc}") from exc
    value = decode(encoded)
    _MEMORY_CACHE[key] = value
    if path is not None:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_suffix(f".{os.getpid()}.tmp")
            tmp.write_text(json.dumps(encoded))
            os.replace(tmp, path)
        except OSError:
            pass
    return value


class Context:
    """Per-problem grading context shared by its checks."""

    def __init__(self, problem: int, child, answers: dict | None, answers_error: str | None, seed: int):
        self.problem = problem
        self.child = child
        self._answers = answers or {}
        self._answers_error = answers_error
        self.seed = seed
        self.figures: list = []
        self.last_seed: int | None = None

    # -------------------------------------------------------------- the student's code and the reference

    def student(self, probe: str, *args, timeout: float | None = None):
        """Run ``probe`` on the student's package in the sandbox."""
        return self.child.call(probe, *args, timeout=timeout)

    def reference(self, probe: str, *args, persist: bool = False):
        """Run ``probe`` on the reference (cached)."""
        return reference_call(probe, *args, persist=persist)

    # -------------------------------------------------------------- answers.toml

    def answer(self, key: str):
        """The student's answer ``[problem_NN] key`` from answers.toml; blank answers raise ``NotAnswered``."""
        if self._answers_error:
            raise StudentCodeError("answers", "TOMLDecodeError", self._answers_error, "", "call")
        table = self._answers.get(f"problem_{self.problem:02d}", {})
        value = table.get(key, "") if isinstance(table, dict) else ""
        if value == "" or value is None:
            raise NotAnswered(f'answers.toml: [problem_{self.problem:02d}] {key} is not answered yet')
        return value

    def free_text(self) -> dict:
        table = self._answers.get(f"problem_{self.problem:02d}", {})
        texts = table.get("free_text", {}) if isinstance(table, dict) else {}
        return texts if isinstance(texts, dict) else {}

    # -------------------------------------------------------------- figures

    def add_figure(self, fig) -> None:
        self.figures.append(fig)

    # -------------------------------------------------------------- randomized comparison

    def compare_random(
        self,
        probe: str,
        strategy,
        *,
        name: str,
        tol: Tol,
        examples: int = 20,
        mistakes=None,
        describe=None,
        compare=None,
    ) -> None:
        """Compare the student's ``probe`` with the reference's on inputs drawn from ``strategy`` (a hypothesis
        strategy of argument tuples).  On a mismatch hypothesis shrinks to a minimal failing input; the failure
        names that input and the seed.  ``mistakes(args, expected)`` lists known mistakes for the diagnosis;
        ``compare(got, expected, args)`` replaces the default entrywise comparison."""
        from hypothesis import HealthCheck, Phase, Verbosity, given, settings
        from hypothesis import seed as hyp_seed

        state: dict = {"last": None, "fatal": None}

        def one(args):
            if state["fatal"] is not None:
                raise state["fatal"][1]
            try:
                got = self.student(probe, *args)
            except (StudentTimeout, WorkerCrash) as exc:
                state["fatal"] = (args, exc)
                raise
            expected = self.reference(probe, *args)
            if compare is not None:
                compare(got, expected, args)
            else:
                found = mistakes(args, expected) if mistakes else ()
                assert_close(got, expected, name, tol, found)

        @settings(
            max_examples=examples,
            database=None,
            deadline=None,
            derandomize=False,
            suppress_health_check=list(HealthCheck),
            phases=(Phase.generate, Phase.shrink),
            verbosity=Verbosity.quiet,
            report_multiple_bugs=False,
            print_blob=False,
        )
        @hyp_seed(self.seed)
        @given(strategy)
        def run(args):
            try:
                one(args)
            except (CheckFailure, StudentFault) as exc:
                state["last"] = (args, exc)
                raise

        self.last_seed = self.seed
        try:
            run()
        except (CheckFailure, StudentFault):
            pass
        except Exception as exc:  # noqa: BLE001
            if state["last"] is None and state["fatal"] is None:
                raise GraderFault(f"randomized comparison failed: {type(exc).__name__}: {exc}") from exc
        if state["fatal"] is not None:
            raise state["fatal"][1]
        if state["last"] is None:
            return
        args, exc = state["last"]
        shown = describe(args) if describe else _describe_args(args)
        where = f"on the randomized input {shown}\n(minimal failing input found by hypothesis; seed {self.seed})"
        if isinstance(exc, CheckFailure):
            first, _, rest = exc.message.partition("\n")
            raise CheckFailure(f"{first}\n{where}\n{rest}", exc.hint, exc.diagnosis)
        if isinstance(exc, StudentCodeError) and not exc.not_implemented:
            raise StudentCodeError(exc.kind, exc.type_name, f"{exc.message}\n{where}", exc.traceback, exc.phase)
        raise exc


def _describe_args(args) -> str:
    from .checking import format_array

    parts = []
    for a in args:
        try:
            import numpy as np

            arr = np.asarray(a, dtype=float)
            parts.append(format_array(arr, 6) if arr.ndim else f"{float(arr):.6g}")
        except (TypeError, ValueError):
            parts.append(repr(a)[:200])
    return "(" + ", ".join(parts) + ")"
