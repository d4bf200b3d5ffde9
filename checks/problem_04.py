"""Checks of problem 4: the four-bar linkage, its assembly and its balance.

The assembly must meet a single target and close the loop (on random reachable configurations, whichever
branch it finds), and refuse over-specified targets and unreachable fixed points with the declared exceptions; an
assembly that cannot close the loop (a target that leaves the other links unable to reach the fixed point) raises,
rather than returning the angles where its iteration stopped.  A balanced configuration is accepted when the loop
closes and gravity does no work along the linkage's only motion, whichever balanced configuration it is; it is
asked for the sheet's fixed point and for points on the ground the sheet does not print ((0.3, 0, 0) and one drawn
per grading), so that the sheet's configuration typed in earns nothing.  The MuJoCo model (inside the sandbox) must
close the loop with an equality constraint at the fixed point it is given (the sheet's, and another on the
ground), and its acceleration at rest along that motion must be the reference's (projected Newton-Euler,
independent of MuJoCo) and vanish in the student's balanced configuration.
"""

import itertools

import numpy as np

from grader import strategies as st
from grader.errors import StudentFault, ends_grading
from grader.strategies import assume
from grader.checking import (
    STAGE_DEFINED,
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    STAGE_VALUES,
    EXACT,
    CheckFailure,
    Mistake,
    Tol,
    as_array,
    assert_close,
    check,
    close,
    fail,
    figure,
)
from probes import problem_03 as p03
from probes import problem_04 as p04

from ._mujoco import (
    ALUMINIUM,
    DIRECTION,
    EARTH,
    HDPE,
    HEIGHT,
    LENGTH,
    MOON,
    POSITION,
    WIDTH,
    assert_link_masses,
    hinges,
    model_of,
    student_once,
)

TITLE = "A four-bar linkage: assembly and balance"
MANUAL = {
    "a": ("4(a): With state targets on all four joints the model does not run. Explain the error.", 1),
    "c": ("4(c): With the fixed point at (1, 0, 0) the model cannot be assembled. Why?", 1),
}

FIXED_POINT = (0.5, 0.0, 0.0)
UNREACHABLE_POINT = (1.0, 0.0, 0.0)
#: 4(a): all four joint targets at 0; 4(c): one target (the trapezoid's q1) with the far fixed point
ALL_ZERO = [0.0, 0.0, 0.0, 0.0]
ONE_TARGET = [0.72273, None, None, None]
#: an unbalanced configuration for the model's dynamics: joint 1 at 0.4 rad
DYNAMICS_TARGETS = [0.4, None, None, None]
#: a fixed point on the ground the sheet does not print, where the trapezoid's q1 as a target of the assembly can
#: give the loop's other, unbalanced configuration
GROUND_POINT = (0.3, 0.0, 0.0)
#: the ground points (d, 0, 0) drawn for each grading: within reach, away from the stretched loop
GROUND = (0.12, 0.56)
#: a target that leaves links 2 and 3 unable to close the loop at the sheet's fixed point: link 1 points away from it
AWAY = [np.pi, None, None, None]
#: the loop closes and the targets are met to the accuracy of a converged Newton solve
CLOSURE = Tol("loop closure and targets", 1e-6)
#: gravity's work along the unit motion of the joints, relative to L (0 in static equilibrium)
BALANCE = Tol("static equilibrium, |d(sum of link heights)/ds| / L", 1e-4)
#: MuJoCo's acceleration along the linkage's free motion against the reference's
ALONG = Tol("acceleration along the free motion [rad/s^2]", 1e-3, 1e-3)
#: at rest in a balanced configuration (about 1e-4 rad from balance gives 0.02 rad/s^2)
AT_REST = Tol("at rest [rad/s^2]", 0.05)
FINITE = dict(allow_nan=False, allow_infinity=False)
ANGLES = st.floats(-np.pi, np.pi, **FINITE)

EXCEPTIONS = {"overconstrained": "OverconstrainedError", "unreachable": "UnreachableError"}


def loop_points(q):
    """Joints 1-3 and the end of link 3 (x, y) for the angles ``q`` (q1, q2, q3 used; complex angles allowed, for
    the complex-step derivatives below)."""
    phi = np.cumsum(np.asarray(q)[:3])
    return np.vstack([np.zeros(2), np.cumsum(LENGTH * np.stack([np.cos(phi), np.sin(phi)], axis=1), axis=0)])


def _complex_step(function, q, h=1e-30):
    """d function / dq (one column per angle) by the complex step, exact to rounding: the checks differentiate the
    given geometry rather than carry a closed form of their own."""
    q = np.asarray(q, dtype=float)[:3]
    return np.stack([np.imag(function(q + 1j * h * e)) / h for e in np.eye(3)], axis=-1)


def closure_jacobian(q):
    """d(end of link 3)/dq: the 2 x 3 Jacobian of the loop's closure."""
    return _complex_step(lambda x: loop_points(x)[-1], q)


def height_gradient(q):
    """d/dq of the sum of the three links' centre heights (gravity's potential over m g)."""
    def heights(x):
        points = loop_points(x)
        return np.sum((points[:-1, 1] + points[1:, 1]) / 2)
    return _complex_step(heights, q)


def _wrapped(angle):
    return float(np.angle(np.exp(1j * angle)))


@st.composite
def reachable_cases(draw):
    """A configuration drawn at random, its end as the fixed point, and one of its joint angles as the target;
    away from the singular (stretched or folded) configurations, where the assembly is ill-conditioned."""
    q = np.array([draw(ANGLES), draw(st.floats(0.4, 2.7, **FINITE)) * draw(st.sampled_from([-1, 1])),
                  draw(st.floats(0.4, 2.7, **FINITE)) * draw(st.sampled_from([-1, 1]))])
    joint = draw(st.integers(0, 3))
    end = loop_points(q)[-1]
    row = -np.ones(3) if joint == 3 else np.eye(3)[joint]
    system = np.vstack([closure_jacobian(q), row])
    assume(0.15 <= np.linalg.norm(end) <= 0.55 and np.linalg.svd(system)[1][-1] > 0.05)
    targets = [None] * 4
    targets[joint] = float(q[joint]) if joint < 3 else _wrapped(-np.sum(q))
    return targets, [float(end[0]), float(end[1]), 0.0]


def _describe_targets(targets, point):
    shown = ", ".join("None" if t is None else f"{t:.6g}" for t in targets)
    return f"assemble([{shown}], ({point[0]:.6g}, {point[1]:.6g}, {point[2]:.6g}))"


def _expect_raise(got, kind, call, reason):
    name = EXCEPTIONS[kind]
    if "q" in got:
        fail(f"{call} returned q = {np.round(np.asarray(got['q'], dtype=float), 6).tolist()} instead of raising "
             f"{name}: {reason}.", f"Raise problem_04.{name}, with a message that says why.", "no_error")
    if got["kind"] != kind:
        fail(f"{call} raised {got['raised']}: {got['message']}\nexpected problem_04.{name}: {reason}.",
             f"Raise the exception the docstring declares (problem_04.{name}, a subclass of AssemblyError and of "
             "ValueError), so that a caller can tell the two failures apart.", "wrong_error")
    if len(got["message"].strip()) < 10:
        fail(f"{call} raised {name} with the message {got['message']!r}, which does not say why.",
             f"Name the reason and the numbers, e.g. that {reason}.", "no_message")


# ------------------------------------------------------------------------------------ the assembly


@check(2, title="4(a): targets on more joints than the one degree of freedom raise OverconstrainedError (all four "
       "at 0, and random conflicting pairs)", stage=STAGE_VALUES, group="overconstrained")
def check_overconstrained(ctx):
    reason = "a four-bar has one degree of freedom, so four targets conflict"
    _expect_raise(ctx.student(p04.assemble, ALL_ZERO, FIXED_POINT), "overconstrained",
                  _describe_targets(ALL_ZERO, FIXED_POINT), reason)

    def pairs(draw_args):
        (j, k), (a, b) = draw_args
        targets = [None] * 4
        targets[j], targets[k] = a, b
        return targets, list(FIXED_POINT)

    strategy = st.tuples(st.sampled_from([(0, 1), (0, 2), (1, 3), (2, 3), (0, 3)]),
                         st.tuples(ANGLES, ANGLES)).map(pairs)
    ctx.compare_random(p04.assemble, strategy, name="assemble(...)", tol=EXACT, examples=5,
                       compare=lambda got, expected, args: _expect_raise(
                           got, "overconstrained", _describe_targets(*args),
                           "two targets on a linkage with one degree of freedom conflict"),
                       describe=lambda args: _describe_targets(*args))


@check(2, title="4(c): a fixed point out of the links' reach raises UnreachableError ((1, 0, 0), and random far "
       "points), and so does a target that leaves the other links unable to reach the fixed point",
       stage=STAGE_VALUES, group="unreachable")
def check_unreachable(ctx):
    reason = "three links of 0.2 m reach at most 0.6 m, and the fixed point is 1 m away"
    _expect_raise(ctx.student(p04.assemble, ONE_TARGET, UNREACHABLE_POINT), "unreachable",
                  _describe_targets(ONE_TARGET, UNREACHABLE_POINT), reason)

    def far(args):
        distance, angle, joint, target = args
        targets = [None] * 4
        targets[joint] = target
        return targets, [distance * np.cos(angle), distance * np.sin(angle), 0.0]

    strategy = st.tuples(st.floats(0.62, 2.0, **FINITE), ANGLES, st.integers(0, 3), ANGLES).map(far)
    ctx.compare_random(p04.assemble, strategy, name="assemble(...)", tol=EXACT, examples=5,
                       compare=lambda got, expected, args: _expect_raise(
                           got, "unreachable", _describe_targets(*args),
                           f"the fixed point is {np.linalg.norm(args[1]):.3f} m away, beyond the links' 0.6 m"),
                       describe=lambda args: _describe_targets(*args))
    _assert_blocked_targets_raise(ctx)


def _blocking(args):
    """A fixed point within reach and a target on joint 1 or 4 that points its link away from it: the two other
    links cannot close the loop (their free end is farther than 2 L from where they must go)."""
    distance, direction, joint, spread = args
    point = np.array([distance * np.cos(direction), distance * np.sin(direction)])
    away = direction + np.pi + spread  # the absolute angle of link 1 (joint 1) or of link 3 (joint 4: q4 = -angle)
    targets = [None] * 4
    targets[joint] = _wrapped(away if joint == 0 else -away)
    return targets, [float(point[0]), float(point[1]), 0.0]


def _gap(targets, point):
    """How far the two free links would have to reach [m] for one target on joint 1 (link 1 at the angle q1 from
    joint 1) or on joint 4 (link 3 at the angle -q4 into the fixed point): the same distance either way."""
    angle = targets[0] if targets[0] is not None else -targets[3]
    return float(np.linalg.norm(np.asarray(point[:2]) - LENGTH * np.array([np.cos(angle), np.sin(angle)])))


def _assert_blocked_targets_raise(ctx):
    """Targets that leave links 2 and 3 unable to close the loop, the fixed point within reach: the assembly must
    raise UnreachableError rather than return the angles where its iteration stopped (the sheet's fixed point with
    link 1 pointing away from it, and random ones)."""
    def reason(targets, point):
        return (f"with that target the two other links would have to reach {_gap(targets, point):.3f} m, beyond "
                f"their {2 * LENGTH:g} m")

    _expect_raise(ctx.student(p04.assemble, AWAY, FIXED_POINT), "unreachable",
                  _describe_targets(AWAY, FIXED_POINT), reason(AWAY, FIXED_POINT))
    strategy = st.tuples(st.floats(0.3, 0.55, **FINITE), ANGLES, st.sampled_from([0, 3]),
                         st.floats(-0.5, 0.5, **FINITE)).map(_blocking)
    ctx.compare_random(p04.assemble, strategy, name="assemble(...)", tol=EXACT, examples=5,
                       compare=lambda got, expected, args: _expect_raise(got, "unreachable", _describe_targets(*args),
                                                                         reason(*args)),
                       describe=lambda args: _describe_targets(*args))


def _assert_assembled(q, targets, point, call):
    q = as_array(q, f"the angles returned by {call}", (4,))
    end = loop_points(q)[-1]
    assert_close(end, np.asarray(point, dtype=float)[:2], f"the end of link 3 for the angles {np.round(q, 6).tolist()} "
                 f"returned by {call}", CLOSURE, context="(the fixed point: the loop must close)")
    assert_close(_wrapped(np.sum(q)), 0.0, f"q1 + q2 + q3 + q4 (mod 2 pi) returned by {call}", CLOSURE,
                 note="q4 is the angle of the world frame relative to link 3, so the four angles add up to 0.")
    for k, target in enumerate(targets):
        if target is not None:
            assert_close(_wrapped(q[k] - target), 0.0, f"q{k + 1} - its target {target:.6g} (mod 2 pi) in {call}",
                         CLOSURE)
    return q


@check(2, title="4(b): with one target the assembly closes the loop and meets the target (random reachable "
       "configurations, either branch)", stage=STAGE_RANDOM, group="assembly")
def check_assembly(ctx):
    def compare(got, expected, args):
        targets, point = args
        call = _describe_targets(targets, point)
        if "q" not in got:
            fail(f"{call} raised {got['raised']}: {got['message']}\nbut the linkage can be assembled there (the "
                 "reference finds a configuration).", "Start Newton's method from several guesses (both branches), "
                 "and take a least-squares step where the Jacobian is not square.", "not_assembled")
        _assert_assembled(got["q"], targets, point, call)

    ctx.compare_random(p04.assemble, reachable_cases(), name="assemble(...)", tol=EXACT, examples=10,
                       compare=compare, describe=lambda args: _describe_targets(*args))


# ------------------------------------------------------------------------------------ the balanced configuration


def _drawing(q):
    """The links from joint 1 to the end of link 3, then the ground from the fixed point back to joint 1."""
    points = np.vstack([loop_points(q), np.asarray(FIXED_POINT)[:2], np.zeros(2)])
    return points[:, 0], points[:, 1]


def _ground_point(ctx):
    """A fixed point ``(d, 0, 0)`` on the ground that the sheet does not print, drawn for this grading."""
    return (round(float(ctx.draw(lambda rng: rng.uniform(*GROUND))), 4), 0.0, 0.0)


def _call(point):
    return f"balanced_configuration(({point[0]:g}, {point[1]:g}, {point[2]:g}))"


TYPED_HINT = (
    "This is the configuration of the sheet's fixed point (0.5, 0, 0), whatever fixed_point is asked: compute it "
    "from fixed_point (the symmetric trapezoid has cos(q1) = (d - L) / (2 L) for the fixed point (d, 0, 0)); the "
    "checks also ask other points on the ground."
)


def _assert_balanced(q, point, sheet_q=None):
    """``q`` closes the loop at ``point`` and gravity does no work along the linkage's only motion there;
    ``sheet_q``: the student's configuration for the sheet's fixed point, to name it when it comes back for another
    point."""
    call = _call(point)
    q = as_array(q, call, (4,))
    if sheet_q is not None and point[:2] != FIXED_POINT[:2] and np.allclose(q, sheet_q, atol=1e-9):
        if not np.allclose(loop_points(q)[-1], np.asarray(point)[:2], atol=CLOSURE.atol):
            fail(f"{call} returned {np.round(q, 6).tolist()}, the configuration you return for the sheet's fixed "
                 f"point (0.5, 0, 0): its loop does not close at ({point[0]:g}, {point[1]:g}).", TYPED_HINT,
                 "typed_numbers or ignored_argument")
    _assert_assembled(q, [None] * 4, point, call)
    t = np.linalg.svd(closure_jacobian(q))[2][-1]
    work = float(t @ height_gradient(q)) / LENGTH
    assert_close(work, 0.0, f"gravity's work along the unit motion, over m g L, at q = {np.round(q, 6).tolist()} "
                 f"(fixed point ({point[0]:g}, {point[1]:g}, {point[2]:g}))", BALANCE,
                 note="In static equilibrium the centre of gravity neither rises nor falls when the linkage moves (its "
                      "only motion, with q1, q2, q3 along the null space of the closure Jacobian).")
    return q


@check(2, title="4(b): balanced_configuration() closes the loop and is in static equilibrium (gravity does no "
       "work along the linkage's motion), for the sheet's fixed point and for other points on the ground",
       stage=STAGE_STRUCTURE, group="balance")
def check_balanced(ctx):
    points = [FIXED_POINT, GROUND_POINT, _ground_point(ctx)]
    ref = ctx.reference(p04.balanced, FIXED_POINT)
    q = as_array(ctx.student(p04.balanced, FIXED_POINT), "balanced_configuration()", (4,))
    ctx.add_figure(figure("Problem 4(b): the four-bar in your balanced configuration", "x [m]", "y [m]",
                          student=[("links", *_drawing(q))], reference=[("links", *_drawing(ref))], equal_axes=True))
    _assert_balanced(q, FIXED_POINT)
    for point in points[1:]:
        _assert_balanced(ctx.student(p04.balanced, point), point, q)


# ------------------------------------------------------------------------------------ the MuJoCo model


def _model(ctx, q, what, point=FIXED_POINT, density=HDPE, gravity=EARTH):
    return model_of(student_once(ctx, p04.model, density, gravity, q, point), what)


def _along(desc, what):
    """The acceleration along the linkage's motion at rest, or a failure saying why MuJoCo's model has none."""
    at_rest = desc["at_rest"]
    if "error" in at_rest:
        fail(f"{what}: {at_rest['error']}.", "Close the loop with one <connect> between the end of link 3 and the "
             "world: three hinges and a connect leave one degree of freedom.", "no_connect")
    return at_rest["alpha"]


@check(1, title="four_bar(...): three hinges about +z at the joints of q, and an equality constraint joining the end "
       "of link 3 to the world at the fixed point (the sheet's, and another on the ground)", stage=STAGE_DEFINED,
       group="model")
def check_model_structure(ctx):
    for point in (FIXED_POINT, GROUND_POINT):
        _assert_structure(ctx, point)


STRAIGHT_HINT = ("Build the model in the configuration q: rotate each link's body by its joint angle "
                 "(euler=\"0 0 q_i\" with <compiler angle=\"radian\"/>).")
#: the links a model built straight leaves unturned (their joint angles left out of their bodies' orientations):
#: any one of them, or several
UNTURNED = [links for n in (1, 2, 3) for links in itertools.combinations(range(3), n)]


def _configuration(ctx, point):
    """``(q, what)``: the configuration the reference assembles at ``point``, and the model's call in words."""
    q = ctx.reference(p04.assemble, DYNAMICS_TARGETS, point)["q"]
    return q, f"four_bar(950, 9.81, q = {np.round(q, 6).tolist()}, fixed_point = ({point[0]:g}, {point[1]:g}, 0))"


def _assert_structure(ctx, point):
    """The model of a configuration the reference assembles at ``point``: its hinges where the joints of q are,
    and one connect that holds the end of link 3 at ``point``."""
    q, what = _configuration(ctx, point)
    desc = _model(ctx, q, what, point)
    joints = hinges(desc, 3, what)
    points = loop_points(q)
    for k, joint in enumerate(joints):
        straight = None if close(joint["anchor"][:2], points[k], POSITION) else _straight(ctx, desc, q, point)
        assert_close(joint["anchor"][:2], points[k], f"the position of joint {k + 1} in {what}", POSITION,
                     mistakes=[] if straight is None else [Mistake("built_straight", straight[k], STRAIGHT_HINT)])
        assert_close(joint["axis"], [0.0, 0.0, 1.0], f"the axis of joint {k + 1} in {what}", DIRECTION)
    connects = [e for e in desc["equalities"] if e["type"] == "connect" and e["active"]]
    if not connects and any(e["type"] == "weld" and e["active"] for e in desc["equalities"]):
        fail(f"{what} closes the loop with a <weld>, which locks the orientation of link 3 as well as its end: "
             "three hinges and a weld leave no degree of freedom.",
             "The fourth joint is a revolute one: a <connect> between link 3's tip and the fixed point holds the "
             "points together and lets the link turn, '<equality><connect site1=\"tip\" site2=\"fixed\"/>"
             "</equality>'.", "weld_for_connect")
    if len(connects) != 1 or not connects[0]["to_world"]:
        fail(f"{what} must close the loop with one active <connect> between link 3 and the world; it has "
             f"{len(desc['equalities'])} equality constraint(s): "
             f"{', '.join(e['type'] for e in desc['equalities']) or 'none'}.",
             '<equality><connect site1="tip" site2="fixed"/></equality>, with the site "fixed" on the world body.',
             "no_connect")
    p1, p2 = (np.asarray(connects[0][k], dtype=float) for k in ("point1", "point2"))
    ignored = [] if tuple(point) == FIXED_POINT else [Mistake(
        "ignored_argument", FIXED_POINT, "The world's end of the connect sits at the sheet's fixed point (0.5, 0, 0) "
        "whatever fixed_point is given: place the site \"fixed\" at fixed_point.")]
    assert_close(p2, point, f"where the connect holds the end of link 3 in {what}", POSITION, mistakes=ignored,
                 note="A body-anchored connect holds the point where it is in the model as written: build the model "
                      "in the assembled configuration, or join two sites.")
    assert_close(p1, p2, f"the two points the connect joins in {what}", POSITION,
                 context="(the loop closes in the model as written)")


def _unturned(desc, q, links=UNTURNED):
    """``(links, points)``: the first of ``links`` (each a tuple of links) whose model built unturned in the
    configuration ``q`` gives the student's model ``desc``: every joint where it is, and the point where the connect
    holds the moving body where the end of link 3 is (``loop_points``); None where none does."""
    connects = [e for e in desc["equalities"] if e["type"] == "connect" and e["active"] and e.get("to_world")]
    joints = desc["joints"]
    if len(connects) != 1 or connects[0].get("point1") is None or len(joints) != 3:
        return None
    mine = np.vstack([np.asarray(p, dtype=float)[:2] for p in [j["anchor"] for j in joints] + [connects[0]["point1"]]])
    for unturned in links:
        points = loop_points([0.0 if i in unturned else angle for i, angle in enumerate(np.asarray(q)[:3])])
        if close(mine, points, POSITION):
            return unturned, points
    return None


def _straight(ctx, desc, q, point):
    """The joints and the end of link 3 of the model built with some links unturned, where that model is the
    student's (``_unturned``) in the configuration ``q`` shown and, with the same links unturned, in the other
    configuration the check asks (a fixed point on the ground for the sheet's, the sheet's for the other); None
    otherwise: a model that is nearly straight, or straight in one configuration by its angles' chance (angles
    cast to whole numbers), is no model built straight."""
    found = _unturned(desc, q)
    if found is None:
        return None
    other = GROUND_POINT if tuple(point) == FIXED_POINT else FIXED_POINT
    q_other, what = _configuration(ctx, other)
    try:
        again = _unturned(_model(ctx, q_other, what, other), q_other, [found[0]])
    except CheckFailure:
        return None
    except StudentFault as exc:
        if ends_grading(exc):
            raise
        return None
    return found[1] if again is not None else None


@check(2, title="four_bar(...): released at rest in an unbalanced configuration, MuJoCo's acceleration along the "
       "linkage's motion is the reference's, of HDPE on the Earth and of aluminium on the Moon", stage=STAGE_VALUES,
       group="model")
def check_model_dynamics(ctx):
    q = ctx.reference(p04.assemble, DYNAMICS_TARGETS, FIXED_POINT)["q"]
    _assert_alpha(ctx, q, HDPE, EARTH)
    assert_link_masses(*_assert_alpha(ctx, q, OTHER_DENSITY, OTHER_GRAVITY), 3, OTHER_DENSITY,
                       lambda density: ctx.reference(p03.link_inertia, LENGTH, WIDTH, HEIGHT, density)["mass"])


#: the model is also built of another material under another gravity: the acceleration at rest follows g (the
#: density cancels from it), the links' masses follow the density
OTHER_DENSITY, OTHER_GRAVITY = ALUMINIUM, MOON


def _gravity_slips(desc, gravity):
    """The known mistakes of the model's gravity that leave nothing to accelerate the linkage, each where the model's
    gravity is the slip's (a linkage at rest is no evidence of which): none at all, or the given one along z, out of
    the plane of the motion (MuJoCo's default axis)."""
    try:
        mine = np.asarray(desc["gravity"], dtype=float)
    except (KeyError, TypeError, ValueError):
        return []
    if mine.shape != (3,):
        return []
    if close(mine, np.zeros(3), EXACT):
        return [Mistake("missing_gravity", 0.0, "Nothing accelerates the linkage: the model has no gravity; it must "
                        "be (0, -g, 0), in the plane of the motion.")]
    if close(np.abs(mine), [0.0, 0.0, gravity], EXACT):
        return [Mistake("gravity_axis", 0.0, "Nothing accelerates the linkage: your gravity points along z, out of "
                        "the plane of the motion (MuJoCo's default axis); it must be (0, -g, 0).")]
    return []


def _assert_alpha(ctx, q, density, gravity):
    """The acceleration along the linkage's motion of the model of ``density`` under ``gravity`` is the
    reference's; returns the student's model description and what it is called."""
    expected = ctx.reference(p04.tangent_acceleration, q, density, gravity)
    what = f"four_bar({density:g}, {gravity:g}, q = {np.round(q, 6).tolist()})"
    desc = _model(ctx, q, what, density=density, gravity=gravity)
    mistakes = _gravity_slips(desc, gravity)
    if gravity != EARTH:
        sheet = ctx.reference(p04.tangent_acceleration, q, density, EARTH)["alpha"]
        mistakes.append(Mistake("ignored_argument", sheet, "The model's gravity is the Earth's 9.81 whatever gravity "
                                "four_bar is given: write <option gravity=\"0 -g 0\"/> with the g passed in."))
    assert_close(_along(desc, what), expected["alpha"], f"the acceleration along the linkage's motion in {what}",
                 ALONG, mistakes=mistakes,
                 note="alpha = t.T qfrc_smooth / (t.T M t) with t the unit null vector of the constraint Jacobian: "
                      "exact even though MuJoCo's soft constraint lets qacc itself differ from alpha t.")
    return desc, what


@check(1, title="4(b): in your balanced configuration your MuJoCo model stays at rest (no acceleration along the "
       "linkage's motion), for the sheet's fixed point and another point on the ground", stage=STAGE_VALUES,
       group="balance")
def check_model_at_rest(ctx):
    for point in (FIXED_POINT, _ground_point(ctx)):
        q = as_array(ctx.student(p04.balanced, point), _call(point), (4,))
        what = f"four_bar(950, 9.81, q = {np.round(q, 6).tolist()}, fixed_point = ({point[0]:g}, 0, 0))"
        alpha = _along(_model(ctx, q, what, point), what)
        assert_close(alpha, 0.0, f"the acceleration along the linkage's motion in {what}", AT_REST,
                     note="A balanced four-bar released at rest does not start to move (it is unstable, so it does "
                          "after a while).")
