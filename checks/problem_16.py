"""Checks of problem 16: inertia of a cuboid, an ellipsoid and six particles (numeric and symbolic), and the
inverse maps from principal moments to dimensions.

Symbolic answers are evaluated inside the probe at points the check draws; the grader never parses them.
"""

import numpy as np

from checks._rigid import FINITE, body_inertia, compact
from grader import strategies as st
from grader.checking import EXACT, STAGE_RANDOM, Mistake, as_array, assert_close, check, fail
from probes import problem_16 as p16

TITLE = "Computing Inertia Matrices"

POSITIVE = st.floats(0.1, 5.0, **FINITE)
MASSES = st.floats(0.1, 20.0, **FINITE)
BODY_ARGS = st.tuples(MASSES, POSITIVE, POSITIVE, POSITIVE)

ONE_THIRD_HINT = ("The cuboid's moments are m/12 (b² + c²), cyclic, with the full edge lengths; m/3 (b² + c²) is "
                  "the formula with half edges (or the moment about an edge).")
SEMI_AXES_HINT = ("a, b, c are the FULL axes of the ellipsoid (problem data): the semi-axes are a/2, b/2, c/2, so "
                  "I1 = m/5 ((b/2)² + (c/2)²) = m/20 (b² + c²), cyclic.")
PARTICLE_MASS_HINT = "Each of the six particles has the mass m/6, not m."
PARTICLE_POSITION_HINT = "The particles sit at the face centres, (±a/2, 0, 0), ..., not at (±a, 0, 0)."
AXES_HINT = "The moment about the 1-axis involves the extents along the OTHER two axes: I1 ~ b² + c², cyclic."


def _diag(m, a, b, c, factor):
    return factor * m * np.diag([b**2 + c**2, a**2 + c**2, a**2 + b**2])


def body_mistakes(name, m, a, b, c):
    """What a body's inertia is with each known mistake."""
    swapped = _diag(m, a, b, c, 1.0)[::-1, ::-1]
    common = [Mistake("wrong_axes", swapped * {"cuboid": 1 / 12, "ellipsoid": 1 / 20, "particles": 1 / 12}[name],
                      AXES_HINT)]
    return common + {
        "cuboid": [Mistake("one_third", _diag(m, a, b, c, 1 / 3), ONE_THIRD_HINT)],
        "ellipsoid": [Mistake("semi_axes", _diag(m, a, b, c, 1 / 5), SEMI_AXES_HINT),
                      Mistake("cuboid_formula", _diag(m, a, b, c, 1 / 12), "That is the cuboid's inertia: an "
                              "ellipsoid has m/5 times the sum of two squared SEMI-axes.")],
        "particles": [Mistake("mass_per_particle", _diag(m, a, b, c, 1 / 2), PARTICLE_MASS_HINT),
                      Mistake("positions", _diag(m, a, b, c, 1 / 3), PARTICLE_POSITION_HINT)],
    }[name]


def _describe_body(args):
    return "(m, a, b, c) = ({:.6g}, {:.6g}, {:.6g}, {:.6g})".format(*args)


# ------------------------------------------------------------------------------------ point masses


@st.composite
def point_masses(draw):
    n = draw(st.integers(1, 6))
    masses = np.array([draw(MASSES) for _ in range(n)])
    points = np.array([[draw(st.floats(-3.0, 3.0, **FINITE)) for _ in range(3)] for _ in range(n)])
    return masses, points


def _point_mass_mistakes(args, expected):
    masses, points = args
    about_origin = sum(m * ((r @ r) * np.eye(3) - np.outer(r, r)) for m, r in zip(masses, points))
    return [
        Mistake("about_origin", about_origin, "The inertia is about the centre of gravity: measure the points from "
                "r_G = sum m_i r_i / sum m_i, not from the origin."),
        Mistake("sign_flip", -np.asarray(expected), "I = sum m_i (|d_i|² E - d_i d_i^T): the squared norm on the "
                "diagonal is positive, the outer product is subtracted."),
    ]


@check(1, title="centre_of_gravity(masses, points) = sum m_i r_i / sum m_i on random point masses",
       stage=STAGE_RANDOM, group="centre_of_gravity")
def check_centre_of_gravity(ctx):
    def mistakes(args, expected):
        masses, points = args
        return [Mistake("unweighted", points.mean(axis=0), "Weight each point by its mass: r_G = sum m_i r_i / "
                        "sum m_i."),
                Mistake("not_divided", masses @ points, "Divide by the total mass sum m_i.")]

    ctx.student(p16.centre_of_gravity, [1.0, 3.0], [[0.0, 0.0, 0.0], [1.0, 2.0, 3.0]])
    ctx.compare_random(p16.centre_of_gravity, point_masses(), name="centre_of_gravity", tol=EXACT,
                       mistakes=mistakes, examples=10)


@check(1, title="point_masses_inertia(masses, points): the inertia about their centre of gravity (random point "
       "masses)", stage=STAGE_RANDOM, group="point_masses")
def check_point_masses(ctx):
    ctx.student(p16.point_masses, [1.0, 3.0], [[0.0, 0.0, 0.0], [1.0, 2.0, 3.0]])
    ctx.compare_random(p16.point_masses, point_masses(), name="point_masses_inertia", tol=EXACT,
                       mistakes=_point_mass_mistakes, examples=10)


# ------------------------------------------------------------------------------------ the three bodies


def _body_check(ctx, name):
    ctx.student(p16.body, name, 1.0, 1.0, 2.0, 3.0)
    ctx.compare_random(
        p16.body, BODY_ARGS.map(lambda args: (name, *args)), name=f"{name}_inertia(m, a, b, c)",
        tol=EXACT, mistakes=lambda args, expected: body_mistakes(*args), examples=10,
        describe=lambda args: _describe_body(args[1:]),
    )


@check(1, title="cuboid_inertia(m, a, b, c) = m/12 diag(b²+c², a²+c², a²+b²) (random values)",
       stage=STAGE_RANDOM, group="cuboid")
def check_cuboid(ctx):
    _body_check(ctx, "cuboid")


@check(1, title="ellipsoid_inertia(m, a, b, c) with full axes a, b, c: m/20 diag(b²+c², a²+c², a²+b²) (random "
       "values)", stage=STAGE_RANDOM, group="ellipsoid")
def check_ellipsoid(ctx):
    _body_check(ctx, "ellipsoid")


@check(1, title="particles_inertia(m, a, b, c): six particles m/6 at the face centres (random values)",
       stage=STAGE_RANDOM, group="particles")
def check_particles(ctx):
    _body_check(ctx, "particles")


# ------------------------------------------------------------------------------------ symbolic


def _symbolic_check(ctx, name):
    points = ctx.draw(lambda rng: rng.uniform(0.2, 3.0, size=(5, 4)))
    expected = [ctx.reference(p16.body, name, *map(float, point)) for point in points]
    got = ctx.student(p16.symbolic, name, points)
    if isinstance(got, str):
        fail(f"{name}_inertia_symbolic() cannot be evaluated: {got}.",
             "Return a 3 x 3 sympy.Matrix in the symbols m, a, b, c (sympy.symbols('m a b c', positive=True)).")
    values = as_array(got, f"{name}_inertia_symbolic() evaluated at {len(points)} points", (len(points), 3, 3))
    for point, value, target in zip(points, values, expected):
        m, a, b, c = point
        assert_close(value, target, f"{name}_inertia_symbolic()", EXACT, body_mistakes(name, m, a, b, c),
                     context=f"at (m, a, b, c) = {compact(point)}")


@check(1, title="cuboid_inertia_symbolic() equals the cuboid's inertia at random (m, a, b, c)",
       stage=STAGE_RANDOM, group="symbolic_cuboid")
def check_symbolic_cuboid(ctx):
    _symbolic_check(ctx, "cuboid")


@check(1, title="ellipsoid_inertia_symbolic() equals the ellipsoid's inertia (full axes) at random (m, a, b, c)",
       stage=STAGE_RANDOM, group="symbolic_ellipsoid")
def check_symbolic_ellipsoid(ctx):
    _symbolic_check(ctx, "ellipsoid")


@check(1, title="particles_inertia_symbolic() equals the six particles' inertia at random (m, a, b, c)",
       stage=STAGE_RANDOM, group="symbolic_particles")
def check_symbolic_particles(ctx):
    _symbolic_check(ctx, "particles")


# ------------------------------------------------------------------------------------ part (b)


@st.composite
def moments(draw):
    """A mass and principal moments that satisfy the triangle inequality."""
    x2, y2, z2 = (draw(st.floats(0.05, 3.0, **FINITE)) for _ in range(3))
    return draw(MASSES), y2 + z2, x2 + z2, x2 + y2


@check(2, title="part (b): the dimensions of each body reproduce diag(I1, I2, I3) (random moments)",
       stage=STAGE_RANDOM, group="dimensions")
def check_dimensions(ctx):
    halved = {"cuboid": ("one_third", ONE_THIRD_HINT), "ellipsoid": ("semi_axes", SEMI_AXES_HINT),
              "particles": ("positions", PARTICLE_POSITION_HINT)}

    def compare(got, expected, args):
        m, *I = args
        if not isinstance(got, dict):
            fail(f"part_b must return a dict with the keys cuboid, ellipsoid, particles, got {str(got)[:200]}")
        for name in ("cuboid", "ellipsoid", "particles"):
            dims = as_array(got.get(name), f"the dimensions (a, b, c) of the {name}", (3,))
            reproduced = body_inertia(name, m, *dims)
            mistakes = [Mistake(*halved[name][:1], np.diag(I) / 4, halved[name][1])]
            if name == "particles":
                mistakes.append(Mistake("mass_per_particle", np.diag(I) / 6, PARTICLE_MASS_HINT))
            assert_close(reproduced, np.diag(I), f"the {name}'s inertia with your dimensions {compact(dims)}",
                         EXACT, mistakes)

    ctx.student(p16.dimensions, 1.0, 2.0, 2.5, 3.0)
    ctx.compare_random(p16.dimensions, moments(), name="part_b", tol=EXACT, compare=compare, examples=10,
                       describe=lambda args: "(m, I1, I2, I3) = ({:.6g}, {:.6g}, {:.6g}, {:.6g})".format(*args))
