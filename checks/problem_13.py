"""Checks of problem 13: a point T of the screw axis, found from the twist (v_B, omega).

Any point of the axis is correct: the checks test the defining properties of the student's T (its velocity is
parallel to omega) instead of comparing it with ours.  ``assert_screw`` is shared with problem 14.
"""

import numpy as np

from checks._rigid import STATES, describe_state
from grader import strategies as st
from grader.checking import STAGE_RANDOM, Mistake, Tol, as_array, assert_close, check
from probes import problem_13 as p13

TITLE = "Twists and Screw Axis"
MANUAL = {
    "choice_of_T": ("Establish a way to find a point T on the body that only moves along the axis of Omega. "
                    "This point is not unique: how did you select yours, and why?", 2),
}

#: the screw axis is computed in a few operations; omega is bounded away from zero
SCREW = Tol("screw axis", 1e-8, 1e-8)
ON_AXIS = ("T must lie on the screw axis. Any point of it is accepted: B_r_BT = (omega x v_B) / |omega|^2 "
           "+ s * omega for any s; its component perpendicular to omega is unique.")
ALONG_AXIS = ("T moves along the axis: B_v_T = v_B + omega x B_r_BT is parallel to omega (the projection of v_B "
              "onto omega, the same for every point of the axis).")
SIGN_HINT = "The cross product is in the wrong order: B_r_BT = (omega x v_B) / |omega|^2, not v_B x omega."
NORMALIZATION_HINT = ("Divide by |omega|^2 (omega @ omega), not by |omega| or not at all: "
                      "B_r_BT = (omega x v_B) / |omega|^2.")
VELOCITY_OF_B_HINT = ("B_v_T is the velocity of T, not of B: B_v_T = B_v_B + omega x B_r_BT, the projection of "
                      "v_B onto omega.")

ROTATING = STATES.filter(lambda s: np.linalg.norm(s["B_omega_B"]) > 0.1)


def assert_screw(screw, w, v, where=""):
    """Fail unless ``screw = (B_r_BT, B_v_T)`` puts T on the screw axis of the twist ``(v, w)`` with the velocity
    of T parallel to omega; a mistake of the catalogue names the diagnosis."""
    r, v_T = as_array(screw, "screw_axis()", (2, 3))
    w, v = np.asarray(w, dtype=float), np.asarray(v, dtype=float)
    w2 = float(w @ w)
    expected = np.cross(w, v) / w2
    assert_close(r - (r @ w) / w2 * w, expected, "the part of B_r_BT perpendicular to omega", SCREW, [
        Mistake("sign_flip", -expected, SIGN_HINT),
        Mistake("normalization", expected * w2, NORMALIZATION_HINT),
        Mistake("normalization", expected * np.sqrt(w2), NORMALIZATION_HINT),
    ], context=where, note=ON_AXIS)
    assert_close(v_T, (v @ w) / w2 * w, "B_v_T", SCREW, [Mistake("velocity_of_B", v, VELOCITY_OF_B_HINT)],
                 context=where, note=ALONG_AXIS)


@check(2, title="screw_axis() gives a point T on the screw axis whose velocity is parallel to omega (random "
       "twists)", stage=STAGE_RANDOM, group="screw_axis")
def check_screw_axis(ctx):
    from checks.problem_12 import GENERIC

    ctx.student(p13.screw, GENERIC)
    ctx.compare_random(
        p13.screw, st.tuples(ROTATING), name="screw_axis()", tol=SCREW, examples=15,
        compare=lambda got, expected, args: assert_screw(got, args[0]["B_omega_B"], args[0]["B_v_B"]),
        describe=lambda args: describe_state(args[0]),
    )
