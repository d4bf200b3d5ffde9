"""The grade command: exit codes, report files, init, list, loading zips and notebooks."""

import json
import os
import signal
import subprocess
import sys
import time
import zipfile
from pathlib import Path

import nbformat
import pytest

from grader.cli import main

from .submissions import build_hostile, build_planted, copy_reference, planted_mistakes
from .test_gradescope import validate, visible_text

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    return copy_reference(tmp_path_factory.mktemp("ref") / "pkg")


def test_reference_exits_zero_and_writes_reports(reference, tmp_path, capsys):
    html, js, gs = tmp_path / "r.html", tmp_path / "r.json", tmp_path / "results.json"
    code = main(["problem-6", "--submission", str(reference), "--seed", "5", "--html", str(html),
                 "--json", str(js), "--gradescope", str(gs)])
    assert code == 0
    out = capsys.readouterr().out
    assert "Problem 6" in out and "10 / 10 points" in out and "seed 5" in out
    assert "<html" in html.read_text()
    data = json.loads(js.read_text())
    assert data["reports"][0]["visible_score"] == 10
    results = json.loads(gs.read_text())
    assert sum(t["score"] for t in results["tests"]) == 10 and all(t["status"] == "passed" for t in results["tests"])
    assert {"name", "score", "max_score", "output", "visibility"} <= set(results["tests"][0])


def test_failing_checks_exit_one(tmp_path, capsys):
    mistake = next(m for m in planted_mistakes(6) if m.name == "p06-cardan-rotation-order")
    code = main(["problem-6", "--submission", str(build_planted(mistake, tmp_path / "pkg")), "--seed", "1"])
    out = capsys.readouterr().out
    assert code == 1
    assert "wrong order" in out and "hint:" in out and "seed 1" in out


def test_usage_errors_exit_two(tmp_path, capsys):
    assert main(["problem-6", "--submission", str(tmp_path / "missing")]) == 2
    assert main(["problem-99", "--submission", str(tmp_path)]) == 2
    assert main(["frobnicate"]) == 2
    assert "does not exist" in capsys.readouterr().err


def test_a_broken_zip_is_reported_not_crashed(tmp_path, capsys):
    bad = tmp_path / "work.zip"
    bad.write_bytes(b"this is not a zip archive")
    assert main(["problem-6", "--submission", str(bad)]) == 2
    assert "not a readable zip archive" in capsys.readouterr().out


def test_zip_of_a_folder_and_zip_slip(reference, tmp_path, capsys):
    archive = tmp_path / "student.zip"
    with zipfile.ZipFile(archive, "w") as z:
        for path in reference.glob("*"):
            z.write(path, f"mywork/{path.name}")
        z.writestr("../../escape.py", "raise SystemExit('escaped')")
    assert main(["problem-6", "--submission", str(archive), "--seed", "2"]) == 0
    assert not (tmp_path.parent / "escape.py").exists()


def test_notebook_becomes_a_module(reference, tmp_path, capsys):
    source = (reference / "problem_06.py").read_text()
    notebook = nbformat.v4.new_notebook()
    notebook.cells = [nbformat.v4.new_markdown_cell("# Problem 6"), nbformat.v4.new_code_cell("%matplotlib inline"),
                      nbformat.v4.new_code_cell(source)]
    folder = tmp_path / "student"
    folder.mkdir()
    (folder / "rotations.py").write_text((reference / "rotations.py").read_text())
    nbformat.write(notebook, folder / "problem_06.ipynb")
    assert main(["problem-6", "--submission", str(folder), "--seed", "2"]) == 0
    assert "notebook problem_06.ipynb → problem_06.py" in capsys.readouterr().out


def test_init_and_list(tmp_path, capsys):
    target = tmp_path / "mywork"
    assert main(["init", str(target)]) == 0
    assert (target / "answers.toml").exists() and (target / "rotations.py").exists()
    assert main(["init", str(target)]) == 2
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    assert "Euler angles" in out and "points graded automatically" in out


def test_html_report_embeds_figures_and_hides_hidden_checks():
    from grader.report.data import render_json
    from grader.report.html import render_html
    from grader.report.text import render_terminal
    from grader.results import CheckResult, Figure, ProblemReport, Series, Status

    fig = Figure("traces", "x", "y", (Series("yours: B", (0.0, 1.0), (0.0, 1.0), "student"),
                                       Series("reference: B", (0.0, 1.0), (0.0, 2.0), "reference")))
    results = (
        CheckResult("p99.a", 99, "visible one", Status.FAILED, 0, 1, "got 1, expected 2", figures=(fig,)),
        CheckResult("p99.b", 99, "secret one", Status.FAILED, 0, 2, "the hidden detail", visibility="hidden"),
    )
    report = ProblemReport(99, "Test", results, seed=1)
    html = render_html([report])
    assert html.count("data:image/png;base64,") == 1
    assert "the hidden detail" not in html and "1 hidden check worth 2 points" in html
    text = render_terminal([report])
    assert "the hidden detail" not in text and "1 hidden check worth 2 points" in text
    data = json.loads(render_json([report], show_hidden=False))["reports"][0]
    assert data["hidden_checks"] == {"count": 1, "max_score": 2.0}
    assert all(r["check_id"] != "p99.b" for r in data["results"])


def test_student_outputs_hold_the_same_things_and_never_the_model_answers(tmp_path, capsys):
    """The student's view is the same in every format: no format carries the course's model answers of the
    free-text questions (issue: --json once did)."""
    import tomllib

    model = tomllib.loads((ROOT / "reference" / "answers.toml").read_text())["problem_12"]["free_text"]
    submission = copy_reference(tmp_path / "pkg")
    answers = submission / "answers.toml"
    head, _, rest = answers.read_text().partition("[problem_12.free_text]")
    _, _, tail = rest.partition("\n[")
    mine = "".join(f'{key} = "my own words on {key}"\n' for key in model)
    answers.write_text(f"{head}[problem_12.free_text]\n{mine}\n[{tail}")
    html, js, gs = tmp_path / "r.html", tmp_path / "r.json", tmp_path / "results.json"
    main(["problem-12", "--submission", str(submission), "--seed", "3", "--html", str(html), "--json", str(js),
          "--gradescope", str(gs)])
    terminal = capsys.readouterr().out
    outputs = {"terminal": terminal, "html": html.read_text(), "json": js.read_text(), "gradescope": gs.read_text()}
    # the model answers are long sentences: a distinctive stretch of each must appear in no output
    for key, answer in model.items():
        probe = " ".join(answer.split())[:60]
        assert len(probe) > 30
        for name, text in outputs.items():
            assert probe not in " ".join(text.split()), (key, name)
    data = json.loads(js.read_text())["reports"][0]
    assert {m["key"] for m in data["manual"]} == set(model)
    assert all("model_answer" not in m for m in data["manual"])
    shown = {t["extra_data"].get("check_id") for t in json.loads(gs.read_text())["tests"]}
    assert {r["check_id"] for r in data["results"]} <= shown


# ---------------------------------------------------------------------------------------------- --gradescope


@pytest.fixture
def hidden_problem(monkeypatch):
    """Problem 99 of the batch tests (a visible check, a hidden check, a free-text question), gradable by
    ``grade problem-99``."""
    from importlib.machinery import ModuleSpec

    from grader.problems import problem_module

    from .batch_fixtures import HIDDEN_PROBLEM, hidden_check_module

    module = hidden_check_module()
    module.__spec__ = ModuleSpec(module.__name__, None)
    monkeypatch.setitem(sys.modules, module.__name__, module)
    problem_module.cache_clear()
    yield HIDDEN_PROBLEM
    problem_module.cache_clear()


def _checks(data: dict) -> dict:
    return {t["extra_data"]["check_id"]: t for t in data["tests"] if "check_id" in t["extra_data"]}


def test_the_gradescope_file_follows_the_specification_and_withholds_hidden_and_secret_checks(
        hidden_problem, tmp_path, capsys):
    """``grade problem-N --gradescope`` writes the autograder's results.json (one builder): the specification's
    JSON Schema, and on the instructor's side too a hidden or secret check is shown only when grades are
    published."""
    from grader.report.gradescope_results import WITHHELD

    from .batch_fixtures import HIDDEN_PROBLEM

    # a hidden check that fails: graded and counted, shown to no student before publication
    transposed = next(m for m in planted_mistakes(6) if m.name == "p06-vectors-transpose")
    gs = tmp_path / "hidden.json"
    code = main([f"problem-{HIDDEN_PROBLEM}", "--submission", str(build_planted(transposed, tmp_path / "bad")),
                 "--seed", "7", "--gradescope", str(gs)])
    capsys.readouterr()
    assert code == 1
    data = validate(json.loads(gs.read_text()))
    checks = _checks(data)
    hidden = checks[f"p{HIDDEN_PROBLEM}.secret_vector"]
    assert (hidden["visibility"], hidden["status"], hidden["score"], hidden["max_score"]) == (WITHHELD, "failed",
                                                                                             0, 3)
    assert checks[f"p{HIDDEN_PROBLEM}.visible_rotation"]["visibility"] == "visible"
    seen = visible_text(data)
    assert "SECRET" not in seen and "1 hidden check worth 3 points" in data["output"]
    assert data["score"] == 1.0 and data["extra_data"]["seed"] == 7 and "(seed 7)" in data["output"]

    # a secret check (multiple choice) answered wrongly: its message would give the key away
    choice = next(m for m in planted_mistakes(10) if m.name == "p10-a-orthonormal-option")
    folder = copy_reference(tmp_path / "choice")
    answers = folder / "answers.toml"
    answers.write_text(answers.read_text().replace(choice.old, choice.new))
    gs = tmp_path / "secret.json"
    assert main(["problem-10", "--submission", str(folder), "--seed", "3", "--gradescope", str(gs)]) == 1
    capsys.readouterr()
    data = validate(json.loads(gs.read_text()))
    secret = _checks(data)[choice.check]
    assert (secret["visibility"], secret["status"]) == (WITHHELD, "failed") and choice.message in secret["output"]
    assert choice.message not in visible_text(data)
    assert {c for c, t in _checks(data).items() if t["visibility"] == WITHHELD} == {"p10.a", "p10.b"}


def test_the_gradescope_file_of_an_unloadable_submission_says_why_once(tmp_path, capsys):
    bad = tmp_path / "work.zip"
    bad.write_bytes(b"this is not a zip archive")
    gs = tmp_path / "results.json"
    assert main(["problem-6", "--submission", str(bad), "--gradescope", str(gs)]) == 2
    capsys.readouterr()
    data = validate(json.loads(gs.read_text()))
    assert data["output"].startswith("Your submission could not be loaded (problem 6): ")
    assert data["output"].count("not a readable zip archive") == 1
    assert data["score"] == 0 and data["extra_data"]["load_errors"].keys() == {"6"}
    assert data["tests"] and {t["visibility"] for t in data["tests"]} == {"visible"}
    for test in data["tests"]:
        assert test["output"] == "Not run: your submission could not be loaded (the reason is at the top).", test


def test_sigterm_ends_the_command_as_ctrl_c_does_and_leaves_no_folders(tmp_path):
    """``timeout``, a job scheduler or an operator stops ``grade`` with SIGTERM: the student's worker is stopped,
    the command says so and exits with 143, and neither the copy of the submission nor the worker's runtime folder
    stays in the temporary directory (both did: the process died where it stood)."""

    submission = build_hostile("infinite_loop_call", tmp_path / "student")  # problem 6 runs into an endless loop
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    command = subprocess.Popen([sys.executable, "-m", "grader.cli", "problem-6", "--submission", str(submission)],
                               cwd=tmp_path, env=dict(os.environ, TMPDIR=str(temporary)), stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 60
        while not {"submission", "grader-runtime"} <= {p.name.rsplit("-", 1)[0] for p in temporary.iterdir()}:
            assert command.poll() is None and time.monotonic() < deadline, "the grading did not start"
            time.sleep(0.05)
        time.sleep(1.0)  # inside the endless call
        command.send_signal(signal.SIGTERM)
        out, err = command.communicate(timeout=60)
    finally:
        command.kill()
    assert command.returncode == 143, (out, err)
    assert err.strip().splitlines()[-1] == "terminated"
    deadline = time.monotonic() + 20
    while list(temporary.iterdir()) and time.monotonic() < deadline:  # a detached process removes the folders
        time.sleep(0.1)
    assert sorted(p.name for p in temporary.iterdir()) == []


# ---------------------------------------------------------------------------------------------- a student alone


def _commands(help_text: str) -> list[str]:
    """The commands a help text lists, in order."""
    lines = help_text.split("positional arguments:")[1].split("options:")[0].splitlines()
    return [line.split()[0] for line in lines if line.startswith("    ") and not line.startswith("     ")]


def test_help_shows_grade_problem_first(capsys):
    assert main(["--help"]) == 0
    commands = _commands(capsys.readouterr().out)
    assert commands[0] == "problem-N"
    assert {"init", "list", "batch", "gradescope", "kit"} <= set(commands)  # the full project lists every command


def test_the_kits_help_hides_the_instructors_commands(monkeypatch, capsys):
    import grader.oracle

    monkeypatch.setattr(grader.oracle, "reference_available", lambda: False)
    assert main(["--help"]) == 0
    shown = capsys.readouterr().out
    commands = _commands(shown)
    assert commands[:3] == ["problem-N", "init", "list"]
    assert not set(commands) & {"demo", "kit", "gradescope", "batch", "import-manual", "export"}, commands
    assert "check(6)" in shown
    # hidden, not removed: an instructor's command is still understood
    assert main(["export", "--help"]) == 0


@pytest.mark.parametrize("spelling", [["problem", "6"], ["6"], ["p6"], ["Problem-6"]])
def test_other_spellings_of_a_problem_are_understood(spelling, reference, capsys):
    assert main([*spelling, "--submission", str(reference), "--seed", "2"]) == 0
    assert "Problem 6: " in capsys.readouterr().out


@pytest.mark.parametrize("spelling", [["problem_6"], ["prob6"], ["exercise-6"], ["problem"], ["problem-N"]])
def test_a_misspelt_problem_is_answered_with_the_right_spelling(spelling, capsys):
    assert main(spelling) == 2
    error = capsys.readouterr().err
    assert "grade problem-6" in error, error


def test_a_submission_that_does_not_import_is_said_once(tmp_path, capsys):
    """A syntax error: its traceback once, with the line to fix; the other checks that needed the package point
    there in one line each."""
    submission = build_hostile("syntax_error", tmp_path / "pkg")
    assert main(["problem-6", "--submission", str(submission), "--seed", "1"]) == 1
    out = capsys.readouterr().out
    assert out.count("def broken(:") == 1, out
    assert out.count("could not be imported: SyntaxError") == 4  # said in full once; three checks point there
    assert out.count("said in full at “R1, R2, R3 return 3 x 3 numeric matrices”") == 3, out
    assert "Fix line 1 of __init__.py first" in out
    assert len(out.splitlines()) < 25


def test_a_failing_notebook_cell_is_named(tmp_path, capsys):
    """A notebook's function that raises when called: the report names its cell and shows the line."""
    from .notebooks import problem_06_cells, write_notebook

    cells = problem_06_cells(ROOT / "reference")
    frames = next(i for i, c in enumerate(cells) if c.startswith("def frames"))
    cells[frames] = cells[frames].replace('    """', '    scale = 1 / 0  # the slip\n    """', 1)
    notebook = write_notebook(tmp_path / "problem_06.ipynb", ["import numpy as np", *cells])
    assert main(["problem-6", "--submission", str(notebook), "--seed", "1"]) == 1
    out = capsys.readouterr().out
    assert f'File "problem_06.ipynb, cell {frames + 2}"' in out, out
    assert "scale = 1 / 0  # the slip" in out, out


@pytest.mark.parametrize("encoding", ["cp1252", "latin-1"])
def test_the_report_reaches_a_pipe_of_any_encoding(encoding, tmp_path):
    """Windows writes a program's output to a pipe or a file in its ANSI code page (cp1252), a Linux of a Latin-1
    locale in Latin-1: neither can write the report's ✔ and ✘, and the command ended with a UnicodeEncodeError
    after grading.  Such an output gets the report in UTF-8."""
    submission = copy_reference(tmp_path / "pkg")
    done = subprocess.run([sys.executable, "-m", "grader.cli", "problem-6", "--submission", str(submission)],
                          cwd=tmp_path, env=dict(os.environ, PYTHONIOENCODING=encoding), capture_output=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr.decode("utf-8", "replace")
    out = done.stdout.decode("utf-8")
    assert "✔" in out and "10 / 10 points" in " ".join(out.split())


def test_no_colours_on_a_windows_console_that_cannot_show_them(monkeypatch):
    """On Windows, the report is coloured only where the console was asked to read escape sequences and could:
    elsewhere (a console older than Windows 10, or no console at all) they would be printed as they are."""
    from grader import cli

    class Console:
        def isatty(self):
            return True

        def fileno(self):
            return 1

    monkeypatch.delenv("NO_COLOR", raising=False)
    assert cli._colours(Console()) == (os.name != "nt" or cli._windows_escapes(Console()))
    monkeypatch.setattr(os, "name", "nt")
    monkeypatch.setitem(sys.modules, "msvcrt", None)  # not Windows here: its console cannot be asked
    assert not cli._colours(Console())
    monkeypatch.setenv("NO_COLOR", "1")
    monkeypatch.setattr(os, "name", "posix")
    assert not cli._colours(Console())


def test_a_terminal_of_another_encoding_keeps_it_with_what_it_cannot_show_replaced(monkeypatch):
    import io

    from grader import cli

    class Terminal(io.TextIOWrapper):
        def isatty(self):
            return True

    terminal, pipe = Terminal(io.BytesIO(), encoding="latin-1"), io.TextIOWrapper(io.BytesIO(), encoding="cp1252")
    monkeypatch.setattr(sys, "stdout", terminal)
    monkeypatch.setattr(sys, "stderr", pipe)
    cli._readable_output()
    assert (terminal.encoding, terminal.errors) == ("latin-1", "replace")
    assert pipe.encoding == "utf-8"
    print("✔ é", file=terminal)
    terminal.flush()
    assert terminal.buffer.getvalue() == "? é\n".encode("latin-1")
