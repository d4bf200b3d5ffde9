"""Checks of problem 6: elementary rotations and the Cardan (yaw-pitch-roll) sequence."""

import numpy as np

from checks._figures import add_frames, add_vectors
from grader import strategies as st
from grader.checking import (
    EXACT,
    SHEET,
    STAGE_RANDOM,
    STAGE_SHAPE,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    STRUCTURE,
    Mistake,
    as_array,
    assert_close,
    assert_rotation,
    check,
    close,
    fail,
    format_array,
)

TITLE = "Euler angles, Tait-Bryan/Cardan convention"

ANGLES = st.floats(-np.pi, np.pi, allow_nan=False, allow_infinity=False)
#: the sheet's targets (problem data, with the erratum on the C2 label)
SHEET_VECTORS = {
    "I_v": (1.6319, 0.5195, 0.2588),
    "C1_v": (1.6730, -0.3660, 0.2588),
    "C2_v": (1.0, -0.3660, 1.3660),
    "C3_v": (1.0, 1.0, 1.0),
}
AXES = (1, 2, 3)
#: the sheet's yaw gamma, pitch beta and roll alpha [deg]
SHEET_ANGLES_DEG = (30.0, 45.0, 60.0)

TRANSPOSE_HINT = (
    "Your matrix is the transpose of the expected one: it maps the original frame to the rotated frame "
    "(A_CI instead of A_IC). In R1, R2, R3 the -sin sits above the diagonal for the 1- and 3-axis, below it "
    "for the 2-axis."
)
DEGREES_HINT = "The angles are in radians: did you treat them as degrees (np.deg2rad inside the function)?"


def _elementary_mistakes(ctx, axis, angle, expected):
    def R(k, x):
        return ctx.reference("problem_06.elementary", k, x)

    return [
        Mistake("transpose", np.asarray(expected).T, TRANSPOSE_HINT + " (A sign flip of the angle gives the same.)"),
        Mistake("degrees", R(axis, float(np.deg2rad(angle))), DEGREES_HINT),
        *[
            Mistake("wrong_axis", R(other, angle), f"This is the rotation about another axis: R{axis} turns about "
                    f"the {axis}-axis, which stays fixed (row and column {axis} are those of the identity).")
            for other in AXES if other != axis
        ],
    ]


def _cardan_mistakes(ctx, args, expected):
    def R(k, x):
        return ctx.reference("problem_06.elementary", k, x)

    a, b, g = args
    return [
        Mistake("transpose", np.asarray(expected).T, TRANSPOSE_HINT),
        Mistake(
            "rotation_order",
            R(1, a) @ R(2, b) @ R(3, g),
            "The rotations are multiplied in the wrong order: the Cardan sequence is yaw about 3 first, then "
            "pitch about the NEW 2-axis, then roll about the NEWEST 1-axis: A_IC3 = R3(gamma) @ R2(beta) @ "
            "R1(alpha).",
        ),
        Mistake("argument_order", ctx.reference("problem_06.cardan", g, b, a),
                "alpha and gamma are swapped: the signature is cardan(alpha, beta, gamma), alpha being the roll."),
        Mistake("degrees", ctx.reference("problem_06.cardan", *(float(x) for x in np.deg2rad([a, b, g]))),
                DEGREES_HINT),
    ]


def assert_turns(A, name):
    """Fail when the rotation ``A`` (by a non-zero angle) is the identity: it does not turn anything."""
    if close(A, np.eye(3), STRUCTURE):
        fail(f"{name} is the identity matrix: it does not rotate, although the angle is not zero.\n"
             f"got:\n{format_array(A)}",
             "A rotation by a non-zero angle changes the coordinates of every vector off its axis: compute the "
             "matrix from the angle (cos and sin of it) instead of returning the identity.", "identity")


# ------------------------------------------------------------------------------------ elementary rotations


@check(1, title="R1, R2, R3 return 3 x 3 numeric matrices", stage=STAGE_SHAPE, group="elementary")
def check_elementary_shape(ctx):
    for axis in AXES:
        as_array(ctx.student("problem_06.elementary", axis, 0.3), f"R{axis}(0.3)", (3, 3))


@check(1, title="R1, R2, R3 are proper rotations (orthonormal, det = +1)", stage=STAGE_STRUCTURE,
       group="elementary")
def check_elementary_rotation(ctx):
    for axis in AXES:
        for angle in (0.3, -2.0):
            A = assert_rotation(ctx.student("problem_06.elementary", axis, angle), f"R{axis}({angle})")
            assert_turns(A, f"R{axis}({angle})")


@check(2, title="R1, R2, R3 equal the elementary rotations on random angles", stage=STAGE_RANDOM,
       group="elementary")
def check_elementary_values(ctx):
    for axis in AXES:
        ctx.compare_random(
            "problem_06.elementary",
            ANGLES.map(lambda angle, axis=axis: (axis, angle)),
            name=f"R{axis}",
            tol=EXACT,
            mistakes=lambda args, expected: _elementary_mistakes(ctx, args[0], args[1], expected),
            describe=lambda args: f"R{args[0]}({args[1]!r})",
        )


# ------------------------------------------------------------------------------------ Cardan sequence


@check(1, title="cardan(alpha, beta, gamma) is a proper rotation", stage=STAGE_STRUCTURE, group="cardan")
def check_cardan_rotation(ctx):
    A = assert_rotation(ctx.student("problem_06.cardan", 0.4, -0.3, 1.1), "cardan(0.4, -0.3, 1.1)")
    assert_turns(A, "cardan(0.4, -0.3, 1.1)")


@check(2, title="cardan(alpha, beta, gamma) = R3(gamma) R2(beta) R1(alpha) on random angles",
       stage=STAGE_RANDOM, group="cardan")
def check_cardan_values(ctx):
    ctx.compare_random(
        "problem_06.cardan",
        st.tuples(ANGLES, ANGLES, ANGLES),
        name="cardan(alpha, beta, gamma)",
        tol=EXACT,
        mistakes=lambda args, expected: _cardan_mistakes(ctx, args, expected),
        describe=lambda args: "cardan(alpha={!r}, beta={!r}, gamma={!r})".format(*args),
    )


# ------------------------------------------------------------------------------------ the sheet's numbers


@check(1, title="the frames C1, C2, C3 of the sheet (gamma = 30, beta = 45, alpha = 60 deg)",
       stage=STAGE_VALUES, group="sheet")
def check_frames(ctx):
    def R(k, x):
        return ctx.reference("problem_06.elementary", k, x)

    expected = ctx.reference("problem_06.frames")
    g, b, a = (float(x) for x in np.deg2rad(SHEET_ANGLES_DEG))
    wrong_order = {"A_IC1": R(3, g), "A_IC2": R(2, b) @ R(3, g), "A_IC3": R(1, a) @ R(2, b) @ R(3, g)}
    degrees = {"A_IC1": R(3, SHEET_ANGLES_DEG[0])}
    degrees["A_IC2"] = degrees["A_IC1"] @ R(2, SHEET_ANGLES_DEG[1])
    degrees["A_IC3"] = degrees["A_IC2"] @ R(1, SHEET_ANGLES_DEG[2])
    got = ctx.student("problem_06.frames")
    add_frames(ctx, "Problem 6: the frames C1, C2, C3 in I", got, expected, ("A_IC1", "A_IC2", "A_IC3"))
    if not isinstance(got, dict):
        fail(f"frames() must return a dict with keys A_IC1, A_IC2, A_IC3, got {type(got).__name__}.")
    for key in ("A_IC1", "A_IC2", "A_IC3"):
        if key not in got:
            fail(f"frames() has no entry {key!r} (keys: {sorted(got)}).")
        A = assert_rotation(got[key], key)
        assert_close(A, expected[key], key, EXACT, [
            Mistake("transpose", np.asarray(expected[key]).T, TRANSPOSE_HINT),
            Mistake("rotation_order", wrong_order[key],
                    "Each new rotation multiplies from the right (about the NEW axes): "
                    "A_IC2 = A_IC1 @ A_C1C2, not A_C1C2 @ A_IC1."),
            Mistake("degrees", degrees[key], DEGREES_HINT + " np.deg2rad(30) is the angle to use."),
        ])


@check(2, title="the coordinates of V in I, C1, C2, C3 match the sheet", stage=STAGE_VALUES, group="sheet")
def check_vectors(ctx):
    A = ctx.reference("problem_06.frames")
    v = np.ones(3)
    mistakes = {
        "I_v": [Mistake("transpose", A["A_IC3"].T @ v,
                        "You used A_C3I instead of A_IC3: I_v = A_IC3 @ C3_v maps C3-coordinates to I.")],
        "C1_v": [Mistake("transpose", A["A_IC1"] @ (A["A_IC3"] @ v),
                         "C1_v = A_C1I @ I_v with A_C1I = A_IC1.T: did you multiply by A_IC1 instead?")],
        "C2_v": [Mistake("transpose", A["A_IC2"] @ (A["A_IC3"] @ v),
                         "C2_v = A_C2I @ I_v with A_C2I = A_IC2.T: did you multiply by A_IC2 instead?")],
        "C3_v": [],
    }
    got = ctx.student("problem_06.vectors")
    add_vectors(ctx, "Problem 6: V from its coordinates in I, C1, C2, C3 (mapped to I)", got, A, SHEET_VECTORS["I_v"])
    if not isinstance(got, dict):
        fail(f"vectors() must return a dict with keys {sorted(SHEET_VECTORS)}, got {type(got).__name__}.")
    for key, target in SHEET_VECTORS.items():
        if key not in got:
            fail(f"vectors() has no entry {key!r} (keys: {sorted(got)}).")
        assert_close(got[key], target, key, SHEET, mistakes[key], context="(the sheet's value)")
