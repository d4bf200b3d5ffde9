"""The formula tier's budgets (``grader.diagnosis.mutants``): the making of the mutants (the reference's code
parsed, mutated and compiled: the same for every answer, kept for the process) is counted apart from the measuring
of one answer (``TIME_BUDGET``), so that what the tier names does not depend on whether the process made them
before, nor on how much a loaded machine slows their making; and each of the two is still bounded.

The machine's load is stood in for by a clock that runs ahead: the deadline's clock is put forward by a given
amount wherever the tier makes mutants (``_codes``) or runs the reference (``_call``), as a machine that slows
that work would put it.  The answer is problem 27's statement 1 of the frame derivatives with ``+`` where ``-``
belongs, whose mutants took most of the budget to make the first time in a process.
"""

import pytest

from grader.diagnosis import mutants
from grader.private import drop_private

from .test_mutants import evidence, planted_package, scene

STATEMENT = "1: (_derivative(lambda s: A_IB(s).T @ I_r(s), t), B_v - skew(w) @ B_r),"
PLUS = "1: (_derivative(lambda s: A_IB(s).T @ I_r(s), t), B_v + skew(w) @ B_r),"
#: the seeds and times of two rigid motions, and statement 1's residual
CASES, RESIDUAL = [(0, 0.3), (1, 0.7)], (1,)


@pytest.fixture(scope="module")
def statement_plus(tmp_path_factory):
    student = planted_package(tmp_path_factory.mktemp("p27"), "problem_27.py", STATEMENT, PLUS)
    try:
        yield [evidence("problem_27.frame_derivative_residuals", args, RESIDUAL, student) for args in CASES]
    finally:
        drop_private(student)


@pytest.fixture
def ahead(monkeypatch):
    """``ahead(where, seconds)``: every call of the tier's function ``where`` puts the deadline's clocks (CPU and
    wall) ``seconds`` forward, as a machine that slowed that work would."""
    skew = [0.0]

    class Skewed(mutants._Deadline):
        def _now(self):
            cpu, wall = super()._now()
            return cpu + skew[0], wall + skew[0]

    monkeypatch.setattr(mutants, "_Deadline", Skewed)

    def put(where: str, seconds: float):
        original = getattr(mutants, where)

        def slowed(*args, **keywords):
            skew[0] += seconds
            return original(*args, **keywords)

        monkeypatch.setattr(mutants, where, slowed)

    return put


def named(evidences) -> set:
    return {h.name for h in mutants.mutant_slips(scene("p27.frame_residuals"), evidences)}


def test_a_slow_making_of_the_mutants_leaves_the_measuring_its_budget(statement_plus, ahead):
    """Each making of a function's mutants seen to take more than the whole ``TIME_BUDGET``: the slip is named as
    on an idle machine, a sign (or, the term being a skew matrix's, a transpose)."""
    ahead("_codes", mutants.TIME_BUDGET + 0.5)
    assert named(statement_plus) == {"sign_flip", "transpose"}


def test_a_slow_measuring_is_still_interrupted(statement_plus, ahead):
    """The near miss: the same time seen in the runs of the reference on the answer's inputs runs out the budget
    of the measuring, and nothing is named (the tier did not try its slips)."""
    ahead("_call", mutants.TIME_BUDGET / 4)
    assert named(statement_plus) == set()


def test_the_making_has_a_bound_of_its_own(statement_plus, ahead):
    """A making seen to take more than ``MAKING_TIME_BUDGET`` is interrupted too, and nothing is named."""
    ahead("_codes", mutants.MAKING_TIME_BUDGET + 0.5)
    assert named(statement_plus) == set()
