"""Values a check computes from the student's MuJoCo model have a source for the diagnosis engine.

* A MuJoCo model (``grader.diagnosis.models``): the student's compiled model is compared with the reference's on
  the same arguments, element by element; a body moved with what it carries is an offset (and a scale where it
  sits at a factor of the lever from its parent's joint, a sign where it sits at the lever's opposite), a body
  turned about its joint where the reference's starts unturned is the model built in another configuration, where
  it starts turned by an angle given the slip of that angle (degrees, a sign), every body turned by one slip of its
  own angle is the configuration's angles so slipped (read as degrees), and one attribute alone differing is
  told by the grammar of values; joints placed elsewhere in their bodies by one vector, nothing else changed, are
  an offset (the joint's pos).
  Differences that no one story holds name nothing.
* A value of the student's model compared with one the check computes with the reference's own formula (a link's
  mass): the reference's model, from the student's probe on their arguments, stands for that formula where it gives
  the same value, so the engine asks both sides alike (a second input, an argument the model ignores).

The planted mistakes are in no set of ``tests/diagnosis/``, no table of ``tests/engine/`` and no planted suite;
graded as ``grade batch`` grades (a warm fork), live and from the kit's answer key (the same verdicts, and the same
cause or none).
"""

import numpy as np
import pytest

from grader.checking import Tol
from grader.diagnosis import Evidence, Source
from grader.diagnosis.models import model_slips
from grader.diagnosis.scene import Scene
from grader.results import Status
from tests.kit_support import (  # noqa: F401 (fixtures)
    SEED,
    assert_told_alike,
    grade_live_and_kit,
    warm_slot,
)
from tests.submissions import Planted, build_planted

#: problem 3's custom-inertia model with its second link hung further out along the first (L + W for L): an offset,
#: no factor of the grammar
LINK_FURTHER_OUT = Planted(
    name="models-p03-custom-link2-further-out", problem=3, file="problem_03.py",
    old="inner = link_body(2, pos=LENGTH, inertial=inertial)",
    new="inner = link_body(2, pos=LENGTH + WIDTH, inertial=inertial)",
    check="p03.custom_inertia", diagnosis="offset", message="sit (+0.01, +0, +0) m from where they belong")
#: problem 3's model (a) with its second link starting turned a quarter turn about joint 2: its centre of mass moves,
#: its joint does not
LINK_TURNED = Planted(
    name="models-p03-link2-starts-turned", problem=3, file="problem_03.py",
    old="    inner = link_body(2, density, pos=LENGTH)\n    return _model(\"double_pendulum\"",
    new="    inner = link_body(2, density, pos=LENGTH, angle=np.pi / 2)\n    return _model(\"double_pendulum\"",
    check="p03.geometry_inertia", diagnosis="initial_pose", message="start turned by +90.0 degrees about its joint",
    also=("p03.traces_a",))
#: problem 4's four-bar with its third link hung along the second's y-axis where its x-axis belongs: the same lever
#: with its coordinates in the wrong order (told beside the offset it is as well)
LINK3_ALONG_Y = Planted(
    name="models-p04-link3-along-y", problem=4, file="problem_04.py",
    old="link3 = link_body(3, density, pos=LENGTH, angle=q[2], children=tip)",
    new="link3 = link_body(3, density, pos=LENGTH, angle=q[2], children=tip).replace(\n"
        "        f'pos=\"{vector([LENGTH, 0.0, 0.0])}\"', f'pos=\"{vector([0.0, LENGTH, 0.0])}\"', 1)",
    check="p04.model_structure", diagnosis="offset or coordinate_order", message="the same lengths along other axes",
    also=("p04.model_at_rest",))
#: every hinge of problem 2's links placed off its body's origin (inside the link), the link itself where it belongs:
#: the anchors move by one vector in their bodies' frames and nothing else does (the joint's pos)
JOINT_INSIDE_LINK = Planted(
    name="models-p02-joint-inside-link", problem=2, file="problem_02.py",
    old='<joint name="joint{i}" type="hinge" axis="0 0 1"',
    new='<joint name="joint{i}" type="hinge" pos="0.01 0 0" axis="0 0 1"',
    check="p02.joint", diagnosis="offset", message="from where it belongs in its body",
    also=("p02.period", "p02.traces_2a", "p02.traces_2b", "p02.traces_2c"))
#: problem 2's density overwritten by aluminium's whatever density is given: the mass the check computes with the
#: reference's formula is compared with the mass of the student's model, and the reference's model (the student's
#: own probe, on their arguments) stands for it, so the test of an ignored argument can change the density
DENSITY_OVERWRITTEN = Planted(
    name="models-p02-density-overwritten", problem=2, file="problem_02.py",
    old="    per_radian = damping * 180 / np.pi  #",
    new="    density = 2700.0\n    per_radian = damping * 180 / np.pi  #",
    check="p02.mass_inertia", diagnosis="ignored_argument", message="your value does not change when argument 1",
    also=("p02.traces_2a", "p02.traces_2b", "p02.traces_2c"))
#: problem 4's four-bar with its compiler told that angles are degrees: every body's euler angle (its joint angle in
#: radians) is read as degrees, each body turned by its own angle's slip
COMPILER_IN_DEGREES = Planted(
    name="models-p04-compiler-in-degrees", problem=4, file="problem_04.py",
    old='<mujoco model="four_bar">\n  <compiler angle="radian"/>',
    new='<mujoco model="four_bar">\n  <compiler angle="degree"/>',
    check="p04.model_structure", diagnosis="degrees", message="as with the angles read as degrees",
    also=("p04.model_dynamics", "p04.model_at_rest"))
MISTAKES = [LINK_FURTHER_OUT, LINK_TURNED, LINK3_ALONG_Y, JOINT_INSIDE_LINK, DENSITY_OVERWRITTEN, COMPILER_IN_DEGREES]
#: its near miss: the density scaled by a factor no grammar holds, which the mass follows: no argument ignored
DENSITY_SCALED = Planted(
    name="models-p02-density-scaled", problem=2, file="problem_02.py",
    old="    per_radian = damping * 180 / np.pi  #",
    new="    density = 1.37 * density\n    per_radian = damping * 180 / np.pi  #",
    check="p02.mass_inertia", diagnosis="", message="")

#: a near miss: the hinges placed off their bodies' origins and turned upside down as well: the anchors move and
#: the axes turn, which no one story of a model holds (joints moved alone are an offset, an axis alone a sign)
JOINTS_MOVED_AND_TURNED = Planted(
    name="models-p02-joints-moved-and-turned", problem=2, file="problem_02.py",
    old='<joint name="joint{i}" type="hinge" axis="0 0 1"',
    new='<joint name="joint{i}" type="hinge" pos="0.01 0 0" axis="0 0 -1"',
    check="p02.joint", diagnosis="", message="")


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({m.problem for m in MISTAKES + [JOINTS_MOVED_AND_TURNED, DENSITY_SCALED]}))


@pytest.mark.parametrize("mistake", MISTAKES, ids=lambda m: m.name)
def test_a_value_without_a_reference_call_is_told_its_cause(mistake, tmp_path, kit_oracle, deferred_ids, slot):
    assert_told_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)


def test_a_model_whose_differences_no_story_holds_names_nothing(tmp_path, kit_oracle, slot):
    submission = build_planted(JOINTS_MOVED_AND_TURNED, tmp_path / "pkg")
    live, _ = grade_live_and_kit(JOINTS_MOVED_AND_TURNED.problem, submission, kit_oracle, zygote=slot)
    target = {r.check_id: r for r in live.results}[JOINTS_MOVED_AND_TURNED.check]
    assert target.status is Status.FAILED, target.message
    assert target.diagnosis == "", (target.diagnosis, target.hint)


def test_a_density_the_model_follows_is_no_argument_ignored(tmp_path, kit_oracle, slot):
    submission = build_planted(DENSITY_SCALED, tmp_path / "pkg")
    live, _ = grade_live_and_kit(DENSITY_SCALED.problem, submission, kit_oracle, zygote=slot)
    target = {r.check_id: r for r in live.results}[DENSITY_SCALED.check]
    assert target.status is Status.FAILED, target.message
    assert "ignored_argument" not in target.diagnosis, (target.diagnosis, target.hint)


# ------------------------------------------------------------------------------------------ stand-ins

L = 0.2


def _rotation(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _chain(angles, lengths=(L, L), gravity=(0.0, -9.81, 0.0), along=(1.0, 0.0, 0.0)):
    """A description of a planar chain of bricks (``probes._mjcf.describe``): body i turned by ``angles[i]``
    relative to its parent, hung at ``lengths[i - 1]`` along its parent's ``along`` (x)."""
    bodies, joints, frame, origin = [], [], np.eye(3), np.zeros(3)
    for i, angle in enumerate(angles):
        if i:
            origin = origin + frame @ (lengths[i - 1] * np.asarray(along, dtype=float))
        frame = frame @ _rotation(angle)
        bodies.append({"name": f"link{i + 1}", "parent": i, "mass": 0.5, "com": origin + frame @ [L / 2, 0.0, 0.0],
                       "inertia": frame @ np.diag([1e-5, 2e-3, 2e-3]) @ frame.T, "frame": frame})
        joints.append({"name": f"joint{i + 1}", "type": "hinge", "body": i + 1, "anchor": origin, "axis":
                       np.array([0.0, 0.0, 1.0]), "damping": 0.0, "armature": 0.0, "frictionloss": 0.0,
                       "stiffness": 0.0})
    return {"gravity": np.array(gravity), "timestep": 0.002, "bodies": bodies, "joints": joints, "actuators": [],
            "qpos": np.zeros(len(angles)), "qvel": np.zeros(len(angles)), "sites": [], "equalities": []}


def _tipped(desc, pos):
    """``desc`` with a site at ``pos`` on its last body, and a connect that joins it to the world where the site
    is."""
    frame, origin = desc["bodies"][-1]["frame"], desc["joints"][-1]["anchor"]
    world = origin + frame @ np.asarray(pos, dtype=float)
    return {**desc, "sites": [{"name": "tip", "body": len(desc["bodies"]), "pos": np.asarray(pos, dtype=float),
                               "world": world}],
            "equalities": [{"type": "connect", "active": True, "point1": world, "point2": world, "to_world": True}]}


class _Oracle:
    mode = "live"

    def __init__(self, answer):
        self.answer = answer

    def reference(self, probe, args, persist=False, check=""):
        return self.answer


class _Ctx:
    check_id = "stub.model"

    def __init__(self, mine, theirs):
        self.oracle = _Oracle(theirs)
        self.calls = [("student", "stub.model", (1.0,), mine)]


def _told(mine, theirs, got):
    """The names the model tier tells for a comparison of ``got`` (a value of the student's model ``mine``)."""
    tol = Tol("positions", 1e-6)
    evidence = Evidence(np.asarray(got, dtype=float), np.zeros(np.shape(got)), tol, "value", got, None)
    evidence.student = Source("stub.model", (1.0,), (), mine)
    return sorted({h.name for h in model_slips(Scene(_Ctx(mine, theirs)), evidence)})


def test_a_configuration_given_in_degrees_is_told_as_degrees():
    theirs, mine = _chain([0.4, -0.7]), _chain([np.degrees(0.4), -0.7])
    assert _told(mine, theirs, mine["joints"][1]["anchor"]) == ["degrees"]


@pytest.mark.parametrize("slip", [np.radians, np.degrees], ids=["read-as-degrees", "written-in-degrees"])
def test_every_angle_of_a_configuration_in_degrees_is_told_as_degrees(slip):
    """Every body turned by one slip of its own angle: the configuration's angles read as degrees (a model that
    declares no <compiler angle="radian"/>) or written in degrees, each body keeping its own structure."""
    q = [0.4, -0.7, 1.2]
    theirs, mine = _chain(q, (L, L, L)), _chain([slip(a) for a in q], (L, L, L))
    assert _told(mine, theirs, mine["bodies"][1]["com"]) == ["degrees"]


def test_angles_turned_by_different_slips_or_with_a_link_lengthened_name_nothing():
    """The near misses: one angle in degrees and the next negated hold no one slip; every angle in degrees with the
    second link hung further out changes a body's own structure as well."""
    q = [0.4, -0.7, 1.2]
    theirs = _chain(q, (L, L, L))
    mixed = _chain([np.radians(q[0]), -q[1], q[2]], (L, L, L))
    assert _told(mixed, theirs, mixed["bodies"][1]["com"]) == []
    longer = _chain([np.radians(a) for a in q], (L, 1.5 * L, L))
    assert _told(longer, theirs, longer["bodies"][1]["com"]) == []


def test_a_link_turned_by_its_parent_s_angle_as_well_names_nothing():
    """The second link given its absolute angle where its angle relative to the first belongs: a turn that is no
    slip of the angle's value."""
    theirs, mine = _chain([0.4, -0.7]), _chain([0.4, -0.7 + 0.4])
    assert _told(mine, theirs, mine["bodies"][1]["com"]) == []


def test_a_link_unturned_in_the_reference_is_a_model_built_in_another_configuration():
    theirs, mine = _chain([0.0, 0.0]), _chain([0.0, 1.1])
    assert _told(mine, theirs, mine["bodies"][1]["com"]) == ["initial_pose"]


def test_a_link_hung_at_half_the_lever_is_an_offset_and_a_factor():
    theirs, mine = _chain([0.3, 0.5]), _chain([0.3, 0.5], lengths=(L / 2, L))
    assert _told(mine, theirs, mine["joints"][1]["anchor"]) == ["factor_half", "offset"]


def test_a_link_hung_along_its_parent_s_y_is_an_offset_and_axes_exchanged():
    """The second link hung at L along its parent's y where L along its x belongs (its parent turned, so the world's
    coordinates are no permutation of each other): the lever's coordinates in the wrong order, told beside the
    offset."""
    theirs, mine = _chain([0.3, 0.5]), _chain([0.3, 0.5], along=(0.0, 1.0, 0.0))
    assert _told(mine, theirs, mine["joints"][1]["anchor"]) == ["coordinate_order", "offset"]


def test_a_link_hung_along_its_parent_s_z_backwards_is_axes_exchanged_as_well():
    theirs, mine = _chain([0.3, 0.5]), _chain([0.3, 0.5], along=(0.0, 0.0, -1.0))
    assert "coordinate_order" in _told(mine, theirs, mine["joints"][1]["anchor"])


def test_a_link_hung_at_a_slant_is_an_offset_only():
    """The near misses: the lever turned by 45 degrees in the parent's frame (its lengths along other axes are not
    the reference's), or stretched along another axis as well: no order, no sign, no factor."""
    theirs = _chain([0.3, 0.5])
    for along in [(np.sqrt(0.5), np.sqrt(0.5), 0.0), (1.0, 0.5, 0.0), (-1.0, 0.5, 0.0)]:
        mine = _chain([0.3, 0.5], along=along)
        assert _told(mine, theirs, mine["joints"][1]["anchor"]) == ["offset"], along


def test_a_link_hung_behind_its_parent_s_joint_is_an_offset_and_a_sign():
    """The second link hung at -L along its parent's x where +L belongs (the length typed with a minus): the body's
    offset is what the answer shows, the lever's sign where the slip was made; both are told (each coordinate where
    it belongs: no order).  Hung at -L/2, it is a sign and a factor at once, which the lever's slips of one edit do
    not tell: an offset alone."""
    theirs = _chain([0.3, 0.5])
    mine = _chain([0.3, 0.5], along=(-1.0, 0.0, 0.0))
    assert _told(mine, theirs, mine["joints"][1]["anchor"]) == ["offset", "sign_flip"]
    mine = _chain([0.3, 0.5], along=(-0.5, 0.0, 0.0))
    assert _told(mine, theirs, mine["joints"][1]["anchor"]) == ["offset"]


def test_a_joint_moved_in_its_body_is_an_offset_and_joints_moved_apart_name_nothing():
    """The second joint placed 0.03 m along its body's x (the body where it belongs): an offset, its joint's pos;
    the first and second moved by different vectors in their bodies' frames: no one story."""
    theirs = _chain([0.3, 0.5])
    mine = _chain([0.3, 0.5])
    frame = mine["bodies"][1]["frame"]
    mine["joints"][1] = {**mine["joints"][1], "anchor": mine["joints"][1]["anchor"] + frame @ [0.03, 0.0, 0.0]}
    assert _told(mine, theirs, mine["joints"][1]["anchor"]) == ["offset"]
    mine["joints"][0] = {**mine["joints"][0], "anchor": mine["joints"][0]["anchor"] + [0.0, 0.02, 0.0]}
    assert _told(mine, theirs, mine["joints"][1]["anchor"]) == []


def test_gravity_alone_negated_is_a_sign():
    theirs, mine = _chain([0.0, 0.0]), _chain([0.0, 0.0], gravity=(0.0, 9.81, 0.0))
    assert _told(mine, theirs, mine["gravity"]) == ["sign_flip"]


def test_differences_the_compared_value_is_not_among_name_nothing():
    """Gravity negated, but the compared value is a centre of mass that is the reference's."""
    theirs, mine = _chain([0.0, 0.0]), _chain([0.0, 0.0], gravity=(0.0, 9.81, 0.0))
    assert _told(mine, theirs, mine["bodies"][1]["com"]) == []


def test_two_stories_at_once_name_nothing():
    """A link moved and gravity negated: no one story holds both."""
    theirs, mine = _chain([0.0, 0.0]), _chain([0.0, 0.0], lengths=(1.5 * L, L), gravity=(0.0, 9.81, 0.0))
    assert _told(mine, theirs, mine["joints"][1]["anchor"]) == []


def test_a_site_with_its_coordinates_exchanged_is_told_by_the_point_it_holds():
    """The compared value is the world point a connect holds, which follows from the site's position in its body."""
    theirs, mine = _tipped(_chain([0.3, -0.5]), [L, 0.0, 0.0]), _tipped(_chain([0.3, -0.5]), [0.0, L, 0.0])
    assert _told(mine, theirs, mine["equalities"][0]["point1"]) == ["swapped"]


def test_a_tree_of_the_course_s_own_classes_is_no_model():
    """A result with bodies and joints that is no MuJoCo model's description (a tree of problem 24's classes)."""
    tree = {"bodies": [{"name": "B1", "A_IB": np.eye(3)}], "joints": [{"name": "J1", "q": 0.3}]}
    assert _told(tree, tree, [0.3]) == []
