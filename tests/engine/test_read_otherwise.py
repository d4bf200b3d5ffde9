"""Reads of one value where another belongs, and other slips of one read (``grader.diagnosis.mutants``), each planted
into a made-up problem that the formula tier names on two inputs:

* a name bound to a sum read as one of its terms (``l2 * cb`` for ``radius * cb`` where ``radius = l2 + l3 *
  np.sin(phi)``): a term left out there (``sum_part``);
* a constructor that stores one of its arguments from another it stores (a line copied from its neighbour), and a
  list of names with one entry written as its neighbour (``(m1, m1)`` for ``(m1, m2)``, in a loop's iterable too: it
  runs as often): a value left unused, an argument ignored (``stored_from``, ``repeated``);
* a loop's iterable that reads a quantity for its rate (``zip(q, qdd)`` for ``zip(q, qd)``): a state read from the
  wrong row;
* half a length written as a floor division (``L // 2`` for ``0.5 * L``): a value cut to a whole number (``floor``);
* a term of a sum taken twice (``l2 + 2 * l3 * np.sin(phi)``, the Coriolis habit, or an update written twice): a
  factor two there, and as truly that term added once more (``term_doubled``);
* a rotation left out of a product whose value is a matrix (``dt * W`` for ``dt * W @ A_IC``): as truly a matrix
  factor left out as a frame's slip;
* a parameter read as the constant its module imports from the library (``LENGTH`` for ``length``), as for a constant
  the module binds, and a gravity vector read as the Earth's (``np.array([0.0, -9.81, 0.0])`` for ``I_grav``): the
  argument ignored;
* one read of an argument where another that the same line reads in its arithmetic belongs (``a**2 + b**2`` for
  ``a**2 + c**2``): the wrong argument (``parameter_read``).

The near misses name no such slip: a term of the sum at three times its value, an argument stored at twice itself,
the entries of the list exchanged, a third of the length, a gravity of 9.7, a term doubled for the wrong argument, and
a module's constant typed with another's value (``RADIUS = 1.0`` where ``LENGTH = 1.0``: ``l, r = LENGTH, LENGTH``
gives the same, but a constant so written is a constant typed otherwise, which the constants' slips tell)."""

import numpy as np
import pytest

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants

from .stand_ins import made_up_fixture, made_up_package
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem of values read otherwise."""

import numpy as np


def reach(l2, l3, phi, beta):
    """A made-up point on a circle whose radius is an arm and a chain's reach."""
    # BEGIN SOLUTION problem 84
    radius = l2 + l3 * np.sin(phi)
    return np.array([radius * np.cos(beta), l3 * np.cos(phi), -radius * np.sin(beta)])
    # END SOLUTION


class Holder:
    """A made-up object that keeps two vectors and their sum."""

    def __init__(self, first, second):
        # BEGIN SOLUTION problem 84
        self.first = np.asarray(first, dtype=float)
        self.second = np.asarray(second, dtype=float)
        # END SOLUTION


def held(first, second):
    """A made-up reading of what a ``Holder`` keeps."""
    # BEGIN SOLUTION problem 84
    holder = Holder(first, second)
    return np.concatenate([holder.first, 2.0 * holder.second])
    # END SOLUTION


def weighted(a, b, m1, m2):
    """A made-up sum of two vectors, each weighted by its own mass."""
    # BEGIN SOLUTION problem 84
    total = np.zeros(2)
    for x, m in zip((a, b), (m1, m2)):
        total = total + m * np.asarray(x, dtype=float)
    return total
    # END SOLUTION


LENGTH = 1.0
RADIUS = 0.5


def wheel(angle):
    """A made-up point of a wheel of the module's radius on a leg of the module's length."""
    # BEGIN SOLUTION problem 84
    l, r = LENGTH, RADIUS
    return np.array([l * np.sin(angle) - r * angle, r - l * np.cos(angle)])
    # END SOLUTION


def turned_step(A_IC, w, dt):
    """A made-up Euler step of a rotation matrix turning at ``w``."""
    # BEGIN SOLUTION problem 84
    W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
    return A_IC + dt * W @ A_IC
    # END SOLUTION


def inertial(A_IB, B_v):
    """A made-up vector of body coordinates in inertial ones."""
    # BEGIN SOLUTION problem 84
    return A_IB @ B_v
    # END SOLUTION


def weight(m, I_grav):
    """A made-up weight of a body in a given gravity."""
    # BEGIN SOLUTION problem 84
    return m * np.asarray(I_grav, dtype=float)
    # END SOLUTION


def box(a, b, c):
    """A made-up set of a box's moments per unit mass."""
    # BEGIN SOLUTION problem 84
    return np.array([b**2 + c**2, a**2 + c**2, a**2 + b**2]) / 12
    # END SOLUTION


def power(q, qd, qdd):
    """A made-up sum of the coordinates' products with their rates, beside the accelerations' sum."""
    # BEGIN SOLUTION problem 84
    total = 0.0
    for qi, qdi in zip(q, qd):
        total = total + qi * qdi
    return np.array([total, np.sum(qdd)])
    # END SOLUTION


def centres(length, angles):
    """A made-up list of the centres of links of one length, at half the length along each angle."""
    # BEGIN SOLUTION problem 84
    half = 0.5 * length
    return np.array([[half * np.cos(a), half * np.sin(a)] for a in angles])
    # END SOLUTION
'''

made_up = made_up_fixture(SOURCE, 84, "read_otherwise")


def found(package, name, student, inputs):
    evidences = made_up_evidences(package, name, student, inputs, number=84)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    return mutants.mutant_slips(scene(f"p84.{name}"), evidences)


def names_of(hypotheses) -> set:
    return {h.name for h in hypotheses}


REACH = [(0.8, 0.5, 0.4, 1.1), (1.3, 0.7, -0.6, 0.3)]


def arm_only(l2, l3, phi, beta):
    radius = l2 + l3 * np.sin(phi)
    return np.array([l2 * np.cos(beta), l3 * np.cos(phi), -radius * np.sin(beta)])


def test_a_sum_read_as_its_first_term_is_a_term_left_out(made_up):
    hypotheses = found(made_up, "reach", arm_only, REACH)
    assert names_of(hypotheses) == {"missing_term"}, [(h.name, h.detail) for h in hypotheses]
    assert any("reads a name bound to a sum as one of its terms" in h.detail for h in hypotheses)


def reach_with(factor: float):
    def reach(l2, l3, phi, beta):
        radius = l2 + factor * l3 * np.sin(phi)
        return np.array([radius * np.cos(beta), l3 * np.cos(phi), -radius * np.sin(beta)])

    return reach


def test_a_term_of_the_sum_doubled_is_a_term_taken_twice_and_no_sum_read_as_a_term(made_up):
    hypotheses = found(made_up, "reach", reach_with(2.0), REACH)
    assert names_of(hypotheses) == {"factor_two", "extra_term"}, [(h.name, h.detail) for h in hypotheses]
    assert any("takes one term of a sum twice" in h.detail for h in hypotheses)
    assert any("adds one term of a sum once more" in h.detail for h in hypotheses)
    assert not any("bound to a sum" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_a_term_of_the_sum_at_three_times_its_value_is_no_term_taken_twice(made_up):
    assert "factor_two" not in names_of(found(made_up, "reach", reach_with(3.0), REACH))


VECTORS = [(np.array([0.3, -1.2, 0.5]), np.array([1.1, 0.4, -0.7])),
           (np.array([-0.8, 0.6, 1.4]), np.array([0.2, -0.9, 0.3]))]


def test_an_argument_stored_from_its_neighbour_is_a_value_unused(made_up):
    hypotheses = found(made_up, "held", lambda first, second: np.concatenate([first, 2.0 * first]), VECTORS)
    assert names_of(hypotheses) == {"value_unused"}, [(h.name, h.detail) for h in hypotheses]
    assert DIAGNOSES["value_unused"].family == "ignored_argument"
    assert any("stores one of its arguments from another" in h.detail for h in hypotheses)


def test_an_argument_stored_twice_itself_is_no_value_unused(made_up):
    hypotheses = found(made_up, "held", lambda first, second: np.concatenate([first, 4.0 * second]), VECTORS)
    assert "value_unused" not in names_of(hypotheses), [(h.name, h.detail) for h in hypotheses]


WEIGHTED = [(np.array([0.3, -1.2]), np.array([1.1, 0.4]), 2.0, 0.7),
            (np.array([-0.8, 0.6]), np.array([0.2, -0.9]), 1.3, 3.1)]


def test_an_entry_of_a_loops_list_written_as_its_neighbour_is_a_value_unused(made_up):
    hypotheses = found(made_up, "weighted", lambda a, b, m1, m2: m1 * a + m1 * b, WEIGHTED)
    assert names_of(hypotheses) == {"value_unused"}, [(h.name, h.detail) for h in hypotheses]
    assert any("writes one entry of a list of names as its neighbour" in h.detail for h in hypotheses)


def test_the_entries_of_a_loops_list_exchanged_are_no_value_unused(made_up):
    hypotheses = found(made_up, "weighted", lambda a, b, m1, m2: m2 * a + m1 * b, WEIGHTED)
    assert "value_unused" not in names_of(hypotheses), [(h.name, h.detail) for h in hypotheses]


CENTRES = [(3.0, np.array([0.3, 1.1, -0.4])), (5.0, np.array([-0.9, 0.2, 0.7]))]


def test_half_a_length_written_as_a_floor_division_is_a_value_cut_to_a_whole_number(made_up):
    def floored(length, angles):
        half = length // 2
        return np.array([[half * np.cos(a), half * np.sin(a)] for a in angles])

    hypotheses = found(made_up, "centres", floored, CENTRES)
    assert names_of(hypotheses) == {"integer_truncated"}, [(h.name, h.detail) for h in hypotheses]


def test_a_third_of_the_length_is_no_floor_division(made_up):
    def third(length, angles):
        return np.array([[length / 3 * np.cos(a), length / 3 * np.sin(a)] for a in angles])

    assert "integer_truncated" not in names_of(found(made_up, "centres", third, CENTRES))


POWERS = [(np.array([0.3, -1.2, 0.5]), np.array([1.1, 0.4, -0.7]), np.array([0.2, 0.9, -1.5])),
          (np.array([-0.8, 0.6, 1.4]), np.array([0.2, -0.9, 0.3]), np.array([1.3, -0.4, 0.6]))]


def test_a_loops_iterable_that_reads_the_accelerations_for_the_rates_is_a_state_row(made_up):
    hypotheses = found(made_up, "power", lambda q, qd, qdd: np.array([q @ qdd, np.sum(qdd)]), POWERS)
    assert names_of(hypotheses) == {"state_row"}, [(h.name, h.detail) for h in hypotheses]
    assert any("reads a quantity where its rate belongs" in h.detail for h in hypotheses)


def test_a_constant_typed_with_anothers_value_is_no_value_unused(made_up):
    def wheel(angle):
        return np.array([np.sin(angle) - angle, 1.0 - np.cos(angle)])

    hypotheses = found(made_up, "wheel", wheel, [(0.4,), (1.1,)])
    assert "value_unused" not in names_of(hypotheses), [(h.name, h.detail) for h in hypotheses]


def rotation(angle, axis):
    from scipy.spatial.transform import Rotation

    return Rotation.from_rotvec(angle * np.asarray(axis) / np.linalg.norm(axis)).as_matrix()


def test_a_rotation_left_out_of_a_matrix_product_is_as_truly_a_matrix_factor_left_out(made_up):
    """``dt * W`` for ``dt * W @ A_IC``: no vector stays in another frame's coordinates, the value is a matrix;
    told as a frame's slip and, beside it, as a matrix factor left out.  A rotation left out of a vector's
    product stays a frame's slip alone."""
    steps = [(rotation(0.7, [1.0, 2.0, -0.5]), np.array([0.3, -1.1, 0.8]), 0.1),
             (rotation(-1.2, [0.4, -0.3, 1.0]), np.array([-0.6, 0.2, 1.4]), 0.05)]
    hypotheses = found(made_up, "turned_step", lambda A, w, dt: A + dt * np.array(
        [[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]]), steps)
    assert names_of(hypotheses) == {"wrong_frame", "missing_matrix_factor"}, [(h.name, h.detail) for h in hypotheses]
    vectors = [(rotation(0.7, [1.0, 2.0, -0.5]), np.array([0.3, -1.1, 0.8])),
               (rotation(-1.2, [0.4, -0.3, 1.0]), np.array([-0.6, 0.2, 1.4]))]
    hypotheses = found(made_up, "inertial", lambda A, v: v, vectors)
    assert "wrong_frame" in names_of(hypotheses) and "missing_matrix_factor" not in names_of(hypotheses), \
        [(h.name, h.detail) for h in hypotheses]


IMPORTING = '''"""A made-up problem that imports its constants from a module of the library."""

import numpy as np

from .shapes import LENGTH


def moments(length, width):
    """A made-up pair of moments of a plate of the given length and width."""
    # BEGIN SOLUTION problem 83
    return np.array([width**2, length**2 + width**2]) / 12
    # END SOLUTION
'''


@pytest.fixture
def importing(tmp_path, monkeypatch):
    with made_up_package(tmp_path, monkeypatch, IMPORTING, 83, "importing",
                         {"shapes.py": '"""A made-up library module."""\n\nLENGTH = 0.2\n'}) as package:
        yield package


def test_a_parameter_read_as_the_constant_its_module_imports_ignores_the_argument(importing):
    """``LENGTH`` (imported from a module of the library) read where the parameter ``length`` belongs: the argument
    is ignored, as for a constant the module binds itself; the near miss, the length doubled, is no such slip."""
    plates = [(0.5, 0.3), (1.2, 0.7)]
    evidences = made_up_evidences(importing, "moments", lambda length, width: np.array(
        [width**2, 0.2**2 + width**2]) / 12, plates, number=83)
    hypotheses = mutants.mutant_slips(scene("p83.moments"), evidences)
    assert names_of(hypotheses) == {"ignored_argument"}, [(h.name, h.detail) for h in hypotheses]
    evidences = made_up_evidences(importing, "moments", lambda length, width: np.array(
        [width**2, 4 * length**2 + width**2]) / 12, plates, number=83)
    assert "ignored_argument" not in names_of(mutants.mutant_slips(scene("p83.moments"), evidences))


def test_a_gravity_vector_read_as_the_earths_is_the_earths_gravity(made_up):
    gravities = [(2.0, np.array([1.2, -3.4, 0.0])), (0.7, np.array([-0.5, -1.6, 0.3]))]
    hypotheses = found(made_up, "weight", lambda m, I_grav: m * np.array([0.0, -9.81, 0.0]), gravities)
    assert names_of(hypotheses) == {"earth_gravity"}, [(h.name, h.detail) for h in hypotheses]
    assert DIAGNOSES["earth_gravity"].family == "ignored_argument"
    hypotheses = found(made_up, "weight", lambda m, I_grav: m * np.array([0.0, -9.7, 0.0]), gravities)
    assert "earth_gravity" not in names_of(hypotheses), [(h.name, h.detail) for h in hypotheses]


BOXES = [(0.5, 0.3, 0.2), (1.2, 0.7, 0.4)]


def test_one_argument_read_for_another_of_its_line_is_the_wrong_argument(made_up):
    hypotheses = found(made_up, "box", lambda a, b, c: np.array([b**2 + c**2, a**2 + b**2, a**2 + b**2]) / 12,
                       BOXES)
    assert names_of(hypotheses) == {"wrong_parameter"}, [(h.name, h.detail) for h in hypotheses]
    assert DIAGNOSES["wrong_parameter"].family == "order"
    hypotheses = found(made_up, "box", lambda a, b, c: np.array([b**2 + c**2, a**2 + 2 * c**2, a**2 + b**2]) / 12,
                       BOXES)
    assert "wrong_parameter" not in names_of(hypotheses), [(h.name, h.detail) for h in hypotheses]
