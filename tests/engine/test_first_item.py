"""The formula tier's slip of a loop's first item (``grader.diagnosis.mutants``: ``_first_slips``): the first item's
own value (``P_r_PDp=(0, 0, 0) if k == 0 else (half, 0, 0)``, ``A_PDp=A_FIRST if k == 0 else np.eye(3)``) given to
every item, or the others' given to the first.  A position so written is told as an offset, a rotation as a wrong
frame; a value that is neither (a mass) is no such slip.  And a number of a point's position written out doubled or
halved (``_position_slips``: a full length for a half), told as a factor and as an offset beside it.

Each is planted into a made-up problem that the tier names on two inputs, with the near misses of a first mass (the
same slip, which the tier does not try) and of an offset three times as long."""

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import about_3, made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for the slips of a loop's first item."""

import numpy as np


def _turn(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def chain(angles, length):
    """The points of a planar chain of links ``length`` long, the first hung 0.3 above the origin, the first joint
    turned a quarter turn further."""
    # BEGIN SOLUTION problem 94
    points, A, r = [], np.eye(3), np.zeros(3)
    for k, angle in enumerate(angles):
        P_r_PDp = np.array([0.0, 0.3, 0.0]) if k == 0 else np.array([length, 0.0, 0.0])
        A_PDp = _turn(np.pi / 2) if k == 0 else np.eye(3)
        r = r + A @ P_r_PDp
        A = A @ A_PDp @ _turn(angle)
        points.append(r)
    return np.array(points + [r + A @ np.array([length, 0.0, 0.0])])
    # END SOLUTION


def masses(count, m):
    """The masses of ``count`` links of mass ``m``, the first one twice as heavy."""
    # BEGIN SOLUTION problem 94
    out = []
    for k in range(count):
        mass = 2 * m if k == 0 else m
        out.append(mass * 9.81)
    return np.array(out)
    # END SOLUTION
'''


made_up = made_up_fixture(SOURCE, 94, "first")



def student_chain(first_offset: bool, first_turn: bool, reach: float = 1.0):
    """The made-up chain with the first link's own offset or turn given to every link, or the others' offset
    ``reach`` times as long."""
    def chain(angles, length):
        points, A, r = [], np.eye(3), np.zeros(3)
        for k, angle in enumerate(angles):
            P_r_PDp = np.array([0.0, 0.3, 0.0]) if first_offset or k == 0 else np.array([reach * length, 0.0, 0.0])
            A_PDp = about_3(np.pi / 2) if first_turn or k == 0 else np.eye(3)
            r = r + A @ P_r_PDp
            A = A @ A_PDp @ about_3(angle)
            points.append(r)
        return np.array(points + [r + A @ np.array([length, 0.0, 0.0])])
    return chain


CHAINS = [(np.array([0.3, -0.5, 0.8]), 1.2), (np.array([-0.7, 0.2, 0.4]), 0.8)]


def found(package, name, student, inputs):
    evidences = made_up_evidences(package, name, student, inputs, number=94)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    return mutants.mutant_slips(scene(f"p94.{name}"), evidences)


def test_every_link_placed_as_the_first_is_named_an_offset(made_up):
    hypotheses = found(made_up, "chain", student_chain(first_offset=True, first_turn=False), CHAINS)
    assert {h.name for h in hypotheses} == {"offset"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`chain` places every item of a loop as its first" in h.detail for h in hypotheses)
    assert DIAGNOSES["offset"].family == "offset"


def test_every_joint_turned_as_the_first_is_named_a_wrong_frame(made_up):
    hypotheses = found(made_up, "chain", student_chain(first_offset=False, first_turn=True), CHAINS)
    assert {h.name for h in hypotheses} == {"wrong_frame"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`chain` turns every item of a loop as its first" in h.detail for h in hypotheses)


def test_every_mass_as_the_first_is_no_slip_of_a_first_item(made_up):
    """The near miss: the first's own mass given to every link is no position and no rotation: the tier does not
    try it (a factor 2 on every entry but the first, which no slip of the grammar gives, names nothing)."""
    hypotheses = found(made_up, "masses", lambda count, m: np.full(count, 2 * m * 9.81), [(3, 1.5), (4, 0.7)])
    assert not any("of a loop as its first" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_a_point_placed_a_full_length_too_far_is_a_factor_and_an_offset(made_up):
    """The links' offset written twice as long (``2 * length`` for ``length``, a full length for a half): a number of
    a point's position doubled, told as a factor and as an offset beside it; the near miss, three times as long, is
    neither."""
    hypotheses = found(made_up, "chain", student_chain(first_offset=False, first_turn=False, reach=2.0), CHAINS)
    assert {h.name for h in hypotheses} == {"wrong_factor", "offset"}, [(h.name, h.detail) for h in hypotheses]
    assert any("a number of a point's position that `chain` writes out is doubled" in h.detail for h in hypotheses)
    hypotheses = found(made_up, "chain", student_chain(first_offset=False, first_turn=False, reach=3.0), CHAINS)
    assert not any("position" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
