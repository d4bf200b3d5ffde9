"""What a check receives: access to the student's code (sandboxed), the reference (through the oracle: the live
reference or the kit's answer key), the student's answers, the seed, and a randomized comparison.

A randomized comparison (``compare_random``) runs in three steps: obtain the inputs, evaluate the student's code on
them, and on a failure pick the input to show.  Live, the inputs are fresh hypothesis draws from the run's seed and
a failure is shrunk by hypothesis to a minimal input; in the kit (and while its key is recorded) the inputs are the
pool recorded for that call site, and a failure shows the simplest failing input of the pool (``simplicity``).
"""

from __future__ import annotations

from .checking import CheckFailure, NotAnswered, Tol, assert_close
from .errors import GraderFault, StudentCodeError, StudentFault, StudentTimeout, WorkerCrash
from .oracle import Oracle, current, draw_pool, private_hypothesis_home

__all__ = ["Context", "simplicity"]


class Context:
    """Per-problem grading context shared by its checks."""

    def __init__(self, problem: int, child, answers: dict | None, answers_error: str | None, seed: int,
                 oracle: Oracle | None = None):
        self.problem = problem
        self.child = child
        self._answers = answers or {}
        self._answers_error = answers_error
        self.seed = seed
        self.oracle = oracle or current()
        self.figures: list = []
        self.last_seed: int | None = None
        self.check_id: str | None = None
        self._sites = 0
        self.carried: list[tuple[str, str]] = []

    def begin(self, check_id: str) -> None:
        """Start a check: its figures, its seed and the numbering of its draw sites begin afresh."""
        self.check_id = check_id
        self.figures = []
        self.last_seed = None
        self._sites = 0
        self.carried = []

    def _site(self) -> str:
        """The name of the next draw site of the running check (``"p06.cardan_values#0"``, ``#1``, ...)."""
        site = f"{self.check_id or f'p{self.problem:02d}'}#{self._sites}"
        self._sites += 1
        return site

    # -------------------------------------------------------------- the student's code and the reference

    def student(self, probe: str, *args, timeout: float | None = None):
        """Run ``probe`` on the student's package in the sandbox."""
        return self.child.call(probe, *args, timeout=timeout)

    def reference(self, probe: str, *args, persist: bool = False):
        """Run ``probe`` on the reference (cached in memory, and on disk when ``persist``); in the kit, the value
        recorded in the answer key."""
        return self.oracle.reference(probe, args, persist, check=self.check_id)

    def draw(self, make):
        """Random data that the check draws itself: ``make(rng)`` with a numpy ``Generator`` returns plain data.
        Live it is drawn from the run's seed; in the kit it is the draw recorded for this site."""
        self.last_seed = self.seed
        return self.oracle.draw(self._site(), make, self.seed, check=self.check_id)

    def carry_forward(self, upstream: str, what: str) -> None:
        """Record that the running check was judged on the student's own ``what`` (e.g. "R1, R2, R3"), which
        differ from the reference's and are graded by the check ``upstream`` (a check id such as
        ``"p06.elementary_values"``): error carried forward.  When the check passes, the runner names the mistake
        once, at the failing check that finds it, and the passing check gets full credit with a pointer there."""
        if (upstream, what) not in self.carried:
            self.carried.append((upstream, what))

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
        strategy of argument tuples).  The failure names the input (minimal, or the simplest of the kit's pool)
        and the seed.  ``mistakes(args, expected)`` lists known mistakes for the diagnosis; ``compare(got,
        expected, args)`` replaces the default entrywise comparison.  Both may reach the reference through
        ``ctx.reference`` with values computed from ``args`` alone, never from the student's answer."""

        def evaluate(args):
            got = self.student(probe, *args)
            expected = self.reference(probe, *args)
            if compare is not None:
                compare(got, expected, args)
            else:
                found = mistakes(args, expected) if mistakes else ()
                assert_close(got, expected, name, tol, found)

        site = self._site()
        if self.oracle.pooled:
            inputs = self.oracle.pool(site, strategy, examples, check=self.check_id)
            failure = _simplest_failure(inputs, evaluate)
            if failure is None:
                return
            args, exc, count = failure
            where = (f"(the simplest of the {count} failing input{'s' * (count != 1)} among the {len(inputs)} "
                     f"recorded random inputs of this check)")
        else:
            self.last_seed = self.seed
            inputs = self._fresh_inputs(strategy, examples)
            failure = _first_failure(inputs, evaluate)
            if failure is None:
                return
            args, exc = self._shrink(strategy, examples, evaluate) or failure
            where = f"(minimal failing input found by hypothesis; seed {self.seed})"
        _raise_at(args, exc, describe, where)

    def _fresh_inputs(self, strategy, examples: int) -> list:
        try:
            return draw_pool(strategy, examples, self.seed)
        except Exception as exc:  # noqa: BLE001 - a strategy that cannot draw is the grader's defect
            raise GraderFault(f"randomized inputs could not be drawn: {type(exc).__name__}: {exc}") from exc

    def _shrink(self, strategy, examples: int, evaluate):
        """Let hypothesis find (again, from the same seed) and shrink a failing input: ``(args, exc)``, or None
        when it finds none (the first failure found is then shown as it is)."""
        from hypothesis import HealthCheck, Phase, Verbosity, given, settings
        from hypothesis import seed as hyp_seed

        private_hypothesis_home()
        state: dict = {"last": None, "fatal": None}

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
            if state["fatal"] is not None:  # no more calls of the student's code: let hypothesis give up
                raise state["fatal"]
            try:
                evaluate(args)
            except (CheckFailure, StudentFault) as exc:
                if _fatal(exc):
                    state["fatal"] = exc
                else:
                    state["last"] = (args, exc)
                raise

        try:
            run()
        except (CheckFailure, StudentFault):
            pass
        except Exception as exc:  # noqa: BLE001
            if state["last"] is None and state["fatal"] is None:
                raise GraderFault(f"randomized comparison failed: {type(exc).__name__}: {exc}") from exc
        if state["fatal"] is not None:
            raise state["fatal"]
        return state["last"]


def _fatal(exc) -> bool:
    return isinstance(exc, (StudentTimeout, WorkerCrash)) or getattr(exc, "not_implemented", False)


def _attempt(evaluate, args):
    """The failure of ``evaluate(args)`` (a ``CheckFailure`` or the student's fault), or None; fatal failures
    (time-outs, crashes, stubs) are raised at once."""
    try:
        evaluate(args)
    except (CheckFailure, StudentFault) as exc:
        if _fatal(exc):
            raise
        return exc
    return None


def _first_failure(inputs, evaluate):
    for args in inputs:
        exc = _attempt(evaluate, args)
        if exc is not None:
            return args, exc
    return None


def simplicity(args) -> tuple:
    """How simple an input is, for choosing the failing input to show from a pool: fewer numbers first (shorter
    lists, fewer steps), then the smaller sum of their magnitudes.  Ties keep the pool's order."""
    import numpy as np

    count, size = 0, 0.0

    def walk(value):
        nonlocal count, size
        if isinstance(value, dict):
            for v in value.values():
                walk(v)
        elif isinstance(value, (list, tuple)):
            for v in value:
                walk(v)
        elif isinstance(value, np.ndarray):
            if value.dtype.kind in "biuf":
                count += value.size
                size += float(np.abs(value).sum())
            else:
                for v in value.ravel():
                    walk(v)
        elif isinstance(value, bool) or value is None:
            count += 1
        elif isinstance(value, (int, float)):
            count += 1
            size += abs(float(value))
        elif isinstance(value, str):
            count += len(value)

    walk(args)
    return count, size


def _simplest_failure(inputs, evaluate):
    """Evaluate every input of a pool: ``(args, exc, number of failing inputs)`` of the simplest failing input,
    or None when all pass."""
    failures = []
    for index, args in enumerate(inputs):
        exc = _attempt(evaluate, args)
        if exc is not None:
            failures.append((simplicity(args), index, args, exc))
    if not failures:
        return None
    _, _, args, exc = min(failures, key=lambda f: (f[0], f[1]))
    return args, exc, len(failures)


def _raise_at(args, exc, describe, where: str):
    shown = describe(args) if describe else _describe_args(args)
    where = f"on the randomized input {shown}\n{where}"
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
