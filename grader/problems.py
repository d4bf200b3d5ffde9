"""The registry of problems: which problems have checks, a problem's check module and its checks, and the id of a
check.  Whoever asks "is there a problem 22, what are its checks, what is its check ``loop_values`` called" asks
here: the runner, the kit, the batch, the deployments and the analysis of the grading code alike.

A problem has checks when ``checks/problem_NN.py`` exists; its checks are the module's ``@check`` functions, in
order (``grader.checking.checks_of``); a check's id is ``pNN.name`` (``check_id``).
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass
from functools import lru_cache

__all__ = ["ProblemInfo", "NoChecks", "problem_module", "has_checks", "require_problem", "require_problems",
           "problems", "check_id", "check_title", "secret_check_ids", "withheld_check_ids"]


@dataclass(frozen=True)
class ProblemInfo:
    number: int
    title: str
    points: float  # automatically graded points
    manual_points: float  # points scored by hand
    checks: int
    hidden: int


class NoChecks(ValueError):
    """A problem (or several) that has no check module: a usage error, said with where to look."""

    def __init__(self, numbers: list[int], message: str):
        super().__init__(message)
        self.numbers = list(numbers)


def check_id(problem: int, name: str) -> str:
    """The id of the check ``name`` of ``problem``: ``p06.cardan_values``."""
    return f"p{problem:02d}.{name}"


def check_title(check_id: str) -> str:
    """``problem N's check “title”`` of a check id (``"p06.elementary_values"``), or "" when there is no such
    check."""
    from .checking import checks_of

    try:
        number, name = int(check_id[1:3]), check_id[4:]
        spec = next(spec for spec in checks_of(problem_module(number)) if spec.name == name)
    except (ValueError, KeyError, StopIteration):
        return ""
    return f"problem {number}'s check “{spec.title}”"


def _module_name(number: int) -> str:
    return f"checks.problem_{number:02d}"


@lru_cache(maxsize=None)
def problem_module(number: int):
    """The check module of problem ``number``; ``KeyError`` when it has none."""
    try:
        return importlib.import_module(_module_name(number))
    except ModuleNotFoundError as exc:
        if exc.name == _module_name(number):
            raise KeyError(number) from None
        raise


def has_checks(number: int) -> bool:
    """Whether problem ``number`` has a check module, found without importing it."""
    import importlib.util

    return importlib.util.find_spec(_module_name(number)) is not None


def require_problem(number: int) -> None:
    """Raise ``NoChecks`` when problem ``number`` has no checks (nothing is imported): what ``grade problem-N`` and
    ``grade batch --problems`` say."""
    if not has_checks(number):
        raise NoChecks([number], f"problem {number} has no checks (see `grade list`)")


def require_problems(numbers: list[int] | None) -> list[int]:
    """The problems a deployment is built for: ``numbers`` when each has checks (every problem with checks for None
    or an empty list); else ``NoChecks`` naming every one that has none."""
    if not numbers:
        return [p.number for p in problems()]
    missing = [number for number in numbers if not has_checks(number)]
    if missing:
        raise NoChecks(missing, f"no checks for problem{'s' if len(missing) > 1 else ''} "
                                f"{', '.join(map(str, missing))} (see `grade list`)")
    return list(numbers)


def problems() -> list[ProblemInfo]:
    """Every problem that has a check module, in order."""
    import checks

    from .checking import checks_of

    infos = []
    for info in pkgutil.iter_modules(checks.__path__):
        if not info.name.startswith("problem_"):
            continue
        number = int(info.name.removeprefix("problem_"))
        module = problem_module(number)
        specs = checks_of(module)
        manual = getattr(module, "MANUAL", {})
        infos.append(
            ProblemInfo(
                number,
                module.TITLE,
                sum(s.points for s in specs),
                sum(points for _, points in manual.values()),
                len(specs),
                sum(1 for s in specs if s.visibility == "hidden"),
            )
        )
    return sorted(infos, key=lambda p: p.number)


def secret_check_ids(numbers: list[int] | None = None) -> set[str]:
    """The ids of the secret and hidden checks of problems ``numbers`` (default: every problem with checks): those whose
    verdicts the kit leaves to the graded submission, and whose tests students see only once grades are
    published."""
    from .checking import checks_of

    numbers = numbers or [p.number for p in problems()]
    return {check_id(n, spec.name) for n in numbers for spec in checks_of(problem_module(n))
            if spec.secret or spec.visibility == "hidden"}


def withheld_check_ids(numbers: list[int]) -> set[str]:
    """The checks whose tests students see only when grades are published: secret and hidden ones.  A problem
    without a check module here (a gradebook of checks since removed) adds none: its hidden checks are still
    withheld by their own visibility; its secret checks, if any, cannot be known."""
    known = []
    for number in sorted(set(numbers)):
        try:
            problem_module(number)
        except KeyError:
            continue
        known.append(number)
    return secret_check_ids(known) if known else set()
