"""Why the engine named what it named: a trace of one explanation, for the engine's authors.

With ``GRADER_DIAGNOSIS_TRACE`` set to a file, every explanation (``explain``, ``doubt``) and every failure the engine
is not asked about appends one JSON line to it: the check, what evidence there was (a reference call behind the
expected value, the student's call, how many inputs), what each tier found (the hypotheses' names, the mutants tried
and kept) and the finding.  Unset (the default) it costs one dictionary per explanation and writes nothing."""

from __future__ import annotations

import json
import os
import threading

__all__ = ["VARIABLE", "begin", "note", "end"]

#: the environment variable naming the trace file
VARIABLE = "GRADER_DIAGNOSIS_TRACE"

_CURRENT = threading.local()


def begin(check_id: str, kind: str) -> None:
    """Start the trace of one explanation of ``check_id``'s failure (``kind``: explain, doubt, not_asked)."""
    _CURRENT.record = {"check": check_id, "kind": kind, "notes": []} if os.environ.get(VARIABLE) else None


def note(what: str, **details) -> None:
    """Add what one step found (names, counts) to the explanation traced now; nothing when none is."""
    record = getattr(_CURRENT, "record", None)
    if record is not None:
        record["notes"].append({"what": what, **{k: _plain(v) for k, v in details.items()}})


def end(finding=None) -> None:
    """Write the explanation traced now, with its finding, and stop tracing it."""
    record = getattr(_CURRENT, "record", None)
    _CURRENT.record = None
    path = os.environ.get(VARIABLE)
    if record is None or not path:
        return
    record["finding"] = None if finding is None else {"names": list(finding.names), "hint": finding.hint[:200]}
    with open(path, "a", encoding="utf-8") as out:
        out.write(json.dumps(record) + "\n")


def _plain(value):
    if isinstance(value, (str, int, float, bool)) or value is None:
        return value
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, set, frozenset)):
        return [_plain(v) for v in value]
    return repr(value)[:120]
