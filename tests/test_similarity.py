"""``grade similarity`` (issue 30): a batch records the students' wrong answers on the inputs every student is
asked, and the report ranks pairs of students by the wrong answers and diagnosed mistakes they share and by the
similarity of their own code.

The class: honest students, each the reference with one planted mistake or one correct variant of
``tests/planted/`` (every one different), and two planted collusions: a copy of one student's work with renamed
names and reordered methods, and two students who give the same unusual wrong answer (one that no catalogue names)
from code written differently.  Both planted pairs must rank above every honest pair."""

from __future__ import annotations

import ast
import csv
import html
import re
import shutil
from itertools import combinations
from pathlib import Path

import numpy as np
import pytest

from grader.answers import Answer, value_digest, wrong_answer
from grader.results import CheckResult, ProblemReport, Status, student_view

from .submissions import (Planted, build_planted, build_variant, copy_reference, correct_variants, plant,
                          planted_mistakes)

# ---------------------------------------------------------------------------------------------- the records


def test_a_value_digest_ignores_round_off_and_tells_values_apart():
    A = np.array([[0.1, -0.2, 0.3], [1e-17, 2.0, 1 / 3]])
    assert value_digest(A) == value_digest(A * (1 + 1e-13))  # the same computation in another order
    assert value_digest(A) == value_digest(A + np.array([[0, 0, 0], [-1e-17, 0, 0]]))  # round-off around zero
    assert value_digest(A) != value_digest(A * (1 + 1e-6))
    assert value_digest(A) != value_digest(A.T)  # the shape counts
    assert value_digest({"a": A, "b": 1.0}) != value_digest({"a": A, "c": 1.0})


def test_a_wrong_answer_is_recorded_only_where_it_differs_from_the_reference():
    expected = np.eye(3)
    assert wrong_answer("p06.x", "problem_06.elementary", (1, 0.0), expected + 1e-12, expected) is None
    found = wrong_answer("p06.x", "problem_06.elementary", (1, 0.3), -expected, expected)
    assert isinstance(found, Answer) and found.call == "problem_06.elementary(1, 0.3)"
    assert found.value_key == value_digest(-expected) and "-1." in found.value and "1." in found.expected
    assert wrong_answer("p06.x", "p.f", (), {"a": 1.0}, {"a": 1.0, "b": 2.0}) is not None  # a missing key


def test_recorded_answers_never_reach_a_student():
    answer = Answer("p06.x", "problem_06.elementary(1, 0.3)", "k", "v", "[[1, 0, 0], ...]", "[[1, 0, 0], ...]")
    report = ProblemReport(6, "t", (CheckResult("p06.x", 6, "x", Status.FAILED, 0, 1),), wrong_answers=(answer,))
    assert "wrong_answers" not in report.to_dict()
    assert student_view(report).wrong_answers == ()


# ---------------------------------------------------------------------------------------------- the class

PROBLEMS = [12, 16, 17]
#: the student whose work is copied, and her mistake
ALICE = "p12-velocity-offset-not-rotated"
#: problems whose correct variants make up the rest of her own way of writing (no honest student here has them)
ALICE_STYLE = (37, 42, 43)
#: the copier's folder: a name a spreadsheet would take for a formula, with markup in it
CARL = "=carl<script>"
#: the unusual wrong answer (1/10 where 1/12 belongs: no catalogue names it), written two ways
CUBOID = "return m / 12 * np.diag([b**2 + c**2, a**2 + c**2, a**2 + b**2])"
DORA = "return m / 10 * np.diag([b**2 + c**2, a**2 + c**2, a**2 + b**2])"
EMIL = "return np.diag([b * b + c * c, a * a + c * c, a * a + b * b]) * (0.1 * m)"
#: a comment of the copier's that must be shown as text
HOSTILE_COMMENT = '# </pre><script>alert("copied")</script>'


#: two slips of problem 12 that give the very same wrong numbers on the wheel's drawn case (omega x r left out of the
#: position's step, omega x v of the velocity's): two students who made one each share a wrong answer that the
#: grader's evidence cannot tell from a copied one (the report is evidence for a person, never a verdict), so the
#: class of students who share nothing keeps only the first
ALIKE = ("p12-missing-omega-x-v",)


def _honest() -> list[tuple[str, object]]:
    """The honest students: planted mistakes and correct variants of the graded problems, each different, and no two
    with the same wrong numbers (``ALIKE``)."""
    chosen = []
    for number, count in ((12, 9), (16, 5), (17, 5)):
        mistakes = [m for m in planted_mistakes(number) if m.name != ALICE and m.name not in ALIKE][:count]
        chosen += [(m.name, m) for m in mistakes]
    for number in (12, 17):
        chosen += [(v["name"], v) for v in correct_variants(number)[:1]]
    return chosen


def renamed_and_reordered(text: str, names: dict[str, str]) -> str:
    """A copy's disguise: each name of ``names`` renamed (whole words) and the methods of every class, and the
    module's functions, in reverse order."""
    lines = text.splitlines()
    tree = ast.parse(text)
    blocks = []  # (start, end) of runs of definitions to reverse, innermost first
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef)):
            defs = [n for n in node.body if isinstance(n, ast.FunctionDef)]
            if len(defs) > 1:
                blocks.append([(min([d.lineno] + [x.lineno for x in d.decorator_list]) - 1, d.end_lineno)
                               for d in defs])
    for spans in sorted(blocks, key=lambda s: -s[0][0]):
        first, last = spans[0][0], spans[-1][1]
        between = [line for a, b in zip(spans, spans[1:]) for line in lines[a[1]:b[0]]]
        if any(line.strip() for line in between):  # something other than blank lines between: leave it
            continue
        parts = ["\n".join(lines[a:b]) for a, b in reversed(spans)]
        lines[first:last] = "\n\n".join(parts).splitlines()
    out = "\n".join(lines) + "\n"
    for old, new in names.items():
        out = re.sub(rf"\b{re.escape(old)}\b", new, out)
    return out


@pytest.fixture(scope="module")
def klass(tmp_path_factory):
    """The class's submissions folder, graded by ``grade batch`` on the problems, and ``grade similarity`` run."""
    from grader.batch import run_batch
    from grader.cli import main

    base = tmp_path_factory.mktemp("similarity")
    folder = base / "submissions"
    folder.mkdir()
    honest = _honest()
    for name, entry in honest:
        if isinstance(entry, dict):
            build_variant(entry, folder / name)
        else:
            build_planted(entry, folder / name)
    alice = next(m for m in planted_mistakes(12) if m.name == ALICE)
    build_planted(alice, folder / "alice")
    # her own way of writing a few other functions (correct variants of problems no honest student here uses)
    style = [Planted(v["name"], v["problem"], v["file"], v["old"], v["new"], "")
             for number in ALICE_STYLE for v in correct_variants(number)[:2]]
    assert sum(plant(variant, folder / "alice", strict=False) for variant in style) >= 3
    carl = shutil.copytree(folder / "alice", folder / CARL)
    module = carl / alice.file
    text = module.read_text().replace(alice.new, f"{HOSTILE_COMMENT}\n        {alice.new}")
    module.write_text(renamed_and_reordered(text, {"B_r_BQ": "q_offset", "B_Om": "Wb", "I_Om": "Wi", "Om": "W"}))
    for name, line in (("dora", DORA), ("emil", EMIL)):
        target = copy_reference(folder / name) / "inertia.py"
        text = target.read_text()
        assert text.count(CUBOID) == 1
        target.write_text(text.replace(CUBOID, line))
    out = base / "results"
    report = run_batch(folder, out, problems=PROBLEMS, jobs=2, progress=False)
    assert report.graded == len(honest) + 4 and not report.not_graded
    grades = (out / "grades.csv").read_bytes()
    assert main(["similarity", str(out)]) == 0
    return {"out": out, "honest": [name for name, _ in honest], "grades": grades, "folder": folder}


def _pairs(out: Path) -> list[dict]:
    with open(out / "similarity.csv", encoding="utf-8", newline="") as handle:
        return list(csv.DictReader(handle))


def _pair(row: dict) -> frozenset:
    from grader.batch.gradebook import spreadsheet_text

    return frozenset((spreadsheet_text(row["student"]), spreadsheet_text(row["other student"])))


@pytest.mark.slow
def test_both_planted_pairs_rank_above_every_honest_pair(klass):
    from grader.batch.gradebook import Gradebook

    students = klass["honest"] + ["alice", CARL, "dora", "emil"]
    with Gradebook.in_folder(klass["out"]) as book:
        rows = book.submitted()
        hashes = {student: digest for student, _, _, digest, _ in rows}
        scores = {}
        for g in book.current(figures=False):
            scores.setdefault(g.student, {})[g.report.problem] = g.report.score
    assert sorted(hashes) == sorted(students) and len(students) >= 22
    assert len(set(hashes.values())) == len(students)  # every submission different
    # the copy is graded as its original is: the same mistake, the same scores
    assert scores[CARL] == scores["alice"] and scores["dora"] == scores["emil"]
    assert scores["alice"][12] < scores[klass["honest"][-1]][12]  # a correct variant's full marks
    ranked = [_pair(row) for row in _pairs(klass["out"])]
    planted_pairs = {frozenset(("alice", CARL)), frozenset(("dora", "emil"))}
    positions = {pair: ranked.index(pair) for pair in planted_pairs}
    honest = [pair for pair in ranked if pair not in planted_pairs]
    assert sorted(positions.values()) == [0, 1], (positions, ranked[:5])
    assert len(ranked) <= len(list(combinations(students, 2)))
    rows = {_pair(row): row for row in _pairs(klass["out"])}
    copy, unusual = rows[frozenset(("alice", CARL))], rows[frozenset(("dora", "emil"))]
    assert float(copy["tokens"]) >= 0.8  # renamed and reordered, the code is still theirs
    assert float(unusual["tokens"]) == 0  # no code in common beyond the template and the reference
    assert int(unusual["shared wrong answers"]) >= 1 and "p16.cuboid" in unusual["checks"]
    best_honest = max((float(rows[pair]["score"]) for pair in honest), default=0.0)
    assert float(unusual["score"]) > best_honest and float(copy["score"]) > best_honest


@pytest.mark.slow
def test_the_report_shows_evidence_for_a_person_and_changes_no_grade(klass):
    out = klass["out"]
    assert (out / "grades.csv").read_bytes() == klass["grades"]  # no score changed
    page = (out / "similarity.html").read_text()
    assert "Evidence for a person to read, never a verdict." in page
    assert "Nothing in this report\nchanges a score." in page
    # the unusual pair's shared wrong answer: the call, their value and the reference's
    section = page[page.index("dora and emil"):]
    section = section[:section.index("<h2", 10)] if "<h2" in section[10:] else section
    assert "p16.cuboid" in section and "wrong answer: " in section
    assert "cuboid" in section and "m / 10" in section and "(0.1 * m)" in section  # their code side by side
    # the copy: their code side by side, the shared passages marked; the student's text is inert
    assert "<mark>" in page
    assert "<script>" not in page and html.escape(CARL) in page
    assert html.escape(HOSTILE_COMMENT) in page or "&lt;/pre&gt;&lt;script&gt;" in page
    # the CSV: every cell a spreadsheet shows as text
    raw = (out / "similarity.csv").read_text()
    assert "'=carl<script>" in raw and "\n=carl" not in raw and ",=carl" not in raw


@pytest.mark.slow
def test_the_batch_records_wrong_answers_only_where_a_check_failed(klass):
    from grader.batch.gradebook import Gradebook

    with Gradebook.in_folder(klass["out"]) as book:
        answers = book.wrong_answers()
        failed = {(g.student, r.check_id) for g in book.current(figures=False) for r in g.report.results
                  if not r.passed}
    assert answers
    for student, problem, answer in answers:
        assert (student, answer.check_id) in failed
        assert answer.check_id.startswith(f"p{problem:02d}.")
    correct = {v["name"] for v in correct_variants()}
    assert not [a for a in answers if a[0] in correct]  # a correct variant gives no wrong answer
    dora = {a.check_id: a for s, _, a in answers if s == "dora"}
    emil = {a.check_id: a for s, _, a in answers if s == "emil"}
    assert dora["p16.cuboid"].value_key == emil["p16.cuboid"].value_key
    assert dora["p16.cuboid"].call_key == emil["p16.cuboid"].call_key


def test_grade_similarity_needs_a_gradebook(tmp_path, capsys):
    from grader.cli import main

    assert main(["similarity", str(tmp_path)]) == 2
    assert "holds no gradebook" in capsys.readouterr().err


# ---------------------------------------------------------------------------------------------- a small gradebook


def _record(book, run: int, student: str, source: Path, digest: str, answers=(), diagnosis: str = "") -> None:
    status = Status.FAILED if answers or diagnosis else Status.PASSED
    result = CheckResult("p06.frames", 6, "the frames", status, 0.0 if answers else 1.0, 1.0, diagnosis=diagnosis)
    report = ProblemReport(6, "Euler angles", (result,), seed=1, submission=str(source), wrong_answers=tuple(answers))
    book.record(student, digest, {6: "v"}, run, [report])


def test_code_that_cannot_be_read_or_is_huge_is_named_and_the_rest_compared(tmp_path, monkeypatch):
    from grader.batch.gradebook import Gradebook
    from grader.loader import submission_digest
    from grader.similarity import write_similarity

    MAX_CODE = 2_000
    monkeypatch.setattr("grader.similarity.MAX_CODE", MAX_CODE)
    folder = tmp_path / "submissions"
    shared = Answer("p06.frames", "problem_06.frames()", "call", "value", "[[1, 2]]", "[[1, 0]]")
    students = {}
    for name in ("ann", "ben", "cat"):
        students[name] = copy_reference(folder / name)
    (students["cat"] / "problem_06.py").write_text("".join(f"x{i} = {i}\n" for i in range(MAX_CODE)))  # too much
    link = folder / "dan"
    link.symlink_to(students["ann"])
    with Gradebook.in_folder(tmp_path / "results") as book:
        run = book.start_run(str(folder), [6], 1)
        for name, source in students.items():
            _record(book, run, name, source, submission_digest(source), [shared] if name != "cat" else [])
        _record(book, run, "dan", link, "whatever", [shared])
    found = write_similarity(tmp_path / "results", jobs=1)
    notes = "\n".join(found.notes)
    assert "dan: code not compared" in notes and "symbolic link" in notes
    assert f"cat: only the first {MAX_CODE:,} characters" in notes
    assert found.with_code == 3
    pairs = {frozenset((p.first, p.second)): p for p in found.pairs}
    # the wrong answer that ann, ben and dan alone give (of 4 graded): ln(4/3) each
    assert pairs[frozenset(("ann", "ben"))].answers == pytest.approx(np.log(4 / 3))
    assert pairs[frozenset(("ann", "dan"))].tokens == 0  # dan's code was not read
    page = (tmp_path / "results" / "similarity.html").read_text()
    assert "dan: code not compared" in page


def test_recording_changes_no_verdict_and_a_correct_submission_records_nothing(tmp_path):
    """The batch's recording (``record_answers``) on the same seed: the same verdicts and messages as without it; a
    planted mistake found only by a randomized comparison is recorded on the input every student is asked there,
    and the reference records nothing."""
    from grader.runner import grade_submission

    mistake = next(m for m in planted_mistakes(6) if m.name == "p06-R3-transpose")
    planted = build_planted(mistake, tmp_path / "planted")
    reference = copy_reference(tmp_path / "reference")
    for folder in (planted, reference):
        plain, = grade_submission(folder, [6], seed=11)
        recorded, = grade_submission(folder, [6], seed=11, record_answers=True)
        assert [(r.check_id, r.status, r.score, r.message, r.diagnosis) for r in plain.results] == \
            [(r.check_id, r.status, r.score, r.message, r.diagnosis) for r in recorded.results]
        assert plain.wrong_answers == ()
    assert recorded.wrong_answers == ()  # the reference
    again, = grade_submission(planted, [6], seed=12, record_answers=True)
    first, = grade_submission(planted, [6], seed=11, record_answers=True)
    (answer,) = first.wrong_answers
    assert answer.check_id == mistake.check and answer.call.startswith("problem_06.elementary(3, ")
    assert again.wrong_answers == first.wrong_answers  # the same input whatever the student's own seed
