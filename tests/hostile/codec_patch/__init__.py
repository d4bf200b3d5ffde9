"""Patches the worker's JSON encoder (probes._codec.encode) so that every reply is crafted: a dict arrives as the
list of its values, an array flat and with its numbers turned in turn into NaN, text and booleans, a number into
NaN."""
import itertools
import math

import probes._codec as _codec

_real = _codec.encode
_turn = itertools.cycle([math.nan, "x", True, math.inf, False])


def _crafted(data):
    if isinstance(data, dict) and "__array__" in data:
        values = data["data"]
        return {"__array__": [len(values)], "data": [next(_turn) for _ in values]}
    if isinstance(data, dict):
        return [_crafted(value) for value in data.values()]
    if isinstance(data, list):
        return [_crafted(value) for value in data]
    if isinstance(data, float):
        return math.nan
    return data


def _encode(value, depth=0):
    return _crafted(_real(value, depth))


_codec.encode = _encode
