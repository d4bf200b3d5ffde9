"""Checks of problem 39: the turbine's inertia (aligned and misaligned) and the forces its bearings must withstand.

The sheet's model answers (problem data P39) and random rotors, rates, masses and bearing distances.  The forces
are also checked by the physics they must satisfy: they carry the weight and their moment about the centre of
gravity is the gyroscopic moment ``omega x (I2 omega)``.
"""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_VALUES,
    Mistake,
    Tol,
    assert_close,
    assert_close_each,
    check,
    close,
    fail,
)
from probes import problem_39 as p39

TITLE = "Turbine"

#: problem data P39 (sheet's approximations: pi = sqrt(10), g = 10)
I_AXIAL, I_TRANSVERSE = 5e4, 4.5e5
ALPHA = 1e-3
OMEGA = 50.0 * np.sqrt(10.0)
MASS, GRAVITY, DISTANCE = 1e5, 10.0, 10.0
I1_SHEET = np.diag([5e4, 4.5e5, 4.5e5])
I2_SHEET = np.array([[50000.45, -400.0, 0.0], [-400.0, 450000.05, 0.0], [0.0, 0.0, 450000.0]])
F1_SHEET, F2_SHEET = np.array([0.0, 1.5e6, 0.0]), np.array([0.0, -0.5e6, 0.0])
#: the small-angle approximation and an exact rotation by 1e-3 differ by up to 0.45 in I2's diagonal
SMALL_ANGLE = Tol("small-angle approximation", 0.5)
FORCES = Tol("sheet's forces", 1.0, 1e-6)
PHYSICS = Tol("balance of forces and moments", 1e-6, 1e-9)
_SEEDS = st.integers(0, 2**32 - 1)

TRANSPOSE_HINT = ("I2 = A I1 A.T with A the small rotation about the 3-axis, A = [[1, -alpha, 0], [alpha, 1, 0], "
                  "[0, 0, 1]]; yours is A.T I1 A (the rotation the other way).")


def _rot3(alpha):
    """The exact rotation about the 3-axis (scipy's, so that no line of problem 6's solution is in the checks)."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_rotvec([0.0, 0.0, alpha]).as_matrix()


def _small(alpha):
    return np.array([[1.0, -alpha, 0.0], [alpha, 1.0, 0.0], [0.0, 0.0, 1.0]])


def _moments(rng):
    """An axial and a transverse moment of a rotor of its own (drawn anew at each grading: no key holds it)."""
    return [float(x) for x in np.round(rng.uniform(1.0, 10.0, 2), 6)]


@check(1, title="(a) I1 = diag(50000, 450000, 450000): the axis of symmetry along 1 (and a rotor of other moments)",
       stage=STAGE_VALUES, group="I1")
def check_inertia_aligned(ctx):
    other = ctx.draw(_moments)
    for I_axial, I_transverse, sheet in ((I_AXIAL, I_TRANSVERSE, True), (*other, False)):
        got = ctx.student(p39.inertia_aligned, I_axial, I_transverse)
        expected = ctx.reference(p39.inertia_aligned, I_axial, I_transverse)
        assert_close(got, I1_SHEET if sheet else expected, f"inertia_aligned({I_axial:g}, {I_transverse:g})", EXACT, [
            Mistake("axis_order", np.diag([I_transverse, I_axial, I_transverse]), "The rotor turns about the 1-axis, "
                    "its axis of symmetry: the axial moment is I1[0, 0]."),
            Mistake("axis_order", np.diag([I_transverse, I_transverse, I_axial]), "The rotor turns about the "
                    "1-axis, its axis of symmetry: the axial moment is I1[0, 0]."),
        ], context="(the sheet's turbine)" if sheet else "")


def _misaligned_mistakes(I1, alpha):
    A = _small(alpha)
    return [Mistake("transpose", A.T @ I1 @ A, TRANSPOSE_HINT),
            Mistake("one_sided", A @ I1, "An inertia matrix transforms with the rotation on both sides: I2 = A I1 "
                    "A.T."),
            Mistake("degrees", _small(np.deg2rad(alpha)) @ I1 @ _small(np.deg2rad(alpha)).T, "alpha is in radians "
                    "(1/1000 rad).")]


#: a rotor and a misalignment the sheet does not print (the sheet's I2 and forces typed in earn nothing there)
OTHER_I1, OTHER_ALPHA = np.diag([2.0, 5.0, 5.0]), 2e-2
OTHER_ROTOR = (np.array([[2.0, -0.1, 0.0], [-0.1, 5.0, 0.0], [0.0, 0.0, 5.0]]), 3.0, 2.0, 9.81, 1.5)
TYPED_HINT = ("These are the sheet's model answers whatever the arguments: compute them from the arguments (the "
              "checks also ask values the sheet does not print).")


def _assert_misaligned(got, expected, I1, alpha, extra=(), context=""):
    """``I2`` of ``inertia_misaligned(I1, alpha)``: the small-angle rotation (the reference's) or the exact one."""
    exact = _rot3(alpha) @ I1 @ _rot3(alpha).T
    if close(got, exact, EXACT):
        return
    assert_close(got, expected, f"inertia_misaligned(I1, {alpha:.6g})", EXACT,
                 [*extra, *_misaligned_mistakes(I1, alpha)],
                 context=context or "(with sin alpha = alpha, cos alpha = 1; the exact rotation is accepted as well)")


@check(2, title="(b) I2 = A I1 A.T for the misalignment alpha = 1e-3 about 3: the sheet's value (and the reference's "
       "for a rotor the sheet does not print)", stage=STAGE_VALUES, group="I2")
def check_inertia_misaligned(ctx):
    got = ctx.student(p39.inertia_misaligned, I1_SHEET, ALPHA)
    assert_close(got, I2_SHEET, f"inertia_misaligned(I1, {ALPHA:g})", SMALL_ANGLE,
                 _misaligned_mistakes(I1_SHEET, ALPHA), context="(the sheet's model answer; an exact rotation by alpha is accepted as well)")
    expected = ctx.reference(p39.inertia_misaligned, OTHER_I1, OTHER_ALPHA)
    _assert_misaligned(ctx.student(p39.inertia_misaligned, OTHER_I1, OTHER_ALPHA), expected, OTHER_I1,
                       OTHER_ALPHA, [Mistake("typed_numbers", I2_SHEET, TYPED_HINT)],
                       "(a rotor the sheet does not print; the exact rotation is accepted as well)")


@st.composite
def _inertias(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    x2, y2, z2 = rng.uniform(0.5, 2.0, 3)
    return np.diag([y2 + z2, x2 + z2, x2 + y2]), float(rng.uniform(-0.05, 0.05))


@check(1, title="(b) inertia_misaligned on random principal inertias and small angles (small-angle rotation or "
       "exact)", stage=STAGE_RANDOM, group="I2")
def check_inertia_misaligned_random(ctx):
    def compare(got, expected, args):
        _assert_misaligned(got, expected, *args)

    ctx.compare_random(p39.inertia_misaligned, _inertias(), name="I2", tol=EXACT, compare=compare,
                       examples=10)


def _force_mistakes(I2, omega, m, g, d, expected):
    F1, F2 = (np.asarray(F) for F in expected)
    weight = np.array([0.0, m * g / 2, 0.0])
    dynamic1, dynamic2 = F1 - weight, F2 - weight
    return [
        ("missing_gravity", [dynamic1, dynamic2], "The bearings carry the rotor's weight as well: F1 + F2 = "
         "(0, m g, 0)."),
        ("missing_gyroscopic", [weight, weight], "The misaligned rotor needs a moment to keep turning about the fixed "
         "axis: omega x (I2 omega) (omegaDot = 0), carried by the bearings as a couple."),
        ("gyroscopic_sign", [weight - dynamic1, weight - dynamic2], "The moment the bearings exert is "
         "+omega x (I2 omega) (Euler, omegaDot = 0): check the order of the cross product and which bearing sits "
         "at -d/2 (bearing 1; bearing 2 at +d/2)."),
        ("gravity_sign", [dynamic1 - weight, dynamic2 - weight], "Gravity acts along -y, so the bearings push up: "
         "F1 + F2 = (0, +m g, 0)."),
    ]


def _force_case(got, expected, args, tol, context="", extra=()):
    """The comparison of ``[F1, F2]`` (rows) with the expected forces, with the known mistakes of the pair (and
    ``extra``), as ``assert_close_each`` takes it."""
    if not isinstance(got, list) or len(got) != 2:
        fail(f"bearing_forces must return the two forces (F1, F2), got {str(got)[:200]}", diagnosis="format")
    found = [*extra, *(Mistake(mistake, np.array(value), hint)
                       for mistake, value, hint in _force_mistakes(*args, expected))]
    return np.array(got, dtype=float), np.array(expected), "(F1, F2) (one force per row)", tol, found, context


def _assert_forces(got, expected, args, tol, context="", extra=()):
    """``[F1, F2]`` (rows) against the expected forces, with the known mistakes of the pair (and ``extra``)."""
    assert_close_each([_force_case(got, expected, args, tol, context, extra)])


def _own_rotor(rng):
    """A rotor of its own (drawn anew at each grading: no key holds its forces): I2, omega, m, g, d."""
    A = rng.uniform(-1.0, 1.0, (3, 3))
    omega, m, g, d = (float(x) for x in rng.uniform([1.0, 0.5, 1.0, 0.5], [10.0, 5.0, 10.0, 5.0]))
    return [(A @ A.T + np.eye(3)).tolist(), omega, m, g, d]


@check(2, title="(c) the sheet's forces: F1 = (0, 1.5e6, 0) N and F2 = (0, -0.5e6, 0) N at 1500 rpm (pi = sqrt(10), "
       "g = 10), and the reference's for a rotor the sheet does not print and for one drawn at each grading",
       stage=STAGE_VALUES, group="forces")
def check_bearing_forces(ctx):
    args = (I2_SHEET, OMEGA, MASS, GRAVITY, DISTANCE)
    cases = [_force_case(ctx.student(p39.bearing_forces, *args), [F1_SHEET, F2_SHEET], args, FORCES,
                         "(the sheet's model answer)")]
    expected = ctx.reference(p39.bearing_forces, *OTHER_ROTOR)
    cases.append(_force_case(ctx.student(p39.bearing_forces, *OTHER_ROTOR), expected, OTHER_ROTOR, EXACT,
                             "(a rotor the sheet does not print, against the reference)",
                             [Mistake("typed_numbers", np.array([F1_SHEET, F2_SHEET]), TYPED_HINT)]))
    I2, *rest = ctx.draw(_own_rotor)
    rotor = (np.array(I2), *rest)
    expected = ctx.reference(p39.bearing_forces, *rotor)
    cases.append(_force_case(ctx.student(p39.bearing_forces, *rotor), expected, rotor, EXACT,
                             f"(a rotor of its own, omega = {rest[0]:.4g} rad/s, m = {rest[1]:.4g} kg, against the "
                             "reference)", [Mistake("typed_numbers", np.array([F1_SHEET, F2_SHEET]), TYPED_HINT)]))
    assert_close_each(cases)  # a known mistake is named where it gives the student's forces on every rotor


@st.composite
def _rotors(draw):
    rng = np.random.default_rng(draw(_SEEDS))
    A = rng.uniform(-1, 1, (3, 3))
    I2 = A @ A.T + np.eye(3)
    return I2, float(rng.uniform(1, 10)), float(rng.uniform(0.5, 5)), float(rng.uniform(1, 10)), float(
        rng.uniform(0.5, 5))


@check(2, title="(c) bearing_forces on random rotors: they carry the weight, their moment is omega x (I2 omega), and "
       "they match the reference", stage=STAGE_RANDOM, group="forces")
def check_bearing_forces_random(ctx):
    def compare(got, expected, args):
        I2, omega, m, g, d = args
        if isinstance(got, list) and len(got) == 2 and all(np.shape(F) == (3,) for F in got):
            F1, F2 = (np.asarray(F, dtype=float) for F in got)
            w = np.array([omega, 0.0, 0.0])
            moment = np.cross([-d / 2, 0.0, 0.0], F1) + np.cross([d / 2, 0.0, 0.0], F2)
            balanced = close(F1 + F2, [0.0, m * g, 0.0], PHYSICS) and close(moment, np.cross(w, I2 @ w), PHYSICS)
            if balanced and close(F1[0], 0.0, PHYSICS) and close(F2[0], 0.0, PHYSICS):
                return
        _assert_forces(got, expected, args, EXACT, "(expected: F1 + F2 = (0, m g, 0), moment about the centre of "
                                                   "gravity omega x (I2 omega), no axial force)")

    ctx.compare_random(p39.bearing_forces, _rotors(), name="F1, F2", tol=EXACT, compare=compare,
                       examples=10)
