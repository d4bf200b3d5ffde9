"""The cases of the tree checks: kinematic trees as plain data (the format of ``probes._trees`` and
``probes._dynamics``), drawn at random or fixed, and their description in a message.

What the kinematics (``checks._trees``) and the dynamics (``checks._dynamics``) share is here; what differs stays
with them as a parameter: how a joint's geometry and its successor body are made (kinematic trees have the
probe's own ``"test"`` joint and unit masses, dynamic trees masses and inertias), how many joints a tree has at
least, and what follows the coordinates in a case.

* ``draw_tree``: a random tree, each joint at a random earlier body (shrinking towards a chain), its geometry from
  a seed of its own (seed 0: the plainest joint), the coordinates numbered in a random order;
* ``case_strategy``: ``(description, *values, *tail)`` with ``count`` vectors of values in [-2, 2] (from seeds,
  shrinking towards zero);
* ``rich_joints`` and ``rich_values``: the fixed case that exercises every term: a chain through all kinds plus a
  branch at body 1, values bounded away from zero;
* ``joint_lines``: the joints of a case in words.
"""

import numpy as np

from grader import strategies as st

__all__ = [
    "NQ",
    "SEEDS",
    "rotation_of",
    "random_rotation",
    "random_frames",
    "values",
    "number_coordinates",
    "coordinate_count",
    "draw_tree",
    "case_strategy",
    "rich_joints",
    "rich_values",
    "KIND_NAMES",
    "joint_lines",
]

#: the number of coordinates of each kind of joint (the probe's "test" joint has one or two)
NQ = {"rotational": 1, "translational": 1, "rolling_contact": 1, "virtual_3dof": 3, "rigid": 0}
#: the seed of a joint's geometry or of a vector of values: 0 is the plainest
SEEDS = st.integers(0, 2**32 - 1)


def rotation_of(quaternion):
    """The rotation matrix of a quaternion ``(w, x, y, z)`` (normalized here)."""
    w, x, y, z = np.asarray(quaternion, dtype=float) / np.linalg.norm(quaternion)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def random_rotation(rng, nudge: float = 0.0):
    """A random rotation (uniformly distributed): of a random quaternion, each entry moved by ``nudge`` (which keeps
    it away from zero)."""
    quaternion = rng.normal(size=4)
    return rotation_of(quaternion + nudge if nudge else quaternion)


def random_frames(rng, nudge: float = 0.0) -> dict:
    """A joint's random offsets (in [-1, 1]) and frames, drawn from ``rng`` in the order ``P_r_PDp``, ``A_PDp``,
    ``S_r_SDs``, ``A_SDs``."""
    return {"P_r_PDp": rng.uniform(-1, 1, 3), "A_PDp": random_rotation(rng, nudge), "S_r_SDs": rng.uniform(-1, 1, 3),
            "A_SDs": random_rotation(rng, nudge)}


def values(seed, n, bound=2.0):
    """``n`` values in [-bound, bound] from ``seed``; seed 0 gives zeros."""
    return np.zeros(n) if seed == 0 else np.random.default_rng(seed).uniform(-bound, bound, n)


def number_coordinates(joints, sizes, order) -> None:
    """Give each joint its ``q_index``: the next ``size`` numbers of ``order``."""
    for joint, start, size in zip(joints, np.cumsum([0, *sizes]), sizes):
        joint["q_index"] = [int(i) for i in order[start:start + size]]


def coordinate_count(description) -> int:
    return sum(len(joint["q_index"]) for joint in description["joints"])


def draw_tree(draw, kinds, joints, root, member):
    """A tree description of ``draw(joints)`` joints of the given ``kinds``: ``root(draw)`` is the first body, and
    ``member(draw, k, kind)`` gives joint ``k``'s geometry, its successor body and its number of coordinates.  Each
    joint hangs at a random earlier body (shrinking towards a chain); the coordinates are numbered in a random
    order.  The first joint moves, so ``nq >= 1``."""
    n = draw(joints)
    bodies, found, sizes = [root(draw)], [], []
    for k in range(n):
        kind = draw(st.sampled_from([kind for kind in kinds if kind != "rigid"] if k == 0 else list(kinds)))
        parent = k - draw(st.integers(0, k))
        geometry, body, nq = member(draw, k, kind)
        found.append({"kind": kind, "parent": parent, **geometry})
        bodies.append(body)
        sizes.append(nq)
    number_coordinates(found, sizes, draw(st.permutations(range(sum(sizes)))))
    return {"bodies": bodies, "joints": found}


def case_strategy(trees, count, tail=()):
    """``(description, *values, *tail)``: a tree of the strategy ``trees`` and ``count`` vectors of values in
    [-2, 2], one per coordinate (each drawn from a seed, shrinking towards zero)."""

    @st.composite
    def draw_case(draw):
        description = draw(trees)
        nq = coordinate_count(description)
        return (description, *[values(draw(SEEDS), nq) for _ in range(count)], *tail)

    return draw_case()


def rich_joints(rng, kinds, geometry, nq_of):
    """The joints of the fixed case: a chain through all ``kinds`` (after a first joint of ``kinds[0]``) plus a
    branch at body 1 (of ``kinds[-1]``), ``geometry(rng, kind)`` each, coordinates numbered in random order."""
    sequence = [kinds[0], *kinds, kinds[-1]]
    joints, sizes = [], []
    for k, kind in enumerate(sequence):
        joints.append({"kind": kind, "parent": 1 if k == len(sequence) - 1 else k, **geometry(rng, kind)})
        sizes.append(nq_of(kind))
    number_coordinates(joints, sizes, rng.permutation(sum(sizes)))
    return joints


def rich_values(rng, n, count):
    """``count`` vectors of ``n`` values bounded away from zero: magnitudes in [0.3, 1.5], random signs."""
    return [rng.uniform(0.3, 1.5, n) * rng.choice([-1, 1], n) for _ in range(count)]


#: how a message names a kind of joint (the others by their own name)
KIND_NAMES = {"test": "test joint (rotation c @ q about the Dp 3-axis, translation U @ q)",
              "virtual_3dof": "virtual 3-DOF", "rolling_contact": "rolling contact"}


def joint_lines(description, compact) -> list[str]:
    """One line per joint of ``description``: its kind, the bodies it joins, its coordinates and geometry, each
    vector or matrix shown by ``compact``."""
    names = [body["name"] for body in description["bodies"]]
    lines = []
    for k, joint in enumerate(description["joints"]):
        extra = ""
        if joint["kind"] == "rolling_contact":
            extra = f", r = {joint['r']:.4g}"
        elif joint["kind"] == "test":
            extra = f", c = {compact(joint['c'])}, U = {compact(joint['U'])}"
        lines.append(
            f"  joint {k + 1}: {KIND_NAMES.get(joint['kind'], joint['kind'])} {names[joint['parent']]} -> "
            f"{names[k + 1]}, q_index {joint['q_index']}, P_r_PDp = {compact(joint['P_r_PDp'])}, "
            f"A_PDp = {compact(joint['A_PDp'])}, S_r_SDs = {compact(joint['S_r_SDs'])}, "
            f"A_SDs = {compact(joint['A_SDs'])}{extra}")
    return lines
