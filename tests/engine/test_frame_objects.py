"""The formula tier's slips of a coordinate system read for another (``grader.diagnosis.mutants``: ``frame_objects``,
the course's ``C1``, ``C2``, ``C3``): ``C1.to() @ v`` for ``C3.to() @ v``, a call given a frame that takes none
(``C3.to(C1)``) or left without the one it takes (``C3.to()`` for ``C3.to(C3)``), each told as a wrong frame.

Planted into a made-up problem that the tier names on two inputs, with the near miss of a vector turned by a rotation
that no frame of the chain gives."""

import numpy as np
import pytest

from grader.diagnosis import mutants

from .stand_ins import about_3, made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem of coordinate systems."""

import numpy as np


def turn(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


class Frame:
    """A frame turned by ``A`` relative to ``parent`` (the inertial frame where None)."""

    def __init__(self, A, parent=None):
        self.A, self.parent = A, parent

    def to(self, other=None):
        """The rotation from this frame's coordinates into ``other``'s (the inertial frame's where None)."""
        A = self.A if self.parent is None else self.parent.to() @ self.A
        return A if other is None else other.to().T @ A


def coordinates(v, angle):
    """``v``, given in the last frame of a chain of three, in inertial coordinates and in the first frame's."""
    # BEGIN SOLUTION problem 91
    C1 = Frame(turn(angle))
    C2 = Frame(turn(2 * angle), C1)
    C3 = Frame(turn(0.5), C2)
    return np.concatenate([C3.to() @ v, C3.to(C1) @ v, C3.to(C3) @ v])
    # END SOLUTION
'''


made_up = made_up_fixture(SOURCE, 91, "frames")



INPUTS = [(np.array([0.3, -1.2, 0.7]), 0.4), (np.array([1.1, 0.4, -0.9]), -0.7)]


def found(package, student):
    evidences = made_up_evidences(package, "coordinates", student, INPUTS, number=91)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    return mutants.mutant_slips(scene("p91.coordinates"), evidences)


def rotation(into, frm):
    """The rotation of the made-up chain from frame ``frm``'s coordinates into ``into``'s."""
    def coordinates(v, angle):
        A = {"I": np.eye(3), "1": about_3(angle)}
        A["2"] = A["1"] @ about_3(2 * angle)
        A["3"] = A["2"] @ about_3(0.5)
        return A[into].T @ A[frm] @ v
    return coordinates


def student(*pairs):
    def coordinates(v, angle):
        return np.concatenate([rotation(into, frm)(v, angle) for into, frm in pairs])
    return coordinates


RIGHT = (("I", "3"), ("1", "3"), ("3", "3"))


@pytest.mark.parametrize("pairs, what", [
    ((("I", "1"), ("1", "3"), ("3", "3")), "C1 read for C3"),
    ((("I", "3"), ("I", "3"), ("3", "3")), "a call left without its frame"),
    ((("1", "3"), ("1", "3"), ("3", "3")), "a call given a frame it does not take"),
])
def test_a_coordinate_system_read_for_another_is_a_wrong_frame(made_up, pairs, what):
    hypotheses = found(made_up, student(*pairs))
    assert "wrong_frame" in {h.name for h in hypotheses}, (what, [(h.name, h.detail) for h in hypotheses])
    assert any("`coordinates` reads one coordinate system where another belongs" in h.detail for h in hypotheses)


def test_a_vector_turned_by_no_frame_of_the_chain_is_not_that_slip(made_up):
    def other(v, angle):
        right = student(*RIGHT)(v, angle)
        return np.concatenate([about_3(0.9) @ v, right[3:]])

    hypotheses = found(made_up, other)
    assert not any("coordinate system" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
