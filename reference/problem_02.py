"""Problem 2: a pendulum in MuJoCo (the course's "Getting started with Simscape Multibody").

One link, the sheet's brick (``mjcf.LENGTH x WIDTH x HEIGHT``), hangs from a hinge about the world z-axis at
one of its ends; it starts at rest, horizontal along +x.  (a) The tutorial's model: aluminium, joint damping
8e-5 N m/(deg/s), input torque 0.06 sin(t) N m.  (b) HDPE, no torque, no damping: plot the angle and the angle
rate over 10 s; does the motion change with the density?  (c) The same on the Moon.

Read the module docstring of ``mjcf`` first: it states the conventions (gravity along -y, angles about +z) and
how the grader runs a model.
"""

import numpy as np

from .mjcf import HEIGHT, LENGTH, WIDTH, number, vector

__all__ = ["pendulum"]


def pendulum(density, gravity, damping=0.0, torque=0.0):
    """MJCF text of the pendulum: one body with one hinge joint and one box geom.

    ``density``  [kg/m^3] of the link; MuJoCo computes its mass and inertia from the box (use the ``density``
                 attribute of the geom, not ``mass``).
    ``gravity``  the magnitude g [m/s^2] (``mjcf.EARTH``, ``mjcf.MOON``); it points along -y.
    ``damping``  the joint's damping AS THE TUTORIAL GIVES IT, in N m/(deg/s); MuJoCo's hinge ``damping`` is in
                 N m s/rad, so convert it.
    ``torque``   amplitude [N m] of the input torque ``torque * sin(t)``.  Declare one ``<motor>`` on the joint
                 whose ``gear`` is ``torque``: the grader feeds it the control ``sin(t)`` at every step (the
                 tutorial's sine-wave source), so that the joint torque is ``torque * sin(t)``.  With
                 ``torque = 0`` declare no actuator.

    The joint sits at the world origin with axis +z; the link extends from the joint along +x (angle 0 is
    horizontal, counter-clockwise positive).  Declare the integrator: ``<option integrator="RK4"
    timestep="0.001"/>``.  Write numbers with ``mjcf.number``/``mjcf.vector`` (full precision).
    """
    # BEGIN SOLUTION problem 2
    per_radian = damping * 180 / np.pi  # N m/(deg/s) -> N m s/rad: 1 rad/s is 180/pi deg/s
    motor = ""
    if torque:
        motor = f"""
  <actuator>
    <motor name="input_torque" joint="joint1" gear="{number(torque)}"/>
  </actuator>"""
    return f"""<mujoco model="pendulum">
  <compiler angle="radian"/>
  <option gravity="{vector([0.0, -gravity, 0.0])}" timestep="0.001" integrator="RK4"/>
  <worldbody>
    {link_body(1, density, damping=per_radian)}
  </worldbody>{motor}
</mujoco>
"""
    # END SOLUTION


# BEGIN REFERENCE ONLY
# The reference's building block of every Exercise I model, and its own planar model of the chains of links (an
# ODE solved with scipy, independent of MuJoCo): the oracle that the students' MuJoCo runs are compared with.


def link_body(i, density=None, pos=0.0, angle=0.0, damping=0.0, children="", inertial=None):
    """The ``<body>`` of link ``i``: a hinge about z at the body's origin (``pos`` along the parent's x, rotated by
    ``angle`` about z), the brick from there along the body's x; inertia from ``density``, or from ``inertial``
    (``(mass, com, B_I_S)``: mass, centre of mass and inertia about it, in the body frame)."""
    size = vector([LENGTH / 2, WIDTH / 2, HEIGHT / 2])
    centre = vector([LENGTH / 2, 0.0, 0.0])
    if inertial is None:
        geom = f'<geom name="brick{i}" type="box" size="{size}" pos="{centre}" density="{number(density)}"'
        explicit = ""
    else:
        mass, com, I = inertial
        I = np.asarray(I, dtype=float)
        full = vector([I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]])
        explicit = f'<inertial pos="{vector(com)}" mass="{number(mass)}" fullinertia="{full}"/>\n      '
        geom = f'<geom name="brick{i}" type="box" size="{size}" pos="{centre}" mass="0"'
    return (
        f'<body name="link{i}" pos="{vector([pos, 0.0, 0.0])}" euler="0 0 {number(angle)}">\n'
        f'      <joint name="joint{i}" type="hinge" axis="0 0 1" damping="{number(damping)}"/>\n'
        f"      {explicit}{geom} contype=\"0\" conaffinity=\"0\"/>\n"
        + (f"      {children}\n" if children else "")
        + "    </body>"
    )


def link_mass_inertia(density):
    """Mass and inertia about the centre of gravity, about the link's z-axis, of the brick: ``m``, ``I_zz``."""
    m = density * LENGTH * WIDTH * HEIGHT
    return m, m * (LENGTH**2 + WIDTH**2) / 12


def chain_dynamics(q, qd, density, gravity):
    """``M, f, g`` of ``M qdd = f + g + tau`` for a planar chain of ``len(q)`` identical links (the brick, pivot at
    one end, next joint at the other), joint angles relative, about z; gravity ``(0, -gravity)``.

    Projected Newton-Euler: with the absolute angles ``phi_i = q_1 + ... + q_i``, the centre of gravity of link i
    is ``r_Si = sum_{k<i} L e(phi_k) + L/2 e(phi_i)``; ``M = sum(m J_S.T J_S + I J_R.T J_R)``,
    ``f = -sum(m J_S.T sigma_S)`` (sigma_S: the acceleration of S with qdd = 0), ``g = sum(J_S.T m (0, -gravity))``.
    """
    q, qd = np.asarray(q, dtype=float), np.asarray(qd, dtype=float)
    n = len(q)
    m, I = link_mass_inertia(density)
    phi, phid = np.cumsum(q), np.cumsum(qd)
    e = np.stack([np.cos(phi), np.sin(phi)], axis=1)
    e_perp = np.stack([-np.sin(phi), np.cos(phi)], axis=1)
    M, f, g = np.zeros((n, n)), np.zeros(n), np.zeros(n)
    for i in range(n):
        arm = np.full(i + 1, LENGTH)
        arm[i] = LENGTH / 2
        J_S = np.zeros((2, n))
        J_S[:, : i + 1] = np.cumsum((arm[:, None] * e_perp[: i + 1])[::-1], axis=0)[::-1].T
        sigma_S = -(arm[:, None] * e[: i + 1] * phid[: i + 1, None] ** 2).sum(axis=0)
        J_R = (np.arange(n) <= i).astype(float)
        M += m * J_S.T @ J_S + I * np.outer(J_R, J_R)
        f -= m * J_S.T @ sigma_S
        g += J_S.T @ np.array([0.0, -m * gravity])
    return M, f, g


def chain_run(n, density, gravity, duration, sample=0.01, damping=0.0, torque=0.0, rate=None, q0=None):
    """The chain of ``n`` links from rest (angles ``q0``, default 0) over ``duration`` seconds, sampled every
    ``sample`` seconds: ``{"t", "q", "qd"}`` (``q``, ``qd``: samples x n).

    ``damping`` [N m s/rad] acts on every joint; ``torque * sin(t)`` drives joint 1; with ``rate`` joint 1 is driven
    kinematically, ``q1 = rate t`` (so ``q1_dot = rate`` from t = 0, ``q1_ddot = 0``) and the others are free.
    ``solve_ivp`` (DOP853, rtol 1e-10): far tighter than any comparison made with it.
    """
    from scipy.integrate import solve_ivp

    q0 = np.zeros(n) if q0 is None else np.asarray(q0, dtype=float)
    free = slice(1, n) if rate is not None else slice(0, n)
    nf = n - 1 if rate is not None else n

    def full(t, y):
        q, qd = q0.copy(), np.zeros(n)
        q[free], qd[free] = y[:nf], y[nf:]
        if rate is not None:
            q[0], qd[0] = q0[0] + rate * t, rate
        return q, qd

    def rhs(t, y):
        q, qd = full(t, y)
        M, f, g = chain_dynamics(q, qd, density, gravity)
        tau = -damping * qd
        tau[0] += torque * np.sin(t)
        qdd = np.linalg.solve(M[free, free], (f + g + tau)[free])  # qdd of a driven joint is 0
        return np.concatenate([y[nf:], qdd])

    t = np.arange(int(round(duration / sample)) + 1) * sample
    y0 = np.concatenate([q0[free], np.zeros(nf)])
    sol = solve_ivp(rhs, (0.0, t[-1]), y0, method="DOP853", t_eval=t, rtol=1e-10, atol=1e-12)
    if not sol.success:
        raise RuntimeError(f"the reference ODE failed: {sol.message}")
    states = [full(tk, yk) for tk, yk in zip(t, sol.y.T)]
    return {"t": t, "q": np.array([s[0] for s in states]), "qd": np.array([s[1] for s in states])}


def pendulum_ode(density, gravity, damping=0.0, torque=0.0, duration=10.0, sample=0.01):
    """The reference's pendulum: ``chain_run`` with one link, ``damping`` in the tutorial's N m/(deg/s)."""
    return chain_run(1, density, gravity, duration, sample, damping=damping * 180 / np.pi, torque=torque)


def pendulum_period(density, gravity):
    """Exact period [s] of the undamped pendulum released at rest from the horizontal (amplitude pi/2 about the
    hanging position): ``T = 4 sqrt(I_O / (m g L/2)) K(sin(pi/4))``, K the complete elliptic integral of the
    first kind, ``I_O = I + m (L/2)^2`` the inertia about the pivot.  It does not depend on the density."""
    from scipy.special import ellipk

    m, I = link_mass_inertia(density)
    I_O = I + m * (LENGTH / 2) ** 2
    return float(4 * np.sqrt(I_O / (m * gravity * LENGTH / 2)) * ellipk(np.sin(np.pi / 4) ** 2))


# END REFERENCE ONLY
