"""Every argument of a student's function that a probe calls is varied by some check, or is in the allowlist with
its reason (``tests/arguments_allowed.toml``): an answer that ignores an argument no check varies loses nothing.

``tests/arguments.py`` records, over a grading of the reference, the values each parameter took in the calls the
probes make of the student's package (defaults filled in); a parameter that took one value only is a gap.  The
full sweep grades every problem (about two minutes: slow); the problems whose gaps were mended are held to it on
their own at every run.
"""

from __future__ import annotations

import tomllib

import pytest

from grader.problems import problems

from .arguments import gaps, parameter_values, probe_calls
from .kit_support import warm_slot
from .submissions import ROOT, copy_reference

ALLOWLIST = ROOT / "tests" / "arguments_allowed.toml"
PROBLEMS = [p.number for p in problems()]
#: problems whose checks were mended to vary an argument, with the arguments that must now take several values
MENDED = {
    3: ("problem_03.double_pendulum:density", "problem_03.double_pendulum_custom_inertia:density",
        "problem_03.driven_double_pendulum:density", "problem_03.driven_double_pendulum:rate"),
    24: ("problem_24.simulate:q0", "problem_24.simulate:qd0", "problem_24.simulate:dt"),
}


def allowed() -> dict[str, str]:
    return tomllib.loads(ALLOWLIST.read_text())


def test_every_allowed_gap_has_a_reason():
    entries = allowed()
    assert entries
    for name, reason in entries.items():
        function, _, parameter = name.partition(":")
        assert function and parameter, f"{name!r} is not 'function:parameter'"
        assert isinstance(reason, str) and len(reason.split()) >= 3, f"{name!r} needs a one-line reason"


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    return copy_reference(tmp_path_factory.mktemp("arguments") / "reference")


def _values(numbers, reference, folder):
    calls = []
    for slot in warm_slot(numbers):
        for problem in numbers:
            calls += probe_calls(problem, reference, slot)
    return parameter_values(calls, folder)


@pytest.mark.parametrize("problem", sorted(MENDED))
def test_the_mended_arguments_are_varied(problem, reference, tmp_path):
    values = _values([problem], reference, tmp_path)
    own = f"problem_{problem:02d}."
    found = [gap for gap in gaps(values) if gap.startswith(own)]
    print(f"problem {problem}: arguments no check varies: {found}")
    for name in MENDED[problem]:
        function, _, parameter = name.partition(":")
        assert len(values.get(function, {}).get(parameter, ())) > 1, f"no check varies {name}"
    assert not set(found) - set(allowed()), f"new gaps: {sorted(set(found) - set(allowed()))}"


@pytest.mark.slow
def test_every_argument_a_probe_passes_is_varied_or_allowed(reference, tmp_path):
    values = _values(PROBLEMS, reference, tmp_path)
    found = gaps(values)
    print("arguments no check varies:\n" + "\n".join(f"  {gap}" for gap in found))
    entries = allowed()
    new = [gap for gap in found if gap not in entries]
    stale = [name for name in entries if name not in found]
    assert not new, "arguments no check varies (vary them in a check, or allow them with a reason):\n" + "\n".join(new)
    assert not stale, "allowed gaps that are gaps no longer (remove them from the allowlist):\n" + "\n".join(stale)
