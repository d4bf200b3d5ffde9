"""The formula tier's refutations within a grading (``grader.diagnosis.mutants._Refuted``): a mutant whose value of
the student's own call is not the student's value is not the student's code, and a later explanation of the same
grading does not measure it again, where the call that refuted it ran no code that the later call does not run.

* The same slip is named in the later explanation, with fewer mutants measured than in a grading of its own.
* A refutation from a call that ran a function the later call does not run is not heard (a second slip there
  would have refuted the first slip's mutant).
* Another grading hears none of it, though the same oracle serves both (a batch's worker grades every submission
  with one).
"""

import importlib
from types import SimpleNamespace

import numpy as np
import pytest

from checks._diagnoses import DIAGNOSES
from grader.checking import Tol
from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, Source, array_of, at
from .stand_ins import made_up_package

TIGHT = Tol("tight", 1e-9, 1e-9)

SOURCE = '''
import numpy as np


def lever(a, b):
    """The moment of a force ``b`` at arm ``a`` less its tenth."""
    # BEGIN SOLUTION problem 96
    return a * b - 0.1 * b
    # END SOLUTION


def tip(a):
    """A tip's offset: the cube of ``a`` over three."""
    # BEGIN SOLUTION problem 96
    return a ** 3 / 3.0
    # END SOLUTION


def moments(a, b, tipped):
    """The lever's moment and, where ``tipped``, the tip's offset beside it."""
    # BEGIN SOLUTION problem 96
    return np.array([lever(a, b), tip(a) if tipped else 0.0])
    # END SOLUTION
'''


@pytest.fixture
def made_up(tmp_path, monkeypatch):
    with made_up_package(tmp_path, monkeypatch, SOURCE, 96, "refuted") as package:
        yield package


def moments(pkg, a, b, tipped):
    return importlib.import_module(f"{pkg.__name__}.problem_96").moments(a, b, tipped)


def grading(oracle=None):
    """One grading's scene: its context (one submission's problem) is what the refutations belong to; the oracle
    (given) may serve many, as a batch's does."""
    oracle = SimpleNamespace(mode="live") if oracle is None else oracle
    return SimpleNamespace(ctx=SimpleNamespace(check_id="p96.moments", oracle=oracle))


def evidences_of(package, student, inputs):
    return [Evidence(array_of(student(*args)), array_of(at(moments(package, *args), ())), TIGHT, "value",
                     source=Source(moments, args, ())) for args in inputs]


def lever_swapped(a, b, tipped):
    """The student's moments: ``0.1 * a`` subtracted where ``0.1 * b`` belongs."""
    return np.array([a * b - 0.1 * a, a ** 3 / 3.0 if tipped else 0.0])


@pytest.fixture
def measured(monkeypatch):
    """The mutants measured (``_mutated_values``), one entry each."""
    counted = []
    values = mutants._mutated_values

    def counting(package, mutant, *args, **kwargs):
        counted.append(mutant.slip)
        return values(package, mutant, *args, **kwargs)

    monkeypatch.setattr(mutants, "_mutated_values", counting)
    return counted


def named(found):
    return {DIAGNOSES[h.name].family for h in found}


FIRST = [(1.5, 2.0, True), (0.7, -1.2, True)]
LATER = [(2.5, 0.4, True), (-0.6, 1.7, True)]


def test_a_mutant_refuted_once_is_not_measured_again_in_the_grading(made_up, measured):
    alone = mutants.mutant_slips(grading(), evidences_of(made_up, lever_swapped, LATER))
    measured_alone = len(measured)
    assert alone and measured_alone

    one = grading()
    first = mutants.mutant_slips(one, evidences_of(made_up, lever_swapped, FIRST))
    assert named(first) == named(alone)
    del measured[:]
    later = mutants.mutant_slips(one, evidences_of(made_up, lever_swapped, LATER))
    assert [h.name for h in later] == [h.name for h in alone]
    assert 0 < len(measured) < measured_alone / 2, (len(measured), measured_alone)


def test_a_refutation_from_a_call_that_ran_more_code_is_not_heard(made_up, measured):
    """The first call runs ``tip`` (``tipped``), the later one does not: a student whose ``tip`` is wrong too
    refutes every slip of ``lever`` there, yet the later call, which never reaches ``tip``, still names it."""
    def both_wrong(a, b, tipped):
        return np.array([a * b - 0.1 * a, a ** 2 / 3.0 if tipped else 0.0])

    untipped = [(2.5, 0.4, False), (-0.6, 1.7, False)]
    alone = mutants.mutant_slips(grading(), evidences_of(made_up, both_wrong, untipped))
    measured_alone = len(measured)
    assert alone

    one = grading()
    assert mutants.mutant_slips(one, evidences_of(made_up, both_wrong, FIRST)) == []
    del measured[:]
    later = mutants.mutant_slips(one, evidences_of(made_up, both_wrong, untipped))
    assert [h.name for h in later] == [h.name for h in alone]
    assert len(measured) == measured_alone


def test_another_grading_hears_no_refutation(made_up, measured):
    mutants.mutant_slips(grading(), evidences_of(made_up, lever_swapped, FIRST))
    del measured[:]
    mutants.mutant_slips(grading(), evidences_of(made_up, lever_swapped, LATER))
    measured_fresh = len(measured)
    del measured[:]
    mutants.mutant_slips(grading(), evidences_of(made_up, lever_swapped, LATER))
    assert len(measured) == measured_fresh > 0


def test_another_submission_graded_by_the_same_oracle_hears_no_refutation(made_up, measured):
    """The first submission's ``tip`` is wrong too, which refutes every slip of ``lever`` on its calls; the next
    submission, graded with the same oracle, has only the slip of ``lever``, and its grading names it."""
    def both_wrong(a, b, tipped):
        return np.array([a * b - 0.1 * a, a ** 2 / 3.0 if tipped else 0.0])

    oracle = SimpleNamespace(mode="live")
    alone = mutants.mutant_slips(grading(), evidences_of(made_up, lever_swapped, LATER))
    assert alone
    assert mutants.mutant_slips(grading(oracle), evidences_of(made_up, both_wrong, FIRST)) == []
    later = mutants.mutant_slips(grading(oracle), evidences_of(made_up, lever_swapped, LATER))
    assert [h.name for h in later] == [h.name for h in alone]



def test_the_refutations_of_a_grading_in_another_thread_are_not_heard():
    """Two gradings under way at once in two threads of one process: the one thread's refutations are not heard in
    the other's grading (each thread keeps its own), and its own are."""
    import threading

    store = mutants._Refuted()
    mutant = mutants.Mutant("problem_96", ("lever",), "sign", None)
    ran = frozenset({"lever"})
    mine, theirs = object(), object()

    def other():
        with store.grading(theirs):
            store.refute(mutant, ran)

    with store.grading(mine):
        thread = threading.Thread(target=other)
        thread.start()
        thread.join()
        assert not store.refuted(mutant, ran)
        store.refute(mutant, ran)
        assert store.refuted(mutant, ran)
