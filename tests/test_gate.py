"""One gate for every answer: what a check receives from the student has the type, shape and keys it needs, or the
check fails saying that the answer cannot be graded (the student's error, never an internal grader error); every
natural way of writing a correct answer passes it."""

from __future__ import annotations

import pytest

import importlib
import math
import pkgutil

import numpy as np

import probes
from checks._answers import option_number
from grader import grade_submission
from grader.workers import Fresh
from grader.checking import CheckFailure
from grader.errors import GraderFault
from grader.gate import admit
from grader.results import Status
from probes._forms import ANY, Arr, ByArgs, Dict, Either, Flag, Items, Maybe, Num, Seq, Text, Tup

from .submissions import copy_reference

# ---------------------------------------------------------------------------------------------- the forms


def _probe_functions():
    for info in pkgutil.iter_modules(probes.__path__):
        module = importlib.import_module(f"probes.{info.name}")
        for name, func in vars(module).items():
            if getattr(func, "is_probe", False) and func.__module__ == module.__name__:
                yield f"{info.name}.{name}", func


def test_every_probe_declares_the_form_of_its_reply():
    found = dict(_probe_functions())
    assert len(found) > 150
    undeclared = [name for name, func in found.items() if func.returns is None and not func.reference_only]
    assert not undeclared, f"probes without a form (@probe(returns=...)) or reference_only: {undeclared}"
    both = [name for name, func in found.items() if func.returns is not None and func.reference_only]
    assert not both


def test_a_probe_of_the_references_own_data_is_never_asked_of_a_student():
    from grader.context import Context

    class Child:
        def call(self, *args, **kwargs):
            raise AssertionError("the probe must not be sent")

    ctx = Context(10, Child(), {}, None, 1)
    with pytest.raises(GraderFault, match="never run on a submission"):
        ctx.student("problem_10.key_a")


@pytest.mark.parametrize("form, value", [
    (Num(), 1), (Num(), -2.5), (Num(), np.float64(3.0)), (Num(finite=False), math.nan),
    (Arr(3), [1, 2, 3]), (Arr(3), np.zeros(3)), (Arr(None, 2), np.zeros((5, 2))), (Arr(2, 2), [[1, 0], [0, 1]]),
    (Arr(), np.zeros((2, 3, 4))), (Arr(ndim=2), np.zeros((3, 1))), (Arr(3, finite=False), [math.nan, 0, 1]),
    (Arr(lambda q: len(q)), np.zeros(4)), (Text(), "x"), (Flag(), False), (Maybe(Arr(3)), None),
    (Dict({"a": Num()}), {"a": 1, "extra": "ignored"}), (Dict({"a": Num(), "b": Num()}, optional=("b",)), {"a": 1}),
    (Items(Num()), {"x": 1, "y": 2}), (Seq(Num()), []), (Seq(Num(), length=2), [1, 2]), (Tup(Num(), Text()), [1, "s"]),
    (Either(Text(), Arr(2)), "why not"), (Either(Text(), Arr(2)), [1, 2]), (ANY, object()),
    (ByArgs(lambda which: Arr(3) if which == "v" else Arr(3, 3)), np.zeros(3)),
])
def test_a_reply_of_its_form_passes(form, value):
    args = (np.zeros(4),) if isinstance(form, Arr) and form.dims and callable(form.dims[0]) else ("v",)
    assert form.fault(value, args) is None


@pytest.mark.parametrize("form, value, diagnosis, text", [
    (Num(), True, "", "must be a number"), (Num(), "1", "", "must be a number"), (Num(), None, "none", "is None"),
    (Num(), math.inf, "not_finite", "finite"), (Arr(3), [1, 2], "shape", "must have shape (3,), got shape (2,)"),
    (Arr(3, 3), np.zeros(9), "shape", "got shape (9,)"), (Arr(3), ["x", 1, 2], "", "must be numeric"),
    (Arr(3), [True, 1.0, 2.0], "", "must be numeric"), (Arr(3), np.array([math.nan, 0, 0]), "not_finite", "NaN"),
    (Arr(3), np.array([1, "x", 2], dtype=object), "", "not numbers"), (Arr(2, 2), [[1, 2], [3]], "shape", "unequal"),
    (Arr(ndim=2), np.zeros(3), "shape", "2 dimensions"), (Text(), 3, "", "must be text"),
    (Flag(), 1, "", "True or False"), (Dict({"a": Num()}), [1], "shape", "must be a dict"),
    (Dict({"a": Num(), "b": Num()}), {"a": 1}, "shape", "has no entries ['b']"),
    (Dict({"a": Arr(2)}), {"a": [1]}, "shape", "got shape (1,)"), (Items(Num()), {"x": "1"}, "", "must be a number"),
    (Seq(Num(), length=2), [1], "shape", "must have 2 entries, got 1"), (Seq(Num()), {"a": 1}, "shape", "a list"),
    (Tup(Num(), Num()), [1, 2, 3], "shape", "must have 2 entries"), (Either(Text(), Arr(2)), [1], "shape", "(2,)"),
])
def test_a_reply_of_another_form_is_named(form, value, diagnosis, text):
    fault = form.fault(value, ())
    assert fault is not None and fault.diagnosis == diagnosis and text in fault.text, fault


def test_the_gate_says_where_in_the_reply_and_that_it_cannot_be_graded():
    bodies = {"bodies": [{"A_IB": np.eye(3)}, {"A_IB": "x"}]}
    with pytest.raises(CheckFailure) as failure:
        admit("problem_06.frames", (), {"A_IC1": np.eye(3), "A_IC2": np.eye(3), "A_IC3": np.zeros(9)})
    assert failure.value.message == ("cannot be graded: frames()['A_IC3'] must have shape (3, 3), got shape (9,).")
    assert failure.value.diagnosis == "shape" and "np.reshape(x, (3, 3))" in failure.value.hint
    assert admit("problem_06.elementary", (1, 0.3), np.eye(3)) is not None
    with pytest.raises(CheckFailure, match=r"cannot be graded: R1\(0.3\) must be numeric"):
        admit("problem_06.elementary", (1, 0.3), bodies)

def test_a_matrix_of_the_transposed_shape_is_told_as_a_transpose_where_the_engine_is_on(monkeypatch):
    """Six points returned one per column where one per row is asked: the transposed shape names its cause, and the
    hint says to swap rows and columns, never to reshape (which would scramble them)."""
    import grader.diagnosis

    reply = {name: {"masses": np.ones(n), "points": np.zeros((3, n))} for name, n in (("six_points", 6),
                                                                                   ("four_points", 4))}
    reply.update(ellipsoid={"mass": 1.0, "axes": np.ones(3), "V": np.eye(3)},
                 cuboid={"mass": 1.0, "edges": np.ones(3), "V": np.eye(3)})
    with pytest.raises(CheckFailure) as failure:
        admit("problem_17.representations", (np.eye(3), 1.0), reply)
    assert failure.value.diagnosis == "transpose" and "transposed shape" in failure.value.message
    assert ".T" in failure.value.hint and "reshape" not in failure.value.hint.lower()
    # near misses: another shape of as many entries, and the engine switched off, are a shape alone
    assert Arr(6, 3).fault(np.zeros((2, 9)), ()).transposed == ()
    assert Arr(3, 3).fault(np.zeros(9), ()).transposed == ()
    monkeypatch.setattr(grader.diagnosis, "ENABLED", False)
    with pytest.raises(CheckFailure) as failure:
        admit("problem_17.representations", (np.eye(3), 1.0), reply)
    assert failure.value.diagnosis == "shape"


def test_values_returned_in_another_order_are_told_as_such_where_the_engine_is_on(monkeypatch):
    """``V, moments`` returned where ``moments, V`` is asked: the entries fit the form in one other order, so the
    cause is named (two entries exchanged), and the hint says to return them in the order asked.  Near misses:
    entries of one form (either order fits: nothing to tell), a reply that fits in no order, and the engine off."""
    import grader.diagnosis
    from grader.gate import in_another_order

    with pytest.raises(CheckFailure) as failure:
        admit("problem_17.principal_axes", (np.eye(3),), [np.eye(3), np.ones(3)])
    assert failure.value.diagnosis == "swapped" and "in another order" in failure.value.message
    assert "your entry 2 has the form of entry 1" in failure.value.hint, failure.value.hint
    assert in_another_order(Tup(Arr(3), Arr(3)), [np.ones(2), np.ones(3)]) is None
    assert in_another_order(Tup(Arr(3), Arr(3, 3)), [np.ones(4), np.eye(3)]) is None
    assert in_another_order(Tup(Arr(2), Arr(3), Arr(3, 3)), [np.eye(3), np.ones(2), np.ones(3)]) == (1, 2, 0)
    # a dict's values under each other's keys, in every failing entry of a sequence alike
    pair = Dict({"qdd": Arr(3), "lam": Arr(1)})
    assert in_another_order(Seq(pair), [{"qdd": np.ones(1), "lam": np.ones(3)}] * 2) == (1, 0)
    assert in_another_order(Seq(pair), [{"qdd": np.ones(1), "lam": np.ones(3)}, {"qdd": np.ones(2),
                                                                                 "lam": np.ones(3)}]) is None
    # a sequence longer than the gate looks through fails as a shape alone
    from grader.gate import ORDER_ENTRIES
    assert in_another_order(Seq(pair), [{"qdd": np.ones(1), "lam": np.ones(3)}] * (ORDER_ENTRIES + 1)) is None
    monkeypatch.setattr(grader.diagnosis, "ENABLED", False)
    with pytest.raises(CheckFailure) as failure:
        admit("problem_17.principal_axes", (np.eye(3),), [np.eye(3), np.ones(3)])
    assert failure.value.diagnosis == "shape"


# ---------------------------------------------------------------------------------------------- choices


@pytest.mark.parametrize("written, number", [
    (4, 4), (4.0, 4), ("4", 4), (" 4 ", 4), ("4.0", 4), (1, 1),
    (True, None), (False, None), (4.5, None), ("four", None), ("", None), (None, None), ([4], None),
    (float("nan"), None), (float("inf"), None),
])
def test_an_option_is_a_whole_number_however_written(written, number):
    assert option_number(written) == number


#: (answers.toml section, key, the reference's option): one multiple-choice answer of every problem that has them
CHOICES = [("problem_10", "a", 4, "p10.a"), ("problem_20", "a", 3, "p20.part_a"),
           ("problem_27", "a", 4, "p27.choice_a"), ("problem_41", "a", 4, "p41.choice_a"),
           ("problem_42", "b", 2, "p42.direction_choice")]


def _answered(tmp_path, written: dict):
    """A reference copy whose answers.toml writes the chosen options as given (``{(section, key): text}``)."""
    submission = copy_reference(tmp_path / "pkg")
    path = submission / "answers.toml"
    lines, section = [], ""
    for line in path.read_text().splitlines():
        if line.startswith("["):
            section = line.strip("[]")
        key = line.partition("=")[0].strip()
        if (section, key) in written:
            line = f"{key} = {written[section, key]}"
        lines.append(line)
    path.write_text("\n".join(lines) + "\n")
    return submission


@pytest.mark.parametrize("form", ["{n}.0", '"{n}"', '" {n} "', '"{n}.0"'])
def test_every_way_of_writing_the_right_option_passes(form, tmp_path):
    """``a = 4.0`` crashed problem 41's check (KeyError '4.0', an internal grader error) and a digit string failed
    problem 10: the same option, however written, passes every multiple-choice check."""
    submission = _answered(tmp_path, {(section, key): form.format(n=n) for section, key, n, _ in CHOICES})
    reports = grade_submission(submission, [10, 20, 27, 41, 42], seed=3)
    results = {r.check_id: r for report in reports for r in report.results}
    for *_, check_id in CHOICES:
        assert results[check_id].status is Status.PASSED, (check_id, results[check_id].message)


@pytest.mark.parametrize("written", ["true", "4.5", '"four"', "5", "[4]"])
def test_an_answer_that_is_no_option_is_the_students_error(written, tmp_path):
    submission = _answered(tmp_path, {(section, key): written for section, key, *_ in CHOICES})
    reports = grade_submission(submission, [10, 20, 27, 41, 42], seed=3)
    results = {r.check_id: r for report in reports for r in report.results}
    for *_, check_id in CHOICES:
        result = results[check_id]
        assert result.status is Status.FAILED and result.diagnosis == "format", (check_id, result.message)
        assert "must be the number of one option, 1 to 4" in result.message
    assert not [r.check_id for r in results.values() if r.status is Status.GRADER_ERROR]


# ---------------------------------------------------------------------------------------------- crafted replies


def test_a_crafted_reply_is_the_students_error_and_grade_exits_1(tmp_path, capsys):
    """A worker whose JSON encoder is patched (tests/hostile/codec_patch: NaN, text, booleans, flat arrays, a list
    for a dict) made three checks of problem 6 internal grader errors and ``grade`` exit 3, the code of a broken
    installation: now every check that reads a reply fails saying that it cannot be graded, and ``grade`` exits 1."""
    from grader.cli import EXIT_FAILED, main

    from .submissions import build_hostile

    submission = build_hostile("codec_patch", tmp_path / "pkg")
    code = main(["problem-6", "--submission", str(submission), "--seed", "7", "--json", str(tmp_path / "r.json")])
    assert code == EXIT_FAILED, capsys.readouterr().out
    import json

    results = json.loads((tmp_path / "r.json").read_text())["reports"][0]["results"]
    assert sum(r["score"] for r in results) == 0
    ran = [r for r in results if r["status"] != "skipped"]
    assert ran and all(r["status"] == "failed" and r["message"].startswith("cannot be graded: ") for r in ran), ran


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(2))
def test_no_crafted_reply_crashes_a_check_of_any_problem(seed, tmp_path):
    """Every probe's reply meets the gate: a worker whose encoder shuffles what it sends (a dict as a list, keys
    dropped, numbers as NaN, text or booleans, arrays of other shapes, lists shortened) never makes a check of any
    problem an internal grader error."""
    from grader.problems import problems

    submission = copy_reference(tmp_path / "pkg")
    (submission / "__init__.py").write_text((submission / "__init__.py").read_text() + SHUFFLING_ENCODER % seed)
    reports = grade_submission(submission, [p.number for p in problems()], seed=seed, workers=Fresh(count=2))
    crashed = [(r.check_id, r.message[:200]) for report in reports for r in report.results
               if r.status is Status.GRADER_ERROR]
    assert not crashed


#: appended to a reference's __init__.py: every reply of the worker reshuffled at random (seeded)
SHUFFLING_ENCODER = '''
import math as _math
import random as _random

import probes._codec as _codec

_real_encode = _codec.encode
_rng = _random.Random(%d)


def _shuffled(data):
    if isinstance(data, dict) and "__array__" in data:
        values, shape = data["data"], data["__array__"]
        kind = _rng.choice(["keep", "keep", "nan", "text", "flag", "flat", "drop", "column", "number", "none"])
        if kind == "nan":
            return {"__array__": shape, "data": [_math.nan] * len(values)}
        if kind in ("text", "flag"):
            return {"__array__": shape, "data": ["x" if kind == "text" else True] * len(values)}
        if kind == "flat":
            return {"__array__": [len(values)], "data": values}
        if kind == "drop":
            return {"__array__": [max(len(values) - 1, 0)], "data": values[:-1]}
        if kind == "column":
            return {"__array__": [len(values), 1], "data": values}
        return {"number": 0.5, "none": None}.get(kind, data)
    if isinstance(data, dict):
        if _rng.random() < 0.1:
            return [_shuffled(value) for value in data.values()]
        return {key: _shuffled(value) for key, value in data.items() if _rng.random() > 0.1}
    if isinstance(data, list):
        items = [_shuffled(value) for value in data]
        return items[:-1] if items and _rng.random() < 0.15 else items
    if isinstance(data, (int, float)) and not isinstance(data, bool) and _rng.random() < 0.3:
        return _rng.choice([_math.nan, _math.inf, "x", True, [data, data], None])
    if isinstance(data, str) and _rng.random() < 0.3:
        return _rng.choice([3.0, None, ["x"]])
    return data


def _encode(value, depth=0):
    return _shuffled(_real_encode(value, depth))


_codec.encode = _encode
'''
