"""The diagnosis engine's own second input (``grader.diagnosis.engine._second_input``): a comparison of a value
shown on one input (a sheet's case, a described tree) is also made on an input the engine draws, so that the
grammar and the tier of formulas judge a hypothesis on two inputs.

* Where the probe declares no roles to draw, every float of its arguments is varied but keeps what it is
  (``grammar.varied``): a rotation stays a rotation, a symmetric matrix symmetric (and definite), a positive mass
  positive, a unit vector a unit vector, a zero a zero; integers, flags, strings, tables, grids and the structure
  stay as they are.
* A draw on which the reference raises or gives a degenerate value is not used; a value that does not depend on
  the arguments gets no second input; in the student kit a draw the key does not hold names nothing.
* An explanation counts each distinct reference call once against its budget.
* Graded as ``grade batch`` grades (``tests/engine/second_inputs.toml``): mistakes in problems whose compared
  probes declare nothing to draw are named live, the kit names the same or nothing, and with the engine off no
  cause of that family is named.
"""

import sys
import types
from pathlib import Path

import numpy as np
import pytest

import grader.diagnosis as engine
from grader.checking import CheckFailure, Tol, assert_close
from grader.context import Context, explained
from grader.diagnosis import scene as scenes
from grader.diagnosis.grammar import DRAWN_ENTRIES, second_args, varied
from grader.errors import GraderFault

from ..kit_support import (  # noqa: F401 (fixtures)
    assert_named_live_and_alike,
    graded_table,
)

ROOT = Path(__file__).resolve().parents[2]
TIGHT = Tol("tight", 1e-9, 1e-9)


@pytest.fixture(autouse=True)
def stub_probes(monkeypatch):
    """Made-up probes (``probes.stub_drawn``) that declare nothing to the engine."""
    from probes import probe
    from probes._forms import ANY

    stub = types.ModuleType("probes.stub_drawn")
    for name in ("body", "plain", "flat"):
        setattr(stub, name, probe(returns=ANY)(lambda pkg, *args: None))
        monkeypatch.setitem(engine._DECLARATIONS, f"stub_drawn.{name}", None)
    monkeypatch.setitem(sys.modules, "probes.stub_drawn", stub)


# ------------------------------------------------------------------------------------------ the draw


def turn(axis, angle):
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    K = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + np.sin(angle) * K + (1.0 - np.cos(angle)) * K @ K


#: a described body: a rotation, an inertia, a mass, an offset, a unit axis, indices, a name, a flag, a time grid
#: and a table of data
BODY = {
    "name": "link",
    "m": 2.5,
    "A": turn([0.2, -0.4, 0.9], 0.7),
    "I": np.array([[2.0, 0.1, 0.0], [0.1, 3.0, -0.2], [0.0, -0.2, 1.5]]),
    "r": [0.3, 0.0, -0.2],
    "axis": [0.0, 0.6, 0.8],
    "q_index": [0, 2],
    "fixed": True,
    "t": np.linspace(0.0, 1.0, 12),
    "table": np.arange(2.0 * DRAWN_ENTRIES).reshape(-1, 2),
}


def test_a_varied_input_keeps_what_each_number_is():
    args = (BODY, 0.4, 3, "euler", np.eye(3))
    drawn = varied(args, [5, 6])
    body, angle, count, scheme, identity = drawn
    assert count == 3 and scheme == "euler" and isinstance(angle, float) and angle > 0 and angle != 0.4
    assert set(body) == set(BODY) and body["name"] == "link" and body["q_index"] == [0, 2] and body["fixed"] is True
    assert body["m"] > 0 and body["m"] != BODY["m"]
    A = body["A"]
    assert np.allclose(A.T @ A, np.eye(3)) and np.isclose(np.linalg.det(A), 1.0) and not np.allclose(A, BODY["A"])
    assert np.allclose(identity.T @ identity, np.eye(3)) and not np.allclose(identity, np.eye(3))
    I = body["I"]
    assert np.allclose(I, I.T) and np.all(np.linalg.eigvalsh(I) > 0) and not np.allclose(I, BODY["I"])
    assert I[0, 2] == 0.0  # a zero stays a zero
    assert isinstance(body["r"], list) and body["r"][1] == 0.0
    assert np.sign(body["r"][0]) == 1 and np.sign(body["r"][2]) == -1 and body["r"] != BODY["r"]
    assert np.isclose(np.linalg.norm(body["axis"]), 1.0) and body["axis"][0] == 0.0 and body["axis"] != BODY["axis"]
    assert np.array_equal(body["t"], BODY["t"]) and np.array_equal(body["table"], BODY["table"])
    assert varied(args, [5, 6])[1] == angle  # the same seed, the same draw
    assert varied(args, [5, 7])[1] != angle


def test_arguments_without_a_number_to_vary_give_no_second_input():
    assert varied(("euler", 3, [1, 2], True, np.zeros(3)), [1, 2]) is None
    assert second_args(None, ({"kind": "revolute", "parent": 0},), [1, 2]) is None


def test_a_probe_that_must_not_be_drawn_or_a_run_gets_no_varied_input():
    from grader.diagnosis import Declaration

    assert second_args(Declaration(draw=False), (0.5, 1.5), [1, 2]) is None
    assert second_args(Declaration(motion={"time": "t"}), (0.5, 1.5), [1, 2]) is None
    assert second_args(Declaration(args=("", "")), (0.5, 1.5), [1, 2]) is not None  # roles that draw nothing


# ------------------------------------------------------------------------------------------ on stand-ins


class StubChild:
    def __init__(self, function):
        self.function = function

    def call(self, probe, *args, timeout=None):
        return self.function(*args)


class StubOracle:
    """The reference of the made-up probes: live, or (``held``) a key that holds only the calls given."""

    def __init__(self, function, held=None):
        self.function = function
        self.held = held
        self.mode = "live" if held is None else "kit"
        self.asked = []

    def reference(self, probe, args, persist=False, check=None):
        self.asked.append(tuple(args))
        if self.held is not None and not any(_same(args, held) for held in self.held):
            raise GraderFault(f"the answer key holds no value for {probe}")
        return self.function(*args)

    def draw(self, site, make, seed, check=None):
        return make(np.random.default_rng([seed, len(site)]))


def _same(a, b):
    from grader.diagnosis.evidence import call_key

    return call_key("", tuple(a)) == call_key("", tuple(b))


def pose(body, gamma):
    """A made-up value of a described body: its rotation turned by gamma about its axis, applied to its offset,
    scaled by its mass, as a 3 x 3 matrix (the outer product with the axis)."""
    A = np.asarray(body["A"]) @ turn(body["axis"], gamma)
    return body["m"] * np.outer(A @ np.asarray(body["r"]), body["axis"]) + np.asarray(body["I"])


SHOWN = ({"name": "link", "m": 2.0, "A": turn([0.0, 0.0, 1.0], 0.3), "I": np.diag([1.0, 2.0, 3.0]),
          "r": [0.5, 0.2, 0.1], "axis": [0.0, 0.0, 1.0]}, 0.6)


def explain_case(student, reference=pose, held=None, probe="stub_drawn.body"):
    """The engine's finding for a failing comparison of ``probe`` on the one input ``SHOWN``."""
    oracle = StubOracle(reference, held)
    ctx = Context(99, StubChild(student), {}, None, 3, oracle)
    ctx.begin("p99.body_case")
    with pytest.raises(CheckFailure) as caught:
        assert_close(ctx.student(probe, *SHOWN), ctx.reference(probe, *SHOWN), "the body", TIGHT)
    return explained(ctx, caught.value), oracle


def test_a_slip_on_a_probe_that_declares_nothing_is_named_on_a_drawn_input():
    failure, oracle = explain_case(lambda body, gamma: pose(body, gamma).T)
    assert failure.diagnosis == "transpose"
    assert "on the input shown and on a second one" in failure.hint
    assert len(oracle.asked) >= 2 and not _same(oracle.asked[-1], SHOWN)


def test_a_slip_that_holds_on_the_input_shown_only_is_not_named():
    """The student's value is the transpose on the input shown and something else on any other: with one input the
    transpose would be named; the drawn input rules it out."""
    def student(body, gamma):
        value = pose(body, gamma)
        return value.T if gamma == SHOWN[1] else value.T + 0.3

    failure, _ = explain_case(student)
    assert failure.diagnosis == "" and failure.hint == ""


@pytest.fixture
def draws_only(monkeypatch):
    """The reference's calls of the tests below are the engine's draws only: the test of an ignored argument, heard
    beside every other tier, changes the arguments as well, and is not heard here (``test_ignored`` tests it)."""
    from grader.diagnosis import engine as explaining

    monkeypatch.setattr(explaining, "_ignored", lambda scene, evidences, *rest: [])


def test_a_draw_on_which_the_reference_raises_is_not_used(draws_only):
    """The reference refuses the first draw (a mass out of its range, say): the next draw is the second input."""
    drawn = []

    def reference(body, gamma):
        if not _same((body, gamma), SHOWN):
            drawn.append(gamma)
            if len(drawn) == 1:
                raise GraderFault("the reference failed on the drawn input")
        return pose(body, gamma)

    failure, _ = explain_case(lambda body, gamma: -pose(body, gamma), reference=reference)
    assert len(drawn) == 2 and failure.diagnosis == "sign_flip"
    assert "on the input shown and on a second one" in failure.hint


def test_a_second_input_is_drawn_past_many_refused_draws(draws_only):
    """The reference refuses the first five draws (a fixed point drawn beyond a linkage's reach, as half the draws
    of problem 4's point are, every grading of one check drawing the same): the engine draws on until it has one."""
    drawn = []

    def reference(body, gamma):
        if not _same((body, gamma), SHOWN):
            drawn.append(gamma)
            if len(drawn) <= 5:
                raise GraderFault("the reference failed on the drawn input")
        return pose(body, gamma)

    failure, _ = explain_case(lambda body, gamma: -pose(body, gamma), reference=reference)
    assert len(drawn) == 6 and failure.diagnosis == "sign_flip"
    assert "on the input shown and on a second one" in failure.hint


def test_a_degenerate_draw_is_not_used(draws_only):
    """The reference gives zeros on the first draw where the input shown gives none: the next draw is used."""
    drawn = []

    def reference(body, gamma):
        if not _same((body, gamma), SHOWN):
            drawn.append(gamma)
            if len(drawn) == 1:
                return np.zeros((3, 3))
        return pose(body, gamma)

    failure, _ = explain_case(lambda body, gamma: 2.0 * pose(body, gamma), reference=reference)
    assert len(drawn) == 2 and failure.diagnosis == "factor_two"


def test_a_value_that_does_not_change_with_the_arguments_gets_no_second_input(draws_only):
    """The compared value is a constant of the problem (the probe's arguments feed other results): a drawn input
    tells nothing, and a slip that one input shows is judged as on one input."""
    constant = np.array([[1.0, 2.0], [3.0, 4.0]])
    failure, oracle = explain_case(lambda body, gamma: constant.T, reference=lambda body, gamma: constant)
    assert failure.diagnosis == "transpose" and "This reproduces your answer here." in failure.hint
    assert len(oracle.asked) == 2  # the input shown, and one draw


def test_one_input_is_all_there_is_where_the_value_does_not_change_or_nothing_is_drawn(draws_only, monkeypatch):
    """Where a drawn input gives the same value, or there is nothing to draw, the input shown is marked ``alone``:
    the formula tier tries its slips there (its evidences say so); a value a drawn input changes is not alone, and
    neither is one on which no draw was usable (the reference raised on every draw)."""
    from grader.diagnosis import engine as explaining

    asked = []
    monkeypatch.setattr(explaining, "mutant_slips", lambda scene, evidences, *rest: asked.append(evidences) or [])

    def alone_after(student, **case):
        asked.clear()
        explain_case(student, **case)
        return [e.alone for e in asked[0][:1]] if asked else None

    constant = np.array([[1.0, 2.0], [3.0, 4.0]])
    assert alone_after(lambda body, gamma: constant + 0.7, reference=lambda body, gamma: constant) == [True]
    assert alone_after(lambda body, gamma: pose(body, gamma) + 0.7) == [False]

    def refusing(body, gamma):
        if not _same((body, gamma), SHOWN):
            raise GraderFault("the reference failed on the drawn input")
        return pose(body, gamma)

    assert alone_after(lambda body, gamma: pose(body, gamma) + 0.7, reference=refusing) == [False]
    monkeypatch.setattr(explaining, "second_args", lambda *args: None)  # nothing to draw
    assert alone_after(lambda body, gamma: pose(body, gamma) + 0.7) == [True]


def test_in_the_kit_a_draw_the_key_does_not_hold_names_nothing():
    """The key holds the input shown only: the kit cannot judge a second input, and names no cause rather than
    one judged on a single input."""
    failure, _ = explain_case(lambda body, gamma: pose(body, gamma).T, held=[SHOWN])
    assert failure.diagnosis == ""


def test_a_repeated_reference_call_is_counted_once(monkeypatch):
    class Oracle:
        mode = "live"

        def __init__(self):
            self.asked = 0

        def reference(self, probe, args, persist=False, check=None):
            self.asked += 1
            return np.array([float(args[0])])

    oracle = Oracle()
    scene = scenes.Scene(types.SimpleNamespace(oracle=oracle, check_id="p99.x"))
    monkeypatch.setattr(scenes, "MAX_REFERENCE_CALLS", 2)
    for _ in range(5):
        scene.reference("stub_drawn.plain", (1.0,))
    scene.reference("stub_drawn.plain", (2.0,))
    assert oracle.asked == 2 and scene.reference_calls == 2
    with pytest.raises(scenes.Budget, match="2 reference calls"):
        scene.reference("stub_drawn.plain", (3.0,))


# ------------------------------------------------------------------------------------------ graded


DRAWN, _, slot, test_the_graded_mistakes_are_of_their_families = graded_table(
    ROOT / "tests" / "engine" / "second_inputs.toml")


@pytest.mark.parametrize("mistake", DRAWN, ids=lambda m: m.name)
def test_a_mistake_shown_on_one_input_is_named_on_a_drawn_second_one(
        mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch):
    target, _ = assert_named_live_and_alike(mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch)
    assert "on the input shown and on a second one" in target.hint, target.hint
