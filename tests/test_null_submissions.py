"""Answers that do nothing earn nothing: the null family.

For every problem, three submissions built from the reference (``tests/nulls.py``) whose public functions return
zeros, ones or 0.5 wherever the reference returns a number, with the reference's shapes and containers, are
graded on workers forked from a batch slot's warm process (as ``grade batch`` grades).  A check may pass on them
only when nothing of the student it saw was changed by the mapping: every student value it received equals the
reference submission's value for the same call (answers read from ``answers.toml``, a MuJoCo model built from
unchanged MJCF text, a value whose correct answer happens to be the constant).  Which checks these are is
derived from the calls each check makes, not listed by hand.  The untouched template earns nothing at all.

The family grades the reference and three null submissions of every problem: about 80 s on two cores (slow).
"""

from __future__ import annotations

import copy
import importlib
import sys

import numpy as np
import pytest

from checks._effects import same
from grader.problems import problems
from grader.errors import StudentFault
from grader.results import Status
from probes import call_key

from .kit_support import warm_slot
from .nulls import FILLS, build_null
from .submissions import ROOT, copy_reference
from .wrapped import grade_wrapped

PROBLEMS = [p.number for p in problems()]


class RecordingChild:
    """A sandboxed child that remembers, for each check, the student values it handed out."""

    def __init__(self, child):
        self.child = child
        self.ctx = None
        self.calls: dict[str, list] = {}

    def call(self, probe, *args, timeout=None):
        key = call_key(probe, args)
        try:
            value = self.child.call(probe, *args, timeout=timeout)
        except StudentFault as exc:
            self.calls.setdefault(self.ctx.check_id, []).append((key, ("raised", type(exc).__name__)))
            raise
        self.calls.setdefault(self.ctx.check_id, []).append((key, ("value", copy.deepcopy(value))))
        return value

    def output(self):
        return self.child.output()


def grade_recorded(problem: int, source, zygote):
    """The results of one problem of a submission (live reference) and the student values each check saw."""
    results, recorder = grade_wrapped(problem, source, zygote, RecordingChild)
    return results, recorder.calls


def unchanged(calls: list, reference: dict) -> bool:
    """True when every student value of ``calls`` is what the reference submission gave for the same call."""
    for key, (kind, value) in calls:
        if key not in reference:
            return False
        other_kind, other = reference[key]
        if kind != other_kind or (kind == "raised" and value != other) or (kind == "value" and not same(value, other)):
            return False
    return True


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(PROBLEMS)


@pytest.fixture(autouse=True)
def verdicts_only(monkeypatch):
    """Whether a check passes is all that counts here.  The diagnosis engine and hypothesis's shrinking, which name
    and show a failure a check found already and never turn it into a pass, are off: they were most of the time of a
    grading where nearly every check fails (a failing randomized comparison shows the simplest failing input of its
    draws instead)."""
    import grader.diagnosis as engine
    from grader.context import Context

    monkeypatch.setattr(engine, "ENABLED", False)
    monkeypatch.setattr(Context, "_shrink", lambda self, strategy, examples, evaluate: None)


@pytest.fixture(scope="module")
def packages(tmp_path_factory):
    """The reference and the three null submissions, built once."""
    root = tmp_path_factory.mktemp("nulls")
    built = {"reference": copy_reference(root / "reference")}
    for family, fill in FILLS.items():
        built[family] = build_null(root / family, fill)
    return built


def test_a_null_package_keeps_the_structure_of_every_result(tmp_path, monkeypatch):
    """The mapping itself: shapes, keys, named tuples and integers kept, every float the constant, state read
    through a public class's attributes mapped too, exceptions passed on."""
    build_null(tmp_path / "nullpkg", 0.5)
    monkeypatch.syspath_prepend(str(tmp_path))
    try:
        rotations = importlib.import_module("nullpkg.rotations")
        frames = importlib.import_module("nullpkg.problem_06").frames()
        tree = importlib.import_module("nullpkg.tree")
        p04 = importlib.import_module("nullpkg.problem_04")
        assert np.array_equal(rotations.R1(0.3), np.full((3, 3), 0.5))
        assert sorted(frames) == ["A_IC1", "A_IC2", "A_IC3"] and all(np.all(a == 0.5) for a in frames.values())
        root, body = tree.Body("ground"), tree.Body("link", m=2.0)
        joint = tree.RotationalJoint(root, body, q_index=(0,))
        assert tree.KinematicTree(root).nq == 1 and root.child_joints == [joint]
        root.forward_kinematics(np.array([0.4]), np.array([1.0]), np.array([0.0]))
        assert np.all(body.A_IB == 0.5) and np.all(body.B_J_S == 0.5) and body.B_J_S.shape == (3, 1)
        with pytest.raises(p04.OverconstrainedError):
            p04.assemble([0.0, 0.0, 0.0, 0.0])
        assert "<mujoco" in p04.four_bar(950.0, 9.81, np.zeros(4))
    finally:
        for name in [name for name in sys.modules if name.split(".")[0] == "nullpkg"]:
            del sys.modules[name]


@pytest.mark.slow
@pytest.mark.parametrize("problem", PROBLEMS)
def test_null_submissions_earn_nothing(problem, packages, slot):
    reference_results, reference_calls = grade_recorded(problem, packages["reference"], slot)
    assert all(r.passed for r in reference_results), [r.check_id for r in reference_results if not r.passed]
    seen = {key: value for calls in reference_calls.values() for key, value in calls}
    credited = []
    for family in FILLS:
        results, calls = grade_recorded(problem, packages[family], slot)
        for result in results:
            if result.status is Status.PASSED and not unchanged(calls.get(result.check_id, []), seen):
                credited.append(f"{family}: {result.check_id} ({result.score:g} points)")
    assert not credited, "checks gave credit to answers that do nothing:\n" + "\n".join(credited)


def test_untouched_template_earns_nothing(slot):
    scored = []
    for problem in PROBLEMS:
        results, _ = grade_recorded(problem, ROOT / "student_template", slot)
        scored += [f"{r.check_id} ({r.score:g})" for r in results if r.score > 0]
    assert not scored, f"the untouched template earns points: {scored}"
