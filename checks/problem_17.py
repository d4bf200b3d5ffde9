"""Checks of problem 17: principal axes and four bodies that represent an inertia matrix.

A representation is judged by what it reproduces (total mass, centre of gravity at the origin, inertia matrix),
never by our numbers: eigenvector signs and orders, and so the points, legitimately differ.
"""

import numpy as np

from checks._figures import ellipsoid_drawer
from checks._rigid import FINITE, ROTATIONS, body_inertia, compact
from grader import strategies as st
from grader.checking import (
    STAGE_RANDOM,
    STAGE_STRUCTURE,
    CheckFailure,
    Mistake,
    Tol,
    as_array,
    assert_close,
    assert_rotation,
    check,
    close,
    fail,
)
from probes import problem_17 as p17

TITLE = "Visualize Inertia Matrices"

#: eigen-decompositions and square roots of well-separated moments
REPRODUCE = Tol("reproduced inertia", 1e-8, 1e-8)


def sheet_matrices(ctx):
    """The sheet's four inertia matrices and the mass (the package's constants)."""
    sheet = ctx.reference(p17.constants)
    return [sheet["MATRICES"][k] for k in sorted(sheet["MATRICES"], key=int)], float(sheet["MASS"])


@st.composite
def inertias(draw):
    """Inertia matrices in a random orientation, principal moments from second moments in [0.1, 3]."""
    A = draw(ROTATIONS)
    x2, y2, z2 = (draw(st.floats(0.1, 3.0, **FINITE)) for _ in range(3))
    return A @ np.diag([y2 + z2, x2 + z2, x2 + y2]) @ A.T


NOT_ROTATED_HINT = ("Your body has the inertia diag(I1, I2, I3): it is built along the principal axes but not turned "
                    "into B. Map every point (or the body's axes) with V, the matrix of eigenvectors: r_B = V @ r.")
ORIENTATION_HINT = ("Your body has the right principal moments but the wrong orientation: the k-th principal "
                    "direction is the k-th COLUMN of V (in the order of the moments), points map as r_B = V @ r "
                    "(not V.T @ r), and each distance belongs on its own principal axis.")


def assert_reproduces(J, B_I_G, name, note, scale_hints=(), where=""):
    """Fail unless the inertia ``J`` of the student's body equals ``B_I_G``; name the known mistakes."""
    moments = np.linalg.eigvalsh(B_I_G)
    mistakes = [Mistake("not_rotated", np.diag(moments), NOT_ROTATED_HINT),
                *(Mistake(mistake, B_I_G * factor, hint) for mistake, factor, hint in scale_hints)]
    try:
        assert_close(J, B_I_G, name, REPRODUCE, mistakes, context=where, note=note)
    except CheckFailure as exc:
        if not exc.diagnosis and close(np.linalg.eigvalsh(J), moments, REPRODUCE):
            fail(exc.message, ORIENTATION_HINT, "orientation", evidence=exc.evidence)
        raise


def _points_inertia(masses, points):
    """Inertia about the origin of point masses."""
    return sum(m * ((r @ r) * np.eye(3) - np.outer(r, r)) for m, r in zip(masses, points))


def _entry(got, key):
    if not isinstance(got, dict) or key not in got or not isinstance(got[key], dict):
        fail(f"inertia_representations must return a dict with an entry {key!r} (a dict), got "
             f"{str(got)[:200]}")
    return got[key]


def assert_points(got, B_I_G, m, key, n, scale_hints=(), where=""):
    entry = _entry(got, key)
    masses = as_array(entry.get("masses"), f"{key}['masses']", (n,))
    points = as_array(entry.get("points"), f"{key}['points']", (n, 3))
    assert_close(masses.sum(), m, f"the total mass of {key}", REPRODUCE, context=where)
    assert_close(masses @ points / m, np.zeros(3), f"the centre of gravity of {key}", REPRODUCE, context=where,
                 note="The representation must have its centre of gravity at the origin.")
    assert_reproduces(_points_inertia(masses, points), B_I_G, f"the inertia of your {key}",
                      "Your points must reproduce the inertia matrix.", scale_hints, where)


def assert_solid(got, B_I_G, m, key, size, body, scale_hints=(), where=""):
    entry = _entry(got, key)
    assert_close(entry.get("mass"), m, f"{key}['mass']", REPRODUCE, context=where)
    dims = as_array(entry.get(size), f"{key}[{size!r}]", (3,))
    V = as_array(entry.get("V"), f"{key}['V']", (3, 3))
    if abs(abs(np.linalg.det(V)) - 1.0) > 1e-6:
        assert_rotation(V, f"{key}['V']")
    assert_reproduces(V @ body_inertia(body, m, *dims) @ V.T, B_I_G,
                      f"the inertia of your {key} (V @ I_body @ V.T)", f"The {key} with {size} {compact(dims)} "
                      "along the columns of V must reproduce the inertia matrix.", scale_hints, where)


def _representation_check(ctx, assertion):
    """``assertion(got, B_I_G, m, where)`` on the sheet's four matrices, then on random ones."""
    matrices, mass = sheet_matrices(ctx)
    for k, B_I_G in enumerate(matrices, 1):
        assertion(ctx.student(p17.representations, B_I_G, mass), B_I_G, mass,
                  f"for the sheet's matrix {k} (m = {mass:g})")
    ctx.compare_random(
        p17.representations, st.tuples(inertias(), st.floats(0.5, 20.0, **FINITE)),
        name="inertia_representations", tol=REPRODUCE, examples=10,
        compare=lambda got, expected, args: assertion(got, *args, ""),
        describe=lambda args: f"B_I_G = {compact(args[0])}, m = {args[1]!r}",
    )


@check(1, title="principal_axes: ascending moments and a proper rotation V with V diag(I1, I2, I3) V.T = B_I_G",
       stage=STAGE_STRUCTURE, group="principal_axes")
def check_principal_axes(ctx):
    def compare(got, expected, args):
        (B_I_G,) = args
        if not isinstance(got, list) or len(got) != 2:
            fail(f"principal_axes must return (moments, V), got {str(got)[:200]}")
        moments = as_array(got[0], "the moments", (3,))
        V = as_array(got[1], "V", (3, 3))
        if np.any(np.diff(moments) < -1e-12):
            fail(f"the principal moments must be sorted I1 <= I2 <= I3, got {compact(moments)}.",
                 "np.linalg.eigh returns them in ascending order; keep the columns of V in the same order.",
                 "unsorted")
        assert_close(moments, expected[0], "the principal moments", REPRODUCE)
        assert_rotation(V, "V")
        try:
            assert_close(V @ np.diag(moments) @ V.T, B_I_G, "V @ diag(moments) @ V.T", REPRODUCE)
        except CheckFailure as exc:
            if close(V.T @ np.diag(moments) @ V, B_I_G, REPRODUCE):
                fail(exc.message, "The principal axes are the COLUMNS of V (B_I_G = V @ diag @ V.T): you returned "
                     "them as rows.", "transpose", evidence=exc.evidence)
            raise

    ctx.student(p17.principal_axes, sheet_matrices(ctx)[0][2])
    ctx.compare_random(p17.principal_axes, st.tuples(inertias()), name="principal_axes", tol=REPRODUCE,
                       compare=compare, examples=10, describe=lambda args: f"B_I_G = {compact(args[0])}")


@check(1, title="case 1: six points of mass m/6 reproduce m, the centre of gravity 0 and the inertia (sheet's and "
       "random matrices)", stage=STAGE_RANDOM, group="six_points")
def check_six_points(ctx):
    hints = [("mass_per_point", 6.0, "Each of the six points has the mass m/6.")]
    _representation_check(ctx, lambda got, I, m, where: assert_points(got, I, m, "six_points", 6, hints, where))


@check(2, title="case 2: four points of mass m/4 reproduce m, the centre of gravity 0 and the inertia (sheet's "
       "and random matrices)", stage=STAGE_RANDOM, group="four_points")
def check_four_points(ctx):
    hints = [("mass_per_point", 4.0, "Each of the four points has the mass m/4.")]
    _representation_check(ctx, lambda got, I, m, where: assert_points(got, I, m, "four_points", 4, hints, where))


@check(1, title="case 3: the ellipsoid (full axes along V) reproduces the inertia (sheet's and random matrices)",
       stage=STAGE_RANDOM, group="ellipsoid")
def check_ellipsoid(ctx):
    hints = [("semi_axes", 0.25, "axes are the FULL axes of the ellipsoid (problem data): twice the semi-axes.")]
    _representation_check(ctx, ellipsoid_drawer(ctx, "Problem 17: the ellipsoids of the sheet's matrices",
                                                lambda got, I, m, where: assert_solid(got, I, m, "ellipsoid", "axes",
                                                                                      "ellipsoid", hints, where)))


@check(1, title="case 4: the cuboid (edges along V) reproduces the inertia (sheet's and random matrices)",
       stage=STAGE_RANDOM, group="cuboid")
def check_cuboid(ctx):
    hints = [("one_third", 0.25, "Your edges are half as long as needed: the cuboid's moments are m/12 (b² + c²), "
              "cyclic, so a = sqrt(6/m (-I1 + I2 + I3)).")]
    _representation_check(ctx, lambda got, I, m, where: assert_solid(got, I, m, "cuboid", "edges",
                                                                      "cuboid", hints, where))
