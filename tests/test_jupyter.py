"""Checks from inside Jupyter (issue 28): a real kernel (ipykernel, driven by nbclient) runs a student's notebook
whose last cell is ``check(6)``; the verdicts are those of ``grade problem-6`` on the same cells, whether the kernel
knows its notebook's file (Jupyter's server tells it) or grades the cells it ran; the report is shown inline, as
HTML with the figures."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from grader.cli import main

from .notebooks import problem_06_cells, r3_transposed, write_notebook
from .submissions import ROOT, copy_template

nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")
import nbformat  # noqa: E402

pytestmark = pytest.mark.slow

SEED = 5
#: the student's last cell
CHECK = "from grader import check\nresult = check(6, seed=%d)\nprint('VERDICTS', json.dumps(result.verdicts))\nresult"


def _work_folder(tmp_path: Path, last: str) -> Path:
    """A work folder of the template with a notebook for problem 6: the reference's definitions, R3 transposed
    (so that some checks fail and others pass), then ``last``."""
    work = copy_template(tmp_path / "mywork")
    cells = r3_transposed(problem_06_cells(ROOT / "reference"))
    write_notebook(work / "problem_06.ipynb", ["import json\nimport numpy as np", *cells, last])
    return work


def _run_kernel(work: Path, monkeypatch, session: str | None) -> list:
    """Run the notebook in a fresh kernel started in ``work`` (the grader of this tree importable there); with
    ``session``, the kernel is told its notebook's path as Jupyter's server tells it (``JPY_SESSION_NAME``)."""
    monkeypatch.setenv("PYTHONPATH", str(ROOT))
    if session is None:
        monkeypatch.delenv("JPY_SESSION_NAME", raising=False)
    else:
        monkeypatch.setenv("JPY_SESSION_NAME", session)
    book = nbformat.read(work / "problem_06.ipynb", as_version=4)
    client = nbclient.NotebookClient(book, timeout=600, kernel_name="python3",
                                     resources={"metadata": {"path": str(work)}})
    client.execute()
    return book.cells[-1].outputs


def _kernel_verdicts(outputs: list) -> dict:
    text = "".join(o.get("text", "") for o in outputs if o.get("output_type") == "stream")
    line = next(line for line in text.splitlines() if line.startswith("VERDICTS "))
    return json.loads(line.removeprefix("VERDICTS "))


def _grade_verdicts(submission: Path, tmp_path: Path) -> dict:
    report = tmp_path / "grade.json"
    main(["problem-6", "--submission", str(submission), "--seed", str(SEED), "--json", str(report)])
    (graded,) = json.loads(report.read_text())["reports"]
    return {r["check_id"]: r["status"] for r in graded["results"]}


def _html(outputs: list) -> str:
    return "".join(o.get("data", {}).get("text/html", "") for o in outputs if o.get("output_type") in
                   ("execute_result", "display_data"))


@pytest.mark.parametrize("session", ["problem_06.ipynb", None], ids=["notebook-file", "kernel-cells"])
def test_check_in_a_kernel_gives_the_verdicts_of_grade(session, tmp_path, monkeypatch):
    work = _work_folder(tmp_path, CHECK % SEED)
    if session is not None:  # the server's path: from its root, a folder above the notebook's
        session = f"{work.name}/{session}"
        monkeypatch.chdir(tmp_path)
    outputs = _run_kernel(work, monkeypatch, session)
    verdicts = _kernel_verdicts(outputs)
    assert verdicts == _grade_verdicts(work, tmp_path)
    assert verdicts["p06.elementary_values"] == "failed" and verdicts["p06.elementary_shape"] == "passed"
    html = _html(outputs)
    assert "<iframe" in html and "data:image/png;base64" in html  # the HTML report, its figures inline
    assert ("cells run in this kernel" in html) == (session is None)


def test_the_grade_magic(tmp_path, monkeypatch):
    work = _work_folder(tmp_path, "%load_ext grader\n%grade 6")
    outputs = _run_kernel(work, monkeypatch, "problem_06.ipynb")
    html = _html(outputs)
    assert "Problem 6:" in html and "<iframe" in html, outputs


def test_an_unsaved_cell_is_said(tmp_path, monkeypatch):
    """A cell run in the kernel that the saved file lacks: the file is graded, and the report says to save it."""
    work = _work_folder(tmp_path, CHECK % SEED)
    ran = nbformat.read(work / "problem_06.ipynb", as_version=4)
    ran.cells.insert(len(ran.cells) - 1, nbformat.v4.new_code_cell("def extra():\n    return 1"))
    monkeypatch.setenv("PYTHONPATH", str(ROOT))
    monkeypatch.setenv("JPY_SESSION_NAME", "problem_06.ipynb")
    nbclient.NotebookClient(ran, timeout=600, kernel_name="python3",
                            resources={"metadata": {"path": str(work)}}).execute()
    html = _html(ran.cells[-1].outputs)
    assert "1 cell you ran is not in problem_06.ipynb as it is saved" in html, html[:2000]
