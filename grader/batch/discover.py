"""The students of a submissions folder: one folder, .zip archive or .ipynb notebook each, with the content hash
that decides whether a student is graded again, and the seed of their randomized checks."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

from ..errors import SubmissionError

__all__ = ["Entry", "SUBMISSION_SUFFIXES", "student_seed", "submission_hash", "discover"]

SUBMISSION_SUFFIXES = (".zip", ".ipynb")

@dataclass(frozen=True)
class Entry:
    """One student's submission: a folder, a zip archive or a notebook."""

    name: str
    path: Path
    content_hash: str

    @property
    def seed(self) -> int:
        return student_seed(self.content_hash)


def student_seed(content_hash: str) -> int:
    """The seed of the randomized checks: fixed by the content, so that a regrade is reproducible."""
    return int(hashlib.sha256(content_hash.encode()).hexdigest()[:8], 16) & 0x7FFFFFFF


def submission_hash(path: Path) -> str:
    """The content hash of a submission (its files' names and contents), as the loader computes it."""
    from ..loader import submission_digest

    try:
        return submission_digest(path)
    except SubmissionError as exc:
        data = path.read_bytes() if path.is_file() else str(exc).encode()
        return "unloadable-" + hashlib.sha256(data).hexdigest()


def discover(folder: str | Path, exclude: Path | None = None) -> tuple[list[Entry], list[str]]:
    """The students of ``folder`` and the names of the entries that are not submissions."""
    folder = Path(folder)
    if not folder.is_dir():
        raise SubmissionError(f"{folder} is not a folder")
    entries, ignored, seen = [], [], {}
    for path in sorted(folder.iterdir()):
        if path.name.startswith((".", "__")) or (exclude is not None and path.resolve() == exclude.resolve()):
            continue
        if not (path.is_dir() or path.suffix in SUBMISSION_SUFFIXES):
            ignored.append(path.name)
            continue
        name = path.name if path.is_dir() else path.stem
        if name in seen:
            raise SubmissionError(f"{seen[name]} and {path.name} would both be the student {name!r}")
        seen[name] = path.name
        entries.append(Entry(name, path, submission_hash(path)))
    return entries, ignored

