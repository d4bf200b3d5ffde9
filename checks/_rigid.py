"""Shared by the checks of problems 11-20: random rotations and kinematic states, the integration step with a
known mistake switched on, and the comparison of traces that names the first departing step.

Nothing here uses the reference: rotations are drawn from quaternions, and the mistaken steps are computed with
numpy from the values the reference gave (through ``ctx.reference``) and the inputs.
"""

import numpy as np

from grader import strategies as st
from grader.checking import (
    Mistake,
    Tol,
    assert_close,
    close,
    fail,
)
from probes import problem_12 as p12


STATE = ("A_IB", "B_r_IB", "B_v_B", "B_omega_B")
#: long runs of the same algorithm: rounding accumulates over thousands of steps
SIMULATION = Tol("simulation, same algorithm", 1e-6, 1e-6)
#: the figures draw at most this many points per curve
MAX_POINTS = 500

FINITE = dict(allow_nan=False, allow_infinity=False)
ANGLES = st.floats(-np.pi, np.pi, **FINITE)


def vectors(bound):
    return st.tuples(*[st.floats(-bound, bound, **FINITE)] * 3).map(np.array)


def skew(w):
    """The matrix of ``x -> w x x`` (numpy, for the mistake catalogues)."""
    return np.cross(np.asarray(w, dtype=float).reshape(3), np.eye(3) * -1.0)


def expm_skew(W):
    """``expm(W)`` of a skew matrix by the Rodrigues formula (numpy, for the mistake catalogues)."""
    W = np.asarray(W, dtype=float)
    theta = float(np.sqrt(0.5 * np.sum(W * W)))
    if theta < 1e-10:
        return np.eye(3) + W + W @ W / 2.0
    return np.eye(3) + (np.sin(theta) / theta) * W + ((1.0 - np.cos(theta)) / theta**2) * (W @ W)


def quaternion_rotation(q):
    """The rotation matrix of the quaternion ``q = (w, x, y, z)`` (normalized here)."""
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


#: the inertia of each body of problem 16 is FACTOR * m * diag(b² + c², a² + c², a² + b²) for its dimensions
#: a, b, c (full edges or full axes; problem data)
BODY_FACTORS = {"cuboid": 1 / 12, "ellipsoid": 1 / 20, "particles": 1 / 12}


def body_inertia(body, m, a, b, c):
    """The inertia matrix of a body of problem 16 (cuboid, ellipsoid, six face-centre particles)."""
    return BODY_FACTORS[body] * m * np.diag([b**2 + c**2, a**2 + c**2, a**2 + b**2])


#: the quaternion that random rotations shrink towards: a generic rotation (the identity or a half turn would make
#: different mistakes give the same matrix, and a minimal failing input would lose its diagnosis)
GENERIC_QUATERNION = np.array([0.8, 0.3, -0.5, 0.4])
#: random rotations: quaternions GENERIC_QUATERNION + d with d in [-1, 1]^4 (every direction occurs, since the box
#: contains the origin), normalized
ROTATIONS = (st.tuples(*[st.floats(-1.0, 1.0, **FINITE)] * 4)
             .map(lambda d: GENERIC_QUATERNION + np.asarray(d))
             .filter(lambda q: float(q @ q) > 0.01)
             .map(quaternion_rotation))
#: kinematic states: a random orientation, bounded velocities and accelerations
STATES = st.fixed_dictionaries({
    "A_IB": ROTATIONS,
    "B_r_IB": vectors(5.0),
    "B_v_B": vectors(3.0),
    "B_a_B": vectors(3.0),
    "B_omega_B": vectors(3.0),
    "B_omegaDot_B": vectors(3.0),
})
STEP_SIZES = st.floats(1e-3, 0.1, **FINITE)
STEP_COUNTS = st.integers(1, 20)

#: the sheet's cases of part (a): initial state (A_IB = E, B_r_IB = 0) and the printed final values
SHEET_TARGETS = {
    1: ([[0.0707, 0, 0.9975], [0, 1, 0], [-0.9975, 0, 0.0707]], [0, 0, 0]),
    2: ([[0.0707, 0, 0.9975], [0, 1, 0], [-0.9975, 0, 0.0707]], [0.1301, 0, 1.5112]),
    3: ([[0.7368, 0, 0.6761], [0, 1, 0], [-0.6761, 0, 0.7368]], [0.6041, 0, 0.4219]),
}
DT, STEPS = 0.01, 100  # t_end = 1 s with the course's loop
WHEEL_DT, WHEEL_STEPS, WHEEL_EVERY = 0.001, 3001, 10  # t_end = 3 s with the course's loop

ORDER_HINT = ("Every update of the step must use the values from BEFORE the step: compute B_Om and I_Om first, "
              "then update B_r_IB, B_v_B, A_IB, and B_omega_B last (problem data, P12).")
KINEMATIC_MISTAKES = {
    "omega_frame": (
        "A_IB was turned with the angular velocity in the wrong frame: B_omega_B is in body coordinates. Use "
        "A_IB = expm(dt * skew(A_IB @ B_omega_B)) @ A_IB (inertial omega, from the left) or, equivalently, "
        "A_IB @ expm(dt * skew(B_omega_B)) (body omega, from the right)."
    ),
    "rotation_side": (
        "expm(dt * I_Om) multiplies A_IB from the LEFT: A_IB = expm(dt * I_Om) @ A_IB. On the right it would "
        "need the body-frame skew matrix B_Om instead."
    ),
    "explicit_euler": (
        "A_IB was updated by explicit Euler (A_IB + dt * I_Om @ A_IB), which does not keep it a rotation. The "
        "sheet asks for the matrix exponential: A_IB = expm(dt * I_Om) @ A_IB (scipy.linalg.expm or Rodrigues' "
        "formula)."
    ),
    "missing_omega_x_r": (
        "The position update misses the term omega x r: B_r_IB is expressed in the rotating frame B, so "
        "d/dt B_r_IB = B_v_B - B_omega_B x B_r_IB."
    ),
    "missing_omega_x_v": (
        "The velocity update misses the term omega x v: B_v_B is expressed in the rotating frame B, so "
        "d/dt B_v_B = B_a_B - B_omega_B x B_v_B."
    ),
    "omega_x_r_sign": "Sign of the transport term: d/dt B_r_IB = B_v_B - B_omega_B x B_r_IB (minus).",
    "omega_x_v_sign": "Sign of the transport term: d/dt B_v_B = B_a_B - B_omega_B x B_v_B (minus).",
    "update_order": "B_omega_B was updated before it was used. " + ORDER_HINT,
    "omega_before_rotation": "A_IB was turned with the updated B_omega_B. " + ORDER_HINT,
    "velocity_first": "B_v_B was updated before the position update used it. " + ORDER_HINT,
}


# ------------------------------------------------------------------------------------ the step, with mistakes


def kinematic_step(state, dt, mistake=None):
    """One integration step of the problem data, or with the named mistake of ``KINEMATIC_MISTAKES`` applied."""
    A, r, v, w, a, wd = (np.asarray(state[k], dtype=float) for k in (*STATE, "B_a_B", "B_omegaDot_B"))
    if mistake == "update_order":
        w = w + dt * wd
    B_Om, I_Om = skew(w), skew(A @ w)
    transport_r = {"missing_omega_x_r": 0.0, "omega_x_r_sign": -1.0}.get(mistake, 1.0)
    transport_v = {"missing_omega_x_v": 0.0, "omega_x_v_sign": -1.0}.get(mistake, 1.0)
    v_new = v + dt * (a - transport_v * B_Om @ v)
    r_new = r + dt * ((v_new if mistake == "velocity_first" else v) - transport_r * B_Om @ r)
    if mistake == "omega_before_rotation":
        I_Om = skew(A @ (w + dt * wd))
    A_new = {
        "omega_frame": lambda: expm_skew(dt * B_Om) @ A,
        "rotation_side": lambda: A @ expm_skew(dt * I_Om),
        "explicit_euler": lambda: A + dt * I_Om @ A,
    }.get(mistake, lambda: expm_skew(dt * I_Om) @ A)()
    w_new = w if mistake == "update_order" else w + dt * wd
    return {**state, "A_IB": A_new, "B_r_IB": r_new, "B_v_B": v_new, "B_omega_B": w_new}


def simulate(state, dt, n, mistake=None):
    for _ in range(n):
        state = kinematic_step(state, dt, mistake)
    return state


def sheet_state(values):
    """A body at rest at the origin (``A_IB = E``, ``B_r_IB = 0``) with the sheet's velocities and accelerations."""
    return {"A_IB": np.eye(3), "B_r_IB": np.zeros(3), **{k: np.array(v, dtype=float) for k, v in values.items()}}


def initial(ctx, case):
    """The initial state of the sheet's case ``case`` of problem 12(a) (the package's ``CASES``)."""
    return sheet_state(ctx.reference(p12.constants)["CASES"][str(case)])


# ------------------------------------------------------------------------------------ traces


def trace_array(got, key, shape):
    """The student's trace ``key`` as a float array of the reference's shape."""
    value = got.get(key) if isinstance(got, dict) else None
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        fail(f"{key} must be numeric, got {str(value)[:200]}")
    if array.shape != tuple(shape):
        fail(f"{key} must keep the shape {tuple(shape[1:])} during the run; the trace has shape {array.shape}, "
             f"expected {tuple(shape)}.", diagnosis="shape")
    return array


def first_departure(got, expected, keys, tol):
    """``(sample, key, got_trace)`` of the first sample (and the first of ``keys``) where the student's traces
    leave the reference's, or ``None``; every trace is checked for its shape first."""
    arrays = {key: trace_array(got, key, np.shape(expected[key])) for key in keys}
    for i in range(len(expected["step"])):
        for key in keys:
            if not close(arrays[key][i], expected[key][i], tol):
                return i, key, arrays[key]
    return None


def assert_traces(got, expected, keys, tol, mistakes_at=None, what="", dt=None):
    """Fail at the first sample where the student's traces leave the reference's, naming the step and the
    attribute; ``mistakes_at(sample, key)`` lists the known mistakes at that sample."""
    found = first_departure(got, expected, keys, tol)
    if found is None:
        return
    i, key, trace = found
    steps = int(expected["step"][i])
    when = f"after {steps} step{'s' * (steps != 1)}" + (f" (t = {steps * dt:g} s)" if dt else "")
    earlier = "(the first departure: every earlier sample agrees)" if i else "(already before the first step)"
    assert_close(trace[i], expected[key][i], f"{key} {when}", tol, mistakes_at(i, key) if mistakes_at else (),
                 context=f"{what} {earlier}".strip())


def kinematic_mistakes_at(expected, state, dt, mistakes=KINEMATIC_MISTAKES, step=kinematic_step):
    """``mistakes_at`` for the traces of a run from ``state``: each mistake applied with ``step`` from the
    reference's previous sample on (the accelerations and any other entries taken from ``state``)."""

    def at(i, key):
        if i == 0:
            return []
        previous = {**state, **{k: expected[k][i - 1] for k in STATE}}
        n = int(expected["step"][i] - expected["step"][i - 1])
        found = []
        for name, hint in mistakes.items():
            s = previous
            for _ in range(n):
                s = step(s, dt, name)
            found.append(Mistake(name, s[key], hint))
        return found

    return at


def compact(value):
    """A number or an array on one line."""
    array = np.asarray(value, dtype=float)
    if array.ndim == 0:
        return f"{float(array):.6g}"
    with np.printoptions(precision=6, suppress=True, floatmode="maxprec"):
        return np.array2string(array, separator=", ", max_line_width=10**6).replace("\n", "")


def describe_state(state):
    return ", ".join(f"{k} = {compact(v)}" for k, v in state.items())


def subsample(x, y, limit=MAX_POINTS):
    every = max(1, int(np.ceil(len(x) / limit)))
    return np.asarray(x)[::every], np.asarray(y)[::every]


# ------------------------------------------------------------------------------------ part (a): integration
