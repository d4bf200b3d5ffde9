"""The held-out measure of the diagnosis (issue 27): the fresh set of mistakes that no catalogue lists, the second
to the thirty-fourth held-out sets written apart from the engine (``fresh2`` ... ``fresh34``), and the script that
grades them and classifies each diagnosis (``tests/diagnosis/score.py``), strictly and leniently (where an entry of
the seventh to the thirty-fourth set names a second family, ``also``).

The set is data, checked here without grading: every exercise is covered, every entry is well formed and plants
into the reference, and the diagnosis recorded with it (``today``) is not the right cause, which is what put it in
the set.  The classification of a diagnosis is tested on made-up names.  One slow test runs the script on a
subset of the set and checks that it grades and classifies each mistake; the issue's target (at least 60% right,
at most 2% wrong) is reported by the script, not asserted, until the diagnosis engine lands.
"""

import json
import subprocess
import sys
import types
from collections import Counter

import pytest

from grader.checking import checks_of
from grader.problems import problem_module

from .score import (
    EXERCISES,
    FALLBACK,
    FAMILIES,
    FRESH,
    FRESH2,
    FRESH3,
    FRESH4,
    FRESH5,
    FRESH6,
    FRESH7,
    FRESH8,
    FRESH9,
    FRESH10,
    FRESH11,
    FRESH12,
    FRESH13,
    FRESH14,
    FRESH15,
    FRESH16,
    FRESH17,
    FRESH18,
    FRESH19,
    FRESH20,
    FRESH21,
    FRESH22,
    FRESH23,
    FRESH24,
    FRESH25,
    FRESH26,
    FRESH27,
    FRESH28,
    FRESH29,
    FRESH30,
    FRESH31,
    FRESH32,
    FRESH33,
    FRESH34,
    NAMED,
    NAMED2,
    NAMED3,
    ROOT,
    candidate_families,
    classify,
    defects,
    exercise_of,
    fresh_mistakes,
    naming,
)

FRESH_SET = fresh_mistakes(FRESH)
NAMED_SET = fresh_mistakes(NAMED)
FRESH2_SET = fresh_mistakes(FRESH2)
NAMED2_SET = fresh_mistakes(NAMED2)
FRESH3_SET = fresh_mistakes(FRESH3)
NAMED3_SET = fresh_mistakes(NAMED3)
FRESH4_SET = fresh_mistakes(FRESH4)
FRESH5_SET = fresh_mistakes(FRESH5)
FRESH6_SET = fresh_mistakes(FRESH6)
FRESH7_SET = fresh_mistakes(FRESH7)
FRESH8_SET = fresh_mistakes(FRESH8)
FRESH9_SET = fresh_mistakes(FRESH9)
FRESH10_SET = fresh_mistakes(FRESH10)
FRESH11_SET = fresh_mistakes(FRESH11)
FRESH12_SET = fresh_mistakes(FRESH12)
FRESH13_SET = fresh_mistakes(FRESH13)
FRESH14_SET = fresh_mistakes(FRESH14)
FRESH15_SET = fresh_mistakes(FRESH15)
FRESH16_SET = fresh_mistakes(FRESH16)
FRESH17_SET = fresh_mistakes(FRESH17)
FRESH18_SET = fresh_mistakes(FRESH18)
FRESH19_SET = fresh_mistakes(FRESH19)
FRESH20_SET = fresh_mistakes(FRESH20)
FRESH21_SET = fresh_mistakes(FRESH21)
FRESH22_SET = fresh_mistakes(FRESH22)
FRESH23_SET = fresh_mistakes(FRESH23)
FRESH24_SET = fresh_mistakes(FRESH24)
FRESH25_SET = fresh_mistakes(FRESH25)
FRESH26_SET = fresh_mistakes(FRESH26)
FRESH27_SET = fresh_mistakes(FRESH27)
FRESH28_SET = fresh_mistakes(FRESH28)
FRESH29_SET = fresh_mistakes(FRESH29)
FRESH30_SET = fresh_mistakes(FRESH30)
FRESH31_SET = fresh_mistakes(FRESH31)
FRESH32_SET = fresh_mistakes(FRESH32)
FRESH33_SET = fresh_mistakes(FRESH33)
FRESH34_SET = fresh_mistakes(FRESH34)


def _fallback(name):
    return FALLBACK.get(name, "?")


# ------------------------------------------------------------------------------------------------- the set


def test_the_fresh_set_covers_every_exercise_with_at_least_six_mistakes_and_eighty_in_all():
    per_exercise = Counter(m.exercise for m in FRESH_SET)
    assert set(per_exercise) == set(EXERCISES)
    assert min(per_exercise.values()) >= 6, per_exercise
    assert len(FRESH_SET) >= 80
    # weighted towards the exercises whose causes are told least (I, VI, VII)
    assert sum(per_exercise[e] for e in ("I", "VI", "VII")) > len(FRESH_SET) / 2


@pytest.mark.parametrize("sets", [(FRESH_SET, NAMED_SET), (FRESH2_SET, NAMED2_SET), (FRESH3_SET, NAMED3_SET),
                                  (FRESH4_SET, []), (FRESH5_SET, []), (FRESH6_SET, []), (FRESH7_SET, []),
                                  (FRESH8_SET, []), (FRESH9_SET, []), (FRESH10_SET, []), (FRESH11_SET, []),
                                  (FRESH12_SET, []), (FRESH13_SET, []), (FRESH14_SET, []), (FRESH15_SET, []),
                                  (FRESH16_SET, []), (FRESH17_SET, []), (FRESH18_SET, []), (FRESH19_SET, []),
                                  (FRESH20_SET, []), (FRESH21_SET, []), (FRESH22_SET, []),
                                  (FRESH23_SET, []), (FRESH24_SET, []), (FRESH25_SET, []),
                                  (FRESH26_SET, []), (FRESH27_SET, []), (FRESH28_SET, []),
                                  (FRESH29_SET, []), (FRESH30_SET, []), (FRESH31_SET, []),
                                  (FRESH32_SET, []), (FRESH33_SET, []), (FRESH34_SET, [])],
                         ids=["first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth",
                              "tenth", "eleventh", "twelfth", "thirteenth", "fourteenth", "fifteenth", "sixteenth",
                              "seventeenth", "eighteenth", "nineteenth", "twentieth", "twenty-first",
                              "twenty-second", "twenty-third", "twenty-fourth", "twenty-fifth", "twenty-sixth",
                              "twenty-seventh", "twenty-eighth", "twenty-ninth", "thirtieth", "thirty-first",
                              "thirty-second", "thirty-third", "thirty-fourth"])
def test_every_entry_plants_into_the_reference_and_names_a_check_of_its_problem(sets):
    for mistakes in sets:
        assert defects(mistakes) == []
    for mistake in sets[0] + sets[1]:
        ids = {f"p{mistake.problem:02d}.{spec.name}" for spec in checks_of(problem_module(mistake.problem))}
        assert mistake.check in ids, mistake.name
        assert mistake.family in FAMILIES and mistake.cause, mistake.name
        assert mistake.also == "" or (mistake.also in FAMILIES and mistake.also != mistake.family), mistake.name
        assert exercise_of(mistake.problem) == mistake.exercise


def test_no_mistake_is_in_both_sets_or_in_the_planted_suite():
    fresh = {(m.file, m.old, m.new) for m in FRESH_SET}
    named = {(m.file, m.old, m.new) for m in NAMED_SET}
    assert not fresh & named
    import tomllib

    planted = set()
    for path in (ROOT / "tests" / "planted").glob("problem_*.toml"):
        planted |= {(e["file"], e["old"], e["new"]) for e in tomllib.loads(path.read_text()).get("mistake", [])}
    assert not (fresh | named) & planted


def test_an_entry_with_an_unknown_family_or_field_is_refused(tmp_path):
    entry = ('[[mistake]]\nname = "x"\nfile = "rotations.py"\nold = "a"\nnew = "b"\ncheck = "p06.cardan_values"\n'
             'cause = "c"\n')
    (tmp_path / "problem_06.toml").write_text(entry + 'family = "weather"\n')
    with pytest.raises(ValueError, match="unknown family"):
        fresh_mistakes(tmp_path)
    (tmp_path / "problem_06.toml").write_text(entry + 'family = "sign"\nseverity = 3\n')
    with pytest.raises(ValueError, match="severity"):
        fresh_mistakes(tmp_path)
    (tmp_path / "problem_06.toml").write_text(entry + 'family = "sign"\nalso = "weather"\n')
    with pytest.raises(ValueError, match="unknown also"):
        fresh_mistakes(tmp_path)
    (tmp_path / "problem_06.toml").write_text(entry + 'family = "sign"\nalso = "transpose"\n')
    assert fresh_mistakes(tmp_path)[0].also == "transpose"


def test_defects_holds_the_second_family_to_the_families_and_apart_from_the_first():
    planted = fresh_mistakes(FRESH6)[0]
    import dataclasses

    assert defects([dataclasses.replace(planted, also="transpose" if planted.family != "transpose" else "sign")]) == []
    assert any("unknown second family" in d for d in defects([dataclasses.replace(planted, also="weather")]))
    assert any("repeats its family" in d for d in defects([dataclasses.replace(planted, also=planted.family)]))
    assert any("unknown family" in d for d in defects([dataclasses.replace(planted, family="weather")]))


def test_the_recorded_diagnoses_are_not_the_right_cause_in_the_fresh_set_and_are_in_the_named_one():
    """What put a mistake in the fresh set: when it was written, the grader did not name its cause (``today``).
    Every name recorded is one the fallback table knows."""
    _assert_chosen_by_their_recorded_diagnoses(FRESH_SET, NAMED_SET, _fallback, "?")


def _assert_chosen_by_their_recorded_diagnoses(fresh, named, recorded, unknown) -> None:
    """Every name recorded with a held-out set and its named part (``today``) has a family in ``recorded`` (not
    ``unknown``); none of the set's was of the true family when it was written, each of the named part's was."""
    for mistake in fresh + named:
        assert all(recorded(n) != unknown for n in mistake.today.split(" or ") if n), mistake.name
    assert [m.name for m in fresh if classify(m.today, m.family, recorded) == "right"] == []
    assert [m.name for m in named if classify(m.today, m.family, recorded) != "right"] == []


# ------------------------------------------------------------------------------------------------- the second set

#: the problems whose answers are simulated (a model run, an ODE solved, an event found)
SIMULATED = (3, 5, 24, 37, 38, 42, 44, 46, 47)

#: the families of the diagnosis names recorded with the second set (``today``), as the table of
#: ``checks/_diagnoses.py`` gave them when the set was written (``None``: a symptom, no cause; ``"?"``: a name the
#: table held no family for); frozen here as ``FALLBACK`` freezes those of the first set
RECORDED2 = {
    "about_origin": "frame", "about_the_joint": "frame", "angle_sign": "sign", "argument_order": "order",
    "com_at_joint": "offset", "constant_answer": None, "degrees": "scale", "energy_drift": "step_size",
    "event_early": "event", "forgot_triangle_inequality": None, "gravity_sign": "sign",
    "ignored_argument": "ignored_argument", "impulse_sign": "sign", "initial_state": "initial_state",
    "integration": "step_size", "load_error": None, "mass_not_small": "scale", "missing_f": "missing_term",
    "missing_gyroscopic": "missing_term", "missing_pd": "missing_term", "missing_torque": "missing_term",
    "no_event": "event", "not_assembled": None, "not_divided": "scale", "not_orthonormal": None,
    "not_terminal": "event", "offset_frame": "frame", "orientation": "transpose", "outer_sign": "sign",
    "positions": "scale", "rate_degrees": "scale", "reflection": "?", "rolling_sign": "sign", "sign_flip": "sign",
    "slope_sign": "sign", "soft_servo": "step_size", "starts_at_rest": "initial_state", "state_row": "state_row",
    "swapped": "order", "transpose": "transpose", "wrong_factor": "scale", "wrong_frame": "frame",
}


def _planted_text(mistake):
    """The reference file with ``mistake`` planted, without whitespace: the same slip written with another context
    or spacing gives the same text."""
    text = (ROOT / "reference" / mistake["file"]).read_text()
    return mistake["file"], "".join(text.replace(mistake["old"], mistake["new"]).split())


def test_the_second_set_covers_every_exercise_roughly_in_proportion_and_every_simulated_problem():
    per_exercise = Counter(m.exercise for m in FRESH2_SET)
    assert set(per_exercise) == set(EXERCISES)
    assert len(FRESH2_SET) >= 60
    graded = {e: sum(1 for p in problems if p not in (23, 29)) for e, problems in EXERCISES.items()}
    for exercise, count in per_exercise.items():
        share = graded[exercise] / sum(graded.values())
        assert 0.5 * share <= count / len(FRESH2_SET) <= 1.5 * share, (exercise, count, per_exercise)
    assert {m.problem for m in FRESH2_SET} >= set(SIMULATED)
    assert sum(1 for m in FRESH2_SET if m.problem in SIMULATED) >= 20


def test_the_second_set_repeats_no_mistake_of_the_first_sets_or_of_the_planted_suite():
    """Each planted text is compared whole, without whitespace, so that a slip written with another context is
    still the same slip; no name is shared with the first sets either."""
    import tomllib

    def texts(mistakes):
        return {_planted_text({"file": m.file, "old": m.old, "new": m.new}) for m in mistakes}

    fresh2, named2 = texts(FRESH2_SET), texts(NAMED2_SET)
    assert not fresh2 & named2
    assert len(fresh2) == len(FRESH2_SET) and len(named2) == len(NAMED2_SET)
    earlier = texts(FRESH_SET + NAMED_SET)
    for path in (ROOT / "tests" / "planted").glob("problem_*.toml"):
        for entry in tomllib.loads(path.read_text()).get("mistake", []):
            if "old" in entry and (ROOT / "reference" / entry["file"]).is_file():
                earlier.add(_planted_text(entry))
    assert not (fresh2 | named2) & earlier
    names = {m.name for m in FRESH_SET + NAMED_SET}
    assert not names & {m.name for m in FRESH2_SET + NAMED2_SET}


def test_the_recorded_diagnoses_of_the_second_set_are_not_the_right_cause_in_it_and_are_in_its_named_part():
    _assert_chosen_by_their_recorded_diagnoses(FRESH2_SET, NAMED2_SET,
                                               lambda name: RECORDED2.get(name, "unrecorded"), "unrecorded")


# ------------------------------------------------------------------------------------------------- the third set

#: the families of the diagnosis names recorded with the third set (``today``), as the table of
#: ``checks/_diagnoses.py`` gave them when the set was written (``None``: a symptom, no cause), frozen as ``RECORDED2``
#: freezes those of the second set
RECORDED3 = {
    "argument_order": "order", "damping_per_degree": "scale", "energy_drift": "step_size", "energy_gain": None,
    "event_direction": "event", "factor_half": "scale", "factor_two": "scale", "float32": "precision",
    "forgot_positive_definite": None, "gravity_sign": "sign", "gyroscopic_sign": "sign", "horizontal": "offset",
    "ignored_argument": "ignored_argument", "initial_state": "initial_state", "jacobian_sign": "sign",
    "mass_per_particle": "scale", "missing_centripetal": "missing_term", "missing_pd": "missing_term",
    "missing_term": "missing_term", "no_actuator": "missing_term", "no_event": "event", "not_orthonormal": None,
    "offset_sign": "sign", "one_third": "scale", "orientation": "transpose", "sign_flip": "sign",
    "state_row": "state_row", "swapped": "order", "torque_sign": "sign", "transpose": "transpose",
    "wrong_axes": "order", "wrong_factor": "scale", "wrong_frame": "frame", "wrong_index": "state_row",
}


def _earlier_entries():
    """Every entry of the earlier sets, their named companions and the planted suite, as dicts."""
    import tomllib

    entries = [{"name": m.name, "file": m.file, "old": m.old, "new": m.new}
               for m in FRESH_SET + NAMED_SET + FRESH2_SET + NAMED2_SET]
    for path in (ROOT / "tests" / "planted").glob("problem_*.toml"):
        entries += [e for e in tomllib.loads(path.read_text()).get("mistake", []) if "old" in e]
    return entries


def test_the_third_set_covers_every_exercise_roughly_in_proportion_and_the_simulated_problems():
    """Problem 5 is left out of the simulated problems: its graded part is the structure of a repaired model, and
    every slip written for it repeated the planted suite or was not caught."""
    _assert_in_proportion(FRESH3_SET, 80)
    assert len({m.family for m in FRESH3_SET}) >= 10


def _assert_in_proportion(mistakes, at_least: int, simulated: int = 20) -> None:
    """At least ``at_least`` mistakes, every exercise within half and one and a half times its share of the graded
    problems, and the simulated problems but 5 all there, with ``simulated`` mistakes or more (twenty unless told)."""
    per_exercise = Counter(m.exercise for m in mistakes)
    assert set(per_exercise) == set(EXERCISES)
    assert len(mistakes) >= at_least
    graded = {e: sum(1 for p in problems if p not in (23, 29)) for e, problems in EXERCISES.items()}
    for exercise, count in per_exercise.items():
        share = graded[exercise] / sum(graded.values())
        assert 0.5 * share <= count / len(mistakes) <= 1.5 * share, (exercise, count, per_exercise)
    assert {m.problem for m in mistakes} >= set(SIMULATED) - {5}
    assert sum(1 for m in mistakes if m.problem in SIMULATED) >= simulated


def test_the_third_set_repeats_no_mistake_of_the_earlier_sets_or_of_the_planted_suite():
    """Neither the same edit, nor the same replaced text in the same file, nor the same planted text (compared
    without whitespace, so that a slip written with another context is still the same slip); no name is shared."""
    _assert_repeats_none(FRESH3_SET + NAMED3_SET, _earlier_entries())


def _assert_repeats_none(mistakes, earlier: list[dict]) -> None:
    """No mistake of ``mistakes`` replaces the text an ``earlier`` entry replaces in the same file, plants the same
    text (without whitespace) or shares its name, and no two of them plant the same text."""
    replaced = {(e["file"], e["old"]) for e in earlier}
    assert [m.name for m in mistakes if (m.file, m.old) in replaced] == []
    planted = {_planted_text(e) for e in earlier if (ROOT / "reference" / e["file"]).is_file()}
    texts = [_planted_text({"file": m.file, "old": m.old, "new": m.new}) for m in mistakes]
    assert [m.name for m, text in zip(mistakes, texts) if text in planted] == []
    assert len(set(texts)) == len(texts)
    assert not {e.get("name") for e in earlier} & {m.name for m in mistakes}


def test_the_recorded_diagnoses_of_the_third_set_are_not_the_right_cause_in_it_and_are_in_its_named_part():
    _assert_chosen_by_their_recorded_diagnoses(FRESH3_SET, NAMED3_SET,
                                               lambda name: RECORDED3.get(name, "unrecorded"), "unrecorded")


# ------------------------------------------------------------------------------------------------- the fourth set


def test_the_fourth_set_covers_every_exercise_roughly_in_proportion_the_simulated_problems_and_many_families():
    """Every realistic mistake whose check fails is kept, whatever its diagnosis, so the families are spread by the
    slips themselves: none of them holds more than a fifth of the set (and a little)."""
    _assert_in_proportion(FRESH4_SET, 90)
    families = Counter(m.family for m in FRESH4_SET)
    assert len(families) >= 12, families
    assert max(families.values()) <= 0.22 * len(FRESH4_SET), families


def test_the_fourth_set_repeats_no_mistake_of_the_earlier_sets_the_engines_tests_or_the_planted_suite():
    """Neither the same edit, nor the same replaced text in the same file, nor the same planted text; the earlier
    entries are those of the three sets, their named companions, the engine's own mistakes (``tests/engine``) and
    the planted suite."""
    import tomllib

    earlier = _earlier_entries() + [{"name": m.name, "file": m.file, "old": m.old, "new": m.new}
                                    for m in FRESH3_SET + NAMED3_SET]
    for path in sorted((ROOT / "tests" / "engine").rglob("*.toml")):
        earlier += [e for e in tomllib.loads(path.read_text()).get("mistake", []) if "old" in e and "file" in e]
    _assert_repeats_none(FRESH4_SET, earlier)


# -------------------------------------------------------------------------- the fifth to thirty-fourth sets

#: the sets written like the fourth (every realistic mistake whose check fails, whatever its diagnosis), each with
#: the sets written before it beyond the first three (whose entries ``_earlier_entries`` reads itself)
_ORDINALS = ("fifth", "sixth", "seventh", "eighth", "ninth", "tenth", "eleventh", "twelfth", "thirteenth", "fourteenth",
             "fifteenth", "sixteenth", "seventeenth", "eighteenth", "nineteenth", "twentieth", "twenty-first",
             "twenty-second", "twenty-third", "twenty-fourth", "twenty-fifth", "twenty-sixth", "twenty-seventh",
             "twenty-eighth", "twenty-ninth", "thirtieth", "thirty-first", "thirty-second", "thirty-third",
             "thirty-fourth")
_WRITTEN = (FRESH5_SET, FRESH6_SET, FRESH7_SET, FRESH8_SET, FRESH9_SET, FRESH10_SET, FRESH11_SET, FRESH12_SET,
            FRESH13_SET, FRESH14_SET, FRESH15_SET, FRESH16_SET, FRESH17_SET, FRESH18_SET, FRESH19_SET, FRESH20_SET,
            FRESH21_SET, FRESH22_SET, FRESH23_SET, FRESH24_SET, FRESH25_SET, FRESH26_SET, FRESH27_SET, FRESH28_SET,
            FRESH29_SET, FRESH30_SET, FRESH31_SET, FRESH32_SET, FRESH33_SET, FRESH34_SET)
LATER_SETS = {ordinal: (written, sum(_WRITTEN[:k], FRESH3_SET + NAMED3_SET + FRESH4_SET))
              for k, (ordinal, written) in enumerate(zip(_ORDINALS, _WRITTEN))}

#: the size of a later set and its mistakes in the simulated problems, at least: ninety and twenty, except the tenth to
#: thirty-fourth sets, written to a smaller size (about fifty entries, at most three of one problem; the twelfth 42, the
#: thirteenth 36, the fourteenth 43, the fifteenth 40, the sixteenth 38, the seventeenth 30, the eighteenth 29, the
#: nineteenth 35, the twentieth 35, the twenty-first 27, the twenty-second 26, the twenty-third 31, the twenty-fourth
#: 26, the twenty-fifth 28, the twenty-sixth 30, the twenty-seventh 33, the twenty-eighth 31, the twenty-ninth 32, the
#: thirtieth 32, the thirty-first 32, the thirty-second 26, the thirty-third 29 and the thirty-fourth 25, at most four
#: of one problem) after the earlier sets had taken most slips of the simulated problems (the seventeenth: 11 of its
#: entries in the problems of ``SIMULATED``, 14 in Exercise I's MuJoCo problems and the runs; the eighteenth: 11 and 16;
#: the nineteenth: 12 and 17; the twentieth: 13 and 17; the twenty-first: 11 and 13; the twenty-second: 10 and 14,
#: counting problem 24's run; the twenty-third: 14 and 17; the twenty-fourth: 12 and 12; the twenty-fifth: 11 and 15;
#: the twenty-sixth: 10 and 16; the twenty-seventh: 11 and 15; the twenty-eighth: 10 and 10, 11 counting problem 24's
#: run; the twenty-ninth: 13 and 13, 15 counting problem 24's; the thirtieth: 13 and 13, 15 counting problem 24's; the
#: thirty-first: 11 in the problems of ``SIMULATED``, one of them in each of problems 24 and 38; the thirty-second: 10
#: in the problems of ``SIMULATED``, every one but problem 5, two of them in each of problems 37 and 47; the
#: thirty-third: 11 in the problems of ``SIMULATED``, every one but problem 5, two of them in each of problems 24, 38
#: and 47; the thirty-fourth: 10 in the problems of ``SIMULATED``, every one but problem 5, two of them in each of
#: problems 38 and 47)
LATER_SIZES = {"tenth": (50, 14), "eleventh": (48, 15), "twelfth": (42, 14), "thirteenth": (36, 13),
               "fourteenth": (43, 15), "fifteenth": (40, 13), "sixteenth": (38, 13),
               "seventeenth": (30, 11), "eighteenth": (29, 11), "nineteenth": (35, 12),
               "twentieth": (35, 13), "twenty-first": (27, 11), "twenty-second": (26, 10),
               "twenty-third": (31, 14), "twenty-fourth": (26, 12),
               "twenty-fifth": (28, 11), "twenty-sixth": (30, 10),
               "twenty-seventh": (33, 11), "twenty-eighth": (31, 10),
               "twenty-ninth": (32, 13), "thirtieth": (32, 13),
               "thirty-first": (32, 11), "thirty-second": (26, 10),
               "thirty-third": (29, 11), "thirty-fourth": (25, 10)}


@pytest.mark.parametrize("which", sorted(LATER_SETS))
def test_a_later_set_covers_every_exercise_roughly_in_proportion_the_simulated_problems_and_many_families(which):
    """Chosen like the fourth set (every realistic mistake whose check fails, whatever its diagnosis), so no family
    holds more than a fifth of the set (and a little)."""
    chosen, _ = LATER_SETS[which]
    _assert_in_proportion(chosen, *LATER_SIZES.get(which, (90, 20)))
    families = Counter(m.family for m in chosen)
    assert len(families) >= 12, families
    assert max(families.values()) <= 0.22 * len(chosen), families


@pytest.mark.parametrize("which", sorted(LATER_SETS))
def test_a_later_set_repeats_no_mistake_of_the_earlier_sets_the_engines_tests_or_the_planted_suite(which):
    """Neither the same edit, nor the same replaced text in the same file, nor the same planted text, nor a name; the
    earlier entries are those of the sets before it, their named companions, the engine's own mistakes
    (``tests/engine``) and the planted suite."""
    import tomllib

    chosen, before = LATER_SETS[which]
    earlier = _earlier_entries() + [{"name": m.name, "file": m.file, "old": m.old, "new": m.new} for m in before]
    for path in sorted((ROOT / "tests" / "engine").rglob("*.toml")):
        earlier += [e for e in tomllib.loads(path.read_text()).get("mistake", []) if "old" in e and "file" in e]
    _assert_repeats_none(chosen, earlier)


# ------------------------------------------------------------------------------------------------- classification

TABLE = {"transpose": "transpose", "sign_flip": "sign", "gyroscopic_sign": "sign", "rotation_order": "order",
         "degrees": "scale", "integration": "step_size", "wrong_frame": "frame", "shape": None}


def test_a_diagnosis_of_the_true_family_alone_or_beside_one_other_is_right():
    family_of = TABLE.get
    assert classify("transpose", "transpose", family_of) == "right"
    assert classify("transpose or rotation_order", "order", family_of) == "right"
    # two names of one family count as one candidate
    assert classify("sign_flip or gyroscopic_sign or degrees", "sign", family_of) == "right"


def test_the_lenient_reading_counts_the_second_family_as_the_true_one():
    """A slip as truly of two families (``also``): the strict reading is right only for its ``family``; the lenient
    one for either, and wrong only when the told families include neither."""
    family_of = TABLE.get
    # told the family: right both ways
    assert classify("sign_flip", "sign", family_of) == "right"
    assert classify("sign_flip", "sign", family_of, also="transpose") == "right"
    # told the second family: none of the true family strictly (a wrong cause), right leniently
    assert classify("transpose", "sign", family_of) == "wrong"
    assert classify("transpose", "sign", family_of, also="transpose") == "right"
    assert classify("transpose or degrees", "sign", family_of, also="transpose") == "right"
    # told neither: wrong both ways; nothing: none both ways
    assert classify("integration", "sign", family_of) == "wrong"
    assert classify("integration", "sign", family_of, also="transpose") == "wrong"
    assert classify("", "sign", family_of, also="transpose") == "none"
    # either true family among more than two candidates: none
    assert classify("transpose or integration or degrees", "sign", family_of, also="transpose") == "none"


@pytest.mark.parametrize("which", ["first", "second", "third", "fourth", "fifth", "sixth"])
def test_a_set_without_a_second_family_reads_alike_strictly_and_leniently(which):
    """The earlier sets name no ``also``: every recorded diagnosis of theirs, and every made-up one, is classified
    leniently exactly as strictly, and the graded mistake's lenient verdict is its strict one."""
    from .score import Graded

    chosen = {"first": FRESH_SET + NAMED_SET, "second": FRESH2_SET + NAMED2_SET, "third": FRESH3_SET + NAMED3_SET,
              "fourth": FRESH4_SET, "fifth": FRESH5_SET, "sixth": FRESH6_SET}[which]
    family_of = naming().family_of
    assert all(m.also == "" for m in chosen)
    for mistake in chosen:
        for told in (mistake.today, "transpose", "sign_flip or degrees", ""):
            assert classify(told, mistake.family, family_of, mistake.also) == classify(told, mistake.family,
                                                                                     family_of), mistake.name
    g = Graded(chosen[0], "failed", "transpose", "", classify("transpose", chosen[0].family, family_of), ())
    assert g.lenient_verdict == g.verdict


@pytest.mark.parametrize("which", ["seventh", "eighth", "ninth", "tenth", "eleventh", "twelfth", "thirteenth",
                                   "fourteenth", "fifteenth", "sixteenth", "seventeenth", "eighteenth",
                                   "nineteenth", "twentieth", "twenty-first", "twenty-second", "twenty-third",
                                   "twenty-fourth", "twenty-fifth", "twenty-sixth", "twenty-seventh",
                                   "twenty-eighth", "twenty-ninth", "thirtieth", "thirty-first",
                                   "thirty-second", "thirty-third", "thirty-fourth"])
def test_a_set_with_second_families_reads_them_leniently_only(which):
    """The sets that name a second family (``also``) on some entries: an entry without one is classified alike
    strictly and leniently, whatever is told; an entry with one is right leniently and wrong strictly when only its
    second family is told, and right both ways when its family is."""
    chosen = {"seventh": FRESH7_SET, "eighth": FRESH8_SET, "ninth": FRESH9_SET, "tenth": FRESH10_SET,
              "eleventh": FRESH11_SET, "twelfth": FRESH12_SET, "thirteenth": FRESH13_SET,
              "fourteenth": FRESH14_SET, "fifteenth": FRESH15_SET, "sixteenth": FRESH16_SET,
              "seventeenth": FRESH17_SET, "eighteenth": FRESH18_SET, "nineteenth": FRESH19_SET,
              "twentieth": FRESH20_SET, "twenty-first": FRESH21_SET, "twenty-second": FRESH22_SET,
              "twenty-third": FRESH23_SET, "twenty-fourth": FRESH24_SET,
              "twenty-fifth": FRESH25_SET, "twenty-sixth": FRESH26_SET,
              "twenty-seventh": FRESH27_SET, "twenty-eighth": FRESH28_SET,
              "twenty-ninth": FRESH29_SET, "thirtieth": FRESH30_SET,
              "thirty-first": FRESH31_SET, "thirty-second": FRESH32_SET,
              "thirty-third": FRESH33_SET, "thirty-fourth": FRESH34_SET}[which]
    named = {}
    for name, family in FALLBACK.items():
        named.setdefault(family, name)
    with_also = [m for m in chosen if m.also]
    assert with_also, which
    for mistake in chosen:
        if not mistake.also:
            for told in (mistake.today, "transpose", "sign_flip or degrees", ""):
                assert classify(told, mistake.family, _fallback, mistake.also) == classify(told, mistake.family,
                                                                                         _fallback), mistake.name
    for mistake in with_also:
        second, first = named[mistake.also], named[mistake.family]
        assert classify(second, mistake.family, _fallback) == "wrong", mistake.name
        assert classify(second, mistake.family, _fallback, mistake.also) == "right", mistake.name
        assert classify(first, mistake.family, _fallback, mistake.also) == "right", mistake.name


def test_the_report_gives_both_readings_and_tells_them_apart_where_a_mistake_has_a_second_family():
    """The summary's totals, targets and per-mistake lines carry the strict and the lenient class."""
    import dataclasses

    from .score import Graded, Naming, summary

    family_of = TABLE.get
    base = fresh_mistakes(FRESH6)[0]
    mistakes = [dataclasses.replace(base, name=f"m{k}", family="sign", also=also) for k, also in
                enumerate(("transpose", "", "transpose"))]
    told = ("transpose", "transpose", "sign_flip")
    graded = [Graded(m, "failed", d, "", classify(d, m.family, family_of), (),
                     lenient=classify(d, m.family, family_of, m.also)) for m, d in zip(mistakes, told)]
    assert [g.verdict for g in graded] == ["wrong", "wrong", "right"]
    assert [g.lenient_verdict for g in graded] == ["right", "wrong", "right"]
    text = summary(graded, Naming(family_of, "a table of the test"), verbose=True, which="fresh7")
    assert "lenient reading (right also when the told family is the entry's second family, also; 2 entries" in text
    assert "target (issue 27: right >= 60%, wrong <= 2%): not met (right 33%, wrong 67%;" in text
    assert "lenient target (issue 27: right >= 60%, wrong <= 2%): not met (right 67%, wrong 33%;" in text
    assert "  wrong      right      m0 [" in text and "true: sign (also transpose)" in text


def test_a_diagnosis_of_other_families_only_is_wrong_and_one_of_no_cause_is_none():
    family_of = TABLE.get
    assert classify("integration", "state_row", family_of) == "wrong"
    assert classify("transpose or degrees", "sign", family_of) == "wrong"
    assert classify("", "sign", family_of) == "none"
    assert classify("shape", "sign", family_of) == "none"  # a symptom, no cause
    # the true family among more than two candidates tells the student nothing they can act on
    assert classify("transpose or sign_flip or degrees", "sign", family_of) == "none"


def test_a_name_of_unknown_family_counts_against_the_diagnosis():
    def family_of(name):
        return TABLE.get(name, "?")

    assert candidate_families("made_up or transpose", family_of) == (["transpose"], ["made_up"])
    assert classify("made_up", "sign", family_of) == "wrong"
    assert classify("made_up or sign_flip", "sign", family_of) == "right"
    assert classify("made_up or degrees or sign_flip", "sign", family_of) == "none"


def test_the_engines_table_is_preferred_when_checks_diagnoses_provides_one(monkeypatch):
    engine = types.ModuleType("checks._diagnoses")
    labels = {"looks_like_a_row": "state row", "step_too_large": "integration", "sign_of_a_term": "sign",
              "mystery": "weather"}
    engine.family_of = labels.__getitem__
    monkeypatch.setitem(sys.modules, "checks._diagnoses", engine)
    chosen = naming()
    assert "checks/_diagnoses.py" in chosen.source
    assert chosen.family_of("looks_like_a_row") == "state_row"
    assert chosen.family_of("step_too_large") == "step_size"
    assert chosen.family_of("mystery") == "?"  # a family the measure does not know
    assert chosen.family_of("transpose") == "transpose"  # a name the table lacks: the fallback
    assert "fallback" in naming(prefer_engine=False).source


def test_a_table_of_entries_with_families_is_read_too(monkeypatch):
    engine = types.ModuleType("checks._diagnoses")
    engine.DIAGNOSES = {"gyroscopic_missing": types.SimpleNamespace(family="missing term", phrase="...")}
    monkeypatch.setitem(sys.modules, "checks._diagnoses", engine)
    assert naming().family_of("gyroscopic_missing") == "missing_term"


# ------------------------------------------------------------------------------------------------- the script


@pytest.mark.slow
def test_the_script_grades_and_classifies_a_subset(tmp_path):
    """The script runs as a user runs it, on the first mistake of each exercise, and classifies every one of them
    as right, wrong, none or not caught.  Its figures are not asserted: the target of issue 27 is reported until
    the diagnosis engine lands."""
    out = tmp_path / "graded.json"
    run = subprocess.run([sys.executable, str(ROOT / "tests" / "diagnosis" / "score.py"), "--per-exercise", "1",
                          "--json", str(out)], cwd=ROOT, capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stderr[-2000:]
    assert "diagnosis of the fresh set: 7 mistakes" in run.stdout
    assert "target (issue 27: right >= 60%, wrong <= 2%)" in run.stdout
    rows = json.loads(out.read_text())["mistakes"]
    assert sorted(r["exercise"] for r in rows) == sorted(EXERCISES)
    firsts = {}
    for mistake in FRESH_SET:
        firsts.setdefault(mistake.exercise, mistake)
    assert {r["name"] for r in rows} == {m.name for m in firsts.values()}
    for row in rows:
        assert row["verdict"] in ("right", "wrong", "none", "not caught")
        family_of = naming().family_of
        if row["status"] == "failed":
            assert row["verdict"] == classify(row["diagnosis"], row["family"], family_of)
    for exercise in EXERCISES:
        assert any(line.lstrip().startswith(exercise + " ") for line in run.stdout.splitlines())


@pytest.mark.slow
def test_the_unlisted_measure_leaves_out_a_mistake_that_a_check_names_without_the_engine():
    """``--unlisted`` grades each mistake with the engine off and on: a planted mistake of problem 8 that its
    check's catalogue names (a body-frame Euler step) is listed and left out of the measure; the engine's own
    development mistake of the same problem (the rate matrix inverted), which no catalogue names, is not, and is
    read with the engine on."""
    from .score import Fresh, grade_all, summary

    planted = Fresh("p08-euler-body-frame", 8, "problem_08.py", "return A_IC + dt * skew(I_omega) @ A_IC",
                    "return A_IC + dt * A_IC @ skew(I_omega)", "p08.euler_step", "frame", "a body-frame step")
    engine = Fresh("engine-inverse-rate-matrix", 8, "rotations.py",
                   "return np.array([[1.0, 0.0, -sb], [0.0, ca, cb * sa], [0.0, -sa, ca * cb]])",
                   "return np.linalg.inv(np.array([[1.0, 0.0, -sb], [0.0, ca, cb * sa], [0.0, -sa, ca * cb]]))",
                   "p08.rate_matrix", "inverse", "the rate matrix inverted")
    naming_ = naming()
    graded = {g.mistake.name: g for g in grade_all([planted, engine], naming_.family_of, unlisted=True)}
    assert graded["p08-euler-body-frame"].listed is True
    assert graded["engine-inverse-rate-matrix"].listed is False
    assert graded["engine-inverse-rate-matrix"].verdict == "right", graded["engine-inverse-rate-matrix"].diagnosis
    text = summary(list(graded.values()), naming_, which="pool")
    assert "listed (named rightly with the diagnosis engine off): 1; the issue's measure is read on the other 1" in text
    assert "right 100%, wrong 0%; mistakes that no check names rightly without the engine" in text
    plain = grade_all([engine], naming_.family_of)
    assert plain[0].listed is None and "listed (named" not in summary(plain, naming_, which="pool")


def test_a_name_that_states_a_symptom_of_several_families_names_no_cause():
    """A reflection (one axis reversed, or two exchanged), a body in the wrong orientation and a run that diverges
    say what the answer shows, which slips of several families show alike: told, they name no cause, neither the
    sign, transpose or step they were once read as, nor a wrong one."""
    family_of = naming().family_of
    for name, true in (("reflection", "sign"), ("reflection", "order"), ("orientation", "transpose"),
                       ("orientation", "order"), ("diverged", "step_size"), ("diverged", "extra_term")):
        assert family_of(name) is None, name
        assert classify(name, true, family_of) == "none", (name, true)
    assert classify("reflection or transpose", "transpose", family_of) == "right"


def test_a_verdict_on_an_answer_that_does_nothing_names_no_cause():
    """An answer that does nothing (zeros or one constant, the identity, nothing returned, credit resting on such
    results) may come from a slip of any family (a body started at rest, an argument or a term never used): told,
    its verdict names no cause, neither a wrong one nor one of unknown family."""
    family_of = naming().family_of
    for name in ("degenerate", "degenerate_input", "constant_answer", "always_zero", "identity", "none"):
        assert family_of(name) is None, name
        assert classify(name, "initial_state", family_of) == "none", name
    assert classify("degenerate or initial_state", "initial_state", family_of) == "right"
