"""The plain-data codec of probe arguments and results (``probes._codec``): what its fast paths must keep of the
general rules, in the grader and in the worker alike."""

import numpy as np
import pytest

from probes._codec import MAX_ARRAY, decode, encode


def test_numeric_arrays_travel_as_floats_and_come_back_as_float_arrays():
    for array in (np.arange(6.0).reshape(2, 3), np.arange(4).reshape(2, 2), np.array([True, False])):
        encoded = encode(array)
        assert encoded == {"__array__": list(array.shape), "data": [float(x) for x in array.ravel()]}
        assert all(type(x) is float for x in encoded["data"])
        back = decode(encoded)
        assert back.dtype == float and back.shape == array.shape and np.array_equal(back, array.astype(float))


def test_an_array_with_a_bool_or_text_among_its_data_is_an_object_array():
    for data in ([1.0, True], [1.0, "x"], [None, 2.0]):
        back = decode({"__array__": [2], "data": data})
        assert back.dtype == object and list(back) == data and type(back[0]) is type(data[0])


def test_ints_and_floats_of_the_data_are_numbers():
    back = decode({"__array__": [3], "data": [1, 2.5, -3]})
    assert back.dtype == float and back.tolist() == [1.0, 2.5, -3.0]


def test_lists_come_back_as_new_lists():
    """A flat list is never handed back as the very object it came in (a check that changes its value must not
    change a cached reference value)."""
    plain = [1.0, 2.0, "a", None, True]
    for function in (encode, decode):
        out = function(plain)
        assert out == plain and out is not plain
    nested = [[1.0], [2.0]]
    out = decode(nested)
    assert out == nested and out[0] is not nested[0]


def test_numpy_scalars_are_plain_numbers_and_float_subclasses_stay():
    assert type(encode(np.int64(3))) is int and type(encode(np.bool_(True))) is bool
    assert type(encode([np.float64(1.5)])[0]) is np.float64  # a float already: sent as it is
    assert encode(2**60) == float(2**60)


def test_tuples_become_lists_and_keys_text():
    assert encode((1.0, (2.0, "b"))) == [1.0, [2.0, "b"]]
    assert encode({1: [1.0], "k": None}) == {"1": [1.0], "k": None}


def test_the_limits_hold_on_every_path():
    with pytest.raises(TypeError, match="nested too deeply"):
        encode([1.0], 20)  # a flat list one level too deep
    with pytest.raises(TypeError, match="complex"):
        encode(np.array([1j]))
    with pytest.raises(TypeError, match="too large"):
        encode(np.zeros(MAX_ARRAY + 1))
    with pytest.raises(TypeError, match="cannot send"):
        encode({"x": object()})
