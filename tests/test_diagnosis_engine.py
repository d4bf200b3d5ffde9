"""The diagnosis engine (``grader.diagnosis``): a failing comparison that no known mistake explains is tried
against a grammar of common slips, and the simplest slips that reproduce the student's answer on the input shown
and on a second one are named; none, never a default cause.

* The grammar on small stand-ins: a stub child (the student) and a stub oracle (the reference) for made-up probes
  whose declarations the tests set, so that every input and slip is known.
* Its development set, ``tests/engine/mistakes.toml``: for each family of the grammar one mistake planted into the
  reference where no catalogue names it, graded as ``grade batch`` grades (a warm fork), live and from the kit's
  answer key (the same verdict and diagnosis: the key holds the engine's reference calls), and once with the
  engine off (the check then names no cause).
"""

import tomllib
from pathlib import Path

import numpy as np
import pytest

import grader.diagnosis as engine
from checks._diagnoses import family_of
from grader import strategies as st
from grader.checking import EXACT, CheckFailure, Tol, assert_close
from grader.context import Context, explained
from grader.diagnosis import Declaration, Evidence, explain

from .kit_support import (  # noqa: F401 (fixtures)
    assert_no_catalogue_names_it,
    assert_told_alike,
    strict,
    warm_slot,
)
from .submissions import Planted

ROOT = Path(__file__).resolve().parents[1]
#: the families of the engine's grammar
GRAMMAR = {"transpose", "inverse", "sign", "order", "scale", "frame", "missing_term", "extra_term",
           "ignored_argument", "initial_state", "time_shift", "offset", "step_size", "event", "state_row",
           "precision"}


@pytest.fixture(autouse=True)
def stub_probes(monkeypatch):
    """The made-up probes as a module of probes (``probes.stub``) whose every reply has its form, since the gate
    holds each reply of the student's side to the form its probe declares (``grader.gate``); their declarations
    for the engine are the tests' own (``declare``)."""
    import sys
    import types

    from probes import probe
    from probes._forms import ANY

    stub = types.ModuleType("probes.stub")
    for name in ("f", "g", "h", "R", "run", "fixed", "h_terms"):
        setattr(stub, name, probe(returns=ANY)(lambda pkg, *args: None))
    monkeypatch.setitem(sys.modules, "probes.stub", stub)


# ------------------------------------------------------------------------------------------ stand-ins


class StubChild:
    def __init__(self, function):
        self.function = function

    def call(self, probe, *args, timeout=None):
        return self.function(probe, *args)


class StubOracle:
    """The reference of the made-up probes: live, or (``pool``) the recorded pool of the kit."""

    mode = "live"

    def __init__(self, functions, pool=None):
        self.functions = functions
        self.pooled = pool is not None
        self.mode = "kit" if self.pooled else "live"
        self._pool = pool
        self.asked = []

    def reference(self, probe, args, persist=False, check=None):
        self.asked.append((probe, tuple(args)))
        return self.functions[probe](*args)

    def pool(self, site, strategy, examples, check=None):
        return list(self._pool)

    def draw(self, site, make, seed, check=None):
        return make(np.random.default_rng([seed, len(site)]))


def declare(monkeypatch, probe, **declared):
    monkeypatch.setitem(engine._DECLARATIONS, probe, Declaration(
        args=declared.get("args", ()), names=declared.get("names", ()), terms=declared.get("terms", ""),
        rotation=declared.get("rotation"), motion=declared.get("motion", {}), constants=declared.get("constants", ""),
        draw=declared.get("draw", True)))


def reference_f(a, b):
    return np.array([[a, 2.0 * b], [a * b, 1.0 + a]])


SCALARS = st.tuples(st.floats(-2.0, 2.0, allow_nan=False), st.floats(-2.0, 2.0, allow_nan=False))


def compare(student, oracle_functions=None, pool=None, seed=7, inputs=SCALARS):
    """The failure of a randomized comparison of ``stub.f`` (reference ``reference_f``) with ``student`` on
    ``inputs``."""
    functions = oracle_functions or {"stub.f": reference_f}
    oracle = StubOracle(functions, pool)
    ctx = Context(99, StubChild(lambda probe, *args: student(*args)), {}, None, seed, oracle)
    ctx.begin("p99.f_values")
    with pytest.raises(CheckFailure) as caught:
        ctx.compare_random("stub.f", inputs, name="f(a, b)", tol=EXACT, examples=10)
    return caught.value


# ------------------------------------------------------------------------------------------ the grammar


def test_an_output_slip_is_named_on_two_inputs(monkeypatch):
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))
    failure = compare(lambda a, b: reference_f(a, b).T)
    assert failure.diagnosis == "transpose"
    assert failure.hint.startswith("Looks like a transposed matrix") and "on the input shown and on a second one" \
        in failure.hint


def test_an_input_slip_is_named_from_the_reference_on_transformed_arguments(monkeypatch):
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))
    failure = compare(lambda a, b: reference_f(b, a))
    assert failure.diagnosis == "argument_order"
    assert "a and b are swapped" in failure.hint


def test_angles_as_degrees_and_negated_angles(monkeypatch):
    def rotation(angle):
        c, s = np.cos(angle), np.sin(angle)
        return np.array([[c, -s], [s, c]])

    declare(monkeypatch, "stub.R", args=("angle",), names=("angle",))
    for student, expected in ((lambda x: rotation(np.deg2rad(x)), "degrees"),
                              (lambda x: rotation(-x), "transpose or angle_sign")):
        oracle = StubOracle({"stub.R": rotation})
        ctx = Context(99, StubChild(lambda probe, x, student=student: student(x)), {}, None, 3, oracle)
        ctx.begin("p99.R_values")
        with pytest.raises(CheckFailure) as caught:
            ctx.compare_random("stub.R", st.tuples(st.floats(-3.0, 3.0, allow_nan=False)), name="R", tol=EXACT)
        assert caught.value.diagnosis == expected  # a rotation by -x is its transpose: both are told


def test_every_angle_negated_at_once(monkeypatch):
    """Two angles each entering with the opposite sign (every rotation the other way): neither angle negated alone
    reproduces the answer, both at once do."""
    def rotation(angle):
        c, s = np.cos(angle), np.sin(angle)
        return np.array([[c, -s], [s, c]])

    def turned(a, b):
        return rotation(a) @ np.array([[1.0, 2.0], [0.0, 3.0]]) @ rotation(b)

    declare(monkeypatch, "stub.g", args=("angle", "angle"), names=("a", "b"))
    oracle = StubOracle({"stub.g": turned})
    ctx = Context(99, StubChild(lambda probe, a, b: turned(-a, -b)), {}, None, 3, oracle)
    ctx.begin("p99.g_values")
    with pytest.raises(CheckFailure) as caught:
        ctx.compare_random("stub.g", st.tuples(st.floats(-3.0, 3.0, allow_nan=False),
                                               st.floats(-3.0, 3.0, allow_nan=False)), name="T", tol=EXACT)
    assert caught.value.diagnosis == "angle_sign", (caught.value.diagnosis, caught.value.hint)
    assert "every angle enters with the opposite sign" in caught.value.hint, caught.value.hint


def test_never_a_default_cause(monkeypatch):
    """A value that no slip of the grammar gives: no diagnosis, no hint; the message says what differs."""
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))
    failure = compare(lambda a, b: reference_f(a, b) + np.array([[0.3 * a * a, 0.0], [0.0, 0.1]]))
    assert failure.diagnosis == "" and failure.hint == ""
    assert "got:" in failure.message and "expected:" in failure.message and "|diff|" in failure.message


def test_a_finding_the_formula_tier_contests_is_told_as_nothing(monkeypatch):
    """An earlier tier's explanation that the formula tier, heard late, contests with slips of more families than
    can be told (``mutants.Contested``) is told as nothing: the transpose alone stands only where nothing contests
    it."""
    from grader.diagnosis import engine as finding, mutants

    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))

    def contesting(scene, evidences, another=None, told=None, untested=False, unreached=()):
        if told is not None:  # heard late: three families of the reference's code reproduce the answer as well
            raise mutants.Contested(["order", "scale", "sign"])
        return []

    monkeypatch.setattr(finding, "mutant_slips", lambda *args, **kwargs: [])
    assert compare(lambda a, b: reference_f(a, b).T).diagnosis == "transpose"
    monkeypatch.setattr(finding, "mutant_slips", contesting)
    failure = compare(lambda a, b: reference_f(a, b).T)
    assert failure.diagnosis == "" and failure.hint == ""


def test_a_slip_that_holds_on_one_input_only_is_not_named(monkeypatch):
    """The student's value is the transpose on the degenerate input (b = 0, a = 0) only: nothing is named."""
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))

    def student(a, b):
        value = reference_f(a, b)
        return value.T if a == 0.0 else value + 1.0

    failure = compare(student, pool=[(0.0, 0.5), (1.0, 0.3), (-0.4, 1.2)])
    assert failure.diagnosis == ""


def test_without_a_declaration_only_the_value_itself_is_transformed(monkeypatch):
    monkeypatch.setitem(engine._DECLARATIONS, "stub.f", None)
    assert compare(lambda a, b: -reference_f(a, b)).diagnosis == "sign_flip"
    assert compare(lambda a, b: reference_f(b, a)).diagnosis == ""  # argument order needs the arguments' roles


def test_a_small_value_within_a_loose_tolerance_is_not_a_scale_slip():
    """pi/180 times a value, or half of it, is within a loose tolerance of a student's zeros where the value is
    small: a hypothesis must be clearly other than zero to be named."""
    expected = np.linspace(0.0, 6.0, 50)
    log = [("reference", "stub.run", (), {"y": expected})]

    class Ctx:
        calls = log
        check_id = "p99.run"
        oracle = StubOracle({})
        child = None
        seed = 1

    evidence = Evidence(np.zeros(50), expected, Tol("loose", 0.5), "y", None, expected)
    assert explain(Ctx(), [evidence]) is None


def test_precision_slips_need_the_exact_rounded_value(monkeypatch):
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))
    failure = compare(lambda a, b: reference_f(a, b).astype(np.float32).astype(float))
    assert failure.diagnosis == "float32"
    failure = compare(lambda a, b: np.round(reference_f(a, b), 3))
    assert failure.diagnosis == "rounded" and "rounded to 3 decimals" in failure.hint


def test_zeros_are_not_a_rounding_of_small_values():
    """Small expected values round to zeros at a few decimals, but an answer of zeros has not rounded anything: the
    rounding hypothesis, as every other, must be clearly other than zero to be named (a damping torque left out
    was told "rounded to 3 decimals"); a rounding that keeps two digits of them is named."""
    from grader.diagnosis.grammar import precision_slips

    small = np.array([8.3e-5, -2.46e-4, 3.1e-5])
    assert precision_slips(np.zeros(3), small, Tol("tight", 1e-9)) == []
    assert [h.name for h in precision_slips(np.round(small, 5), small, Tol("tight", 1e-9))] == ["rounded"]


def test_whole_numbers_are_not_a_rounding_of_values_near_them():
    """A rotation a little off the identity rounds to the identity at two decimals, but an answer of 0s and 1s has
    not rounded anything (a rotation whose small angle a formula leaves out was told "rounded to 2 decimals"); the
    same rotation rounded to three decimals is named."""
    from grader.diagnosis.grammar import precision_slips

    near = np.array([[0.99998, -0.00471, 0.0], [0.00471, 0.99998, 0.0], [0.0, 0.0, 1.0]])
    assert precision_slips(np.eye(3), near, Tol("tight", 1e-9)) == []
    assert [h.name for h in precision_slips(np.round(near, 3), near, Tol("tight", 1e-9))] == ["rounded"]


def test_an_ignored_argument_is_found_by_changing_it_for_the_student(monkeypatch):
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))
    failure = compare(lambda a, b: reference_f(a, 0.7))
    assert failure.diagnosis == "ignored_argument" and "when b does" in failure.hint


def test_an_argument_the_reference_ignores_too_is_not_named(monkeypatch):
    """The reference does not depend on b either: that the student's value does not change with b says nothing."""
    declare(monkeypatch, "stub.g", args=("scalar", "scalar"), names=("a", "b"))
    functions = {"stub.g": lambda a, b: np.array([a, 2.0 * a])}
    oracle = StubOracle(functions)
    ctx = Context(99, StubChild(lambda probe, a, b: np.array([a, 2.0 * a + 0.1])), {}, None, 5, oracle)
    ctx.begin("p99.g_values")
    with pytest.raises(CheckFailure) as caught:
        ctx.compare_random("stub.g", SCALARS, name="g(a, b)", tol=EXACT)
    assert caught.value.diagnosis == ""


def terms_of(a, b):
    """``reference_h = gravity + coriolis`` with ``gyroscopic`` a term that does not belong."""
    return {"terms": {"gravity": np.array([a, 1.0, 0.5 * b]), "coriolis": np.array([b * b, -a * b, 2.0])},
            "extra": {"gyroscopic": np.array([1.0, b, a])}}


def reference_h(a, b):
    parts = terms_of(a, b)["terms"]
    return parts["gravity"] + parts["coriolis"]


@pytest.mark.parametrize("student, expected", [
    (lambda a, b: terms_of(a, b)["terms"]["coriolis"], "missing_gravity"),
    (lambda a, b: reference_h(a, b) - 2 * terms_of(a, b)["terms"]["coriolis"], "coriolis_sign"),
    (lambda a, b: reference_h(a, b) + terms_of(a, b)["extra"]["gyroscopic"], "extra_gyroscopic"),
    # zeros: every term left out gives them, as do many other mistakes; no term is named
    (lambda a, b: np.zeros(3), ""),
])
def test_declared_terms_are_found_by_least_squares(monkeypatch, student, expected):
    declared_terms_found(monkeypatch, student, expected, terms_of)


def gravity_alone(a, b):
    """A value made of one declared term."""
    return {"terms": {"gravity": np.array([a, 1.0, 0.5 * b])}, "extra": {}}


def test_zeros_for_a_value_of_one_term_are_that_term_left_out(monkeypatch):
    declared_terms_found(monkeypatch, lambda a, b: np.zeros(3), "missing_gravity", gravity_alone)


def declared_terms_found(monkeypatch, student, expected, terms):
    """``student``'s value of ``stub.h``, whose terms are ``terms``, compared on random inputs: the diagnosis."""
    declare(monkeypatch, "stub.h", args=("scalar", "scalar"), names=("a", "b"), terms="stub.h_terms")

    def reference(a, b):
        return sum(terms(a, b)["terms"].values())

    oracle = StubOracle({"stub.h": reference, "stub.h_terms": terms})
    ctx = Context(99, StubChild(lambda probe, a, b: student(a, b)), {}, None, 11, oracle)
    ctx.begin("p99.h_values")
    with pytest.raises(CheckFailure) as caught:
        ctx.compare_random("stub.h", SCALARS, name="h(a, b)", tol=EXACT)
    assert caught.value.diagnosis == expected


def test_a_fixed_comparison_is_checked_on_an_input_the_engine_draws(monkeypatch):
    """A sheet's case: the engine draws a second input from the declared roles and asks the student and the
    reference there; a slip that holds only on the case itself is not named."""
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))
    oracle = StubOracle({"stub.f": reference_f})
    for student, expected in ((lambda a, b: reference_f(b, a), "argument_order"),
                              (lambda a, b: reference_f(b, a) if (a, b) == (0.5, 1.5) else reference_f(a, b) + 1, "")):
        ctx = Context(99, StubChild(lambda probe, a, b, student=student: student(a, b)), {}, None, 3, oracle)
        ctx.begin("p99.f_case")
        with pytest.raises(CheckFailure) as caught:
            assert_close(ctx.student("stub.f", 0.5, 1.5), ctx.reference("stub.f", 0.5, 1.5), "f", EXACT)
        assert explained(ctx, caught.value).diagnosis == expected


POSITIVE = st.tuples(st.floats(0.5, 2.0, allow_nan=False), st.floats(0.5, 2.0, allow_nan=False))


def compare_positive(student, seed=7):
    """``compare`` on positive arguments (a reciprocal stays finite)."""
    return compare(student, seed=seed, inputs=POSITIVE)


def test_a_number_among_the_arguments_at_twice_half_or_its_reciprocal(monkeypatch):
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))
    doubled = compare_positive(lambda a, b: reference_f(a, 2.0 * b))
    assert doubled.diagnosis == "scaled_argument" and "b enters at twice its value" in doubled.hint
    halved = compare_positive(lambda a, b: reference_f(0.5 * a, b))
    assert halved.diagnosis == "scaled_argument" and "a enters at half its value" in halved.hint
    flipped = compare_positive(lambda a, b: reference_f(a, 1.0 / b))
    assert flipped.diagnosis == "reciprocal_argument" and "b enters as its reciprocal" in flipped.hint
    assert family_of("scaled_argument") == "scale" and family_of("reciprocal_argument") == "inverse"


def test_a_whole_value_off_by_another_simple_factor(monkeypatch):
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))
    quarter = compare(lambda a, b: 0.25 * reference_f(a, b))
    assert quarter.diagnosis == "wrong_factor" and "times 1/4" in quarter.hint
    assert compare(lambda a, b: np.sqrt(2.0) * reference_f(a, b)).diagnosis == "wrong_factor"
    assert compare(lambda a, b: 1.37 * reference_f(a, b)).diagnosis == ""  # not a simple factor: nothing


def test_a_declared_term_twice_or_half(monkeypatch):
    declare(monkeypatch, "stub.h", args=("scalar", "scalar"), names=("a", "b"), terms="stub.h_terms")
    oracle = StubOracle({"stub.h": reference_h, "stub.h_terms": terms_of})
    for student, expected, words in (
            (lambda a, b: reference_h(a, b) - 0.5 * terms_of(a, b)["terms"]["coriolis"], "factor_half", "half"),
            # a term at twice its value is a factor on it and as truly the term counted twice: both told
            (lambda a, b: reference_h(a, b) + terms_of(a, b)["terms"]["gravity"], "factor_two or gravity_twice",
             "twice")):
        ctx = Context(99, StubChild(lambda probe, a, b, student=student: student(a, b)), {}, None, 11, oracle)
        ctx.begin("p99.h_values")
        with pytest.raises(CheckFailure) as caught:
            ctx.compare_random("stub.h", SCALARS, name="h(a, b)", tol=EXACT)
        assert caught.value.diagnosis == expected and words in caught.value.hint


def test_a_printed_value_is_traced_to_the_reference_through_the_students_call(monkeypatch):
    """The sheet's printed value is compared before the check asks the reference: the engine asks the reference
    with the arguments of the student's call, takes its value (the printed one within the tolerance) as the
    expected one, and names the slip; in the kit the key holds that call (it is made while the key is recorded)."""
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))
    printed = np.round(reference_f(0.5, 1.5), 2)
    sheet = Tol("the sheet's decimals", 0.01)
    oracle = StubOracle({"stub.f": reference_f})
    ctx = Context(99, StubChild(lambda probe, a, b: reference_f(a, 2.0 * b)), {}, None, 3, oracle)
    ctx.begin("p99.f_sheet")
    with pytest.raises(CheckFailure) as caught:
        assert_close(ctx.student("stub.f", 0.5, 1.5), printed, "f", sheet)
    finding = explained(ctx, caught.value)
    assert finding.diagnosis == "scaled_argument" and "b enters at twice its value" in finding.hint
    assert ("stub.f", (0.5, 1.5)) in oracle.asked
    untraced = Context(99, StubChild(lambda probe, a, b: reference_f(a, 2.0 * b)), {}, None, 3, oracle)
    untraced.begin("p99.f_sheet")
    with pytest.raises(CheckFailure) as caught:  # a printed value the reference does not give: no source
        assert_close(untraced.student("stub.f", 0.5, 1.5), printed + 1.0, "f", sheet)
    assert explained(untraced, caught.value).diagnosis == ""


def test_a_property_of_derived_values_is_explained_by_the_results_they_came_from(monkeypatch):
    """A randomized comparison's own ``compare`` judges a property of the student's result (here the trace of
    f's matrix): where it fails, each result that differs from the reference's on both failing inputs is explained
    as a comparison of its own, and the cause they agree on is named."""
    declare(monkeypatch, "stub.f", args=("scalar", "scalar"), names=("a", "b"))

    def trace(got, expected, args):
        assert_close(np.trace(np.asarray(got)), np.trace(np.asarray(expected)), "the trace of f", EXACT)

    for student, diagnosis in ((lambda a, b: -reference_f(a, b), "sign_flip"),
                               (lambda a, b: reference_f(a, b) + np.eye(2) * (a * a + 0.3), "")):
        oracle = StubOracle({"stub.f": reference_f})
        ctx = Context(99, StubChild(lambda probe, a, b, student=student: student(a, b)), {}, None, 7, oracle)
        ctx.begin("p99.f_trace")
        with pytest.raises(CheckFailure) as caught:
            ctx.compare_random("stub.f", SCALARS, name="f(a, b)", tol=EXACT, compare=trace)
        assert caught.value.diagnosis == diagnosis
        if diagnosis:
            assert caught.value.hint.startswith("Your result: looks like a sign slip")


# ------------------------------------------------------------------------------------------ runs


def run(t, y):
    return {"t": t, "y": y}


def ball(t, start=0.0, speed=4.0):
    height = start + speed * t - 4.905 * t * t
    return np.column_stack([height, speed - 9.81 * t])


def explain_run(monkeypatch, got, expected, tol=Tol("band", 1e-3), events=(), fixed=None):
    declare(monkeypatch, "stub.run", motion={"time": "t", "states": ("y",), "events": events,
                                             **({"fixed_step": "stub.fixed", "schemes": ("euler",),
                                                 "steps": (0.01, 0.02)} if fixed else {})})
    functions = {"stub.run": lambda: expected}
    if fixed:
        functions["stub.fixed"] = fixed

    class Ctx:
        calls = [("reference", "stub.run", (), expected), ("student", "stub.run", (), got)]
        check_id = "p99.run"
        oracle = StubOracle(functions)
        child = None
        seed = 1

    evidence = Evidence(np.asarray(got["y"], dtype=float), np.asarray(expected["y"], dtype=float), tol, "y",
                        got, expected)
    return explain(Ctx(), [evidence])


def test_runs_a_time_shift_a_state_row_an_offset_and_a_wrong_start(monkeypatch):
    t = np.linspace(0.0, 0.8, 81)
    expected = run(t, ball(t))
    shifted = explain_run(monkeypatch, run(t, ball(t + 0.05)), expected)
    assert shifted.diagnosis == "time_shift" and "t +0.05" in shifted.hint
    rows = explain_run(monkeypatch, run(t, ball(t)[:, ::-1]), expected)
    assert rows.diagnosis == "state_row" and "y[0] is the reference's y[1]" in rows.hint
    moved = explain_run(monkeypatch, run(t, ball(t, start=1.0)), expected)
    assert moved.diagnosis == "offset or initial_state"  # a height moved by 1 m: both tell the run alike
    faster = explain_run(monkeypatch, run(t, ball(t, speed=5.0)), expected)
    assert faster.diagnosis == "initial_state" and "y(t0)" in faster.hint


def test_runs_an_event_found_late(monkeypatch):
    t = np.linspace(0.0, 0.8, 81)
    expected = {**run(t, ball(t)), "t_land": 0.8155}
    late = {**run(t, ball(t)), "t_land": 0.83}
    assert explain_run(monkeypatch, late, expected, events=("t_land",)).diagnosis == "event_late"


def test_runs_an_error_that_grows_with_the_step(monkeypatch):
    """The student's run is a fixed-step Euler run at 0.02 s: its error is twice that of the reference's own
    fixed-step run at 0.01 s (and the same as at 0.02 s)."""

    def euler(h):
        steps = int(round(0.8 / h))
        y = [np.array([0.0, 4.0, 1.0])]
        for _ in range(steps):
            height, speed, drag = y[-1]
            y.append(y[-1] + h * np.array([speed, -9.81 - drag * speed * abs(speed), 0.0]))
        grid = np.linspace(0.0, steps * h, steps + 1)
        return grid, np.array(y)[:, :2]

    t = np.linspace(0.0, 0.8, 81)
    fine_t, fine = euler(1e-5)
    expected = run(t, np.column_stack([np.interp(t, fine_t, fine[:, j]) for j in range(2)]))
    coarse_t, coarse = euler(0.02)
    got = run(t, np.column_stack([np.interp(t, coarse_t, coarse[:, j]) for j in range(2)]))
    finding = explain_run(monkeypatch, got, expected, tol=Tol("band", 1e-3),
                          fixed=lambda h, scheme: dict(zip(("t", "y"), euler(h))))
    assert finding.diagnosis == "step_size" and "a step of about 0.02 s" in finding.hint


# ------------------------------------------------------------------------------------------ the kit


def test_the_key_holds_the_engines_calls_for_every_comparison_of_a_declared_probe():
    """While the key is recorded, a comparison of a declared probe's value makes the engine's reference calls
    (inputs transformed, the second input drawn): the kit then names the slip as the live reference does."""
    from grader.kit import record_key

    key, _ = record_key(problems=[26], seed=5)
    positions = [call for call in key.calls if call.startswith("problem_26.position[")]
    sheet_like = {tuple(entry["checks"]) for call, entry in key.calls.items() if call.startswith("problem_26.")}
    assert len(positions) > 40  # the pool's inputs, and each one's arguments swapped, as degrees, changed
    assert any("p26.position_values" in checks for checks in sheet_like)


# ------------------------------------------------------------------------------------------ the development set


def development_set() -> list[Planted]:
    entries = tomllib.loads((ROOT / "tests" / "engine" / "mistakes.toml").read_text())["mistake"]
    return [Planted(name=e["name"], problem=e["problem"], file=e["file"], old=e["old"], new=e["new"],
                    check=e["check"], diagnosis=e["diagnosis"], message=e["message"], also=tuple(e.get("also", ())))
            for e in entries]


FAMILIES = {e["name"]: e["family"] for e in tomllib.loads(
    (ROOT / "tests" / "engine" / "mistakes.toml").read_text())["mistake"]}
#: the checks among a mistake's others (``also``) that name its diagnosis too
ALSO_NAMED = {e["name"]: e.get("also_named", []) for e in tomllib.loads(
    (ROOT / "tests" / "engine" / "mistakes.toml").read_text())["mistake"]}
DEVELOPMENT = development_set()


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({mistake.problem for mistake in DEVELOPMENT}))


def test_the_development_sets_hold_no_mistake_of_the_held_out_measure():
    """The engine is tuned on its own mistakes (``tests/engine/``), never on the held-out set of
    ``tests/diagnosis/`` (nor on the planted suite's, which the catalogues name)."""
    from tests.diagnosis.score import FRESH, NAMED, fresh_mistakes

    from .engine.score_development import REALISTIC

    def key(file, old, new):
        return file, old.strip(), new.strip()

    held_out = {key(m.file, m.old, m.new) for m in fresh_mistakes(FRESH) + fresh_mistakes(NAMED)}
    planted = {key(e["file"], e["old"], e["new"]) for path in (ROOT / "tests" / "planted").glob("problem_*.toml")
               for e in tomllib.loads(path.read_text()).get("mistake", [])}
    formulas = tomllib.loads((ROOT / "tests" / "engine" / "formulas.toml").read_text())["mistake"]
    development = [key(m.file, m.old, m.new) for m in DEVELOPMENT] + [
        key(m.file, m.old, m.new) for m in fresh_mistakes(REALISTIC)] + [
        key(e["file"], e["old"], e["new"]) for e in formulas]
    assert len(development) > 30
    assert not set(development) & (held_out | planted)


def test_every_family_of_the_grammar_has_its_mistake():
    assert set(FAMILIES.values()) == GRAMMAR
    for mistake in DEVELOPMENT:
        assert FAMILIES[mistake.name] in family_of(mistake.diagnosis).split(" or "), mistake.name


@pytest.mark.parametrize("mistake", DEVELOPMENT, ids=lambda m: m.name)
def test_the_engine_names_a_mistake_no_catalogue_lists(mistake, tmp_path, kit_oracle, deferred_ids, slot,
                                                       monkeypatch):
    submission, live, _ = assert_told_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)
    results = {r.check_id: r for r in live.results}
    for check in ALSO_NAMED[mistake.name]:
        assert check in mistake.also and results[check].diagnosis == mistake.diagnosis, (check, results[check].hint)
    assert_no_catalogue_names_it(mistake, submission, slot, monkeypatch)  # (a shape, say, is not a cause)
