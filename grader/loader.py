"""Turning a submission (a directory, a zip archive or Jupyter notebooks) into a private package directory.

The copy starts from the student template, so that a submission that lacks a module still imports (and its
functions report "not implemented yet"); the student's files are laid over it.  Notebooks become modules: the
code cells of ``problem_06.ipynb`` become ``problem_06.py``.  Nothing of the submission runs here.
"""

from __future__ import annotations

import hashlib
import os
import re
import shutil
import stat
import tempfile
import zipfile
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

from .errors import SubmissionError

__all__ = ["Submission", "materialize", "submission_digest", "template_dir", "content_hash", "read_answers",
           "MAX_FILES", "MAX_BYTES"]

MAX_FILES = 500
MAX_BYTES = 50 * 2**20
MAX_ANSWERS_BYTES = 2**20
IGNORED_DIRS = {"__pycache__", ".git", ".ipynb_checkpoints", "__MACOSX", ".venv", "venv", "node_modules"}
KEPT_SUFFIXES = {".py", ".toml", ".ipynb", ".md", ".txt"}
MODULE_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


@dataclass(frozen=True)
class Submission:
    source: str  # what the user pointed at
    path: Path  # the private package directory (template + student's files)
    digest: str  # sha256 of the student's files (names and contents)
    files: tuple[str, ...]  # the student's files, as laid over the template
    notes: tuple[str, ...] = ()


def template_dir() -> Path:
    here = Path(__file__).resolve().parents[1] / "student_template"
    if here.is_dir():
        return here
    import importlib.util

    spec = importlib.util.find_spec("student_template")
    if spec is None or spec.origin is None:
        raise FileNotFoundError("the student template is not installed")
    return Path(spec.origin).parent


def content_hash(files: dict[str, bytes]) -> str:
    digest = hashlib.sha256()
    for name in sorted(files):
        digest.update(name.encode() + b"\0" + hashlib.sha256(files[name]).digest())
    return digest.hexdigest()


def _collect_dir(root: Path) -> dict[str, bytes]:
    files: dict[str, bytes] = {}
    total = 0
    for dirpath, dirnames, filenames in os.walk(root, followlinks=False):
        dirnames[:] = sorted(d for d in dirnames if d not in IGNORED_DIRS and not d.startswith("."))
        for name in sorted(filenames):
            path = Path(dirpath) / name
            if path.is_symlink() or Path(name).suffix not in KEPT_SUFFIXES:
                continue
            rel = path.relative_to(root).as_posix()
            size = path.stat().st_size
            total += size
            if len(files) >= MAX_FILES or total > MAX_BYTES:
                raise SubmissionError(f"the submission is too large (more than {MAX_FILES} files or "
                                      f"{MAX_BYTES // 2**20} MB of source)")
            files[rel] = path.read_bytes()
    return files


def _collect_zip(path: Path) -> dict[str, bytes]:
    files: dict[str, bytes] = {}
    total = 0
    try:
        with zipfile.ZipFile(path) as archive:
            for info in archive.infolist():
                if info.is_dir():
                    continue
                name = PurePosixPath(info.filename.replace("\\", "/"))
                if name.is_absolute() or ".." in name.parts or any(p in IGNORED_DIRS for p in name.parts):
                    continue
                if stat.S_ISLNK(info.external_attr >> 16) or name.suffix not in KEPT_SUFFIXES:
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
    except (zipfile.BadZipFile, OSError, RuntimeError, NotImplementedError) as exc:
        raise SubmissionError(f"{path.name} is not a readable zip archive: {exc}") from exc
    return files


def _strip_common_folder(files: dict[str, bytes]) -> dict[str, bytes]:
    """A zip of a folder holds ``folder/...``: use what is inside the folder."""
    while files:
        heads = {name.split("/", 1)[0] for name in files}
        if len(heads) != 1 or all("/" not in name for name in files):
            break
        head = heads.pop() + "/"
        files = {name[len(head):]: data for name, data in files.items() if name.startswith(head)}
    return files


def notebook_to_source(data: bytes, name: str) -> str:
    """The code cells of a notebook as one module; IPython magics and shell lines are commented out."""
    import nbformat

    try:
        notebook = nbformat.reads(data.decode("utf-8"), as_version=4)
    except Exception as exc:  # noqa: BLE001 - nbformat raises many kinds of errors for malformed input
        raise SubmissionError(f"the notebook {name} cannot be read: {exc}") from exc
    chunks = [f"# Generated from the notebook {name}: its code cells, in order.\n"]
    for index, cell in enumerate(notebook.cells):
        if cell.get("cell_type") != "code":
            continue
        lines = []
        for line in str(cell.get("source", "")).splitlines():
            stripped = line.lstrip()
            if stripped.startswith(("%", "!")) or "get_ipython()" in stripped:
                line = line[: len(line) - len(stripped)] + "# (notebook magic) " + stripped
            lines.append(line)
        chunks.append(f"# --- cell {index + 1}\n" + "\n".join(lines) + "\n")
    return "\n".join(chunks)


def _student_files(source: Path) -> dict[str, bytes]:
    if not source.exists():
        raise SubmissionError(f"{source} does not exist")
    if source.is_dir():
        files = _collect_dir(source)
    elif source.suffix == ".zip":
        files = _collect_zip(source)
    elif source.suffix in (".ipynb", ".py", ".toml"):
        files = {source.name: source.read_bytes()}
    else:
        raise SubmissionError(f"{source.name}: expected a folder, a .zip archive or a .ipynb notebook")
    files = _strip_common_folder(files)
    if not files:
        raise SubmissionError(f"{source.name} contains no Python files, notebooks or answers.toml")
    return files


def submission_digest(source: str | Path) -> str:
    """The content hash of a submission as ``materialize`` would compute it (names and contents of the
    student's files), without copying anything."""
    return content_hash(_student_files(Path(source)))


def materialize(source: str | Path, workdir: str | Path | None = None) -> Submission:
    """Copy the template and lay the submission over it in a fresh private directory."""
    source = Path(source)
    files = _student_files(source)
    digest = content_hash(files)
    root = Path(tempfile.mkdtemp(prefix="submission-", dir=workdir))
    target = root / "pkg"
    shutil.copytree(template_dir(), target, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    notes = []
    laid: list[str] = []
    for name, data in files.items():
        rel = PurePosixPath(name)
        if rel.suffix == ".ipynb":
            module = rel.stem.replace("-", "_").replace(" ", "_")
            if not MODULE_NAME.match(module):
                notes.append(f"skipped the notebook {name}: {module!r} is not a valid module name")
                continue
            out = target / rel.parent / f"{module}.py"
            out.parent.mkdir(parents=True, exist_ok=True)
            out.write_text(notebook_to_source(data, name))
            notes.append(f"notebook {name} → {module}.py")
            laid.append(name)
            continue
        out = target / rel
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_bytes(data)
        laid.append(name)
    for dirpath, dirnames, filenames in os.walk(root):
        os.chmod(dirpath, 0o755)
        for fname in filenames:
            os.chmod(os.path.join(dirpath, fname), 0o644)
    return Submission(str(source), target, digest, tuple(sorted(laid)), tuple(notes))


def read_answers(package: Path) -> tuple[dict, str | None]:
    """The parsed answers.toml of a materialized submission, or an error text (no code runs: TOML only)."""
    import tomllib

    path = package / "answers.toml"
    if not path.exists():
        return {}, None
    if path.stat().st_size > MAX_ANSWERS_BYTES:
        return {}, f"answers.toml is larger than {MAX_ANSWERS_BYTES // 1024} kB"
    try:
        return tomllib.loads(path.read_text(encoding="utf-8")), None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        return {}, f"answers.toml is not valid TOML: {exc}"


def cleanup(submission: Submission) -> None:
    shutil.rmtree(submission.path.parent, ignore_errors=True)
