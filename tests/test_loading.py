"""Loading submissions: bad input gets one clear message for that student (a file name that is not UTF-8, a
symbolic link, a corrupt zip, an unreadable notebook, an empty folder, a folder that is not a work folder), never a
traceback, never the same line under every check, and never a walk of a parent folder or of ``/``."""

import codecs
import json
import os
import sqlite3
import stat
import tempfile
import tomllib
import warnings
import zipfile
from pathlib import Path
from types import SimpleNamespace
from unittest import mock

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from grader import loader
from grader.batch import run_batch
from grader.checking import checks_of
from grader.cli import main
from grader.errors import SubmissionError
from grader.gradebook import Gradebook
from grader.loader import FIX, materialize, submission_digest
from grader.results import Status
from grader.runner import grade_submission
from grader.workers import Fresh
from grader.problems import problem_module
from grader.sandbox import Limits, sandbox_mode

from .notebooks import problem_06_cells, write_notebook
from .submissions import ROOT, copy_reference, copy_template

LIMITS = Limits(call_timeout=5.0, import_timeout=10.0)
ODD = b"caf\xe9.py"  # Latin-1, not UTF-8


def odd_file(folder: Path) -> Path:
    with open(os.path.join(os.fsencode(folder), ODD), "w") as handle:
        handle.write("x = 1\n")
    return folder


@pytest.fixture(params=["descriptors", "paths"])
def reads(request, monkeypatch):
    """Each way the loader reads a folder: relative to descriptors of its folders (Linux, macOS), and by path,
    each entry checked with ``os.lstat`` before it is opened and opened without ``O_NOFOLLOW``, ``O_NONBLOCK`` or
    ``O_CLOEXEC``, as on Windows (which lacks them and ``dir_fd``)."""
    if request.param == "descriptors":
        if not loader._relative_reads():
            pytest.skip("this platform cannot read a folder relative to a descriptor")
        monkeypatch.setattr(loader, "_relative_reads", lambda: True)
    else:
        monkeypatch.setattr(loader, "_relative_reads", lambda: False)
        monkeypatch.setattr(loader, "_read_flags", lambda: os.O_RDONLY)
    return request.param


def grade_cli(capsys, *argv):
    code = main(["problem-6", *argv])
    captured = capsys.readouterr()
    return code, " ".join(captured.out.split()), captured.err  # the terminal report wraps long lines


# ------------------------------------------------------------------------------------------ names and links


def test_a_file_name_that_is_not_utf8_is_left_out_with_a_note(reads, tmp_path, capsys):
    submission = odd_file(copy_reference(tmp_path / "pkg"))
    code, out, err = grade_cli(capsys, "--submission", str(submission), "--seed", "3")
    assert "Traceback" not in out + err
    assert code == 0, out
    assert "left out caf\\xe9.py: its name is not valid UTF-8" in out


def test_a_submission_that_is_a_link_is_refused_not_followed(reads, tmp_path, capsys):
    link = tmp_path / "mywork"
    link.symlink_to(copy_reference(tmp_path / "elsewhere"))  # followed, it would grade the reference: 10/10
    code, out, _ = grade_cli(capsys, "--submission", str(link))
    assert code == 2
    assert out.count("is a symbolic link, which the grader never follows") == 1, out
    assert "0 / 10 points" in out


def test_links_inside_are_refused_and_never_copied(reads, tmp_path):
    submission = copy_template(tmp_path / "pkg")
    (submission / "rotations.py").unlink()
    (submission / "rotations.py").symlink_to(Path(__file__).resolve().parents[1] / "reference" / "rotations.py")
    (submission / "etc").symlink_to("/etc")
    (report,) = grade_submission(submission, [6], seed=1, workers=Fresh(LIMITS))
    assert "symbolic links" in report.load_error and "rotations.py →" in report.load_error and "etc →" in report.load_error
    assert report.score == 0 and all(r.status is Status.ERROR and not r.message for r in report.results)


def test_a_fifo_named_like_a_module_does_not_block_the_loader(reads, tmp_path):
    submission = copy_reference(tmp_path / "pkg")
    os.mkfifo(submission / "stuck.py")  # reading it would wait for a writer forever
    loaded = materialize(submission, tmp_path)
    assert any("left out stuck.py: it is not a regular file" in note for note in loaded.notes)
    loader.cleanup(loaded)


def _own_and_outside(tmp_path: Path) -> tuple[Path, Path]:
    """A work folder (the reference, with a folder ``extra`` of its own) and, outside it, a folder whose files a
    link could make the grader read: each file of either says whose it is."""
    work = copy_reference(tmp_path / "work")
    (work / "extra").mkdir()
    (work / "extra" / "notes.py").write_text("WHOSE = 'own'\n")
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "notes.py").write_text("WHOSE = 'beyond the work folder'\n")
    (outside / "rotations.py").write_text("WHOSE = 'beyond the work folder'\n")
    return work, outside


def _read_from(loaded) -> str:
    return "".join((loaded.path / name).read_text() for name in loaded.files)


def test_a_file_swapped_for_a_link_after_its_check_is_never_read_through_it(reads, tmp_path, monkeypatch):
    """The file the loader opens is the file it checked: one swapped for a link in between is left out, never
    read through the link (``O_NOFOLLOW`` where the platform has it, else the file number of what was opened
    against that of what was checked)."""
    work, outside = _own_and_outside(tmp_path)
    real_open = os.open
    swapped = []

    def open_after_a_swap(path, flags, *args, **kwargs):
        if os.fspath(path).endswith("rotations.py") and not swapped:
            (work / "rotations.py").unlink()
            (work / "rotations.py").symlink_to(outside / "rotations.py")
            swapped.append(path)
        return real_open(path, flags, *args, **kwargs)

    monkeypatch.setattr(os, "open", open_after_a_swap)
    loaded = materialize(work, tmp_path)
    monkeypatch.setattr(os, "open", real_open)
    try:
        assert swapped
        assert "left out rotations.py: it is not a regular file that can be read" in loaded.notes
        assert "rotations.py" not in loaded.files and "beyond the work folder" not in _read_from(loaded)
        assert "own" in (loaded.path / "extra" / "notes.py").read_text()
    finally:
        loader.cleanup(loaded)


def test_a_folder_swapped_for_a_link_while_it_is_listed_is_never_read_through_it(reads, tmp_path, monkeypatch):
    """A folder of the submission swapped for a link while the loader lists it: relative to descriptors, the
    folder opened is listed and read (the student's own files); by path, the folder is checked again after its
    listing and left out.  Neither reads a file through the link."""
    work, outside = _own_and_outside(tmp_path)
    extra = os.lstat(work / "extra").st_ino
    real_scandir = os.scandir
    swapped = []

    def scandir_after_a_swap(path=None):
        folder = os.fstat(path) if isinstance(path, int) else os.lstat(path)
        if folder.st_ino == extra and not swapped:
            (work / "extra").rename(tmp_path / "moved")
            (work / "extra").symlink_to(outside)
            swapped.append(path)
        return real_scandir(path)

    monkeypatch.setattr(os, "scandir", scandir_after_a_swap)
    loaded = materialize(work, tmp_path)
    monkeypatch.setattr(os, "scandir", real_scandir)
    try:
        assert swapped
        assert "beyond the work folder" not in _read_from(loaded)
        if reads == "descriptors":
            assert "own" in (loaded.path / "extra" / "notes.py").read_text()
        else:
            assert "left out the folder extra: it cannot be read (it was replaced while it was read)" in loaded.notes
            assert "extra/notes.py" not in loaded.files
    finally:
        loader.cleanup(loaded)


def _described(mode: int, attributes: int = 0, tag: int = 0) -> SimpleNamespace:
    """How ``os.lstat`` describes an entry on Windows: its mode, attributes and reparse tag."""
    return SimpleNamespace(st_mode=mode, st_ino=1, st_file_attributes=attributes, st_reparse_tag=tag)


def test_what_windows_calls_a_link_is_refused_as_a_link():
    """Symbolic links, junctions and every other reparse point that names another file are links; a reparse point
    that does not (a file OneDrive keeps online) is a file."""
    reparse, folder = stat.FILE_ATTRIBUTE_REPARSE_POINT, stat.FILE_ATTRIBUTE_DIRECTORY
    assert loader._link_kind(_described(stat.S_IFLNK | 0o777, reparse, 0xA000000C)) == "symbolic link"
    assert loader._link_kind(_described(stat.S_IFDIR | 0o777, reparse | folder, 0xA0000003)) == "junction"
    assert loader._link_kind(_described(stat.S_IFREG | 0o666, reparse, 0xA000001D)) == "link"  # WSL's
    assert loader._link_kind(_described(stat.S_IFREG | 0o666, reparse, 0x9000001A)) is None  # OneDrive's
    assert loader._link_kind(_described(stat.S_IFREG | 0o666)) is None
    assert loader._link_kind(os.lstat(__file__)) is None


class _Junction:
    """A folder as ``os.lstat`` describes a junction on Windows (the rest as the folder's own description)."""

    st_file_attributes = stat.FILE_ATTRIBUTE_DIRECTORY | stat.FILE_ATTRIBUTE_REPARSE_POINT
    st_reparse_tag = 0xA0000003

    def __init__(self, info):
        self._info = info

    def __getattr__(self, name):
        return getattr(self._info, name)


def test_junctions_are_refused_inside_and_at_the_root(tmp_path, monkeypatch):
    """Read by path, as on Windows: a junction inside the submission is refused with the other links, and a
    submission that is a junction is refused as a symbolic link is (to ``Path.is_symlink`` and ``os.DirEntry`` a
    junction is no symbolic link, and a listing shows it as a folder)."""
    work, _ = _own_and_outside(tmp_path)
    real_lstat = os.lstat
    junctions = {str(work / "extra"), str(tmp_path / "mywork")}
    target = "C:\\Users\\someone\\elsewhere"
    monkeypatch.setattr(loader, "_relative_reads", lambda: False)
    monkeypatch.setattr(os, "lstat", lambda path, **kw: _Junction(real_lstat(path, **kw))
                        if os.fspath(path) in junctions else real_lstat(path, **kw))
    monkeypatch.setattr(os, "readlink", lambda path, **kw: target)
    with pytest.raises(SubmissionError) as refused:
        materialize(work, tmp_path)
    assert (f"the submission holds symbolic links, which the grader never follows: extra → {target} (a junction)"
            in str(refused.value))
    copy_reference(tmp_path / "mywork")
    with pytest.raises(SubmissionError, match="mywork is a junction, which the grader never follows"):
        materialize(tmp_path / "mywork", tmp_path)


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
    (report,) = grade_submission(tmp_path / "alice", [6], seed=1, workers=Fresh(LIMITS))
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


# ------------------------------------------------------------------------------------------ shapes that crashed


def _zip(path: Path, entries: list[tuple[str, bytes]]) -> Path:
    with zipfile.ZipFile(path, "w") as archive:
        for name, data in entries:
            archive.writestr(name, data)
    return path


def _reference_entries() -> list[tuple[str, bytes]]:
    folder = Path(__file__).resolve().parents[1] / "reference"
    return [(name, (folder / name).read_bytes()) for name in ("rotations.py", "problem_06.py", "__init__.py")]


def _deep_notebook(levels: int) -> str:
    return ('{"cells": [{"cell_type": "code", "metadata": {}, "outputs": [], "execution_count": null, "source": '
            + "[" * levels + "]" * levels + '}], "metadata": {}, "nbformat": 4, "nbformat_minor": 5}')


def _folder_named_like_a_module(tmp_path: Path) -> Path:
    folder = copy_reference(tmp_path / "work")
    (folder / "rotations.py").unlink()
    (folder / "rotations.py").mkdir()
    (folder / "rotations.py" / "R1.py").write_text("x = 1\n")
    return folder


#: submissions that crashed `grade` with a traceback (exit 1): each is refused now, with one reason
SHAPES = {
    "folder named rotations.py": (_folder_named_like_a_module, "a folder named rotations.py, which is a file of the "
                                                               "template"),
    "zip with foo.py and foo.py/bar.py": (
        lambda tmp: _zip(tmp / "work.zip", [*_reference_entries(), ("foo.py", b"x = 1\n"), ("foo.py/bar.py", b"")]),
        "both a file and a folder named foo.py"),
    "zip with foo.py/bar.py before foo.py": (
        lambda tmp: _zip(tmp / "work.zip", [*_reference_entries(), ("foo.py/bar.py", b""), ("foo.py", b"x = 1\n")]),
        "both a file and a folder named foo.py"),
    "zip entry name of 300 characters": (
        lambda tmp: _zip(tmp / "work.zip", [*_reference_entries(), ("n" * 297 + ".py", b"x = 1\n")]),
        "a name longer than 255 bytes"),
    "zip entry name of 130 characters, 257 bytes": (
        lambda tmp: _zip(tmp / "work.zip", [*_reference_entries(), ("é" * 127 + ".py", b"x = 1\n")]),
        "a name longer than 255 bytes"),
    "zip entry 30 folders of 200 characters deep": (
        lambda tmp: _zip(tmp / "work.zip", [*_reference_entries(), ("/".join(["d" * 200] * 30) + "/x.py", b"")]),
        "in folders nested deeper than 8"),
    "notebook problem_06.ipynb 5,000 lists deep": (
        lambda tmp: (tmp / "problem_06.ipynb").write_text(_deep_notebook(5000)) and tmp / "problem_06.ipynb",
        "its JSON is nested deeper than 100 levels"),
}


@pytest.mark.parametrize("shape", SHAPES)
def test_a_submission_of_a_shape_that_crashed_the_loader_is_refused_once(shape, tmp_path, capsys):
    build, expected = SHAPES[shape]
    (tmp_path / "in").mkdir()
    source = build(tmp_path / "in")
    gs = tmp_path / "results.json"
    code, out, err = grade_cli(capsys, "--submission", str(source), "--gradescope", str(gs))
    assert "Traceback" not in out + err, out + err
    assert code == 2, out + err  # cannot be loaded: the student's, said once
    assert out.count(expected) == 1, out
    assert "none of the" in out and "checks of this problem ran" in out
    assert expected in json.loads(gs.read_text())["output"]


@pytest.mark.parametrize("name", ["D:/evil.py", "rotations.py:stream.py", "con.py", "lib/NUL.txt", "lib./x.py",
                                  "lib /x.py", "a<b.py", 'say"so".md', "why?.py", "tab\t.py"])
def test_on_windows_a_name_windows_cannot_give_a_file_is_refused(name, tmp_path, monkeypatch):
    """On Windows, an archive made elsewhere can hold a name that Windows gives no file: a drive (``D:`` would lay
    the file out on that drive's current folder), a stream (``a:b``), a device (``con.py``), a name ending in a
    dot or a space, a reserved character.  It is refused with its name, before anything is laid out; elsewhere
    it is a name as any."""
    archive = _zip(tmp_path / "work.zip", [*_reference_entries(), (name, b"x = 1\n")])
    loader.cleanup(materialize(archive, tmp_path))
    monkeypatch.setattr(loader, "_windows_names", lambda: True)
    with pytest.raises(SubmissionError, match="a name that Windows cannot give a file"):
        materialize(archive, tmp_path)


def test_on_windows_the_reference_and_the_template_are_names_windows_gives(tmp_path, monkeypatch):
    monkeypatch.setattr(loader, "_windows_names", lambda: True)
    for folder in (copy_reference(tmp_path / "reference"), copy_template(tmp_path / "template")):
        loader.cleanup(materialize(folder, tmp_path))


def test_bounds_of_a_zip_entries_and_path_and_of_a_notebooks_depth(tmp_path):
    """An archive of more entries than a work folder holds is refused before its entries are looked at, a path
    longer than ``MAX_PATH_BYTES`` (within the depth allowed) is refused; a notebook nested deeper than
    ``MAX_NOTEBOOK_DEPTH`` is refused, one within it read."""
    many = _zip(tmp_path / "many.zip", [*_reference_entries(), *((f"img/{i}.png", b"") for i in range(5000))])
    with pytest.raises(SubmissionError, match="more than 5000 entries"):
        materialize(many, tmp_path)
    long = _zip(tmp_path / "long.zip", [*_reference_entries(), ("/".join(["d" * 200] * 8) + "/x.py", b"")])
    with pytest.raises(SubmissionError, match="a path longer than 1024 bytes"):
        materialize(long, tmp_path)
    for levels, refused in ((loader.MAX_NOTEBOOK_DEPTH - 2, False), (loader.MAX_NOTEBOOK_DEPTH - 1, True)):
        folder = tmp_path / f"nb{levels}"
        folder.mkdir()
        (folder / "mine.ipynb").write_text(  # the lists start at depth 3: notebook, metadata, x
            '{"cells": [], "metadata": {"x": ' + "[" * levels + "]" * levels + '}, "nbformat": 4, "nbformat_minor": 5}')
        if refused:
            with pytest.raises(SubmissionError, match="nested deeper than 100 levels"):
                materialize(folder, tmp_path)
        else:
            loader.cleanup(materialize(folder, tmp_path))


def test_answers_nested_5000_deep_are_the_students_error_not_a_crash(tmp_path, capsys):
    folder = copy_reference(tmp_path / "work")
    (folder / "answers.toml").write_text("[problem_10]\na = " + "[" * 5000 + "]" * 5000 + "\n")
    code = main(["problem-10", "--submission", str(folder), "--seed", "1"])
    captured = capsys.readouterr()
    assert "Traceback" not in captured.out + captured.err and code == 1, captured.out + captured.err
    assert "answers.toml is not valid TOML: its arrays or tables are nested too deep" in captured.out


# ------------------------------------------------------------------------------------------ any shape

_VALID_NOTEBOOK = json.dumps({"cells": [{"cell_type": "code", "metadata": {}, "outputs": [], "execution_count": None,
                                         "source": "def R1(a):\n    return a\n"}],
                              "metadata": {}, "nbformat": 4, "nbformat_minor": 5}).encode()
#: names of files and folders: the template's, ordinary ones, ones no file system or loader should take as they are
_NAMES = st.sampled_from(["rotations.py", "problem_06.py", "answers.toml", "__init__.py", "problem_06.ipynb", "foo.py",
                          "mine.ipynb", "notes.md", "a", "b", ".", "..", "", "__pycache__", "__MACOSX", ".hidden.py",
                          "x\\y.py", "/", "C:"])
_PART = st.one_of(
    _NAMES, _NAMES, _NAMES,
    st.text(alphabet="aé._-\x1b", min_size=1, max_size=6).map(lambda text: text + ".py"),
    st.integers(250, 300).map(lambda n: "n" * n + ".py"),
    st.integers(120, 135).map(lambda n: "é" * n + ".py"),
)
_CONTENT = st.sampled_from([b"x = 1\n", b"", b"\xff\xfe", b"{", b"[]", _VALID_NOTEBOOK,
                            _deep_notebook(5000).encode(), b"a = " + b"[" * 3000 + b"]" * 3000 + b"\n"])
_ENTRY = st.tuples(st.lists(_PART, min_size=1, max_size=3) | st.lists(_PART, min_size=9, max_size=11),
                   st.sampled_from(["file", "file", "folder", "link"]), _CONTENT)


def _loads_or_refuses(source: Path, scratch: Path) -> None:
    """The loader's promise: a submission is loaded, every file of the student's in place, or refused with a
    ``SubmissionError``; nothing else escapes.  The content hash that a batch computes agrees."""
    try:
        digest = submission_digest(source)
    except SubmissionError:
        digest = None
    try:
        loaded = materialize(source, scratch)
    except SubmissionError as exc:
        assert str(exc)
        event("refused")
        return
    event("loaded")
    try:
        assert digest == loaded.digest
        for name in loaded.files:
            assert name.endswith(".ipynb") or (loaded.path / name).is_file(), name
    finally:
        loader.cleanup(loaded)


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(entries=st.lists(_ENTRY, min_size=1, max_size=8))
def test_any_zip_is_loaded_or_refused_with_a_reason(entries):
    with tempfile.TemporaryDirectory() as scratch:
        scratch = Path(scratch)
        archive = scratch / "work.zip"
        with zipfile.ZipFile(archive, "w") as out, warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a name twice: as an archiver may write it
            for parts, kind, data in entries:
                if not "/".join(parts):
                    continue  # no entry has an empty name
                info = zipfile.ZipInfo("/".join(parts) + ("/" if kind == "folder" else ""))
                if kind == "link":
                    info.external_attr = (stat.S_IFLNK | 0o777) << 16
                    data = b"/etc/passwd"
                out.writestr(info, b"" if kind == "folder" else data)
        _loads_or_refuses(archive, scratch)


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(entries=st.lists(_ENTRY, min_size=1, max_size=8))
def test_any_folder_is_loaded_or_refused_with_a_reason(entries):
    with tempfile.TemporaryDirectory() as scratch:
        scratch = Path(scratch)
        root = scratch / "work"
        _build_folder(root, entries)
        _loads_or_refuses(root, scratch)


def _build_folder(root: Path, entries) -> None:
    root.mkdir()
    for parts, kind, data in entries:
        if any(part in ("", ".", "..") or "/" in part for part in parts):
            continue  # not a name a folder can hold
        path = root.joinpath(*parts)
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            if kind == "folder":
                path.mkdir(exist_ok=True)
            elif kind == "link":
                path.symlink_to("/etc")
            else:
                path.write_bytes(data)
        except OSError:  # the file system refused it (a name too long, a file where a folder goes)
            continue


def _read_as(root: Path, relative: bool):
    """The student's files and notes as the loader reads ``root`` one way or the other, or why it refuses."""
    with mock.patch.object(loader, "_relative_reads", lambda: relative):
        try:
            return loader._student_files(root)
        except SubmissionError as exc:
            return str(exc)


@pytest.mark.skipif(not loader._relative_reads(), reason="this platform cannot read relative to a descriptor")
@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(entries=st.lists(_ENTRY, min_size=1, max_size=8))
def test_a_folder_read_by_path_is_read_as_relative_to_descriptors(entries):
    """Both ways of reading a folder (relative to descriptors, by path as on Windows) keep the same files, leave
    out the same with the same notes, and refuse the same links with the same message."""
    with tempfile.TemporaryDirectory() as scratch:
        root = Path(scratch) / "work"
        _build_folder(root, entries)
        by_descriptors = _read_as(root, True)
        event("refused" if isinstance(by_descriptors, str) else "loaded")
        assert _read_as(root, False) == by_descriptors


@pytest.mark.skipif(not loader._relative_reads(), reason="this platform cannot read relative to a descriptor")
def test_a_work_folder_read_by_path_is_read_as_relative_to_descriptors(tmp_path):
    """A work folder with what students' folders hold (folders in folders, a notebook, hidden and ignored folders,
    a file named in bytes that are not UTF-8, a FIFO, files of other kinds) is read alike both ways."""
    work = odd_file(copy_reference(tmp_path / "work"))
    (work / "lib" / "deeper").mkdir(parents=True)
    (work / "lib" / "deeper" / "helpers.py").write_text("H = 1\r\n")
    (work / "lib" / "data.csv").write_text("1,2\n")
    (work / ".ipynb_checkpoints").mkdir()
    (work / ".ipynb_checkpoints" / "problem_06-checkpoint.ipynb").write_text("{}")
    (work / "__pycache__").mkdir()
    (work / "problem_06.ipynb").write_text(json.dumps({"cells": [], "metadata": {}, "nbformat": 4,
                                                       "nbformat_minor": 5}))
    os.mkfifo(work / "lib" / "stuck.py")
    files, notes = _read_as(work, True)
    assert "lib/deeper/helpers.py" in files and "problem_06.ipynb" in files and "lib/data.csv" not in files
    assert any("stuck.py" in note for note in notes) and any("caf\\xe9.py" in note for note in notes)
    assert _read_as(work, False) == (files, notes)


def test_the_templates_files_with_windows_line_ends_are_still_the_templates(tmp_path):
    """A work folder checked out by git on Windows (``core.autocrlf``) holds the template's files with ``\\r\\n``
    line ends: they are still the template's, so a notebook that leaves out a name the problem needs is told so
    (not taken as defined in the student's own ``problem_06.py``)."""
    work = tmp_path / "work"
    work.mkdir()
    for name in ("rotations.py", "problem_06.py"):
        (work / name).write_bytes((loader.template_dir() / name).read_bytes().replace(b"\n", b"\r\n"))
    cells = [c.replace("def frames():", "def Frames():").replace("A = frames()", "A = Frames()")
             for c in problem_06_cells(ROOT / "reference")]
    write_notebook(work / "problem_06.ipynb", ["import numpy as np", *cells])
    loaded = materialize(work, tmp_path)
    try:
        assert {"rotations.py", "problem_06.py"} <= set(loaded.template_copies)
        assert any("frames (problem_06), which none of your notebooks or files defines" in note
                   for note in loaded.problem_notes(6))
    finally:
        loader.cleanup(loaded)


def test_answers_saved_with_a_byte_order_mark_and_windows_line_ends_are_read(tmp_path):
    """Notepad before 2019 and PowerShell 5 save UTF-8 with a byte order mark, Windows's editors end lines with
    ``\\r\\n``: answers.toml is read all the same."""
    work = copy_reference(tmp_path / "work")
    text = (work / "answers.toml").read_text(encoding="utf-8")
    (work / "answers.toml").write_bytes(codecs.BOM_UTF8 + text.replace("\n", "\r\n").encode())
    loaded = materialize(work, tmp_path)
    try:
        answers, error = loader.read_answers(loaded.path)
        assert error is None and answers == tomllib.loads(text) and answers
        assert (loaded.answers, loaded.answers_error) == (answers, None)  # what the runner receives
    finally:
        loader.cleanup(loaded)


def test_reading_a_notebook_prints_no_warning_that_quotes_its_cells(tmp_path):
    """Parsing a cell can warn (an invalid escape sequence: a DeprecationWarning in Python 3.11, a SyntaxWarning,
    shown by default, from 3.12), and the warning quotes the cell's text, control characters included: the loader
    parses in silence."""
    (tmp_path / "mine.ipynb").write_text(json.dumps({
        "cells": [{"cell_type": "code", "metadata": {}, "outputs": [], "execution_count": None,
                   "source": 'def R1(a):\n    return "\\\x1b]0;title\x07"\n'}],
        "metadata": {}, "nbformat": 4, "nbformat_minor": 5}))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        loaded = materialize(tmp_path / "mine.ipynb", tmp_path)
    loader.cleanup(loaded)
    assert [str(w.message) for w in caught] == []
    assert any("→ rotations.py: R1" in note for note in loaded.notes)
