"""The diagnosis of a randomized comparison: a known mistake is named only when it is the one that matches, on the
(often degenerate) minimal input shown AND on a failing input that was drawn rather than shrunk; when several
mistakes still match, the report says it could be any of them instead of naming the first in the catalogue.

The comparison here is a small made-up function, ``f(a, b) = a + b``, with a stub sandbox child (the student) and
a stub oracle (the reference), so that the inputs and the mistakes are fully known:

* the student computes ``a - b`` (the mistake "sign_flip", of b);
* the catalogue also holds "ignored_argument" (``-b``: a forgotten): at ``a = 0``, where hypothesis shrinks every failure to, both
  mistakes give the student's value, and only a drawn input with ``a != 0`` tells them apart.
"""

import importlib

import numpy as np
import pytest

from grader import strategies as st
from checks._diagnoses import student_phrase
from grader.checking import EXACT, CheckFailure, Mistake, assert_close, diagnose
from grader.context import Context
from probes import probe
from probes._forms import Arr, Num

SIGN_HINT = "b enters with the wrong sign: f = a + b."
FORGOT_HINT = "a is missing: f = a + b."
TWIN_HINT = "b is subtracted: f = a + b (the same as a sign flip of b)."

INPUTS = st.tuples(st.floats(-2.0, 2.0, allow_nan=False), st.floats(-2.0, 2.0, allow_nan=False))


def reference_f(a, b):
    return np.array([a + b])


@probe(returns=Arr(1), says="f({0}, {1})")
def f(pkg, a, b):
    """The made-up probe: the stubs below answer it (every probe declares the form of its reply)."""
    return module_f(pkg)(a, b)


@probe(returns=Num())
def double(pkg, x):
    """A made-up probe of one number."""
    return 2 * x


def module_f(pkg):
    return pkg.f


def student_f(a, b):
    return np.array([a - b])


def catalogue(args, expected, twin=False):
    a, b = args
    mistakes = [Mistake("ignored_argument", np.array([-b]), FORGOT_HINT), Mistake("sign_flip", np.array([a - b]), SIGN_HINT)]
    if twin:  # a second name for the same computation: never told apart
        mistakes.append(Mistake("offset_sign", np.array([a - b]), TWIN_HINT))
    return mistakes


class StubChild:
    """The student's package: answers the probe ``f`` with the student's function."""

    def __init__(self, function):
        self.function = function
        self.calls = []

    def call(self, probe, *args, timeout=None):
        self.calls.append(args)
        return self.function(*args)


class StubOracle:
    """The reference: live (fresh draws, hypothesis shrinks a failure) or, with ``pool``, a recorded pool."""

    def __init__(self, pool=None):
        self.pooled = pool is not None
        self.mode = "kit" if self.pooled else "live"
        self._pool = pool

    def reference(self, probe, args, persist=False, check=None):
        return reference_f(*args)

    def pool(self, site, strategy, examples, check=None):
        return list(self._pool)


def compare(oracle, twin=False, seed=7):
    """Run the randomized comparison; returns the failure and the inputs the report showed."""
    shown = []

    def describe(args):
        shown.append(tuple(float(x) for x in args))
        return f"(a={args[0]!r}, b={args[1]!r})"

    ctx = Context(99, StubChild(student_f), {}, None, seed, oracle)
    ctx.begin("p99.f_values")
    with pytest.raises(CheckFailure) as caught:
        ctx.compare_random(f, INPUTS, name="f(a, b)", tol=EXACT, examples=10, describe=describe,
                           mistakes=lambda args, expected: catalogue(args, expected, twin))
    return caught.value, shown[-1]


def inputs_tried(seed: int) -> list:
    """Every input the randomized comparison of ``student_f`` asked the student, live, in order."""
    child = StubChild(student_f)
    ctx = Context(99, child, {}, None, seed, StubOracle())
    ctx.begin("p99.f_values")
    with pytest.raises(CheckFailure):
        ctx.compare_random(f, INPUTS, name="f(a, b)", tol=EXACT, examples=10,
                           mistakes=lambda args, expected: catalogue(args, expected))
    return child.calls


def test_the_inputs_a_seed_gives_do_not_depend_on_the_modules_imported_before(tmp_path, monkeypatch):
    """hypothesis draws now and then a literal it found in the source of the process's local modules; the grader's
    runs see none, so the inputs a seed makes the student's code run on are the same whatever the process imported
    before (a batch slot imports every problem's modules, ``grade problem-N`` one problem's, an editable install the
    grader's own), and no grading parses the process's source files."""
    from hypothesis import strategies as hs

    from grader.oracle import draw_pool

    pairs = hs.tuples(hs.floats(-2.0, 2.0), hs.floats(-2.0, 2.0))
    seeds = range(4)
    before = [inputs_tried(seed) for seed in seeds]
    drawn = draw_pool(pairs, 300, seed=5)
    (tmp_path / "sheet_values.py").write_text(
        "VALUES = [" + ", ".join(f"{x:.7f}" for x in np.linspace(-1.93, 1.97, 400)) + "]\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.delitem(__import__("sys").modules, "sheet_values", raising=False)
    importlib.import_module("sheet_values")
    assert all(len(tried) > 5 for tried in before) and len(drawn) == 300
    assert draw_pool(pairs, 300, seed=5) == drawn
    assert [inputs_tried(seed) for seed in seeds] == before


def test_diagnose_names_one_mistake_or_all_that_match():
    sign = Mistake("sign_flip", None, SIGN_HINT)
    forgot = Mistake("ignored_argument", None, FORGOT_HINT)
    assert diagnose(()) == ("", "")
    assert diagnose([sign]) == (SIGN_HINT, "sign_flip")
    assert diagnose([sign, Mistake("sign_flip", None, "another wording")]) == (SIGN_HINT, "sign_flip")
    hint, name = diagnose([forgot, sign])
    assert name == "ignored_argument or sign_flip"
    assert f"could be {student_phrase('ignored_argument')} or {student_phrase('sign_flip')}" in hint
    assert FORGOT_HINT in hint and SIGN_HINT in hint


def test_degenerate_input_alone_is_ambiguous():
    """At a = 0 both mistakes give the student's value: the check does not pick the first of the catalogue."""
    args = (0.0, 1.0)
    with pytest.raises(CheckFailure) as caught:
        assert_close(student_f(*args), reference_f(*args), "f(a, b)", EXACT, catalogue(args, None))
    assert caught.value.diagnosis == "ignored_argument or sign_flip"
    assert {m.name for m in caught.value.candidates} == {"ignored_argument", "sign_flip"}


def test_live_shrunk_input_is_degenerate_and_the_drawn_one_names_the_mistake():
    failure, shown = compare(StubOracle())
    assert "minimal failing input found by hypothesis" in failure.message
    a, b = shown
    assert a == 0.0 and b != 0.0  # shrunk to the degenerate input, where both mistakes give the same value
    assert np.allclose(student_f(a, b), -b)
    assert failure.diagnosis == "sign_flip"
    assert failure.hint == SIGN_HINT
    assert "(a=0.0, b=" in failure.message


def test_live_two_mistakes_that_always_agree_are_both_named():
    failure, shown = compare(StubOracle(), twin=True)
    assert shown[0] == 0.0
    assert failure.diagnosis == "sign_flip or offset_sign"
    assert SIGN_HINT in failure.hint and TWIN_HINT in failure.hint and FORGOT_HINT not in failure.hint


def test_kit_pool_simplest_failure_is_degenerate_and_the_first_drawn_one_names_the_mistake():
    pool = [(0.0, 0.0), (0.7, -1.3), (0.0, 0.5), (-1.9, 1.1)]
    failure, shown = compare(StubOracle(pool))
    assert shown == (0.0, 0.5)  # the simplest failing input of the pool: a = 0, both mistakes agree there
    assert "the simplest of the 3 failing inputs among the 4 recorded random inputs" in failure.message
    assert failure.diagnosis == "sign_flip"


def test_kit_pool_with_only_degenerate_failures_stays_ambiguous():
    failure, shown = compare(StubOracle([(0.0, 0.0), (0.0, 0.5), (0.0, -1.5)]))
    assert shown == (0.0, 0.5)
    assert failure.diagnosis == "ignored_argument or sign_flip"


def test_a_mistake_matching_only_on_the_degenerate_input_is_not_named():
    """The student's mistake is not in the catalogue ("b twice": a - b at a = 0 is -b, as are both mistakes at
    that point, but not elsewhere): no cause is named rather than a wrong one."""

    def doubled(a, b):
        return np.array([2 * a - b])

    ctx = Context(99, StubChild(doubled), {}, None, 3, StubOracle([(0.0, 1.0), (1.0, 1.0)]))
    ctx.begin("p99.f_values")
    with pytest.raises(CheckFailure) as caught:
        ctx.compare_random(f, INPUTS, name="f(a, b)", tol=EXACT, examples=2,
                           mistakes=lambda args, expected: catalogue(args, expected))
    assert caught.value.diagnosis == ""
    assert caught.value.hint == ""


def test_a_child_without_call_later_is_called_at_once_and_its_failure_raised_when_asked():
    from grader.errors import StudentCodeError

    class Plain:
        def call(self, probe, *args, timeout=None):
            if args[0] < 0:
                raise StudentCodeError("exception", "ValueError", "negative", "", "call")
            return args[0] * 2

    ctx = Context(99, Plain(), {}, None, 1, StubOracle())
    assert ctx.student_later(double, 2)() == 4
    later = ctx.student_later(double, -1)
    with pytest.raises(StudentCodeError, match="negative"):
        later()


def _turn(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


@pytest.mark.parametrize("got, expected, catalogue, told", [
    # a rotation's transpose is the rotation by the negated angle: a catalogue of one of them is told with both
    (_turn(0.4).T, _turn(0.4), ["transpose"], "transpose or angle_sign"),
    (_turn(0.4).T, _turn(0.4), ["sign_flip"], "sign_flip or transpose"),
    (_turn(0.4).T, _turn(0.4), ["transpose", "angle_sign"], "transpose or angle_sign"),
    # near misses: the whole matrix negated is no rotation's transpose; a matrix that is not a rotation has no twin
    (-_turn(0.4), _turn(0.4), ["sign_flip"], "sign_flip"),
    (np.diag([1.0, 2.0, 3.0]) + np.triu(np.ones((3, 3)), 1).T, np.diag([1.0, 2.0, 3.0]) + np.triu(np.ones((3, 3)), 1),
     ["transpose"], "transpose"),
])
def test_a_rotation_transposed_is_told_as_the_rotation_the_other_way_too(got, expected, catalogue, told):
    with pytest.raises(CheckFailure) as caught:
        assert_close(got, expected, "A", EXACT, [Mistake(name, got, "the catalogue's hint") for name in catalogue])
    assert caught.value.diagnosis == told
    assert caught.value.hint.count("the catalogue's hint") == len(catalogue)
