"""Loading submissions: bad input gets one clear message for that student (a file name that is not UTF-8, a
symbolic link, a corrupt zip, an unreadable notebook, an empty folder, a folder that is not a work folder), never a
traceback, never the same line under every check, and never a walk of a parent folder or of ``/``."""

import json
import os
import sqlite3
from pathlib import Path

import pytest

from grader import loader
from grader.batch import run_batch
from grader.checking import checks_of
from grader.cli import main
from grader.gradebook import Gradebook
from grader.loader import FIX, materialize
from grader.results import Status
from grader.runner import grade_submission, problem_module
from grader.sandbox import Limits, sandbox_mode

from .submissions import copy_reference, copy_template

LIMITS = Limits(call_timeout=5.0, import_timeout=10.0)
ODD = b"caf\xe9.py"  # Latin-1, not UTF-8


def odd_file(folder: Path) -> Path:
    with open(os.path.join(os.fsencode(folder), ODD), "w") as handle:
        handle.write("x = 1\n")
    return folder


def grade_cli(capsys, *argv):
    code = main(["problem-6", *argv])
    captured = capsys.readouterr()
    return code, " ".join(captured.out.split()), captured.err  # the terminal report wraps long lines


# ------------------------------------------------------------------------------------------ names and links


def test_a_file_name_that_is_not_utf8_is_left_out_with_a_note(tmp_path, capsys):
    submission = odd_file(copy_reference(tmp_path / "pkg"))
    code, out, err = grade_cli(capsys, "--submission", str(submission), "--seed", "3")
    assert "Traceback" not in out + err
    assert code == 0, out
    assert "left out caf\\xe9.py: its name is not valid UTF-8" in out


def test_a_submission_that_is_a_link_is_refused_not_followed(tmp_path, capsys):
    link = tmp_path / "mywork"
    link.symlink_to(copy_reference(tmp_path / "elsewhere"))  # followed, it would grade the reference: 10/10
    code, out, _ = grade_cli(capsys, "--submission", str(link))
    assert code == 2
    assert out.count("is a symbolic link, which the grader never follows") == 1, out
    assert "0 / 10 points" in out


def test_links_inside_are_refused_and_never_copied(tmp_path):
    submission = copy_template(tmp_path / "pkg")
    (submission / "rotations.py").unlink()
    (submission / "rotations.py").symlink_to(Path(__file__).resolve().parents[1] / "reference" / "rotations.py")
    (submission / "etc").symlink_to("/etc")
    (report,) = grade_submission(submission, [6], seed=1, limits=LIMITS)
    assert "symbolic links" in report.load_error and "rotations.py →" in report.load_error and "etc →" in report.load_error
    assert report.score == 0 and all(r.status is Status.ERROR and not r.message for r in report.results)


def test_a_fifo_named_like_a_module_does_not_block_the_loader(tmp_path):
    submission = copy_reference(tmp_path / "pkg")
    os.mkfifo(submission / "stuck.py")  # reading it would wait for a writer forever
    loaded = materialize(submission, tmp_path)
    assert any("left out stuck.py: it is not a regular file" in note for note in loaded.notes)
    loader.cleanup(loaded)


# ------------------------------------------------------------------------------------------ said once


@pytest.mark.parametrize("case", ["corrupt_zip", "unreadable_notebook", "empty_folder", "not_a_work_folder"])
def test_an_unloadable_submission_is_said_once_with_the_fix(case, tmp_path, capsys):
    if case == "corrupt_zip":
        source, expected = tmp_path / "work.zip", "not a readable zip archive"
        source.write_bytes(b"PK\x03\x04 this is not a zip archive")
    elif case == "unreadable_notebook":
        source, expected = tmp_path / "problem_06.ipynb", "the notebook problem_06.ipynb cannot be read"
        source.write_text('{"cells": [ {"cell_type": "code", "source": "x = ')
    elif case == "empty_folder":
        source, expected = tmp_path / "empty", "is empty"
        source.mkdir()
    else:
        source, expected = tmp_path / "home", "is not a work folder"
        source.mkdir()
        (source / "notes.md").write_text("my notes")
        (source / "photos").mkdir()
    js, gs = tmp_path / "r.json", tmp_path / "results.json"
    code, out, err = grade_cli(capsys, "--submission", str(source), "--json", str(js), "--gradescope", str(gs))
    assert code == 2  # a submission that cannot be loaded: the student's to fix, not a grader fault (3)
    assert out.count(expected) == 1, out
    checks = len(checks_of(problem_module(6)))
    assert f"none of the {checks} checks of this problem ran" in out and "Traceback" not in out + err
    if case in ("empty_folder", "not_a_work_folder"):
        assert out.count("Run `grade` inside the folder that `grade init`") == 1
    report = json.loads(js.read_text())["reports"][0]
    assert expected in report["load_error"] and not any(r["message"] for r in report["results"])
    results = json.loads(gs.read_text())
    assert expected in results["output"] and sum(t["score"] for t in results["tests"]) == 0
    assert not any(expected in t["output"] for t in results["tests"])


def test_outside_a_work_folder_nothing_is_walked(tmp_path, monkeypatch, capsys):
    """``grade problem-6`` in a folder that is not a work folder (or at ``/``) says so at once: the folder is
    looked at (its top level), never walked."""

    def walked(root):
        raise AssertionError(f"{root} was walked")

    monkeypatch.setattr(loader, "_collect_dir", walked)
    for folder in (Path("/"), tmp_path):
        (tmp_path / "deep" / "er").mkdir(parents=True, exist_ok=True)
        (tmp_path / "deep" / "er" / "rotations.py").write_text("")  # only a walk would find it
        (tmp_path / "notes.md").write_text("")
        monkeypatch.chdir(folder)
        code, out, _ = grade_cli(capsys)
        assert code == 2 and out.count(FIX) == 1, out
        assert f"{os.path.abspath(folder)} is not a work folder" in out


def test_a_folder_with_a_single_work_folder_inside_is_graded(tmp_path):
    """A submission wrapped in a folder (as a zip of a folder unpacks) is still found."""
    copy_reference(tmp_path / "alice" / "mywork")
    (report,) = grade_submission(tmp_path / "alice", [6], seed=1, limits=LIMITS)
    assert not report.load_error and report.score == report.auto_max_score


# ------------------------------------------------------------------------------------------ a batch


@pytest.mark.skipif(not sandbox_mode().isolated, reason="a batch needs bubblewrap (or --no-sandbox)")
def test_a_batch_grades_everyone_and_records_one_message_for_each_bad_submission(tmp_path):
    subs = tmp_path / "subs"
    subs.mkdir()
    copy_reference(subs / "alice")
    odd_file(copy_reference(subs / "bob"))
    (subs / "carol").symlink_to(copy_reference(tmp_path / "reference_copy"))
    (subs / "dave").mkdir()
    (subs / "erin.zip").write_bytes(b"not a zip")
    copy_reference(Path(os.fsdecode(os.path.join(os.fsencode(subs), b"fr\xe9d"))))  # a folder named in Latin-1
    out = tmp_path / "results"
    report = run_batch(subs, out, problems=[6], jobs=1, limits=LIMITS, progress=False)
    assert report.graded == report.students == 5 and not report.not_graded
    assert report.ignored == ["fr\\xe9d (its name is not valid UTF-8: rename it)"]
    with Gradebook.in_folder(out) as book:
        stored = {g.student: g.report for g in book.current()}
    assert {name: r.score for name, r in stored.items()} == {"alice": 10, "bob": 10, "carol": 0, "dave": 0, "erin": 0}
    assert any("not valid UTF-8" in note for note in stored["bob"].notes)
    assert "symbolic link" in stored["carol"].load_error
    assert "is empty" in stored["dave"].load_error
    assert "not a readable zip archive" in stored["erin"].load_error
    for name in ("carol", "dave", "erin"):
        assert all(r.status is Status.ERROR and not r.message for r in stored[name].results)
    with sqlite3.connect(out / "gradebook.sqlite") as db:  # recorded as graded (the student's fault), once each
        assert db.execute("SELECT count(*) FROM submissions WHERE load_error != ''").fetchone() == (3,)
    summary = (out / "summary.html").read_text()
    assert "could not be loaded" in summary
