"""The course's constants as named constants of every problem (``grader.diagnosis.scene.COURSE_CONSTANTS``): a value
the Earth's gravity of the course times the expected one (a generalized gravity force multiplied by g once more,
where the gravity vector already holds it) is a value off by a constant of the problem, on a probe that declares
none; the near miss, a value 9.7 times the expected one, is no such slip."""

import numpy as np

from .test_ignored import _explain


def weights(masses, heights):
    """A made-up potential energy's gradient: each mass's weight along its height's rate."""
    return 9.81 * np.asarray(masses) * np.asarray(heights)


MASSES, HEIGHTS = [2.0, 0.5, 1.5], [0.3, -1.1, 0.8]


def test_a_value_times_the_courses_gravity_is_a_constant_factor(monkeypatch):
    finding = _explain(monkeypatch, "stub.weights", None, weights, lambda m, h: 9.81 * weights(m, h),
                       (MASSES, HEIGHTS))
    assert finding is not None and finding.names == ("constant_factor",), finding
    assert "times g = 9.81" in finding.hint


def test_a_value_divided_by_the_courses_gravity_is_a_constant_factor(monkeypatch):
    finding = _explain(monkeypatch, "stub.weights", None, weights, lambda m, h: weights(m, h) / 9.81,
                       (MASSES, HEIGHTS))
    assert finding is not None and finding.names == ("constant_factor",), finding
    assert "divided by g = 9.81" in finding.hint


def test_a_value_off_by_another_number_is_no_constant_factor(monkeypatch):
    finding = _explain(monkeypatch, "stub.weights", None, weights, lambda m, h: 9.7 * weights(m, h),
                       (MASSES, HEIGHTS))
    assert finding is None or "constant_factor" not in finding.names, finding
