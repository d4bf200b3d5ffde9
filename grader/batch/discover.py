"""The students of a submissions folder: one folder, .zip archive or .ipynb notebook each, with the content hash
that decides whether a student is graded again, and the seed of their randomized checks (from the content and the
batch's secret)."""

from __future__ import annotations

import hashlib
import hmac
import os
from dataclasses import dataclass
from pathlib import Path

from ..errors import SubmissionError
from .course import COURSE_FILE  # the course's deadlines and policy, which may sit in the submissions folder

__all__ = ["Entry", "SUBMISSION_SUFFIXES", "BAD_NAME", "GRADESCOPE_METADATA", "student_seed",
           "submission_hash", "discover", "uploaded"]

SUBMISSION_SUFFIXES = (".zip", ".ipynb")
#: follows an ignored entry whose name is not valid UTF-8
BAD_NAME = " (its name is not valid UTF-8: rename it)"
#: Gradescope's metadata of a submission, beside (never inside) the folder of what the student submitted
GRADESCOPE_METADATA = "submission_metadata.json"


@dataclass(frozen=True)
class Entry:
    """One student's submission: a folder, a zip archive or a notebook; ``metadata``, Gradescope's metadata of it
    when the student's entry is laid out as Gradescope's autograder sees a submission (``NAME/submission/`` and
    ``NAME/submission_metadata.json``); ``seed``, the seed of its randomized checks, which a batch gives it from its
    secret (``student_seed``; None before: a fresh seed)."""

    name: str
    path: Path
    content_hash: str
    metadata: Path | None = None
    seed: int | None = None


def student_seed(content_hash: str, secret: bytes) -> int:
    """The seed of a submission's randomized checks: an HMAC of its content under the batch's secret (kept in the
    gradebook, ``Gradebook.seed_secret``).  The same submission gets the same seed in every run of its results
    folder, and the instructor reproduces its inputs with ``--seed``; the submission, without the secret, cannot
    compute it from its own files."""
    return int(hmac.new(secret, content_hash.encode(), hashlib.sha256).hexdigest()[:8], 16) & 0x7FFFFFFF


def submission_hash(path: Path) -> str:
    """The content hash of a submission (its files' names and contents), as the loader computes it; for a
    submission that cannot be loaded, a hash of why (and of the file, when it is a regular one), so that a
    corrected submission is graded again."""
    from ..loader import MAX_BYTES, submission_digest

    try:
        return submission_digest(path)
    except SubmissionError as exc:
        digest = hashlib.sha256(str(exc).encode("utf-8", "replace"))
        if not path.is_symlink() and path.is_file():
            try:
                with open(path, "rb") as handle:
                    digest.update(handle.read(MAX_BYTES + 1))
            except OSError:
                pass
        return "unloadable-" + digest.hexdigest()


def _valid_name(name: str) -> bool:
    try:
        name.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


def uploaded(folder: Path) -> Path:
    """What a student uploaded into ``folder``: the one .zip or .ipynb there, else the folder itself."""
    entries = [p for p in folder.iterdir() if not p.name.startswith(".") and p.name != "__MACOSX"]
    if len(entries) == 1 and entries[0].is_file() and not entries[0].is_symlink() \
            and entries[0].suffix in SUBMISSION_SUFFIXES:
        return entries[0]
    return folder


def _gradescope_layout(path: Path) -> tuple[Path, Path] | None:
    """(what the student submitted, Gradescope's metadata) of an entry laid out as Gradescope's autograder folder:
    the metadata stands beside the submission, where the student's own files cannot put it."""
    if path.is_symlink() or not path.is_dir():
        return None
    submission, metadata = path / "submission", path / GRADESCOPE_METADATA
    if submission.is_dir() and not submission.is_symlink() and metadata.is_file() and not metadata.is_symlink():
        return uploaded(submission), metadata
    return None


def discover(folder: str | Path, exclude: Path | None = None) -> tuple[list[Entry], list[str]]:
    """The students of ``folder`` and the names of the entries that are not submissions (a name that is not
    valid UTF-8 is shown as its bytes, followed by ``BAD_NAME``).  A symbolic link
    is a student whose submission is refused (the loader never follows links), not a reason to stop."""
    folder = Path(folder)
    if not folder.is_dir():
        raise SubmissionError(f"{folder} is not a folder")
    entries, ignored, seen = [], [], {}
    for path in sorted(folder.iterdir()):
        if path.name.startswith((".", "__")) or (exclude is not None and path.resolve() == exclude.resolve()) \
                or path.name == COURSE_FILE:
            continue
        if not _valid_name(path.name):
            ignored.append(f"{repr(os.fsencode(path.name))[2:-1]}{BAD_NAME}")
            continue
        if not (path.is_dir() or path.suffix in SUBMISSION_SUFFIXES):
            ignored.append(path.name)
            continue
        name = path.stem if path.suffix in SUBMISSION_SUFFIXES and not path.is_dir() else path.name
        if name in seen:
            raise SubmissionError(f"{seen[name]} and {path.name} would both be the student {name!r}")
        seen[name] = path.name
        layout = _gradescope_layout(path)
        if layout is not None:
            entries.append(Entry(name, layout[0], submission_hash(layout[0]), layout[1]))
        else:
            entries.append(Entry(name, path, submission_hash(path)))
    return entries, ignored
