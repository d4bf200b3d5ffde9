"""The shape of what comes back from the student's side (problems 21-36).

Everything a probe returns from the sandbox is untrusted: the student's code runs in the same process as the probe
and can change what it returns.  A check that loops over such a reply (``zip``, ``for``, ``all``) must first make
sure the reply has the length or the keys the comparison needs; otherwise an empty reply compares nothing and
passes.  These helpers fail with a message that says what is missing.
"""

from grader.checking import fail

__all__ = ["as_list", "as_dict"]


def _kind(value) -> str:
    return type(value).__name__


def as_list(value, name: str, length: int) -> list:
    """``value`` as a list of exactly ``length`` entries, or a failure that says how many it has."""
    if not isinstance(value, (list, tuple)):
        fail(f"{name} must be a list of {length} entries, got a value of type {_kind(value)}: {str(value)[:200]}",
             diagnosis="shape")
    if len(value) != length:
        fail(f"{name} must have {length} entries, got {len(value)}.", diagnosis="shape")
    return list(value)


def as_dict(value, name: str, keys=()) -> dict:
    """``value`` as a dict holding every one of ``keys``, or a failure that names the missing ones."""
    if not isinstance(value, dict):
        fail(f"{name} must be a dict, got a value of type {_kind(value)}: {str(value)[:200]}", diagnosis="shape")
    missing = [key for key in keys if key not in value]
    if missing:
        fail(f"{name} has no entries {missing} (it has {sorted(map(str, value))[:20]}).", diagnosis="shape")
    return value
