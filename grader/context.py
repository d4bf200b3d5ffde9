"""What a check receives: access to the student's code (sandboxed), the reference (through the oracle: the live
reference or the kit's answer key), the student's answers, the seed, and a randomized comparison.

A randomized comparison (``compare_random``) runs in three steps: obtain the inputs, evaluate the student's code on
them, and on a failure pick the input to show and name the mistake.  Live, the inputs are fresh draws from the
run's seed (``grader.strategies``: no hypothesis while everything passes) and a failure brings hypothesis in to
shrink it to a minimal input; in the kit (and while its key is recorded) the inputs are the pool recorded for that
call site, and a failure shows the simplest failing input of the pool (``simplicity``).  The diagnosis is checked on
a second failing input, drawn rather than shrunk: a minimal input is often degenerate (zero angles, an axis-aligned
angular velocity) where several known mistakes give the same value; a mistake is named only when it matches on
both, and when several still do, all of them are ("could be X or Y").
"""

from __future__ import annotations

import threading

import probes

from .checking import (
    CheckFailure,
    JudgedOnSubmission,
    NotAnswered,
    Tol,
    assert_close,
    at_sheet_digits,
    diagnose,
    property_of,
    random_input,
)
from .diagnosis import doubt, explain, judge, rival, symptom, prepare_call, prepared, recording, remember_run, trace
from .errors import GraderFault, ProbeFault, StudentCodeError, StudentFault, ends_grading
from .gate import admit, form_of
from .oracle import Oracle, current, draw_pool, hypothesis_run

#: hypothesis's engine is not meant to run in two threads at once
_HYPOTHESIS = threading.Lock()

__all__ = ["Context", "Catalogue", "Judged", "simplicity", "explained"]


def _probe_name(probe):
    """The name of ``probe`` (``"problem_22.loop"``) at the context's doors: checks name a probe by its function
    (``ctx.student(p22.loop, ...)``), and everything behind the doors (the sandbox's protocol, the oracle's cache,
    the kit's answer key, the diagnosis engine, the logs) keeps its name.  A probe function outside the probes
    package (a test's own, answered by a stand-in child and oracle) passes as it is; an object that is no probe is
    the grader's fault."""
    try:
        return probes.name_of(probe)
    except probes.ProbeLookupError as exc:
        if callable(probe) and getattr(probe, "is_probe", False):
            return probe
        raise ProbeFault(f"a check asks for {probe!r}, which is no probe: {exc}") from exc


class Context:
    """Per-problem grading context shared by its checks."""

    def __init__(self, problem: int, child, answers: dict | None, answers_error: str | None, seed: int,
                 oracle: Oracle | None = None, record_answers: bool = False):
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
        #: the wrong answers on fixed inputs of the checks that did not pass (``grader.answers``): recorded by a
        #: batch, with the live reference, for ``grade similarity``
        self.wrong_answers: list = []
        self._recording = record_answers and self.oracle.mode == "live"
        self._fixed = True  # the running check's inputs are the same for every student (no random draw yet)
        self._asked: list[tuple[str, tuple, object]] = []  # the running check's fixed calls of the student's code
        self._referenced: list[tuple[str, tuple, object]] = []  # the running check's fixed calls of the reference
        self._common: list[tuple[str, str, str, object]] = []  # failed randomized comparisons: check, site, probe
        #: the running check's calls ``(side, probe, args, value)``, side "reference" or "student": the diagnosis
        #: engine finds there where a compared value came from
        self.calls: list[tuple] = []
        #: True while a randomized comparison evaluates its inputs (the engine's second input is then its own)
        self.randomized = False
        self._hybrid = None
        #: the running check used a value that the kit's key holds at the sheet's digits only
        self.sheet_digits = False

    def close(self) -> None:
        """End the problem's grading: the reference's code composed with the student's functions is dropped."""
        if self._hybrid is not None:
            self._hybrid.close()
            self._hybrid = None
        at_sheet_digits(False)

    def begin(self, check_id: str) -> None:
        """Start a check: its figures, its seed, the numbering of its draw sites and its log of calls begin
        afresh."""
        self.check_id = check_id
        self.figures = []
        self.last_seed = None
        self._sites = 0
        self.carried = []
        self._fixed = True
        self._asked = []
        self._referenced = []
        self.calls = []
        self.__dict__.pop("_engine_prepared", None)
        recording(self if self.oracle.mode == "record" else None)
        self.sheet_digits = False
        at_sheet_digits(False)

    def end(self, passed: bool) -> None:
        """End the running check: when recording and the check did not pass, keep the student's answers on its
        fixed inputs that differ from the reference's on the same call."""
        if self._recording and not passed and self._asked and self._referenced:
            from .answers import wrong_answer
            from probes import call_key

            expected = {call_key(probe, args): value for probe, args, value in self._referenced}
            for probe, args, value in self._asked:
                key = call_key(probe, args)
                if key in expected:
                    found = wrong_answer(self.check_id or "", probe, args, value, expected[key])
                    if found is not None and found not in self.wrong_answers:
                        self.wrong_answers.append(found)
        self._asked = []
        self._referenced = []

    def _note(self, probe: str, args: tuple, value) -> None:
        if self._recording and self._fixed:
            self._asked.append((probe, args, value))

    def _site(self) -> str:
        """The name of the next draw site of the running check (``"p06.cardan_values#0"``, ``#1``, ...)."""
        site = f"{self.check_id or f'p{self.problem:02d}'}#{self._sites}"
        self._sites += 1
        return site

    # -------------------------------------------------------------- the student's code and the reference

    def student(self, probe, *args, timeout: float | None = None):
        """Run ``probe`` (a probe function, ``p22.loop``) on the student's package in the sandbox; the reply has the
        probe's form (``grader.gate``), or the check fails saying that it cannot be graded."""
        probe = _probe_name(probe)
        form_of(probe)  # a probe that cannot be asked of a student is the grader's defect, found before it runs
        value = admit(probe, args, self.child.call(probe, *args, timeout=timeout))
        self._note(probe, args, value)
        self.calls.append(("student", probe, args, value))
        remember_run(self, probe, args, value)
        return value

    def student_later(self, probe, *args, timeout: float | None = None):
        """Send the call of ``probe`` to the student's code now; returns a function that waits for its value (held
        to the probe's form, as ``student``'s), so that the grader's own work in between (the reference, a
        catalogue of mistakes) overlaps the student's code.  A child without ``call_later`` is called at once."""
        probe = _probe_name(probe)
        form_of(probe)
        later = getattr(self.child, "call_later", None)
        if later is not None:
            wait = later(probe, *args, timeout=timeout)
            noting = self._recording and self._fixed

            def value_later():
                value = admit(probe, args, wait())
                if noting:
                    self._asked.append((probe, args, value))
                self.calls.append(("student", probe, args, value))
                remember_run(self, probe, args, value)
                return value

            return value_later
        try:
            value = self.student(probe, *args, timeout=timeout)
        except StudentFault as exc:
            failure = exc

            def raise_later():
                raise failure

            return raise_later
        return lambda: value

    def reference(self, probe, *args, persist: bool = False):
        """Run ``probe`` on the reference (cached in memory, and on disk when ``persist``); in the kit, the value
        recorded in the answer key (a fixed case at the sheet's digits only: the check's comparisons then allow for
        them, and a pass says so)."""
        probe = _probe_name(probe)
        value = self.oracle.reference(probe, args, persist, check=self.check_id)
        if self._recording and self._fixed:
            self._referenced.append((probe, args, value))
        self.calls.append(("reference", probe, args, value))
        if self.oracle.mode == "record":
            prepared(self, probe, args)
        held = getattr(self.oracle, "held_at_sheet_digits", None)
        if held is not None and held(probe, args):
            self.sheet_digits = True
            at_sheet_digits(True)
        return value

    def catalogue(self, compute):
        """A catalogue of known mistakes: ``compute()`` returns it (a list, from ``ctx.reference`` calls on the
        inputs alone), computed when it is first consulted, i.e. when a comparison fails: a passing comparison
        costs no mistaken computation.  While the kit's answer key is recorded it is computed at once, so that
        the key holds its reference calls for every input whatever the comparison finds (the kit consults them
        when a student's value fails there)."""
        catalogue = Catalogue(compute)
        if self.oracle.mode == "record":
            catalogue.items()
        return catalogue

    def draw(self, make):
        """Random data that the check draws itself: ``make(rng)`` with a numpy ``Generator`` returns plain data.
        Live it is drawn from the run's seed; in the kit it is the draw recorded for this site."""
        self.last_seed = self.seed
        self._fixed = False  # the student's own random data from here on: nothing to compare with another's
        return self.oracle.draw(self._site(), make, self.seed, check=self.check_id)

    def carry_forward(self, upstream: str, what: str) -> None:
        """Record that the running check was judged on the student's own ``what`` (e.g. "R1, R2, R3"), which
        differ from the reference's and are graded by the check ``upstream`` (a check id such as
        ``"p06.elementary_values"``): error carried forward.  When the check passes, the runner names the mistake
        once, at the failing check that finds it, and the passing check gets full credit with a pointer there."""
        if (upstream, what) not in self.carried:
            self.carried.append((upstream, what))

    def upstream(self, probe, args: tuple, shared: dict, flaw) -> "Judged":
        """What the reference's code of ``probe(*args)`` gives on the student's own functions of earlier problems
        (error carried forward across problems, ``grader.upstream``): a ``Judged`` whose ``result()`` is computed
        when first asked, i.e. when the student's answer differs from the reference's.  ``shared`` maps
        ``"module.function"`` to ``(the problem that owns it, the check that grades it)``; ``flaw(mine,
        reference)`` says why a value of the student's is not real ("" when it is).  While the kit's key is
        recorded, the calls are recorded at once; in the kit the student's functions are compared at those calls."""
        from probes import call_key

        probe = _probe_name(probe)
        key = call_key(probe, args)
        if self.oracle.mode == "record":
            self.oracle.record_upstream(key, self._hybrid_for(shared, flaw).calls_of(probe, args, self.check_id))
        return Judged(self, probe, tuple(args), key, shared, flaw)

    def _hybrid_for(self, shared, flaw):
        from .upstream import Hybrid

        if self._hybrid is None:
            self._hybrid = Hybrid(self.problem, shared, self.student, self.reference, flaw)
        return self._hybrid

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
        probe,
        strategy,
        *,
        name: str,
        tol: Tol,
        examples: int = 20,
        mistakes=None,
        describe=None,
        compare=None,
    ) -> None:
        """Compare the student's ``probe`` with the reference's on inputs drawn from ``strategy`` (a strategy of
        argument tuples from ``grader.strategies``, or a hypothesis strategy).  The failure names the input
        (minimal, or the simplest of the kit's pool) and the seed, and a known mistake that matches there and on a
        second failing input.  ``mistakes(args, expected)`` lists known mistakes for the diagnosis; ``compare(got,
        expected, args)`` replaces the default entrywise comparison.  Both may reach the reference through
        ``ctx.reference`` with values computed from ``args`` alone, never from the student's answer.  Where the
        student's code raises, ``compare.carried_error(exc, args)`` (if ``compare`` has it) may take the error as
        carried forward (True: the input passes), as ``checks._upstream.judged_comparison`` does where the
        reference's code raises alike on the student's own shared functions; only where some other input was
        judged by its value: code that raises on every input earns nothing, whatever raised it."""
        probe = _probe_name(probe)
        #: an error of the student's code carried forward (the first), and whether an input was judged by its value
        errors = {"carried": None, "judged": False}

        def evaluate(args):
            with random_input():  # a failure here may show the digits it needs: the next grading draws anew
                got = self.student_later(probe, *args)  # the reference and the catalogue meanwhile
                expected = self.reference(probe, *args)
                found = mistakes(args, expected) if mistakes and compare is None else ()
                try:
                    got = got()
                except StudentCodeError as exc:  # raised where the reference's code on their own functions does
                    carried = getattr(compare, "carried_error", None)
                    if carried is None or ends_grading(exc) or not carried(exc, args):
                        raise
                    errors["carried"] = errors["carried"] or exc
                    return
                errors["judged"] = True
                if compare is None:
                    assert_close(got, expected, name, tol, found)
                    return
                if self.oracle.mode == "record":
                    prepare_call(self, probe, args)
                try:
                    compare(got, expected, args)
                except CheckFailure as exc:  # the engine may explain the results the compared values came from
                    if exc.evidence is not None and exc.evidence.call is None:
                        exc.evidence.call = (probe, tuple(args), got, expected)
                    raise

        site = self._site()
        fixed, self._fixed = self._fixed, False  # each student's own random inputs: never recorded
        try:
            self._compare_random(site, strategy, evaluate, examples, describe)
        except CheckFailure:
            if self._recording and fixed:  # asked on the input every student is asked, after the last check
                self._common.append((self.check_id or "", site, probe, strategy))
            raise
        finally:
            self._fixed = fixed
        if errors["carried"] is not None and not errors["judged"]:  # raised on every input: nothing of it judged
            raise errors["carried"]

    def ask_common(self, failed: set[str]) -> None:
        """After the problem's last check: ask the student's code once more for each randomized comparison that
        failed in a check of ``failed``, on the input of its site that every such student is asked
        (``COMMON_SEED``), so that ``grade similarity`` can compare the wrong answers of students whose random
        inputs all differ.  Only when recording, and only now, when no check is left that the call could change
        (a student's code that keeps state between calls); a failure here changes nothing of the grade."""
        import zlib

        from .answers import wrong_answer

        pending, self._common = self._common, []
        for check_id, site, probe, strategy in pending:
            if check_id not in failed:
                continue
            try:
                args = tuple(draw_pool(strategy, 2, COMMON_SEED ^ zlib.crc32(site.encode()))[-1])
                value = self.child.call(probe, *args)
                expected = self.oracle.reference(probe, args, False, check=check_id)
                found = wrong_answer(check_id, probe, args, value, expected)
            except Exception:  # noqa: BLE001 - the grade is decided already; this only feeds the similarity report
                continue
            if found is not None and found not in self.wrong_answers:
                self.wrong_answers.append(found)

    def _compare_random(self, site: str, strategy, evaluate, examples: int, describe) -> None:
        """Run a randomized comparison: find the failing input to show, name its mistake (the catalogue's narrowed
        on a second failing input, else the diagnosis engine's), and raise its failure."""
        self.randomized = True
        try:
            shown, where, failures = self._compare(site, strategy, examples, evaluate)
        finally:
            self.randomized = False
        if shown is None:
            return
        args, exc = shown
        _raise_at(args, self._narrowed(exc, failures), describe, where)

    def _compare(self, site, strategy, examples, evaluate):
        """``(shown, where, failures)`` of a randomized comparison: the failing input to show (None when every
        input passes), where it comes from, and every failure found."""
        if self.oracle.pooled:
            inputs = self.oracle.pool(site, strategy, examples, check=self.check_id)
            failures = _failures(inputs, evaluate)
            if not failures:
                return None, "", failures
            shown = _simplest(failures)
            where = (f"(the simplest of the {len(failures)} failing input{'s' * (len(failures) != 1)} among the "
                     f"{len(inputs)} recorded random inputs of this check)")
        else:
            self.last_seed = self.seed
            inputs = self._fresh_inputs(strategy, examples)
            failures = _failures(inputs, evaluate, until_generic=True)
            if not failures:
                return None, "", failures
            shown = self._shrink(strategy, examples, evaluate)
            if shown is not None:
                where = f"(minimal failing input found by hypothesis; seed {self.seed})"
            else:
                shown = _simplest(failures)
                where = f"(the simplest failing input of the {len(inputs)} random inputs drawn; seed {self.seed})"
        return shown, where, failures

    def _narrowed(self, shown, failures):
        """The failure of the input shown, its diagnosis checked on the second failing input (``_narrowed``); when
        no known mistake names it, the diagnosis engine is asked with the comparison shown and the one of another
        failing input, the generic one where it can (a single failing input names no cause: a slip of the grammar
        fails on every generic input)."""
        failure = _narrowed(shown, _generic(failures)[1])
        if not isinstance(failure, CheckFailure) or failure.diagnosis or failure.explained:
            return failure
        if failure.evidence is None:
            return self._told_beside(failure, failures)
        first = property_of(shown)
        others = [exc for _, _, exc in sorted(failures, key=lambda f: (f[0] == 0, f[0]))
                  if exc is not shown and isinstance(exc, CheckFailure) and exc.evidence is not None
                  and property_of(exc) == first]
        if not others and any(exc is not shown for _, _, exc in failures):  # another input failed at another
            # place (a trace's other entry, another step): the engine is asked on the comparison shown, and draws
            # its second input itself
            return explained(self, failure, [failure.evidence])
        if not others:
            return CheckFailure(failure.message, failure.hint, failure.diagnosis, failure.candidates,
                                failure.evidence, explained=True)
        return explained(self, failure, [failure.evidence, others[0].evidence])

    def _told_beside(self, failure: CheckFailure, failures) -> CheckFailure:
        """A failure shown without a comparison (the student's code raised, or a property stated in words), where
        other failing inputs of the same check did compare the student's value with the reference's: the cause
        the diagnosis engine finds there (on two of them, or on one and its own second input) told beside the
        failure shown, which stays as it is.  Asked once (``explained``)."""
        compared = [exc for _, _, exc in sorted(failures, key=lambda f: (f[0] == 0, f[0]))
                    if exc is not failure and isinstance(exc, CheckFailure) and exc.evidence is not None
                    and not exc.diagnosis]
        alike = [exc for exc in compared if compared and property_of(exc) == property_of(compared[0])]
        finding = None
        if len(alike) > 1:
            finding = explained(self, alike[0], [alike[0].evidence, alike[1].evidence])
        elif alike and alike[0].evidence.call is not None:
            found = judge(self, alike[0].evidence)
            if found is not None and found.names:
                finding = CheckFailure(alike[0].message, found.hint, found.diagnosis, explained=True)
        if finding is None or not finding.diagnosis:
            return CheckFailure(failure.message, failure.hint, failure.diagnosis, failure.candidates,
                                failure.evidence, explained=True)
        hint = "\n".join(part for part in (failure.hint, f"On another input where your function returned a value: "
                                             f"{finding.hint[:1].lower()}{finding.hint[1:]}") if part)
        return CheckFailure(failure.message, hint, finding.diagnosis, failure.candidates, failure.evidence,
                            explained=True)

    def _fresh_inputs(self, strategy, examples: int) -> list:
        try:
            return draw_pool(strategy, examples, self.seed)
        except Exception as exc:  # noqa: BLE001 - a strategy that cannot draw is the grader's defect
            raise GraderFault(f"randomized inputs could not be drawn: {type(exc).__name__}: {exc}") from exc

    def _shrink(self, strategy, examples: int, evaluate):
        """Bring hypothesis in to find (from the run's seed) and shrink a failing input: ``(args, exc)`` of the
        minimal one, or None when it finds none in its examples (the failure found is then shown as it is)."""
        with _HYPOTHESIS:  # one shrink at a time in a process (problems graded side by side: one thread each)
            return self._shrink_alone(strategy, examples, evaluate)

    def _shrink_alone(self, strategy, examples: int, evaluate):
        from hypothesis import HealthCheck, Phase, Verbosity, given, settings
        from hypothesis import seed as hyp_seed

        from .strategies import to_hypothesis

        state: dict = {"last": None, "fatal": None}

        @settings(
            max_examples=SHRINK_SEARCH * examples + 10,
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
        @given(to_hypothesis(strategy))
        def run(args):
            if state["fatal"] is not None:  # no more calls of the student's code: let hypothesis give up
                raise state["fatal"]
            try:
                evaluate(args)
            except (CheckFailure, StudentFault) as exc:
                if ends_grading(exc):
                    state["fatal"] = exc
                else:
                    state["last"] = (args, exc)
                raise

        try:
            with hypothesis_run():
                run()
        except (CheckFailure, StudentFault):
            pass
        except Exception as exc:  # noqa: BLE001
            if state["last"] is None and state["fatal"] is None:
                raise GraderFault(f"randomized comparison failed: {type(exc).__name__}: {exc}") from exc
        if state["fatal"] is not None:
            raise state["fatal"]
        return state["last"]


class Judged:
    """The reference's code of one probe call on the student's own upstream functions (``Context.upstream``),
    computed when ``result()`` is first asked.  ``result()`` is None when those functions give the reference's
    values along the way (nothing to carry forward), else an ``grader.upstream.Upstream``; in the kit, where
    nothing can be composed, the student's functions are compared at the recorded calls, and where one differs
    and is real the check is left to the graded submission (``JudgedOnSubmission``)."""

    def __init__(self, ctx, probe, args, key, shared, flaw):
        self._ctx, self._probe, self._args, self._key = ctx, probe, args, key
        self._shared, self._flaw = shared, flaw
        self._result = None
        self._done = False

    def result(self):
        if not self._done:
            self._result = self._compute()
            self._done = True
        return self._result

    def _compute(self):
        from .problems import check_title
        from .upstream import Upstream, UpstreamCall, same

        ctx = self._ctx
        if ctx.oracle.composes:
            found = ctx._hybrid_for(self._shared, self._flaw).run(self._probe, self._args, ctx.check_id)
            return found if found.differing else None
        differing: dict[int, UpstreamCall] = {}
        for index, (function, args, parent) in enumerate(ctx.oracle.upstream_calls(self._key)):
            module_name, _, name = function.rpartition(".")
            theirs = ctx.reference("_upstream.call", module_name, name, list(args))
            try:
                mine = ctx.student("_upstream.call", module_name, name, list(args))
            except (StudentFault, CheckFailure) as exc:
                call = UpstreamCall(function, args, None, theirs, str(getattr(exc, "message", exc)).split("\n")[0])
                return Upstream(None, (call,), f"your {name} could not be called ({call.error})")
            if same(mine, theirs):
                continue
            call = UpstreamCall(function, args, mine, theirs, parent=parent)
            flaw = self._flaw(mine, theirs, function)
            if flaw:
                return Upstream(None, (call,), f"your {call.shown()} {flaw}")
            differing[index] = call
        if not differing:
            return None
        explained = {call.parent for call in differing.values()}  # a difference of the calls made inside it
        first: dict[str, UpstreamCall] = {}
        for index, call in differing.items():
            if index not in explained:
                first.setdefault(call.function, call)
        calls = list(first.values())
        one = len(calls) == 1
        names = ", ".join(call.function.rpartition(".")[2] for call in calls)
        graded = "; ".join(dict.fromkeys(check_title(self._shared[call.function][1]) for call in calls))
        raise JudgedOnSubmission(
            f"judged on your own {names} when you submit: {'it differs' if one else 'they differ'} from the "
            f"reference's (e.g. {calls[0].shown()}) and {'is' if one else 'are'} graded by {graded}; only the "
            f"graded submission can compute this answer from {'it' if one else 'them'} (error carried forward)")


class Catalogue:
    """A list of known mistakes computed when first consulted (see ``Context.catalogue``): iterate it, index it,
    take its length."""

    def __init__(self, compute):
        self._compute = compute
        self._items: list | None = None

    def items(self) -> list:
        if self._items is None:
            self._items = list(self._compute())
        return self._items

    def __iter__(self):
        return iter(self.items())

    def __len__(self) -> int:
        return len(self.items())

    def __getitem__(self, index):
        return self.items()[index]

    def __bool__(self) -> bool:
        return bool(self.items())


#: hypothesis looks for a failure to shrink among this many times the check's examples (plus ten)
SHRINK_SEARCH = 2
#: the seed of the input of each randomized comparison that every student whose comparison failed is also asked
#: (with the name of its site), for ``grade similarity``: the same in every batch
COMMON_SEED = 0x5EED_C0DE


def _attempt(evaluate, args):
    """The failure of ``evaluate(args)`` (a ``CheckFailure`` or the student's fault), or None; fatal failures
    (time-outs, crashes, stubs) are raised at once."""
    try:
        evaluate(args)
    except (CheckFailure, StudentFault) as exc:
        if ends_grading(exc):
            raise
        return exc
    return None


def _failures(inputs, evaluate, until_generic: bool = False) -> list:
    """``(index, args, exc)`` of the inputs that fail, in order: all of them, or (``until_generic``) up to the
    first one after the first input, the simplest one that the draws begin with."""
    failures = []
    for index, args in enumerate(inputs):
        exc = _attempt(evaluate, args)
        if exc is not None:
            failures.append((index, args, exc))
            if until_generic and index > 0:
                break
    return failures


def _generic(failures) -> tuple:
    """``(args, exc)`` of a failing input on which the mistakes of a catalogue are told apart: the first failing
    one after the simplest input the draws begin with (all zeros, say), else that one."""
    index, args, exc = next((f for f in failures if f[0] > 0), failures[0])
    return args, exc


def _simplest(failures) -> tuple:
    """``(args, exc)`` of the simplest failing input (``simplicity``; ties keep the order of the draws)."""
    _, args, exc = min(failures, key=lambda f: (simplicity(f[1]), f[0]))
    return args, exc


def _narrowed(shown, other):
    """The failure to report on the input ``shown`` was raised for, its diagnosis checked on a second failing
    input ``other`` (the failure a shrunk, often degenerate input, gives): a known mistake is named when it
    matches on both; when several still match, all of them are ("could be X or Y").  Failures of different
    properties (their first lines without the numbers and spaces in them: a comparison's name may show its input), or
    without a catalogue, are reported as they are."""
    if other is shown or not isinstance(shown, CheckFailure) or not isinstance(other, CheckFailure):
        return shown
    if shown.candidates is None or other.candidates is None:
        return shown
    if property_of(shown) != property_of(other):
        return shown
    names = {mistake.name for mistake in other.candidates}
    common = tuple(mistake for mistake in shown.candidates if mistake.name in names)
    hint, diagnosis = diagnose(common)
    return CheckFailure(shown.message, hint, diagnosis, common, shown.evidence)


def explained(ctx, failure: CheckFailure, evidences=None) -> CheckFailure:
    """``failure`` with the cause the diagnosis engine names from ``evidences`` (default: the failure's own
    comparison), when no known mistake named one; its hint becomes the cause's.  A cause that blames a run's
    integration is the engine's to doubt (``diagnosis.doubt``): a wrong model is not told as a wrong integration.
    Asked once per failure."""
    if failure.explained:
        return failure
    if failure.diagnosis:
        finding = doubt(ctx, failure.evidence, failure.diagnosis)  # an integration blamed for a wrong model
        if finding is None:
            return _beside_symptom(ctx, failure)
        return CheckFailure(failure.message, finding.hint, finding.diagnosis, failure.candidates, failure.evidence,
                            explained=True)
    if failure.evidence is None:
        trace.begin(getattr(ctx, "check_id", ""), "no_evidence")
        trace.end()
        return failure
    finding = explain(ctx, evidences or [failure.evidence])
    if finding is None:
        return CheckFailure(failure.message, failure.hint, "", failure.candidates, failure.evidence, explained=True)
    if not finding.names:  # no cause, but a note (the student kit leaves formulas to the graded submission)
        hint = "\n".join(part for part in (failure.hint, finding.hint) if part)
        return CheckFailure(failure.message, hint, "", failure.candidates, failure.evidence, explained=True)
    return CheckFailure(failure.message, finding.hint, finding.diagnosis, failure.candidates, failure.evidence,
                        explained=True)


def _beside_symptom(ctx, failure: CheckFailure) -> CheckFailure:
    """A failure whose diagnosis names only a symptom (``diagnosis.SYMPTOMS``), with the cause the diagnosis engine
    finds by comparing the student's call behind the judged value with the reference's (``diagnosis.judge``): the
    message (the symptom) stays, the hint tells the symptom's and then the cause's, and the diagnosis names the
    cause.  A failure whose diagnosis names an effect its value shows (``diagnosis.EFFECTS``: entries with the wrong
    sign), with the rival of another family the engine finds (``diagnosis.rival``: two arguments exchanged), told
    beside it.  Where the engine finds none, the failure as it was."""
    if not symptom(failure.diagnosis):
        found = rival(ctx, failure.evidence, failure.diagnosis)
        if found is None:
            return failure
        hint = "\n".join(part for part in (failure.hint, found.hint) if part)
        return CheckFailure(failure.message, hint, found.diagnosis, failure.candidates, failure.evidence,
                            explained=True)
    finding = judge(ctx, failure.evidence)
    if finding is None or not finding.names:
        return failure
    hint = "\n".join(part for part in (failure.hint, finding.hint) if part)
    return CheckFailure(failure.message, hint, finding.diagnosis, failure.candidates, failure.evidence,
                        explained=True)


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


def _raise_at(args, exc, describe, where: str):
    shown = describe(args) if describe else _describe_args(args)
    where = f"on the randomized input {shown}\n{where}"
    if isinstance(exc, CheckFailure):
        first, _, rest = exc.message.partition("\n")
        raise CheckFailure(f"{first}\n{where}\n{rest}", exc.hint, exc.diagnosis, exc.candidates, exc.evidence,
                           exc.explained)
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
