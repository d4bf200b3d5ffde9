"""Shared checks of the dynamics problems (24, 37, 38, 46).

* Random trees with masses and inertias as plain data (``tree_cases``, ``rich_case``, from the case factory
  ``checks._cases``), in the format of ``probes._dynamics`` (numpy only: rotations from quaternions, inertias from
  second moments).
* The sheet's robot (P32) and walker (P25) as plain data (``ROBOT``, ``WALKER``).
* Physics checks on the ``_dynamics.lagrange`` probe, judged on the student's own model: ``M`` symmetric
  positive-definite, the kinetic energy of the student's own Jacobians, ``g`` as minus the gradient of the
  student's own potential energy, Lagrange's equations for ``f`` with the student's own ``M``.  The reference's
  reply at the same case only says whether the student's model is real (``checks._real``): a model that does
  nothing is consistent with itself and earns nothing.
* ``compare_mfg``: ``M``, ``f``, ``g`` against the reference with the mistake catalogue of ``_dynamics.mfg_mistakes``.
* Runs (simulations): the first departure from a reference run, and figures; a start that is not the given one
  told with the slip of a typed value that makes it (``wrong_start``), or, where some of its parts are the sheet's
  whatever is passed, as those arguments ignored (``defaulted_blocks``).
* Right-hand sides along a run: called at several states in turn on one tree, as an integrator calls them, they
  give what they give on a fresh tree (``assert_fresh_along_a_run``): a mass matrix computed once and reused is
  ``stale_mass_matrix``.
"""

import numpy as np

from grader import strategies as st
from grader.checking import (
    EXACT,
    CheckFailure,
    Mistake,
    Tol,
    as_array,
    assert_close,
    close,
    diagnose,
    fail,
    figure,
    format_array,
)

from ._cases import (
    NQ,
    SEEDS,
    case_strategy,
    coordinate_count,
    draw_tree,
    joint_lines,
    random_frames,
    random_rotation,
    rich_joints,
    rich_values,
    values,
)
from ._effects import same, shown
from ._real import mass_matrix_flaw, rank_flaw, real, require_real
from ._shapes import as_list

__all__ = [
    "defaulted_blocks",
    "wrong_start",
    "H",
    "LAGRANGE_DIFFERENCES",
    "KINDS",
    "I_GRAV",
    "ROBOT",
    "WALKER",
    "MFG_HINTS",
    "trees",
    "tree_cases",
    "rich_case",
    "robot_cases",
    "describe_case",
    "check_spd",
    "check_kinetic_energy",
    "check_gravity_gradient",
    "check_lagrange",
    "compare_mfg",
    "first_departure",
    "assert_run",
    "assert_event_found",
    "ended_early",
    "run_figure",
    "run_array",
    "same_crossings",
    "assert_energy_conserved",
    "subsample",
    "ALONG_A_RUN_HINT",
    "assert_fresh_along_a_run",
]

#: step of the finite differences of the physics checks (central differences: error ~ h^2)
H = 1e-5
#: the physics checks of the ``_dynamics.lagrange`` probe: the student's own f and g against Lagrange's equations
#: and the gradient of the potential, from differences of their own M and positions on random trees with masses
#: and inertias (f is a difference of quadratic forms in M over 4 h: a looser bound than the kinematics')
LAGRANGE_DIFFERENCES = Tol("finite differences, h = 1e-5", 1e-5, 1e-5)
#: symmetry and positive definiteness of M
SPD = Tol("symmetric positive-definite", 1e-9, 1e-9)
KINDS = ("rotational", "translational", "rolling_contact", "virtual_3dof", "rigid")
#: gravity of the random trees, off the axes so that a frame mix-up shows
I_GRAV = np.array([0.3, -9.81, 0.5])
#: keeps each entry of a random quaternion away from zero
_NUDGE = 1e-9


def _inertia(rng):
    """An inertia matrix: principal moments from second moments (triangle inequality), randomly oriented."""
    x2, y2, z2 = rng.uniform(0.05, 1.0, 3)
    A = random_rotation(rng, _NUDGE)
    return A @ np.diag([y2 + z2, x2 + z2, x2 + y2]) @ A.T


def _joint(rng, kind, nq, plain=False):
    if plain:
        joint = {"P_r_PDp": np.zeros(3), "A_PDp": np.eye(3), "S_r_SDs": np.array([0.0, 0.5, 0.0]), "A_SDs": np.eye(3)}
    else:
        joint = random_frames(rng, _NUDGE)
    if kind == "rolling_contact":
        joint["r"] = 0.5 if plain else float(rng.uniform(0.1, 1.0))
    if kind == "test":
        joint["c"], joint["U"] = rng.uniform(0.5, 1.5, nq), rng.uniform(-1, 1, (3, nq))
    return joint


def _body(rng, k, plain=False):
    if plain:
        return {"name": f"body_{k}", "m": 1.0, "I": np.diag([0.1, 0.2, 0.3])}
    return {"name": f"body_{k}", "m": float(rng.uniform(0.2, 3.0)), "I": _inertia(rng)}


@st.composite
def trees(draw, kinds=KINDS, max_joints=4):
    """Tree descriptions with masses and inertias: one to ``max_joints`` joints of the given ``kinds``, each at a
    random earlier body (shrinking towards a chain), geometry, mass and inertia from a seed per joint (seed 0: no
    offsets but the successor's centre of gravity, aligned frames, a unit mass); coordinates numbered in a random
    order.  The first joint moves, so ``nq >= 1``; every moving body has mass and inertia, so ``M`` is positive
    definite."""

    def root(draw):
        seed = draw(SEEDS)
        return _body(np.random.default_rng(seed), 0, seed == 0)

    def member(draw, k, kind):
        seed = draw(SEEDS)
        rng = np.random.default_rng(seed)
        joint = _joint(rng, kind, NQ[kind], seed == 0)
        return joint, _body(rng, k + 1, seed == 0), NQ[kind]

    return draw_tree(draw, kinds, st.integers(1, max_joints), root, member)


def tree_cases(kinds=KINDS, extra=(), max_joints=4):
    """``(description, q, qd, I_grav, *extra)`` with coordinates and velocities in [-2, 2] (from seeds, shrinking
    towards zero)."""
    return case_strategy(trees(kinds, max_joints), 2, (I_GRAV, *extra))


def rich_case(kinds=KINDS, extra=(), seed=37):
    """A fixed case in the format of ``tree_cases`` that exercises every term: a chain through all ``kinds`` and a
    branch at body 1, random geometry, masses and inertias, coordinates numbered in random order and values bounded
    away from zero."""
    rng = np.random.default_rng(seed)
    joints = rich_joints(rng, kinds, lambda rng, kind: _joint(rng, kind, NQ[kind]), NQ.__getitem__)
    bodies = [_body(rng, k) for k in range(len(joints) + 1)]
    q, qd = rich_values(rng, coordinate_count({"joints": joints}), 2)
    return ({"bodies": bodies, "joints": joints}, q, qd, I_GRAV, *extra)


def _plain_joint(kind, parent, q_index, P_r_PDp=(0.0, 0.0, 0.0), A_PDp=np.eye(3), S_r_SDs=(0.0, 0.0, 0.0), **extra):
    return {"kind": kind, "parent": parent, "q_index": list(q_index), "P_r_PDp": np.array(P_r_PDp, dtype=float),
            "A_PDp": np.array(A_PDp, dtype=float), "S_r_SDs": np.array(S_r_SDs, dtype=float), "A_SDs": np.eye(3),
            **extra}


#: the robot arm of problem data P32: three links (m = 3, I = diag(0.2, 0.02, 0.2)) and a massless end effector
ROBOT = {
    "bodies": [{"name": "ground", "m": 0.0, "I": np.zeros((3, 3))},
               *({"name": f"link_{k}", "m": 3.0, "I": np.diag([0.2, 0.02, 0.2])} for k in (1, 2, 3)),
               {"name": "end_effector", "m": 0.0, "I": np.zeros((3, 3))}],
    "joints": [
        _plain_joint("rotational", 0, [0], S_r_SDs=(0.0, 0.5, 0.0)),
        _plain_joint("rotational", 1, [1], P_r_PDp=(0.0, -0.5, 0.0), A_PDp=[[0, 0, 1], [0, 1, 0], [-1, 0, 0]],
                     S_r_SDs=(0.0, 0.5, 0.0)),
        _plain_joint("rotational", 2, [2], P_r_PDp=(0.0, -0.5, 0.0), A_PDp=[[0, 0, -1], [0, 1, 0], [1, 0, 0]],
                     S_r_SDs=(0.0, 0.5, 0.0)),
        _plain_joint("rigid", 3, [], P_r_PDp=(0.0, -0.5, 0.0)),
    ],
}
#: the passive dynamic walker of problem data P25: l = 1, r = 0.5, dx = 0.05, dy = 0.7, legs m = 1,
#: I = diag(0.03, 0.01, 0.03)
WALKER = {
    "bodies": [{"name": "ground", "m": 0.0, "I": np.zeros((3, 3))},
               {"name": "stance_leg", "m": 1.0, "I": np.diag([0.03, 0.01, 0.03])},
               {"name": "swing_leg", "m": 1.0, "I": np.diag([0.03, 0.01, 0.03])}],
    "joints": [
        _plain_joint("rolling_contact", 0, [0], P_r_PDp=(0.0, 0.5, 0.0), S_r_SDs=(-0.05, 0.2, 0.0), r=0.5),
        _plain_joint("rotational", 1, [1], P_r_PDp=(-0.05, 0.7, 0.0), S_r_SDs=(-0.05, 0.7, 0.0)),
    ],
}


def robot_cases(description, nq, I_grav, bound=2.0):
    """``(description, q, qd, I_grav)`` for a fixed tree at random states."""

    @st.composite
    def draw_case(draw):
        return (description, values(draw(SEEDS), nq, bound), values(draw(SEEDS), nq, bound), I_grav)

    return draw_case()


def _compact(a):
    a = np.asarray(a, dtype=float)
    if a.shape == (3, 3) and np.allclose(a, np.eye(3)):
        return "E"
    return " ".join(format_array(a).split())


def describe_case(args):
    """A readable description of ``(description, q, qd, I_grav, ...)``."""
    description, q, qd, I_grav = args[:4]
    lines = [f"a tree of {len(description['bodies'])} bodies:"]
    for body in description["bodies"]:
        lines.append(f"  {body['name']}: m = {body['m']:.4g}, B_I_B = {_compact(body['I'])}")
    lines += joint_lines(description, _compact)
    lines += [f"  q = {_compact(q)}", f"  qd = {_compact(qd)}", f"  I_grav = {_compact(I_grav)}"]
    return "\n".join(lines)


# ------------------------------------------------------------------------------------------ physics checks

MFG_HINTS = {
    "missing_gyroscopic": "f misses the gyroscopic term: f = -sum(J_S.T m sigma_S + J_R.T (I sigma_R + skew(omega) I "
                     "omega)); omega x (I omega) does no work, so only a comparison of the whole vector shows it "
                     "(DynamicBody.mfg_contribution, problem 37).",
    "gyroscopic_sign": "The gyroscopic term is skew(omega) I omega = omega x (I omega), not (I omega) x omega "
                       "(DynamicBody.mfg_contribution, problem 37).",
    "missing_bias": "f misses the bias accelerations: f = -sum(J_S.T m sigma_S + J_R.T (I sigma_R + skew(omega) I "
               "omega)) with sigma_S = B_a_B and sigma_R = B_omegaDot_B from the pass with qdd = 0 (the centripetal "
               "and Coriolis accelerations; DynamicBody.mfg_contribution, problem 37).",
    "gravity_sign": "g is the generalized force of gravity, g = sum(J_S.T A_IB.T I_grav m) with I_grav pointing "
                    "down; yours has the opposite sign (M qdd = f + g + tau puts g on the right-hand side).",
    "gravity_body_frame": "I_grav is given in inertial coordinates: bring it into the body first, g = sum(J_S.T "
                          "(A_IB.T I_grav) m) (DynamicBody.mfg_contribution, problem 37).",
    "transpose": "The Jacobians project onto the generalized coordinates with their transpose: M = J_S.T m J_S + "
                 "J_R.T I J_R, f = -(J_S.T m sigma_S + ...), g = J_S.T ...; you used J where J.T belongs.",
    "f_sign": "f carries a minus sign: M qdd = f + g + tau with f = -sum(J_S.T m sigma_S + J_R.T (I sigma_R + "
              "skew(omega) I omega)) (DynamicBody.mfg_contribution, problem 37).",
}


def _bodies(got, nq):
    bodies = got.get("bodies") if isinstance(got, dict) else None
    if not isinstance(bodies, list):
        fail("the probe could not read the tree's bodies back.")
    out = []
    for body in bodies:
        name = body["name"]
        out.append((name, float(body["m"]), as_array(body["I"], f"B_I_B of {name}", (3, 3)),
                    as_array(body["B_J_S"], f"B_J_S of {name}", (3, nq)),
                    as_array(body["B_J_R"], f"B_J_R of {name}", (3, nq))))
    return out


def _mfg_of(got, nq):
    return (as_array(got["M"], "M", (nq, nq)), as_array(got["f"], "f", (nq,)), as_array(got["g"], "g", (nq,)))


def _stacked(bodies) -> np.ndarray:
    """Every body's ``B_J_S`` and ``B_J_R`` stacked (6 rows per body): of rank nq when every coordinate moves a
    body."""
    return np.vstack([np.vstack([J_S, J_R]) for *_, J_S, J_R in bodies])


def _jacobian_findings(got, expected, nq):
    """Whether the student's Jacobians (all bodies stacked) are real: of the rank of the reference's."""
    return [("the matrix of every body's B_J_S and B_J_R, stacked,",
             rank_flaw(_stacked(_bodies(got, nq)), _stacked(_bodies(expected, nq))))]


def check_spd(got, expected, args):
    """``M`` is symmetric and positive-definite."""
    nq = len(args[1])
    M = as_array(got["M"], "M", (nq, nq))
    scale = max(1.0, float(np.abs(M).max()))
    asymmetry = float(np.abs(M - M.T).max())
    if asymmetry > SPD.atol * scale:
        fail(f"M is not symmetric: max |M - M.T| = {asymmetry:.3g} (tolerance {SPD}).\ngot:\n{format_array(M)}",
             "Every share J_S.T m J_S + J_R.T I J_R is symmetric; a sum of them is too. Look for a product in the "
             "wrong order (J_S.T m J_R?).", "not_symmetric")
    smallest = float(np.linalg.eigvalsh(0.5 * (M + M.T)).min())
    if smallest <= SPD.atol * scale:
        fail(f"M is not positive-definite: its smallest eigenvalue is {smallest:.4g} (tolerance {SPD}).\n"
             f"got:\n{format_array(M)}",
             "The kinetic energy qd.T M qd / 2 is positive for every motion: every body adds J_S.T m J_S + J_R.T I "
             "J_R (with the transposes on the left).", "not_positive_definite")


def check_kinetic_energy(got, expected, args):
    """``qd.T M qd / 2`` equals the kinetic energy of the bodies from the student's own Jacobians (when they are
    real)."""
    description, q, qd = args[:3]
    nq = len(q)
    M = as_array(got["M"], "M", (nq, nq))
    require_real("qd.T M qd / 2", "Jacobians", _jacobian_findings(got, expected, nq))
    translation = rotation = 0.0
    for _, m, I, J_S, J_R in _bodies(got, nq):
        v, omega = J_S @ qd, J_R @ qd
        translation += 0.5 * m * v @ v
        rotation += 0.5 * omega @ I @ omega
    mine = 0.5 * qd @ M @ qd
    assert_close(mine, translation + rotation, "qd.T M qd / 2", EXACT, [
        Mistake("missing_rotation", translation, "M misses the rotational part J_R.T I J_R of each body."),
        Mistake("missing_translation", rotation, "M misses the translational part J_S.T m J_S of each body."),
        Mistake("factor_two", 2 * (translation + rotation), "M qdd = ... has the kinetic energy qd.T M qd / 2: your "
                "M is twice the mass matrix."),
    ], context="(expected: sum(m v.v + omega.I omega) / 2 with v = B_J_S qd, omega = B_J_R qd from your own "
               "Jacobians)")


def check_gravity_gradient(got, expected, args, h=H):
    """``g = -dV/dq`` for the potential ``V = -sum(m I_grav . I_r_IB)`` of the student's own positions (when
    they are real: their gradient does not vanish where the reference's ``g`` does not)."""
    description, q, _, I_grav = args[:4]
    masses = {body["name"]: body["m"] for body in description["bodies"]}
    names = [body["name"] for body in got["bodies"]]

    def potential(positions):
        return -sum(masses[name] * I_grav @ as_array(r, f"the position of {name}", (3,))
                    for name, r in zip(names, positions))

    fd = -np.array([(potential(plus) - potential(minus)) / (2 * h) for plus, minus in got["positions"]])
    require_real("g", "positions", [
        *(real(f"the position of {name} at q + h e_1", mine, (3,), ours)
          for name, mine, ours in zip(names, got["positions"][0][0], expected["positions"][0][0])),
        ("-dV/dq of your own potential energy", rank_flaw(fd, expected["g"]))])
    assert_close(got["g"], fd, "g", LAGRANGE_DIFFERENCES, [
        Mistake("gravity_sign", -fd, MFG_HINTS["gravity_sign"]),
    ], context=f"(expected: -dV/dq of V = -sum(m I_grav . I_r_IB) from your own positions, I_grav = "
               f"{np.asarray(I_grav).tolist()})")


def check_lagrange(got, expected, args, h=H):
    """Lagrange's equations with the student's own ``M`` (when it is real: positive-definite):
    ``f = -Mdot qd + d/dq (qd.T M qd / 2)``."""
    q, qd = args[1], args[2]
    nq = len(q)
    M, f, _ = _mfg_of(got, nq)
    require_real("f", "M and Jacobians", [("M", mass_matrix_flaw(M)), *_jacobian_findings(got, expected, nq)])
    plus, minus = (as_array(x, "M", (nq, nq)) for x in got["M_path"])
    M_dot = (plus - minus) / (2 * h)
    dT = np.array([qd @ (as_array(p, "M", (nq, nq)) - as_array(m, "M", (nq, nq))) @ qd / (4 * h)
                   for p, m in got["M_coordinates"]])
    lagrange = -M_dot @ qd + dT
    gyroscopic = -sum(J_R.T @ np.cross(J_R @ qd, I @ (J_R @ qd)) for _, _, I, _, J_R in _bodies(got, nq))
    assert_close(f, lagrange, "f", LAGRANGE_DIFFERENCES, [
        Mistake("f_sign", -lagrange, MFG_HINTS["f_sign"]),
        Mistake("missing_gyroscopic", lagrange - gyroscopic, MFG_HINTS["missing_gyroscopic"]),
        Mistake("gyroscopic_sign", lagrange - 2 * gyroscopic, MFG_HINTS["gyroscopic_sign"]),
    ], context="(expected: Lagrange's equations with your own M, f = -Mdot qd + d/dq (qd.T M qd / 2), "
               "Mdot = dM/dt along qd; the gyroscopic terms from your own Jacobians)")


def compare_mfg(got, expected, mistakes, context=""):
    """``M``, ``f``, ``g`` of the student against the reference's, each with the known mistakes that change it."""
    nq = np.asarray(expected["M"]).shape[0]
    for key in ("M", "f", "g"):
        found = [Mistake(name, value[key], MFG_HINTS[name]) for name, value in mistakes.items()
                 if not close(value[key], expected[key], EXACT)]
        assert_close(got[key] if isinstance(got, dict) else None, expected[key], key, EXACT, found,
                     context=context or f"(nq = {nq})")


# ------------------------------------------------------------------------------------------ runs


def first_departure(got, expected, tol):
    """Index of the first row where ``got`` leaves ``expected`` (entrywise ``tol``), or ``None``."""
    bad = np.abs(got - expected) > tol.atol + tol.rtol * np.abs(expected)
    rows = np.flatnonzero(bad.reshape(bad.shape[0], -1).any(axis=1))
    return int(rows[0]) if rows.size else None


def wrong_start(got, given, hint: str, tol: Tol = EXACT) -> tuple[str, str]:
    """``(hint, diagnosis)`` of a run that starts from ``got`` where the ``given`` start belongs: a wrong start
    (``initial_state``), and, "could be" beside it, a slip of a value that gives ``got`` from ``given`` (an angle
    typed with the wrong sign, two rates exchanged, rates in degrees: ``grader.diagnosis.engine.value_slips``), as
    the engine tells a run's start; the wrong start alone where no slip gives it or its slips take the families
    past two."""
    from checks._diagnoses import DIAGNOSES
    from grader.diagnosis.engine import value_slips

    slips = {h.name: h.detail for h in value_slips(got, given, tol)}
    if not slips or len({DIAGNOSES[name].family for name in ["initial_state", *slips]}) > 2:
        return hint, "initial_state"
    return diagnose([Mistake("initial_state", None, hint)] + [
        Mistake(name, None, f"Your start is the given one changed so: {detail}.") for name, detail in slips.items()])


def defaulted_blocks(mine, given, defaults, tol: Tol = EXACT) -> list:
    """The names of the parts of a run's start ``mine`` that are the sheet's where another was given: ``defaults``
    is ``((name, the sheet's value), ...)`` in the order the start holds them (``given`` is as long).  Each part of
    ``mine`` must be the given one or, where that differs from the sheet's, the sheet's (the argument ignored, the
    module's default or the sheet's numbers used instead); empty where some part is neither, or none is the sheet's
    in place of another."""
    mine, given = np.ravel(np.asarray(mine, dtype=float)), np.ravel(np.asarray(given, dtype=float))
    sizes = [np.size(value) for _, value in defaults]
    if mine.shape != given.shape or sum(sizes) != mine.size:
        return []
    names, at = [], 0
    for (name, value), size in zip(defaults, sizes):
        part, passed, sheet = mine[at:at + size], given[at:at + size], np.ravel(np.asarray(value, dtype=float))
        at += size
        if close(part, passed, tol):
            continue
        if not close(part, sheet, tol):
            return []
        names.append(name)
    return names


def run_array(run, key, shape, what, times=None, pieces=False):
    """``run[key]`` as a finite array of the given shape.  Given the expected output ``times``, a run whose own
    times span them evenly in one sample more or fewer fails as a grid off by one (``grid_off_by_one``: every
    sample after the first at another time) rather than as a value of the wrong shape, and a run whose own times
    are expected ones, some left out or some twice, fails saying which (``_assert_samples``; ``pieces``: a run
    integrated in pieces between breaks at the output times)."""
    if not isinstance(run, dict) or key not in run:
        fail(f"{what} returned no {key!r}.", "Return a dict with the keys named in the docstring.", "format")
    if times is not None:
        _assert_grid(run, key, np.asarray(times, dtype=float), what, pieces)
    return as_array(run[key], f"{key} of {what}", shape)


def _assert_grid(run, key, times, what, pieces=False):
    """Fail where ``run[key]`` has one row per output time ``run["t"]``, those times are as many as ``times`` but
    one more or fewer or otherwise not as many (so it fails a shape of one row per time of ``times`` anyway), and
    they run evenly from the first of ``times`` to the last in one more or one fewer, or lie on ``times``."""
    try:
        t = np.asarray(run.get("t"), dtype=float)
        rows = np.shape(run[key])
    except (TypeError, ValueError):
        return
    if times.ndim != 1 or t.ndim != 1 or t.size == times.size or t.size < 2 or times.size < 3 or not rows \
            or rows[0] != t.size or not (np.all(np.isfinite(t)) and np.all(np.isfinite(times))):
        return
    steps = np.diff(t)
    span = times[-1] - times[0]
    if span <= 0:
        return
    if abs(t.size - times.size) == 1 and t.size >= 3 and np.all(steps > 0) \
            and np.ptp(steps) <= 1e-6 * steps.mean() and abs(t[0] - times[0]) <= 1e-9 * span \
            and abs(t[-1] - times[-1]) <= 1e-9 * span:
        fewer = t.size < times.size
        fail(f"{what} returned {t.size} output times from {t[0]:.6g} s to {t[-1]:.6g} s, one "
             f"{'fewer' if fewer else 'more'} than the {times.size} expected: its samples lie {steps.mean():.6g} s "
             f"apart, not {span / (times.size - 1):.6g} s, so every sample after the first comes "
             f"{'late' if fewer else 'early'}.",
             "np.linspace(t0, t_end, n) gives n points and n - 1 steps of (t_end - t0) / (n - 1): for a step dt from "
             "t0 to t_end it takes round((t_end - t0) / dt) + 1 points.", "grid_off_by_one")
    _assert_samples(t, times, span, what, pieces)
    _assert_own_steps(t, times, span, what)


#: a run's own steps are uneven where the longest and the shortest differ by more than this share of their mean
UNEVEN = 1e-3


def _assert_own_steps(t, times, span, what):
    """Fail where the output times ``t`` of the student's run span the expected ``times`` from the first to the last
    at uneven steps, most of them off the expected ones: the solver's own steps, the output times asked for left out
    (``t_eval`` not passed to ``solve_ivp``: ``solver_steps``)."""
    steps = np.diff(t)
    if t.size < 3 or np.any(steps <= 0) or np.ptp(steps) <= UNEVEN * steps.mean() \
            or abs(t[0] - times[0]) > ON_GRID * span or abs(t[-1] - times[-1]) > 1e-6 * span:
        return
    at = np.clip(np.searchsorted(times, t), 1, times.size - 1)
    on_grid = np.minimum(np.abs(times[at - 1] - t), np.abs(times[at] - t)) <= ON_GRID * span
    if on_grid.mean() >= 0.5:
        return
    fail(f"{what} returned {t.size} output times from {t[0]:.6g} s to {t[-1]:.6g} s at uneven steps (from "
         f"{steps.min():.3g} s to {steps.max():.3g} s), where the {times.size} output times asked for are expected: "
         "they are the solver's own steps.",
         "Pass the output times to the solver: solve_ivp(..., t_eval=times) returns the solution at them; without "
         "t_eval it returns the steps it took.", "solver_steps")


#: an output time of the student's run is one of the expected times within this share of their span
ON_GRID = 1e-9
#: the times listed in a message, at most
LISTED_TIMES = 6


def _listed(values) -> str:
    shown = ", ".join(f"{v:.6g}" for v in values[:LISTED_TIMES])
    return shown + (f" and {len(values) - LISTED_TIMES} more" if len(values) > LISTED_TIMES else "") + " s"


def _assert_samples(t, times, span, what, pieces=False):
    """Fail saying which output times differ, where every output time ``t`` of the student's run, in order, is one
    of the expected ``times`` and their numbers differ: times left out (``samples_left_out``: a boundary of the span,
    or of a piece, taken with < where <= belongs, or the reverse), times kept twice (``samples_repeated``: a sample
    on a boundary kept by both pieces that meet there), every m-th time alone (``output_step``: an output step m
    times too long).  A run that lacks its last output time alone has left the end out (taken with < where <=
    belongs: ``samples_left_out``) or ended one step short (``span_short``), or, where it is integrated in pieces
    between breaks at the output times (``pieces``), left its last piece, one output step long, un-integrated
    (``piece_left_out``); one that stops further short of the span's end, or that both leaves out and repeats
    times, is told by what differs alone (``shape``): its causes are too many (the last piece of a run in pieces
    never integrated, an event that ends it, a span cut short)."""
    if np.any(np.diff(t) < 0):
        return
    at = np.clip(np.searchsorted(times, t), 1, times.size - 1)
    nearest = np.where(np.abs(times[at - 1] - t) <= np.abs(times[at] - t), at - 1, at)
    if np.any(np.abs(times[nearest] - t) > ON_GRID * span):
        return
    counts = np.bincount(nearest, minlength=times.size)
    missing, twice = np.flatnonzero(counts == 0), np.flatnonzero(counts > 1)
    said = (f"{what} returned {t.size} output times where {times.size} are expected; each of them is one of the "
            "expected times, but")
    if twice.size and not missing.size:
        fail(f"{said} {_listed(times[twice])} come{'s' if twice.size == 1 else ''} twice.",
             "Each output time belongs in the run once: where two pieces of a run meet (a break, an event), keep "
             "the sample on their boundary in one of them only (t < b in the piece that ends at b).",
             "samples_repeated")
    if not missing.size or twice.size:
        if missing.size:
            fail(f"{said} {_listed(times[missing])} {'is' if missing.size == 1 else 'are'} left out and "
                 f"{_listed(times[twice])} {'comes' if twice.size == 1 else 'come'} twice.",
                 "Keep every output time asked for, each once.", "shape")
        return
    kept = np.flatnonzero(counts)
    stride = kept[1] - kept[0] if kept.size > 2 else 0
    gaps = np.diff(times)
    if stride > 1 and kept[0] == 0 and np.all(np.diff(kept) == stride) and times.size - 1 - kept[-1] < stride \
            and np.ptp(gaps) <= 1e-6 * gaps.mean():
        fail(f"{said} only one of every {stride} is there: your samples lie {stride * gaps.mean():.6g} s apart, "
             f"not {gaps.mean():.6g} s.",
             "Sample the run at the output times asked for (the step between them as given, not a longer one).",
             "output_step")
    if missing[-1] == times.size - 1 and missing.size == times.size - 1 - kept[-1]:
        last = (f"the last output time, {times[-1]:.6g} s, is" if missing.size == 1 else
                f"the last {missing.size} output times, from {times[missing[0]]:.6g} s to {times[-1]:.6g} s, are")
        # the end alone left out is the end taken with < where <= belongs, or a span one step short, or, in a run in
        # pieces, its last piece, one output step long, never integrated; more of the run's end missing has causes
        # too many to name
        fail(f"{said} the run stops at {t[-1]:.6g} s: {last} not in it.",
             "Integrate over the whole span asked for, up to its end, and keep every output time in it (the end "
             "of the span included" + (", and the last piece of the run, from the last break to the end, "
                                       "integrated too)." if pieces else ")."),
             ("samples_left_out or span_short or piece_left_out" if pieces else "samples_left_out or span_short")
             if missing.size == 1 else "shape")
    fail(f"{said} {_listed(times[missing])} {'is' if missing.size == 1 else 'are'} left out.",
         "Keep every output time asked for: a boundary of the span or of a piece belongs to the run (<= where the "
         "end is included, >= where the start is).", "samples_left_out")


def assert_run(got, expected, keys, tols, what, hint="", diagnosis="", note="", roots=None, pieces=False):
    """Fail at the first output time where one of ``keys`` of the run ``got`` leaves the reference run
    ``expected`` (tolerance per key in ``tols``); the message names the time and shows both states.  The failure
    carries the whole run as evidence for the diagnosis engine (``roots``: the probes' whole results, the
    student's and the reference's, when ``got`` and ``expected`` are parts of them; ``pieces``: see
    ``run_array``)."""
    t = np.asarray(expected["t"], dtype=float)
    run_array(got, "t", t.shape, what, times=t, pieces=pieces)
    mine = {key: run_array(got, key, np.shape(expected[key]), what, times=t, pieces=pieces) for key in keys}
    departures = [(i, k, key) for k, key in enumerate(keys)
                  if (i := first_departure(mine[key], np.asarray(expected[key]), tols[key])) is not None]
    if not departures:
        return
    i, _, key = min(departures)
    try:
        assert_close(mine[key][i], expected[key][i], f"{key} at t = {t[i]:.6g} s", tols[key], context=f"({what})",
                     note=f"Your run first leaves the reference's at t = {t[i]:.6g} s (output {i + 1} of {t.size}); "
                          f"up to there it agrees.{(' ' + note) if note else ''}")
    except CheckFailure as exc:
        from grader.diagnosis import Evidence

        mine_root, our_root = roots if roots is not None else (mine[key], expected[key])
        evidence = Evidence(mine[key], np.asarray(expected[key], dtype=float), tols[key], key, mine_root, our_root)
        raise CheckFailure(exc.message, hint, diagnosis, evidence=evidence) from None


def assert_event_found(got, expected, event, keys, tols, what, message, hint, others=None):
    """Where the run ``got`` has no ``event`` (None) and the reference's run ``expected`` has: a run that leaves
    the reference's before the reference's event fails there, at the first output time where one of ``keys``
    departs (``tols`` per key), with the whole runs as evidence for the diagnosis engine (the run never reaching
    the event is then a symptom, and its cause is what differs: a start, a model); only a run that follows the
    reference's up to its event and goes on without one has missed the event (``no_event``, ``message`` and
    ``hint``); one that follows it to its own end and ends before the event never reached it (``span_short``:
    ``ended_early``), and where it ends at the value of another argument of the call (``others``: their names and
    values; the support's distance ``s`` of ``simulate(q0, t_end, s)``), within an output step, the end time and
    that argument were exchanged as well (``argument_order``)."""
    if not isinstance(got, dict) or got.get(event) is not None:
        return
    t_event = float(expected[event])
    t_ours = np.asarray(expected["t"], dtype=float)
    t_mine = run_array(got, "t", None, what)
    before = np.zeros(0, dtype=int)
    if t_mine.size > 1 and np.all(np.diff(t_mine) > 0):
        before = np.flatnonzero((t_ours < t_event - 1e-12) & (t_ours >= t_mine[0] - 1e-12)
                                & (t_ours <= t_mine[-1] + 1e-12))
    if before.size:
        ours = {key: np.asarray(expected[key], dtype=float)[before] for key in keys}
        mine = {}
        for key in keys:
            rows = run_array(got, key, (t_mine.size, ours[key].shape[1]), what)
            mine[key] = np.column_stack([np.interp(t_ours[before], t_mine, rows[:, j]) for j in range(rows.shape[1])])
        departures = [(i, k, key) for k, key in enumerate(keys)
                      if (i := first_departure(mine[key], ours[key], tols[key])) is not None]
        if departures:
            i, _, key = min(departures)
            t = t_ours[before][i]
            try:
                assert_close(mine[key][i], ours[key][i], f"{key} at t = {t:.6g} s", tols[key], context=f"({what})",
                             note=f"{message} Your run leaves the reference's before its event, first at t = "
                                  f"{t:.6g} s; up to there it agrees.")
            except CheckFailure as exc:
                from grader.diagnosis import Evidence

                evidence = Evidence(mine[key], ours[key], tols[key], key, got, expected)
                raise CheckFailure(exc.message, "", "", evidence=evidence) from None
    if before.size:
        ended = ended_early(t_mine, {key: run_array(got, key, None, what) for key in keys}, expected, keys, t_event,
                            tols)
        if ended is not None:
            said = (f"{message} Your run ends at t = {ended:.6g} s, before the reference's event at t = "
                    f"{t_event:.6g} s; up to its end it agrees with the reference's.")
            step = float(t_mine[-1] - t_mine[-2]) if t_mine.size > 1 else 0.0
            for name, value in (others or {}).items():
                slack = 1e-9 * max(1.0, abs(value))  # the end at the value, or an output step short of it
                if -slack <= value - ended <= step + slack:
                    fail(f"{said} It ends at {name} = {value:.6g}, another argument of the call: the end time and "
                         f"{name} look exchanged.", "Pass the arguments in the order of the signature (or by their "
                         "names): the run integrates up to t_end.", "argument_order or span_short")
            fail(said, SPAN_HINT, "span_short")
    fail(message, hint, "no_event")


SPAN_HINT = ("Integrate over the whole span asked for: the event lies beyond the end of your run, so the run never "
             "reaches it.")


def ended_early(t_mine, mine: dict, expected, keys, t_event: float, tols) -> float | None:
    """The end time of a run (its times ``t_mine``, its rows ``mine[key]``) that stops before the reference's
    event at ``t_event`` while its last row agrees with the reference run ``expected`` (its ``"t"`` and ``keys``)
    at that time, within ``tols[key]``: a span of the integration too short (``span_short``), where the event is
    not missed but never reached.  None where the run reaches the event's time, or where it has left the
    reference's by its end (then what differs is the cause)."""
    try:
        t_mine, t_ours = np.asarray(t_mine, dtype=float), np.asarray(expected["t"], dtype=float)
    except (TypeError, ValueError):
        return None
    if t_mine.ndim != 1 or t_ours.ndim != 1 or t_mine.size < 2 or t_ours.size < 2 \
            or not np.all(np.isfinite(t_mine)) or not np.all(np.diff(t_ours) > 0):
        return None
    end = float(t_mine[-1])
    if not (t_ours[0] <= end < t_event - 1e-9 * max(1.0, abs(t_event))):
        return None
    for key in keys:
        try:
            ours, rows = np.asarray(expected[key], dtype=float), np.asarray(mine[key], dtype=float)
        except (TypeError, ValueError):
            return None
        if rows.ndim != 2 or ours.ndim != 2 or rows.shape[0] != t_mine.size or rows.shape[1] != ours.shape[1]:
            return None
        there = np.array([np.interp(end, t_ours, ours[:, j]) for j in range(ours.shape[1])])
        if not close(rows[-1], there, tols[key]):
            return None
    return end


def subsample(t, y, n=250):
    """At most ``n`` points of a curve, for the figures."""
    t, y = np.asarray(t, dtype=float), np.asarray(y, dtype=float)
    step = max(1, int(np.ceil(t.size / n)))
    return t[::step], y[::step]


def run_figure(title, ylabel, t_mine, mine, t_ours, ours, labels, extra=()):
    """Curves of the student's run over the reference's (columns of ``mine``/``ours`` labelled by ``labels``);
    ``extra``: more reference-side curves ``(label, t, y)`` such as the desired values."""
    mine, ours = np.asarray(mine, dtype=float), np.asarray(ours, dtype=float)
    return figure(title, "t [s]", ylabel,
                  student=[(label, *subsample(t_mine, mine[:, k])) for k, label in enumerate(labels)],
                  reference=[(label, *subsample(t_ours, ours[:, k])) for k, label in enumerate(labels)]
                  + [(label, *subsample(t, y)) for label, t, y in extra])


def assert_energy_conserved(got, tol, what, hint):
    """The energy ``T + V`` of the run ``got`` (``"t"``, ``"T"``, ``"V"``, from the student's own kinematics) stays
    within ``tol`` of its start."""
    t = run_array(got, "t", None, what)
    T, V = run_array(got, "T", t.shape, what), run_array(got, "V", t.shape, what)
    E = T + V
    drift = np.abs(E - E[0])
    if drift.max() > tol.atol:
        i = int(np.argmax(drift > tol.atol))
        try:
            assert_close(E[i], E[0], f"the energy T + V at t = {t[i]:.4g} s", tol,
                         context=f"(its value at t = 0: {what} is conservative)",
                         note=f"T and V come from your own kinematics (T = sum(m v.v + omega.I omega) / 2 with your "
                              f"Jacobians, V = -sum(m I_grav . I_r_IB)); the largest drift is {drift.max():.4g} at "
                              f"t = {t[int(np.argmax(drift))]:.4g} s.")
        except CheckFailure as exc:
            raise CheckFailure(exc.message, hint, "energy_drift", None, exc.evidence) from None


def same_crossings(mine, values, zero=1e-9) -> bool:
    """True when the student's event values cross zero where the reference's do: the same sign at every state where
    the reference's is not zero, and zero where it is (a positive multiple of the residual, say, or a squared
    distance less a squared length): another formulation of the same event, which gives the same run."""
    mine, values = np.asarray(mine, dtype=float), np.asarray(values, dtype=float)
    if mine.shape != values.shape or not np.all(np.isfinite(mine)):
        return False
    scale = max(1.0, float(np.abs(mine).max()))
    at_zero = np.abs(values) <= zero
    return bool(np.all(np.sign(mine[~at_zero]) == np.sign(values[~at_zero]))
                and np.all(np.abs(mine[at_zero]) <= zero * scale))


# ------------------------------------------------------------------------------------------ along a run

ALONG_A_RUN_HINT = (
    "An integrator calls the right-hand side again and again on the same tree, at a new state each time: compute "
    "everything from t and y at every call. Something is kept from an earlier call (an attribute set on the tree, a "
    "module-level variable, a cache keyed on the wrong thing); if it is the tree's forward_kinematics that keeps "
    "state, problems 24 and 31 say so."
)
_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth")


def _ordinal(k: int) -> str:
    return _ORDINALS[k] if k < len(_ORDINALS) else f"{k + 1}th"


def assert_fresh_along_a_run(ctx, probe, head, cases, what, stale=(), describe=str):
    """The student's right-hand side, called by the probe ``probe(*head, cases)`` at ``cases`` in turn on one tree
    (as an integrator calls it), gives at every case what it gives on a fresh tree (``probe(*head, [case])``).
    Otherwise it keeps something between calls: ``stale`` lists ``(name, values, hint)``, the values along the
    cases of a known way of doing so (the reference's, with a model computed once at the first case and reused,
    from a probe called before this); the check fails with the names of those the student's values match, else
    with ``state_between_calls``.  Needs nothing of the reference otherwise: the values themselves are graded by
    the comparisons with the reference that come before.  Returns the values on fresh trees."""
    cases = list(cases)
    along = as_list(ctx.student(probe, *head, cases), f"the values of {what} along a run", len(cases))
    fresh = [as_list(ctx.student(probe, *head, [case]), f"the value of {what} on a fresh tree", 1)[0]
             for case in cases]
    for k, (case, alone) in enumerate(zip(cases, fresh)):
        if same(along[k], alone):
            continue
        matches = [(name, hint) for name, values, hint in stale
                   if all(same(mine, ours) for mine, ours in zip(along, values))]
        names = list(dict.fromkeys(name for name, _ in matches))
        fail(f"{what} keeps something between calls: called at {len(cases)} states in turn on one tree, as an "
             f"integrator calls it, it gives at the {_ordinal(k)} ({describe(case)})\n{shown(along[k])}\nwhere a "
             f"fresh tree gives\n{shown(alone)}\n(tolerance {EXACT}; the states before it: "
             f"{'; '.join(describe(c) for c in cases[:k])})",
             matches[0][1] if len(names) == 1 else ALONG_A_RUN_HINT,
             " or ".join(names) if names else "state_between_calls")
    return fresh
