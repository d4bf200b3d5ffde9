"""The student's side of a probe that declares a cheaper call holding part of its result (``Scene.student_at``):
problem 37's Lagrange probe computes ``M``, ``f``, ``g`` and, beside them, the mass matrix at thirty shifted
coordinates; the test of an ignored argument asks the student's ``f`` of it through ``mfg`` alone, the call the
probe's own code makes first, and asks the whole probe for a value outside that part."""

from types import SimpleNamespace

import numpy as np

from grader.diagnosis.scene import Scene


class Child:
    """A sandbox child that records the probes it is asked."""

    def __init__(self):
        self.asked = []

    def call(self, probe, *args, timeout=None):
        self.asked.append((probe, args))
        return {"M": np.eye(2), "f": np.array([1.0, 2.0]), "g": np.zeros(2), "bodies": []}


def test_the_part_of_a_probe_is_asked_of_the_student_through_its_cheaper_call():
    child = Child()
    scene = Scene(SimpleNamespace(child=child, oracle=SimpleNamespace(mode="live"), check_id="p37.x"))
    args = ({"bodies": [], "joints": []}, [0.1, 0.2], [0.3, 0.4], [0.0, -9.81, 0.0], 1e-6)
    value = scene.student_at("_dynamics.lagrange", args, ("f",))
    assert np.array_equal(value, [1.0, 2.0])
    assert child.asked == [("_dynamics.mfg", args[:4])]
    scene.student_at("_dynamics.lagrange", args, ("bodies",))
    assert child.asked[-1] == ("_dynamics.lagrange", args)
    assert scene.student_calls == 2
