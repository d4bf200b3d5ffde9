"""Plain-data encoding of probe arguments and results: JSON types, with arrays as {"__array__": shape, ...}."""

__all__ = ["encode", "decode", "MAX_ARRAY"]

MAX_ARRAY = 1_000_000

#: the types ``json`` gives numbers (a bool is not a number here)
_NUMBERS = frozenset((int, float))
#: values that ``encode`` returns as they are, by exact type
_PLAIN = frozenset((float, str, bool, type(None)))
#: ``numpy.ndarray`` once an array was met (the codec imports numpy only when it meets a numpy value)
_ARRAY = None


def _remember(np) -> None:
    global _ARRAY
    _ARRAY = np.ndarray


def encode(value, depth=0):
    """Turn a value into JSON-able data; numpy arrays become ``{"__array__": shape, "data": [...]}``."""
    if depth > 20:
        raise TypeError("value nested too deeply")
    kind = type(value)
    if kind in _PLAIN:  # the common cases first, by exact type; subclasses take the general path below
        return value
    if kind is _ARRAY and value.dtype.kind in "biuf" and value.size <= MAX_ARRAY:
        return {"__array__": list(value.shape), "data": value.astype(float).ravel().tolist()}
    if kind is dict:
        return {str(k): encode(v, depth + 1) for k, v in value.items()}
    if kind is list or kind is tuple:
        if depth < 20 and _PLAIN.issuperset(map(type, value)):  # a flat list of floats (strings, ...): as it is
            return list(value)
        return [encode(v, depth + 1) for v in value]
    if value is None or isinstance(value, (bool, str, float)):
        return value
    if isinstance(value, int):
        return value if abs(value) < 2**53 else float(value)
    if kind.__module__ == "numpy":
        import numpy as np

        _remember(np)
        if isinstance(value, np.ndarray):
            if value.dtype.kind == "c":
                raise TypeError("complex numbers are not accepted here")
            if value.size > MAX_ARRAY:
                raise TypeError(f"an array of {value.size} entries is too large")
            if value.dtype.kind in "biuf":
                return {"__array__": list(value.shape), "data": value.astype(float).ravel().tolist()}
            return {"__array__": list(value.shape), "data": [encode(v, depth + 1) for v in value.ravel()]}
        if isinstance(value, np.generic):
            return encode(value.item(), depth + 1)
    if isinstance(value, dict):
        return {str(k): encode(v, depth + 1) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [encode(v, depth + 1) for v in value]
    if isinstance(value, complex):
        raise TypeError("complex numbers are not accepted here")
    raise TypeError(f"cannot send a value of type {type(value).__name__}")


def _numeric(data) -> bool:
    """True when every entry of ``data`` is an int or a float (not a bool)."""
    if _NUMBERS.issuperset(map(type, data)):  # exact types: the common case, without a Python loop
        return True
    return all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in data)


def decode(value):
    """Inverse of ``encode``: arrays come back as float numpy arrays (object arrays when not numeric)."""
    if type(value) is list and _PLAIN.issuperset(map(type, value)):  # a flat list of floats: nothing to convert
        return list(value)
    if isinstance(value, dict):
        if len(value) == 2 and "__array__" in value and "data" in value:
            import numpy as np

            data = value["data"]
            shape = tuple(map(int, value["__array__"]))
            if _numeric(data):
                return np.array(data, dtype=float).reshape(shape)
            out = np.empty(len(data), dtype=object)
            out[:] = [decode(x) for x in data]
            return out.reshape(shape)
        return {k: decode(v) for k, v in value.items()}
    if isinstance(value, list):
        return [decode(v) for v in value]
    return value
