"""Wrong answers on the inputs every student is asked: what a batch records for ``grade similarity``.

A check asks the student's code on two kinds of inputs: random ones drawn from the student's own seed (different
for every student, so that hard-coding earns nothing) and fixed ones written in the check or taken from the sheet
(the same for every student).  Only inputs that two students are both asked can show that they gave the *same*
answer, so the batch records:

* the answers on the fixed inputs, which cost nothing more: the checks ask them anyway, and their authors chose
  them generic, to tell mistakes apart;
* for a randomized comparison that failed, the answer on one more input of that comparison, drawn alike for every
  student (``grader.context.COMMON_SEED`` and the comparison's site), asked after the problem's last check so that
  it cannot change a verdict.  Many checks are randomized comparisons only; a student whose comparisons pass is
  asked nothing more, so a batch pays one call of the student's code per failed comparison.

An answer is kept only where it is wrong (it differs from the reference's on the same call beyond ``EXACT``) in a
check that did not pass: a right answer says nothing about copying, and a check passed on the student's own earlier
results (error carried forward) names its mistake at the check that found it.  A value is kept as a digest of its
numbers rounded to ``DIGITS`` significant digits (the same computation in another order gives the same digest) and
as a short text to show.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass

from .checking import EXACT

__all__ = ["Answer", "wrong_answer", "value_digest", "DIGITS", "SHOWN_CHARS"]

#: significant digits of a value's digest
DIGITS = 8
#: the longest text kept of a call or a value
SHOWN_CHARS = 300
#: the most numbers of a value that its digest reads (evenly spaced beyond that: a long simulated trajectory)
DIGEST_NUMBERS = 20_000


@dataclass(frozen=True)
class Answer:
    """A wrong answer of the student's code on a call that every student is asked."""

    check_id: str  # the check that asked it, e.g. "p06.cardan_rotation"
    call: str  # the probe and its arguments, shortened: "problem_06.cardan_with_factors(0.4, -0.3, 1.1)"
    call_key: str  # a digest of the probe and its exact arguments
    value_key: str  # a digest of the student's value (``value_digest``)
    value: str  # the student's value, shortened
    expected: str  # the reference's value, shortened


def _skeleton_and_numbers(encoded, numbers: list) -> object:
    """The structure of a codec-encoded value, its numbers appended to ``numbers`` (floats and float arrays)."""
    import numpy as np

    if isinstance(encoded, dict):
        if len(encoded) == 2 and "__array__" in encoded and "data" in encoded:
            data = encoded["data"]
            if all(type(x) in (int, float) for x in data):
                numbers.append(np.asarray(data, dtype=float))
                return {"array": list(encoded["__array__"])}
            return {"array": list(encoded["__array__"]), "items": [_skeleton_and_numbers(x, numbers) for x in data]}
        return {str(k): _skeleton_and_numbers(v, numbers) for k, v in sorted(encoded.items())}
    if isinstance(encoded, list):
        return [_skeleton_and_numbers(x, numbers) for x in encoded]
    if isinstance(encoded, (int, float)) and not isinstance(encoded, bool):
        numbers.append(np.array([float(encoded)]))
        return "#"
    return encoded


def _flat(value):
    """``(skeleton text, float array)`` of a probe's value as it came back (or an encoded one)."""
    import numpy as np

    from probes._codec import encode

    numbers: list = []
    skeleton = _skeleton_and_numbers(encode(value), numbers)
    flat = np.concatenate(numbers) if numbers else np.zeros(0)
    return json.dumps(skeleton, sort_keys=True, default=str), flat


def value_digest(value) -> str:
    """A digest of ``value``: its structure and its numbers rounded to ``DIGITS`` significant digits."""
    import numpy as np

    skeleton, numbers = _flat(value)
    if numbers.size > DIGEST_NUMBERS:
        numbers = numbers[np.linspace(0, numbers.size - 1, DIGEST_NUMBERS).astype(int)]
    mantissa, exponent = np.frexp(numbers)
    scale = 2.0 ** int(np.ceil(DIGITS * np.log2(10)))
    with np.errstate(invalid="ignore"):
        rounded = np.ldexp(np.round(mantissa * scale) / scale, exponent) + 0.0  # + 0.0: no negative zero
    rounded[np.abs(numbers) < EXACT.atol] = 0.0  # round-off around zero is zero
    rounded[np.isnan(rounded)] = np.nan  # one bit pattern for every NaN
    digest = hashlib.blake2b(skeleton.encode(), digest_size=12)
    digest.update(np.ascontiguousarray(rounded).tobytes())
    return digest.hexdigest()


def _agrees(value, expected) -> bool:
    import numpy as np

    try:
        skeleton, got = _flat(value)
        expected_skeleton, want = _flat(expected)
    except (TypeError, ValueError):
        return False
    if skeleton != expected_skeleton or got.shape != want.shape:
        return False
    with np.errstate(invalid="ignore"):
        return bool(np.all((np.abs(got - want) <= EXACT.atol + EXACT.rtol * np.abs(want))
                           | (np.isnan(got) & np.isnan(want))))


def _shown(value) -> str:
    """A short text of a value: arrays (also inside dicts and lists) summarised beyond 40 entries."""
    import reprlib

    import numpy as np

    shorter = reprlib.Repr()
    shorter.maxstring, shorter.maxother, shorter.maxlist, shorter.maxdict, shorter.maxlevel = 120, 120, 12, 12, 4
    try:
        with np.printoptions(precision=6, suppress=True, linewidth=100, threshold=40, edgeitems=2):
            if isinstance(value, np.ndarray):
                text = np.array2string(value, separator=", ")
            elif isinstance(value, (dict, list, tuple)):
                text = shorter.repr(value)
            else:
                text = repr(value)
    except Exception:  # noqa: BLE001 - a text to show, never a reason to fail
        text = f"<{type(value).__name__}>"
    return text if len(text) <= SHOWN_CHARS else text[:SHOWN_CHARS - 3] + "..."


def wrong_answer(check_id: str, probe: str, args: tuple, value, expected) -> Answer | None:
    """The record of the student's ``value`` of ``probe(*args)`` when it differs from the reference's ``expected``
    beyond ``EXACT``; None when it agrees."""
    from probes import call_key

    if _agrees(value, expected):
        return None
    call = f"{probe}({', '.join(_shown(a) for a in args)})"
    return Answer(
        check_id=check_id,
        call=call if len(call) <= SHOWN_CHARS else call[:SHOWN_CHARS - 3] + "...",
        call_key=hashlib.blake2b(call_key(probe, args).encode(), digest_size=12).hexdigest(),
        value_key=value_digest(value),
        value=_shown(value),
        expected=_shown(expected),
    )
