"""A value the engine has on one input only: a run's start, and any value no second input can be drawn for.

A start that differs is what the answer shows, not what made it so: where the grammar of a value gives the
student's start from the given one (rounded, entries exchanged, negated), that slip is told beside the wrong start
(``engine._start_slips``).  The start is one value, so it must say enough of its slip to be told as what made it: the
entries that differ from the given start must be ``evidence.ONE_INPUT_NUMBERS`` distinct values or more
(``evidence.numbers_told``); one number or two (a pair exchanged) are matched by some of the grammar's many slips by
chance, and entries that repeat one value say it once.  On fewer numbers the slip is told as a twin of the wrong
start ("could be" either): one angle typed with the wrong sign is as truly a sign slip as a wrong start.

Any other value the engine has on one input (nothing to draw: a constant of the model, a value whose arguments do
not change it) is held to the same rule for the slips of a number's size (``engine.BY_CHANCE``: a factor, a unit,
a rounding) where it is an array: they are told on it only where it differs in ``ONE_INPUT_NUMBERS`` entries or
more (``engine._told_enough``).  A joint placed a whole link along an axis where half a link belongs is twice the
expected offset in its one entry: what made the number is not what the array's shape says.  A single number is the
whole answer and keeps its factor, and so does an array off in three entries that repeat one value (a diagonal
matrix halved); a sign or an exchange of entries relates entries of the value itself and keeps its name.

The runs and values below are made up, each a slip none of the fresh sets holds; the near misses are a start no
slip gives, the same slip on too few numbers, and a value of three numbers on one input, which keeps its slip.
"""

import numpy as np

import grader.diagnosis as engine
from grader.checking import Tol
from grader.diagnosis import Declaration, Evidence, explain
from grader.diagnosis.evidence import ONE_INPUT_NUMBERS, numbers_told
from tests.engine.stand_ins import StandInChild, StandInOracle

TIGHT = Tol("tight", 1e-9, 1e-9)


class _Ctx:
    check_id = "p99.one"
    oracle = StandInOracle({})
    child = StandInChild({})
    seed = 1


def _names(finding):
    return () if finding is None else finding.names


def test_the_numbers_a_value_says_are_its_distinct_values_off_the_expected_ones():
    expected = np.array([0.3, -1.2, 0.7, 2.5])
    assert numbers_told(-expected, expected, TIGHT) == 4
    assert numbers_told(expected[[0, 2, 1, 3]], expected, TIGHT) == 2  # a pair exchanged
    assert numbers_told(np.array([0.3, -1.2, -0.7, 2.5]), expected, TIGHT) == 1
    assert numbers_told(np.array([0.3, 5.0, 5.0, 5.0]), expected, TIGHT) == 1  # one value, repeated
    assert numbers_told(np.array(0.87), np.array(0.8734), TIGHT) == 1
    assert numbers_told(expected, expected, TIGHT) == 0
    assert numbers_told(np.zeros((2, 2)), expected, TIGHT) == 1  # another shape: its own values
    assert ONE_INPUT_NUMBERS == 3


# ------------------------------------------------------------------------------------------ a run's start

T = np.linspace(0.0, 1.0, 51)
#: the given start of three angles, and their start rates
START, RATES = np.array([np.pi / 5, -np.pi / 7, np.pi / 3]), np.array([0.4, -0.2, 0.9])


def _run(q0):
    """Three angles that swing (a start off keeps no constant offset)."""
    return {"t": T, "q": np.outer(np.cos(3 * T), q0) + np.outer(np.sin(3 * T), RATES / 3)}


def _explain_start(monkeypatch, start):
    """A run ``turn()`` of three angles from the module's start, the student's from ``start``."""
    monkeypatch.setitem(engine.DECLARATIONS, "stub.turn", Declaration(motion={"time": "t", "states": ("q",)}))
    expected, got = _run(START), _run(start)

    class Ctx(_Ctx):
        calls = [("reference", "stub.turn", (), expected), ("student", "stub.turn", (), got)]
        oracle = StandInOracle({"stub.turn": lambda: expected})
        child = StandInChild({"stub.turn": lambda: got})

    return explain(Ctx(), [Evidence(got["q"], expected["q"], Tol("band", 1e-3), "q", got, expected)])


def test_a_start_typed_short_is_told_as_rounded_beside_the_wrong_start(monkeypatch):
    finding = _explain_start(monkeypatch, np.round(START, 2))
    assert set(_names(finding)) == {"initial_state", "rounded"}, finding
    assert "rounded to 2 decimals" in finding.hint, finding.hint


def test_a_start_cut_to_whole_numbers_is_told_beside_the_wrong_start(monkeypatch):
    """``np.asarray(q0, dtype=int)``: every angle of the start cut to a whole number (0, 0 and 1: three numbers off),
    told as values cut to whole numbers beside the wrong start; a start of 1.3 times the given one is not."""
    finding = _explain_start(monkeypatch, np.trunc(START))
    assert set(_names(finding)) == {"initial_state", "integer_truncated"}, finding
    assert "cut to whole numbers" in finding.hint, finding.hint
    assert "integer_truncated" not in _names(_explain_start(monkeypatch, 1.3 * START))


def test_a_start_wrong_in_a_number_or_two_by_a_slip_is_told_could_be_that_slip(monkeypatch):
    """One angle typed with the wrong sign, two angles exchanged: too few numbers to tell the slip as what made
    the start, so it is told as a twin of the wrong start ("could be" either)."""
    finding = _explain_start(monkeypatch, START * np.array([1.0, -1.0, 1.0]))
    assert set(_names(finding)) == {"initial_state", "sign_flip"}, finding
    assert "entry 2 has the opposite sign" in finding.hint and finding.hint.startswith("Could be"), finding.hint
    assert set(_names(_explain_start(monkeypatch, START[[1, 0, 2]]))) == {"initial_state", "swapped"}


def test_a_start_that_no_slip_gives_is_told_as_a_wrong_start_alone(monkeypatch):
    """The near misses: a start off by amounts no slip of a value gives, and a start with one angle rounded (one
    number says nothing of a rounding)."""
    finding = _explain_start(monkeypatch, START + np.array([0.013, -0.021, 0.008]))
    assert _names(finding) == ("initial_state",), finding
    one = START.copy()
    one[1] = round(one[1], 2)
    assert _names(_explain_start(monkeypatch, one)) == ("initial_state",)


#: a run of two states: a matrix's nine entries that drift at a constant rate (a motion that does not depend on where
#: it is: a start moved keeps its offset) and three rates that stay as they are
MATRIX, DRIFT = np.linspace(-0.93, 0.87, 9) + np.pi / 1000, np.linspace(0.1, 0.9, 9)
W = np.array([0.3, -1.1, 0.7]) + np.e / 1000


def _drift(start):
    return {"t": T, "A": start + np.outer(T, DRIFT), "w": np.tile(W, (T.size, 1))}


def _explain_drift(monkeypatch, start):
    """A run ``drift()`` of a matrix and rates, the student's from the matrix ``start``, compared tightly."""
    monkeypatch.setitem(engine.DECLARATIONS, "stub.drift", Declaration(motion={"time": "t", "states": ("A", "w")}))
    expected, got = _drift(MATRIX), _drift(start)

    class Ctx(_Ctx):
        calls = [("reference", "stub.drift", (), expected), ("student", "stub.drift", (), got)]
        oracle = StandInOracle({"stub.drift": lambda: expected})
        child = StandInChild({"stub.drift": lambda: got})

    return explain(Ctx(), [Evidence(got["A"], expected["A"], Tol("tight", 1e-12, 1e-12), "A", got, expected)])


def test_a_start_of_one_state_in_float32_is_told_as_float32_beside_the_wrong_start_not_an_offset(monkeypatch):
    """``as_matrix(A_IB).astype(np.float32)``: the start of one state (a matrix) in single precision, the other
    states' in double: the rounded state's every entry is exact in single precision, which no number count tells,
    and the run keeps the start's offset: told as the start made in float32, not as a constant offset; a start of
    that state moved by a like amount that no rounding gives is told as a wrong start or an offset."""
    finding = _explain_drift(monkeypatch, MATRIX.astype(np.float32).astype(float))
    assert set(_names(finding)) == {"initial_state", "float32"}, finding
    moved = _explain_drift(monkeypatch, MATRIX + 3e-8)
    assert "float32" not in _names(moved) and "offset" in _names(moved), moved


# ------------------------------------------------------------------------------------------ any value on one input


def _explain_one(monkeypatch, expected, got):
    """A value ``place()`` that no second input can be drawn for (its declaration draws nothing): the reference's
    ``expected``, the student's ``got``."""
    monkeypatch.setitem(engine.DECLARATIONS, "stub.place", Declaration(draw=False))
    expected, got = np.asarray(expected, dtype=float), np.asarray(got, dtype=float)

    class Ctx(_Ctx):
        calls = [("reference", "stub.place", (), expected), ("student", "stub.place", (), got)]
        oracle = StandInOracle({"stub.place": lambda: expected})
        child = StandInChild({"stub.place": lambda: got})

    return explain(Ctx(), [Evidence(got, expected, TIGHT, "place", got, expected)])


def test_a_slip_of_the_grammar_on_one_input_is_told_where_the_value_says_enough(monkeypatch):
    """The near miss: a point of three distinct coordinates, all doubled, on the one input there is."""
    point = np.array([0.31, -0.52, 0.17])
    assert _names(_explain_one(monkeypatch, point, 2 * point)) == ("factor_two",)
    assert _names(_explain_one(monkeypatch, point, -point)) == ("sign_flip",)


def test_one_or_two_numbers_off_on_one_input_name_no_factor_or_rounding(monkeypatch):
    """Planted: a joint placed one link length along y, where the expected offset is half a link (one number, twice
    the expected one, by what the offset is and not by a factor); a point's two coordinates at a tenth of their
    size (a unit, on two entries).  The near misses: a single number rounded keeps its rounding (it is the whole
    answer), a diagonal matrix halved its factor (three entries); a coordinate typed negated, or two exchanged,
    keep their slips (entries of the value itself)."""
    assert _names(_explain_one(monkeypatch, [0.0, -0.25, 0.0], [0.0, -0.5, 0.0])) == ()
    assert _names(_explain_one(monkeypatch, [0.31, 0.0, -0.52], [0.031, 0.0, -0.052])) == ()
    assert _names(_explain_one(monkeypatch, 1.2346, 1.23)) == ("rounded",)
    assert _names(_explain_one(monkeypatch, 0.7 * np.eye(3), 0.35 * np.eye(3))) == ("factor_half",)
    assert _names(_explain_one(monkeypatch, [0.31, -0.52, 0.17], [0.31, 0.52, 0.17])) == ("sign_flip",)
    assert _names(_explain_one(monkeypatch, [0.31, -0.52, 0.17], [-0.52, 0.31, 0.17])) == ("swapped",)


def test_a_checks_wrong_start_is_told_with_the_slip_that_makes_it():
    """A check that names a run's wrong start itself (``checks._dynamics.wrong_start``) tells the slip of a value
    beside it as the engine does: a start at rest in the middle position with its rates typed as half of them; the
    near miss, a start no slip gives, is a wrong start alone."""
    from checks._dynamics import wrong_start

    given = np.concatenate([np.zeros(3), RATES])
    hint, diagnosis = wrong_start(np.concatenate([np.zeros(3), RATES / 2]), given, "Start at the given state.")
    assert diagnosis == "initial_state or factor_half" and "Start at the given state." in hint, (diagnosis, hint)
    assert "your value is half the expected one" in hint, hint
    assert wrong_start(given + 0.013, given, "Start at the given state.") == ("Start at the given state.",
                                                                            "initial_state")
