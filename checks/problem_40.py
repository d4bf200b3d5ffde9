"""Checks of problem 40: the equations of motion of two point masses (``equations_of_motion_symbolic``).

The answer is symbolic; it is evaluated inside the sandbox at points the grader sends (never parsed here).  First
its shape and symbols, then physics that needs no reference (``M`` symmetric positive-definite, ``f`` from the
student's own ``M`` by Lagrange's equations), then the values against the reference at random points.
"""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    STAGE_RANDOM,
    STAGE_SHAPE,
    STAGE_STRUCTURE,
    Mistake,
    Tol,
    as_array,
    assert_close,
    check,
    fail,
    format_array,
)
from probes import problem_40 as p40

TITLE = "Equations of Motion for a System of Particles"

NAMES = ("q1", "q2", "dq1", "dq2", "l1", "l2", "m1", "m2", "g")
H = 1e-5
DIFFERENCES = Tol("finite differences, h = 1e-5", 1e-6, 1e-6)
_SEEDS = st.integers(0, 2**32 - 1)


def _point(rng):
    return dict(zip(NAMES, [*rng.uniform(-3, 3, 4), *rng.uniform(0.2, 3.0, 5)]))


@st.composite
def _points(draw):
    return ([_point(np.random.default_rng(draw(_SEEDS)))],)


def _describe(args):
    return ", ".join(f"{name} = {value:.4g}" for name, value in args[0][0].items())


def _values(got, key, k=0):
    if not isinstance(got, dict):
        fail(f"the probe could not evaluate your answer: {str(got)[:200]}")
    if "problem" in got:
        fail(f"equations_of_motion_symbolic(): {got['problem']}.",
             "Return (M, f, g): sympy matrices 2 x 2, 2 x 1, 2 x 1 in the symbols of symbols().", "format")
    shape = (2, 2) if key == "M" else (2,)
    return as_array(got[key][k], key, shape)


@check(1, title="equations_of_motion_symbolic() returns M (2 x 2), f and g (2 x 1) in the symbols q1 q2 dq1 dq2 l1 l2 "
       "m1 m2 g", stage=STAGE_SHAPE, group="symbolic")
def check_shapes(ctx):
    point = _point(np.random.default_rng(40))
    got = ctx.student(p40.evaluate, [point], timeout=30)
    for key in ("M", "f", "g"):
        _values(got, key)


@check(1, title="M is symmetric positive-definite at random points", stage=STAGE_STRUCTURE, group="symbolic")
def check_mass_matrix(ctx):
    def compare(got, expected, args):
        M = _values(got, "M")
        where = f"at {_describe(args)}"
        if np.abs(M - M.T).max() > 1e-9 * max(1.0, np.abs(M).max()):
            fail(f"M is not symmetric {where}:\n{format_array(M)}", "M = sum(m J.T J) is symmetric.", "not_symmetric")
        if np.linalg.eigvalsh(0.5 * (M + M.T)).min() <= 0:
            fail(f"M is not positive-definite {where}:\n{format_array(M)}",
                 "The kinetic energy qd.T M qd / 2 of moving masses is positive: M = sum(m J.T J).",
                 "not_positive_definite")

    ctx.compare_random(p40.evaluate, _points(), name="M", tol=EXACT, compare=compare, examples=8,
                       describe=_describe)


def _shifted(point, h=H):
    """The point, then q shifted by +-h along q1 and q2, then along (dq1, dq2)."""
    q = np.array([point["q1"], point["q2"]])
    qd = np.array([point["dq1"], point["dq2"]])
    points = [point]
    for shift in (h * np.eye(2)[0], -h * np.eye(2)[0], h * np.eye(2)[1], -h * np.eye(2)[1], h * qd, -h * qd):
        points.append({**point, "q1": q[0] + shift[0], "q2": q[1] + shift[1]})
    return points


@st.composite
def _lagrange_points(draw):
    return (_shifted(_point(np.random.default_rng(draw(_SEEDS)))),)


@check(2, title="f satisfies Lagrange's equations with your own M: f = -Mdot qd + d/dq (qd.T M qd / 2)",
       stage=STAGE_STRUCTURE, group="symbolic")
def check_lagrange(ctx):
    def compare(got, expected, args):
        point = args[0][0]
        qd = np.array([point["dq1"], point["dq2"]])
        M = [_values(got, "M", k) for k in range(7)]
        f = _values(got, "f", 0)
        dT = np.array([qd @ (M[1] - M[2]) @ qd, qd @ (M[3] - M[4]) @ qd]) / (4 * H)
        lagrange = -(M[5] - M[6]) / (2 * H) @ qd + dT
        assert_close(f, lagrange, "f", DIFFERENCES, [
            Mistake("f_sign", -lagrange, "M qdd - f - g = 0: f is on the right-hand side, f = -sum(m J.T sigma) "
                    "with the bias acceleration sigma = d(J qd)/dq qd."),
        ], context=f"at {_describe((args[0][:1],))} (expected: Lagrange's equations with your own M)")

    ctx.compare_random(p40.evaluate, _lagrange_points(), name="f", tol=DIFFERENCES, compare=compare,
                       examples=8, describe=lambda args: _describe((args[0][:1],)))


@check(3, title="M, f and g at random points equal the reference's", stage=STAGE_RANDOM, group="symbolic")
def check_values(ctx):
    hints = {
        "M": [],
        "f": [("f_sign", -1.0, "M qdd - f - g = 0 puts f on the right-hand side: f = -sum(m J.T sigma).")],
        "g": [("gravity_sign", -1.0, "Gravity acts along -y: g = sum(J.T m (0, -g)), so g = -g (...) sin(...): "
               "it pulls the pendulum back towards q = 0.")],
    }

    def compare(got, expected, args):
        for key in ("M", "f", "g"):
            value = np.asarray(expected[key][0])
            assert_close(_values(got, key), value, key, EXACT,
                         [Mistake(name, factor * value, hint) for name, factor, hint in hints[key]],
                         context=f"at {_describe(args)}")

    ctx.compare_random(p40.evaluate, _points(), name="M, f, g", tol=EXACT, compare=compare, examples=10,
                       describe=_describe)
