"""Rivals of another family that the same evidence holds: one slip read two ways is told "could be X or Y", and a
name more particular than another is told only where the evidence proves it.

* The formula tier (``mutants.rivals``): a product with a quantity where the division by it belongs uses the
  quantity as its reciprocal (a scale and an inverse alike; a number's factor is a scale only); a point subtracted
  from a position and left out (``p - X_r_Y`` as ``X_r_Y``) is a position taken from the origin, as ``X_r_Y - p``
  is; where the test of an ignored argument could change none of the call's arguments, a parameter with a
  default that the slip leaves unused is an argument ignored as well; two entries exchanged that are one
  expression of a quantity and of its rate read each where the other belongs (a state row as well); two names
  unpacked from a run's state exchanged read the state from each other's rows; an object that a run counted in steps
  starts from, built ignoring a value it is given, starts the run from another state.
* The test of an ignored argument (``engine._ignored``): an angle or a rotation ignored, where the student's value
  is the reference's with it turning nothing, is a rotation left out as well (a frame slip).

Each is shown on a mistake planted into a made-up problem, and each has its near miss.
"""

import importlib

import numpy as np
import pytest

from grader.checking import Tol
from grader.diagnosis import Declaration
from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, Source, array_of, at
from grader.diagnosis.grammar import unturned

from tests.kit_support import (  # noqa: F401 (fixtures)
    assert_told_alike,
    warm_slot,
)
from tests.submissions import Planted

from .stand_ins import made_up_package
from .test_ignored import _explain
from .test_mutants import scene

TIGHT = Tol("tight", 1e-9, 1e-9)

SOURCE = '''"""A made-up problem whose slips have rivals of another family."""

import numpy as np

CENTRE = np.array([0.5, -0.25, 1.0])


def rate(k, m):
    """``(k / m, k / 2)``."""
    # BEGIN SOLUTION problem 98
    return np.array([k / m, k / 2.0])
    # END SOLUTION


def stretch(I_r_IE, centre=CENTRE, length=1.5):
    """The stretch of a cord from ``centre`` to the point E, ``|centre - I_r_IE| - length``, and E's height."""
    # BEGIN SOLUTION problem 98
    return np.array([np.linalg.norm(centre - I_r_IE) - length, I_r_IE[2]])
    # END SOLUTION


def slip_speed(I_v_P, v_belt):
    """The speed of P relative to a belt, ``|v_belt - I_v_P|``, and P's first component."""
    # BEGIN SOLUTION problem 98
    return np.array([np.linalg.norm(v_belt - I_v_P), I_v_P[0]])
    # END SOLUTION


def step_height(t, y, s=0.4):
    """The height of a sliding point above a slope, ``h - s x + t / 10``, with ``x, h = y[:2]``."""
    # BEGIN SOLUTION problem 98
    x, h = y[:2]
    return np.array([h - s * x + 0.1 * t])
    # END SOLUTION


def joint_rates(S, qd, qdd):
    """A joint's ``(S qd, S qdd)``."""
    # BEGIN SOLUTION problem 98
    return np.concatenate([S @ qd, S @ qdd])
    # END SOLUTION


def two_loads(S, u, w):
    """Two loads ``(S u, S w)`` mapped alike."""
    # BEGIN SOLUTION problem 98
    return np.concatenate([S @ u, S @ w])
    # END SOLUTION


def heat(m, c, dT, t):
    """The heat ``m c dT`` that warms a body by ``dT``, and the time ``t`` over which it flows."""
    # BEGIN SOLUTION problem 98
    return np.array([m * c * dT, t])
    # END SOLUTION


LEVER = 2.0
#: the ropes' direction, outside the solution (no entry of it is the formula tier's to leave out)
UP = np.array([0.0, 1.0])


def ropes(W, T):
    """Two ropes' pulls ``W/2 + (0, 2 T / LEVER)`` and ``W/2 - (0, 2 T / LEVER)``: the weight ``W`` shared, a
    torque ``T`` about the middle taken up at the ropes' lever."""
    # BEGIN SOLUTION problem 98
    spread = 2.0 * T / LEVER * UP
    return np.concatenate([0.5 * (W + spread), 0.5 * (W - spread)])
    # END SOLUTION


def lean(v, s=0.4):
    """``b - s a`` of a vector's first entries ``a, b = v[:2]`` (no run's state)."""
    # BEGIN SOLUTION problem 98
    a, b = v[:2]
    return np.array([b - s * a])
    # END SOLUTION
'''


@pytest.fixture
def made_up(tmp_path, monkeypatch):
    """A package of one made-up problem (98) that the formula tier mutates in place of the reference."""
    with made_up_package(tmp_path, monkeypatch, SOURCE, 98, "rivals") as package:
        yield package


def _found(package, name, student, inputs, untested=False, unreached=(), probe=None, tol=TIGHT):
    """The formula tier's hypotheses for the student's ``student`` where the made-up ``name`` belongs (``probe``:
    the probe of the call, where not one that passes its arguments on as they come)."""
    def passing(pkg, *args):
        return getattr(importlib.import_module(f"{pkg.__name__}.problem_98"), name)(*args)

    probe = passing if probe is None else probe

    evidences = [Evidence(array_of(student(*args)), array_of(at(probe(package, *args), ())), tol, "value",
                          source=Source(probe, args, ())) for args in inputs]
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    found = mutants.mutant_slips(scene("p98.made_up"), evidences, untested=untested, unreached=unreached)
    return {h.name for h in found}, found


def V(*x):
    return np.array(x, dtype=float)


# ------------------------------------------------------------------------------------------ a reciprocal


def test_a_product_with_a_quantity_for_the_division_is_also_its_reciprocal(made_up):
    """``k m`` where ``k / m`` belongs: a factor off (scale) and ``m`` used as its reciprocal (inverse), both
    told; the reciprocal is the same edit read another way (a twin, left out where it would take the families
    past two)."""
    names, found = _found(made_up, "rate", lambda k, m: np.array([k * m, k / 2.0]), [(3.0, 0.8), (1.7, 2.5)])
    assert names == {"wrong_factor", "reciprocal_argument"}, [(h.name, h.detail) for h in found]
    assert [h.name for h in found if h.twin] == ["reciprocal_argument"]
    assert any("`rate` multiplies by a quantity where it should divide by it" in h.detail for h in found)


def test_a_product_with_a_number_for_the_division_is_a_scale_only(made_up):
    """The near miss: ``2 k`` where ``k / 2`` belongs is a constant factor (4): no quantity used as its
    reciprocal."""
    names, found = _found(made_up, "rate", lambda k, m: np.array([k / m, k * 2.0]), [(3.0, 0.8), (1.7, 2.5)])
    assert names == {"wrong_factor"}, [(h.name, h.detail) for h in found]


# ------------------------------------------------------------------------------------------ unlike slips alike

#: a tolerance of a few newtons on pulls of tens of kilonewtons: the torque's share, which the student leaves out,
#: is far outside it, and a factor of it left out (``2 / LEVER``), or it upside down (``LEVER / 2T``), far inside
NEWTONS = Tol("pulls", 2.0, 1e-9)
LOADS = [(V(0.0, 3e4), 2e4), (V(0.0, 5e4), 4.5e4)]


def test_unlike_slips_that_all_make_a_term_vanish_tell_nothing(made_up):
    """The torque's share left out of the ropes' pulls: a factor left out of it (``2 / LEVER``), the ratio upside
    down (``LEVER / 2T``) and a division for a product (``2 / T / LEVER``) each leave a share far inside the
    tolerance, on every input: three unlike slips of two families reproduce the answer alike, which says that the
    inputs cannot tell causes apart, and the engine tells none of them."""
    from grader.diagnosis.engine import _told_apart

    def without_torque(W, T):
        return np.concatenate([0.5 * W, 0.5 * W])

    names, found = _found(made_up, "ropes", without_torque, LOADS, tol=NEWTONS)
    assert len({h.name for h in found if not h.twin}) > 2, [(h.name, h.detail) for h in found]
    assert _told_apart(found) == [], [(h.name, h.detail) for h in found]


def test_one_slip_read_two_ways_is_told_still(made_up):
    """The near miss: ``k m`` where ``k / m`` belongs, a factor off and its twin the reciprocal (two names, one
    edit), is no sign of inputs that cannot tell causes apart: both told."""
    from grader.diagnosis.engine import _told_apart

    names, found = _found(made_up, "rate", lambda k, m: np.array([k * m, k / 2.0]), [(3.0, 0.8), (1.7, 2.5)])
    assert {h.name for h in _told_apart(found)} == {"wrong_factor", "reciprocal_argument"}, found


def test_exchanges_found_in_several_places_are_told_as_readings_of_one_slip():
    """Two quantities exchanged (the desired rates and accelerations) reproduce the answer as two entries exchanged,
    two arguments exchanged and a quantity read for its rate: three names of two families, each an exchange, which
    reproduces an answer only where the two exchanged are the two that differ.  They are told; three unlike slips
    that are no exchanges (a factor left out, a ratio upside down, a reciprocal) still tell nothing."""
    from grader.diagnosis.engine import _told_apart
    from grader.diagnosis.evidence import Hypothesis

    exchanged = [Hypothesis("a", "swapped", 2, "entries"), Hypothesis("b", "argument_order", 2, "arguments"),
                 Hypothesis("c", "state_row", 2, "a rate")]
    assert _told_apart(exchanged) == exchanged
    vanishing = [Hypothesis("a", "missing_factor", 2, "factor"), Hypothesis("b", "ratio_inverted", 2, "ratio"),
                 Hypothesis("c", "reciprocal_argument", 2, "reciprocal")]
    assert _told_apart(vanishing) == []
    assert _told_apart(vanishing[:2] + exchanged[:1]) == vanishing[:2] + exchanged[:1]


# ------------------------------------------------------------------------------------------ a point at the origin

STRETCHES = [(V(0.3, 1.2, -0.4),), (V(-1.1, 0.6, 0.9),)]


def test_a_point_subtracted_from_a_position_and_left_out_is_a_position_from_the_origin(made_up):
    """``|I_r_IE|`` where ``|centre - I_r_IE|`` belongs: the cord measured from the origin (an offset), as for
    ``I_r_IE - centre``; no term of a sum left out."""
    def from_origin(I_r_IE):
        return np.array([np.linalg.norm(I_r_IE) - 1.5, I_r_IE[2]])

    names, found = _found(made_up, "stretch", from_origin, STRETCHES)
    assert names == {"from_origin"}, [(h.name, h.detail) for h in found]
    assert any("`stretch` measures a position from the origin" in h.detail for h in found)


def test_a_defaulted_argument_left_unused_is_told_where_no_argument_could_be_tested(made_up):
    """Where the test of an ignored argument could change none of the call's arguments (``untested``), the
    parameter with a default that the slip leaves unused (``centre``) is an argument ignored as well: told beside
    the position from the origin, as its twin."""
    def from_origin(I_r_IE):
        return np.array([np.linalg.norm(I_r_IE) - 1.5, I_r_IE[2]])

    names, found = _found(made_up, "stretch", from_origin, STRETCHES, untested=True)
    assert names == {"from_origin", "ignored_argument"}, [(h.name, h.detail) for h in found]
    assert [h.detail for h in found if h.twin] == ["`stretch` leaves its argument `centre` unused"]


def test_a_velocity_left_out_of_a_difference_with_no_default_is_a_term_left_out(made_up):
    """The near miss of both: ``|I_v_P|`` where ``|v_belt - I_v_P|`` belongs subtracts no position (no point at
    the origin), and ``v_belt`` has no default (the test of an ignored argument measures it): a term left out,
    nothing else, even where that test could change nothing."""
    def absolute(I_v_P, v_belt):
        return np.array([np.linalg.norm(I_v_P), I_v_P[0]])

    inputs = [(V(0.3, 1.2, -0.4), V(1.0, 0.5, 0.2)), (V(-1.1, 0.6, 0.9), V(0.4, -0.8, 1.3))]
    for untested in (False, True):
        names, found = _found(made_up, "slip_speed", absolute, inputs, untested=untested)
        assert names == {"missing_term"}, [(h.name, h.detail) for h in found]


HEATS = [(2.0, 450.0, 3.0, 10.0), (0.7, 900.0, -1.5, 4.0)]


def heat(pkg, m, c, dT, t):
    """The probe of the made-up ``heat``: its arguments, named as its parameters, passed on."""
    return importlib.import_module(f"{pkg.__name__}.problem_98").heat(m, c, dT, t)


def test_a_factor_left_out_that_is_an_argument_the_test_did_not_reach_is_also_an_argument_ignored(made_up):
    """``m dT`` where ``m c dT`` belongs, the test of an ignored argument having run out of its budget before it
    changed ``c`` (position 1, ``unreached``): a factor left out, and ``c`` ignored, both told."""
    names, found = _found(made_up, "heat", lambda m, c, dT, t: np.array([m * dT, t]), HEATS, unreached=(1, 3),
                          probe=heat)
    assert names == {"missing_factor", "ignored_argument"}, [(h.name, h.detail) for h in found]
    assert [h.detail for h in found if h.twin] == ["`heat` leaves its argument `c` unused"]


def test_a_factor_left_out_that_the_test_reached_is_a_factor_left_out_only(made_up):
    """The near misses: where the test of an ignored argument changed ``c`` (it found it followed, or ignored and
    told it itself), or did not reach only arguments the slip uses, the factor left out alone is told."""
    for unreached in ((), (3,), (0, 2)):
        names, found = _found(made_up, "heat", lambda m, c, dT, t: np.array([m * dT, t]), HEATS, unreached=unreached,
                              probe=heat)
        assert names == {"missing_factor"}, (unreached, [(h.name, h.detail) for h in found])


# ------------------------------------------------------------------------------------------ a state's entries

JOINTS = [(np.array([[1.0, 0.2], [0.0, 1.0], [0.5, -0.3]]), V(0.4, -1.2), V(2.0, 0.7)),
          (np.array([[0.3, 1.0], [-0.8, 0.1], [0.0, 0.6]]), V(-0.9, 0.5), V(0.2, -1.4))]


def test_a_quantity_and_its_rate_exchanged_are_also_a_state_row_slip(made_up):
    """``(S qdd, S qd)`` where ``(S qd, S qdd)`` belongs: two entries (or arguments) exchanged, and the rate read
    where the quantity belongs and the reverse: both told, the state row as the twin of the exchange."""
    names, found = _found(made_up, "joint_rates", lambda S, qd, qdd: np.concatenate([S @ qdd, S @ qd]), JOINTS)
    assert {mutants.DIAGNOSES[n].family for n in names} == {"order", "state_row"}, [(h.name, h.detail) for h in found]
    assert [h.name for h in found if h.twin] == ["state_row"]
    assert any("`joint_rates` reads a quantity where its rate belongs" in h.detail for h in found)


def test_two_quantities_that_are_no_rates_exchanged_are_of_the_order_only(made_up):
    """The near miss: ``(S w, S u)`` where ``(S u, S w)`` belongs: no rate of the other, an exchange only."""
    names, found = _found(made_up, "two_loads", lambda S, u, w: np.concatenate([S @ w, S @ u]), JOINTS)
    assert names and {mutants.DIAGNOSES[n].family for n in names} == {"order"}, [(h.name, h.detail) for h in found]

def test_names_unpacked_from_a_runs_state_exchanged_are_a_state_row_slip(made_up):
    """``h, x = y[:2]`` where ``x, h = y[:2]`` belongs: each name reads the other's row of the state, a state
    read from the wrong rows (the particular name the evidence proves), not two entries swapped."""
    def exchanged(t, y, s=0.4):
        h, x = y[:2]
        return np.array([h - s * x + 0.1 * t])

    names, found = _found(made_up, "step_height", exchanged, [(0.3, V(0.5, -1.0, 2.0)), (1.1, V(-0.2, 0.7, 0.6))])
    assert names == {"state_row"}, [(h.name, h.detail) for h in found]


def test_names_unpacked_from_a_vector_that_is_no_state_exchanged_are_swapped(made_up):
    """The near miss: the same exchange of a vector that is no run's state is of the order family."""
    def exchanged(v, s=0.4):
        b, a = v[:2]
        return np.array([b - s * a])

    names, found = _found(made_up, "lean", exchanged, [(V(0.5, -1.0, 2.0),), (V(-0.2, 0.7, 0.6),)])
    assert names and "state_row" not in names, [(h.name, h.detail) for h in found]
    assert {mutants.DIAGNOSES[n].family for n in names} == {"order"}, [(h.name, h.detail) for h in found]


# ------------------------------------------------------------------------------------------ an angle ignored


def _R3(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _tilted(alpha, I):
    """A body's inertia turned by ``alpha`` about z."""
    return _R3(alpha) @ np.asarray(I) @ _R3(alpha).T


INERTIA = np.array([[2.0, 0.3, 0.0], [0.3, 1.0, 0.1], [0.0, 0.1, 3.0]])
TILTED = Declaration(args=("angle", "inertia"), names=("alpha", "I"), draw=False)


def test_an_angle_ignored_that_leaves_the_rotation_out_is_also_a_frame_slip(monkeypatch):
    """The student's inertia not turned by ``alpha``: the value does not follow ``alpha`` (an argument ignored),
    and it is the reference's with ``alpha = 0`` on both inputs (a rotation left out): both told."""
    finding = _explain(monkeypatch, "stub.tilted", TILTED, _tilted, lambda alpha, I: np.asarray(I), (0.7, INERTIA))
    assert finding is not None and set(finding.names) == {"ignored_argument", "wrong_frame"}, finding
    assert "alpha turning nothing" in finding.hint


def test_an_angle_ignored_at_another_angle_is_no_frame_slip(monkeypatch):
    """The near miss: the student's inertia turned by a fixed 0.5 whatever ``alpha``: the angle ignored, but the
    value is no reference's with the rotation left out; the argument ignored alone is told."""
    finding = _explain(monkeypatch, "stub.tilted_fixed", TILTED, _tilted, lambda alpha, I: _tilted(0.5, I),
                       (0.7, INERTIA))
    assert finding is not None and finding.names == ("ignored_argument",), finding


#: problem 26's seat position with the carousel's turn by beta left out: the seat in the arm's own frame, which
#: does not follow beta and is the reference's at beta = 0
SEAT_NOT_TURNED = Planted(
    name="rivals-p26-seat-not-turned", problem=26, file="problem_26.py",
    old="return np.array([radius * np.sin(beta), l1 - l3 * np.cos(phi), radius * np.cos(beta)])",
    new="return np.array([0.0, l1 - l3 * np.cos(phi), radius])",
    check="p26.position_values", diagnosis="ignored_argument or wrong_frame", message="beta turning nothing",
    also=("p26.jacobian_derivative",))


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot([26])


def test_an_angle_ignored_graded_is_told_with_its_frame_rival(tmp_path, kit_oracle, deferred_ids, slot):
    """Graded as ``grade batch`` grades, live and from the kit's key (which holds the reference's values with the
    angle turning nothing): live both names, the kit the same or none."""
    assert_told_alike(SEAT_NOT_TURNED, tmp_path / "pkg", kit_oracle, deferred_ids, slot)


def test_what_turns_nothing():
    assert unturned("angle", 0.7) == 0.0 and unturned("angles", [0.2, -0.4]) == [0.0, 0.0]
    assert np.array_equal(unturned("rotation", _R3(0.3)), np.eye(3))
    assert unturned("angle", 0.0) is None  # already turning nothing: no rival to try
    assert unturned("scalar", 0.7) is None and unturned("vector", V(1.0, 0.0, 0.0)) is None
    assert unturned("", np.diag([1.0, 1.0, -1.0])) is None  # a reflection is no rotation


def test_an_object_a_run_steps_built_ignoring_a_value_it_is_given_starts_from_another_state(tmp_path):
    """Problem 12's body built with its angular velocity ignored (``self.B_omega_B = np.zeros(3)``), stepped from a
    drawn start: its constructor takes the default whatever it is given, an argument ignored, and the run of steps
    starts from another state than the given one as truly (``mutants._hypotheses``): both told.  The near miss is
    the same slip on a call that is no run (a point's velocity of a body built so): no wrong start is told there
    (the term the zero angular velocity takes away is)."""
    from checks._rigid import sheet_state
    from grader.private import drop_private

    from .test_mutants import evidence, planted_package, scene

    state = sheet_state({"B_v_B": [0.3, -0.2, 0.5], "B_omega_B": [0.4, 1.1, -0.7], "B_a_B": [0.1, 0.0, 0.2],
                         "B_omegaDot_B": [0.0, 0.3, 0.1]})
    student = planted_package(tmp_path, "rigid_body.py", "self.B_omega_B = _vector_or_zeros(B_omega_B)",
                              "self.B_omega_B = np.zeros(3)")
    try:
        run = evidence("problem_12.integrate", (state, 0.05, 4), ("B_r_IB",), student)
        run.alone = True
        found = mutants.mutant_slips(scene("p12.random_steps"), [run])
        point = evidence("problem_12.point", (state, "velocity_of_point", np.array([0.2, 0.5, -0.1])), (), student)
        point.alone = True
        alone = mutants.mutant_slips(scene("p12.velocity_of_point"), [point])
    finally:
        drop_private(student)
    from checks._diagnoses import DIAGNOSES

    assert {DIAGNOSES[h.name].family for h in found} == {"ignored_argument", "initial_state"}, \
        [(h.name, h.detail) for h in found]
    assert alone and "initial_state" not in {DIAGNOSES[h.name].family for h in alone}, \
        [(h.name, h.detail) for h in alone]
