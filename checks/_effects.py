"""Side effects: what one call's outputs cannot show.

Later problems reuse the functions of earlier ones.  A function that changes its caller's arrays in place, returns
the same array object on every call (so that the next call overwrites what the caller kept), or keeps state that a
second call inherits gives the right value when called once on fresh arguments, and breaks the code built on it.
``assert_no_side_effects`` calls the student's function through the probe ``_effects.calls`` on copies of a first
input, on a second input and on the first again, and fails with the diagnosis ``mutates_argument``,
``shared_result`` or ``state_between_calls``.  It needs nothing of the reference: the function's values are
graded by the problem's other checks.
"""

import numpy as np

from grader.checking import EXACT, close, fail, format_array
from probes import _effects as probe_effects

from ._shapes import as_dict, as_list

__all__ = ["assert_no_side_effects", "same", "shown", "MUTATION_HINT"]

MUTATION_HINT = (
    "Work on a copy instead of changing the caller's array: e.g. x = np.array(x, dtype=float) (a copy) instead of "
    "np.asarray(x) (the same array), and x = x + ... instead of x += ...; the code of later problems reuses the "
    "arrays it passes."
)
SHARED_HINT = (
    "Create the result inside the function (np.array(...), np.zeros(...)) on every call: returning one array kept "
    "at module level (or in a default argument) hands every caller the same object, and the next call overwrites "
    "what the caller kept."
)
STATE_HINT = (
    "The function keeps something between calls (a module-level variable, a default argument that is a list or an "
    "array, a cache keyed on the wrong thing): compute the result from the arguments alone."
)


def same(a, b) -> bool:
    """True when two plain-data values (numbers, arrays, lists, dicts of them, None) agree to ``EXACT``."""
    if a is None or b is None:
        return a is None and b is None
    if isinstance(a, dict) or isinstance(b, dict):
        return isinstance(a, dict) and isinstance(b, dict) and a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    try:
        return close(a, np.asarray(b, dtype=float), EXACT)
    except (TypeError, ValueError):
        if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
            return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
        return False


def shown(value) -> str:
    """A value as the report shows it (an array formatted, anything else as text)."""
    try:
        return format_array(np.asarray(value, dtype=float))
    except (TypeError, ValueError):
        return str(value)[:300]


def assert_no_side_effects(ctx, module: str, function: str, first, second, params):
    """Fail unless ``module.function`` leaves its arguments unchanged, returns a fresh object on each call and gives
    the same result when called again with the same arguments (``first``, then ``second``, then ``first``;
    ``params`` names the arguments)."""
    first, second = list(first), list(second)
    got = as_dict(ctx.student(probe_effects.calls, module, function, first, second),
                  f"the reply of the side-effect probe ({function})", ("first", "first_later", "again", "args_after"))
    after = as_list(got["args_after"], f"the arguments of {function} after the call", len(first))
    call = f"{function}({', '.join(params)})"
    for name, sent, left in zip(params, first, after):
        if not same(sent, left):
            fail(f"{call} changes its argument {name} in place: the caller's array is not the same after the call.\n"
                 f"passed:\n{shown(sent)}\nafter the call:\n{shown(left)}", MUTATION_HINT, "mutates_argument")
    if not same(got["first"], got["first_later"]):
        fail(f"{call} returns the same array object on every call: the next call changed the result the caller "
             f"kept.\nreturned:\n{shown(got['first'])}\nthe same object after the next call:\n"
             f"{shown(got['first_later'])}", SHARED_HINT, "shared_result")
    if not same(got["first"], got["again"]):
        fail(f"{call} gives another result when called again with the same arguments: it keeps state between "
             f"calls.\nfirst call:\n{shown(got['first'])}\nsame arguments, after another call:\n"
             f"{shown(got['again'])}", STATE_HINT, "state_between_calls")
