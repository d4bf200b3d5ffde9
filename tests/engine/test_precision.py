"""The formula tier's slips of precision (``grader.diagnosis.mutants``: ``PRECISION_SLIPS``): a dtype of double
precision given as single, an argument converted to float32 at a function's start, a constant typed short (pi as
3.14, 9.81 as 9.8), and an expression of numbers or a module's constant typed short (``TYPED_DECIMALS``).  A dtype of
double precision given as an integer cuts every value to a whole number: far outside the band of precision, it is
tried among the other slips of the code (``integer_truncated``).

Each is a mistake planted into a copy of the reference (or of a made-up problem) that the tier names, and a near
miss it must not name: a value in the band of precision that no slip of precision reproduces, a constant typed so
short that the value leaves the band.  A slip of precision is tried on one input too (a comparison the engine cannot
draw a second input for), only where the student's value is in the band.  They are graded as ``grade batch``
grades in ``tests/engine/test_reached.py``.
"""

import numpy as np
import pytest

from checks._diagnoses import DIAGNOSES
from grader.checking import Tol
from grader.diagnosis import grammar, mutants
from grader.diagnosis.evidence import Evidence
from grader.private import drop_private

from .stand_ins import made_up_package
from .test_mutants import BEARINGS, evidence, made_up_evidences, planted_package, scene

TIGHT = Tol("tight", 1e-9, 1e-9)


def named(found) -> set:
    return {h.name for h in found}


def failing(evidences):
    """Every comparison fails, by little: the student's value is near the expected one but beyond the tolerance."""
    for e in evidences:
        assert not np.allclose(e.got, e.expected, rtol=1e-12, atol=1e-12)
        assert np.max(np.abs(e.got - e.expected)) <= 1e-2 * np.max(np.abs(e.expected))
    return evidences


def planted_slips(tmp_path, check_id, file, old, new, probe, inputs, path):
    student = planted_package(tmp_path, file, old, new)
    try:
        evidences = failing([evidence(probe, args, path, student) for args in inputs])
        return mutants.mutant_slips(scene(check_id), evidences)
    finally:
        drop_private(student)


# ------------------------------------------------------------------------------------------ on the reference


def test_values_converted_with_an_integer_dtype_are_named_cut_to_whole_numbers(tmp_path):
    """Problem 39's inertia converted with ``dtype=int``: its entries cut to whole numbers, far off the expected
    forces, on two inputs whose products of inertia (the entries the forces read) are no whole numbers above 1 (cut,
    they are not written 0)."""
    student = planted_package(tmp_path, "problem_39.py", "moment = np.cross(w, np.asarray(I2, dtype=float) @ w)",
                              "moment = np.cross(w, np.asarray(I2, dtype=int) @ w)")
    try:
        tilted = np.array([[4.0, 1.3, 2.7], [1.3, 5.0, 0.4], [2.7, 0.4, 6.0]])  # products of inertia above 1
        inputs = [(tilted, 10.0, 5.0, 9.81, 0.8), (1.7 * tilted, 7.0, 3.0, 9.81, 1.2)]
        evidences = [evidence("problem_39.bearing_forces", args, (0,), student) for args in inputs]
        assert all(not np.allclose(e.got, e.expected, rtol=1e-2) for e in evidences)
        found = mutants.mutant_slips(scene("p39.bearing_forces"), evidences)
    finally:
        drop_private(student)
    assert named(found) == {"integer_truncated"}, [(h.name, h.detail) for h in found]
    assert any("`bearing_forces` converts values with an integer dtype" in h.detail for h in found)
    assert DIAGNOSES["integer_truncated"].family == "precision"



def test_a_product_in_single_precision_is_named_float32(tmp_path):
    """Problem 39's inertia taken as float32 inside the moment of the bearing forces: the dtype given as single."""
    found = planted_slips(tmp_path, "p39.bearing_forces", "problem_39.py",
                          "moment = np.cross(w, np.asarray(I2, dtype=float) @ w)",
                          "moment = np.cross(w, np.asarray(I2, dtype=np.float32) @ w)",
                          "problem_39.bearing_forces", BEARINGS, (0,))
    assert named(found) == {"float32"}, [(h.name, h.detail) for h in found]
    assert any("`bearing_forces` computes in single precision" in h.detail for h in found)


def test_a_value_off_by_little_that_no_slip_of_precision_gives_names_nothing(tmp_path):
    """The near miss: the same moment off by a relative 3e-7, in the band of precision, but no float32 and no
    constant typed short gives it."""
    found = planted_slips(tmp_path, "p39.bearing_forces", "problem_39.py",
                          "moment = np.cross(w, np.asarray(I2, dtype=float) @ w)",
                          "moment = np.cross(w, np.asarray(I2, dtype=float) @ w) * (1.0 + 3e-7)",
                          "problem_39.bearing_forces", BEARINGS, (0,))
    assert found == [], [(h.name, h.detail) for h in found]


PENDULUM_STATES = [([(0.0, [0.3, -0.2, 0.5, 0.1, 0.4, -0.3])],), ([(0.5, [-0.7, 0.4, 0.1, -0.6, 0.2, 0.8])],)]


def test_a_runs_state_converted_to_single_precision_is_named_float32(tmp_path):
    """Problem 24's right-hand side with the state converted to float32 before the equations of motion: the
    argument converted at the function's start."""
    found = planted_slips(tmp_path, "p24.pendulum_ode", "problem_24.py", "    q, qd = y[:3], y[3:]\n",
                          "    y = y.astype(np.float32)\n    q, qd = y[:3], y[3:]\n", "problem_24.pendulum_ode",
                          PENDULUM_STATES, (0,))
    assert named(found) == {"float32"}, [(h.name, h.detail) for h in found]
    assert any("`pendulum_ode` converts an argument to single precision" in h.detail for h in found)


def test_an_attribute_of_its_object_converted_to_single_precision_is_named_float32(tmp_path):
    """Problem 14's screw axis computed from the body's velocity converted to float32 (``self.B_v_B.astype(...)``), on
    a run of steps from a drawn start: the reads of an attribute converted, the object's "argument".  The near miss:
    the screw axis off by a relative 3e-7, which no conversion gives."""
    from checks.problem_13 import SCREW
    from checks._rigid import sheet_state

    rng = np.random.default_rng(3)
    start = sheet_state({key: [float(x) for x in rng.uniform(-1.5, 1.5, 3)]
                         for key in ("B_v_B", "B_omega_B", "B_a_B", "B_omegaDot_B")})
    old = "w, v = self.B_omega_B, self.B_v_B"
    for new, names in (("w, v = self.B_omega_B, self.B_v_B.astype(np.float32)", {"float32"}),
                       ("w, v = self.B_omega_B * (1.0 + 3e-7), self.B_v_B", set())):
        student = planted_package(tmp_path / str(len(names)), "rigid_body.py", old, new)
        try:
            first = evidence("problem_14.screw_run", (start, 0.01, 20), ("screw",), student, tol=SCREW)
            first.alone = True
            found = mutants.mutant_slips(scene("p14.run_screw"), failing([first]))
        finally:
            drop_private(student)
        assert named(found) == names, [(h.name, h.detail) for h in found]
    assert any("`screw_axis` converts an argument to single precision" in h.detail for h in found) or not names


def test_a_slip_of_precision_needs_no_difference_where_the_student_has_none():
    """A slip of precision reproduces the student's value closely (``mutants._closely``: within a tenth of the
    difference); on an input where the student's value is the expected one within the tolerance (another state of a
    run, its last digits rounded otherwise) there is none to reproduce: a mutant within the tolerance of it is close
    enough.  Where there is a difference, a value a tenth of it away is not."""
    expected = np.array([1.0, -2.0, 0.5])
    same = Evidence(expected + 1.4e-17, expected, TIGHT, "value")
    assert mutants._closely(expected + 2.8e-17, same)
    shown = Evidence(expected + 1e-6, expected, TIGHT, "value")
    assert mutants._closely(expected + 1e-6 + 1e-8, shown)
    assert not mutants._closely(expected + 1e-6 + 2e-7, shown)


def test_a_slip_of_precision_is_not_told_outside_the_band():
    """A student's value off the expected one by more than ``PRECISION_BAND`` is no loss of precision, nor is one
    that equals it."""
    expected = np.array([1.0, -2.0, 0.5])

    def at_difference(d):
        return Evidence(expected + np.array([0.0, d, 0.0]), expected, TIGHT, "value")

    assert mutants._in_band(at_difference(1e-7)) and mutants._in_band(at_difference(0.019))
    assert not mutants._in_band(at_difference(0.03)) and not mutants._in_band(at_difference(0.0))
    assert not mutants._in_band(Evidence(np.array([np.nan, 0.0, 0.0]), expected, TIGHT, "value"))


# ------------------------------------------------------------------------------------------ a made-up problem


SOURCE = '''"""A made-up problem for the slips of precision."""

import numpy as np


def turn(n, w):
    """The angle and the point on the unit circle after ``n`` steps of ``pi / n`` at the rate ``w``."""
    # BEGIN SOLUTION problem 97
    step = np.pi / n
    angle = w * step * n
    return np.array([angle, np.cos(angle), np.sin(angle)])
    # END SOLUTION


def weight(m):
    """The weight of ``m`` under g = 9.81."""
    # BEGIN SOLUTION problem 97
    return np.array([0.0, -m * 9.81, 0.0])
    # END SOLUTION


def shares(m):
    """The mass of each of six equal points that make up ``m``."""
    # BEGIN SOLUTION problem 97
    return m / 6 * np.ones(6)
    # END SOLUTION
'''


@pytest.fixture
def made_up(tmp_path, monkeypatch):
    """A package of one made-up problem (97) that the tier mutates in place of the reference."""
    with made_up_package(tmp_path, monkeypatch, SOURCE, 97, "precision") as package:
        yield package


def shown_alone(package, name, student, args):
    """The one comparison of ``name(*args)``: the engine has no second input of it."""
    return made_up_evidences(package, name, student, [args], number=97)


def one_input(package, name, student, args):
    """The one failing comparison of ``name(*args)``, off by little."""
    return failing(shown_alone(package, name, student, args))


def test_pi_typed_short_is_named_rounded_on_one_input(made_up):
    """``pi`` typed as 3.1416 in the step: on the one input shown, a constant typed short reproduces it."""
    def student(n, w):
        angle = w * (3.1416 / n) * n
        return np.array([angle, np.cos(angle), np.sin(angle)])

    found = mutants.mutant_slips(scene("p97.turn"), one_input(made_up, "turn", student, (40, 1.3)))
    assert named(found) == {"rounded"} and {DIAGNOSES[h.name].family for h in found} == {"precision"}
    assert any("`turn` uses a constant typed short" in h.detail for h in found)


def test_g_typed_short_is_named_rounded_on_one_input(made_up):
    found = mutants.mutant_slips(scene("p97.weight"), one_input(made_up, "weight", lambda m: [0.0, -m * 9.8, 0.0],
                                                                (2.5,)))
    assert named(found) == {"rounded"}


def test_a_division_by_a_number_typed_as_its_reciprocal_short_is_named_rounded(made_up):
    """``0.167 * m * ...`` for ``m / 6 * ...``: the reciprocal of the number typed to three decimals, a constant typed
    short; the near miss, ``0.16 * m``, leaves the band of precision and is named nothing."""
    found = mutants.mutant_slips(scene("p97.shares"), one_input(made_up, "shares", lambda m: 0.167 * m * np.ones(6),
                                                                (2.5,)))
    assert named(found) == {"rounded"}, [(h.name, h.detail) for h in found]
    (shown,) = shown_alone(made_up, "shares", lambda m: 0.16 * m * np.ones(6), (2.5,))
    assert mutants.mutant_slips(scene("p97.shares"), [shown]) == []


def test_pi_typed_far_too_short_is_no_slip_of_precision(made_up):
    """The near miss: pi as 3 leaves the band of precision (5% off): on one input the tier names nothing."""
    def student(n, w):
        angle = w * (3.0 / n) * n
        return np.array([angle, np.cos(angle), np.sin(angle)])

    (shown,) = shown_alone(made_up, "turn", student, (40, 1.3))
    assert not mutants._in_band(shown)
    assert mutants.mutant_slips(scene("p97.turn"), [shown]) == []


def test_on_one_input_only_slips_of_precision_are_tried(made_up, monkeypatch):
    """On one input no slip of another kind is named, even one that reproduces the value in the band (``w``
    left out of the angle, with ``w`` near 1)."""
    def student(n, w):
        angle = (np.pi / n) * n
        return np.array([angle, np.cos(angle), np.sin(angle)])

    evidences = one_input(made_up, "turn", student, (40, 1.0 + 2e-4))
    assert mutants.mutant_slips(scene("p97.turn"), evidences) == []
    tried = []
    monkeypatch.setattr(mutants, "_evaluate", lambda package, made, *a, **k: tried.extend(made) or [])
    mutants.mutant_slips(scene("p97.turn"), evidences)
    assert tried and {m.slip for m in tried} <= mutants.PRECISION_SLIPS


# ------------------------------------------------------------------------------------------ a constant typed short


WALKER_STATES = [([(0.0, [0.2, -0.3, 0.5, -0.4])],), ([(0.3, [-0.1, 0.25, -0.6, 0.8])],)]


def test_a_module_constant_typed_short_is_named_rounded(tmp_path):
    """Problem 38's slope gravity typed to three decimals, (0.017, -1.0, 0), where the sheet's 1 degree belongs: the
    right-hand side reads the module's constant, and its value rounded reproduces the student's on both states."""
    found = planted_slips(tmp_path, "p38.walker_ode", "problem_38.py",
                          "I_GRAV = np.array([np.sin(SLOPE), -np.cos(SLOPE), 0.0])",
                          "I_GRAV = np.array([0.017, -1.0, 0.0])", "problem_38.walker_ode", WALKER_STATES, (0,))
    assert named(found) == {"rounded"}, [(h.name, h.detail) for h in found]
    assert any("`walker_ode` uses a constant typed short" in h.detail for h in found)


def test_a_module_constant_typed_at_the_sheets_four_decimals_is_named_rounded(tmp_path):
    """Problem 6's pitch typed to the four decimals the sheet prints, 0.7854 for 45 degrees: the frames read the
    module's constant, and its value rounded reproduces the student's on the one input there is; typed with its
    last digit wrong (0.7853), no rounding gives it."""
    for typed, told in (("0.7854", {"rounded"}), ("0.7853", set())):
        found = planted_slips(tmp_path / typed, "p06.frames", "problem_06.py", "BETA = np.deg2rad(45.0)",
                              f"BETA = {typed}", "problem_06.frames", [()], ("A_IC2",))
        assert named(found) == told, (typed, [(h.name, h.detail) for h in found])


def test_a_slope_left_out_of_a_module_constant_is_no_constant_typed_short(tmp_path):
    """The near miss: the slope's component written 0 (gravity straight down) is what the same constant rounded to
    one decimal gives, but a term left out, not a value typed short: no slip of precision is told."""
    student = planted_package(tmp_path, "problem_38.py", "I_GRAV = np.array([np.sin(SLOPE), -np.cos(SLOPE), 0.0])",
                              "I_GRAV = np.array([0.0, -1.0, 0.0])")
    try:
        evidences = [evidence("problem_38.walker_ode", args, (0,), student) for args in WALKER_STATES]
        found = mutants.mutant_slips(scene("p38.walker_ode"), evidences)
    finally:
        drop_private(student)
    assert "rounded" not in named(found), [(h.name, h.detail) for h in found]


def test_the_largest_expression_of_numbers_is_typed_short_and_pi_alone_is_not():
    """An expression of numbers is typed short as a whole (``np.sqrt(3.0) * np.pi`` as 5.441, not its parts); a
    read of a name other than a module's constant, or pi alone (``short``: 3.14), is no such expression."""
    statement = mutants.ast.parse("x = w * (np.pi / 40) * n + np.sqrt(3.0) * np.pi + np.pi + GAMMA + alpha").body[0]
    sites = [mutants.ast.unparse(node) for node, parent, _, _ in mutants._parented(statement)
             for slip, _ in mutants._typed_slips(node, parent, frozenset({"GAMMA"}))]
    assert sites == [site for site in ("np.pi / 40", "np.sqrt(3.0) * np.pi", "GAMMA")
                     for _ in mutants.TYPED_DECIMALS], sites


# ------------------------------------------------------------------------------- a rounding that keeps digits


def test_an_answer_rounded_to_whole_numbers_is_named_where_it_keeps_two_digits():
    """Forces of order ten returned as whole numbers (``int()`` or ``round()`` of each): two significant digits are
    kept of the largest, a rounding a student writes."""
    E = np.array([12.3418, -7.8106, 31.0552])
    found = grammar.precision_slips(np.round(E), E, TIGHT)
    assert [h.key for h in found] == ["rounded:0"], found
    assert "rounded to 0 decimals" in found[0].detail


def test_values_of_order_one_rounded_to_whole_numbers_are_no_slip_of_precision():
    """The near miss: the same rounding of values of order one keeps one digit or none, a coincidence an offset or a
    factor lands on; the same values to one decimal keep two digits and are named."""
    E = np.array([1.3418, -0.7811, 0.3055])
    assert grammar.precision_slips(np.round(E), E, TIGHT) == []
    assert [h.key for h in grammar.precision_slips(np.round(E, 1), E, TIGHT)] == ["rounded:1"]
