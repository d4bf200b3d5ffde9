"""The formula tier's slips of whole numbers and of sums (``grader.diagnosis.mutants``): an array created as one of
integers and then filled with floats (``np.zeros(n, dtype=int)``), a number converted with ``int`` where ``float``
belongs, a division by a whole number written ``//``, a length taken as its square (``v @ v`` for
``np.linalg.norm(v)``), a running sum left out (``steps`` for ``np.cumsum(steps, axis=0)``) and a term of a sum left
outside the solve it belongs under (``solve(M, f + g) + tau``), or every term subtracted added instead (``M qdd + f +
g`` for ``M qdd - f - g``), or a factor of one term multiplying the whole sum (``m * (J.T @ J + R.T @ R)``), or the
weights of two terms exchanged (``w * a + (1 - w) * b``), or the identity written where a square block of zeros
belongs (``np.eye(k)`` for ``np.zeros((k, k))``).

Each is a mistake planted into a made-up problem that the tier names on two inputs, with a near miss it must not
name: a floor division whose quotient is zero on every input (an answer of zeros, which many slips reproduce, tells
nothing) and an array of integers that is only read, never filled (numpy's sums of it are floats: no slip)."""

import numpy as np

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem for the slips of whole numbers."""

import numpy as np


def table(n, w):
    """The cosines and sines of ``k w`` for ``k = 0 .. n - 1``, each scaled by 3.7."""
    # BEGIN SOLUTION problem 95
    out = np.zeros((n, 2))
    for k in range(n):
        out[k] = 3.7 * np.array([np.cos(w * k), np.sin(w * k)])
    return out
    # END SOLUTION


def shifted(n, w):
    """The cosines of ``k w`` for ``k = 0 .. n - 1``, each plus 0.25."""
    # BEGIN SOLUTION problem 95
    base = np.zeros(n)
    return base + np.cos(w * np.arange(n)) + 0.25
    # END SOLUTION


def moment(m, length):
    """A rod's moment of inertia about its centre and its centre's distance from its end."""
    # BEGIN SOLUTION problem 95
    return np.array([m / 12 * length ** 2, float(m * length / 2)])
    # END SOLUTION


def direction(v):
    """The unit vector along ``v``."""
    # BEGIN SOLUTION problem 95
    return v / np.linalg.norm(v)
    # END SOLUTION


def accelerations(M, f, g, tau):
    """The accelerations that solve ``M qdd = f + g + tau``."""
    # BEGIN SOLUTION problem 95
    return np.linalg.solve(M, f + g + tau)
    # END SOLUTION


def torque(M, qdd, f, g):
    """The torque that gives ``qdd`` against the bias ``f + g``."""
    # BEGIN SOLUTION problem 95
    return M @ qdd - f - g
    # END SOLUTION


def shares(m, J, R):
    """A made-up mass matrix: the translational share of mass ``m`` and the rotational one."""
    # BEGIN SOLUTION problem 95
    return m * J.T @ J + R.T @ R
    # END SOLUTION


def blend(a, b, w):
    """A made-up blend of ``a`` and ``b`` by the weight ``w``."""
    # BEGIN SOLUTION problem 95
    return (1.0 - w) * a + w * b
    # END SOLUTION


def saddle(M, J, b):
    """A made-up saddle-point system ``[[M, -J.T], [J, 0]] x = b`` solved."""
    # BEGIN SOLUTION problem 95
    k = J.shape[0]
    return np.linalg.solve(np.block([[M, -J.T], [J, np.zeros((k, k))]]), b)
    # END SOLUTION


def points(steps):
    """The points a chain of ``steps`` (rows) reaches from the origin."""
    # BEGIN SOLUTION problem 95
    return np.cumsum(steps, axis=0)
    # END SOLUTION
'''


made_up = made_up_fixture(SOURCE, 95, "whole")


def found(package, name, student, inputs):
    evidences = made_up_evidences(package, name, student, inputs, number=95)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    return mutants.mutant_slips(scene(f"p95.{name}"), evidences)


def named(hypotheses) -> set:
    return {h.name for h in hypotheses}


def test_an_array_of_integers_filled_with_floats_is_named_cut_to_whole_numbers(made_up):
    def student(n, w):
        out = np.zeros((n, 2), dtype=int)
        for k in range(n):
            out[k] = 3.7 * np.array([np.cos(w * k), np.sin(w * k)])
        return out

    hypotheses = found(made_up, "table", student, [(5, 0.7), (6, 1.3)])
    assert named(hypotheses) == {"integer_truncated"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`table` creates an array of integers" in h.detail for h in hypotheses)
    assert DIAGNOSES["integer_truncated"].family == "precision"


def test_an_array_of_integers_only_read_is_no_slip(made_up):
    """The near miss: ``base`` of integers is only added to, and numpy's sum is of floats: the mutant is the
    reference itself, and the student's value (a cosine of the wrong angle) is named by no slip of whole numbers."""
    hypotheses = found(made_up, "shifted", lambda n, w: np.zeros(n) + np.cos(1.1 * w * np.arange(n)) + 0.25,
                       [(5, 0.7), (6, 1.3)])
    assert "integer_truncated" not in named(hypotheses)


def test_a_number_converted_with_int_is_named_cut_to_a_whole_number(made_up):
    hypotheses = found(made_up, "moment", lambda m, length: np.array([m / 12 * length ** 2, int(m * length / 2)]),
                       [(2.5, 1.3), (3.1, 0.9)])
    assert named(hypotheses) == {"integer_truncated"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`moment` converts a number with ``int``" in h.detail for h in hypotheses)


def test_a_floor_division_is_named_where_its_quotient_is_not_zero(made_up):
    hypotheses = found(made_up, "moment", lambda m, length: np.array([m // 12 * length ** 2, m * length / 2]),
                       [(30.5, 1.3), (41.0, 0.9)])
    assert named(hypotheses) == {"integer_truncated"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`moment` divides with ``//``" in h.detail for h in hypotheses)


def test_a_floor_division_that_leaves_zeros_is_not_named(made_up):
    """The near miss: a mass below 12 floor-divided by 12 is 0, and the moment vanishes on every input: a value of
    zeros is reproduced by many slips and tells none of them."""
    def student(m, length):
        return np.array([m // 12 * length ** 2, 0.0])

    assert found(made_up, "moment", student, [(2.5, 1.3), (3.1, 0.9)]) == []


def test_a_length_taken_as_its_square_is_named_a_square_root_missing(made_up):
    hypotheses = found(made_up, "direction", lambda v: v / (v @ v), [(np.array([0.3, -1.2, 2.0]),),
                                                                    (np.array([1.5, 0.4, -0.7]),)])
    assert named(hypotheses) == {"wrong_factor"}, [(h.name, h.detail) for h in hypotheses]
    assert any("a square root is missing in `direction`" in h.detail for h in hypotheses)
    assert DIAGNOSES["wrong_factor"].family == "scale"


def test_a_running_sum_left_out_is_named_a_term_missing(made_up):
    steps = [(np.array([[0.3, 0.1], [0.2, -0.4], [0.5, 0.6]]),), (np.array([[-0.2, 0.7], [0.9, 0.1], [0.1, 0.3]]),)]
    hypotheses = found(made_up, "points", lambda s: s, steps)
    assert "missing_term" in named(hypotheses), [(h.name, h.detail) for h in hypotheses]
    assert any("`points` leaves out a running sum" in h.detail for h in hypotheses)
    assert {DIAGNOSES[h.name].family for h in hypotheses} == {"missing_term"}


def test_a_term_left_outside_the_solve_is_an_inverse_missing(made_up):
    M = [np.array([[2.0, 0.3, 0.0], [0.3, 1.5, 0.2], [0.0, 0.2, 1.0]]), np.array([[3.0, -0.4, 0.1], [-0.4, 2.0, 0.0],
                                                                                   [0.1, 0.0, 1.2]])]
    inputs = [(M[0], np.array([0.3, -1.0, 0.5]), np.array([0.0, -2.0, 0.1]), np.array([1.0, 0.4, -0.7])),
              (M[1], np.array([-0.8, 0.2, 1.1]), np.array([0.5, 0.3, -1.2]), np.array([-0.4, 0.9, 0.6]))]
    hypotheses = found(made_up, "accelerations", lambda M, f, g, tau: np.linalg.solve(M, f) + g + tau, inputs)
    assert {h.name for h in hypotheses} == {"no_inverse"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`accelerations` solves with a matrix for part of a sum only" in h.detail for h in hypotheses)


def test_every_term_subtracted_added_instead_is_a_sign(made_up):
    M = np.array([[2.0, 0.3, 0.0], [0.3, 1.5, 0.2], [0.0, 0.2, 1.0]])
    inputs = [(M, np.array([0.3, -1.0, 0.5]), np.array([0.0, -2.0, 0.1]), np.array([1.0, 0.4, -0.7])),
              (1.5 * M, np.array([-0.8, 0.2, 1.1]), np.array([0.5, 0.3, -1.2]), np.array([-0.4, 0.9, 0.6]))]
    hypotheses = found(made_up, "torque", lambda M, qdd, f, g: M @ qdd + f + g, inputs)
    assert {h.name for h in hypotheses} == {"sign_flip"}, [(h.name, h.detail) for h in hypotheses]


def test_a_factor_of_one_term_multiplying_the_whole_sum_is_a_factor(made_up):
    """The near miss: the second term scaled by the square of the factor is no factor spread over the sum."""
    rng = np.random.default_rng(7)
    inputs = [(2.5, rng.normal(size=(2, 3)), rng.normal(size=(2, 3))), (0.7, rng.normal(size=(2, 3)),
                                                                       rng.normal(size=(2, 3)))]
    hypotheses = found(made_up, "shares", lambda m, J, R: m * (J.T @ J + R.T @ R), inputs)
    assert {h.name for h in hypotheses} == {"wrong_factor"}, [(h.name, h.detail) for h in hypotheses]
    assert any("multiplies the whole sum" in h.detail for h in hypotheses)
    hypotheses = found(made_up, "shares", lambda m, J, R: m * J.T @ J + m ** 2 * R.T @ R, inputs)
    assert not any("whole sum" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_the_weights_of_two_terms_exchanged_are_swapped(made_up):
    inputs = [(np.array([0.3, -1.0, 0.5]), np.array([1.2, 0.4, -0.7]), 0.3),
              (np.array([-0.8, 0.2, 1.1]), np.array([0.5, 0.3, -1.2]), 0.15)]
    hypotheses = found(made_up, "blend", lambda a, b, w: w * a + (1.0 - w) * b, inputs)  # a, b exchanged alike
    assert {DIAGNOSES[h.name].family for h in hypotheses} == {"order"}, [(h.name, h.detail) for h in hypotheses]
    assert any("the weights of two terms of a sum in `blend` are exchanged" in h.detail for h in hypotheses)


def test_the_identity_where_a_block_of_zeros_belongs_is_a_term_added(made_up):
    """The near miss: the block written as twice the identity is not that slip."""
    M = np.array([[2.0, 0.3, 0.0], [0.3, 1.5, 0.2], [0.0, 0.2, 1.0]])
    inputs = [(M, np.array([[0.4, -1.0, 0.3]]), np.array([0.3, -1.0, 0.5, 0.2])),
              (1.5 * M, np.array([[-0.2, 0.7, 1.1]]), np.array([-0.8, 0.2, 1.1, -0.6]))]

    def student(block):
        return lambda M, J, b: np.linalg.solve(np.block([[M, -J.T], [J, block]]), b)

    hypotheses = found(made_up, "saddle", student(np.eye(1)), inputs)
    assert {h.name for h in hypotheses} == {"extra_term"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`saddle` writes the identity where a square block of zeros belongs" in h.detail for h in hypotheses)
    hypotheses = found(made_up, "saddle", student(2.0 * np.eye(1)), inputs)
    assert not any("block of zeros" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]
