"""Problem 35: the joint functions of the four joint types, symbolically.

Each joint type is defined by its relative pose ``A_DpDs(q)``, ``Dp_r_DpDs(q)``; everything else follows by
differentiation along ``q(t)`` (problem data P35), all in Dp-coordinates:

``r_rel_dot  = d r_rel/dt = (d r_rel/dq) qd``          ``r_rel_ddot = d r_rel_dot/dt``
``skew(omega_rel) = (d A_DpDs/dt) A_DpDs.T``             ``omega_rel_dot = d omega_rel/dt``
``S = d r_rel_dot/d qd``                                ``R = d omega_rel/d qd``

The symbols: rotational ``q = (gamma,)``, translational ``q = (dx,)``, 3-DOF ``q = (dx, dy, gamma)``, rolling
``q = (gamma,)`` with the radius ``r``; the derivatives are named ``d_<name>`` and ``dd_<name>``.
"""

__all__ = [
    "JOINT_TYPES",
    "joint_function_from_pose",
    "rotational_joint_function",
    "translational_joint_function",
    "virtual_3dof_joint_function",
    "rolling_contact_joint_function",
    "solve",
]

#: the joint types of the sheet, in its order (a)-(d)
JOINT_TYPES = ("rotational", "translational", "virtual_3dof", "rolling_contact")


def _coordinates(names):
    """Sympy column vectors ``(q, qd, qdd)`` of real symbols named ``names``, ``d_names``, ``dd_names``."""
    import sympy as sp

    q = sp.Matrix(sp.symbols(names, real=True))
    qd = sp.Matrix([sp.Symbol(f"d_{s.name}", real=True) for s in q])
    qdd = sp.Matrix([sp.Symbol(f"dd_{s.name}", real=True) for s in q])
    return q, qd, qdd


def _rot3(angle):
    import sympy as sp

    c, s = sp.cos(angle), sp.sin(angle)
    return sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def joint_function_from_pose(q, qd, qdd, A_DpDs, Dp_r_DpDs):
    """The complete joint function for the relative pose ``A_DpDs(q)``, ``Dp_r_DpDs(q)`` (sympy), as a dict with
    the keys ``q``, ``qd``, ``qdd``, ``A_DpDs``, ``Dp_r_DpDs``, ``r_rel_dot``, ``r_rel_ddot``, ``omega_rel``,
    ``omega_rel_dot``, ``S``, ``R`` (sympy matrices; vectors as 3 x 1, ``S`` and ``R`` as 3 x nq)."""
    import sympy as sp

    # TODO problem 35: write your solution here
    raise NotImplementedError("Problem 35: joint_function_from_pose is not implemented yet")


def rotational_joint_function():
    """(a) Rotation by ``gamma`` about the Dp 3-axis: ``A_DpDs = R3(gamma)``, ``Dp_r_DpDs = 0``."""
    import sympy as sp

    q, qd, qdd = _coordinates("gamma,")
    # TODO problem 35: write your solution here
    raise NotImplementedError("Problem 35: rotational_joint_function is not implemented yet")


def translational_joint_function():
    """(b) Translation by ``dx`` along the Dp 1-axis: ``A_DpDs = E``, ``Dp_r_DpDs = (dx, 0, 0)``."""
    import sympy as sp

    q, qd, qdd = _coordinates("dx,")
    # TODO problem 35: write your solution here
    raise NotImplementedError("Problem 35: translational_joint_function is not implemented yet")


def virtual_3dof_joint_function():
    """(c) Planar 3-DOF joint, ``q = (dx, dy, gamma)``: ``A_DpDs = R3(gamma)``, ``Dp_r_DpDs = (dx, dy, 0)``."""
    import sympy as sp

    q, qd, qdd = _coordinates("dx, dy, gamma")
    # TODO problem 35: write your solution here
    raise NotImplementedError("Problem 35: virtual_3dof_joint_function is not implemented yet")


def rolling_contact_joint_function():
    """(d) Rolling contact of a circle of radius ``r``: ``A_DpDs = R3(gamma)``, ``Dp_r_DpDs = (-r gamma, 0, 0)``.
    The dict also holds the symbol ``r``."""
    import sympy as sp

    q, qd, qdd = _coordinates("gamma,")
    r = sp.Symbol("r", positive=True)
    # TODO problem 35: write your solution here
    raise NotImplementedError("Problem 35: rolling_contact_joint_function is not implemented yet")
    result["r"] = r
    return result


def solve():
    """``{joint type: joint function dict}`` for the four ``JOINT_TYPES``."""
    return {
        "rotational": rotational_joint_function(),
        "translational": translational_joint_function(),
        "virtual_3dof": virtual_3dof_joint_function(),
        "rolling_contact": rolling_contact_joint_function(),
    }
