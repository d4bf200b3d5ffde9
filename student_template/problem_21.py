"""Problem 21: the planar arms of cases a and b at the sheet's two joint configurations.

Case (1) is the configuration of the sheet's figure; for case (2) and ``q_b`` the end effector sits at
``(-0.1799, 0.3616, 1.0472)``.
"""

import numpy as np

from .planar import chain_a, chain_b, jacobian_a, jacobian_b

__all__ = ["D", "CASES", "TARGET_END_EFFECTOR_CASE_2", "solve"]

#: length of the final link [m]
D = 0.15

#: the sheet's joint coordinates per case: ``{case: (q_a, q_b)}`` (lengths in m, angles in rad)
CASES = {
    1: ((0.1, np.deg2rad(-45.0)), (0.1, np.deg2rad(-45.0), 0.2, np.deg2rad(45.0))),
    2: ((0.2, np.deg2rad(30.0)), (0.2, np.deg2rad(30.0), 0.1, np.deg2rad(30.0))),
}

#: end-effector pose ``(xe, ye, gammae)`` of case (2), ``q_b``, as printed on the sheet (four decimals)
TARGET_END_EFFECTOR_CASE_2 = (-0.1799, 0.3616, 1.0472)


def solve(case):
    """``{"x_a", "J_a", "x_b", "J_b"}`` of the sheet's case 1 or 2 with ``d = D``."""
    q_a, q_b = CASES[case]
    return {
        "x_a": chain_a(q_a, D),
        "J_a": jacobian_a(q_a, D),
        "x_b": chain_b(q_b, D),
        "J_b": jacobian_b(q_b, D),
    }
