"""Checks of problem 3: the double pendulum in MuJoCo, with inertia from the geometry (3a), custom inertia (3b) and
joint 1 driven at a constant rate (3c).

The custom inertia is compared with the reference's on random bricks; what each model declares is read by MuJoCo
inside the sandbox; the runs are compared with the reference's own ODE (scipy, independent of MuJoCo) only up to
the chaos horizon: the double pendulum is chaotic, and the reference's ODE started a milliradian off parts from
itself after about two seconds, so a comparison beyond that would test rounding, not the model.
"""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    STAGE_DEFINED,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    Mistake,
    Tol,
    assert_close,
    check,
    fail,
)
from probes import problem_03 as p03

from ._mujoco import (
    ALUMINIUM,
    DIRECTION,
    EARTH,
    HDPE,
    MOON,
    HEIGHT,
    LENGTH,
    MASS,
    POSITION,
    SAMPLE,
    WIDTH,
    assert_link_masses,
    body_of,
    compare_traces,
    hinges,
    integration_to_blame,
    model_of,
    run_as_sheet,
    run_of,
    stepped_otherwise,
    student_once,
    trace_figure,
)

TITLE = "A double pendulum in MuJoCo"
MANUAL = {
    "why_five_seconds": ("3: For 3(a) and 3(b) only the first five seconds of the output were given to compare the "
                         "solutions. Why not the full 10 seconds?", 1),
}

#: the runs: the sheet's five seconds (3a, 3b) and ten seconds of the driven pendulum (3c)
DURATION, DRIVEN_DURATION = 5.0, 10.0
#: 3(c): joint 1 turns at 1 rad/s
RATE = 1.0
#: the models are also built of another material and 3(c) for another rate: a model with HDPE's density or the
#: sheet's rate typed in would pass every check at the sheet's values
OTHER_DENSITY = ALUMINIUM
OTHER_RATE = 2.5
#: the model built for ``OTHER_RATE`` is run this long [s]
OTHER_RATE_DURATION = 1.0
ANGLE = Tol("angle, MuJoCo vs the reference's ODE", 0.05)
RATE_TOL = Tol("rate, MuJoCo vs the reference's ODE", 0.5)
#: 3(c): joint 1 follows q1 = t (a servo of kp = 1000 stays within 1e-4 rad)
DRIVEN = Tol("joint 1 on its prescribed motion", 0.01)
FINITE = dict(allow_nan=False, allow_infinity=False)
BRICKS = st.tuples(st.floats(0.05, 1.0, **FINITE), st.floats(0.005, 0.1, **FINITE), st.floats(0.005, 0.1, **FINITE),
                   st.floats(100.0, 10000.0, **FINITE))
VARIANTS = {"geometry": "3(a), inertia from the geometry", "custom": "3(b), custom inertia",
            "driven": "3(c), joint 1 driven"}


def _model(ctx, variant, gravity=EARTH, density=HDPE, rate=RATE):
    rate = rate if variant == "driven" else None
    what = f"the model of {VARIANTS[variant]}"
    desc = model_of(student_once(ctx, p03.model, variant, density, gravity, rate), what)
    return desc, what


def _density(ctx, variant):
    """The model takes the density it is given: built of aluminium, each link has the mass of an aluminium brick."""
    desc, what = _model(ctx, variant, density=OTHER_DENSITY)
    assert_link_masses(desc, what, 2, OTHER_DENSITY,
                       lambda density: ctx.reference(p03.link_inertia, LENGTH, WIDTH, HEIGHT, density)["mass"])


def _gravity(ctx, variant):
    """The model declares the gravity it is given: the runs are on the Earth, so the model is also built for the
    Moon (a fixed 9.81 would pass every run)."""
    for where, g in (("on the Moon", MOON), ("on the Earth", EARTH)):
        desc, what = _model(ctx, variant, g)
        assert_close(desc["gravity"], [0.0, -g, 0.0], f"the gravity of {what} built {where}", DIRECTION, mistakes=[
            Mistake("earth_gravity", [0.0, -EARTH, 0.0], "Use the gravity you are given (the Moon's is 1.62 "
                    "m/s^2), not a fixed 9.81: <option gravity=\"0 -g 0\"/> with g the argument."),
        ])


def _run(ctx, variant):
    rate = RATE if variant == "driven" else None
    duration = DRIVEN_DURATION if variant == "driven" else DURATION
    got = run_of(student_once(ctx, p03.run, variant, HDPE, EARTH, duration, SAMPLE, rate, timeout=30),
                 f"the model of {VARIANTS[variant]}")
    expected = ctx.reference(p03.ode, HDPE, EARTH, duration, SAMPLE, rate, persist=True)
    return got, expected, duration


def _inertia_mistakes(custom, density):
    """Known mistakes in a brick's custom inertia, from the reference's values."""
    m, com, I = custom["mass"], np.asarray(custom["com"]), np.asarray(custom["inertia"])
    return {
        "one_third": ("The moments of a brick about its CENTRE are m/12 (W^2 + H^2, L^2 + H^2, L^2 + W^2); m/3 (...) "
                      "is the moment about an end.",
                      {"mass": m, "com": com, "inertia": 4 * I}),
        "about_the_joint": ("The inertia is about the centre of mass (MuJoCo's <inertial> takes it there), not "
                            "about the joint: drop the m (L/2)^2 terms.",
                            {"mass": m, "com": com, "inertia": I + m * (np.dot(com, com) * np.eye(3)
                                                                        - np.outer(com, com))}),
        "com_at_joint": ("The centre of mass is in the middle of the brick, (L/2, 0, 0) from the joint.",
                         {"mass": m, "com": 0 * com, "inertia": I}),
        "com_full_length": ("The centre of mass is in the middle of the brick: L/2, not L, from the joint.",
                            {"mass": m, "com": 2 * com, "inertia": I}),
        "density_as_mass": ("The mass is rho L W H (density times volume), not the density.",
                            {"mass": density, "com": com, "inertia": I / m * density}),
    }


def _assert_inertial(got, expected, what, mistakes):
    """Mass, centre of mass and inertia of ``got`` against ``expected``; a mismatch names the known mistake that
    reproduces every part."""
    for key, name, tol in (("mass", "mass", MASS), ("com", "centre of mass", POSITION),
                           ("inertia", "inertia about the centre of mass", MASS)):
        candidates = [Mistake(n, value[key], hint) for n, (hint, value) in mistakes.items()
                      if not np.allclose(value[key], expected[key])]
        assert_close(got[key], expected[key], f"the {name} {what}", tol, candidates)


# ------------------------------------------------------------------------------------ 3(b): the custom inertia


@check(2, title="3(b): link_inertia(L, W, H, rho) = m = L W H rho at (L/2, 0, 0), m/12 diag(W^2+H^2, L^2+H^2, "
       "L^2+W^2) on random bricks", stage=STAGE_RANDOM, group="link_inertia")
def check_link_inertia(ctx):
    ctx.student(p03.link_inertia, LENGTH, WIDTH, HEIGHT, HDPE)

    def compare(got, expected, args):
        if not isinstance(got, dict) or not {"mass", "com", "inertia"} <= set(got):
            fail(f'link_inertia must return a dict with "mass", "com" and "inertia", got {str(got)[:200]}')
        shaped = {"mass": got["mass"], "com": got["com"], "inertia": got["inertia"]}
        _assert_inertial(shaped, expected, "of link_inertia(...)", _inertia_mistakes(expected, args[3]))

    ctx.compare_random(p03.link_inertia, BRICKS, name="link_inertia(...)", tol=EXACT, compare=compare,
                       examples=10, describe=lambda a: f"(L, W, H, rho) = ({a[0]!r}, {a[1]!r}, {a[2]!r}, {a[3]!r})")


# ------------------------------------------------------------------------------------ what the models declare


def _structure(ctx, variant):
    desc, what = _model(ctx, variant)
    joints = hinges(desc, 2, what)
    for k, joint in enumerate(joints):
        anchor = [k * LENGTH, 0.0, 0.0]
        assert_close(joint["anchor"], anchor, f"the position of joint {k + 1} in {what}", POSITION, mistakes=[
            Mistake("joint_at_centre", [k * LENGTH / 2, 0.0, 0.0], "Joint 2 sits at the FREE END of link 1, a full "
                    "length from joint 1: the inner body's pos is \"L 0 0\"."),
        ])
        assert_close(joint["axis"], [0.0, 0.0, 1.0], f"the axis of joint {k + 1} in {what}", DIRECTION,
                     mistakes=[Mistake("axis_sign", [0.0, 0.0, -1.0], "Angles count counter-clockwise about +z: "
                                       'axis="0 0 1".')])
    bodies = [body_of(desc, j) for j in joints]
    if bodies[1]["parent"] != joints[0]["body"]:
        fail(f"in {what} link 2 must be a child body of link 1 (joint 2 carries link 2 on link 1).",
             "Nest <body name=\"link2\" pos=\"L 0 0\"> inside the body of link 1.", "structure")
    return desc, what, bodies


@check(1, title="3(a): two links, joint 1 at the origin and joint 2 at the end of link 1, both about +z, and the "
       "gravity given", stage=STAGE_DEFINED, group="model_a")
def check_model_a(ctx):
    _structure(ctx, "geometry")
    _gravity(ctx, "geometry")


@check(1, title="3(a): mass, centre of mass and inertia about z from the geometry equal the analytic values, for "
       "the density given",
       stage=STAGE_STRUCTURE, group="model_a")
def check_geometry_inertia(ctx):
    desc, what, bodies = _structure(ctx, "geometry")
    _density(ctx, "geometry")
    custom = ctx.reference(p03.link_inertia, LENGTH, WIDTH, HEIGHT, HDPE)
    mistakes = _inertia_mistakes(custom, HDPE)
    for k, body in enumerate(bodies):
        offset = np.array([k * LENGTH, 0.0, 0.0])
        expected = {"mass": custom["mass"], "com": offset + custom["com"], "inertia": custom["inertia"][2, 2]}
        got = {"mass": body["mass"], "com": body["com"], "inertia": body["inertia"][2, 2]}
        shifted = {n: (h, {"mass": v["mass"], "com": offset + np.asarray(v["com"]),
                           "inertia": np.asarray(v["inertia"])[2, 2]}) for n, (h, v) in mistakes.items()}
        _assert_inertial(got, expected, f"of link {k + 1} (about z, at the start) in {what}", shifted)


@check(2, title="3(b): each body declares the custom mass, centre of mass, moments and products of inertia, and "
       "the model the gravity given, for the density given",
       stage=STAGE_STRUCTURE, group="model_b")
def check_custom_inertia(ctx):
    desc, what, bodies = _structure(ctx, "custom")
    _gravity(ctx, "custom")
    _density(ctx, "custom")
    custom = ctx.reference(p03.link_inertia, LENGTH, WIDTH, HEIGHT, HDPE)
    mistakes = _inertia_mistakes(custom, HDPE)
    for k, body in enumerate(bodies):
        offset = np.array([k * LENGTH, 0.0, 0.0])
        expected = {"mass": custom["mass"], "com": offset + custom["com"], "inertia": custom["inertia"]}
        shifted = {n: (h, {**v, "com": offset + np.asarray(v["com"])}) for n, (h, v) in mistakes.items()}
        _assert_inertial(body, expected, f"of link {k + 1} (at the start) in {what}", shifted)


# ------------------------------------------------------------------------------------ runs, within the chaos horizon


def _horizon(ctx, rate, duration):
    found = ctx.reference(p03.horizon, HDPE, EARTH, duration, SAMPLE, rate, ANGLE.atol, RATE_TOL.atol,
                          persist=True)
    return float(found["horizon"]), float(found["perturbation"])


def _chaos_traces(ctx, variant, title):
    got, expected, duration = _run(ctx, variant)
    rate = RATE if variant == "driven" else None
    horizon, perturbation = _horizon(ctx, rate, duration)
    mine = _traces(got)
    ref = {"q1 [rad]": expected["q"][:, 0], "q1_dot [rad/s]": expected["qd"][:, 0], "q2 [rad]": expected["q"][:, 1],
           "q2_dot [rad/s]": expected["qd"][:, 1]}
    shown = ("q2 [rad]", "q2_dot [rad/s]")  # the figure shows joint 2, the chaotic one
    ctx.add_figure(trace_figure(title, expected["t"], {k: mine[k] for k in shown}, {k: ref[k] for k in shown},
                                horizon if horizon < duration else None))
    tols = {"q1 [rad]": ANGLE, "q1_dot [rad/s]": RATE_TOL, "q2 [rad]": ANGLE, "q2_dot [rad/s]": RATE_TOL}
    why = ""
    if horizon < duration:
        why = (f"The double pendulum is chaotic: the reference's own ODE, started {perturbation:g} rad off, parts "
               f"from itself by more than the tolerance after {horizon:.2f} s, so only the first {horizon:.2f} s "
               "can tell a wrong model from rounding (the sheet compared five seconds by eye).")
    stepped = integration_to_blame(ctx, p03.run, (variant, HDPE, EARTH, duration, SAMPLE, rate), got, _traces,
                                   expected["t"], ref, tols, horizon)
    hint = (f"Your model {stepped}, too coarse for a chaotic motion: stepped as the sheet's models are, with RK4 at "
            '1 ms, it follows the reference, so declare <option integrator="RK4" timestep="0.001"/>.' if stepped else
            "The checks of what the model declares (above) name the likely cause.")
    compare_traces(expected["t"], mine, ref, tols, horizon, f"of {VARIANTS[variant]}", hint,
                   "integration" if stepped else "", note=why)


def _traces(run):
    """The traces of a run of a double pendulum, by label: both joints' angles and rates."""
    qpos, qvel = np.asarray(run["qpos"], dtype=float), np.asarray(run["qvel"], dtype=float)
    return {"q1 [rad]": qpos[:, 0], "q1_dot [rad/s]": qvel[:, 0], "q2 [rad]": qpos[:, 1], "q2_dot [rad/s]": qvel[:, 1]}


@check(2, title="3(a): both joints' angles and rates follow the reference up to the chaos horizon",
       stage=STAGE_VALUES, group="model_a")
def check_traces_a(ctx):
    _chaos_traces(ctx, "geometry", "Problem 3(a): angle and rate of joint 2")


@check(2, title="3(b): with the custom inertia the motion is the same: it follows the reference up to the chaos "
       "horizon", stage=STAGE_VALUES, group="model_b")
def check_traces_b(ctx):
    _chaos_traces(ctx, "custom", "Problem 3(b): angle and rate of joint 2 (custom inertia)")


# ------------------------------------------------------------------------------------ 3(c): joint 1 driven


@check(1, title="3(c): two links as in 3(a) with the gravity and the density given, and an actuator drives joint 1",
       stage=STAGE_DEFINED, group="driven")
def check_driven_model(ctx):
    desc, what, _ = _structure(ctx, "driven")
    _gravity(ctx, "driven")
    if not desc["actuators"]:
        fail(f"{what} has no actuator: nothing drives joint 1.",
             'A stiff servo drives a joint kinematically: <intvelocity joint="joint1" kp="1000"/>, with its control '
             "(the rate) and the start in motion in a keyframe.", "no_actuator")
    driven = sorted({int(actuator["joint"]) for actuator in desc["actuators"]})
    if driven != [0]:
        which = ", ".join(f"joint {j + 1}" if j >= 0 else "no joint" for j in driven)
        fail(f"{what}: its actuator drives {which}; the sheet drives joint 1 (q1 = t) and leaves joint 2 free.",
             'Attach the servo to the first hinge: <intvelocity joint="joint1" kp="1000"/>.', "actuator_joint")
    _density(ctx, "driven")


def _follows_as_sheet(ctx, q1_ref, duration):
    """Whether the student's driven model, stepped with the sheet's integration (RK4 at 1 ms) whatever it declares,
    holds joint 1 on q1 = t (``q1_ref``): True (the model's own integration is what strays), False (it strays as
    well, at the right average rate: the servo), or None (that run cannot say)."""
    again = run_as_sheet(ctx, p03.run, ("driven", HDPE, EARTH, duration, SAMPLE, RATE))
    try:
        q1 = np.asarray(again["qpos"], dtype=float)[:, 0]
    except (KeyError, TypeError, ValueError, IndexError):
        return None
    if q1.shape != np.shape(q1_ref) or not np.all(np.isfinite(q1)):
        return None
    if np.all(np.abs(q1 - q1_ref) <= DRIVEN.atol):
        return True
    return False if _right_average(q1, q1_ref) else None


def _right_average(q1, q1_ref) -> bool:
    """The run turns at the prescribed rate on average (its best straight line against the reference's)."""
    t = np.arange(q1.size, dtype=float)
    return bool(np.isclose(np.polyfit(t, q1, 1)[0], np.polyfit(t, q1_ref, 1)[0], rtol=0.02))


def _other_rate(ctx):
    """Joint 1 turns at the rate given: the model built for ``OTHER_RATE`` follows q1 = OTHER_RATE t (a model with
    the sheet's rate typed in would pass the run at the sheet's rate)."""
    what = f"the model of {VARIANTS['driven']} built for a rate of {OTHER_RATE:g} rad/s"
    got = run_of(student_once(ctx, p03.run, "driven", HDPE, EARTH, OTHER_RATE_DURATION, SAMPLE, OTHER_RATE,
                              timeout=30), what)
    t = np.asarray(got["t"], dtype=float)
    assert_close(got["qpos"][:, 0], OTHER_RATE * t, f"q1 of {what}", DRIVEN, context=f"(q1 = {OTHER_RATE:g} t)",
                 mistakes=[Mistake("ignored_argument", RATE * t, f"That is the sheet's rate, {RATE:g} rad/s: drive "
                                   "joint 1 at the rate you are given (the keyframe's qvel and ctrl).")])


@check(2, title="3(c): joint 1 moves at the prescribed rate, q1 = t, from the start (1 rad/s at t = 0), and at "
       "another rate given", stage=STAGE_VALUES, group="driven")
def check_driven_rate(ctx):
    got, expected, duration = _run(ctx, "driven")
    start, start_ref = float(got["qvel"][0, 0]), float(expected["qd"][0, 0])
    if not abs(start - start_ref) <= DRIVEN.atol and abs(start) < abs(start_ref) / 2:
        fail(f"joint 1 of {VARIANTS['driven']} starts at {start:.4g} rad/s; q1 = {RATE:g} t turns at {start_ref:.4g} "
             "rad/s from t = 0.",
             "Start the model in motion: in the keyframe joint 1 already turns at the rate, "
             '<key qvel="rate 0" ctrl="rate"/> (joint 2 at rest relative to link 1). From rest the servo jerks '
             "link 1 up to speed and kicks link 2.", "starts_at_rest")
    t, q1, q1_ref = expected["t"], got["qpos"][:, 0], expected["q"][:, 0]
    bad = np.flatnonzero(~(np.abs(q1 - q1_ref) <= DRIVEN.atol))
    if not bad.size and abs(start - start_ref) <= DRIVEN.atol:
        _other_rate(ctx)
        return
    i = int(bad[0]) if bad.size else 0
    slope = float(np.polyfit(t, q1, 1)[0]) if np.all(np.isfinite(q1)) else float("nan")
    message = (f"joint 1 of {VARIANTS['driven']} leaves its prescribed motion q1 = {RATE:g} t at t = {t[i]:.2f} s: "
               f"got q1 = {q1[i]:+.4f} rad, expected {q1_ref[i]:+.4f} rad (tolerance: {DRIVEN}); over the run it "
               f"turns at {slope:.4g} rad/s on average, and at {start:.4g} rad/s at the start.")
    if np.isclose(slope, RATE * 180 / np.pi, rtol=0.05) or np.isclose(slope, RATE * np.pi / 180, rtol=0.05):
        fail(message, "The rate is in rad/s: you converted it as if it were in degrees (or converted degrees "
             "twice).", "rate_degrees")
    if np.isclose(slope, RATE, rtol=0.02) and not abs(start - start_ref) <= DRIVEN.atol:
        # the drive turns the joint at its rate, from a start at another: the keyframe's initial velocity, not
        # the servo (a servo's stiffness has no say at t = 0)
        fail(f"{message}\nIts drive turns it at the rate, but it starts at {start:.4g} rad/s where q1 = {RATE:g} t "
             f"turns at {start_ref:.4g} rad/s" + (", the other way" if start * start_ref < 0 else "") + ".",
             "Start joint 1 at the rate it is driven at: the keyframe's initial velocity is the rate itself, "
             '<key qvel="rate 0" ctrl="rate"/>.', "initial_state")
    if np.isclose(slope, RATE, rtol=0.02):
        stepped = stepped_otherwise(got)
        if stepped:  # a servo that lags and a model stepped otherwise both stray from q1 = t on the right average
            as_sheet = _follows_as_sheet(ctx, q1_ref, duration)
            if as_sheet:
                fail(f"{message}\nYour model {stepped}; stepped as the sheet's models are, with RK4 at 1 ms, it "
                     "follows q1 = t.", "Declare the sheet's integration, <option integrator=\"RK4\" "
                     "timestep=\"0.001\"/>: with another step or integrator the servo holds the joint otherwise.",
                     "integration")
            fail(f"{message}\nYour model {stepped}; the sheet's models integrate with RK4 at 1 ms.",
                 "On average the rate is right but the joint strays from q1 = t. Your model is not integrated as the "
                 "sheet's (<option integrator=\"RK4\" timestep=\"0.001\"/>): with another step or integrator the "
                 "servo holds the joint otherwise. If it still strays with the sheet's, look at the servo (kp = 1000, "
                 "no damping kv).", "soft_servo" if as_sheet is False else "")
        fail(message, "On average the rate is right but the joint strays from q1 = t: stiffen the servo (kp = 1000) "
             "and drop its damping kv, which lags the joint behind a moving setpoint.", "soft_servo")
    if np.isclose(slope, -RATE, rtol=0.05):
        fail(message, "Joint 1 turns the other way: the servo's control and the keyframe's initial velocity are the "
             "rate itself, +rate (q1 = +t).", "sign_flip")
    fail(*_off_rate(t, q1, slope, message))


RATE_HINT = ("The servo's control is the rate in rad/s (an <intvelocity> integrates it into the setpoint): set it, and "
             "the keyframe's initial velocity, to the rate.")
UNSTEADY_HINT = ("Joint 1 should turn steadily, q1 = rate t: an <intvelocity> servo (kp = 1000) integrates its "
                 "control, the rate in rad/s, into a setpoint that moves so. Look at the actuator, its control and the "
                 "keyframe that starts it (its qvel and ctrl).")
#: a turn is steady where it strays from its best straight line q1 = a + b t by at most this share of the angle it
#: turns over the run (or by the band of the driven joint, whichever is larger): a servo driven at another rate
STEADY_SHARE = 0.05


def _off_rate(t, q1, slope, message) -> tuple[str, str, str]:
    """``(message, hint, diagnosis)`` of joint 1 off its prescribed motion at none of the rates the check names
    otherwise: a steady turn at another positive rate is the rate (``wrong_rate``); an unsteady turn is told how far
    it strays from its best straight line, with no cause; a steady turn at no positive rate (at rest, backwards) or
    a run that is not finite, with no cause either."""
    if not (np.all(np.isfinite(q1)) and np.isfinite(slope)):
        return message, RATE_HINT, ""
    strays = float(np.max(np.abs(np.polyval(np.polyfit(t, q1, 1), t) - q1)))
    if strays > max(STEADY_SHARE * abs(slope) * float(t[-1] - t[0]), DRIVEN.atol):
        return (f"{message}\nIt does not turn steadily: it strays up to {strays:.3g} rad from the straight line "
                "q1 = a + b t that fits it best.", UNSTEADY_HINT, "")
    return message, RATE_HINT, "wrong_rate" if slope > 0 and not np.isclose(slope, RATE, rtol=0.05) else ""


@check(2, title="3(c): joint 2's angle and rate follow the reference over 10 s (up to the chaos horizon, if any)",
       stage=STAGE_VALUES, group="driven")
def check_traces_c(ctx):
    _chaos_traces(ctx, "driven", "Problem 3(c): angle and rate of joint 2 (joint 1 driven, q1 = t)")
