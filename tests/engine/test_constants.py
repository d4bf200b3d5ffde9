"""The formula tier on module constants (``grader.diagnosis.mutants``: ``constant_mutants``): the data a student
types from the sheet into the constants of a problem's module or of the library (lengths, masses, gains, gravity)
may be typed otherwise (a number's sign, a factor 2, ten, a hundred or a thousand, degrees for radians, a square
root, an entry of a table exchanged or written 0, a matrix written out transposed, a vector written as its
direction alone, a sine for a cosine, two constants exchanged); those slips are tried after every slip of the code,
where none reproduced the student's value.

The test plants a mistake into a copy of the reference and asks the tier on two inputs, as
``tests/engine/test_mutants.py`` does: the library's gravity typed a tenth of itself reaches problem 24's triple
pendulum through the name its module imports and the constant it computes from it (``I_GRAV``), and so does the
gravity typed in centimetres per second squared (981).  The near miss is the gravity three times itself, which no
slip of typing gives: nothing is named.  A joint frame's rotation of
problem 32's table typed with its rows as columns is a transpose; with two rows changed otherwise, it is none.

A step's constant or a count of steps (``DT``, ``N_STEPS``: ``mutants._STEP_CONSTANT``) typed otherwise is a step
typed otherwise (the run takes steps of another size); a count stays an integer (``range`` takes it), and is not
typed a hundred or a thousand times itself; the near miss, a count at another value, is none.

A run's start (``A_IC0``, ``ANGLES0``: ``mutants._START``) written whole as a plain value, the identity or zeros, is
a wrong initial state, and its numbers typed otherwise that give the same within the tolerance (an angle a
thousandth of itself) are not told beside it; the near misses, a start at another angle, are no such slip.  A
slip of a start's numbers (two of its entries exchanged) starts the run from another state as truly: a wrong initial
state is told beside it.  Problem
8's runs read their constants only, and the second input is the same call at another angular velocity
(``probes._rebound``).

A slip in a constant that the second input draws anew is bound away there (the student's value is the expected
one): the slips of those constants are judged on the sheet's call alone (``mutants._drawn_constants``): a yaw
typed in degrees, a roll converted the wrong way, an angular velocity typed short; a yaw at another angle is
none.
"""

import numpy as np

from grader.diagnosis import mutants
from grader.private import drop_private

from .test_mutants import evidence, planted_package, scene

#: two states of the triple pendulum (angles, rates) at which its right-hand side is compared
STATES = [[(0.0, [0.3, -0.5, 0.8, 0.2, -0.1, 0.4])], [(0.0, [-0.7, 0.4, 0.1, -0.3, 0.6, 0.0])]]


def assert_told(found, name: str, detail: str) -> None:
    """The slips found are of ``name`` alone, and one of their hints says ``detail``."""
    assert {h.name for h in found} == {name}, [(h.name, h.detail) for h in found]
    assert any(detail in h.detail for h in found), [h.detail for h in found]


def planted_slips(tmp_path, file: str, old: str, new: str, probe: str, inputs, parts, check: str):
    """The formula tier's slips for a package with ``old`` written as ``new`` in ``file``, on two inputs of
    ``probe`` (each a tuple of its arguments) that the slip changes."""
    student = planted_package(tmp_path, file, old, new)
    try:
        evidences = [evidence(probe, args, parts, student) for args in inputs]
        assert all(not np.allclose(e.got, e.expected) for e in evidences)
        return mutants.mutant_slips(scene(check), evidences)
    finally:
        drop_private(student)


def pendulum_slips(tmp_path, new: str):
    return planted_slips(tmp_path, "conventions.py", "GRAVITY = 9.81", new, "problem_24.pendulum_ode",
                         [(cases,) for cases in STATES], (0,), "p24.pendulum_ode")


def test_a_library_constant_typed_otherwise_is_named(tmp_path):
    found = pendulum_slips(tmp_path, "GRAVITY = 0.981")
    assert {h.name for h in found} == {"wrong_factor"}, [(h.name, h.detail) for h in found]
    assert any("`GRAVITY` is a tenth" in h.detail for h in found), [h.detail for h in found]


def test_a_library_constant_typed_in_centimetres_is_named(tmp_path):
    found = pendulum_slips(tmp_path, "GRAVITY = 981.0")
    assert {h.name for h in found} == {"wrong_factor"}, [(h.name, h.detail) for h in found]
    assert any("`GRAVITY` is a hundred times" in h.detail and "cm for m" in h.detail for h in found), \
        [h.detail for h in found]


def torque_slips(tmp_path, new: str):
    """The tier on problem 32's torques that hold the arm against gravity, with its gravity constant written as
    ``new``."""
    return planted_slips(tmp_path, "problem_32.py", "I_GRAV = np.array([0.0, -GRAVITY, 0.0])", new,
                         "problem_32.torques", [([[0.3, -0.6, 0.9]],), ([[-0.8, 0.4, 1.3]],)], (0,),
                         "p32.gravity_trajectory")


def test_a_vector_constant_written_as_its_direction_is_named(tmp_path):
    found = torque_slips(tmp_path, "I_GRAV = np.array([0.0, -1.0, 0.0])")
    assert {h.name for h in found} == {"wrong_factor"}, [(h.name, h.detail) for h in found]
    assert any("`I_GRAV` is written as its direction alone" in h.detail for h in found), [h.detail for h in found]


def test_a_vector_constant_turned_is_no_direction(tmp_path):
    assert "wrong_factor" not in {h.name for h in torque_slips(tmp_path, "I_GRAV = np.array([0.0, -9.81, 1.0])")}


def steps_slips(tmp_path, new: str):
    """The tier on problem 8's Euler runs of the matrix and of the angles with the count of steps written as ``new``
    (the step ``DT`` is computed from it: a run over the same span)."""
    student = planted_package(tmp_path, "problem_08.py", "N_STEPS = 100", new)
    try:
        evidences = [evidence("problem_08.part", ("a",), (), student),
                     evidence("problem_08.part", ("b",), ("A_IC",), student)]
        assert all(not np.allclose(e.got, e.expected) for e in evidences)
        return mutants.mutant_slips(scene("p08.part_a"), evidences)
    finally:
        drop_private(student)


def test_a_count_of_steps_typed_a_tenth_is_a_step_typed_otherwise(tmp_path):
    """The count is an integer that ``range`` takes: typed a tenth, it stays one (10 steps, not 10.0), and the slip
    of a step's constant is of the step's size."""
    found = steps_slips(tmp_path, "N_STEPS = 10")
    assert {h.name for h in found} == {"step_typed"}, [(h.name, h.detail) for h in found]
    assert any("`N_STEPS`, a step or a count of steps" in h.detail for h in found), [h.detail for h in found]


def test_a_count_of_steps_at_another_value_is_no_step_typed(tmp_path):
    assert steps_slips(tmp_path, "N_STEPS = 37") == []


def test_a_constant_off_by_a_factor_no_typing_gives_names_nothing(tmp_path):
    assert pendulum_slips(tmp_path, "GRAVITY = 3.0 * 9.81") == []


def arm_slips(tmp_path, new: str):
    """The tier on problem 32's arm with its second joint frame's constant matrix written as ``new``."""
    old = "np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]),"
    return planted_slips(tmp_path, "problem_32.py", old, new, "problem_32.robot",
                         [([0.3, -0.6, 0.9],), ([-0.8, 0.4, 1.3],)], ("end_effector",), "p32.end_effector")


def test_a_constant_matrix_written_transposed_is_a_transpose(tmp_path):
    """A joint frame's rotation typed into the module's table with its rows as columns: a transpose."""
    assert_told(arm_slips(tmp_path, "np.array([[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]),"),
                "transpose", "`_A_PDP` is written transposed")


def test_a_constant_matrix_with_two_rows_changed_names_no_transpose(tmp_path):
    """The near miss: the rotation's first row negated and its last exchanged with the middle one (no transpose)."""
    found = arm_slips(tmp_path, "np.array([[0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]),")
    assert "transpose" not in {h.name for h in found}, [(h.name, h.detail) for h in found]


def rebound_slips(tmp_path, file: str, old: str, new: str, probe: str, args: list, bindings: list, path: tuple,
                  check: str):
    """The tier's slips for a planted package on a call without arguments to draw: the sheet's, and the same call
    at the module's constants ``bindings`` drawn anew (``probes._rebound``), as the engine's second input is."""
    return planted_slips(tmp_path, file, old, new, "_rebound.rebound",
                         [(probe, [], args), (probe, bindings, args)], path, check)


#: problem 8's angular velocity drawn anew
P08_OMEGA = [["problem_08", "I_OMEGA", [0.4, 0.7, 0.5]]]


def test_a_start_written_as_the_identity_is_a_wrong_initial_state(tmp_path):
    """Problem 8's start ``A_IC0`` typed as the identity: a start written whole as a plain value.  Its angle
    typed a thousandth of itself (a turn of nearly nothing) gives the same within the tolerance, and is not told
    beside it."""
    found = rebound_slips(tmp_path, "problem_08.py", "A_IC0 = R3(np.pi / 2)", "A_IC0 = np.eye(3)",
                          "problem_08.part", ["a"], P08_OMEGA, (), "p08.part_a")
    assert {h.name for h in found} == {"initial_state"}, [(h.name, h.detail) for h in found]
    assert any("the start `A_IC0` is written as the identity" in h.detail for h in found), [h.detail for h in found]


def test_a_start_at_another_angle_is_no_start_written_plainly(tmp_path):
    """The near miss: the start turned by 60 degrees rather than 90, which no plain value and no typing gives."""
    found = rebound_slips(tmp_path, "problem_08.py", "A_IC0 = R3(np.pi / 2)", "A_IC0 = R3(np.pi / 3)",
                          "problem_08.part", ["a"], P08_OMEGA, (), "p08.part_a")
    assert "initial_state" not in {h.name for h in found}, [(h.name, h.detail) for h in found]


def test_a_start_written_as_zeros_is_a_wrong_initial_state(tmp_path):
    """Problem 8's Cardan start ``ANGLES0`` typed as zeros (the second input draws the angular velocity only):
    a start written whole as a plain value, or its one entry other than zero written 0, where an entry of another
    table written 0 is a term left out."""
    found = rebound_slips(tmp_path, "problem_08.py", "ANGLES0 = np.array([0.0, 0.0, np.pi / 2])",
                          "ANGLES0 = np.array([0.0, 0.0, 0.0])", "problem_08.part", ["b"], P08_OMEGA, ("angles",),
                          "p08.part_b")
    assert {h.name for h in found} == {"initial_state"}, [(h.name, h.detail) for h in found]
    assert any("the start `ANGLES0` is written as zeros" in h.detail for h in found), [h.detail for h in found]


def test_a_start_typed_otherwise_is_no_wrong_initial_state(tmp_path):
    """The near miss: the yaw of the start typed 60 degrees rather than 90, which no plain value gives."""
    found = rebound_slips(tmp_path, "problem_08.py", "ANGLES0 = np.array([0.0, 0.0, np.pi / 2])",
                          "ANGLES0 = np.array([0.0, 0.0, np.pi / 3])", "problem_08.part", ["b"], P08_OMEGA,
                          ("angles",), "p08.part_b")
    assert "initial_state" not in {h.name for h in found}, [(h.name, h.detail) for h in found]


def test_two_entries_of_a_start_exchanged_are_an_exchange_and_a_wrong_initial_state(tmp_path):
    """Problem 8's Cardan start with its yaw typed into the pitch's slot: two entries of a constant exchanged, and,
    the constant being a start (``mutants._START``), a run that starts from another state as truly (``rivals``): both
    told, "could be" either.  The near misses are the slips of constants that are no start, above (the gravity
    typed a tenth of itself is that slip alone: ``assert_told``)."""
    found = rebound_slips(tmp_path, "problem_08.py", "ANGLES0 = np.array([0.0, 0.0, np.pi / 2])",
                          "ANGLES0 = np.array([0.0, np.pi / 2, 0.0])", "problem_08.part", ["b"], P08_OMEGA,
                          ("angles",), "p08.part_b")
    assert {h.name for h in found} == {"swapped", "initial_state"}, [(h.name, h.detail) for h in found]
    assert any("the start `ANGLES0` is typed otherwise" in h.detail for h in found), [h.detail for h in found]


def test_the_starts_by_the_course_notation():
    starts = ["A_IC0", "ANGLES0", "Q0", "QD0", "X_START", "START_ANGLES", "INITIAL_STATE"]
    others = ["I_OMEGA", "N_STEPS", "JOINT_1", "T10", "GRAVITY", "DT", "X_END"]
    assert all(mutants._START.match(name) for name in starts)
    assert not any(mutants._START.match(name) for name in others)


def drawn_constants_slips(tmp_path, file: str, old: str, new: str, probe: str, args: list, bindings: list,
                          path: tuple, check: str):
    """The tier's slips where a planted constant's slip shows on the sheet's call and not at the constants drawn
    anew: the drawn input binds the constant on both sides, so the student's value is the expected one there."""
    student = planted_package(tmp_path, file, old, new)
    try:
        shown = evidence("_rebound.rebound", (probe, [], args), path, student)
        drawn = evidence("_rebound.rebound", (probe, bindings, args), path, student)
        assert not np.allclose(shown.got, shown.expected) and np.allclose(drawn.got, drawn.expected)
        return mutants.mutant_slips(scene(check), [shown, drawn])
    finally:
        drop_private(student)


P06_ANGLES = [["problem_06", "GAMMA", 0.41], ["problem_06", "BETA", 0.97], ["problem_06", "ALPHA", 1.32]]


def test_a_drawn_constant_typed_otherwise_is_named_on_the_input_shown(tmp_path):
    """Problem 6's yaw typed in degrees (``GAMMA = 30.0``): right at the angles drawn anew, so the slips of the
    drawn constants are judged on the sheet's call alone."""
    found = drawn_constants_slips(tmp_path, "problem_06.py", "GAMMA = np.deg2rad(30.0)", "GAMMA = 30.0",
                                  "problem_06.frames", [], P06_ANGLES, ("A_IC1",), "p06.frames")
    assert {h.name for h in found} == {"degrees"}, [(h.name, h.detail) for h in found]
    assert any("the constant `GAMMA`" in h.detail for h in found), [h.detail for h in found]


def test_a_drawn_constant_at_another_value_is_named_nothing(tmp_path):
    """The near miss: the yaw at 35 degrees, which no slip of typing gives."""
    found = drawn_constants_slips(tmp_path, "problem_06.py", "GAMMA = np.deg2rad(30.0)", "GAMMA = np.deg2rad(35.0)",
                                  "problem_06.frames", [], P06_ANGLES, ("A_IC1",), "p06.frames")
    assert found == [], [(h.name, h.detail) for h in found]


def test_a_drawn_constant_converted_the_wrong_way_and_one_typed_short(tmp_path):
    """Problem 6's roll converted with rad2deg, and problem 8's angular velocity with sqrt(1/3) typed as 0.577:
    a conversion the other way, and an expression of numbers typed short (a slip of precision)."""
    found = drawn_constants_slips(tmp_path, "problem_06.py", "ALPHA = np.deg2rad(60.0)", "ALPHA = np.rad2deg(60.0)",
                                  "problem_06.frames", [], P06_ANGLES, ("A_IC3",), "p06.frames")
    assert any("the constant `ALPHA` is converted the wrong way" in h.detail for h in found), \
        [(h.name, h.detail) for h in found]
    found = drawn_constants_slips(tmp_path / "p08", "problem_08.py", "I_OMEGA = np.sqrt(1.0 / 3.0) * np.ones(3)",
                                  "I_OMEGA = 0.577 * np.ones(3)", "problem_08.part", ["a"],
                                  [["problem_08", "I_OMEGA", [0.4, 0.7, 0.5]]], (), "p08.part_a")
    assert {h.name for h in found} == {"rounded"}, [(h.name, h.detail) for h in found]


#: problem 34's constants of the gait drawn anew
P34_GAIT = [["problem_34", "PITCH", 0.05], ["problem_34", "HIP_AMPLITUDE", 0.3]]


def test_a_drawn_angle_typed_as_the_degrees_read_off_it_is_a_slip_of_degrees(tmp_path):
    """Problem 34's pitch of 0.03 rad typed as 1.7, the degrees a student reads off it to one decimal: the constant
    in degrees, rounded as typed."""
    found = drawn_constants_slips(tmp_path, "problem_34.py", "PITCH = 0.03", "PITCH = 1.7", "problem_34.biped",
                                  [0.37], P34_GAIT, ("outline",), "p34.biped")
    assert {h.name for h in found} == {"degrees"}, [(h.name, h.detail) for h in found]
    assert any("the constant `PITCH`" in h.detail for h in found), [h.detail for h in found]


def test_a_drawn_angle_near_its_degrees_but_no_rounding_of_them_is_named_nothing(tmp_path):
    """The near miss: the pitch typed as 1.9, which no rounding of its 1.72 degrees gives."""
    found = drawn_constants_slips(tmp_path, "problem_34.py", "PITCH = 0.03", "PITCH = 1.9", "problem_34.biped",
                                  [0.37], P34_GAIT, ("outline",), "p34.biped")
    assert "degrees" not in {h.name for h in found}, [(h.name, h.detail) for h in found]


def gravity_slips(tmp_path, new: str):
    """The tier on problem 38's walker with its gravity vector on the slope written as ``new``."""
    return planted_slips(tmp_path, "problem_38.py", "I_GRAV = np.array([np.sin(SLOPE), -np.cos(SLOPE), 0.0])", new,
                         "problem_38.walker_ode",
                         [([(0.3, [0.2, -0.4, 0.7, -1.1])],), ([(1.1, [-0.6, 0.5, -0.3, 0.9])],)],
                         (0,), "p38.walker_ode")


def test_an_expression_of_a_constant_with_the_wrong_sign_is_a_sign(tmp_path):
    """Problem 38's gravity on the slope typed ``[-np.sin(SLOPE), -np.cos(SLOPE), 0.0]``: an entry that is an
    expression (not a number) given a minus, which no slip of the code gives (the gravity's part along the slope
    alone turned)."""
    assert_told(gravity_slips(tmp_path, "I_GRAV = np.array([-np.sin(SLOPE), -np.cos(SLOPE), 0.0])"), "sign_flip",
                "`I_GRAV`")


def test_an_expression_of_a_constant_changed_otherwise_is_no_sign(tmp_path):
    """The near miss: the part along the slope of twice the slope's angle, which no sign gives."""
    found = gravity_slips(tmp_path, "I_GRAV = np.array([np.sin(2 * SLOPE), -np.cos(SLOPE), 0.0])")
    assert "sign_flip" not in {h.name for h in found}, [(h.name, h.detail) for h in found]


def test_a_constant_that_takes_a_sine_for_a_cosine_is_sin_and_cos_swapped(tmp_path):
    """Problem 38's gravity on the slope typed ``[np.sin(SLOPE), -np.sin(SLOPE), 0.0]``: the part across the slope a
    sine where its cosine belongs; the near miss, the part along the slope of twice the slope's angle, is none."""
    assert_told(gravity_slips(tmp_path / "a", "I_GRAV = np.array([np.sin(SLOPE), -np.sin(SLOPE), 0.0])"),
                "sin_cos_swapped", "the constant `I_GRAV` takes sin where cos belongs")
    found = gravity_slips(tmp_path / "b", "I_GRAV = np.array([np.sin(2 * SLOPE), -np.cos(SLOPE), 0.0])")
    assert "sin_cos_swapped" not in {h.name for h in found}, [(h.name, h.detail) for h in found]


def test_an_array_constant_of_single_precision_is_float32(tmp_path):
    """Problem 38's gravity on the slope typed as an array of ``dtype=np.float32``: its entries rounded to single
    precision, which the walker's right-hand side carries into its accelerations; the near miss, the gravity's
    entries typed to four decimals (a rounding no float32 gives), is no float32."""
    def slips(new, folder):  # the answers differ from the expected ones by little: beyond a tight tolerance
        student = planted_package(tmp_path / folder, "problem_38.py",
                                  "I_GRAV = np.array([np.sin(SLOPE), -np.cos(SLOPE), 0.0])", new)
        try:
            evidences = [evidence("problem_38.walker_ode", ([(t, y)],), (0,), student)
                         for t, y in ((0.3, [0.2, -0.4, 0.7, -1.1]), (1.1, [-0.6, 0.5, -0.3, 0.9]))]
            assert all(not np.array_equal(e.got, e.expected) for e in evidences)
            return mutants.mutant_slips(scene("p38.walker_ode"), evidences)
        finally:
            drop_private(student)

    assert_told(slips("I_GRAV = np.array([np.sin(SLOPE), -np.cos(SLOPE), 0.0], dtype=np.float32)", "single"), "float32",
                "`I_GRAV` is an array of single precision")
    found = slips("I_GRAV = np.round(np.array([np.sin(SLOPE), -np.cos(SLOPE), 0.0]), 4)", "rounded")
    assert "float32" not in {h.name for h in found}, [(h.name, h.detail) for h in found]


def test_an_entry_of_a_constant_written_0_is_a_term_left_out_and_an_offset(tmp_path):
    """Problem 46's wire anchor with its first coordinate typed 0: a number of the data the module holds, which
    is where the anchor sits; told as a term left out and as an offset, as an entry of a list that a given
    function sets is (``_ENTRIES``)."""
    states = [([[0.3, -0.5, 0.8, 0.0, 0.0, 0.0], [0.1, 0.4, -0.2, 0.0, 0.0, 0.0]],),
              ([[-0.6, 0.2, 0.5, 0.0, 0.0, 0.0], [0.9, -0.3, 0.1, 0.0, 0.0, 0.0]],)]
    found = planted_slips(tmp_path, "problem_46.py", "ANCHOR = np.array([-1.0, -1.0, -1.0])",
                          "ANCHOR = np.array([0.0, -1.0, -1.0])", "problem_46.event", states, ("values",),
                          "p46.event_function")
    assert {h.name for h in found} == {"missing_term", "offset"}, [(h.name, h.detail) for h in found]
    assert any("a number of the constant `ANCHOR`" in h.detail for h in found), [h.detail for h in found]
