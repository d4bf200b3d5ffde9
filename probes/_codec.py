"""Plain-data encoding of probe arguments and results: JSON types, with arrays as {"__array__": shape, ...}."""

__all__ = ["encode", "decode", "MAX_ARRAY"]

MAX_ARRAY = 1_000_000


def encode(value, depth=0):
    """Turn a value into JSON-able data; numpy arrays become ``{"__array__": shape, "data": [...]}``."""
    if depth > 20:
        raise TypeError("value nested too deeply")
    if value is None or isinstance(value, (bool, str, float)):
        return value
    if isinstance(value, int):
        return value if abs(value) < 2**53 else float(value)
    if type(value).__module__ == "numpy":
        import numpy as np

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


def decode(value):
    """Inverse of ``encode``: arrays come back as float numpy arrays (object arrays when not numeric)."""
    if isinstance(value, dict):
        if "__array__" in value and set(value) == {"__array__", "data"}:
            import numpy as np

            data = value["data"]
            shape = tuple(int(n) for n in value["__array__"])
            if all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in data):
                return np.array(data, dtype=float).reshape(shape)
            out = np.empty(len(data), dtype=object)
            out[:] = [decode(x) for x in data]
            return out.reshape(shape)
        return {k: decode(v) for k, v in value.items()}
    if isinstance(value, list):
        return [decode(v) for v in value]
    return value
