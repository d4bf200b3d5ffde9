"""The engine's key of a probe call (``grader.diagnosis.evidence.call_key``): a digest of the arguments that holds
two calls the same exactly where their plain data, written as text (``text_key``, JSON as the oracle writes it), is
the same: arrays by their shape and entries as floats, lists and tuples alike, a dict's entries by their keys as text
in any order, ``1`` and ``1.0`` and ``True`` apart."""

import numpy as np
from hypothesis import given, settings, strategies as st

from grader.diagnosis.evidence import call_key, text_key

#: leaves that the codec writes alike or apart in ways that are easy to get wrong
LEAVES = [0, 0.0, -0.0, 1, 1.0, True, False, None, "a", "1", 2**60, float(2**60), np.float64(1.0), np.int64(1),
          np.bool_(True), np.array([1.0]), np.array([1]), np.array([True]), np.array([[1.0]]), np.array(1.0),
          np.arange(3.0), np.arange(3), np.zeros((0, 3)), np.zeros((3, 0)), 1.5, np.float32(1.5)]

values = st.recursive(
    st.sampled_from(LEAVES),
    lambda inner: st.one_of(st.lists(inner, max_size=3), st.lists(inner, max_size=3).map(tuple),
                            st.dictionaries(st.sampled_from(["x", "y", 1, "1"]), inner, max_size=2)),
    max_leaves=6)


@settings(max_examples=300, deadline=None)
@given(st.lists(values, min_size=2, max_size=6))
def test_two_calls_have_the_same_key_exactly_where_their_plain_data_is_the_same(calls):
    for a in calls:
        for b in calls:
            assert (call_key("p", (a,)) == call_key("p", (b,))) == (text_key("p", (a,)) == text_key("p", (b,)))


def test_a_dicts_keys_alike_as_text_keep_the_later_entry_as_the_codec_writes_them():
    """``{1: 0, "1": x}`` is written ``{"1": x}``: the same call as ``{"1": x}`` (or ``{1: x}``), not as ``{1: 0}``."""
    x = [0, 0, 0]
    assert call_key("p", ({1: 0, "1": x},)) == call_key("p", ({1: x},)) == call_key("p", ({"1": x},))
    assert call_key("p", ({1: 0, "1": x},)) != call_key("p", ({"1": x, 1: 0},)) == call_key("p", ({"1": 0},))


def test_the_key_names_the_probe_and_digests_large_arrays_without_writing_them():
    big = np.linspace(0.0, 1.0, 200_000)
    key = call_key("problem_42.throw", (big, {"g": 9.81}))
    assert "problem_42.throw" in key and len(key) < 100
    assert key == call_key("problem_42.throw", (big.copy(), {"g": 9.81}))
    changed = big.copy()
    changed[-1] = np.nextafter(1.0, 2.0)
    assert key != call_key("problem_42.throw", (changed, {"g": 9.81}))
    assert key != call_key("problem_42.run", (big, {"g": 9.81}))


def test_arguments_the_digest_does_not_read_are_keyed_by_their_text():
    odd = (np.array(["a", "b"]),)
    assert call_key("p", odd) == call_key("p", (np.array(["a", "b"]),)) != call_key("p", (np.array(["a", "c"]),))
