"""Checks of problem 2: the pendulum in MuJoCo.

What the model declares (joint, gravity, mass and inertia from the geometry, damping, input torque) is read by
MuJoCo inside the sandbox and compared with the sheet and the reference's analytic values; then the model is run
and its angle and rate are compared with the reference's own ODE (solved with scipy, independent of MuJoCo) over
10 s, and its period on the Earth and on the Moon with the exact period of the physical pendulum.
"""

import numpy as np

from grader.checking import (
    STAGE_DEFINED,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    Mistake,
    Tol,
    assert_close,
    check,
    fail,
)
from probes import problem_02 as p02, problem_03 as p03

from ._answers import typed_or_ignored
from ._mujoco import (
    ALUMINIUM,
    DIRECTION,
    EARTH,
    HDPE,
    HEIGHT,
    LENGTH,
    MASS,
    MOON,
    POSITION,
    SAMPLE,
    WIDTH,
    body_of,
    compare_traces,
    hinges,
    integration_to_blame,
    model_of,
    reference_of,
    run_of,
    student_once,
    trace_figure,
)

TITLE = "A pendulum in MuJoCo"
MANUAL = {"density": ("2(b): Does the motion change when you change the density of the material? Why?", 1)}

#: the tutorial's model (2a): aluminium, joint damping 8e-5 N m/(deg/s), input torque 0.06 sin(t) N m
TUTORIAL = (ALUMINIUM, EARTH, 8e-5, 0.06)
#: (label, density, gravity, damping, torque) of the runs compared with the reference
CASES = {
    "2a": ("2(a), the tutorial's model", TUTORIAL),
    "2b": ("2(b), HDPE on the Earth", (HDPE, EARTH, 0.0, 0.0)),
    "2c": ("2(c), HDPE on the Moon", (HDPE, MOON, 0.0, 0.0)),
}
DURATION = 10.0
#: densities at which the declared mass and inertia are checked: the sheet's, and two that no sheet prints
DENSITIES = (HDPE, ALUMINIUM, 1234.5, 7850.0)
#: the run of a correct model (RK4 or Euler with a 1-2 ms step) and the ODE agree far closer than this
ANGLE = Tol("angle, MuJoCo vs the reference's ODE", 0.02)
RATE = Tol("rate, MuJoCo vs the reference's ODE", 0.2)
#: the period measured from the rate's zero crossings (samples every 10 ms)
PERIOD = Tol("period measured from the run", 2e-3)
#: the same model at two densities: MuJoCo's runs agree to rounding
SAME_MOTION = Tol("the same motion, to rounding", 1e-6)
DAMPING = Tol("declared damping and torque, 4 significant digits", 1e-15, 5e-4)


def _model(ctx, density, gravity, damping=0.0, torque=0.0):
    what = f"pendulum({density:g}, {gravity:g}, {damping:g}, {torque:g})"
    return model_of(student_once(ctx, p02.model, density, gravity, damping, torque), what), what


def _run(ctx, case):
    label, args = CASES[case]
    got = run_of(student_once(ctx, p02.run, *args, DURATION, SAMPLE, timeout=30), f"the model of {label}")
    return label, got


# ------------------------------------------------------------------------------------ what the model declares


@check(1, title="pendulum(...) returns a model that MuJoCo loads, with exactly one hinge joint", stage=STAGE_DEFINED,
       group="model")
def check_loads(ctx):
    desc, what = _model(ctx, HDPE, EARTH)
    hinges(desc, 1, what)


@check(1, title="the hinge sits at the origin with axis +z, without armature, friction or spring",
       stage=STAGE_STRUCTURE, group="model")
def check_joint(ctx):
    desc, what = _model(ctx, HDPE, EARTH)
    joint = hinges(desc, 1, what)[0]
    assert_close(joint["anchor"], np.zeros(3), f"the joint's position in {what}", POSITION)
    assert_close(joint["axis"], [0.0, 0.0, 1.0], f"the joint's axis in {what}", DIRECTION,
                 mistakes=[Mistake("axis_sign", [0.0, 0.0, -1.0], "With axis 0 0 -1 the angle is clockwise "
                                   "positive; the course counts angles counter-clockwise about +z.")])
    extras = {k: joint[k] for k in ("armature", "frictionloss", "stiffness") if joint[k] != 0.0}
    if extras:
        fail(f"the joint of {what} declares {', '.join(f'{k} = {v:g}' for k, v in extras.items())}; the "
             "pendulum has none.", "Remove them: each changes the motion.", "joint_extras")


@check(1, title="gravity points along -y: (0, -1.62, 0) on the Moon and (0, -9.81, 0) on the Earth",
       stage=STAGE_STRUCTURE, group="model")
def check_gravity(ctx):
    for where, g in (("on the Moon (2c)", MOON), ("on the Earth (2b)", EARTH)):
        desc, what = _model(ctx, HDPE, g)
        assert_close(desc["gravity"], [0.0, -g, 0.0], f"the gravity of {what} {where}", DIRECTION, mistakes=[
            Mistake("gravity_axis", [0.0, 0.0, -g], "MuJoCo's default gravity points along -z, but the course's "
                    "pendulum swings in the x-y plane with gravity along -y: <option gravity=\"0 -g 0\"/>."),
            Mistake("earth_gravity", [0.0, -EARTH, 0.0], "Use the gravity you are given (the Moon's is 1.62 "
                    "m/s^2), not a fixed 9.81."),
        ])


@check(2, title="mass, centre of mass and inertia about z computed by MuJoCo from the geometry: m = rho L W H, "
       "at (L/2, 0, 0), I_zz = m (L^2 + W^2) / 12 (four densities)", stage=STAGE_VALUES, group="model")
def check_mass_inertia(ctx):
    for density in DENSITIES:
        desc, what = _model(ctx, density, EARTH)
        body = body_of(desc, hinges(desc, 1, what)[0])
        custom = ctx.reference(p03.link_inertia, LENGTH, WIDTH, HEIGHT, density)
        m, com, I_zz = custom["mass"], np.asarray(custom["com"]), custom["inertia"][2, 2]
        assert_close(body["mass"], m, f"the link's mass in {what}", MASS, mistakes=[
            Mistake("density_as_mass", density, "You set the MASS to the density: give the geom density=\"rho\" "
                    "and let MuJoCo compute the mass (rho times the box's volume)."),
            Mistake("box_full_size", 8 * m, "MuJoCo's box size is HALF the edge lengths: size=\"L/2 W/2 H/2\". "
                    "Full lengths make the box 8 times its volume."),
        ])
        assert_close(body["com"], com, f"the link's centre of mass at the start, in {what}", POSITION, mistakes=[
            Mistake("full_length_offset", 2 * com, "The box's centre is HALF a length from the pivot: "
                    "pos=\"L/2 0 0\" (with size half the edges); the full length puts the pivot outside the link."),
            Mistake("centre_pivot", 0 * com, "The pivot is at one END of the link: the box's centre lies L/2 "
                    "along +x from the joint, not on it."),
            Mistake("not_horizontal", [0.0, -com[0], 0.0], "The link starts horizontal along +x (angle 0), not "
                    "hanging down."),
        ])
        assert_close(body["inertia"][2, 2], I_zz, f"the link's inertia about z (through its centre) in {what}",
                     MASS)


#: damping [N m/(deg/s)] and torque amplitude [N m] that the sheet does not print: the model takes them from its
#: arguments, so the tutorial's 8e-5 and 0.06 typed into the MJCF earn nothing
UNPRINTED = (ALUMINIUM, EARTH, 2.5e-4, 0.11)
TYPED_HINT = ("Your model declares the tutorial's {what} whatever {argument} it is given: build it from the argument "
              "{argument} (the checks also ask other values).")


def _unit_torque(desc):
    """The joint torque of a model's motors at control 1."""
    return sum((np.asarray(a["unit_torque"]) for a in desc["actuators"]), np.zeros(1))


def _assert_inputs(ctx, args, tutorial=None):
    """The joint's damping and the motor's torque at control 1 of ``pendulum(*args)`` are the reference's;
    ``tutorial``: the reference's model of the tutorial, whose values typed in are a known mistake here."""
    desc, what = _model(ctx, *args)
    joint = hinges(desc, 1, what)[0]
    ref = reference_of(ctx.reference(p02.model, *args, persist=True), f"the model {what}")
    damping, expected = ref["joints"][0]["damping"], _unit_torque(ref)
    typed_damping, typed_torque = [], []
    if tutorial is not None:
        typed_damping = typed_or_ignored(tutorial["joints"][0]["damping"], TYPED_HINT.format(
            what="damping (8e-5 N m/(deg/s), converted)", argument="damping"), "damping")
        typed_torque = typed_or_ignored(_unit_torque(tutorial), TYPED_HINT.format(
            what="torque amplitude 0.06", argument="torque"), "torque")
    assert_close(joint["damping"], damping, f"the joint's damping [N m s/rad] in {what}", DAMPING, mistakes=[
        Mistake("damping_per_degree", damping * np.pi / 180, "The tutorial's 8e-5 is per DEGREE per second; MuJoCo's "
                "damping is per RADIAN per second: multiply by 180/pi (1 rad/s = 57.3 deg/s)."),
        Mistake("damping_wrong_conversion", damping * (np.pi / 180) ** 2, "The conversion goes the other way: "
                "N m/(deg/s) times 180/pi gives N m s/rad."),
        *typed_damping,
    ])
    if not desc["actuators"]:
        fail(f"{what} has no actuator: the input torque {args[3]:g} sin(t) has nothing to act through.",
             '<actuator><motor joint="..." gear="torque"/></actuator>: the grader sets its control to sin(t).',
             "no_actuator")
    assert_close(_unit_torque(desc), expected, f"the joint torque at control 1 (the amplitude of torque sin(t)) in "
                 f"{what}", DAMPING, mistakes=[
                     Mistake("unit_gear", np.ones_like(expected), "The grader sets the control to sin(t); the "
                             "motor's gear must scale it to torque sin(t): gear=\"torque\"."),
                     *typed_torque])


@check(2, title="2(a): damping 8e-5 N m/(deg/s) declared in N m s/rad, input torque 0.06 sin(t) N m on the joint "
       "(and other damping and torque when asked); 2(b): neither", stage=STAGE_VALUES, group="model")
def check_damping_torque(ctx):
    tutorial = reference_of(ctx.reference(p02.model, *TUTORIAL, persist=True), "tutorial model")
    _assert_inputs(ctx, TUTORIAL)
    _assert_inputs(ctx, UNPRINTED, tutorial)
    quiet, quiet_what = _model(ctx, HDPE, EARTH)
    joint = hinges(quiet, 1, quiet_what)[0]
    torque = _unit_torque(quiet)
    if joint["damping"] != 0.0 or np.any(torque != 0.0):
        fail(f"{quiet_what} must have no damping and no input torque: got damping {joint['damping']:g} N m s/rad "
             f"and a torque of {float(torque[0]):g} N m at control 1.",
             "With damping = 0 and torque = 0, declare damping 0 and no motor (or a motor with gear 0).",
             "leftover_input")


# ------------------------------------------------------------------------------------ runs


def _rate_crossings(t, rate):
    """Times at which the rate crosses zero (linear interpolation), after the start at rest."""
    t, rate = np.asarray(t, dtype=float), np.asarray(rate, dtype=float)
    i = np.flatnonzero((rate[1:-1] * rate[2:] < 0) | ((rate[2:] == 0) & (rate[1:-1] != 0))) + 1
    return t[i] - rate[i] * (t[i + 1] - t[i]) / (rate[i + 1] - rate[i])


@check(2, title="2(b), 2(c): the period on the Earth and on the Moon, measured from the run, is the physical "
       "pendulum's", stage=STAGE_VALUES, group="period")
def check_period(ctx):
    for case, g in (("2c", MOON), ("2b", EARTH)):
        label, got = _run(ctx, case)
        crossings = _rate_crossings(got["t"], got["qvel"][:, 0])
        period = ctx.reference(p02.period, HDPE, g, persist=True)
        if len(crossings) < 2:
            fail(f"the pendulum of {label} does not swing back within {DURATION:g} s: its rate changes sign "
                 f"{len(crossings)} time(s); the period should be {period:.4f} s.",
                 "Released horizontally, the link falls: check that gravity points along -y and that the link "
                 "starts horizontal along +x.", "no_swing")
        measured = 2 * (crossings[-1] - crossings[0]) / (len(crossings) - 1)
        assert_close(measured, period, f"the period of {label} [s]", PERIOD,
                     note=f"Measured from {len(crossings)} reversals of the angle rate; expected the exact period "
                          "4 sqrt(I_O / (m g L/2)) K(sin(pi/4)) of a physical pendulum released at 90 degrees.")


def _traces_check(ctx, case):
    label, got = _run(ctx, case)
    expected = ctx.reference(p02.ode, *CASES[case][1], DURATION, SAMPLE, persist=True)
    mine = _traces(got)
    ref = {"q [rad]": expected["q"][:, 0], "q_dot [rad/s]": expected["qd"][:, 0]}
    ctx.add_figure(trace_figure(f"Problem {label}: angle and angle rate", expected["t"], mine, ref))
    tols = {"q [rad]": ANGLE, "q_dot [rad/s]": RATE}
    stepped = integration_to_blame(ctx, p02.run, (*CASES[case][1], DURATION, SAMPLE), got, _traces, expected["t"],
                                   ref, tols, DURATION)
    compare_traces(expected["t"], mine, ref, tols, DURATION, f"of {label}",
                   f"Your model {stepped}: stepped as the sheet's models are, with RK4 at 1 ms, it follows the "
                   'reference, so declare <option integrator="RK4" timestep="0.001"/>.' if stepped else
                   "The checks of what the model declares (above) name the likely cause.",
                   "integration" if stepped else "")


def _traces(run):
    """The traces of a run of the pendulum, by label: its angle and rate."""
    return {"q [rad]": np.asarray(run["qpos"], dtype=float)[:, 0], "q_dot [rad/s]": np.asarray(run["qvel"],
                                                                                                dtype=float)[:, 0]}


@check(2, title="2(a): the tutorial model's angle and rate follow the reference over 10 s", stage=STAGE_VALUES,
       group="traces_2a")
def check_traces_2a(ctx):
    _traces_check(ctx, "2a")


@check(2, title="2(b): angle and rate (HDPE, no torque, no damping) follow the reference over 10 s",
       stage=STAGE_VALUES, group="traces_2b")
def check_traces_2b(ctx):
    _traces_check(ctx, "2b")


@check(2, title="2(c): angle and rate on the Moon follow the reference over 10 s", stage=STAGE_VALUES,
       group="traces_2c")
def check_traces_2c(ctx):
    _traces_check(ctx, "2c")


@check(1, title="2(b) by experiment: the motion is the same for HDPE and for aluminium (no torque, no damping)",
       stage=STAGE_VALUES, group="density")
def check_density_experiment(ctx):
    _, light = _run(ctx, "2b")
    heavy = run_of(student_once(ctx, p02.run, ALUMINIUM, EARTH, 0.0, 0.0, DURATION, SAMPLE, timeout=30),
                   "the model of 2(b) in aluminium")
    for key, name in (("qpos", "angle"), ("qvel", "angle rate")):
        a, b = np.asarray(light[key])[:, 0], np.asarray(heavy[key])[:, 0]
        if not np.allclose(a, b, atol=SAME_MOTION.atol, rtol=SAME_MOTION.rtol):
            i = int(np.argmax(np.abs(a - b)))
            fail(f"the {name} changes with the density: at t = {light['t'][i]:.2f} s it is {a[i]:+.6f} for HDPE "
                 f"and {b[i]:+.6f} for aluminium.\ntolerance: {SAME_MOTION}",
                 "Without torque and damping every force on the link is proportional to its mass, so the mass "
                 "cancels: does your model add a mass, damping or torque that does not scale with the density?",
                 "density_matters")
