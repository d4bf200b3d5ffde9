"""The strategies of the randomized comparisons (``grader.strategies``): seeded draws without hypothesis, the
simplest example first, bounded ranges, rejection, and the same strategies as hypothesis strategies for shrinking."""

import subprocess
import sys

import numpy as np
import pytest

from grader import strategies as st
from grader.oracle import draw_pool


@st.composite
def pairs(draw, low):
    a = draw(st.integers(low, 9))
    b = draw(st.floats(0.5, 2.5))
    st.assume(a != 3)
    return a, b


STRATEGY = st.tuples(
    st.floats(-np.pi, np.pi, allow_nan=False, allow_infinity=False),
    st.lists(st.tuples(st.integers(-3, 3), st.booleans()), min_size=1, max_size=4),
    st.fixed_dictionaries({"v": st.tuples(*[st.floats(-1.0, 1.0)] * 3).map(np.array), "k": st.sampled_from("xyz")}),
    st.permutations(range(4)),
    st.just("case"),
    pairs(2),
    st.floats(0.1, 0.9).filter(lambda x: x > 0.5),
)


def test_draws_are_reproducible_bounded_and_begin_with_the_simplest():
    drawn = st.draw_examples(STRATEGY, 40, seed=11)
    again = st.draw_examples(STRATEGY, 40, seed=11)
    other = st.draw_examples(STRATEGY, 40, seed=12)
    assert repr(drawn) == repr(again) and repr(drawn) != repr(other)
    angle, items, dictionary, order, case, (a, b), filtered = drawn[0]
    assert angle == 0.0 and items == [(0, False)] and np.array_equal(dictionary["v"], np.zeros(3))
    assert dictionary["k"] == "x" and order == [0, 1, 2, 3] and case == "case" and (a, b) == (2, 1.0)
    assert filtered > 0.5
    for angle, items, dictionary, order, case, (a, b), filtered in drawn:
        assert -np.pi <= angle <= np.pi and isinstance(angle, float)
        assert 1 <= len(items) <= 4 and all(-3 <= i <= 3 and isinstance(i, int) for i, _ in items)
        assert np.all(np.abs(dictionary["v"]) <= 1.0) and sorted(order) == [0, 1, 2, 3]
        assert 2 <= a <= 9 and a != 3 and 0.5 <= b <= 2.5 and 0.5 < filtered <= 0.9
    assert len({angle for angle, *_ in drawn}) == 40  # the draws after the first are spread over the range


def test_simplest_float_outside_zero_is_the_integer_or_bound_nearest_zero():
    assert st.draw_examples(st.floats(0.4, 2.7), 1, 0) == [1.0]
    assert st.draw_examples(st.floats(-2.7, -1.2), 1, 0) == [-2.0]
    assert st.draw_examples(st.floats(1e-3, 0.1), 1, 0) == [1e-3]


def test_unbounded_and_unsatisfiable_strategies_are_refused():
    with pytest.raises(ValueError):
        st.floats(0.0, float("inf"))
    with pytest.raises(ValueError):
        st.integers(0, None)
    with pytest.raises(ValueError, match="unsatisfiable"):
        st.draw_examples(st.integers(0, 5).filter(lambda i: i > 7), 2, 0)


def test_draw_pool_draws_without_importing_hypothesis():
    code = ("import sys; from grader import strategies as st; from grader.oracle import draw_pool; "
            "print(len(draw_pool(st.tuples(st.floats(-1, 1)), 20, 5)), 'hypothesis' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.split() == ["20", "False"]
    assert repr(draw_pool(STRATEGY, 5, 3)) == repr(st.draw_examples(STRATEGY, 5, 3))


def test_no_check_module_brings_hypothesis_onto_the_passing_path():
    """Every check module draws its random inputs with ``grader.strategies``: importing all of them (and the
    grader's checking layer) leaves hypothesis unimported, so a passing comparison never runs its engine."""
    code = ("import sys; from grader.problems import problems, problem_module; "
            "[problem_module(p.number) for p in problems()]; import grader.context; "
            "print(len(problems()), sorted(m for m in sys.modules if m.split('.')[0] == 'hypothesis')[:3])")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    count, modules = done.stdout.split(" ", 1)
    assert int(count) >= 45
    assert modules.strip() == "[]"


def test_the_same_strategy_as_a_hypothesis_strategy():
    from hypothesis import HealthCheck, given, settings

    seen = []

    @settings(max_examples=30, database=None, deadline=None, suppress_health_check=list(HealthCheck))
    @given(st.to_hypothesis(STRATEGY))
    def run(value):
        angle, items, dictionary, order, case, (a, b), filtered = value
        assert -np.pi <= angle <= np.pi and 1 <= len(items) <= 4 and sorted(order) == [0, 1, 2, 3]
        assert a != 3 and 0.5 < filtered <= 0.9 and case == "case" and dictionary["v"].shape == (3,)
        seen.append(value)

    run()
    assert seen
