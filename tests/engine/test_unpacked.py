"""The formula tier's slip of names bound in another order (``grader.diagnosis.mutants``: ``cycled``, on names bound as
well as read): ``phi, x, y = q`` for ``x, y, phi = q``, each name bound from another's row, told as quantities in
another order and as the state read from the wrong rows (names unpacked from what is no state, as the first only; those
of a slice of a run's state, as the second only); and a slice of a state one row on (``y[1:4]`` for ``y[:3]``: as many
entries, each from the next row), told as a neighbouring index, as is the first entry read for a later one (``q[0]`` for
``q[2]``); and a range counted from one (``np.arange(1, n + 1)``), told as an offset.  Planted into a made-up problem
that the tier names on two inputs, with the near misses of a name bound from a row that no order of the three gives and
of a slice two rows on."""

import numpy as np

from grader.diagnosis import mutants

from .stand_ins import made_up_fixture
from .test_mutants import made_up_evidences, scene

SOURCE = '''"""A made-up problem of names bound from a state."""

import numpy as np


def pin(q):
    """A made-up pin's place and its turn, from the coordinates ``q = (x, y, phi)``."""
    # BEGIN SOLUTION problem 92
    x, y, phi = q
    return np.array([x + 2.0 * y, y * phi, np.cos(phi)])
    # END SOLUTION


def harmonics(n, t):
    """The cosines of the first ``n`` harmonics of ``t``, the constant one first."""
    # BEGIN SOLUTION problem 92
    k = np.arange(n)
    return np.cos(k * t)
    # END SOLUTION


def tip(y):
    """A made-up tip's height and reach from a state of six, its first three the coordinates ``(x, h, phi)``."""
    # BEGIN SOLUTION problem 92
    x, h, phi = y[:3]
    return np.array([h + np.sin(phi), x * h])
    # END SOLUTION


def damped(gains, e):
    """A made-up feedback of an error ``e = (position, rate)`` with the gains ``(kp, kd)``."""
    # BEGIN SOLUTION problem 92
    kp, kd = gains
    return -kp * e[0] - kd * e[1]
    # END SOLUTION


def event_state(y):
    """A made-up residual from the first three entries of a state of six."""
    # BEGIN SOLUTION problem 92
    q = y[:3]
    return np.array([q[0] - 2.0 * q[1], q[2] ** 2 + y[4]])
    # END SOLUTION
'''


made_up = made_up_fixture(SOURCE, 92, "unpacked")


INPUTS = [(np.array([0.3, -1.2, 0.7]),), (np.array([1.1, 0.4, -0.9]),)]


def found(package, student):
    evidences = made_up_evidences(package, "pin", student, INPUTS, number=92)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    return mutants.mutant_slips(scene("p92.pin"), evidences)


def test_names_bound_in_another_order_are_quantities_in_another_order_and_rows_of_the_state(made_up):
    """``phi, x, y = q`` binds each name from another's row: as truly quantities in another order as a state read
    from the wrong rows, so both are told."""
    def student(q):
        phi, x, y = q
        return np.array([x + 2.0 * y, y * phi, np.cos(phi)])

    hypotheses = found(made_up, student)
    assert {h.name for h in hypotheses} == {"swapped", "state_row"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`pin` unpacks the coordinates into its names in another order" in h.detail for h in hypotheses)
    assert any("`pin` reads each coordinate it unpacks from another's row" in h.detail for h in hypotheses)


def test_a_name_bound_from_a_row_no_order_gives_is_not_that_slip(made_up):
    def student(q):
        x, y, phi = q[0], q[1], 0.5 * q[2]
        return np.array([x + 2.0 * y, y * phi, np.cos(phi)])

    hypotheses = found(made_up, student)
    assert not any("another order" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


STATES = [(np.array([0.3, -1.2, 0.7, 0.2, -0.5, 0.9]),), (np.array([1.1, 0.4, -0.9, -0.6, 0.8, 0.1]),)]


def test_a_slice_of_the_state_one_row_on_is_a_neighbouring_index(made_up):
    def student(y):
        q = y[1:4]
        return np.array([q[0] - 2.0 * q[1], q[2] ** 2 + y[4]])

    evidences = made_up_evidences(made_up, "event_state", student, STATES, number=92)
    hypotheses = mutants.mutant_slips(scene("p92.event_state"), evidences)
    assert {h.name for h in hypotheses} == {"wrong_index"}, [(h.name, h.detail) for h in hypotheses]

    def two_on(y):
        q = y[2:5]
        return np.array([q[0] - 2.0 * q[1], q[2] ** 2 + y[4]])

    evidences = made_up_evidences(made_up, "event_state", two_on, STATES, number=92)
    hypotheses = mutants.mutant_slips(scene("p92.event_state"), evidences)
    assert "wrong_index" not in {h.name for h in hypotheses}, [(h.name, h.detail) for h in hypotheses]


def test_the_first_entry_read_for_a_later_one_is_a_wrong_index(made_up):
    """``q[0]`` for ``q[2]``: an index of 2 or more read as 0 (the first entry), told as a wrong index."""
    def student(y):
        q = y[:3]
        return np.array([q[0] - 2.0 * q[1], q[0] ** 2 + y[4]])

    evidences = made_up_evidences(made_up, "event_state", student, STATES, number=92)
    hypotheses = mutants.mutant_slips(scene("p92.event_state"), evidences)
    assert {h.name for h in hypotheses} == {"wrong_index"}, [(h.name, h.detail) for h in hypotheses]


def test_a_range_counted_from_one_is_an_offset(made_up):
    """``np.arange(1, n + 1)`` for ``np.arange(n)`` (MATLAB's ``1:n``): an offset; the near miss, counted from two,
    is not that slip."""
    inputs = [(4, 0.7), (5, 1.3)]
    evidences = made_up_evidences(made_up, "harmonics", lambda n, t: np.cos(np.arange(1, n + 1) * t), inputs,
                                  number=92)
    hypotheses = mutants.mutant_slips(scene("p92.harmonics"), evidences)
    assert {h.name for h in hypotheses} == {"offset"}, [(h.name, h.detail) for h in hypotheses]
    assert any("`harmonics` counts from one where numpy counts from zero" in h.detail for h in hypotheses)
    evidences = made_up_evidences(made_up, "harmonics", lambda n, t: np.cos(np.arange(2, n + 2) * t), inputs,
                                  number=92)
    hypotheses = mutants.mutant_slips(scene("p92.harmonics"), evidences)
    assert not any("counts from one" in h.detail for h in hypotheses), [(h.name, h.detail) for h in hypotheses]


def test_two_names_of_a_slice_of_a_runs_state_exchanged_are_the_state_read_from_the_wrong_rows(made_up):
    """``h, x, phi = y[:3]``: the names of a slice of a run's state are its reads, read from each other's rows."""
    def student(y):
        h, x, phi = y[:3]
        return np.array([h + np.sin(phi), x * h])

    evidences = made_up_evidences(made_up, "tip", student, STATES, number=92)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    hypotheses = mutants.mutant_slips(scene("p92.tip"), evidences)
    assert {h.name for h in hypotheses} == {"state_row"}, [(h.name, h.detail) for h in hypotheses]


def test_names_unpacked_from_what_is_no_state_are_quantities_in_another_order_only(made_up):
    """``kd, kp = gains``: two gains exchanged are no rows of a state."""
    def student(gains, e):
        kd, kp = gains
        return -kp * e[0] - kd * e[1]

    inputs = [(np.array([4.0, 0.7]), np.array([0.3, -1.2])), (np.array([2.5, 1.3]), np.array([-0.8, 0.4]))]
    evidences = made_up_evidences(made_up, "damped", student, inputs, number=92)
    assert all(not np.allclose(e.got, e.expected) for e in evidences)
    hypotheses = mutants.mutant_slips(scene("p92.damped"), evidences)
    assert "swapped" in {h.name for h in hypotheses}, [(h.name, h.detail) for h in hypotheses]
    assert "state_row" not in {h.name for h in hypotheses}, [(h.name, h.detail) for h in hypotheses]
