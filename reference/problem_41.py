"""Problem 41: understanding dynamics, three multiple-choice questions.

Write the number of the option you choose for each question in answers.toml (``[problem_41] a``, ``b``, ``c``).
For (c), the flyball governor is the one of problem 27(d): the ball of mass ``m`` at the distance ``l`` from the
top of the linkage, at the angle ``gamma = 30 deg`` from the spinning axis, ``phi = 0``, ``q = (phi, gamma)``.
"""

__all__ = []


# BEGIN REFERENCE ONLY
# The grader's computation of the keys: not part of the student's package.  Each statement or option becomes a
# numerical identity tested on a random motion, tree or configuration:
# (a) I fixed point and frame, C body-fixed point and frame, G centre of gravity.  (1) d/dt of the C-coordinates of
#     L_G against the C-coordinates of M_G; (2), (3) the derivative of L_C against M_C (the I-coordinates of the
#     derivative and the derivative of the I-coordinates are the same); (4) the derivative of L_I against M_I.
# (b) The generalized force of F_P acting at the point P of body B is the virtual work (d I_r_P / dq).T I_F_P;
#     the key is the option that differs from it.
# (c) The ball's m J.T J at phi = 0, gamma = 30 deg against the four printed matrices.

import numpy as np

from .rotations import cardan, skew, unskew
from .tree import Body, KinematicTree, RotationalJoint, TranslationalJoint

#: a statement holds when its residual is below this (relative to the size of the quantities)
IDENTITY_TOL = 1e-5
_H = 1e-5


def _derivative(func, t, h=_H):
    return (func(t + h) - func(t - h)) / (2.0 * h)


def _only(indices, what):
    if len(indices) != 1:
        raise ValueError(f"expected exactly one option that {what}, found {indices}")
    return indices[0]


def angular_momentum_residuals(seed=41):
    """Relative residuals of the four statements of (a) on a random rigid-body motion (a statement is true when
    its residual vanishes).  The moment ``M_G`` is defined by Euler's law about the centre of gravity in inertial
    coordinates and the force by Newton's law; a moment about another point ``P`` is ``M_P = M_G + r_PG x F``, an
    angular momentum ``L_P = L_G + r_PG x m v_G``."""
    rng = np.random.default_rng(seed)
    m = rng.uniform(1.0, 3.0)
    B_I_G = np.diag(rng.uniform(1.0, 2.0, 3))
    angles = rng.uniform(-1.0, 1.0, (3, 3))
    position = rng.uniform(-1.0, 1.0, (3, 3))
    B_r_GC = rng.uniform(-1.0, 1.0, 3)

    def A_IB(t):
        return cardan(*(angles[0] + angles[1] * t + angles[2] * t * t))

    def r_G(t):
        return position[0] + position[1] * t + position[2] * t * t

    def omega(t):
        return unskew(_derivative(A_IB, t) @ A_IB(t).T)

    def L_G(t):
        A = A_IB(t)
        return A @ B_I_G @ A.T @ omega(t)

    def momentum(t):
        return m * _derivative(r_G, t)

    def r_C(t):
        return r_G(t) + A_IB(t) @ B_r_GC

    def about(point, t, L=True):
        """Angular momentum (or moment) about ``point(t)`` in inertial coordinates."""
        arm = r_G(t) - point(t)
        if L:
            return L_G(t) + np.cross(arm, momentum(t))
        return _derivative(L_G, t, 1e-4) + np.cross(arm, _derivative(momentum, t, 1e-4))

    def origin(t):
        return np.zeros(3)

    t = 0.3
    statements = {
        1: (_derivative(lambda s: A_IB(s).T @ L_G(s), t, 1e-4), A_IB(t).T @ about(r_G, t, L=False)),
        2: (_derivative(lambda s: about(r_C, s), t, 1e-4), about(r_C, t, L=False)),
        3: (A_IB(t) @ _derivative(lambda s: A_IB(s).T @ about(r_C, s), t, 1e-4)
            + skew(omega(t)) @ about(r_C, t), about(r_C, t, L=False)),
        4: (_derivative(lambda s: about(origin, s), t, 1e-4), about(origin, t, L=False)),
    }
    return {k: float(np.linalg.norm(lhs - rhs) / max(np.linalg.norm(rhs), 1.0)) for k, (lhs, rhs) in
            statements.items()}


def answer_a():
    """The number of the true statement of (a)."""
    return _only([k for k, r in angular_momentum_residuals().items() if r < IDENTITY_TOL], "is true")


def _projection_tree(seed=41):
    """A small random tree (rotational and translational joints) and the body ``tip`` the force acts on."""
    rng = np.random.default_rng(seed)
    ground, link, tip = Body("ground"), Body("link", 1.0), Body("tip", 1.0)
    RotationalJoint(ground, link, P_r_PDp=rng.uniform(-1, 1, 3), A_PDp=cardan(*rng.uniform(-3, 3, 3)),
                    S_r_SDs=rng.uniform(-1, 1, 3), A_SDs=cardan(*rng.uniform(-3, 3, 3)), q_index=[0])
    TranslationalJoint(link, tip, P_r_PDp=rng.uniform(-1, 1, 3), A_PDp=cardan(*rng.uniform(-3, 3, 3)),
                       S_r_SDs=rng.uniform(-1, 1, 3), A_SDs=cardan(*rng.uniform(-3, 3, 3)), q_index=[1])
    RotationalJoint(tip, Body("end", 1.0), P_r_PDp=rng.uniform(-1, 1, 3), q_index=[2])
    return KinematicTree(ground), rng


def projection_residuals(seed=41):
    """Residuals of the four options of (b) against the virtual work ``(d I_r_P / dq).T I_F_P`` on a random tree,
    point and force."""
    tree, rng = _projection_tree(seed)
    q = rng.uniform(-1, 1, tree.nq)
    B_r_BP, I_F = rng.uniform(-1, 1, 3), rng.uniform(-1, 1, 3)

    def I_r_P(x):
        body = tree.forward_kinematics(x)["tip"]
        return body.A_IB @ (body.B_r_IB + B_r_BP)

    dr_dq = np.column_stack([(I_r_P(q + _H * e) - I_r_P(q - _H * e)) / (2 * _H) for e in np.eye(tree.nq)])
    virtual_work = dr_dq.T @ I_F
    body = tree.forward_kinematics(q, np.zeros(tree.nq))["tip"]
    J_S, J_R, A_BI = body.B_J_S, body.B_J_R, body.A_IB.T
    B_F = A_BI @ I_F
    J_PS = J_S - skew(B_r_BP) @ J_R
    options = {
        1: J_S.T @ B_F + J_R.T @ skew(B_r_BP) @ B_F,
        2: J_PS.T @ B_F + J_R.T @ np.cross(B_r_BP, B_F),
        3: J_PS.T @ B_F,
        4: J_PS.T @ A_BI @ I_F,
    }
    scale = max(np.linalg.norm(virtual_work), 1.0)
    return {k: float(np.linalg.norm(v - virtual_work) / scale) for k, v in options.items()}


def answer_b():
    """The number of the option of (b) that does NOT give the generalized force."""
    return _only([k for k, r in projection_residuals().items() if r > IDENTITY_TOL], "is not correct")


def flyball_options(l, m):
    """The four printed partial mass matrices of (c) for the length ``l`` and the ball's mass ``m``."""
    s3 = np.sqrt(3.0)
    return {
        1: np.array([[l * l * m / 4, 0.0], [0.0, 3 * l * l * m / 4]]),
        2: np.array([[l * l * m / 4, s3 * l * m / 2], [s3 * l * m / 2, l * l * m]]),
        3: np.array([[l * l * m / 4, 0.0], [0.0, l * l * m]]),
        4: np.array([[l * l * m / 4, s3 * l * m / 2], [s3 * l * m / 2, 3 * l * l * m / 4]]),
    }


def flyball_mass_matrix(l, m, phi=0.0, gamma=np.pi / 6):
    """``m J.T J`` of the ball at ``(phi, gamma)``: the ball at ``(l sin gamma cos phi, -l cos gamma,
    l sin gamma sin phi)`` from the top of the linkage, the spinning axis along y; J by central differences."""

    def ball(q):
        p, g = q
        return np.array([l * np.sin(g) * np.cos(p), -l * np.cos(g), l * np.sin(g) * np.sin(p)])

    q = np.array([phi, gamma])
    J = np.column_stack([(ball(q + _H * e) - ball(q - _H * e)) / (2 * _H) for e in np.eye(2)])
    return m * J.T @ J


def answer_c(l=1.3, m=0.7):
    """The number of the option of (c) that equals the ball's contribution (for arbitrary ``l``, ``m``)."""
    M = flyball_mass_matrix(l, m)
    return _only([k for k, option in flyball_options(l, m).items() if np.allclose(option, M, atol=1e-6)],
                 "matches the ball's mass matrix")


def answers():
    """``{"a", "b", "c"}``: the keys of the three questions."""
    return {"a": answer_a(), "b": answer_b(), "c": answer_c()}
# END REFERENCE ONLY
