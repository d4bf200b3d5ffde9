"""An earlier tier's explanation contested by the formula tier (``grader.diagnosis.mutants.Contested``): where the
formula tier, heard after an earlier tier explained the answer, keeps slips of the reference's code of more families
than can be told, one of them at least not the earlier tier's, the engine tells nothing rather than the earlier
finding alone (no cost outranks a rival that reproduces the answer on the same inputs); the engine's side of it is
tested in tests/test_diagnosis_engine.py."""

import pytest

from checks._diagnoses import DIAGNOSES
from grader.diagnosis import mutants


def _made(*slips):
    return [mutants.Mutant("problem_98", ("f",), slip, None) for slip in slips]


def test_slips_of_three_families_contest_an_earlier_finding_of_another():
    made = _made("entries", "square", "sign")
    assert {DIAGNOSES[m.name].family for m in made} == {"order", "scale", "sign"}
    with pytest.raises(mutants.Contested) as caught:
        mutants._contest(made, {"sign"})
    assert set(caught.value.families) == {"order", "scale", "sign"}
    with pytest.raises(mutants.Contested):
        mutants._contest(made, {"transpose"})


def test_slips_of_two_families_or_of_the_families_told_contest_nothing():
    mutants._contest(_made("entries", "square"), {"sign"})  # two: told beside the earlier finding, or as rivals
    mutants._contest(_made("sign", "entries"), {"sign", "order"})
    mutants._contest(_made("sign", "sign"), {"sign"})

