"""Turning a submission (a folder, a zip archive or Jupyter notebooks) into a private package directory.

The copy starts from the student template, so that a submission that lacks a module still imports (and its
functions report "not implemented yet"); the student's files are laid over it.  Nothing of the submission runs
here: files are read (never through a symbolic link, which is refused) and notebooks parsed, not executed.

Notebooks: the definitions of a notebook's code cells (see ``grader.sandbox.notebook`` for what counts) are placed
into the template's modules by name, whatever the notebook is called: ``R1`` goes to ``rotations``, ``frames`` to
``problem_06``.  A name that several modules define (``solve``, ``vectors``) goes to the problem of the section it
is written in (the nearest markdown heading above it that names a problem), else to the problem the notebook's
file name names (``problem_06.ipynb``, ``Problem 6.ipynb``), else to every module that defines it.  The worker
runs the definitions in the sandbox and puts them into those modules (``_notebooks.json`` tells it what goes
where); the report says which name went where and which names a problem needs that no file or notebook defines.
"""

from __future__ import annotations

import ast
import errno
import hashlib
import json
import os
import re
import shutil
import stat
import tempfile
import warnings
import zipfile
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path, PurePosixPath

from .errors import SubmissionError
from .sandbox.notebook import clean_cell, definitions

__all__ = ["Submission", "NotebookPlan", "materialize", "student_files", "submission_digest", "template_dir",
           "template_index", "content_hash", "read_answers", "notebook_plan", "MAX_FILES",
           "MAX_BYTES", "MAX_ENTRIES", "MAX_DEPTH", "MAX_NAME_BYTES", "MAX_PATH_BYTES", "MAX_NOTEBOOK_DEPTH", "FIX",
           "NOTEBOOK_MANIFEST"]

MAX_FILES = 500
MAX_BYTES = 50 * 2**20
#: entries of a folder looked at (kept or not) before it is refused as not a work folder, and its deepest nesting
MAX_ENTRIES = 5000
MAX_DEPTH = 8
#: the longest name of one file or folder (NAME_MAX of Linux's file systems, in bytes of UTF-8), and of a path
#: inside the submission
MAX_NAME_BYTES = 255
MAX_PATH_BYTES = 1024
#: the code of one notebook's cells (its outputs do not count), and the deepest nesting of its JSON (a notebook
#: nests some seven levels, a little more where an output holds JSON)
MAX_NOTEBOOK_CODE = 2 * 2**20
MAX_NOTEBOOK_DEPTH = 100
MAX_ANSWERS_BYTES = 2**20
IGNORED_DIRS = {"__pycache__", ".git", ".ipynb_checkpoints", "__MACOSX", ".venv", "venv", "node_modules"}
KEPT_SUFFIXES = {".py", ".toml", ".ipynb", ".md", ".txt"}
MODULE_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
#: what to do when the folder graded is not a work folder
FIX = "Run `grade` inside the folder that `grade init` made, or pass `--submission PATH`."
#: the file of the materialized package that tells the worker where the notebooks' definitions go
NOTEBOOK_MANIFEST = "_notebooks.json"
#: a problem named in a notebook's file name or in a markdown heading: "problem_06", "Problem 6", "P6"
PROBLEM_NAME = re.compile(r"(?:problem|aufgabe|prob|p)[\s_-]*0*(\d{1,2})(?!\d)", re.IGNORECASE)
#: the template's stub of a function that the student writes: NotImplementedError("Problem 6: ...")
_STUB = re.compile(r"^Problem (\d+):")


@dataclass(frozen=True)
class NotebookPlan:
    """Where the definitions of one notebook go."""

    file: str  # the notebook's name in the submission
    module: str  # the private module its code runs as, e.g. "_notebook_1"
    cells: tuple[tuple[int, str], ...]  # (cell number, code without IPython lines)
    defined: tuple[str, ...]  # every name its definitions bind, in order
    placed: dict = field(default_factory=dict)  # name -> tuple of template modules
    notes: tuple[str, ...] = ()


@dataclass(frozen=True)
class Submission:
    """A submission as the grader receives it: its private package, the student's files, the answers of its
    answers.toml (read as data, never run) and what its reports say about it."""

    source: str  # what the user pointed at, as given
    path: Path  # the private package directory (template + student's files)
    digest: str  # sha256 of the student's files (names and contents)
    files: tuple[str, ...]  # the student's files, as laid over the template
    notes: tuple[str, ...] = ()
    notebooks: tuple[NotebookPlan, ...] = ()
    template_copies: tuple[str, ...] = ()  # the student's files that are the template's, unchanged
    answers: dict = field(default_factory=dict, compare=False)  # the parsed answers.toml (``read_answers``)
    answers_error: str | None = None  # why answers.toml cannot be read, or None

    def problem_notes(self, number: int) -> tuple[str, ...]:
        """What the report of problem ``number`` says about the submission: its notes, and, for a submission with
        notebooks, the names the problem needs that neither a notebook nor a file of the student defines."""
        notes = list(self.notes)
        if not self.notebooks:
            return tuple(notes)
        needed = template_index()[1].get(number, ())
        given = {(target, name) for plan in self.notebooks for name, targets in plan.placed.items()
                 for target in targets}
        files = set(self.files) - set(self.template_copies)
        missing = [(m, n) for m, n in needed if (m, n) not in given and f"{m}.py" not in files]
        if missing:
            found = [n for plan in self.notebooks for n in plan.defined if not n.startswith("__")]
            shown = ", ".join(f"{n} ({m})" for m, n in missing)
            notes.append(f"problem {number} needs {shown}, which none of your notebooks or files defines; your "
                         f"notebooks define: {', '.join(dict.fromkeys(found)) or 'nothing'}")
        return tuple(notes)


def template_dir() -> Path:
    here = Path(__file__).resolve().parents[1] / "student_template"
    if here.is_dir():
        return here
    import importlib.util

    spec = importlib.util.find_spec("student_template")
    if spec is None or spec.origin is None:
        raise FileNotFoundError("the student template is not installed")
    return Path(spec.origin).parent


def _stub_problem(func: ast.AST) -> int | None:
    """The problem of a template function whose body is the stub ``raise NotImplementedError("Problem N: ...")``."""
    for node in ast.walk(func):
        if isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call) and node.exc.args:
            arg = node.exc.args[0]
            if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
                match = _STUB.match(arg.value)
                if match:
                    return int(match.group(1))
    return None


@lru_cache(maxsize=1)
def template_index() -> tuple[dict[str, tuple[str, ...]], dict[int, tuple[tuple[str, str], ...]]]:
    """The template's top-level names (name -> the modules that define it) and, per problem, the names a student
    writes for it (``(module, name)`` of every stub ``raise NotImplementedError("Problem N: ...")``)."""
    names: dict[str, list[str]] = {}
    required: dict[int, list[tuple[str, str]]] = {}
    for path in sorted(template_dir().glob("*.py")):
        module = path.stem
        if module == "__init__":
            continue
        for stmt in ast.parse(path.read_text(encoding="utf-8")).body:
            if isinstance(stmt, (ast.FunctionDef, ast.ClassDef)):
                bound = [stmt.name]
                number = _stub_problem(stmt)
                if number is not None:
                    required.setdefault(number, []).append((module, stmt.name))
            elif isinstance(stmt, ast.Assign):
                bound = [t.id for t in stmt.targets if isinstance(t, ast.Name)]
            elif isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name):
                bound = [stmt.target.id]
            else:
                bound = []
            for name in bound:
                if not name.startswith("__"):
                    names.setdefault(name, []).append(module)
    return ({k: tuple(dict.fromkeys(v)) for k, v in names.items()},
            {k: tuple(v) for k, v in sorted(required.items())})


@lru_cache(maxsize=1)
def template_modules() -> frozenset[str]:
    return frozenset(p.stem for p in template_dir().glob("*.py"))


def content_hash(files: dict[str, bytes]) -> str:
    digest = hashlib.sha256()
    for name in sorted(files):
        digest.update(name.encode() + b"\0" + hashlib.sha256(files[name]).digest())
    return digest.hexdigest()


def _printable(name: str) -> str:
    """A file name as the report shows it: as is when it is valid UTF-8, else its bytes."""
    try:
        name.encode("utf-8")
    except UnicodeEncodeError:
        return repr(os.fsencode(name))[2:-1]
    return name


def _valid_name(name: str) -> bool:
    try:
        name.encode("utf-8")
    except UnicodeEncodeError:  # os.fsdecode turned bytes that are not UTF-8 into surrogates
        return False
    return True


def _refuse_links(links: list[str]) -> None:
    if links:
        shown = ", ".join(links[:5]) + (f" and {len(links) - 5} more" if len(links) > 5 else "")
        raise SubmissionError(f"the submission holds symbolic links, which the grader never follows: {shown}. "
                              "Put the files themselves in their place.")


# ------------------------------------------------------------------------------------------ reading a folder
#
# Where the platform has them (Linux, macOS), a folder is read relative to an open descriptor of its own: each
# entry is opened with ``dir_fd`` and ``O_NOFOLLOW`` (a folder with ``O_DIRECTORY`` too), so that no link is
# followed, inside the submission or at its root, and nothing can be swapped between the check of an entry and its
# opening: what is read is the entry that was listed.
#
# Windows has none of these (no descriptor of a folder, no ``dir_fd``, no ``O_NOFOLLOW``).  There each entry is
# checked with ``os.lstat`` before it is opened, and a symbolic link, a junction or another reparse point that
# names another file is refused as a link is on Linux; a file is opened by its path and read only when the file
# opened is the file checked (its file number, ``st_ino``), so that a file swapped for a link after its check is
# left out; a folder is listed by its path and its entries kept only when, after the listing, it is still the
# folder checked and still no link.  What is weaker there: a process that swaps a folder of the submission for a
# junction while the grader lists it, and back before the folder is checked again, could have a file under the
# junction's target read as the student's.  That is acceptable where this way runs: the student kit's portable
# mode, the student's own files and code on the student's own machine, read with the student's own rights (a
# file the grader could be tricked into reading there is one the student may read anyway), never instructor
# grading, which runs on Linux.

#: Windows's reparse points that name another file (symbolic links, junctions, WSL's links: the tags for which
#: ``IsReparseTagNameSurrogate`` holds), never followed; the others (a file that OneDrive keeps online, a
#: deduplicated file) are files as any other
_NAME_SURROGATE = 0x20000000
#: the reparse tag of a junction (IO_REPARSE_TAG_MOUNT_POINT)
_JUNCTION = 0xA0000003


def _relative_reads() -> bool:
    """Whether this platform reads a folder relative to a descriptor of its own, never through a link (Linux,
    macOS: ``dir_fd`` for open, stat and readlink, ``scandir`` of a descriptor, ``O_NOFOLLOW``, ``O_DIRECTORY``)."""
    return (hasattr(os, "O_NOFOLLOW") and hasattr(os, "O_DIRECTORY") and os.scandir in os.supports_fd
            and {os.open, os.stat, os.readlink} <= os.supports_dir_fd)


def _read_flags() -> int:
    """How a submission's file is opened, as far as the platform can: never through a link, never waiting for a
    writer (a FIFO), not inherited by a child, and in binary (from a descriptor that Windows opens in text mode,
    ``\\r\\n`` is read as ``\\n`` and the byte 0x1a ends the file)."""
    flags = os.O_RDONLY
    for name in ("O_NOFOLLOW", "O_NONBLOCK", "O_CLOEXEC", "O_BINARY", "O_NOINHERIT"):
        flags |= getattr(os, name, 0)
    return flags


def _link_kind(info: os.stat_result) -> str | None:
    """What kind of link an entry is, as ``os.lstat`` describes it: "symbolic link", "junction" or (another
    reparse point of Windows that names another file) "link"; None for anything else."""
    if stat.S_ISLNK(info.st_mode):
        return "symbolic link"
    if not getattr(info, "st_file_attributes", 0) & stat.FILE_ATTRIBUTE_REPARSE_POINT:
        return None
    tag = getattr(info, "st_reparse_tag", 0)
    if tag == _JUNCTION:
        return "junction"
    return "link" if tag & _NAME_SURROGATE else None


def _same_file(checked: os.stat_result, opened: os.stat_result) -> bool:
    """Whether what was opened is what was checked: the same file number (``st_ino``).  Where the file system
    gives none (0), nothing can be told, and they are taken to be the same."""
    return not checked.st_ino or not opened.st_ino or checked.st_ino == opened.st_ino


def _read_open(fd: int, limit: int, checked: os.stat_result | None = None) -> bytes | None:
    """The bytes (at most ``limit`` + 1) of the open ``fd`` when it is a regular file (and ``checked``'s, when
    given); None otherwise.  Closes ``fd``."""
    try:
        opened = os.fstat(fd)
        if not stat.S_ISREG(opened.st_mode) or (checked is not None and not _same_file(checked, opened)):
            return None
        with os.fdopen(os.dup(fd), "rb") as handle:
            return handle.read(limit + 1)
    finally:
        os.close(fd)


@dataclass(frozen=True)
class _Entry:
    """One entry of a folder as a reader sees it: its name, its kind ("link", "folder" or "file": a file may
    still turn out not to be a regular one), a link's target, and how ``os.lstat`` described it (path reads)."""

    name: str
    kind: str
    target: str = ""
    info: os.stat_result | None = None


class _AtDescriptors:
    """Reading a folder relative to a descriptor of its own (Linux, macOS): a folder is an open descriptor."""

    @staticmethod
    def root(root: Path) -> int:
        return os.open(root, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC)

    @staticmethod
    def entries(folder: int) -> list[_Entry]:
        with os.scandir(folder) as listing:
            found = sorted(listing, key=lambda e: e.name)
        return [_AtDescriptors._entry(folder, entry) for entry in found]

    @staticmethod
    def _entry(folder: int, entry: os.DirEntry) -> _Entry:
        if entry.is_symlink():
            try:
                target = _printable(os.readlink(entry.name, dir_fd=folder))
            except OSError:
                target = "?"
            return _Entry(entry.name, "link", target)
        return _Entry(entry.name, "folder" if entry.is_dir(follow_symlinks=False) else "file")

    @staticmethod
    def enter(folder: int, entry: _Entry) -> int:
        return os.open(entry.name, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC, dir_fd=folder)

    @staticmethod
    def read(folder: int, entry: _Entry, limit: int) -> bytes | None:
        try:
            return _read_open(os.open(entry.name, _read_flags(), dir_fd=folder), limit)
        except OSError:
            return None

    @staticmethod
    def leave(folder: int) -> None:
        os.close(folder)


class _ByPath:
    """Reading a folder by the paths of its entries, each checked with ``os.lstat`` before it is used (Windows;
    see above for what this does not guard against, and why that is acceptable there): a folder is its path and
    how ``os.lstat`` described it when it was checked."""

    @staticmethod
    def _folder(path: Path) -> tuple[Path, os.stat_result]:
        info = os.lstat(path)
        kind = _link_kind(info)
        if kind is not None:
            raise OSError(errno.ELOOP, f"it is a {kind}, which the grader never follows")
        if not stat.S_ISDIR(info.st_mode):
            raise OSError(errno.ENOTDIR, "it is not a folder")
        return path, info

    @staticmethod
    def root(root: Path) -> tuple[Path, os.stat_result]:
        return _ByPath._folder(root)

    @staticmethod
    def entries(folder: tuple[Path, os.stat_result]) -> list[_Entry]:
        path, checked = folder
        with os.scandir(path) as listing:
            names = sorted(entry.name for entry in listing)
        again = os.lstat(path)  # the folder listed was the folder checked, and is still no link
        if _link_kind(again) is not None or not stat.S_ISDIR(again.st_mode) or not _same_file(checked, again):
            raise OSError(errno.EIO, "it was replaced while it was read")
        return [_ByPath._entry(path, name) for name in names]

    @staticmethod
    def _entry(folder: Path, name: str) -> _Entry:
        try:
            info = os.lstat(folder / name)
        except OSError:  # gone since the listing, or a name the system cannot look up: left out as unreadable
            return _Entry(name, "file")
        kind = _link_kind(info)
        if kind is not None:
            try:
                target = _printable(os.readlink(folder / name))
            except (OSError, ValueError):
                target = "?"
            return _Entry(name, "link", target if kind == "symbolic link" else f"{target} (a {kind})", info)
        return _Entry(name, "folder" if stat.S_ISDIR(info.st_mode) else "file", info=info)

    @staticmethod
    def enter(folder: tuple[Path, os.stat_result], entry: _Entry) -> tuple[Path, os.stat_result]:
        path, info = folder[0] / entry.name, entry.info
        if info is None or not stat.S_ISDIR(info.st_mode):
            raise OSError(errno.ENOTDIR, "it is not a folder")
        return path, info

    @staticmethod
    def read(folder: tuple[Path, os.stat_result], entry: _Entry, limit: int) -> bytes | None:
        if entry.info is None or not stat.S_ISREG(entry.info.st_mode):  # a FIFO, a device: never opened
            return None
        try:
            return _read_open(os.open(folder[0] / entry.name, _read_flags()), limit, entry.info)
        except OSError:
            return None

    @staticmethod
    def leave(folder) -> None:
        pass


def _is_submission_file(name: str) -> bool:
    path = PurePosixPath(name)
    return (path.suffix == ".ipynb" or name in ("answers.toml", "__init__.py")
            or (path.suffix == ".py" and path.stem in template_modules()))


def _visible(name: str) -> bool:
    return name not in IGNORED_DIRS and not name.startswith(".")


def _recognised(root: Path, wrapped: bool = True) -> bool:
    """Whether ``root`` looks like a work folder: a module of the template, answers.toml or a notebook at its
    top, or (``wrapped``) a single folder that does (a submission wrapped in one folder).  Only the top level
    and that one folder are listed."""
    try:
        with os.scandir(root) as listing:
            entries = [e for _, e in zip(range(MAX_ENTRIES), listing) if _visible(e.name)]
    except OSError:
        return False
    if any(e.is_file(follow_symlinks=False) and _is_submission_file(e.name) for e in entries):
        return True
    return (wrapped and len(entries) == 1 and entries[0].is_dir(follow_symlinks=False)
            and _valid_name(entries[0].name) and _recognised(root / entries[0].name, wrapped=False))


def _collect_dir(root: Path) -> tuple[dict[str, bytes], list[str]]:
    """The student's files under ``root`` and notes on what was left out.  Never follows a link (a link is
    refused), reads regular files only, and stops at ``MAX_ENTRIES`` entries.  Read relative to descriptors
    where the platform can (``_AtDescriptors``), else by path (``_ByPath``)."""
    files: dict[str, bytes] = {}
    notes: list[str] = []
    links: list[str] = []
    total = seen = 0
    reader = _AtDescriptors if _relative_reads() else _ByPath

    def walk(folder, prefix: str, depth: int) -> None:
        nonlocal total, seen
        for entry in reader.entries(folder):
            seen += 1
            if seen > MAX_ENTRIES or depth > MAX_DEPTH:
                raise SubmissionError(f"{root} holds more than {MAX_ENTRIES} entries or folders nested deeper than "
                                      f"{MAX_DEPTH}: it is not a work folder. {FIX}")
            if not _visible(entry.name):
                continue
            rel = prefix + entry.name
            if not _valid_name(entry.name):
                notes.append(f"left out {_printable(rel)}: its name is not valid UTF-8 (rename it with plain "
                             "letters, digits and _)")
                continue
            if entry.kind == "link":
                links.append(f"{rel} → {entry.target}")
                continue
            if entry.kind == "folder":
                try:
                    sub = reader.enter(folder, entry)
                except OSError as exc:
                    notes.append(f"left out the folder {rel}: it cannot be read ({exc.strerror})")
                    continue
                try:
                    walk(sub, rel + "/", depth + 1)
                except OSError as exc:
                    notes.append(f"left out the folder {rel}: it cannot be read ({exc.strerror})")
                finally:
                    reader.leave(sub)
                continue
            if PurePosixPath(entry.name).suffix not in KEPT_SUFFIXES:
                continue
            data = reader.read(folder, entry, MAX_BYTES)
            if data is None:
                notes.append(f"left out {rel}: it is not a regular file that can be read")
                continue
            total += len(data)
            if len(files) >= MAX_FILES or total > MAX_BYTES:
                raise SubmissionError(f"the submission is too large (more than {MAX_FILES} files or "
                                      f"{MAX_BYTES // 2**20} MB of source)")
            files[rel] = data

    try:
        top = reader.root(root)
    except OSError as exc:
        raise SubmissionError(f"{root} cannot be read: {exc.strerror}") from exc
    try:
        walk(top, "", 0)
    except OSError as exc:
        raise SubmissionError(f"{root} cannot be read: {exc.strerror}") from exc
    finally:
        reader.leave(top)
    _refuse_links(links)
    return files, notes


def _collect_zip(path: Path) -> dict[str, bytes]:
    files: dict[str, bytes] = {}
    links: list[str] = []
    total = 0
    try:
        with zipfile.ZipFile(path) as archive:
            infos = archive.infolist()
            if len(infos) > MAX_ENTRIES:
                raise SubmissionError(f"the archive {path.name} holds more than {MAX_ENTRIES} entries: it is not a "
                                      f"work folder. {FIX}")
            for info in infos:
                if info.is_dir():
                    continue
                name = PurePosixPath(info.filename.replace("\\", "/"))
                if name.is_absolute() or ".." in name.parts or any(p in IGNORED_DIRS for p in name.parts):
                    continue
                if stat.S_ISLNK(info.external_attr >> 16):
                    links.append(name.as_posix())
                    continue
                if name.suffix not in KEPT_SUFFIXES:
                    continue
                total += info.file_size
                if len(files) >= MAX_FILES or total > MAX_BYTES:
                    raise SubmissionError(f"the archive is too large (more than {MAX_FILES} files or "
                                          f"{MAX_BYTES // 2**20} MB unpacked)")
                with archive.open(info) as handle:
                    data = handle.read(MAX_BYTES + 1)
                if len(data) > info.file_size:
                    raise SubmissionError(f"{name} in the archive is larger than its header says")
                files[name.as_posix()] = data
    except (zipfile.BadZipFile, OSError, RuntimeError, NotImplementedError, EOFError, ValueError) as exc:
        raise SubmissionError(f"{path.name} is not a readable zip archive: {exc}. Make the archive again from the "
                              "folder that `grade init` made (or submit the folder itself).") from exc
    _refuse_links(links)
    return files


def _strip_common_folder(files: dict[str, bytes]) -> dict[str, bytes]:
    """A zip of a folder holds ``folder/...``: use what is inside the folder (when nothing lies beside it, not
    even a file of the folder's name)."""
    while files:
        heads = {name.split("/", 1)[0] for name in files}
        if len(heads) != 1 or any("/" not in name for name in files):
            break
        head = heads.pop() + "/"
        files = {name[len(head):]: data for name, data in files.items() if name.startswith(head)}
    return files


def _shown_name(name: str) -> str:
    """A name as a message shows it: a long one cut short."""
    return name if len(name) <= 60 else f"{name[:40]}…{name[-12:]} ({len(name.encode())} bytes)"


#: a name that Windows cannot give a file: one of its reserved characters (``:`` among them, which makes ``D:``
#: a drive and ``a:b`` a stream of the file ``a``) or a control character, a dot or a space at its end (dropped
#: there), or a device's name with any extension (``con.py``, ``nul.txt``: a write to it reaches the device)
_NOT_A_WINDOWS_NAME = re.compile(r'[<>:"|?*\\\x00-\x1f]|[. ]$|^(con|prn|aux|nul|com\d|lpt\d)(\.|$)', re.IGNORECASE)


def _windows_names() -> bool:
    """Whether the submission is laid out on Windows, whose names are narrower than a zip archive's."""
    return os.name == "nt"


def _check_names(files: dict[str, bytes]) -> None:
    """Refuse (``SubmissionError``, one reason) the names that cannot be laid over the template: a file or folder
    name longer than ``MAX_NAME_BYTES``, a path longer than ``MAX_PATH_BYTES`` or deeper than ``MAX_DEPTH``, a
    name that is both a file and a folder of the submission (``foo.py`` and ``foo.py/bar.py``), a folder
    where the template has a file (a folder ``rotations.py/``), and on Windows a name that Windows cannot give a
    file (``_NOT_A_WINDOWS_NAME``: only an archive made elsewhere holds one)."""
    folders: set[str] = set()
    windows = _windows_names()
    for name in files:
        parts = name.split("/")
        odd = next((part for part in parts if _NOT_A_WINDOWS_NAME.search(part)), None) if windows else None
        if odd is not None:
            raise SubmissionError(f"the submission holds {_shown_name(odd)!r}, a name that Windows cannot give a "
                                  "file (it holds one of < > : \" | ? * \\, ends in a dot or a space, or names a "
                                  "device, such as CON or NUL): rename it.")
        long = next((part for part in parts if len(part.encode()) > MAX_NAME_BYTES), None)
        if long is not None:
            raise SubmissionError(f"the submission holds a name longer than {MAX_NAME_BYTES} bytes, which no file "
                                  f"system stores: {_shown_name(long)}. Rename it.")
        if len(parts) - 1 > MAX_DEPTH:
            raise SubmissionError(f"the submission holds {_shown_name(name)}, in folders nested deeper than "
                                  f"{MAX_DEPTH}: it is not a work folder. {FIX}")
        if len(name.encode()) > MAX_PATH_BYTES:
            raise SubmissionError(f"the submission holds a path longer than {MAX_PATH_BYTES} bytes: "
                                  f"{_shown_name(name)}. Shorten the names of its folders.")
        folders.update("/".join(parts[:end]) for end in range(1, len(parts)))
    both = sorted(folders & set(files))
    if both:
        raise SubmissionError(f"the submission holds both a file and a folder named {_shown_name(both[0])}: rename "
                              "the folder.")
    taken = sorted(folder for folder in folders if (template_dir() / folder).is_file())
    if taken:
        raise SubmissionError(f"the submission holds a folder named {_shown_name(taken[0])}, which is a file of the "
                              "template: rename the folder (or put the file itself in its place).")


# ------------------------------------------------------------------------------------------ notebooks


def _notebook_json(data: bytes, name: str):
    """The JSON of the notebook ``name``, no deeper than ``MAX_NOTEBOOK_DEPTH``; ``SubmissionError`` when it
    cannot be read."""
    try:
        value = json.loads(data.decode("utf-8"))
    except RecursionError:
        value = None
    except (UnicodeDecodeError, ValueError) as exc:
        raise SubmissionError(f"the notebook {name} cannot be read ({str(exc)[:300]}). Open it in Jupyter, save it "
                              "again (File → Save) and submit that file.") from None
    if value is None or _deeper_than(value, MAX_NOTEBOOK_DEPTH):
        raise SubmissionError(f"the notebook {name} cannot be read: its JSON is nested deeper than "
                              f"{MAX_NOTEBOOK_DEPTH} levels, which no notebook is. Open it in Jupyter, save it "
                              "again (File → Save) and submit that file.")
    return value


def _deeper_than(value, limit: int) -> bool:
    """Whether the lists and objects of a JSON value nest deeper than ``limit`` (walked without recursion)."""
    stack = [(value, 1)]
    while stack:
        item, depth = stack.pop()
        if isinstance(item, (dict, list)):
            if depth > limit:
                return True
            stack.extend((child, depth + 1) for child in (item.values() if isinstance(item, dict) else item))
    return False


def _read_notebook(data: bytes, name: str):
    """The notebook ``name`` as nbformat's version 4 (read, converted, not validated: what is missing is looked
    up with defaults)."""
    import nbformat
    from nbformat.reader import get_version

    value = _notebook_json(data, name)
    try:
        major, minor = get_version(value)
        notebook = nbformat.versions[major].to_notebook_json(value, minor=minor)
        return nbformat.convert(notebook, 4)
    except Exception as exc:  # noqa: BLE001 - nbformat raises many kinds of errors for malformed input
        reason = str(exc).strip().splitlines()[0][:300] if str(exc).strip() else type(exc).__name__
        raise SubmissionError(f"the notebook {name} cannot be read ({reason}). Open it in Jupyter, save it "
                              "again (File → Save) and submit that file.") from exc


def _problem_in(text: str) -> int | None:
    match = PROBLEM_NAME.search(text)
    return int(match.group(1)) if match else None


def _section_problem(cell) -> int | None:
    """The problem that a markdown heading (or a code cell's first comment) names."""
    source = str(cell.get("source", ""))
    if cell.get("cell_type") == "markdown":
        lines = [line for line in source.splitlines() if line.lstrip().startswith("#")]
    elif cell.get("cell_type") == "code":
        lines = source.lstrip().splitlines()[:1]
        lines = [line for line in lines if line.startswith("#")]
    else:
        lines = []
    for line in lines:
        number = _problem_in(line)
        if number is not None:
            return number
    return None


def _place(name: str, modules: tuple[str, ...], section: int | None, file_problem: int | None) -> tuple[str, ...]:
    if len(modules) == 1:
        return modules
    for number in (section, file_problem):
        if number is not None and f"problem_{number:02d}" in modules:
            return (f"problem_{number:02d}",)
    return modules


def notebook_plan(file: str, data: bytes, module: str) -> NotebookPlan:
    """Where the definitions of the notebook ``file`` go (its code is parsed, never run here)."""
    notebook = _read_notebook(data, file)
    names_index, _ = template_index()
    file_problem = _problem_in(PurePosixPath(file).stem)
    section = None
    cells: list[tuple[int, str]] = []
    defined: dict[str, int | None] = {}  # name -> the section it was (last) defined in
    notes: list[str] = []
    size = dropped = 0
    for number, cell in enumerate(notebook.get("cells", []), 1):
        section = _section_problem(cell) or section
        if cell.get("cell_type") != "code":
            continue
        code, lines = clean_cell(str(cell.get("source", "")))
        dropped += lines
        size += len(code)
        if size > MAX_NOTEBOOK_CODE:
            raise SubmissionError(f"the notebook {file} holds more than {MAX_NOTEBOOK_CODE // 2**20} MB of code")
        try:
            with warnings.catch_warnings():  # a parser's warning quotes the cell's text: never printed here
                warnings.simplefilter("ignore")
                names = definitions(code)
        except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
            where = f", line {exc.lineno}" if isinstance(exc, SyntaxError) and exc.lineno else ""
            notes.append(f"notebook {file}: cell {number} was left out: it does not parse ({type(exc).__name__}"
                         f"{where}: {getattr(exc, 'msg', exc)})")
            continue
        cells.append((number, code))
        for name in names:
            defined.pop(name, None)
            defined[name] = section
    placed: dict[str, tuple[str, ...]] = {}
    for name, where in defined.items():
        if name.startswith("__") or name not in names_index:
            continue
        placed[name] = _place(name, names_index[name], where, file_problem)
    by_module: dict[str, list[str]] = {}
    for name, modules in placed.items():
        for target in modules:
            by_module.setdefault(target, []).append(name)
    for target in sorted(by_module):
        notes.append(f"notebook {file} → {target}.py: {', '.join(sorted(by_module[target]))}")
    several = sorted(n for n, m in placed.items() if len(m) > 1)
    if several:
        notes.append(f"notebook {file}: {', '.join(several)} went to every module that has the name, as neither "
                     "a heading above it (\"## Problem 9\") nor the notebook's name says which problem it is for")
    others = [n for n in defined if n not in placed and not n.startswith("_")]
    if others:
        notes.append(f"notebook {file}: also defined (not names of the template; your functions may use them): "
                     f"{', '.join(others[:20])}{' …' if len(others) > 20 else ''}")
    if dropped:
        notes.append(f"notebook {file}: {dropped} IPython line{'s' if dropped != 1 else ''} (magics, shell "
                     "commands) left out")
    if not cells:
        notes.append(f"notebook {file}: no code cell holds a definition")
    return NotebookPlan(file, module, tuple(cells), tuple(defined), placed, tuple(notes))


# ------------------------------------------------------------------------------------------ the submission


def _single_file(source: Path) -> dict[str, bytes]:
    """A submission of one file (a notebook), never read through a link: opened with ``O_NOFOLLOW``, or where the
    platform reads by path (Windows), only when the file opened is the one ``os.lstat`` saw, which was no link."""
    checked = None
    try:
        if not _relative_reads():
            checked = os.lstat(source)
            if _link_kind(checked) is not None or not stat.S_ISREG(checked.st_mode):
                raise SubmissionError(f"{source} is not a regular file")
        fd = os.open(source, _read_flags())
    except OSError as exc:
        raise SubmissionError(f"{source} cannot be read: {exc.strerror}") from exc
    try:
        data = _read_open(fd, MAX_BYTES, checked)
    except OSError as exc:
        raise SubmissionError(f"{source} cannot be read: {exc.strerror}") from exc
    if data is None:
        raise SubmissionError(f"{source} is not a regular file")
    if len(data) > MAX_BYTES:
        raise SubmissionError(f"{source.name} is larger than {MAX_BYTES // 2**20} MB")
    return {source.name: data}


def _student_files(source: Path) -> tuple[dict[str, bytes], list[str]]:
    """The student's files (name -> bytes) and notes on what was left out."""
    shown = os.path.abspath(source)
    try:
        link = _link_kind(os.lstat(source))
    except (OSError, ValueError):
        link = None
    if link is not None:
        raise SubmissionError(f"{shown} is a {link}, which the grader never follows: submit the folder or file "
                              "itself")
    if not source.exists():
        raise SubmissionError(f"{shown} does not exist. {FIX}")
    notes: list[str] = []
    if source.is_dir():
        if not _recognised(source):
            try:
                empty = not any(_visible(name) for name in os.listdir(source))
            except OSError:
                empty = False
            what = "is empty" if empty else ("holds no module of the template (such as rotations.py or "
                                             "problem_06.py), no answers.toml and no notebook")
            raise SubmissionError(f"{shown} is not a work folder: it {what}. {FIX}")
        files, notes = _collect_dir(source)
    elif source.suffix == ".zip":
        files = _collect_zip(source)
    elif source.suffix in (".ipynb", ".py", ".toml"):
        files = _single_file(source)
    else:
        raise SubmissionError(f"{source.name}: expected a folder, a .zip archive or a .ipynb notebook")
    files = _strip_common_folder(files)
    _check_names(files)
    if not files:
        raise SubmissionError(f"{source.name} holds no Python files, notebooks or answers.toml. {FIX}")
    return files, notes


def student_files(source: str | Path) -> dict[str, bytes]:
    """The student's files of a submission (name -> bytes), read as ``materialize`` reads them (no links followed,
    sizes bounded), without copying the template; ``SubmissionError`` when it cannot be loaded."""
    return _student_files(Path(source))[0]


def submission_digest(source: str | Path) -> str:
    """The content hash of a submission as ``materialize`` would compute it (names and contents of the
    student's files), without copying anything."""
    return content_hash(_student_files(Path(source))[0])


def materialize(source: str | Path, workdir: str | Path | None = None) -> Submission:
    """Copy the template and lay the submission over it in a fresh private directory; a notebook's definitions
    are planned into the template's modules (``NOTEBOOK_MANIFEST``), to be run by the sandboxed worker.  The
    submission's answers.toml is read here, before any of its code runs."""
    given, source = str(source), Path(source)
    files, notes = _student_files(source)
    digest = content_hash(files)
    books = sorted((n, d) for n, d in files.items() if n.endswith(".ipynb") and not _template_notebook(n, d))
    plans = [notebook_plan(name, data, f"_notebook_{index}") for index, (name, data) in enumerate(books, 1)]
    root = Path(tempfile.mkdtemp(prefix="submission-", dir=workdir))
    try:
        target = root / "pkg"
        shutil.copytree(template_dir(), target, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        laid: list[str] = []
        copies: list[str] = []
        for name, data in files.items():
            if name.endswith(".ipynb"):
                laid.append(name)
                if _template_notebook(name, data):
                    copies.append(name)
                continue
            out = target / PurePosixPath(name)
            if out.is_file() and _same_text(out.read_bytes(), data):
                copies.append(name)
            out.parent.mkdir(parents=True, exist_ok=True)
            out.write_bytes(data)
            laid.append(name)
        if plans:
            manifest = [{"file": p.file, "module": p.module, "cells": [list(c) for c in p.cells],
                         "defined": list(p.defined), "placed": {k: list(v) for k, v in p.placed.items()}}
                        for p in plans]
            (target / NOTEBOOK_MANIFEST).write_text(json.dumps({"notebooks": manifest}), encoding="utf-8")
            notes += [note for p in plans for note in p.notes]
            notes += _overlaps(plans)
        for dirpath, dirnames, filenames in os.walk(root):
            os.chmod(dirpath, 0o755)
            for fname in filenames:
                os.chmod(os.path.join(dirpath, fname), 0o644)
        answers, answers_error = read_answers(target)
    except BaseException:
        shutil.rmtree(root, ignore_errors=True)
        raise
    return Submission(given, target, digest, tuple(sorted(laid)), tuple(notes), tuple(plans),
                      tuple(sorted(copies)), answers, answers_error)


def _same_text(template: bytes, data: bytes) -> bool:
    """Whether a student's file is the template's file: the same bytes, or the same lines ended by ``\\r\\n``
    (a work folder checked out by git on Windows, ``core.autocrlf``)."""
    return data == template or data.replace(b"\r\n", b"\n") == template


def _overlaps(plans: list[NotebookPlan]) -> list[str]:
    """Names that several notebooks put into the same module: the last notebook (by name) is graded."""
    owner: dict[tuple[str, str], str] = {}
    notes = []
    for plan in plans:
        for name, targets in plan.placed.items():
            for target in targets:
                if (target, name) in owner:
                    notes.append(f"{name} ({target}) is defined in {owner[(target, name)]} and in {plan.file}: "
                                 f"{plan.file}'s is graded")
                owner[(target, name)] = plan.file
    return notes


# ------------------------------------------------------------------------------------------ grade init --notebook


def _jupyter_import(stmt: ast.stmt, defined: set[str]) -> str | None:
    """An import of a template module as a notebook writes it: ``from .rotations import R1`` becomes ``from
    rotations import R1`` (the work folder is the notebook's working folder), without the names the notebook
    defines itself."""
    if isinstance(stmt, ast.Import):
        return ast.unparse(stmt)
    if not isinstance(stmt, ast.ImportFrom):
        return None
    names = [a for a in stmt.names if (a.asname or a.name) not in defined]
    if not names:
        return None
    module = stmt.module if stmt.level == 0 else (stmt.module or "")
    if stmt.level and not module:  # "from . import x": x is a module of the package
        return "\n".join(f"import {a.name}" + (f" as {a.asname}" if a.asname else "") for a in names)
    return ast.unparse(ast.ImportFrom(module=module, names=names, level=0))


def template_notebooks() -> dict[str, object]:
    """The student template as notebooks, one per problem that has functions to write (``problem_06.ipynb``:
    the problem's text, the imports its code needs, the problem's constants and a cell per function or class to
    write, each with its docstring and stub)."""
    from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

    _, required = template_index()
    sources = {p.stem: p.read_text(encoding="utf-8") for p in template_dir().glob("*.py")}
    trees = {name: ast.parse(text) for name, text in sources.items()}
    books = {}
    for number, names in required.items():
        own = f"problem_{number:02d}"
        modules = list(dict.fromkeys([own, *(m for m, _ in names)]))
        defined = {n for _, n in names}
        constants = []
        if own in trees:
            for stmt in trees[own].body:
                if isinstance(stmt, (ast.Assign, ast.AnnAssign)) and not any(
                        isinstance(t, ast.Name) and t.id.startswith("__")
                        for t in getattr(stmt, "targets", [getattr(stmt, "target", None)])):
                    constants.append(ast.get_source_segment(sources[own], stmt))
                    defined |= {t.id for t in getattr(stmt, "targets", [getattr(stmt, "target", None)])
                                if isinstance(t, ast.Name)}
        imports = []
        for module in modules:
            for stmt in trees.get(module, ast.Module(body=[])).body:
                line = _jupyter_import(stmt, defined)
                if line and line not in imports:
                    imports.append(line)
        doc = (ast.get_docstring(trees[own]) if own in trees else "") or f"Problem {number}"
        title, _, text = doc.partition("\n")
        cells = [new_markdown_cell(f"# {title}\n{text}\n\nWrite your solution in the cells below, "
                                   f"keeping the names and signatures. `grade problem-{number}` in this folder "
                                   "grades this notebook: it takes the definitions (functions, classes, constants, "
                                   "imports) of its code cells; prints, plots and other statements are yours.")]
        if imports:
            cells.append(new_code_cell("\n".join(imports)))
        if constants:
            cells.append(new_code_cell("\n".join(constants)))
        for module, name in names:
            stmt = next(s for s in trees[module].body if getattr(s, "name", None) == name)
            cells.append(new_markdown_cell(f"`{name}` (goes to `{module}.py`)"))
            cells.append(new_code_cell(ast.get_source_segment(sources[module], stmt)))
        books[f"{own}.ipynb"] = new_notebook(cells=cells)
    return books


@lru_cache(maxsize=1)
def _template_code() -> dict[str, tuple[str, ...]]:
    return {name: tuple(c.source for c in book.cells if c.cell_type == "code")
            for name, book in template_notebooks().items()}


def _template_notebook(name: str, data: bytes) -> bool:
    """Whether the notebook ``name`` is one of ``grade init --notebook``'s, its code unchanged (nothing of it
    needs to run: the template's modules hold the same stubs)."""
    expected = _template_code().get(name)
    if expected is None:
        return False
    try:
        cells = _notebook_json(data, name).get("cells", [])
        code = tuple("".join(c["source"]) if isinstance(c["source"], list) else c["source"]
                     for c in cells if c.get("cell_type") == "code")
    except (SubmissionError, AttributeError, KeyError, TypeError):  # not the template's: read as a notebook
        return False
    return code == expected


def read_answers(package: Path) -> tuple[dict, str | None]:
    """The parsed answers.toml of a materialized submission, or an error text (no code runs: TOML only).  A byte
    order mark before it (Notepad before 2019 and PowerShell 5 write UTF-8 so) is not part of it."""
    import tomllib

    path = package / "answers.toml"
    if not path.exists():
        return {}, None
    if path.stat().st_size > MAX_ANSWERS_BYTES:
        return {}, f"answers.toml is larger than {MAX_ANSWERS_BYTES // 1024} kB"
    try:
        return tomllib.loads(path.read_text(encoding="utf-8-sig")), None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        return {}, f"answers.toml is not valid TOML: {exc}"
    except RecursionError:
        return {}, "answers.toml is not valid TOML: its arrays or tables are nested too deep to be read"


def cleanup(submission: Submission) -> None:
    shutil.rmtree(submission.path.parent, ignore_errors=True)
