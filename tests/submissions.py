"""Sample submissions for the tests, the demo and the batch benchmark.

* ``reference`` and ``template``: copies of the two packages.
* planted mistakes: ``tests/planted/problem_NN.toml`` lists ``[[mistake]]`` entries, each a text replacement in
  one file of a reference copy, with the check it must fail and the diagnosis and message it must produce.
* hostile submissions: ``tests/hostile/<name>/`` holds files laid over a reference copy, and ``expect.toml``
  says what the grader must report (on problem 6, or on the problem its ``problem`` names):

  - ``status`` (one or a list) of the ``checks`` listed (default: every check that ran), each scoring 0 unless
    the status is "passed"; ``message``: a text of their messages; ``max_score``: a bound of the total;
    ``stdout``: a text of what the submission printed; ``stdout_not``: texts it must not have printed;
  - ``limits``: fields of ``Limits`` that replace the tests' defaults (e.g. ``{ call_timeout = 60.0 }``);
  - ``isolated_only``: the attack is contained only by bubblewrap's file-system view (plain processes skip it);
  - ``other_uid``: the attack would harm the user who runs the grader: graded only where the child cannot be that
    user (bubblewrap, or a plain process under a uid of its own);
  - ``own_pid_namespace``: the attack is contained by a PID namespace of the child's own: graded where it has one
    (bubblewrap, or a plain process as root, whose report must then say so);
  - ``load_error``: a text of why the submission could not be loaded (said once, for the whole problem);
  - ``note``: a text of one of the report's notes;
  - ``links``: symbolic links to create in the submission, ``{ "NAME" = "TARGET" }``, a target starting with
    ``@`` naming a path of this project (``"@reference/rotations.py"``);
  - ``odd_names``: files to create whose names are not valid UTF-8, written with ``\\xNN`` escapes of their bytes
    (each holds ``x = 1``);
  - ``target``: the test writes ``target.txt`` into the submission (JSON: a ``nonce``, the ``port`` of a socket
    the test listens on, a named Unix socket ``unix`` that every user may connect to and an ``abstract`` one, the
    reference ``cache`` folder the grader uses) and checks afterwards that no process or file named with the nonce
    is left, that the cache is untouched, that a connection reached the port only where the report says the
    network was not isolated, and that none reached either Unix socket;
  - ``keyring``: the test grades from a session keyring of its own that holds a secret key, and checks afterwards
    that the secret is not in the submission's output and that the keyring holds nothing else;
  - ``spy_process``: the test runs a process named with a marker that it writes to ``spy.txt``.
"""

from __future__ import annotations

import os
import shutil
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PLANTED = ROOT / "tests" / "planted"
HOSTILE = ROOT / "tests" / "hostile"


@dataclass(frozen=True)
class Planted:
    name: str
    problem: int
    file: str
    old: str
    new: str
    check: str  # the check id that must fail, e.g. "p06.cardan_values"
    diagnosis: str = ""  # the diagnosis it must name ("" when none is expected)
    message: str = ""  # a text the message or hint must contain
    status: str = "failed"
    also: tuple = field(default=())  # more checks allowed to fail alongside


def planted_mistakes(problem: int | None = None) -> list[Planted]:
    mistakes = []
    for path in sorted(PLANTED.glob("problem_*.toml")):
        number = int(path.stem.removeprefix("problem_"))
        if problem is not None and number != problem:
            continue
        for entry in tomllib.loads(path.read_text()).get("mistake", []):
            entry = dict(entry)
            entry["also"] = tuple(entry.get("also", ()))
            mistakes.append(Planted(problem=number, **entry))
    return mistakes


def correct_variants(problem: int | None = None) -> list[dict]:
    """``[[correct]]`` entries: replacements that keep a solution correct (another valid answer, a different
    but sound way to compute it); each must still score full marks."""
    variants = []
    for path in sorted(PLANTED.glob("problem_*.toml")):
        number = int(path.stem.removeprefix("problem_"))
        if problem is None or number == problem:
            variants += [dict(entry, problem=number) for entry in tomllib.loads(path.read_text()).get("correct", [])]
    return variants


def build_variant(variant: dict, dest: Path) -> Path:
    return build_planted(Planted(name=variant["name"], problem=variant["problem"], file=variant["file"],
                                 old=variant["old"], new=variant["new"], check=""), dest)


def copy_reference(dest: Path) -> Path:
    shutil.copytree(ROOT / "reference", dest, ignore=shutil.ignore_patterns("__pycache__", "answers_*.toml"))
    return dest


def copy_template(dest: Path) -> Path:
    shutil.copytree(ROOT / "student_template", dest, ignore=shutil.ignore_patterns("__pycache__"))
    return dest


def plant(mistake: Planted, folder: Path, strict: bool = True) -> bool:
    """Apply ``mistake`` to the submission in ``folder``.  Its line must occur there once: else ``ValueError``
    (``strict``), or the mistake is left out and False returned (an earlier mistake changed that line)."""
    target = folder / mistake.file
    text = target.read_text()
    if text.count(mistake.old) != 1:
        if strict:
            raise ValueError(f"{mistake.name}: {mistake.old!r} occurs {text.count(mistake.old)} times in "
                             f"{mistake.file}")
        return False
    target.write_text(text.replace(mistake.old, mistake.new))
    return True


def build_planted(mistake: Planted, dest: Path) -> Path:
    copy_reference(dest)
    plant(mistake, dest)
    return dest


def build_with_mistakes(dest: Path, mistakes: list[Planted], strict: bool = True) -> list[str]:
    """A reference with several planted mistakes at once; the names of those applied (all of them if ``strict``)."""
    copy_reference(dest)
    return [mistake.name for mistake in mistakes if plant(mistake, dest, strict)]


def hostile_names() -> list[str]:
    return sorted(p.name for p in HOSTILE.iterdir() if (p / "expect.toml").exists())


def hostile_expectation(name: str) -> dict:
    return tomllib.loads((HOSTILE / name / "expect.toml").read_text())


def build_hostile(name: str, dest: Path) -> Path:
    copy_reference(dest)
    for path in (HOSTILE / name).rglob("*"):
        if path.is_file() and path.name != "expect.toml":
            target = dest / path.relative_to(HOSTILE / name)
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(path, target)
    expect = hostile_expectation(name)
    for edit in expect.get("replace", ()):  # a text of a reference file written otherwise, where it occurs once
        path = dest / edit["file"]
        text = path.read_text()
        assert text.count(edit["old"]) == 1, (name, edit["file"], edit["old"])
        path.write_text(text.replace(edit["old"], edit["new"]))
    for link, target in expect.get("links", {}).items():
        path = dest / link
        if path.exists() or path.is_symlink():
            path.unlink()
        path.symlink_to(ROOT / target[1:] if target.startswith("@") else target)
    for odd in expect.get("odd_names", ()):
        raw = odd.encode("latin-1").decode("unicode_escape").encode("latin-1")
        with open(os.path.join(os.fsencode(dest), raw), "w") as handle:
            handle.write("x = 1\n")
    return dest
