"""Equations of motion of kinematic trees by the projected Newton-Euler equations (problems 24, 37, 38, 46).

``M(q) qdd = f(q, qd) + g(q) + tau`` (problem data, Conventions).  Every body adds its share, computed from its
state after a pass of ``forward_kinematics(q, qd, qdd = 0)``: its Jacobians ``B_J_S``, ``B_J_R`` (body
coordinates) and its bias accelerations ``sigma_S = B_a_B``, ``sigma_R = B_omegaDot_B`` (the accelerations with
``qdd = 0``)::

    M = sum(J_S.T m J_S + J_R.T I J_R)
    f = -sum(J_S.T m sigma_S + J_R.T (I sigma_R + skew(omega) I omega))
    g = sum(J_S.T A_IB.T I_grav m)

``DynamicBody`` extends the tree's ``Body`` with that share and the recursion that sums it over a subtree (the
course's ``LinkedRigidBodyDynamicsMfgCLASS``); the joints need nothing new.  A tree whose bodies are all
``DynamicBody`` has equations of motion (``equations_of_motion``) and forward dynamics (``forward_dynamics``).
"""

import numpy as np

from .conventions import as_vector
from .rotations import skew
from .tree import Body

__all__ = ["DynamicBody", "equations_of_motion", "forward_dynamics", "integrate_piecewise"]


class DynamicBody(Body):
    """A body of a kinematic tree that knows its share of the equations of motion ``M qdd = f + g + tau``."""

    def mfg_contribution(self, I_grav):
        """``(M_B, f_B, g_B)``: this body's share of ``M`` (nq x nq), ``f`` and ``g`` (nq), from its current state
        (after ``forward_kinematics(q, qd, qdd = 0)``, so that ``B_a_B`` and ``B_omegaDot_B`` are the bias
        accelerations ``sigma_S`` and ``sigma_R``) and the gravitational acceleration ``I_grav`` in inertial
        coordinates::

            M_B = J_S.T m J_S + J_R.T I J_R
            f_B = -(J_S.T m sigma_S + J_R.T (I sigma_R + skew(omega) I omega))
            g_B = J_S.T A_IB.T I_grav m
        """
        # BEGIN SOLUTION problem 37
        J_S, J_R, I, m = self.B_J_S, self.B_J_R, self.B_I_B, self.m
        omega = self.B_omega_B
        M = m * J_S.T @ J_S + J_R.T @ I @ J_R
        f = -(m * J_S.T @ self.B_a_B + J_R.T @ (I @ self.B_omegaDot_B + skew(omega) @ I @ omega))
        g = m * J_S.T @ (self.A_IB.T @ I_grav)
        return M, f, g
        # END SOLUTION

    def recursive_mfg(self, I_grav):
        """``(M, f, g)`` of this body and every body below it: its own share plus, recursively, its children's."""
        M, f, g = self.mfg_contribution(I_grav)
        for joint in self.child_joints:
            M_c, f_c, g_c = joint.successor.recursive_mfg(I_grav)
            M, f, g = M + M_c, f + f_c, g + g_c
        return M, f, g


def equations_of_motion(tree, q, qd, I_grav):
    """``(M, f, g)`` of a tree of ``DynamicBody`` at ``(q, qd)``: a pass of ``forward_kinematics(q, qd, 0)``, then
    the recursive sum from the root."""
    tree.forward_kinematics(q, qd, np.zeros(tree.nq))
    return tree.root.recursive_mfg(as_vector(I_grav))


def forward_dynamics(M, f, g, tau):
    """The accelerations ``qdd`` that solve ``M qdd = f + g + tau``."""
    # BEGIN SOLUTION problem 37
    return np.linalg.solve(M, f + g + tau)
    # END SOLUTION


def integrate_piecewise(fun, t_span, y0, t_eval, breaks=(), *, args=(), events=None, method="RK45", rtol=1e-6,
                        atol=1e-8):
    """Integrate ``dy/dt = fun(t, y, *args)`` with ``scipy.integrate.solve_ivp`` piece by piece between the
    ``breaks`` (times where ``fun`` is not smooth, such as the knots of a linearly interpolated table), each piece
    started afresh with a first step as long as the piece, so that the solver never steps across a kink.

    Output at the times ``t_eval`` (within ``t_span``).  ``events``: solve_ivp event functions; the first terminal
    event ends the run.  Returns ``{"t", "y" (one row per time), "t_event", "y_event"}`` (``None`` without an
    event).  On the robot arm of problem 37 one step of RK45 per knot interval, rtol 1e-6, is within 1e-8 of a
    DOP853 run at rtol 1e-12.
    """
    from scipy.integrate import solve_ivp

    t0, t1 = (float(t) for t in t_span)
    t_eval = np.asarray(t_eval, dtype=float)
    inner = np.asarray(breaks, dtype=float)
    edges = np.unique(np.concatenate([[t0], inner[(inner > t0) & (inner < t1)], [t1]]))
    y = np.asarray(y0, dtype=float)
    times, rows = [], []
    for a, b in zip(edges[:-1], edges[1:]):
        wanted = t_eval[(t_eval >= a) & ((t_eval <= b) if b == t1 else (t_eval < b))]
        result = solve_ivp(fun, (a, b), y, method=method, t_eval=np.union1d(wanted, [b]), args=args, events=events,
                           rtol=rtol, atol=atol, first_step=b - a)
        if result.status < 0:
            raise RuntimeError(f"the integration failed at t = {result.t[-1]:g}: {result.message}")
        keep = np.isin(result.t, wanted)
        times.extend(result.t[keep])
        rows.extend(result.y.T[keep])
        if result.status == 1:
            k = next(i for i, t in enumerate(result.t_events) if len(t))
            return {"t": np.array(times), "y": np.array(rows).reshape(-1, y.size),
                    "t_event": float(result.t_events[k][0]), "y_event": result.y_events[k][0].copy()}
        y = result.y[:, -1]
    return {"t": np.array(times), "y": np.array(rows).reshape(-1, y.size), "t_event": None, "y_event": None}


# BEGIN REFERENCE ONLY
# Cross-checks of the grader: not part of the student's package.


def inverse_dynamics(tree, q, qd, qdd, I_grav):
    """The torques ``tau`` that produce ``qdd`` at ``(q, qd)``, from the bodies' full accelerations (a pass with
    ``qdd``) projected with their Jacobians: ``tau = sum(J_S.T m (a - A_IB.T I_grav) + J_R.T (I omegaDot +
    skew(omega) I omega))``.  Equals ``M qdd - f - g`` by a different route."""
    tree.forward_kinematics(q, qd, qdd)
    I_grav = as_vector(I_grav)
    tau = np.zeros(tree.nq)
    for body in tree.bodies:
        I, omega = body.B_I_B, body.B_omega_B
        tau += body.B_J_S.T @ (body.m * (body.B_a_B - body.A_IB.T @ I_grav))
        tau += body.B_J_R.T @ (I @ body.B_omegaDot_B + np.cross(omega, I @ omega))
    return tau


def energy(tree, q, qd, I_grav):
    """``(T, V)``: kinetic energy ``sum(m v.v + omega.I omega) / 2`` and potential energy ``-sum(m I_grav.I_r_IB)``
    of the bodies at ``(q, qd)``."""
    tree.forward_kinematics(q, qd, np.zeros(tree.nq))
    I_grav = as_vector(I_grav)
    T = sum(0.5 * body.m * body.B_v_B @ body.B_v_B + 0.5 * body.B_omega_B @ body.B_I_B @ body.B_omega_B
            for body in tree.bodies)
    V = -sum(body.m * I_grav @ body.I_r_IB for body in tree.bodies)
    return float(T), float(V)
# END REFERENCE ONLY
