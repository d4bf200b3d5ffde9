"""Checks of problem 45: the falling bar hits the second support; when does the first contact open?
(``impact_jacobian``, ``impulses``, ``opening_limit``).

The answers are symbolic; they are evaluated inside the sandbox at points the grader sends (never parsed here).
The physics decides the Jacobian (the gradients of both contacts at ``q- = (l, d, 0)``, by finite differences of the
sheet's constraints) and the impulses (a plastic impact leaves ``J qd+ = 0``: ``J M^-1 J.T Lam = -c_dot-``); the
limit of ``s`` is compared with the reference's at random parameter values.
"""

import numpy as np
from grader import strategies as st

from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_VALUES,
    Mistake,
    Tol,
    as_array,
    assert_close,
    check,
    close,
    engine_on,
    fail,
    transposed_shape_hint,
)
from probes import problem_45 as p45

TITLE = "Collision of Falling Bar"

NAMES = ("s", "l", "d", "m", "theta", "phid")
H = 1e-6
DIFFERENCES = Tol("finite differences, h = 1e-6", 1e-6, 1e-6)
IMPACT = Tol("after a plastic impact", 1e-8, 1e-8)
_SEEDS = st.integers(0, 2**32 - 1)
FORMS = {"J": "impact_jacobian() as a 2 x 3 sympy matrix", "Lam": "impulses() as a 2 x 1 sympy matrix",
         "s_limit": "opening_limit() as one sympy expression"}


def _point(rng):
    s, l, d, m, theta = rng.uniform(0.1, 2.0), rng.uniform(0.1, 1.5), rng.uniform(0.01, 0.3), *rng.uniform(0.2, 3, 2)
    return dict(zip(NAMES, map(float, (s, l, d, m, theta, -rng.uniform(0.1, 3.0)))))


def _points(key):
    """``(key, [point])``: one random point for the answer ``key``."""

    @st.composite
    def draw_points(draw):
        return key, [_point(np.random.default_rng(draw(_SEEDS)))]

    return draw_points()


def _describe(args):
    return ", ".join(f"{name} = {value:.4g}" for name, value in args[1][0].items())


def _value(got, key, expected=None, tol=None):
    """The answer ``key`` at the first point, or a failure that says why it cannot be graded; with ``expected``
    (the value asked for, within ``tol``): a matrix of the transposed shape whose transpose is it fails as a
    transpose."""
    transposed = got.get("transposed") if isinstance(got, dict) else None
    if transposed and expected is not None and engine_on() \
            and close(np.asarray(transposed[0], dtype=float), expected, tol):
        rows, columns = np.shape(expected)
        fail(f"{got['problem']}: the transposed shape, and its transpose is the {FORMS[key].split(' as ')[0]} "
             "asked for.", transposed_shape_hint((rows, columns)), "transpose")
    if isinstance(got, dict) and "problem" in got:
        fail(f"{got['problem']}.", f"Return {FORMS[key]} in the symbols of symbols().", "format")
    if not isinstance(got, list) or len(got) != 1:
        fail(f"the probe could not evaluate your answer: {str(got)[:200]}")
    return as_array(got[0], key, {"J": (2, 3), "Lam": (2,), "s_limit": ()}[key])


def _contacts(q, s, d):
    """``(c1, c2)``: the heights of the bar's lower edge over both supports (at 0 and at s) for ``q = (x, y, phi)``
    (problem data P45)."""
    x, y, phi = q
    return np.array([y * np.cos(phi) - (x - shift) * np.sin(phi) - d for shift in (0.0, s)])


@check(2, title="impact_jacobian() is the Jacobian of both contacts (c1, c2) at q- = (l, d, 0) (finite differences "
       "of the sheet's constraints) at random parameters", stage=STAGE_VALUES, group="jacobian")
def check_jacobian(ctx):
    def compare(got, expected, args):
        point = args[1][0]
        s, l, d = point["s"], point["l"], point["d"]
        q = np.array([l, d, 0.0])
        fd = np.column_stack([(_contacts(q + H * e, s, d) - _contacts(q - H * e, s, d)) / (2 * H) for e in np.eye(3)])
        other_side = fd.copy()
        other_side[1, 2] = -s - l
        assert_close(_value(got, "J", fd, DIFFERENCES), fd, "J", DIFFERENCES, [
            Mistake("jacobian_sign", -fd, "J = dc/dq with c = y cos phi - (x - s_k) sin phi - d (s_k = 0, s): at "
                    "phi = 0 its y-entries are +1."),
            Mistake("support_side", other_side, "The second support sits at x = +s: c2 = y cos phi - (x - s) sin phi "
                    "- d, whose phi-derivative at q- is s - l."),
            Mistake("swapped", fd[::-1], "The first row is the first (left) contact c1, the second the new "
                    "contact c2 at s."),
        ], context=f"at {_describe(args)} (expected: the gradients of c1 and c2 at q- = (l, d, 0))")

    ctx.compare_random(p45.evaluate, _points("J"), name="J", tol=DIFFERENCES, compare=compare, examples=8,
                       describe=_describe)


def _impact(point):
    """``(J, M, c_dot)`` of the sheet's impact at the point (numpy)."""
    s, l, m, theta, phid = (point[name] for name in ("s", "l", "m", "theta", "phid"))
    J = np.array([[0.0, 1.0, -l], [0.0, 1.0, s - l]])
    return J, np.diag([m, m, theta]), np.array([0.0, s * phid])


@check(3, title="impulses(): a plastic impact on both contacts stops them, J qd+ = c_dot- + J M^-1 J.T Lam = 0, "
       "at random parameters", stage=STAGE_VALUES, group="impulses")
def check_impulses(ctx):
    def compare(got, expected, args):
        J, M, c_dot = _impact(args[1][0])
        G = J @ np.linalg.solve(M, J.T)
        Lam = _value(got, "Lam")
        plastic = -np.linalg.solve(G, c_dot)
        assert_close(c_dot + G @ Lam, np.zeros(2), "J qd+", IMPACT, [
            Mistake("elastic", -c_dot, "A plastic impact (restitution 0) stops both contacts: Lam = -M_lam c_dot-. "
                    "Yours reverses their velocities (restitution 1, elastic)."),
            Mistake("impulse_sign", c_dot + G @ -plastic, "Lam = -M_lam c_dot- with M_lam = (J M^-1 J.T)^-1: the "
                    "impulses act through +J.T Lam and stop the closing contact."),
            Mistake("no_inverse", c_dot - G @ G @ c_dot, "Lam = -M_lam c_dot- with M_lam = (J M^-1 J.T)^-1, the "
                    "inverse of J M^-1 J.T."),
        ], context=f"at {_describe(args)} (with J = [[0, 1, -l], [0, 1, s - l]], M = diag(m, m, theta), c_dot- = "
                   f"(0, s phid); qd+ = qd- + M^-1 J.T Lam)")

    ctx.compare_random(p45.evaluate, _points("Lam"), name="Lam", tol=IMPACT, compare=compare, examples=8,
                       describe=_describe)


@check(3, title="opening_limit(): the left contact opens (Lam1 < 0) iff s < s_limit; s_limit equals the "
       "reference's at random parameters", stage=STAGE_RANDOM, group="limit")
def check_opening_limit(ctx):
    def compare(got, expected, args):
        point = args[1][0]
        l, m, theta = point["l"], point["m"], point["theta"]
        limit = float(np.asarray(expected[0]))
        assert_close(_value(got, "s_limit"), limit, "s_limit", EXACT, [
            Mistake("inequality_reversed", 2 * l - limit, "Lam1 < 0 means the left contact would have to pull: "
                    "with phid- < 0, look again at which side of its root Lam1 is negative."),
            Mistake("no_offset", limit - l, "The limit is measured from the first support, like s, and the centre "
                    "of gravity sits at l- from it."),
            Mistake("ratio_inverted", l + m * l / theta, "Check the units: the limit is a length, and m l / theta "
                    "is not one."),
        ], context=f"at {_describe(args)}")

    ctx.compare_random(p45.evaluate, _points("s_limit"), name="s_limit", tol=EXACT, compare=compare,
                       examples=10, describe=_describe)
