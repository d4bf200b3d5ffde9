"""What a student could learn from the grader instead of computing: the failure messages of fixed cases, and the
student kit's answer key.

* A failure of a fixed case (the sheet's configuration) shows the expected values at the sheet's precision, the
  same on every attempt: copying them from the message, attempt after attempt, never passes (a student copied
  problem 6's frames at 4, then 7, then 9 decimals and passed).
* The kit's key holds the sheet's cases only to the sheet's digits (the kit says so where a check passes on them),
  and the live grading asks cases the key does not hold: a submission that looks every probe call up in the key
  earns nothing live nor on Gradescope (it earned 46 of 381 points live).
"""

from __future__ import annotations

import ast
import re

import numpy as np
import pytest

from grader import grade_problem
from grader.workers import Fresh
from grader.results import Status

from .kit_support import SEED
from .submissions import copy_reference

FRAMES = ("A_IC1", "A_IC2", "A_IC3")


def _expected_block(message: str) -> str:
    """The text of the expected value in an ``assert_close`` message."""
    return message.split("\nexpected:\n", 1)[1].split("\n  index", 1)[0]


def _frames_returning(submission, frames: dict) -> None:
    """Make ``problem_06.frames()`` return the given constant matrices (a student's copy of what they read)."""
    path = submission / "problem_06.py"
    literal = {key: np.asarray(value).tolist() for key, value in frames.items()}
    code = f"\n\ndef frames():\n    return {{k: np.array(v) for k, v in {literal!r}.items()}}\n"
    path.write_text(path.read_text() + code)


def test_copying_the_expected_frames_from_the_messages_never_passes(tmp_path):
    """Nine attempts, each copying the expected frames that the previous failure printed: the check never passes,
    and the expected values it prints are the same every time (the sheet's four decimals)."""
    from reference import problem_06
    from reference.rotations import R1

    submission = copy_reference(tmp_path / "pkg")
    current = {key: value @ R1(3e-4) for key, value in problem_06.frames().items()}  # close, still rotations
    _frames_returning(submission, current)
    shown = []
    for attempt in range(9):
        result = next(r for r in grade_problem(6, submission, seed=attempt).results if r.check_id == "p06.frames")
        assert result.status is Status.FAILED, f"attempt {attempt + 1} passed by copying the messages"
        found = re.search(r"^(A_IC\d) is not the expected value", result.message, re.M)
        if found is None:  # the copied digits are no rotation any more (orthonormal to 1e-6): nothing new to copy
            assert "is not orthonormal" in result.message, result.message
            continue
        block = _expected_block(result.message)
        shown.append((found[1], block))
        current[found[1]] = np.array(ast.literal_eval(block))
        _frames_returning(submission, current)
    assert len(set(shown)) == 1, shown  # the first frame, as the sheet's digits give it, every time it is shown
    assert all(len(number.split(".")[1]) == 4 for number in re.findall(r"-?\d+\.\d+", shown[0][1])), shown[0]


# ---------------------------------------------------------------------------------------------- the kit's key

#: appended to the untouched template's __init__.py: every probe of the worker answers from the key's table when it
#: holds the call (the student kit's key, every recorded probe call -> its recorded value), else runs as it is
LOOKUP = '''

import base64 as _base64
import gzip as _gzip
import importlib as _importlib
import json as _json
import pkgutil as _pkgutil

import probes as _probes
from probes._codec import decode as _decode, encode as _encode

from .lookup_table import DATA as _DATA

_TABLE = _json.loads(_gzip.decompress(_base64.b64decode(_DATA)))


def _looked_up(name, real):
    def probe(pkg, *args):
        key = name + _json.dumps(_encode(list(args)), sort_keys=True)
        return _decode(_TABLE[key]) if key in _TABLE else real(pkg, *args)

    probe.is_probe = True
    return probe


for _info in _pkgutil.iter_modules(_probes.__path__):
    _module = _importlib.import_module("probes." + _info.name)
    for _name, _function in list(vars(_module).items()):
        if getattr(_function, "is_probe", False) and _function.__module__ == _module.__name__:
            setattr(_module, _name, _looked_up(_info.name + "." + _name, _function))
'''


def lookup_submission(key, dest):
    """The untouched template with a lookup of every probe call that ``key`` holds, answered in the worker."""
    import base64
    import gzip
    import json

    from .submissions import copy_template

    copy_template(dest)
    table = {call: entry["value"] for call, entry in key.calls.items()}
    data = base64.b64encode(gzip.compress(json.dumps(table).encode())).decode()
    (dest / "lookup_table.py").write_text(f"DATA = {data!r}\n")
    (dest / "__init__.py").write_text((dest / "__init__.py").read_text() + LOOKUP)
    return dest


@pytest.fixture(scope="module")
def looked_up(answer_key, tmp_path_factory):
    return lookup_submission(answer_key, tmp_path_factory.mktemp("lookup") / "pkg")


@pytest.mark.slow
def test_a_lookup_of_the_kits_key_earns_nothing_live(looked_up, kit_oracle):
    """Every probe call the key holds, answered from it: the live grading (a seed of its own) asks the fixed cases
    again, which the key holds at the sheet's digits only, and cases of its own, which it does not hold: 0 points
    (46 of 381 before).  From the key itself the lookup does earn points: the test's lookup works."""
    from grader import grade_submission
    from grader.oracle import LiveOracle
    from grader.problems import problems

    numbers = [p.number for p in problems()]
    live = grade_submission(looked_up, numbers, seed=SEED, oracle=LiveOracle(), workers=Fresh(count=2))
    earned = [(r.check_id, r.score) for report in live for r in report.results if r.score]
    assert not earned, earned
    kit = grade_submission(looked_up, numbers, seed=SEED, oracle=kit_oracle, workers=Fresh(count=2))
    assert sum(report.score for report in kit) > 100


@pytest.mark.slow
def test_a_lookup_of_the_kits_key_earns_nothing_on_gradescope(looked_up, tmp_path, capsys):
    """The same lookup graded as Gradescope's run_autograder grades (grader.gradescope.run, a fresh seed): score
    0 in results.json."""
    import json
    import shutil

    from grader import gradescope
    from grader.problems import problems

    root = tmp_path / "autograder"
    shutil.copytree(looked_up, root / "submission")
    code = gradescope.run(root, [p.number for p in problems()])
    data = json.loads((root / "results" / "results.json").read_text())
    assert code == gradescope.EXIT_GRADED, capsys.readouterr().out
    assert data["score"] == 0, [(t["name"], t["score"]) for t in data["tests"] if t.get("score")]
    assert data["extra_data"]["grader_fault"] is False
