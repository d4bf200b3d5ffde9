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
    # TODO problem 4: write your solution here
    raise NotImplementedError("Problem 4: assemble is not implemented yet")


def balanced_configuration(fixed_point=FIXED_POINT):
    """A configuration ``q`` (four angles) in which the four-bar is in static equilibrium: the loop closes and
    gravity does no work along the linkage's only possible motion, so it stays at rest (if only for a while).
    Any such configuration is accepted, for the sheet's fixed point and for other points ``(d, 0, 0)`` on the ground
    within the links' reach (the checks ask such points too); raises ``UnreachableError`` for a point out of reach.

    The balanced configurations are those where the links' centre of gravity is highest or lowest along the
    motion.  With the fixed point at ``(d, 0, 0)`` one of them is the symmetric trapezoid with link 2 horizontal;
    ``assemble`` with the target ``q1`` of that trapezoid may find the loop's other configuration with the same
    ``q1``, which is not balanced."""
    # TODO problem 4: write your solution here
    raise NotImplementedError("Problem 4: balanced_configuration is not implemented yet")


def four_bar(density, gravity, q, fixed_point=FIXED_POINT):
    """MJCF text of the four-bar in the configuration ``q`` (four angles; the model uses q1, q2, q3).

    Build the three links as the double pendulum of problem 3 plus one more (bodies ``link1`` ... ``link3``,
    hinges ``joint1`` ... ``joint3``), each body rotated by its joint angle about z (``euler="0 0 q_i"`` with
    ``<compiler angle="radian"/>``), so that the model as written IS the configuration ``q``.  Close the loop with
    an equality constraint: ``<equality><connect site1="tip" site2="fixed"/></equality>``, with a site ``tip`` at
    the free end of link 3 and a site ``fixed`` on the world body at ``fixed_point`` (a ``connect`` acts as the
    fourth revolute joint).  Gravity ``(0, -gravity, 0)``; inertia from the geometry; RK4 with a 1 ms step.
    """
    # TODO problem 4: write your solution here
    raise NotImplementedError("Problem 4: four_bar is not implemented yet")


