"""The test of an ignored argument is a rival heard beside every other tier, and it guesses nothing.

* It changes every declared angle, scalar, vector and rotation, and every other argument of real numbers (a
  probe that declares nothing included): a frame given by its rotation, masses, a vector.
* An argument is told ignored only where the reference's value follows it and the student's stays the same, on
  the input shown and again on an input where every argument is moved at once (``grammar.moved``): a value left
  unchanged by a special input (a vector parallel to another, an axis an inertia keeps) is not.
* Heard beside the other tiers: a slip that another tier reproduces as well is told "could be X or
  ignored_argument".

Graded as ``grade batch`` grades (a warm fork), live and from the kit's answer key; the stand-ins below show the
rule on values the test controls.
"""

import numpy as np
import pytest

import grader.diagnosis as engine
from grader.checking import Tol
from grader.diagnosis import Declaration, Evidence, explain
from grader.diagnosis.grammar import ignore_candidates, moved, perturbed

from tests.kit_support import (  # noqa: F401 (fixtures)
    assert_told_alike,
    warm_slot,
)
from tests.engine.stand_ins import StandInChild, StandInOracle
from tests.submissions import Planted

#: problem 7's body angular velocity with A_CI left out, unskew(dA_IC): the value does not follow the rotation A_IC
#: (the test of an ignored argument turns it), and the formula tier reproduces it with a matrix factor left out
OMEGA_WITHOUT_ROTATION = Planted(
    name="ignored-p07-omega-body-without-rotation", problem=7, file="rotations.py",
    old="    return unskew(np.asarray(A_IC).T @ np.asarray(dA_IC))", new="    return unskew(np.asarray(dA_IC))",
    check="p07.omega_body", diagnosis="ignored_argument or missing_matrix_factor", message="when A turns")

MISTAKES = [OMEGA_WITHOUT_ROTATION]


@pytest.fixture(scope="module")
def slot():
    yield from warm_slot(sorted({m.problem for m in MISTAKES}))


@pytest.mark.parametrize("mistake", MISTAKES, ids=lambda m: m.name)
def test_an_ignored_rotation_is_told_beside_its_rival(mistake, tmp_path, kit_oracle, deferred_ids, slot):
    assert_told_alike(mistake, tmp_path / "pkg", kit_oracle, deferred_ids, slot)


# ------------------------------------------------------------------------------------------ the changes


def test_the_changes_keep_what_an_argument_is():
    A = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    I = np.diag([1.0, 2.0, 3.0])
    masses = [1.0, 3.0, 0.5]
    for change in (0, 1):
        turned = perturbed(A, change)
        assert np.allclose(turned.T @ turned, np.eye(3)) and np.isclose(np.linalg.det(turned), 1.0)
        inertia = perturbed(I, change)
        assert np.allclose(inertia, inertia.T) and np.allclose(np.linalg.eigvalsh(inertia), [1.0, 2.0, 3.0])
        assert abs(inertia[0, 2]) > 1e-3  # its axes moved: no zero of the one shown is left
        assert all(m > 0 for m in perturbed(masses, change))
        assert perturbed(1.5, change) != 1.5 and perturbed(0.0, change) != 0.0
    assert perturbed(np.linspace(0.0, 1.0, 20)) is None  # a grid of times is not changed
    assert perturbed(np.zeros(3)) is None  # nor a value no scale changes


def test_every_argument_of_real_numbers_is_a_candidate():
    decl = Declaration(args=("rotation", "", ""), names=("A", "table", "n"))
    args = (np.eye(3), [[0.5, 1.5], [2.0, 0.25]], 3)
    assert [leaf[0] for leaf in ignore_candidates(decl, args)] == [(0,), (1,)]
    assert [leaf[0] for leaf in ignore_candidates(None, ([1.0, 2.0], "text", 4))] == [(0,)]
    shifted = moved(decl, args)
    assert not np.allclose(shifted[0], args[0]) and shifted[2] == 3


# ------------------------------------------------------------------------------------------ stand-ins

TIGHT = Tol("tight", 1e-9, 1e-9)


def _explain(monkeypatch, probe, decl, reference, student, args):
    """The engine's finding for a check that compares the student's ``probe(*args)`` with the reference's."""
    monkeypatch.setitem(engine.DECLARATIONS, probe, decl)
    expected = np.asarray(reference(*args), dtype=float)
    got = np.asarray(student(*args), dtype=float)

    class Ctx:
        check_id = "p99.stub"
        oracle = StandInOracle({probe: lambda *a: np.asarray(reference(*a), dtype=float)})
        child = StandInChild({probe: lambda *a: np.asarray(student(*a), dtype=float)})
        seed = 7
        calls = [("reference", probe, args, expected), ("student", probe, args, got)]

    return explain(Ctx(), [Evidence(got, expected, TIGHT, "the value", got, expected)])


def test_a_frame_ignored_is_told_beside_the_other_frame(monkeypatch):
    """``A @ v`` where the student returns ``v``: the output in the other frame reproduces it, and so does the
    rotation ignored; both are told."""
    decl = Declaration(args=("rotation", "vector"), names=("A", "v"), rotation=0, draw=False)
    A = np.array([[0.36, -0.48, 0.8], [0.8, 0.6, 0.0], [-0.48, 0.64, 0.6]])
    finding = _explain(monkeypatch, "stub.mapped", decl, lambda A, v: np.asarray(A) @ v, lambda A, v: np.asarray(v),
                       (A, np.array([0.3, -1.2, 0.7])))
    assert finding is not None and "ignored_argument" in finding.names and "wrong_frame" in finding.names, finding
    assert "when A turns" in finding.hint


#: a made-up gait: a cosine series and a sine series of the time, ``a @ cos(k t) + b @ sin(k t)``
GAIT = Declaration(args=("scalar", "vector", "vector"), names=("t", "a", "b"), draw=False)
HARMONICS = np.array([1.0, 2.0, 3.0])


def _gait(t, a, b):
    return np.asarray(a) @ np.cos(HARMONICS * t) + np.asarray(b) @ np.sin(HARMONICS * t)


def test_an_argument_ignored_whose_zero_gives_the_value_is_told_beside_its_terms_left_out(monkeypatch):
    """The sine series left out: the value does not follow its coefficients ``b`` (the argument ignored), and it
    is the reference's with ``b`` zero: the terms ``b`` makes are left out, one value read two ways."""
    finding = _explain(monkeypatch, "stub.gait", GAIT, _gait, lambda t, a, b: np.asarray(a) @ np.cos(HARMONICS * t),
                       (0.7, np.array([0.3, -0.2, 0.05]), np.array([0.4, 0.1, -0.3])))
    assert finding is not None and set(finding.names) == {"ignored_argument", "missing_term"}, finding
    assert "with b zero" in finding.hint, finding.hint


def test_an_argument_ignored_for_another_is_no_term_left_out(monkeypatch):
    """The near miss: the sine series with the cosine's coefficients, ``a @ sin(k t)``: ``b`` is ignored, but the
    value is not the reference's with ``b`` zero: the argument ignored alone, which, an array, is told only beside
    another explanation (none here)."""
    from grader.diagnosis import engine as explaining

    heard = []
    ignored = explaining._ignored
    monkeypatch.setattr(explaining, "_ignored", lambda scene, evidences, *rest: heard.append(
        ignored(scene, evidences, *rest)) or heard[-1])
    finding = _explain(monkeypatch, "stub.gait", GAIT, _gait,
                       lambda t, a, b: np.asarray(a) @ np.cos(HARMONICS * t) + np.asarray(a) @ np.sin(HARMONICS * t),
                       (0.7, np.array([0.3, -0.2, 0.05]), np.array([0.4, 0.1, -0.3])))
    assert [h.name for h in heard[0]] == ["ignored_argument"] and "when b is scaled" in heard[0][0].detail, heard
    assert finding is None, finding


def test_masses_ignored_are_told_beside_a_rival_never_alone(monkeypatch):
    """A probe that declares nothing: the student's sum of squared distances without the masses does not follow
    the masses, which the test of an ignored argument finds; alone, no other tier explaining it, an array that a
    value does not follow may as well be a term left out that carried all of its dependence on it, and nothing is
    told; a number ignored is told alone."""
    from grader.diagnosis import engine as explaining

    points = np.array([[1.0, 0.5, -0.2], [-0.3, 0.8, 1.1], [0.4, -1.0, 0.6]])

    def weighted(masses, points):
        return np.array([np.sum(np.asarray(masses) * np.sum(np.asarray(points) ** 2, axis=1))])

    heard = []
    ignored = explaining._ignored
    monkeypatch.setattr(explaining, "_ignored", lambda scene, evidences, *rest: heard.append(
        ignored(scene, evidences, *rest)) or heard[-1])
    finding = _explain(monkeypatch, "stub.second_moment", None, weighted,
                       lambda masses, points: np.array([np.sum(np.asarray(points) ** 2)]), ([2.0, 0.5, 1.5], points))
    assert [h.name for h in heard[0]] == ["ignored_argument"] and "argument 1 is scaled" in heard[0][0].detail
    assert finding is None or "ignored_argument" not in finding.names, finding
    finding = _explain(monkeypatch, "stub.scaled", None, lambda m, v: m * np.asarray(v),
                       lambda m, v: 2.0 * np.asarray(v), (1.5, [0.5, -1.0, 2.0]))
    assert finding is not None and finding.names == ("ignored_argument",), finding


def test_an_array_ignored_alone_leaves_the_formula_tier_heard_in_full(monkeypatch):
    """The masses ignored and nothing else found: an array argument ignored is told only beside another
    explanation, so the formula tier is asked as where nothing explained the answer (no family told), and its every
    stage is heard (a constructor of the library that stores one argument from another is found there), not only the
    rivals of a family told."""
    from grader.diagnosis import engine as explaining

    asked = []
    monkeypatch.setattr(explaining, "mutant_slips",
                        lambda scene, evidences, another=None, told=None, *rest: asked.append(told) or [])
    points = np.array([[1.0, 0.5, -0.2], [-0.3, 0.8, 1.1], [0.4, -1.0, 0.6]])
    _explain(monkeypatch, "stub.second_moment", None,
             lambda masses, points: np.array([np.sum(np.asarray(masses) * np.sum(np.asarray(points) ** 2, axis=1))]),
             lambda masses, points: np.array([np.sum(np.asarray(points) ** 2)]), ([2.0, 0.5, 1.5], points))
    assert asked == [None], asked


def test_the_arguments_the_test_had_no_budget_for_are_passed_on(monkeypatch):
    """The test of an ignored argument changes one argument after another within its budget of the student's
    calls; the positions of those it had no budget for are passed on to the formula tier (which may tell one that
    its slip leaves unused), those it changed are not."""
    from grader.diagnosis import engine as explaining

    left = []
    ignored = explaining._ignored
    monkeypatch.setattr(explaining, "_ignored", lambda scene, evidences, unreached=None: ignored(
        scene, evidences, left if unreached is not None else None))
    args = (1.5, 0.7, 2.2, 0.9, 1.3, 0.4)
    _explain(monkeypatch, "stub.product", None, lambda *x: np.array([np.prod(x)]),
             lambda *x: np.array([np.prod(x[:-1])]), args)
    assert left and left == sorted(left) and left[-1] == len(args) - 1, left
    assert 0 not in left, left  # the first argument is always changed
    left.clear()
    _explain(monkeypatch, "stub.pair", None, lambda a, b: np.array([a * b]), lambda a, b: np.array([a]), (1.5, 0.7))
    assert left == [], left  # both changed (the second found ignored): none left over


def test_a_value_unchanged_by_a_special_input_is_no_ignored_argument(monkeypatch):
    """Near miss: the student's ``v + v x w`` for the reference's ``v + w``, shown where ``w`` is parallel to
    ``v``: there the student's value stays ``v`` when ``w`` is scaled, but it follows ``w`` on an input where every
    argument is moved; nothing is told ignored."""
    decl = Declaration(args=("vector", "vector"), names=("v", "w"), draw=False)
    v = np.array([0.6, -0.3, 0.9])
    finding = _explain(monkeypatch, "stub.sum", decl, lambda v, w: np.asarray(v) + np.asarray(w),
                       lambda v, w: np.asarray(v) + np.cross(v, w), (v, 1.7 * v))
    assert finding is None or "ignored_argument" not in finding.names, finding


# ------------------------------------------------------------------------------------------ a run's start


def test_a_run_from_the_sheets_start_is_a_variant_where_another_start_is_given():
    """A run's start declared with the probe of the sheet's (``motion["start"]``): the reference's run from the
    sheet's start is tried where another is given (the start ignored), at the cost of a start that differs, so both
    are told; where the sheet's start is given, nothing is tried."""
    from grader.diagnosis.runs import parameter_variants

    motion = {"time": "t", "states": ("q",), "start": {"arg": 0, "name": "q0", "sheet": "stub.sheet_start"}}
    sheet = [1.0, 1.0, 0.75]
    found = parameter_variants(motion, ([0.5, 1.25, 0.75], 2.0), None, sheet)
    assert [(h.name, h.cost, args) for h, args in found] == [("ignored_argument", 3, ([1.0, 1.0, 0.75], 2.0))]
    assert "q0 = [0.5000, 1.2500, 0.7500] is given" in found[0][0].detail
    assert parameter_variants(motion, (list(sheet), 2.0), None, sheet) == []
    assert parameter_variants(motion, ([0.5, 1.25, 0.75], 2.0), None, None) == []
