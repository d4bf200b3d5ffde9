"""A catalogue's name needs evidence: a known mistake is named only where the slip it stands for reproduces the
student's answer, not where a property of the answer that the slip would give happens to hold.

* On a second input (``grader.checking.confirmed``): a mistake named on the input shown is named only where it
  reproduces the student's value on a second input the check chooses as well (problem 24's pendulum in a second
  configuration).  Planted: a value in body coordinates that equals the inertial one at the angle shown only; near
  misses: the inertial value on both inputs keeps its name; a second input that passes, or fails another property,
  or raises, names nothing.
* On the whole answer (problem 4's model built straight, ``checks.problem_04._straight``): a model whose joints sit
  where a straight model's would is told ``built_straight`` only where the model built with some links unturned is
  the student's in every joint and in the point where the loop closes, in the configuration shown and in the
  other one the check asks.  Planted: link 2 built without its angle (live, and in the kit); near misses: links 1
  and 2 straight and link 3 turned by another angle (a model nearly straight), and a model straight in one
  configuration only.  A time-out or a crashed worker while the second model is built ends the grading, as in
  ``confirmed``; an error of the student's code there only leaves the model unnamed.
* A linkage at rest is no evidence of which gravity is missing (problem 4's ``_gravity_slips``): its acceleration
  vanishes with no gravity and with gravity out of the plane alike, so each is told only where the model's gravity
  is the slip's.  Planted: gravity along z (``gravity_axis``, ``tests/planted/problem_04.toml`` grades it live);
  near misses: gravity along x, or of another size, names neither.
* A term that vanishes is not told left out where what it is made of is lost (problem 15's gyroscopic term,
  omega x (B_I_B omega), vanishes with an inertia that is a multiple of the identity): ``missing_gyroscopic`` is
  told only where the body's angular momentum is the inertia it is given times omega.
* A run that stops where its t_max says follows its t_max (problem 42's ball thrown with a t_max before its
  landing): ``ignored_argument`` is told only where the run goes past it, not where it ends there and reports a
  landing it did not find.
"""

import numpy as np
import pytest

from checks import problem_04 as c04
from grader.checking import EXACT, CheckFailure, Mistake, assert_close, confirmed
from grader.errors import StudentCodeError
from tests.kit_support import assert_told_alike, warm_slot  # noqa: F401 (fixtures)
from tests.submissions import Planted

R = np.array([0.5, 0.0, 0.0])


def _turn(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _comparison(answer, angle, hint="the generic hint"):
    """The comparison of ``answer(angle)`` with a body-frame position ``R`` whose inertial value is ``turn(angle) R``
    (the catalogue's ``wrong_frame``); ``known``: False compares without the catalogue."""
    def compare(known=True):
        try:
            assert_close(answer(angle), R, "B_r_IB of link_1", EXACT,
                         [Mistake("wrong_frame", _turn(angle) @ R, "the inertial position")] if known else [])
        except CheckFailure as exc:
            if exc.diagnosis or exc.hint:
                raise
            raise CheckFailure(exc.message, hint, "", exc.candidates, exc.evidence) from None

    return compare


def _told(answer, second=0.7):
    try:
        confirmed(_comparison(answer, np.pi / 6), _comparison(answer, second))
    except CheckFailure as exc:
        return exc
    pytest.fail("the comparison passed")


def _by_chance(a):
    """A position off by a shift that makes it the inertial one at the angle shown (pi/6) only."""
    return R + (_turn(np.pi / 6) @ R - R)


def test_a_name_that_holds_on_the_input_shown_only_is_not_told():
    told = _told(_by_chance)
    assert told.diagnosis == "" and told.hint == "the generic hint", (told.diagnosis, told.hint)
    assert told.evidence is not None  # the diagnosis engine is asked


def test_a_name_that_holds_on_both_inputs_is_told():
    assert _told(lambda a: _turn(a) @ R).diagnosis == "wrong_frame"


def test_a_second_input_that_passes_fails_another_property_or_raises_names_nothing():
    passes = _told(lambda a: _turn(a) @ R if a == np.pi / 6 else R)
    assert passes.diagnosis == ""

    def other(known=True):
        assert_close(np.zeros(3), np.ones(3), "A_IB of link_2", EXACT, [Mistake("wrong_frame", np.zeros(3), "")])

    with pytest.raises(CheckFailure) as raised:
        confirmed(_comparison(lambda a: _turn(a) @ R, np.pi / 6), other)
    assert raised.value.diagnosis == ""

    def crashes():
        raise StudentCodeError("exception", "ValueError", "raised on the second input", "", "call")

    with pytest.raises(CheckFailure) as raised:
        confirmed(_comparison(lambda a: _turn(a) @ R, np.pi / 6), crashes)
    assert raised.value.diagnosis == ""


# ------------------------------------------------------------------------------------------ problem 4's model

def _model(q):
    """The description of a four-bar model with link i turned by ``q[i]`` (what ``_unturned`` reads of it)."""
    points = c04.loop_points(q)
    return {"joints": [{"anchor": np.r_[p, 0.0]} for p in points[:3]],
            "equalities": [{"type": "connect", "active": True, "to_world": True, "point1": np.r_[points[3], 0.0],
                            "point2": np.r_[points[3], 0.0]}]}


class _Child:
    """A sandboxed child's stand-in (``student_once`` keeps its calls by child)."""


class _Ctx:
    """The reference's assemblies and the student's models, by fixed point (``student(q)``: the student's angles
    in the configuration ``q``), as ``_straight`` asks them."""

    def __init__(self, student):
        from reference import problem_04 as ref

        self.ref, self.student_angles, self.calls, self.child = ref, student, [], _Child()

    def reference(self, probe, *args, **kwargs):
        return {"q": self.ref.assemble(*args)}

    def student(self, probe, density, gravity, q, point, timeout=None):
        return {"gravity": gravity, **_model(self.student_angles(np.asarray(q, dtype=float), point))}


def _straight(student):
    q = _q()
    return c04._straight(_Ctx(student), _model(student(q, c04.FIXED_POINT)), q, c04.FIXED_POINT)


def _unturned(links, q):
    return [0.0 if i in links else angle for i, angle in enumerate(q[:3])]


def _q():
    from reference import problem_04 as ref

    return np.asarray(ref.assemble(c04.DYNAMICS_TARGETS, c04.FIXED_POINT))


def test_a_link_built_without_its_angle_is_a_model_built_straight():
    points = _straight(lambda q, point: _unturned((1,), q))
    assert points is not None and np.allclose(points, c04.loop_points(_unturned((1,), _q())))


def test_a_model_nearly_straight_or_straight_in_one_configuration_is_not():
    """Links 1 and 2 unturned and link 3 turned by its angle rounded to a tenth: every joint where a straight model
    has it, the end of link 3 not; link 2 unturned at the sheet's fixed point only."""
    assert _straight(lambda q, point: [0.0, 0.0, np.round(q[2], 1)]) is None
    assert _straight(lambda q, point: _unturned((1,), q) if point == c04.FIXED_POINT else q[:3]) is None


def test_a_second_model_that_times_out_ends_the_grading():
    """The second configuration's model is the student's code run again: a time-out or a crashed worker there stops
    the grading (as ``grader.checking.confirmed`` lets it), while an error of their code only leaves the model
    unnamed."""
    from grader.errors import StudentFault, StudentTimeout, WorkerCrash

    def failing(fault):
        def student(q, point):
            if point != c04.FIXED_POINT:
                raise fault
            return _unturned((1,), q)
        return student

    for fault in (StudentTimeout(2.0), WorkerCrash("killed")):
        with pytest.raises(type(fault)):
            _straight(failing(fault))
    assert _straight(failing(StudentFault("ValueError: no model"))) is None


def test_a_linkage_at_rest_is_told_the_gravity_its_model_has():
    def told(gravity):
        return [m.name for m in c04._gravity_slips({"gravity": np.asarray(gravity, dtype=float)}, 9.81)]

    assert told([0.0, 0.0, 0.0]) == ["missing_gravity"]
    assert told([0.0, 0.0, -9.81]) == ["gravity_axis"]
    assert told([-9.81, 0.0, 0.0]) == [] and told([0.0, 0.0, -1.62]) == [] and told([0.0, -9.81, 0.0]) == []


#: problem 4's model with link 2 built without its joint angle: a model built straight in part, told so live and in
#: the kit (the second configuration's calls are in the key)
LINK2_UNTURNED = Planted(
    name="evidence-p04-link2-unturned", problem=4, file="problem_04.py",
    old="link2 = link_body(2, density, pos=LENGTH, angle=q[1], children=link3)",
    new="link2 = link_body(2, density, pos=LENGTH, children=link3)",
    check="p04.model_structure", diagnosis="built_straight", message="rotate each link's body by its joint angle",
    also=("p04.model_dynamics", "p04.model_at_rest"))


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot([4])


def test_a_link_built_without_its_angle_is_told_live_and_in_the_kit(tmp_path, kit_oracle, deferred_ids, slot):
    assert_told_alike(LINK2_UNTURNED, tmp_path / "pkg", kit_oracle, deferred_ids, slot)


# ------------------------------------------------------------------------------------------ problem 42's t_max


def _cut_short(t_land, t_end):
    """Problem 42's ball thrown with a t_max before its landing, the student's run landing at ``t_land`` and ending
    at ``t_end``: the failure of ``_assert_cut_short`` (None where it passes)."""
    from checks import problem_42 as c42

    class Ctx:
        def reference(self, probe, *args):
            return {"t_land": None, "t_end": c42.CUT}

        def student(self, probe, *args, timeout=None):
            return {"t_land": t_land, "t_end": t_end}

    try:
        c42._assert_cut_short(Ctx())
    except CheckFailure as failure:
        return failure
    return None


def test_a_run_that_goes_past_t_max_is_told_t_max_ignored():
    from checks import problem_42 as c42

    failure = _cut_short(c42.CUT + 1.7, c42.CUT + 1.7)
    assert failure is not None and failure.diagnosis == "ignored_argument", failure


def test_a_landing_reported_at_the_end_of_a_run_that_stops_at_t_max_is_no_t_max_ignored():
    """Planted: the run's last time reported as its landing (it ends at t_max, in the air); the near miss above."""
    from checks import problem_42 as c42

    failure = _cut_short(c42.CUT, c42.CUT)
    assert failure is not None and not failure.diagnosis, failure
    assert "t_land is None" in failure.hint
    assert _cut_short(None, c42.CUT) is None


# ---------------------------------------------------------------------------------- problem 15's gyroscopic term


def _natural(omega_dot, inertia):
    """Problem 15's comparison of the natural dynamics at its generic state, the student's omegaDot ``omega_dot``
    and their body's inertia ``inertia`` (what its angular momentum is made of): the failure's diagnosis."""
    from checks import problem_15 as c15

    state = c15.GENERIC_STATE

    class Ctx:
        def student(self, probe, state):
            return np.asarray(inertia, dtype=float) @ np.asarray(state["B_omega_B"], dtype=float)

    expected = {key: value for key, value in zip(("B_a_B", "B_omegaDot_B"), c15.natural_dynamics(state))}
    got = {"B_a_B": np.zeros(3), "B_omegaDot_B": np.asarray(omega_dot, dtype=float)}
    with pytest.raises(CheckFailure) as failure:
        c15._compare_accelerations(got, expected, state, lambda: c15._keeps_inertia(Ctx(), state))
    return failure.value.diagnosis


def test_a_gyroscopic_term_that_vanishes_with_an_inertia_lost_is_no_term_left_out():
    """Planted: a body that keeps twice the identity for its inertia (omega x (I omega) vanishes, written right);
    the near miss: the inertia kept and the term left out is named."""
    from checks import problem_15 as c15

    assert _natural(np.zeros(3), 2.0 * np.eye(3)) == ""
    assert _natural(np.zeros(3), c15.GENERIC_STATE["B_I_B"]) == "missing_gyroscopic"
