"""Notebooks as submissions: a self-contained ``problem_06.ipynb``, ``Problem 6.ipynb`` beside a module it imports
the Jupyter way, a whole exercise in one notebook written as students write them, and a batch entry
``frank.ipynb`` each grade like the equivalent folder (the reference and planted mistakes, with the same seed);
the report says which name went where and which required names are missing; the notebook's code runs only in
the sandboxed worker."""

import json

import pytest

from grader.batch import run_batch
from grader.cli import main
from grader.gradebook import Gradebook
from grader.loader import cleanup, materialize
from grader.runner import grade_submission
from grader.workers import Fresh
from grader.sandbox import Limits, sandbox_mode

from .notebooks import (
    definition,
    exercise_notebook,
    jupyter_problem_06,
    problem_06_cells,
    self_contained_problem_06,
    write_notebook,
)
from .submissions import ROOT, build_planted, copy_reference, planted_mistakes

LIMITS = Limits(call_timeout=5.0, import_timeout=15.0)
MISTAKES = {m.name: m for m in planted_mistakes(6)}
#: a mistake in a module the notebooks hold (rotations), and one in the problem's own module
VARIANTS = [None, "p06-cardan-rotation-order", "p06-vectors-transpose"]


def outcome(reports):
    """What must agree between a notebook and its folder: every check's status, score and diagnosis."""
    return [(r.check_id, r.status.value, r.score, r.diagnosis) for rep in reports for r in rep.results]


def folder_of(variant, dest):
    return copy_reference(dest) if variant is None else build_planted(MISTAKES[variant], dest)


FORMS = {
    "problem_06.ipynb": (lambda folder, tmp: self_contained_problem_06(folder, tmp / "problem_06.ipynb"), [6]),
    "Problem 6.ipynb": (lambda folder, tmp: jupyter_problem_06(folder, tmp / "work"), [6]),
    "exercise2.ipynb": (lambda folder, tmp: exercise_notebook(folder, tmp / "exercise2.ipynb"), [6, 9]),
}


@pytest.mark.parametrize("variant", VARIANTS, ids=lambda v: v or "reference")
@pytest.mark.parametrize("form", list(FORMS))
def test_a_notebook_grades_like_the_equivalent_folder(form, variant, tmp_path):
    folder = folder_of(variant, tmp_path / "folder")
    build, problems = FORMS[form]
    notebook = build(folder, tmp_path)
    expected = grade_submission(folder, problems, seed=11, workers=Fresh(LIMITS))
    got = grade_submission(notebook, problems, seed=11, workers=Fresh(LIMITS))
    assert outcome(got) == outcome(expected)
    assert not any(rep.load_error for rep in got)
    if variant is None:
        assert all(rep.score == rep.auto_max_score for rep in got)
    else:
        assert got[0].score < got[0].auto_max_score
    notes = got[0].notes
    name = form if form != "Problem 6.ipynb" else "Problem 6.ipynb"
    assert f"notebook {name} → problem_06.py: ALPHA, BETA, C3_V, GAMMA, frames, vectors" in notes, notes
    if form != "Problem 6.ipynb":  # there rotations.py is a file of the folder
        assert f"notebook {name} → rotations.py: R1, R2, R3, cardan" in notes, notes


def test_the_whole_exercise_notebook_says_what_it_left_out(tmp_path):
    notebook = exercise_notebook(ROOT / "reference", tmp_path / "exercise2.ipynb")
    report = grade_submission(notebook, [6], seed=2, workers=Fresh(LIMITS))[0]
    notes = "\n".join(report.notes)
    assert "notebook exercise2.ipynb → cosys.py: CoSys" in notes
    # the cell that raises, named by its number and first line
    assert ("cell 12 “broken = frames()['A_IC4']  # a cell that raises KeyError”, line 1 (broken) raised KeyError: "
            "'A_IC4'; it was skipped") in notes
    assert "IPython lines (magics, shell commands) left out" in notes
    assert "A_test" in notes and "A_test) raised" not in notes  # out of order: run again once cardan existed
    assert "[[" not in report.stdout  # prints are not definitions: never run


def test_a_missing_name_is_said_with_the_names_found(tmp_path):
    cells = problem_06_cells(ROOT / "reference")
    cells = [c.replace("def frames():", "def Frames():").replace("A = frames()", "A = Frames()") for c in cells]
    notebook = write_notebook(tmp_path / "problem_06.ipynb", ["import numpy as np", *cells])
    report = grade_submission(notebook, [6], seed=2, workers=Fresh(LIMITS))[0]
    (missing,) = [n for n in report.notes if n.startswith("problem 6 needs")]
    assert "frames (problem_06), which none of your notebooks or files defines" in missing
    assert "your notebooks define: R1, R2, R3, cardan, GAMMA, BETA, ALPHA, C3_V, Frames, vectors" in missing
    assert report.score < report.auto_max_score


def test_the_loader_never_runs_a_notebook(tmp_path):
    marker = tmp_path / "ran"
    notebook = write_notebook(tmp_path / "problem_06.ipynb", [f"ran = open({str(marker)!r}, 'w').write('x')",
                                                              "def frames():\n    return 1"])
    loaded = materialize(notebook, tmp_path)
    try:
        manifest = json.loads((loaded.path / "_notebooks.json").read_text())
        assert manifest["notebooks"][0]["placed"] == {"frames": ["problem_06"]}
        assert not marker.exists()
    finally:
        cleanup(loaded)


def test_a_name_of_several_problems_goes_to_the_section_it_is_written_in(tmp_path):
    notebook = write_notebook(tmp_path / "exercise.ipynb", [
        ("md", "## Problem 6"), "def vectors():\n    return 6",
        ("md", "## Problem 11"), "def solve():\n    return 11",
    ])
    loaded = materialize(notebook, tmp_path)
    try:
        placed = loaded.notebooks[0].placed
        assert placed == {"vectors": ("problem_06",), "solve": ("problem_11",)}
    finally:
        cleanup(loaded)


def test_grade_init_notebook_gives_the_template_as_notebooks(tmp_path, capsys):
    work = tmp_path / "mywork"
    assert main(["init", str(work), "--notebook"]) == 0
    notebook = work / "problem_06.ipynb"
    assert notebook.exists() and (work / "answers.toml").exists()
    report = grade_submission(work, [6], seed=1, workers=Fresh(LIMITS))[0]
    assert not report.load_error and report.score == 0
    assert all(r.status.value == "not_implemented" for r in report.results if r.status.value != "skipped")
    # filled in with the reference's definitions, the notebook earns full marks
    import nbformat

    book = nbformat.read(notebook, as_version=4)
    for cell in book.cells:
        if cell.cell_type == "code" and cell.source.lstrip().startswith("def "):
            name = cell.source.split("def ", 1)[1].split("(", 1)[0]
            module = "rotations" if name in ("R1", "R2", "R3", "cardan") else "problem_06"
            cell.source = definition(ROOT / "reference", module, name)
    nbformat.write(book, notebook)
    report = grade_submission(work, [6], seed=1, workers=Fresh(LIMITS))[0]
    assert report.score == report.auto_max_score, [r.message for r in report.results if not r.passed]


@pytest.mark.skipif(not sandbox_mode().isolated, reason="a batch needs bubblewrap (or --no-sandbox)")
def test_a_batch_entry_frank_ipynb_is_franks_whole_submission(tmp_path):
    subs = tmp_path / "subs"
    subs.mkdir()
    copy_reference(subs / "alice")
    exercise_notebook(ROOT / "reference", subs / "frank.ipynb")
    mistake = build_planted(MISTAKES["p06-cardan-rotation-order"], tmp_path / "planted")
    build_planted(MISTAKES["p06-cardan-rotation-order"], subs / "gina")
    exercise_notebook(mistake, subs / "hank.ipynb")
    report = run_batch(subs, tmp_path / "out", problems=[6, 9], jobs=1, limits=LIMITS, progress=False)
    assert report.graded == report.students == 4
    with Gradebook.in_folder(tmp_path / "out") as book:
        stored = {}
        for g in book.current():
            stored.setdefault(g.student, []).append(g.report)
    statuses = {name: [(r.check_id, r.status.value, r.score) for rep in reps for r in rep.results]
                for name, reps in stored.items()}
    assert statuses["frank"] == statuses["alice"] and statuses["hank"] == statuses["gina"]
    assert sum(r.score for r in stored["frank"][0].results) == 10
    assert any("notebook frank.ipynb → rotations.py" in n for n in stored["frank"][0].notes)
