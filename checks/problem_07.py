"""Checks of problem 7: skew matrices, angular velocity from a transformation, the symbolic derivation."""

import numpy as np

from checks._effects import assert_no_side_effects
from checks._figures import add_frames
from checks._real import assert_real
from checks._rigid import ROTATIONS, skew
from checks._upstream import assert_close_judged, judged
from grader import strategies as st
from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_SHAPE,
    STAGE_VALUES,
    Mistake,
    Tol,
    assert_close,
    assert_rotation,
    check,
    fail,
)
from probes import problem_06 as p06, problem_07 as p07

TITLE = "Derivatives of transformations"

FLOATS = st.floats(-5, 5, allow_nan=False, allow_infinity=False)
VECTORS = st.tuples(FLOATS, FLOATS, FLOATS).map(np.array)
SYMBOLIC = Tol("symbolic evaluation", 1e-9, 1e-9)
KEYS = ("A_IC1", "A_IC2", "A_IC3", "A_C3I", "C3_omega_IC3")
#: the animation's start (alpha, beta, gamma) [deg], as on the sheet
START_DEG = (60.0, 45.0, 30.0)


def _rotation_and_rate(A, w):
    return A, skew(w) @ A  # dA_IC/dt for the inertial angular velocity w


#: a rotation without special structure, for the side-effect check (a quaternion's rotation)
_SIDE_A = np.array([[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]])

MOTIONS = st.tuples(ROTATIONS, VECTORS).map(lambda t: _rotation_and_rate(*t))

SIGN_HINT = ("Your result has the opposite sign: skew(w) has -w3 at [0, 1], +w2 at [0, 2] and -w1 at [1, 2], so "
             "that skew(w) @ x == np.cross(w, x).")


@check(1, title="skew(w) is a 3 x 3 matrix and unskew returns a 3-vector", stage=STAGE_SHAPE, group="skew")
def check_skew_shape(ctx):
    assert_real(ctx.student(p07.skew, np.array([1.0, 2.0, 3.0])), "skew((1, 2, 3))", (3, 3))
    W = np.array([[0.0, -3.0, 2.0], [3.0, 0.0, -1.0], [-2.0, 1.0, 0.0]])
    assert_real(ctx.student(p07.unskew, W), "unskew(skew((1, 2, 3)))", (3,))


@check(1, title="skew(w) @ x equals the cross product w × x on random vectors", stage=STAGE_RANDOM, group="skew")
def check_skew_values(ctx):
    ctx.compare_random(
        p07.skew, VECTORS.map(lambda w: (w,)), name="skew(w)", tol=EXACT,
        mistakes=lambda args, expected: [Mistake("sign_flip", -np.asarray(expected), SIGN_HINT)],
    )


@check(1, title="unskew inverts skew on random vectors", stage=STAGE_RANDOM, group="skew")
def check_unskew_values(ctx):
    ctx.compare_random(
        p07.unskew, VECTORS.map(lambda w: (skew(w),)), name="unskew(W)", tol=EXACT,
        mistakes=lambda args, expected: [
            Mistake("sign_flip", -np.asarray(expected), "The vector of W is (W[2, 1], W[0, 2], W[1, 0]): "
                    "you read the entries on the other side of the diagonal."),
        ],
    )


def _omega_mistakes(frame):
    def mistakes(args, expected):
        A, dA = (np.asarray(x) for x in args)
        other = A.T @ np.asarray(expected) if frame == "inertial" else A @ np.asarray(expected)
        name = "body" if frame == "inertial" else "inertial"
        formula = "skew(I_omega) = dA_IC @ A_CI" if frame == "inertial" else "skew(C_omega) = A_CI @ dA_IC"
        return [
            Mistake("wrong_frame", other, f"You returned the angular velocity in {name} coordinates. "
                    f"Here {formula}."),
            Mistake("sign_flip", -np.asarray(expected), "The product is in the wrong order or the vector is read "
                    "from the wrong side of the diagonal (that flips the sign)."),
        ]

    return mistakes


@check(2, title="omega_body(A_IC, dA_IC) = unskew(A_CI @ dA_IC) on random motions", stage=STAGE_RANDOM,
       group="omega_body")
def check_omega_body(ctx):
    ctx.compare_random(p07.omega_body, MOTIONS, name="C_omega_IC", tol=EXACT,
                       mistakes=_omega_mistakes("body"))


@check(1, title="omega_inertial(A_IC, dA_IC) = unskew(dA_IC @ A_CI) on random motions", stage=STAGE_RANDOM,
       group="omega_inertial")
def check_omega_inertial(ctx):
    ctx.compare_random(p07.omega_inertial, MOTIONS, name="I_omega_IC", tol=EXACT,
                       mistakes=_omega_mistakes("inertial"))


def _points(rng, n=4):
    names = ("alpha", "beta", "gamma", "alpha_dot", "beta_dot", "gamma_dot")
    return [dict(zip(names, map(float, rng.uniform(-2, 2, 6)))) for _ in range(n)]


@check(3, title="derive(): the symbolic A_IC1, A_IC2, A_IC3, A_C3I and C3_omega_IC3 evaluate to the right values",
       stage=STAGE_VALUES, group="symbolic")
def check_symbolic(ctx):
    points = ctx.draw(_points)
    expected = ctx.reference(p07.expressions, points)
    got = ctx.student(p07.symbolic, points, timeout=60)
    missing = [k for k in KEYS if k not in got]
    if missing:
        fail(f"derive() lacks the entries {missing} (it returned {sorted(got)}).")
    for key in KEYS:
        values = got[key]
        if not isinstance(values, list) or len(values) != len(points):
            fail(f"{key} could not be evaluated at the {len(points)} points (got {str(values)[:200]}).")
        for i, (point, g, e) in enumerate(zip(points, values, expected[key])):
            shape = np.shape(e)
            mistakes = []
            if key == "C3_omega_IC3":
                A = np.asarray(expected["A_IC3"][i])
                mistakes = [
                    Mistake("wrong_frame", (A @ np.ravel(e)).reshape(shape),
                            "This is the angular velocity in inertial coordinates: C3_omega comes from "
                            "A_C3I @ dA_IC3/dt, not dA_IC3/dt @ A_C3I."),
                    Mistake("sign_flip", -np.asarray(e), "Read the vector as (W[2,1], W[0,2], W[1,0])."),
                ]
            elif key != "A_C3I":
                mistakes = [Mistake("transpose", np.asarray(e).T, f"{key} is transposed (A_CI for A_IC).")]
            described = ", ".join(f"{k}={v:.4f}" for k, v in point.items())
            assert_close(np.reshape(g, np.shape(g)), e, key, SYMBOLIC, mistakes, context=f"at ({described})")


@check(1, title="the animation ends at the right orientation (100 Euler steps of the Cardan angles)",
       stage=STAGE_VALUES, group="animation")
def check_animation(ctx):
    def cardan(angles):
        return ctx.reference(p06.cardan, *(float(x) for x in angles))

    expected = ctx.reference(p07.animate)
    own = judged(ctx, p07.animate)  # the reference's animation with the student's cardan (problem 6)
    start = np.deg2rad(START_DEG)
    mistakes = [
        Mistake("step_count", cardan(start + np.pi * (1 + 1 / 100)),
                "One step too many: run exactly n = 100 steps of dt = pi / n."),
        Mistake("step_count", cardan(start + np.pi * (1 - 1 / 100)),
                "One step too few: run exactly n = 100 steps of dt = pi / n."),
        Mistake("degrees", cardan(np.deg2rad(np.asarray(START_DEG) + np.pi)),
                "The angles and the step are in radians: add dt = pi / n to angles in radians."),
    ]
    got = ctx.student(p07.animate)
    if not isinstance(got, dict) or "A_IC3" not in got:
        fail("animate() must return a dict with the entries 'angles' and 'A_IC3'.")
    add_frames(ctx, "Problem 7: the frame C3 at the end of the animation", got, expected, ("A_IC3",), ["C3 at t = pi"])
    A = assert_rotation(got["A_IC3"], "A_IC3")
    assert_close_judged(ctx, A, expected["A_IC3"], own, "A_IC3 at t = pi", EXACT, mistakes, pick=lambda v: v["A_IC3"])


# ------------------------------------------------------------------------------------ side effects


@check(1, title="skew, unskew, omega_body and omega_inertial leave their arguments unchanged, return a new array on "
       "every call and keep no state", stage=STAGE_RANDOM + 1, group="skew")
def check_side_effects(ctx):
    A, dA = _rotation_and_rate(_SIDE_A, np.array([0.3, -1.2, 0.8]))
    B, dB = _rotation_and_rate(_SIDE_A.T, np.array([-0.7, 0.1, 2.0]))
    assert_no_side_effects(ctx, "rotations", "skew", [np.array([0.5, -1.0, 2.0])], [np.array([1.5, 0.2, -0.3])],
                           ("w",))
    assert_no_side_effects(ctx, "rotations", "unskew", [skew(np.array([0.5, -1.0, 2.0]))],
                           [skew(np.array([1.5, 0.2, -0.3]))], ("W",))
    for function in ("omega_body", "omega_inertial"):
        assert_no_side_effects(ctx, "rotations", function, [A, dA], [B, dB], ("A_IC", "dA_IC"))
