"""Checks of problem 11: bound coordinate systems and bound vectors, driven through their setters."""

import numpy as np

from checks._rigid import ROTATIONS, compact, vectors
from grader import strategies as st
from grader.checking import EXACT, STAGE_RANDOM, STAGE_VALUES, Mistake, assert_close, check, fail
from probes import problem_11 as p11

TITLE = "Bound Vectors and Coordinate Systems"

TRANSPOSE_HINT = ("A_IC maps C-coordinates to I-coordinates (I_v = A_IC @ C_v); its transpose A_IC.T maps I to C. "
                  "You used one for the other.")
OFFSET_HINT = ("The offset C_r_CO of a bound vector is in C-components: its start point in I is I_r_IC + A_IC @ "
               "C_r_CO (rotated into I before it is added).")
KEYS_SOLVE = ("I_v", "I_r_IO", "I_coords", "C_coords")


def _dict(got, keys, what):
    if not isinstance(got, dict) or any(k not in got for k in keys):
        fail(f"{what} must give the entries {list(keys)}, got {str(got)[:200]}")
    return got


def _assert_entries(got, expected, keys, mistakes, what):
    _dict(got, keys, what)
    for key in keys:
        assert_close(got[key], expected[key], key, EXACT, mistakes.get(key, ()), context=what)


@check(2, title="the test file's vector (C = R3(30°) at (1, 2, 0), C_v = (0, -2, 0) from C_r_CO = (1, 0, 0)) in I "
       "and in C", stage=STAGE_VALUES, group="test_values")
def check_test_values(ctx):
    test = ctx.reference(p11.test_objects)
    A_IC, I_r_IC, C_v, C_r_CO = (test[k] for k in ("A_IC", "I_r_IC", "C_v", "C_r_CO"))
    mistakes = {
        "I_v": [Mistake("transpose", A_IC.T @ C_v, TRANSPOSE_HINT)],
        "I_r_IO": [Mistake("offset_not_rotated", I_r_IC + C_r_CO, OFFSET_HINT),
                   Mistake("transpose", I_r_IC + A_IC.T @ C_r_CO, TRANSPOSE_HINT)],
        "C_coords": [Mistake("transpose", A_IC @ A_IC @ C_v, TRANSPOSE_HINT + " get_coords(X) returns "
                             "X_v = A_IX.T @ I_v.")],
    }
    args = (A_IC, I_r_IC, C_v, C_r_CO)
    expected = ctx.reference(p11.vector, *args)
    _assert_entries(ctx.student(p11.vector, *args), expected, KEYS_SOLVE, mistakes,
                    "(the test file's values)")


#: a fixed example (A_IC, I_r_IC, C_v, C_r_CO, A_new, I_r_new), run before the random ones
EXAMPLE_MOVE = (np.eye(3), np.array([1.0, 2.0, 0.0]), np.array([0.0, -2.0, 0.0]), np.array([1.0, 0.0, 0.0]),
                np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]), np.array([0.5, 0.0, 1.0]))
MOVES = st.tuples(ROTATIONS, vectors(3.0), vectors(2.0), vectors(2.0), ROTATIONS, vectors(3.0))


def _moved_mistakes(args):
    A_IC, I_r_IC, C_v, C_r_CO, A_new, I_r_new = args
    return {
        "A_IC": [Mistake("transpose", A_new.T, "set_transform stores A_IC as given: " + TRANSPOSE_HINT)],
        "I_r_IC": [Mistake("offset_frame", A_new.T @ I_r_new, "The offset of a BoundCoSys is given in INERTIAL "
                           "components: store I_r_IC as it is, without transforming it.")],
        "I_v": [Mistake("transpose", A_new.T @ C_v, TRANSPOSE_HINT),
                Mistake("stale", A_IC @ C_v, "The vector must move with its coordinate system: compute I_v from "
                        "C.A_IC when asked, do not store the inertial value.")],
        "I_r_IO": [Mistake("offset_not_rotated", I_r_new + C_r_CO, OFFSET_HINT)],
    }


@check(2, title="set_transform and set_offset move C, and its bound vector moves with it (random values)",
       stage=STAGE_RANDOM, group="setters")
def check_moves_with_cosys(ctx):
    def compare(got, expected, args):
        _assert_entries(got, expected, ("A_IC", "I_r_IC", "I_v", "I_r_IO"), _moved_mistakes(args),
                        "after C.set_transform(A_new) and C.set_offset(I_r_new)")

    ctx.student(p11.moved, *EXAMPLE_MOVE)
    ctx.compare_random(
        p11.moved, MOVES, name="the moved vector", tol=EXACT, compare=compare, examples=10,
        describe=lambda a: "A_IC = {}, I_r_IC = {}, C_v = {}, C_r_CO = {}, A_new = {}, I_r_new = {}".format(
            *map(compact, a)),
    )


SETS = st.tuples(ROTATIONS, vectors(3.0), ROTATIONS, vectors(2.0), vectors(2.0))


def _set_mistakes(args):
    A_IC, _, A_IX, X_v, X_r = args
    ignored = ("The components are given in the coordinate system X: convert them to C first, "
               "C_v = A_IC.T @ A_IX @ X_v.")
    own = ("Without a coordinate system X, set_vector(v) and set_offset(r) take components in C itself: store "
           "them as they are, C_v = v.")
    return {
        "C_v_own": [Mistake("wrong_frame", A_IC.T @ X_v, own)],
        "C_r_CO_own": [Mistake("wrong_frame", A_IC.T @ X_r, own)],
        "C_v": [Mistake("ignored_frame", X_v, ignored),
                Mistake("transpose", A_IX.T @ A_IC @ X_v, TRANSPOSE_HINT + " C_v = A_CI @ A_IX @ X_v = "
                        "A_IC.T @ A_IX @ X_v.")],
        "C_r_CO": [Mistake("ignored_frame", X_r, ignored),
                   Mistake("transpose", A_IX.T @ A_IC @ X_r, TRANSPOSE_HINT + " C_r_CO = A_IC.T @ A_IX @ X_r.")],
    }


@check(2, title="set_vector(v, X) and set_offset(r, X) take components in another coordinate system X, and in C "
       "itself without X (random values)", stage=STAGE_RANDOM, group="set_in_other_frame")
def check_set_in_other_frame(ctx):
    def compare(got, expected, args):
        _assert_entries(got, expected, ("C_v", "C_r_CO", "I_v", "I_r_IO"), _set_mistakes(args),
                        "after v.set_vector(X_v, X) and v.set_offset(X_r, X)")
        _assert_entries(got, expected, ("C_v_own", "C_r_CO_own"), _set_mistakes(args),
                        "after w.set_vector(X_v) and w.set_offset(X_r), without X")

    ctx.student(p11.set_in, EXAMPLE_MOVE[0], EXAMPLE_MOVE[1], *EXAMPLE_MOVE[4:], EXAMPLE_MOVE[2])
    ctx.compare_random(
        p11.set_in, SETS, name="the vector set in X", tol=EXACT, compare=compare, examples=10,
        describe=lambda a: "A_IC = {}, I_r_IC = {}, A_IX = {}, X_v = {}, X_r = {}".format(*map(compact, a)),
    )


COORDS = st.tuples(ROTATIONS, vectors(3.0), ROTATIONS)


@check(1, title="get_coords(X) = A_IX.T @ I_v, and get_coords() the components in C (random values)",
       stage=STAGE_RANDOM, group="get_coords")
def check_get_coords(ctx):
    def compare(got, expected, args):
        A_IC, C_v, A_IX = args
        mistakes = {"X_v": [Mistake("transpose", A_IX @ A_IC @ C_v, TRANSPOSE_HINT + " X_v = A_IX.T @ I_v.")],
                    "C_v": [Mistake("wrong_frame", A_IC @ C_v, "Without an argument get_coords() returns the "
                                    "components in C itself, i.e. C_v.")]}
        _assert_entries(got, expected, ("X_v", "C_v"), mistakes, "(v.get_coords(X) and v.get_coords())")

    ctx.student(p11.coords, EXAMPLE_MOVE[0], EXAMPLE_MOVE[2], EXAMPLE_MOVE[4])
    ctx.compare_random(
        p11.coords, COORDS, name="get_coords", tol=EXACT, compare=compare, examples=10,
        describe=lambda a: "A_IC = {}, C_v = {}, A_IX = {}".format(*map(compact, a)),
    )
