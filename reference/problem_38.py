"""Problem 38: the passive dynamic walker of problems 25 and 33 with dynamics.

Problem data P38: the walker on a slope of 1 degree, entered as gravity tilted by the slope (normalised to 1),
``I_grav = (sin 1deg, -cos 1deg, 0)``; ``q0 = (0, 0)``, ``qd0 = (-0.1, +1)``; no torques, no heel strike; from 0 to
2 s with 100 output points.  The rolling contact does no work, so the energy ``T + V`` with
``V = -sum(m I_grav . I_r_IB)`` is conserved.
"""

import numpy as np

from .dynamics import DynamicBody, equations_of_motion, forward_dynamics
from .problem_25 import build_walker

__all__ = ["SLOPE", "I_GRAV", "Q0", "QD0", "T_END", "N_OUTPUT", "build_dynamic_walker", "walker_ode", "simulate",
           "solve"]

SLOPE = np.deg2rad(1.0)
I_GRAV = np.array([np.sin(SLOPE), -np.cos(SLOPE), 0.0])
Q0 = np.array([0.0, 0.0])
QD0 = np.array([-0.1, 1.0])
T_END = 2.0
N_OUTPUT = 100


def build_dynamic_walker():
    """The walker of problem 25 with bodies that have equations of motion (``DynamicBody``)."""
    return build_walker(body_class=DynamicBody)


def walker_ode(t, y, tree):
    """The right-hand side ``dy/dt = (qd, qdd)`` of the unactuated walker, ``y = (alpha, gamma, alpha_dot,
    gamma_dot)``: the recursive ``M``, ``f``, ``g`` at ``(q, qd)`` and ``M qdd = f + g``."""
    # BEGIN SOLUTION problem 38
    q, qd = y[:2], y[2:]
    M, f, g = equations_of_motion(tree, q, qd, I_GRAV)
    return np.concatenate([qd, forward_dynamics(M, f, g, np.zeros(2))])
    # END SOLUTION


def simulate(t_end=T_END, n=N_OUTPUT, q0=Q0, qd0=QD0):
    """The walker from ``(q0, qd0)`` to ``t_end`` with ``scipy.integrate.solve_ivp``, output at ``n`` equally
    spaced times from 0 to ``t_end``.  Returns ``{"t", "q", "qd"}`` (one row per time)."""
    from scipy.integrate import solve_ivp

    # BEGIN SOLUTION problem 38
    tree = build_dynamic_walker()
    y0 = np.concatenate([np.asarray(q0, dtype=float), np.asarray(qd0, dtype=float)])
    result = solve_ivp(walker_ode, (0.0, t_end), y0, method="DOP853", t_eval=np.linspace(0.0, t_end, n),
                       rtol=1e-10, atol=1e-10, args=(tree,))
    return {"t": result.t, "q": result.y[:2].T, "qd": result.y[2:].T}
    # END SOLUTION


def solve():
    """The sheet's run: ``simulate()``."""
    return simulate()
