"""Checks of problem 6: elementary rotations and the Cardan (yaw-pitch-roll) sequence."""

import numpy as np

from checks._effects import assert_no_side_effects
from checks._figures import add_frames, add_vectors
from checks._real import assert_real, is_real, require_real, rotation_flaw
from grader import strategies as st
from grader.errors import StudentFault
from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_SHAPE,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    STRUCTURE,
    CheckFailure,
    Mistake,
    as_array,
    assert_close,
    assert_rotation,
    check,
    close,
    fail,
    format_array,
)
from probes import problem_06 as p06

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
        return ctx.reference(p06.elementary, k, x)

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
        return ctx.reference(p06.elementary, k, x)

    a, b, g = args
    angles = {3: g, 2: b, 1: a}  # the factors in the order of the product
    factors = {k: R(k, x) for k, x in angles.items()}

    def one_factor(axis, replaced):
        """The product with the factor about ``axis`` replaced (one wrong elementary rotation inside cardan)."""
        product = np.eye(3)
        for k, factor in factors.items():
            product = product @ (replaced if k == axis else factor)
        return product

    return [
        Mistake("transpose", np.asarray(expected).T, TRANSPOSE_HINT),
        *[Mistake("transpose", one_factor(axis, factors[axis].T),
                  f"One factor of your product is transposed: the rotation about the {axis}-axis enters as A_CI "
                  f"instead of A_IC (its -sin on the wrong side of the diagonal). Build cardan from R1, R2, R3.")
          for axis in AXES],
        *[Mistake("degrees", one_factor(axis, R(axis, float(np.deg2rad(angles[axis])))),
                  f"The rotation about the {axis}-axis inside your product treats its angle as degrees: "
                  + DEGREES_HINT) for axis in AXES],
        Mistake(
            "rotation_order",
            R(1, a) @ R(2, b) @ R(3, g),
            "The rotations are multiplied in the wrong order: the Cardan sequence is yaw about 3 first, then "
            "pitch about the NEW 2-axis, then roll about the NEWEST 1-axis: A_IC3 = R3(gamma) @ R2(beta) @ "
            "R1(alpha).",
        ),
        Mistake("argument_order", ctx.reference(p06.cardan, g, b, a),
                "alpha and gamma are swapped: the signature is cardan(alpha, beta, gamma), alpha being the roll."),
        Mistake("degrees", ctx.reference(p06.cardan, *(float(x) for x in np.deg2rad([a, b, g]))),
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
        assert_real(ctx.student(p06.elementary, axis, 0.3), f"R{axis}(0.3)", (3, 3))


@check(1, title="R1, R2, R3 are proper rotations (orthonormal, det = +1)", stage=STAGE_STRUCTURE,
       group="elementary")
def check_elementary_rotation(ctx):
    for axis in AXES:
        for angle in (0.3, -2.0):
            A = assert_rotation(ctx.student(p06.elementary, axis, angle), f"R{axis}({angle})")
            assert_turns(A, f"R{axis}({angle})")


@check(2, title="R1, R2, R3 equal the elementary rotations on random angles", stage=STAGE_RANDOM,
       group="elementary")
def check_elementary_values(ctx):
    for axis in AXES:
        ctx.compare_random(
            p06.elementary,
            ANGLES.map(lambda angle, axis=axis: (axis, angle)),
            name=f"R{axis}",
            tol=EXACT,
            mistakes=lambda args, expected: _elementary_mistakes(ctx, args[0], args[1], expected),
            describe=lambda args: f"R{args[0]}({args[1]!r})",
        )


# ------------------------------------------------------------------------------------ error carried forward

#: the checks that grade the upstream results later checks are judged on
ELEMENTARY = "p06.elementary_values"
CARDAN = "p06.cardan_values"
FRAMES = "p06.frames"
KEYS = ("A_IC1", "A_IC2", "A_IC3")


def _own_factors(got, expected):
    """The student's own ``R1, R2, R3`` at the input (a dict), when all are there and one differs from the
    reference's; else None (then there is nothing to carry forward)."""
    own = {k: got.get(k) for k in ("R1", "R2", "R3")}
    if any(v is None for v in own.values()):
        return None
    if all(close(own[k], expected[k], EXACT) for k in own):
        return None
    return {k: np.asarray(v, dtype=float) for k, v in own.items()}


def _factor_findings(own, expected, args):
    """Whether the student's own ``R1(alpha), R2(beta), R3(gamma)`` are real rotations (``checks._real``): an
    answer that does nothing (zeros, a constant, the identity) leaves nothing to carry forward."""
    return [(f"R{k}({angle:.6g})", rotation_flaw(own[f"R{k}"], expected[f"R{k}"]))
            for k, angle in zip((1, 2, 3), args)]


def _frame_findings(own, expected):
    """Whether the student's own frames ``{key: A}`` are real rotations, against the reference's ``expected``."""
    return [(key, rotation_flaw(own[key], expected[key])) for key in KEYS]


def _own_cardan_mistakes(own):
    return [
        Mistake("rotation_order", own["R1"] @ own["R2"] @ own["R3"],
                "Your factors are multiplied in the wrong order: the Cardan sequence is yaw about 3 first, then "
                "pitch about the NEW 2-axis, then roll about the NEWEST 1-axis: A_IC3 = R3(gamma) @ R2(beta) @ "
                "R1(alpha)."),
        Mistake("transpose", (own["R3"] @ own["R2"] @ own["R1"]).T, TRANSPOSE_HINT),
    ]


def _carried_structure(got, own):
    """True when ``got`` is the product of the student's own factors, which differ from the reference's: its
    structure is then judged with theirs."""
    return own is not None and close(got, own["R3"] @ own["R2"] @ own["R1"], EXACT)


# ------------------------------------------------------------------------------------ Cardan sequence


@check(1, title="cardan(alpha, beta, gamma) is a proper rotation", stage=STAGE_STRUCTURE, group="cardan")
def check_cardan_rotation(ctx):
    args = (0.4, -0.3, 1.1)
    expected = ctx.reference(p06.cardan_with_factors, *args)
    got = ctx.student(p06.cardan_with_factors, *args)
    name = "cardan(0.4, -0.3, 1.1)"
    A = as_array(got["cardan"], name, (3, 3))
    try:
        assert_rotation(A, name)
        assert_turns(A, name)
    except CheckFailure:
        own = _own_factors(got, expected)
        if not _carried_structure(A, own):
            raise
        require_real(name, "R1, R2, R3", _factor_findings(own, expected, args))
        ctx.carry_forward(ELEMENTARY, "R1, R2, R3")


@check(2, title="cardan(alpha, beta, gamma) = R3(gamma) R2(beta) R1(alpha) on random angles",
       stage=STAGE_RANDOM, group="cardan")
def check_cardan_values(ctx):
    name = "cardan(alpha, beta, gamma)"

    def compare(got, expected, args):
        catalogue = _cardan_mistakes(ctx, args, expected["cardan"])  # the reference's calls, made eagerly
        A = as_array(got["cardan"], name, (3, 3))
        if close(A, expected["cardan"], EXACT):
            return
        own = _own_factors(got, expected)
        findings = [] if own is None else _factor_findings(own, expected, args)
        product = None if own is None else own["R3"] @ own["R2"] @ own["R1"]
        if product is not None and close(A, product, EXACT):
            require_real(name, "R1, R2, R3", findings)
            ctx.carry_forward(ELEMENTARY, "R1, R2, R3")
            return
        if own is None or not is_real(findings):  # nothing of theirs to judge it on
            assert_close(A, expected["cardan"], name, EXACT, catalogue)
            return
        assert_close(A, product, name, EXACT, _own_cardan_mistakes(own) + catalogue,
                     context="(judged on your own R1, R2, R3: R3(gamma) @ R2(beta) @ R1(alpha))",
                     note="Your R1, R2, R3 differ from the reference's (their own check says how); cardan is judged "
                          "on them.")

    ctx.compare_random(
        p06.cardan_with_factors,
        st.tuples(ANGLES, ANGLES, ANGLES),
        name=name,
        tol=EXACT,
        compare=compare,
        describe=lambda args: "cardan(alpha={!r}, beta={!r}, gamma={!r})".format(*args),
    )


# ------------------------------------------------------------------------------------ the sheet's numbers


def _own_frames(got, expected, args):
    """The frames the student's own upstream functions give at the sheet's angles ``args = (alpha, beta, gamma)``,
    each with the check that grades them and whether what they are built from is real:
    ``[(check id, what, {key: A}, findings)]``, only those that differ from the reference's frames."""
    candidates = []
    own = _own_factors(got, expected)
    if own is not None:
        A1 = own["R3"]
        candidates.append((ELEMENTARY, "R1, R2, R3", {"A_IC1": A1, "A_IC2": A1 @ own["R2"],
                                                     "A_IC3": A1 @ own["R2"] @ own["R1"]},
                           _factor_findings(own, expected, args)))
    cardan = got.get("cardan") or [None] * 3
    if all(c is not None for c in cardan):
        partial = dict(zip(KEYS, (np.asarray(c, dtype=float) for c in cardan)))
        if not all(close(partial[k], expected["frames"][k], EXACT) for k in KEYS):
            findings = [(f"cardan{sequence}", rotation_flaw(partial[key], expected["frames"][key]))
                        for key, sequence in zip(KEYS, ("(0, 0, gamma)", "(0, beta, gamma)", "(alpha, beta, gamma)"))]
            candidates.append((CARDAN, "cardan", partial, findings))
    return candidates


@check(1, title="the frames C1, C2, C3 of the sheet (gamma = 30, beta = 45, alpha = 60 deg)",
       stage=STAGE_VALUES, group="sheet")
def check_frames(ctx):
    def R(k, x):
        return ctx.reference(p06.elementary, k, x)

    g, b, a = (float(x) for x in np.deg2rad(SHEET_ANGLES_DEG))
    reference = ctx.reference(p06.frames_with_factors, a, b, g)
    expected = reference["frames"]
    wrong_order = {"A_IC1": R(3, g), "A_IC2": R(2, b) @ R(3, g), "A_IC3": R(1, a) @ R(2, b) @ R(3, g)}
    degrees = {"A_IC1": R(3, SHEET_ANGLES_DEG[0])}
    degrees["A_IC2"] = degrees["A_IC1"] @ R(2, SHEET_ANGLES_DEG[1])
    degrees["A_IC3"] = degrees["A_IC2"] @ R(1, SHEET_ANGLES_DEG[2])
    got = ctx.student(p06.frames)
    add_frames(ctx, "Problem 6: the frames C1, C2, C3 in I", got, expected, KEYS)
    if not isinstance(got, dict):
        fail(f"frames() must return a dict with keys A_IC1, A_IC2, A_IC3, got {type(got).__name__}.")
    for key in KEYS:
        if key not in got:
            fail(f"frames() has no entry {key!r} (keys: {sorted(got)}).")
    frames = {key: as_array(got[key], key, (3, 3)) for key in KEYS}
    if all(close(frames[key], expected[key], EXACT) for key in KEYS):
        return
    try:  # asked only now: frames() passes or fails on its own, whatever a crash of cardan would do
        answer = ctx.student(p06.frames_with_factors, a, b, g)
    except StudentFault:  # R1..R3 or cardan crashed the worker or ran out of time: nothing to carry forward
        answer = {}
    explained = [(upstream, what, findings)
                 for upstream, what, own, findings in _own_frames(answer, reference, (a, b, g))
                 if all(close(frames[key], own[key], EXACT) for key in KEYS)]
    for upstream, what, findings in explained:
        if is_real(findings):
            ctx.carry_forward(upstream, what)
            return
    for upstream, what, findings in explained:
        require_real("frames()", what, findings)
    for key in KEYS:
        A = assert_rotation(frames[key], key)
        assert_close(A, expected[key], key, EXACT, [
            Mistake("transpose", np.asarray(expected[key]).T, TRANSPOSE_HINT),
            Mistake("rotation_order", wrong_order[key],
                    "Each new rotation multiplies from the right (about the NEW axes): "
                    "A_IC2 = A_IC1 @ A_C1C2, not A_C1C2 @ A_IC1."),
            Mistake("degrees", degrees[key], DEGREES_HINT + " np.deg2rad(30) is the angle to use."),
        ])


TYPED_HINT = (
    "These are the sheet's printed numbers (four decimals), not computed ones: compute the coordinates from your "
    "frames (I_v = A_IC3 @ C3_v, Ck_v = A_ICk.T @ I_v); they are compared at full precision."
)


def _vector_mistakes(A, v, key):
    """The known mistakes of the coordinates ``key`` of V, with the frames ``A`` (the reference's or the
    student's own)."""
    I_v = A["A_IC3"] @ v
    return {
        "I_v": [Mistake("transpose", A["A_IC3"].T @ v,
                        "You used A_C3I instead of A_IC3: I_v = A_IC3 @ C3_v maps C3-coordinates to I.")],
        "C1_v": [Mistake("transpose", A["A_IC1"] @ I_v,
                         "C1_v = A_C1I @ I_v with A_C1I = A_IC1.T: did you multiply by A_IC1 instead?")],
        "C2_v": [Mistake("transpose", A["A_IC2"] @ I_v,
                         "C2_v = A_C2I @ I_v with A_C2I = A_IC2.T: did you multiply by A_IC2 instead?")],
        "C3_v": [],
    }[key]


def _vectors_of(A, v):
    I_v = A["A_IC3"] @ v
    return {"I_v": I_v, "C1_v": A["A_IC1"].T @ I_v, "C2_v": A["A_IC2"].T @ I_v, "C3_v": v}


@check(1, title="the coordinates of V in I, C1, C2, C3 (the sheet's values, at full precision)",
       stage=STAGE_VALUES, group="sheet")
def check_vectors(ctx):
    reference = ctx.reference(p06.vectors_with_frames)
    expected = {key: np.asarray(reference["vectors"][key], dtype=float) for key in SHEET_VECTORS}
    frames = {key: np.asarray(reference["frames"][key], dtype=float) for key in KEYS}
    v = np.ones(3)
    answer = ctx.student(p06.vectors_with_frames)
    got = answer["vectors"]
    add_vectors(ctx, "Problem 6: V from its coordinates in I, C1, C2, C3 (mapped to I)", got, frames,
                SHEET_VECTORS["I_v"])
    if not isinstance(got, dict):
        fail(f"vectors() must return a dict with keys {sorted(SHEET_VECTORS)}, got {type(got).__name__}.")
    for key in SHEET_VECTORS:
        if key not in got:
            fail(f"vectors() has no entry {key!r} (keys: {sorted(got)}).")
    vectors = {key: as_array(got[key], key, (3,)) for key in SHEET_VECTORS}
    if all(close(vectors[key], expected[key], EXACT) for key in SHEET_VECTORS):
        return
    own_frames = answer["frames"]
    if own_frames is not None and all(own_frames[key] is not None for key in KEYS):
        own_frames = {key: np.asarray(own_frames[key], dtype=float) for key in KEYS}
        if not all(close(own_frames[key], frames[key], EXACT) for key in KEYS):
            findings = _frame_findings(own_frames, frames)
            own = _vectors_of(own_frames, v)
            if all(close(vectors[key], own[key], EXACT) for key in SHEET_VECTORS):
                require_real("vectors()", "frames A_IC1, A_IC2, A_IC3", findings)
                ctx.carry_forward(FRAMES, "frames A_IC1, A_IC2, A_IC3")
                return
            if is_real(findings):  # else nothing of theirs to judge the coordinates on
                for key in SHEET_VECTORS:
                    assert_close(vectors[key], own[key], key, EXACT, _vector_mistakes(own_frames, v, key),
                                 context="(judged on your own frames)",
                                 note="Your frames differ from the reference's (their own check says how); the "
                                      "coordinates are judged on them.")
    for key, target in SHEET_VECTORS.items():
        typed = [Mistake("typed_numbers", target, TYPED_HINT)] if key != "C3_v" else []
        assert_close(vectors[key], expected[key], key, EXACT, typed + _vector_mistakes(frames, v, key),
                     context="(the sheet's value at full precision)")


# ------------------------------------------------------------------------------------ side effects


#: side effects are credited after the values (same group): a function that does nothing earns nothing for it
STAGE_AFTER_VALUES = STAGE_RANDOM + 1


@check(1, title="R1, R2, R3 and cardan keep no state: called again with the same angles, they give the same matrix",
       stage=STAGE_AFTER_VALUES, group="elementary")
def check_side_effects(ctx):
    for axis in AXES:
        assert_no_side_effects(ctx, "rotations", f"R{axis}", [0.3], [-1.1], ("angle",))
    assert_no_side_effects(ctx, "rotations", "cardan", [0.4, -0.3, 1.1], [1.0, 0.2, -0.5],
                           ("alpha", "beta", "gamma"))
