"""Problem 4: a four-bar linkage in MuJoCo, and the assembly that Simscape did for you.

The double pendulum of problem 3 gets a third identical link; the free end of link 3 is connected by a fourth
revolute joint to a point fixed in the world, ``FIXED_POINT = (0.5, 0, 0)``.  Joint angles
``q = (q1, q2, q3, q4)``: q1 of link 1 from +x, q2 and q3 of each link relative to the previous one (all about z,
counter-clockwise positive), q4 the angle of the fourth joint, i.e. of the world frame relative to link 3, so that
``q1 + q2 + q3 + q4 = 0`` (mod 2 pi).  The loop is closed when the end of link 3 is at the fixed point.

Simscape assembles a model before it runs it: from the joint state targets it finds a configuration in which
every loop closes, or it reports why it cannot.  Here you write that assembly (``assemble``), then the MuJoCo
model of the four-bar in a configuration you found (``four_bar``).

(a) All four joint targets at 0: why does the assembly fail?  (b) Keep one target and find a balanced
configuration, in which the linkage stays at rest (at least initially).  (c) With the fixed point at
``(1, 0, 0)`` the model cannot be assembled: why?  (answers.toml, [problem_04.free_text] a and c)
"""

import numpy as np

from .mjcf import LENGTH, vector

__all__ = [
    "FIXED_POINT",
    "UNREACHABLE_POINT",
    "AssemblyError",
    "OverconstrainedError",
    "UnreachableError",
    "loop_points",
    "assemble",
    "balanced_configuration",
    "four_bar",
]

FIXED_POINT = (0.5, 0.0, 0.0)
UNREACHABLE_POINT = (1.0, 0.0, 0.0)


class AssemblyError(ValueError):
    """The four-bar cannot be assembled as asked; the message says why, with the numbers."""


class OverconstrainedError(AssemblyError):
    """More joint targets than the four-bar's one degree of freedom can meet (they conflict)."""


class UnreachableError(AssemblyError):
    """The loop cannot close: the end of link 3 cannot reach the fixed point (with the targets given)."""


def loop_points(q):
    """The positions (x, y) of joints 1, 2, 3 and of the end of link 3 for the angles ``q`` (q4, if given, is not
    needed): a 4 x 2 array, joint 1 at the origin."""
    q = np.asarray(q, dtype=float)[:3]
    phi = np.cumsum(q)
    steps = LENGTH * np.stack([np.cos(phi), np.sin(phi)], axis=1)
    return np.vstack([np.zeros(2), np.cumsum(steps, axis=0)])


def assemble(targets, fixed_point=FIXED_POINT):
    """A configuration ``q = (q1, q2, q3, q4)`` [rad] in which the loop closes and every targeted joint is at its
    target.

    ``targets``: four entries, one per joint, each a target angle [rad] or ``None`` (no target).  Solve the closure
    equations (the end of link 3 at the fixed point; two equations in the three angles q1, q2, q3) together with the
    targets by Newton's method or least squares, from a few starting guesses; q4 follows from
    ``q1 + q2 + q3 + q4 = 0``.  Return the angles wrapped to (-pi, pi].

    Raises ``OverconstrainedError`` when more joints have targets than the linkage's one degree of freedom allows,
    and ``UnreachableError`` when the loop cannot close (the fixed point is farther away than the three links reach,
    or the targets leave the other links unable to reach it).  The messages say why, with the numbers.
    """
    # BEGIN SOLUTION problem 4
    targets = list(targets)
    if len(targets) != 4:
        raise ValueError(f"targets needs one entry per joint (four), got {len(targets)}")
    given = [(k, float(t)) for k, t in enumerate(targets) if t is not None]
    if len(given) > 1:
        joints = ", ".join(f"q{k + 1} = {t:g}" for k, t in given)
        raise OverconstrainedError(
            f"{len(given)} joint targets ({joints}) for a four-bar with one degree of freedom: three links and "
            "a closed loop leave one free angle, so at most one target can be met; the others conflict")
    P = np.asarray(fixed_point, dtype=float)[:2]
    reach = 3 * LENGTH
    if np.linalg.norm(P) > reach + 1e-12:
        raise UnreachableError(
            f"the fixed point ({P[0]:g}, {P[1]:g}) is {np.linalg.norm(P):g} m from joint 1, but the three "
            f"links of {LENGTH:g} m reach at most {reach:g} m: the loop cannot close")

    def residual(x):
        r = loop_points(x)[-1] - P
        extra = []
        for k, t in given:
            angle = -np.sum(x) if k == 3 else x[k]
            extra.append(np.angle(np.exp(1j * (angle - t))))
        return np.concatenate([r, extra])

    def jacobian(x):
        phi = np.cumsum(x)
        J = np.zeros((2 + len(given), 3))
        for j in range(3):
            J[0, j] = -LENGTH * np.sum(np.sin(phi[j:]))
            J[1, j] = LENGTH * np.sum(np.cos(phi[j:]))
        for row, (k, _) in enumerate(given):
            J[2 + row] = -1.0 if k == 3 else np.eye(3)[k]
        return J

    for guess in _GUESSES:
        x = np.array(guess, dtype=float)
        for k, t in given:
            if k < 3:
                x[k] = t
        for _ in range(60):
            step = np.linalg.lstsq(jacobian(x), -residual(x), rcond=None)[0]
            x = x + step
            if np.linalg.norm(step) < 1e-14:
                break
        if np.linalg.norm(residual(x)) < 1e-10:
            q = np.append(x, -np.sum(x))
            return np.angle(np.exp(1j * q))
    joints = ", ".join(f"q{k + 1} = {t:g}" for k, t in given) or "no target"
    raise UnreachableError(
        f"no configuration closes the loop with {joints}: the remaining links cannot reach the fixed point "
        f"({P[0]:g}, {P[1]:g})")
    # END SOLUTION


def balanced_configuration(fixed_point=FIXED_POINT):
    """A configuration ``q`` (four angles) in which the four-bar is in static equilibrium: the loop closes and
    gravity does no work along the linkage's only possible motion, so it stays at rest (if only for a while).
    Any such configuration is accepted, for the sheet's fixed point and for other points ``(d, 0, 0)`` on the ground
    within the links' reach (the checks ask such points too); raises ``UnreachableError`` for a point out of reach.

    The balanced configurations are those where the links' centre of gravity is highest or lowest along the
    motion.  With the fixed point at ``(d, 0, 0)`` one of them is the symmetric trapezoid with link 2 horizontal;
    ``assemble`` with the target ``q1`` of that trapezoid may find the loop's other configuration with the same
    ``q1``, which is not balanced."""
    # BEGIN SOLUTION problem 4
    # Walk along the loop with q1 (links 2 and 3 close it, their middle joint on either side), find where
    # gravity's work along the motion changes sign, bisect there, and keep the highest balanced configuration.
    P = np.asarray(fixed_point, dtype=float)[:2]
    if np.linalg.norm(P) > 3 * LENGTH + 1e-12:
        raise UnreachableError(
            f"the fixed point ({P[0]:g}, {P[1]:g}) is {np.linalg.norm(P):g} m from joint 1, but the three links "
            f"of {LENGTH:g} m reach at most {3 * LENGTH:g} m: the loop cannot close")

    def closed(q1, side):
        """(q1, q2, q3) closing the loop, or None where the end of link 1 is too far from the fixed point."""
        gap = P - LENGTH * np.array([np.cos(q1), np.sin(q1)])
        distance = np.linalg.norm(gap)
        if not 1e-9 < distance <= 2 * LENGTH:
            return None
        towards, spread = np.arctan2(gap[1], gap[0]), np.arccos(min(1.0, distance / (2 * LENGTH)))
        phi2, phi3 = towards + side * spread, towards - side * spread  # the absolute angles of links 2 and 3
        return np.array([q1, phi2 - q1, phi3 - phi2])

    def work(x):
        """Gravity's work along the motion: the gradient of the links' centre heights along the closure
        Jacobian's null vector (the cross product of its two rows)."""
        phi = np.cumsum(x)
        J = np.array([[-LENGTH * np.sum(np.sin(phi[j:])) for j in range(3)],
                      [LENGTH * np.sum(np.cos(phi[j:])) for j in range(3)]])
        weights = np.array([2.5, 1.5, 0.5])  # links beyond the joint, plus half of its own link
        gradient = np.array([LENGTH * np.sum(weights[j:] * np.cos(phi[j:])) for j in range(3)])
        return float(np.cross(J[0], J[1]) @ gradient)

    def height(x):
        points = loop_points(x)
        return float(np.sum(points[:-1, 1] + points[1:, 1]))

    balanced = []
    grid = np.linspace(-np.pi, np.pi, 361)
    for side in (1.0, -1.0):
        for a, b in zip(grid[:-1], grid[1:]):
            x_a, x_b = closed(a, side), closed(b, side)
            if x_a is None or x_b is None or np.sign(work(x_a)) == np.sign(work(x_b)):
                continue
            for _ in range(60):
                middle = 0.5 * (a + b)
                x_m = closed(middle, side)
                if x_m is None:
                    break
                if np.sign(work(x_m)) == np.sign(work(x_a)):
                    a, x_a = middle, x_m
                else:
                    b, x_b = middle, x_m
            balanced.append(x_a if abs(work(x_a)) <= abs(work(x_b)) else x_b)
    if not balanced:
        raise AssemblyError(f"no balanced configuration found for the fixed point ({P[0]:g}, {P[1]:g})")
    x = max(balanced, key=height)
    return np.angle(np.exp(1j * np.append(x, -np.sum(x))))
    # END SOLUTION


def four_bar(density, gravity, q, fixed_point=FIXED_POINT):
    """MJCF text of the four-bar in the configuration ``q`` (four angles; the model uses q1, q2, q3).

    Build the three links as the double pendulum of problem 3 plus one more (bodies ``link1`` ... ``link3``,
    hinges ``joint1`` ... ``joint3``), each body rotated by its joint angle about z (``euler="0 0 q_i"`` with
    ``<compiler angle="radian"/>``), so that the model as written IS the configuration ``q``.  Close the loop with
    an equality constraint: ``<equality><connect site1="tip" site2="fixed"/></equality>``, with a site ``tip`` at
    the free end of link 3 and a site ``fixed`` on the world body at ``fixed_point`` (a ``connect`` acts as the
    fourth revolute joint).  Gravity ``(0, -gravity, 0)``; inertia from the geometry; RK4 with a 1 ms step.
    """
    # BEGIN SOLUTION problem 4
    from .problem_02 import link_body

    q = np.asarray(q, dtype=float)
    tip = f'<site name="tip" pos="{vector([LENGTH, 0.0, 0.0])}"/>'
    link3 = link_body(3, density, pos=LENGTH, angle=q[2], children=tip)
    link2 = link_body(2, density, pos=LENGTH, angle=q[1], children=link3)
    link1 = link_body(1, density, angle=q[0], children=link2)
    return f"""<mujoco model="four_bar">
  <compiler angle="radian"/>
  <option gravity="{vector([0.0, -gravity, 0.0])}" timestep="0.001" integrator="RK4"/>
  <worldbody>
    <site name="fixed" pos="{vector(fixed_point)}"/>
    {link1}
  </worldbody>
  <equality>
    <connect name="fourth_joint" site1="tip" site2="fixed"/>
  </equality>
</mujoco>
"""
    # END SOLUTION


# BEGIN REFERENCE ONLY
#: starting guesses of the assembly's Newton iterations (q1, q2, q3): both branches, stretched and folded
_GUESSES = [(0.7, -0.7, -0.7), (-0.7, 0.7, 0.7), (1.4, -1.4, -1.4), (-1.4, 1.4, 1.4), (0.2, -2.0, 1.0),
            (-0.2, 2.0, -1.0), (2.5, -2.0, -2.0), (-2.5, 2.0, 2.0), (0.0, 1.5, -3.0), (0.0, -1.5, 3.0)]


def loop_tangent(q):
    """The unit direction ``t`` (in q1, q2, q3) of the linkage's only motion at ``q`` (the null space of the
    closure Jacobian), with its first clearly nonzero entry positive."""
    phi = np.cumsum(np.asarray(q, dtype=float)[:3])
    J = np.array([[-LENGTH * np.sum(np.sin(phi[j:])) for j in range(3)],
                  [LENGTH * np.sum(np.cos(phi[j:])) for j in range(3)]])
    t = np.linalg.svd(J)[2][-1]
    lead = t[np.flatnonzero(np.abs(t) > 1e-9)[0]]
    return t * np.sign(lead)


def tangent_acceleration(q, density, gravity):
    """The acceleration ``alpha`` [rad/s^2] along ``loop_tangent(q)`` of the four-bar released at rest in ``q``:
    ``alpha = t.T g / (t.T M t)`` (the constraint force does no work along t).  0 in a balanced configuration."""
    from .problem_02 import chain_dynamics

    q3 = np.asarray(q, dtype=float)[:3]
    M, _, g = chain_dynamics(q3, np.zeros(3), density, gravity)
    t = loop_tangent(q3)
    return float(t @ g / (t @ M @ t))


# END REFERENCE ONLY
