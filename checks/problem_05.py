"""Checks of problem 5: debugging a model.

MuJoCo refuses the broken model as Simscape did (a moving body without mass); the repaired model must load, keep
the bodies, joints and the link of the broken one, and add only a small mass with a small inertia.  The
description of the error, its fix and the question of energy are read and scored by hand.
"""

import numpy as np

from grader.checking import STAGE_DEFINED, STAGE_STRUCTURE, Tol, assert_close, check, fail
from probes import problem_05 as p05

from ._mujoco import POSITION, model_of, reference_of

TITLE = "Debugging a model"
MANUAL = {
    "error": ("5: Find and describe the error in the model (the sheet's Figure 7, BROKEN_MODEL). How would you "
              "fix it?", 2),
    "energy": ("5: Is this an energy-conserving system? Why?", 1),
}

#: the added mass may be at most this fraction of the link's
SMALL = 0.1
SAME = Tol("the link as in the broken model", 1e-9, 1e-6)


def _configuration(rng):
    """A configuration of the model's joints (the hinge's angle, the ball joint's unit quaternion), drawn anew at
    each grading: what the model declares there is asked of no key."""
    quaternion = rng.normal(size=4)
    return [float(rng.uniform(-np.pi, np.pi)), *(float(x) for x in quaternion / np.linalg.norm(quaternion))]


@check(1, title="fixed_model() loads in MuJoCo", stage=STAGE_DEFINED, group="fixed")
def check_fixed_loads(ctx):
    model_of(ctx.student(p05.fixed, ctx.draw(_configuration)), "fixed_model()")


@check(2, title="fixed_model() keeps the broken model's joints and link, and adds only a small mass and inertia (at "
       "most a tenth of the link's) where they were missing", stage=STAGE_STRUCTURE, group="fixed")
def check_fixed_minimal(ctx):
    qpos = ctx.draw(_configuration)
    got = model_of(ctx.student(p05.fixed, qpos), "fixed_model()")
    ref = reference_of(ctx.reference(p05.fixed, qpos), "fixed model")
    kinds, expected_kinds = [j["type"] for j in got["joints"]], [j["type"] for j in ref["joints"]]
    if kinds != expected_kinds:
        fail(f"fixed_model() has the joints {kinds}; the broken model has {expected_kinds}.",
             "Keep the revolute joint and the spherical joint: the error is not in the joints.", "joints_changed")
    link = ref["bodies"][int(ref["joints"][-1]["body"]) - 1]
    mine = got["bodies"][int(got["joints"][-1]["body"]) - 1]
    assert_close(mine["mass"], link["mass"], "the mass of the link (the body of the spherical joint)", SAME)
    assert_close(mine["com"], link["com"], "the centre of mass of the link", POSITION,
                 context=f"(at the joint configuration qpos = {np.round(qpos, 4).tolist()})")
    carrier = got["bodies"][int(got["joints"][0]["body"]) - 1]
    if not 0 < carrier["mass"] <= SMALL * link["mass"]:
        fail(f"the body of the revolute joint has a mass of {carrier['mass']:.3g} kg; a small mass, more than 0 and "
             f"at most {SMALL:g} of the link's {link['mass']:.3g} kg, repairs the model without changing its motion "
             "much.", "Give the massless body a small <inertial> (mass and diaginertia), or a small geom.",
             "mass_not_small")
    carrier_moment, link_moment = (float(np.max(np.linalg.eigvalsh(np.asarray(body["inertia"], dtype=float))))
                                   for body in (carrier, link))
    if carrier_moment > SMALL * link_moment:
        fail(f"the body of the revolute joint has a principal moment of inertia of {carrier_moment:.3g} kg m^2 about "
             f"its centre of mass; a small inertia, at most {SMALL:g} of the link's largest "
             f"{link_moment:.3g} kg m^2, repairs the model without changing its motion much.",
             "The added body turns with joint 1, so its inertia changes the motion as its mass does: keep it of the "
             "order of the added mass times its size squared (check the exponent of each diaginertia entry).",
             "inertia_not_small")
