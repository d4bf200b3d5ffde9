"""A check that words anew a failure it caught keeps the caught failure's evidence: the diagnosis engine is asked
about a failing comparison only through it (``grader.context``: no evidence, no diagnosis), so a new hint that drops
it leaves every mistake behind that comparison unnamed (problem 21's Jacobians, against the derivative of the
student's own chain, were never diagnosed)."""

import ast
from pathlib import Path

import pytest

from grader.checking import CheckFailure, fail

ROOT = Path(__file__).resolve().parents[1]


def _handlers(tree):
    for node in ast.walk(tree):
        if isinstance(node, ast.ExceptHandler) and node.name is not None:
            caught = node.type.elts if isinstance(node.type, ast.Tuple) else [node.type]
            if any(getattr(t, "id", None) == "CheckFailure" for t in caught):
                yield node


def _raised_anew(handler):
    """The calls of ``fail`` and ``CheckFailure`` inside ``handler`` (not inside a function defined there)."""
    for statement in handler.body:
        for node in ast.walk(statement):
            if isinstance(node, ast.Call):
                name = getattr(node.func, "id", None) or getattr(node.func, "attr", None)
                if name in ("fail", "CheckFailure"):
                    yield node


def _carries_evidence(call, caught: str) -> bool:
    """The call passes an evidence: the keyword, or ``CheckFailure``'s fifth argument (the caught failure's own or
    one the check built)."""
    if any(k.arg == "evidence" for k in call.keywords):
        return True
    return getattr(call.func, "id", None) == "CheckFailure" and len(call.args) >= 5


def _sources():
    return sorted([*(ROOT / "checks").glob("*.py"), *(ROOT / "grader").rglob("*.py")])


def test_every_failure_worded_anew_keeps_the_evidence_of_the_one_caught():
    dropped = []
    for path in _sources():
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for handler in _handlers(tree):
            for call in _raised_anew(handler):
                if not _carries_evidence(call, handler.name):
                    dropped.append(f"{path.relative_to(ROOT)}:{call.lineno}")
    assert dropped == [], f"a caught failure raised anew without its evidence: {dropped}"


def test_the_scan_sees_a_failure_that_drops_its_evidence(tmp_path):
    """The rule above reads what it must: a handler that drops the evidence is found, one that keeps it is not."""
    source = (
        "try:\n    check()\nexcept CheckFailure as exc:\n    fail(exc.message, 'another hint')\n"
        "try:\n    check()\nexcept CheckFailure as exc:\n    fail(exc.message, 'another hint', evidence=exc.evidence)\n"
    )
    calls = [(h.name, c) for h in _handlers(ast.parse(source)) for c in _raised_anew(h)]
    assert [_carries_evidence(c, name) for name, c in calls] == [False, True]


def test_fail_passes_the_evidence_on():
    evidence = object()
    with pytest.raises(CheckFailure) as caught:
        fail("differs", "a hint", evidence=evidence)
    assert caught.value.evidence is evidence and caught.value.hint == "a hint"
