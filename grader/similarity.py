"""``grade similarity RESULTS``: pairs of students whose work agrees more than chance makes likely, after a batch.

Two kinds of evidence, each shown with what it rests on:

* **What only a grader knows.**  A batch records each student's wrong answers on the inputs every student is asked
  (``grader.answers``: the checks' fixed inputs and the sheet's cases, and, where a randomized comparison failed,
  one input of that comparison drawn alike for everyone) and the diagnosis of each failed check.  Two students
  who give the same wrong value on the same call, or whose checks name the same mistake, share that item.  An item
  weighs ``ln(n / k)``, ``n`` the students graded on its problem and ``k`` those who share it: the rarer, the
  heavier; an item that a known mistake explains (the check names it) weighs ``KNOWN_MISTAKE`` of that, because
  such mistakes are common and made independently.  Per check the heaviest shared item counts (one mistake shows
  on several calls), summed over checks: ``answers``.
* **Code.**  The students' code is fingerprinted by ``copydetect`` (tokens with names, strings and comments
  normalised, winnowed k-grams); what the template holds is boilerplate, and so is the reference solution's code
  (short numeric functions written the canonical way are alike in every honest class), and so is a passage that
  more than ``COMMON_SHARE`` of the class share (as MOSS's ``-m``).  A pair's ``tokens`` is copydetect's
  similarity of what is left: the larger of the two shares of each one's remaining code found in the other's.
  A short match is found by chance (copydetect finds any of ``GUARANTEE`` characters of normalised code, about
  a line), so the code's evidence grows with the length matched up to ``FULL_MATCH`` characters (a few lines).

A pair's score is ``answers + TOKEN_WEIGHT * ln(students) * tokens * min(1, matched / FULL_MATCH)``: all of one's
distinctive code in the other's, over a few lines at least, counts as much as one wrong answer that the two alone
give.  ``RESULTS/similarity.csv`` lists every pair with any
evidence, ranked; ``RESULTS/similarity.html`` shows the ``top`` pairs with their shared wrong answers and their code
side by side.  It is evidence for a person to read, never a verdict: nothing here changes a grade.
"""

from __future__ import annotations

import csv
import io
import math
import os
from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Shared", "Pair", "Similarity", "similarity", "write_similarity", "KNOWN_MISTAKE", "TOKEN_WEIGHT",
           "COMMON_SHARE", "COMMON_LEAST", "NOISE", "GUARANTEE", "FULL_MATCH", "TOP"]

#: the weight of an item that a known mistake explains, relative to an unexplained one
KNOWN_MISTAKE = 0.25
#: the weight of code similarity 1.0, in units of ln(class size) (a wrong answer two students alone give)
TOKEN_WEIGHT = 1.0
#: a fingerprint that more than this share of the class has (and at least ``COMMON_LEAST`` students) is
#: common code, not evidence between two of them
COMMON_SHARE = 0.1
COMMON_LEAST = 10
#: copydetect's noise and guarantee thresholds (its defaults): k-grams of ``NOISE`` characters of normalised code,
#: a match of ``GUARANTEE`` characters is always found
NOISE, GUARANTEE = 25, 30
#: the characters of normalised code a match must reach to count in full (shorter matches count in proportion)
FULL_MATCH = 200
#: the most characters of a student's own code that are fingerprinted (a whole course is some 100,000): the rest
#: is left out, and the report says so
MAX_CODE = 1_000_000
#: the pairs the HTML report shows
TOP = 50
#: the lines of a student's code shown for one pair, at most
SHOWN_LINES = 160


@dataclass(frozen=True)
class Shared:
    """One item of evidence a pair shares."""

    problem: int
    check_id: str
    kind: str  # "wrong answer" or "diagnosis"
    what: str  # the call, or the diagnosis
    value: str  # the shared wrong value ("" for a diagnosis)
    expected: str  # the reference's value ("" for a diagnosis)
    students: int  # how many students share it
    weight: float


@dataclass(frozen=True)
class Hunk:
    """Lines of a student's own code (not the template's): a file and the number of its first line."""

    file: str
    line: int
    text: str


@dataclass(frozen=True)
class Segment:
    text: str
    shared: bool


@dataclass(frozen=True)
class Pair:
    first: str
    second: str
    score: float
    answers: float
    tokens: float
    shared_chars: int
    shared: tuple[Shared, ...]
    code: tuple[tuple[tuple[Hunk, tuple[Segment, ...]], ...], ...] = ()  # per student: hunks with their segments

    @property
    def checks(self) -> list[str]:
        return sorted({s.check_id for s in self.shared})


@dataclass(frozen=True)
class Similarity:
    students: int
    pairs: tuple[Pair, ...]
    compared: int  # pairs of students compared
    with_code: int  # students whose code was fingerprinted
    notes: tuple[str, ...] = field(default=())
    seconds: float = 0.0


# ---------------------------------------------------------------------------------------------- grader's evidence


def _evidence(book) -> tuple[dict, list[str], dict[str, tuple[str, str]]]:
    """For each pair of students, per check, the heaviest item they share (``Shared``); the students; each
    student's source and content hash (from a problem they were graded on)."""
    rows = book.submitted()
    students = sorted({r[0] for r in rows})
    graded: dict[int, int] = defaultdict(int)
    sources: dict[str, tuple[str, str]] = {}
    for student, problem, source, content_hash, load_error in rows:
        if not load_error:
            graded[problem] += 1
            sources.setdefault(student, (source, content_hash))
    diagnosed: set[tuple[str, int]] = set()  # (student, problem) where a check names a known mistake
    by_diagnosis: dict[tuple[int, str, str], list[str]] = defaultdict(list)
    for student, problem, check_id, name in book.diagnosed():
        diagnosed.add((student, problem))
        by_diagnosis[(problem, check_id, name)].append(student)
    by_answer: dict[tuple[int, str, str, str], list[tuple[str, object]]] = defaultdict(list)
    for student, problem, answer in book.wrong_answers():
        by_answer[(problem, answer.check_id, answer.call_key, answer.value_key)].append((student, answer))

    best: dict[tuple[str, str], dict[str, Shared]] = defaultdict(dict)

    def keep(a: str, b: str, item: Shared) -> None:
        pair = (a, b) if a < b else (b, a)
        held = best[pair].get(item.check_id)
        if held is None or item.weight > held.weight:
            best[pair][item.check_id] = item

    for (problem, check_id, _, _), holders in by_answer.items():
        if len(holders) < 2:
            continue
        weight = math.log(max(graded[problem], len(holders)) / len(holders))
        if weight <= 0:
            continue
        answer = holders[0][1]
        for i, (a, _) in enumerate(holders):
            for b, _ in holders[i + 1:]:
                explained = (a, problem) in diagnosed and (b, problem) in diagnosed
                keep(a, b, Shared(problem, check_id, "wrong answer", answer.call, answer.value, answer.expected,
                                  len(holders), weight * (KNOWN_MISTAKE if explained else 1.0)))
    for (problem, check_id, name), holders in by_diagnosis.items():
        if len(holders) < 2:
            continue
        weight = math.log(max(graded[problem], len(holders)) / len(holders)) * KNOWN_MISTAKE
        if weight <= 0:
            continue
        for i, a in enumerate(holders):
            for b in holders[i + 1:]:
                keep(a, b, Shared(problem, check_id, "diagnosis", name, "", "", len(holders), weight))
    return best, students, sources


# ---------------------------------------------------------------------------------------------- code


def _boilerplate() -> list[str]:
    """The texts whose code is boilerplate: the template's modules and the reference solution's."""
    import importlib.util

    from .loader import template_dir

    folders = [template_dir()]
    spec = importlib.util.find_spec("reference")
    if spec is not None and spec.origin:
        folders.append(Path(spec.origin).parent)
    return [path.read_text(encoding="utf-8") for folder in folders for path in sorted(folder.glob("*.py"))]


def _code_files(raw: dict[str, bytes]) -> dict[str, str]:
    """A student's code: each Python file, and each notebook's code cells, as text (nothing is run)."""
    from .loader import notebook_plan

    code = {}
    for name, data in raw.items():
        if name.endswith(".py"):
            code[name] = data.decode("utf-8", "replace")
        elif name.endswith(".ipynb"):
            plan = notebook_plan(name, data, "_notebook")
            code[name] = "\n\n".join(text for _, text in plan.cells)
    return code


def _hunks(files: dict[str, str], template: set[str]) -> list[Hunk]:
    """The student's own lines: each run of lines that neither the template nor the reference holds as they are
    (blank lines inside a run are kept), with its file and first line number."""
    hunks = []
    for name in sorted(files):
        run: list[str] = []
        start = 0
        for number, line in enumerate(files[name].splitlines() + [None], 1):
            own = line is not None and (line.strip() not in template or (run and not line.strip()))
            if own:
                if not run:
                    start = number
                run.append(line)
            elif run:
                while run and not run[-1].strip():
                    run.pop()
                if run:
                    hunks.append(Hunk(name, start, "\n".join(run)))
                run = []
    return hunks


@dataclass
class _Code:
    hunks: list[Hunk]
    offsets: list[int]  # where each hunk starts in the document
    fingerprint: object  # copydetect's CodeFingerprint of the document


def _document(hunks: list[Hunk]) -> tuple[str, list[int]]:
    parts, offsets, at = [], [], 0
    for hunk in hunks:
        offsets.append(at)
        parts.append(hunk.text)
        at += len(hunk.text) + 2
    return "\n\n".join(parts), offsets


#: a class from this size on is fingerprinted by one process per core (tokenizing is most of the work)
PARALLEL_FROM = 40
#: the hash seed of the processes that fingerprint: copydetect hashes k-grams with Python's ``hash`` of strings,
#: which differs between processes unless the seed is fixed, and fingerprints are compared across processes
HASH_SEED = "3030"

_BOILERPLATE = None


def _boilerplate_hashes(texts: list[str]):
    import numpy as np
    from copydetect import CodeFingerprint

    common = set()
    for index, text in enumerate(texts):
        common |= CodeFingerprint(f"boilerplate{index}.py", NOISE, 1, fp=io.StringIO(text), language="python").hashes
    return np.array(sorted(common), dtype=np.int64)


def _start_fingerprinting(texts: list[str]) -> None:
    global _BOILERPLATE
    _BOILERPLATE = _boilerplate_hashes(texts)


def _fingerprint(item: tuple[str, str]):
    from copydetect import CodeFingerprint

    name, text = item
    return name, CodeFingerprint(f"{name}.py", NOISE, GUARANTEE - NOISE + 1, boilerplate=_BOILERPLATE,
                                 fp=io.StringIO(text), language="python")


def _fingerprints(texts: dict[str, str], boilerplate: list[str], jobs: int = 1) -> dict[str, object]:
    """copydetect's fingerprints of each document (name -> text) with the boilerplate's k-grams removed, by
    ``jobs`` processes with one hash seed (``HASH_SEED``), or here for a small class."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    if jobs < 2 or len(texts) < PARALLEL_FROM:  # this process alone: its own hash seed is consistent
        _start_fingerprinting(boilerplate)
        return dict(map(_fingerprint, texts.items()))
    saved = os.environ.get("PYTHONHASHSEED")
    os.environ["PYTHONHASHSEED"] = HASH_SEED
    try:
        with ProcessPoolExecutor(max(1, jobs), mp_context=multiprocessing.get_context("spawn"),
                                 initializer=_start_fingerprinting, initargs=(boilerplate,)) as pool:
            return dict(pool.map(_fingerprint, sorted(texts.items()), chunksize=8))
    finally:
        if saved is None:
            os.environ.pop("PYTHONHASHSEED", None)
        else:
            os.environ["PYTHONHASHSEED"] = saved


def _drop(fingerprint, hashes: set) -> None:
    """Remove ``hashes`` (common code) from a fingerprint, as copydetect removes boilerplate."""
    from copydetect.utils import get_token_coverage

    fingerprint.hashes = fingerprint.hashes - hashes
    fingerprint.hash_idx = {h: i for h, i in fingerprint.hash_idx.items() if h not in hashes}
    fingerprint.token_coverage = get_token_coverage(fingerprint.hash_idx, fingerprint.k,
                                                    len(fingerprint.filtered_code))


def _segments(code: _Code, slices) -> list[tuple[Hunk, tuple[Segment, ...]]]:
    """The student's hunks cut into shared and other segments (``slices`` of the document: starts, ends)."""
    spans = sorted(zip(slices[0].tolist(), slices[1].tolist())) if len(slices) and len(slices[0]) else []
    out = []
    for hunk, start in zip(code.hunks, code.offsets):
        end = start + len(hunk.text)
        marks = [(max(a, start) - start, min(b, end) - start) for a, b in spans if a < end and b > start]
        if not marks:
            continue
        segments, at = [], 0
        for a, b in marks:
            if a > at:
                segments.append(Segment(hunk.text[at:a], False))
            segments.append(Segment(hunk.text[max(a, at):b], True))
            at = max(at, b)
        if at < len(hunk.text):
            segments.append(Segment(hunk.text[at:], False))
        out.append((hunk, tuple(segments)))
    return out


def _unshared(code: _Code, files: set[str]) -> list[tuple[Hunk, tuple[Segment, ...]]]:
    return [(hunk, (Segment(hunk.text, False),)) for hunk in code.hunks if hunk.file in files]


def _limited(hunks: list, lines: int = SHOWN_LINES) -> tuple:
    shown, used = [], 0
    for hunk, segments in hunks:
        count = hunk.text.count("\n") + 1
        if used + count > lines and shown:
            break
        shown.append((hunk, segments))
        used += count
    return tuple(shown)


# ---------------------------------------------------------------------------------------------- the report


def similarity(results: str | Path, *, top: int = TOP, jobs: int | None = None) -> Similarity:
    """The pairs of students of the gradebook in ``results``, ranked by their evidence (see the module); the code
    is fingerprinted by ``jobs`` processes (default: one per core) in a class of ``PARALLEL_FROM`` or more."""
    import time

    from copydetect import compare_files

    from .batch.gradebook import Gradebook
    from .errors import SubmissionError
    from .loader import content_hash, student_files

    began = time.monotonic()
    jobs = jobs or len(os.sched_getaffinity(0))
    with Gradebook.in_folder(results) as book:
        best, students, sources = _evidence(book)
    notes = []
    boilerplate = _boilerplate()
    known_lines = {line.strip() for text in boilerplate for line in text.splitlines()}
    texts, codes = {}, {}
    for student in students:
        if student not in sources:
            continue
        source, digest = sources[student]
        try:
            raw = student_files(source)
            if content_hash(raw) != digest:
                notes.append(f"{student}: code not compared (the submission changed since it was graded)")
                continue
            files = _code_files(raw)
        except (SubmissionError, OSError, ValueError) as exc:
            notes.append(f"{student}: code not compared ({exc})")
            continue
        hunks = _hunks(files, known_lines)
        text, offsets = _document(hunks)
        if len(text) > MAX_CODE:
            notes.append(f"{student}: only the first {MAX_CODE:,} characters of their {len(text):,} of own code "
                         "were compared")
            kept = [i for i, at in enumerate(offsets) if at + len(hunks[i].text) <= MAX_CODE]
            hunks, offsets = hunks[:len(kept)], offsets[:len(kept)]
            text = text[:offsets[-1] + len(hunks[-1].text)] if hunks else ""
        texts[student] = text
        codes[student] = _Code(hunks, offsets, None)
    prints = _fingerprints(texts, boilerplate, jobs)
    for student, fingerprint in prints.items():
        codes[student].fingerprint = fingerprint
    holders: dict[int, list[str]] = defaultdict(list)
    for student, fingerprint in prints.items():
        for h in fingerprint.hashes:
            holders[h].append(student)
    limit = max(COMMON_LEAST, COMMON_SHARE * len(students))
    common = {h for h, who in holders.items() if len(who) > limit}
    if common:
        for fingerprint in prints.values():
            _drop(fingerprint, common)
    candidates: set[tuple[str, str]] = set(best)
    for h, who in holders.items():
        if h in common or len(who) < 2:
            continue
        who = sorted(who)
        for i, a in enumerate(who):
            for b in who[i + 1:]:
                candidates.add((a, b))
    scale = math.log(max(len(students), 2))
    pairs = []
    compared_code: dict[tuple[str, str], tuple] = {}
    for a, b in sorted(candidates):
        items = tuple(sorted(best.get((a, b), {}).values(), key=lambda s: (-s.weight, s.check_id)))
        answers = sum(s.weight for s in items)
        tokens, chars = 0.0, 0
        if a in prints and b in prints:
            overlap, shares, slices = compare_files(prints[a], prints[b])
            tokens, chars = float(max(shares)), int(overlap)
            if overlap:
                compared_code[(a, b)] = slices
        score = answers + TOKEN_WEIGHT * scale * tokens * min(1.0, chars / FULL_MATCH)
        if score > 0:
            pairs.append(Pair(a, b, score, answers, tokens, chars, items))
    pairs.sort(key=lambda p: (-p.score, p.first, p.second))
    shown = []
    for pair in pairs[:top]:
        code = []
        for index, student in enumerate((pair.first, pair.second)):
            if student not in codes:
                code.append(())
                continue
            slices = compared_code.get((pair.first, pair.second))
            hunks = _segments(codes[student], slices[index]) if slices is not None else []
            if not hunks:  # no code in common: the code of the problems where the answers agree
                hunks = _unshared(codes[student], _files_of({s.problem for s in pair.shared}))
            code.append(_limited(hunks))
        shown.append(Pair(pair.first, pair.second, pair.score, pair.answers, pair.tokens, pair.shared_chars,
                          pair.shared, tuple(code)))
    pairs[:top] = shown
    return Similarity(len(students), tuple(pairs), len(students) * (len(students) - 1) // 2, len(prints),
                      tuple(notes), time.monotonic() - began)


def _files_of(problems: set[int]) -> set[str]:
    from .prairielearn import problem_files

    files = set()
    for number in problems:
        try:
            files.update(problem_files(number))
        except (OSError, SyntaxError, KeyError):
            files.add(f"problem_{number:02d}.py")
    return files


def _write(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


def _csv(rows: list[list]) -> str:
    """CSV text whose cells a spreadsheet shows as text (student names are untrusted)."""
    from .batch.gradebook import spreadsheet_cell

    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\r\n").writerows(
        [[spreadsheet_cell(cell) if isinstance(cell, str) else cell for cell in row] for row in rows])
    return buffer.getvalue()


def write_similarity(results: str | Path, *, top: int = TOP, jobs: int | None = None) -> Similarity:
    """Compute ``similarity`` and write ``similarity.csv`` and ``similarity.html`` into ``results``."""
    from .report.environment import environment

    results = Path(results)
    found = similarity(results, top=top, jobs=jobs)
    rows = [["rank", "student", "other student", "score", "answers", "tokens", "shared code characters",
             "shared wrong answers", "shared diagnoses", "checks"]]
    for rank, pair in enumerate(found.pairs, 1):
        rows.append([rank, pair.first, pair.second, f"{pair.score:.3f}", f"{pair.answers:.3f}",
                     f"{pair.tokens:.3f}", pair.shared_chars,
                     sum(1 for s in pair.shared if s.kind == "wrong answer"),
                     sum(1 for s in pair.shared if s.kind == "diagnosis"), " ".join(pair.checks)])
    _write(results / "similarity.csv", _csv(rows))
    html = environment("html").get_template("similarity.html.j2").render(
        found=found, shown=found.pairs[:top], top=top, known=KNOWN_MISTAKE, token_weight=TOKEN_WEIGHT,
        common_share=COMMON_SHARE, common_least=COMMON_LEAST, full_match=FULL_MATCH,
        scale=math.log(max(found.students, 2)))
    _write(results / "similarity.html", html)
    return found
