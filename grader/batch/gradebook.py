"""The gradebook: an embedded SQLite database holding every check result of every student.

One row of ``submissions`` is one problem of one student's work, graded once: its key is
(student, content hash, grader version, problem), unique in the schema.  The parent process of a batch is the
only writer, and it commits a student's whole result (every problem, every check) in one transaction, so that a
batch killed at any point leaves each student either completely graded or not at all.  WAL mode with full
synchronisation keeps committed students through a crash or a power loss, and lets readers (exports, a
progress poll) read while a batch writes.

The grader version of a problem (``grader.sources.grader_version``) is the package version plus a digest of every
file that decides its verdicts: editing the checks of problem 6 regrades problem 6 and nothing else, editing
``checks/_trees.py`` regrades every tree problem.
"""

from __future__ import annotations

import csv
import io
import json
import os
import secrets
import sqlite3
from contextlib import contextmanager
from dataclasses import asdict, replace
from datetime import datetime, timezone
from pathlib import Path

from ..results import CheckResult, Figure, Graded, ManualItem, ProblemReport, Series, Status

__all__ = [
    "GRADEBOOK_NAME",
    "SCHEMA",
    "Gradebook",
    "Graded",
    "ManualScoreError",
    "now",
    "spreadsheet_cell",
    "spreadsheet_text",
]

GRADEBOOK_NAME = "gradebook.sqlite"
SCHEMA_VERSION = 1

SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (
    key   TEXT PRIMARY KEY,
    value TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS runs (
    id              INTEGER PRIMARY KEY,
    started_at      TEXT NOT NULL,
    finished_at     TEXT,
    state           TEXT NOT NULL DEFAULT 'running' CHECK (state IN ('running', 'finished', 'interrupted')),
    submissions_dir TEXT NOT NULL,
    problems        TEXT NOT NULL,          -- JSON list of problem numbers
    jobs            INTEGER NOT NULL,
    force           INTEGER NOT NULL DEFAULT 0,
    graded          INTEGER NOT NULL DEFAULT 0,
    skipped         INTEGER NOT NULL DEFAULT 0,
    sandbox         TEXT NOT NULL DEFAULT ''  -- how students' code ran ("--no-sandbox: ..." when chosen so)
);
CREATE TABLE IF NOT EXISTS students (
    id   INTEGER PRIMARY KEY,
    name TEXT NOT NULL UNIQUE
);
CREATE TABLE IF NOT EXISTS submissions (
    id             INTEGER PRIMARY KEY,
    student_id     INTEGER NOT NULL REFERENCES students (id),
    content_hash   TEXT NOT NULL,
    grader_version TEXT NOT NULL,
    problem        INTEGER NOT NULL,
    run_id         INTEGER NOT NULL REFERENCES runs (id),
    graded_at      TEXT NOT NULL,
    seed           INTEGER NOT NULL,
    outcome        TEXT NOT NULL CHECK (outcome IN ('graded', 'timeout', 'crashed')),
    score          REAL NOT NULL,           -- automatically graded points (hidden checks included)
    max_score      REAL NOT NULL,
    source         TEXT NOT NULL,
    title          TEXT NOT NULL,
    sandbox        TEXT NOT NULL,
    isolated       INTEGER NOT NULL,
    duration       REAL NOT NULL,
    stdout         TEXT NOT NULL,
    stderr         TEXT NOT NULL,
    notes          TEXT NOT NULL,           -- JSON list
    manual         TEXT NOT NULL,           -- JSON list of the free-text items (answers, no scores)
    load_error     TEXT NOT NULL DEFAULT '',  -- why the submission could not be loaded ('' when it was)
    UNIQUE (student_id, content_hash, grader_version, problem)
);
CREATE TABLE IF NOT EXISTS check_results (
    submission_id INTEGER NOT NULL REFERENCES submissions (id) ON DELETE CASCADE,
    check_id      TEXT NOT NULL,
    problem       INTEGER NOT NULL,
    title         TEXT NOT NULL,
    status        TEXT NOT NULL,
    score         REAL NOT NULL,
    max_score     REAL NOT NULL,
    message       TEXT NOT NULL,
    hint          TEXT NOT NULL,
    diagnosis     TEXT NOT NULL,
    visibility    TEXT NOT NULL CHECK (visibility IN ('visible', 'hidden')),
    stage         INTEGER NOT NULL,
    seed          INTEGER,
    duration      REAL NOT NULL,
    figures       TEXT NOT NULL,           -- JSON list
    position      INTEGER NOT NULL,
    PRIMARY KEY (submission_id, check_id)
);
CREATE TABLE IF NOT EXISTS manual_scores (
    student_id  INTEGER NOT NULL REFERENCES students (id),
    problem     INTEGER NOT NULL,
    key         TEXT NOT NULL,
    score       REAL NOT NULL,
    comment     TEXT NOT NULL DEFAULT '',
    imported_at TEXT NOT NULL,
    source      TEXT NOT NULL,
    PRIMARY KEY (student_id, problem, key)
);
CREATE TABLE IF NOT EXISTS submission_times (
    student      TEXT NOT NULL,             -- the student's name, as the submissions folder names them
    content_hash TEXT NOT NULL,
    submitted_at TEXT NOT NULL,             -- ISO 8601 with its offset
    source       TEXT NOT NULL CHECK (source IN ('gradescope', 'files')),
    PRIMARY KEY (student, content_hash)
);
CREATE TABLE IF NOT EXISTS assignment_scores (  -- recomputed from course.toml at every export, never graded
    student      TEXT NOT NULL,
    assignment   TEXT NOT NULL,
    raw          REAL,                      -- NULL: no problem of the assignment graded
    possible     REAL NOT NULL,
    penalty      REAL NOT NULL,
    final        REAL,                      -- NULL: excused or not graded
    due          TEXT NOT NULL,             -- the student's own due date ('' when none)
    submitted_at TEXT NOT NULL,
    submitted_from TEXT NOT NULL,
    days_late    INTEGER NOT NULL,
    grace_days   INTEGER NOT NULL,
    excused      INTEGER NOT NULL,
    computed_at  TEXT NOT NULL,
    course       TEXT NOT NULL,             -- the course file they were computed from
    PRIMARY KEY (student, assignment)
);
CREATE TABLE IF NOT EXISTS wrong_answers (  -- grader.answers: for grade similarity, never shown to students
    submission_id INTEGER NOT NULL REFERENCES submissions (id) ON DELETE CASCADE,
    check_id      TEXT NOT NULL,
    call          TEXT NOT NULL,           -- the probe and its arguments, shortened
    call_key      TEXT NOT NULL,           -- a digest of the probe and its exact arguments
    value_key     TEXT NOT NULL,           -- a digest of the student's value
    value         TEXT NOT NULL,
    expected      TEXT NOT NULL,
    PRIMARY KEY (submission_id, check_id, call_key)
);
CREATE INDEX IF NOT EXISTS submissions_current ON submissions (student_id, problem, id);
CREATE INDEX IF NOT EXISTS check_results_check ON check_results (check_id, status);
"""

#: the columns of check_results that ``current`` reads, with and without the figures
_CHECK_COLUMNS_NO_FIGURES = ("check_id, problem, title, status, score, max_score, message, hint, diagnosis, "
                             "visibility, stage, seed, duration")
_CHECK_COLUMNS = _CHECK_COLUMNS_NO_FIGURES + ", figures"

#: the latest graded row of every (student, problem), of every student or of one ({where})
_CURRENT = """
SELECT s.*, st.name AS student FROM submissions s JOIN students st ON st.id = s.student_id
WHERE s.id = (SELECT max(t.id) FROM submissions t WHERE t.student_id = s.student_id AND t.problem = s.problem)
{where}ORDER BY st.name, s.problem
"""


#: a cell beginning with one of these is a formula to a spreadsheet (OWASP's list for CSV injection)
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def spreadsheet_cell(text: str) -> str:
    """``text`` as a CSV cell that a spreadsheet shows as text: a leading apostrophe before a formula start."""
    return "'" + text if text.startswith(FORMULA_START) else text


def spreadsheet_text(cell: str) -> str:
    """The inverse of ``spreadsheet_cell``, for files the grader wrote and an instructor filled in."""
    return cell[1:] if cell.startswith("'") and cell[1:].startswith(FORMULA_START) else cell


def now() -> str:
    return datetime.now(timezone.utc).isoformat(timespec="microseconds")


class ManualScoreError(ValueError):
    """A manual-scores file that cannot be imported: every problem found, one per line."""


def _figure(data: dict) -> Figure:
    """A figure read back from the gradebook (rows written before figures had panels or a third axis lack them)."""
    series = tuple(Series(s["label"], tuple(s["x"]), tuple(s["y"]), s.get("role", "other"), tuple(s.get("z", ())),
                          s.get("colour", ""), s.get("marker", ""), int(s.get("panel", 0))) for s in data["series"])
    return Figure(data["title"], data["xlabel"], data["ylabel"], series, bool(data.get("equal_axes")),
                  data.get("zlabel", ""), tuple(data.get("panels", ())))


class Gradebook:
    """The gradebook of one results folder.  Use as a context manager, or call ``close``."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        try:  # a new gradebook is its owner's alone: it holds the batch's secret (``seed_secret``)
            os.close(os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_CLOEXEC, 0o600))
        except FileExistsError:
            pass
        self.db = sqlite3.connect(self.path, isolation_level=None, timeout=30)
        self.db.row_factory = sqlite3.Row
        self.db.execute("PRAGMA journal_mode = WAL")
        self.db.execute("PRAGMA synchronous = FULL")
        self.db.execute("PRAGMA foreign_keys = ON")
        self.db.executescript(
            f"BEGIN IMMEDIATE; {SCHEMA} "
            f"INSERT OR IGNORE INTO meta VALUES ('schema_version', '{SCHEMA_VERSION}'); COMMIT;"
        )
        columns = {row["name"] for row in self.db.execute("PRAGMA table_info(runs)")}
        if "sandbox" not in columns:  # a gradebook written before runs recorded their sandbox
            self.db.execute("ALTER TABLE runs ADD COLUMN sandbox TEXT NOT NULL DEFAULT ''")
        columns = {row["name"] for row in self.db.execute("PRAGMA table_info(submissions)")}
        if "load_error" not in columns:  # a gradebook written before unloadable submissions were said once
            self.db.execute("ALTER TABLE submissions ADD COLUMN load_error TEXT NOT NULL DEFAULT ''")

    @classmethod
    def in_folder(cls, results_dir: str | Path) -> Gradebook:
        return cls(Path(results_dir) / GRADEBOOK_NAME)

    def close(self) -> None:
        self.db.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @contextmanager
    def transaction(self):
        """One atomic write: committed entirely, or (on any exception, Ctrl-C included) not at all."""
        self.db.execute("BEGIN IMMEDIATE")
        try:
            yield self.db
        except BaseException:
            if self.db.in_transaction:
                self.db.execute("ROLLBACK")
            raise
        self.db.execute("COMMIT")

    # ------------------------------------------------------------------ the secret

    def seed_secret(self) -> bytes:
        """The secret of this results folder, from which each student's seed is derived with their submission
        (``grader.batch.discover.student_seed``): made once, when first asked for, and kept in the gradebook, so
        that every run of the folder gives a submission the same seed, and no submission can compute its own."""
        with self.transaction() as db:
            db.execute("INSERT OR IGNORE INTO meta VALUES ('seed_secret', ?)", (secrets.token_hex(32),))
            (value,) = db.execute("SELECT value FROM meta WHERE key = 'seed_secret'").fetchone()
        return bytes.fromhex(value)

    # ------------------------------------------------------------------ runs

    def start_run(self, submissions_dir: str, problems: list[int], jobs: int, force: bool = False,
                  sandbox: str = "") -> int:
        with self.transaction() as db:
            cursor = db.execute(
                "INSERT INTO runs (started_at, submissions_dir, problems, jobs, force, sandbox) "
                "VALUES (?, ?, ?, ?, ?, ?)",
                (now(), str(submissions_dir), json.dumps(problems), jobs, int(force), sandbox),
            )
        return cursor.lastrowid

    def finish_run(self, run_id: int, state: str, skipped: int) -> None:
        with self.transaction() as db:
            db.execute(
                "UPDATE runs SET finished_at = ?, state = ?, skipped = ? WHERE id = ?",
                (now(), state, skipped, run_id),
            )

    # ------------------------------------------------------------------ grading

    def graded_problems(self, student: str, content_hash: str, versions: dict[int, str]) -> set[int]:
        """The problems of ``versions`` whose result for this content and grader version is committed."""
        rows = self.db.execute(
            "SELECT s.problem, s.grader_version FROM submissions s JOIN students st ON st.id = s.student_id "
            "WHERE st.name = ? AND s.content_hash = ?",
            (student, content_hash),
        )
        return {row["problem"] for row in rows if versions.get(row["problem"]) == row["grader_version"]}

    def stopped(self, student: str) -> bool:
        """Whether the student's latest result of some problem was stopped at the batch's time limit."""
        row = self.db.execute(_CURRENT.format(where="AND st.name = ? AND s.outcome = 'timeout' "), (student,))
        return row.fetchone() is not None

    def record(
        self,
        student: str,
        content_hash: str,
        versions: dict[int, str],
        run_id: int,
        reports: list[ProblemReport],
        outcome: str = "graded",
        replace_existing: bool = False,
    ) -> None:
        """Commit a student's result: every problem and check in one transaction.

        An existing result of the same key is an error (``sqlite3.IntegrityError``, nothing written) unless
        ``replace_existing`` (a forced regrade), which replaces it in the same transaction."""
        graded_at = now()
        with self.transaction() as db:
            db.execute("INSERT OR IGNORE INTO students (name) VALUES (?)", (student,))
            (student_id,) = db.execute("SELECT id FROM students WHERE name = ?", (student,)).fetchone()
            for report in reports:
                key = (student_id, content_hash, versions[report.problem], report.problem)
                if replace_existing:
                    db.execute(
                        "DELETE FROM submissions WHERE student_id = ? AND content_hash = ? AND grader_version = ? "
                        "AND problem = ?",
                        key,
                    )
                cursor = db.execute(
                    "INSERT INTO submissions (student_id, content_hash, grader_version, problem, run_id, graded_at, "
                    "seed, outcome, score, max_score, source, title, sandbox, isolated, duration, stdout, stderr, "
                    "notes, manual, load_error) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                    (
                        *key, run_id, graded_at, report.seed, outcome,
                        sum(r.score for r in report.results), report.auto_max_score, report.submission,
                        report.title, report.sandbox, int(report.isolated), report.duration, report.stdout,
                        report.stderr, json.dumps(list(report.notes)),
                        json.dumps([asdict(replace(m, score=None, comment="")) for m in report.manual]),
                        report.load_error,
                    ),
                )
                db.executemany(
                    "INSERT INTO check_results (submission_id, check_id, problem, title, status, score, max_score, "
                    "message, hint, diagnosis, visibility, stage, seed, duration, figures, position) "
                    "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                    [
                        (
                            cursor.lastrowid, r.check_id, r.problem, r.title, r.status.value, r.score, r.max_score,
                            r.message, r.hint, r.diagnosis, r.visibility, r.stage, r.seed, r.duration,
                            json.dumps([asdict(f) for f in r.figures]), position,
                        )
                        for position, r in enumerate(report.results)
                    ],
                )
                db.executemany(
                    "INSERT OR IGNORE INTO wrong_answers (submission_id, check_id, call, call_key, value_key, value, "
                    "expected) VALUES (?, ?, ?, ?, ?, ?, ?)",
                    [(cursor.lastrowid, a.check_id, a.call, a.call_key, a.value_key, a.value, a.expected)
                     for a in report.wrong_answers],
                )
            db.execute("UPDATE runs SET graded = graded + 1 WHERE id = ?", (run_id,))

    # ------------------------------------------------------------------ reading

    def current(self, student: str | None = None, figures: bool = True) -> list[Graded]:
        """The latest result of every (student, problem), rebuilt as reports with the manual scores and their
        comments merged; only
        ``student``'s when given.  ``figures=False`` leaves the checks' figures out (most of a report's bytes, about
        0.9 MB of a whole course's 1 MB): what the files about the whole class read, so that their memory grows
        with the class by scores and verdicts only."""
        where, args = ("AND st.name = ? ", (student,)) if student is not None else ("", ())
        manual = {
            (row["name"], row["problem"], row["key"]): {"score": row["score"], "comment": row["comment"]}
            for row in self.db.execute(
                "SELECT st.name, m.* FROM manual_scores m JOIN students st ON st.id = m.student_id " + where.replace(
                    "AND", "WHERE"), args)
        }
        graded = []
        for row in self.db.execute(_CURRENT.format(where=where), args).fetchall():
            checks = self.db.execute(
                f"SELECT {_CHECK_COLUMNS if figures else _CHECK_COLUMNS_NO_FIGURES} FROM check_results "
                "WHERE submission_id = ? ORDER BY position", (row["id"],)
            )
            results = tuple(
                CheckResult(
                    check_id=c["check_id"], problem=c["problem"], title=c["title"], status=Status(c["status"]),
                    score=c["score"], max_score=c["max_score"], message=c["message"], hint=c["hint"],
                    diagnosis=c["diagnosis"], visibility=c["visibility"], stage=c["stage"], seed=c["seed"],
                    figures=tuple(_figure(f) for f in json.loads(c["figures"])) if figures else (),
                    duration=c["duration"],
                )
                for c in checks
            )
            items = tuple(
                ManualItem(**dict(item, **manual.get((row["student"], row["problem"], item["key"]),
                                                     {"score": None, "comment": ""})))
                for item in json.loads(row["manual"])
            )
            report = ProblemReport(
                problem=row["problem"], title=row["title"], results=results, manual=items, sandbox=row["sandbox"],
                isolated=bool(row["isolated"]), seed=row["seed"], duration=row["duration"], stdout=row["stdout"],
                stderr=row["stderr"], submission=row["source"], grader_version=row["grader_version"],
                notes=tuple(json.loads(row["notes"])), load_error=row["load_error"],
            )
            graded.append(
                Graded(row["student"], row["content_hash"], row["grader_version"], row["run_id"], row["graded_at"],
                       row["outcome"], report)
            )
        return graded

    # ------------------------------------------------------------------ manual scores

    def import_manual(self, text: str, source: str = "") -> int:
        """Merge a CSV of manual scores (columns student, problem, key, score and optionally comment; rows with
        a blank score are skipped).  All rows are checked first; nothing is imported if any is wrong."""
        items = {
            (g.student, g.report.problem, m.key): m for g in self.current(figures=False) for m in g.report.manual
        }
        reader = csv.DictReader(io.StringIO(text))
        missing = {"student", "problem", "key", "score"} - set(reader.fieldnames or ())
        if missing:
            raise ManualScoreError(f"the file has no column {', '.join(sorted(missing))}")
        rows, errors = [], []
        for line, entry in enumerate(reader, start=2):
            if not (entry.get("score") or "").strip():
                continue
            try:
                key = (spreadsheet_text(entry["student"].strip()), int(str(entry["problem"]).strip()),
                       spreadsheet_text(entry["key"].strip()))
                score = float(entry["score"])
            except ValueError as exc:
                errors.append(f"line {line}: {exc}")
                continue
            item = items.get(key)
            if item is None:
                errors.append(f"line {line}: {key[0]} has no free-text answer {key[2]!r} in problem {key[1]}")
            elif not 0 <= score <= item.max_score:
                errors.append(f"line {line}: score {score:g} is outside 0..{item.max_score:g}")
            else:
                rows.append((*key, score, spreadsheet_text((entry.get("comment") or "").strip())))
        if errors:
            raise ManualScoreError("\n".join(errors))
        stamp = now()
        with self.transaction() as db:
            db.executemany(
                "INSERT INTO manual_scores (student_id, problem, key, score, comment, imported_at, source) "
                "SELECT id, ?, ?, ?, ?, ?, ? FROM students WHERE name = ? "
                "ON CONFLICT (student_id, problem, key) DO UPDATE SET score = excluded.score, "
                "comment = excluded.comment, imported_at = excluded.imported_at, source = excluded.source",
                [(problem, key, score, comment, stamp, source, student)
                 for student, problem, key, score, comment in rows],
            )
        return len(rows)

    # ------------------------------------------------------------------ the course: times, standings, its file

    def meta(self, key: str) -> str | None:
        row = self.db.execute("SELECT value FROM meta WHERE key = ?", (key,)).fetchone()
        return row["value"] if row is not None else None

    def set_meta(self, key: str, value: str) -> None:
        with self.transaction() as db:
            db.execute("INSERT INTO meta VALUES (?, ?) ON CONFLICT (key) DO UPDATE SET value = excluded.value",
                       (key, value))

    def note_submission_times(self, rows: list[tuple[str, str, str, str]]) -> None:
        """Record when each (student, content) was submitted: (student, content hash, ISO time, source).  The first
        time seen for a content stays (a later download of the same work does not make it late), unless the new one
        comes from Gradescope's metadata and the kept one from the files' times."""
        with self.transaction() as db:
            db.executemany(
                "INSERT INTO submission_times (student, content_hash, submitted_at, source) VALUES (?, ?, ?, ?) "
                "ON CONFLICT (student, content_hash) DO UPDATE SET submitted_at = excluded.submitted_at, "
                "source = excluded.source WHERE excluded.source = 'gradescope' AND submission_times.source = 'files'",
                rows)

    def submission_times(self) -> dict[tuple[str, str], tuple[str, str]]:
        """(student, content hash) -> (ISO time, source)."""
        rows = self.db.execute("SELECT student, content_hash, submitted_at, source FROM submission_times")
        return {(r["student"], r["content_hash"]): (r["submitted_at"], r["source"]) for r in rows}

    def save_standings(self, rows: list[tuple], course: str) -> None:
        """Replace the assignments' scores with ``rows`` (student, assignment, raw, possible, penalty, final, due,
        submitted at, submitted from, days late, grace days, excused), computed from ``course``: one transaction."""
        stamp = now()
        with self.transaction() as db:
            db.execute("DELETE FROM assignment_scores")
            db.executemany(
                "INSERT INTO assignment_scores (student, assignment, raw, possible, penalty, final, due, submitted_at, "
                "submitted_from, days_late, grace_days, excused, computed_at, course) "
                "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                [(*row, stamp, course) for row in rows])

    def wrong_answers(self) -> list[tuple[str, int, object]]:
        """``(student, problem, Answer)`` of every student's current results: the wrong answers on the inputs every
        student is asked (``grader.answers``), for ``grade similarity``."""
        from ..answers import Answer

        rows = self.db.execute(
            "SELECT st.name, s.problem, w.check_id, w.call, w.call_key, w.value_key, w.value, w.expected "
            "FROM wrong_answers w JOIN submissions s ON s.id = w.submission_id "
            "JOIN students st ON st.id = s.student_id "
            "WHERE s.id = (SELECT max(t.id) FROM submissions t WHERE t.student_id = s.student_id "
            "AND t.problem = s.problem) ORDER BY st.name, s.problem, w.check_id, w.call_key")
        return [(row[0], row[1], Answer(*row[2:])) for row in rows]

    def submitted(self) -> list[tuple[str, int, str, str, str]]:
        """``(student, problem, source, content hash, load error)`` of every student's current results."""
        rows = self.db.execute(_CURRENT.format(where=""))
        return [(r["student"], r["problem"], r["source"], r["content_hash"], r["load_error"]) for r in rows]

    def diagnosed(self) -> list[tuple[str, int, str, str]]:
        """``(student, problem, check id, diagnosis)`` of every failed check with a diagnosis in the students'
        current results."""
        rows = self.db.execute(
            "SELECT st.name, s.problem, c.check_id, c.diagnosis FROM check_results c "
            "JOIN submissions s ON s.id = c.submission_id JOIN students st ON st.id = s.student_id "
            "WHERE c.diagnosis != '' AND c.status = 'failed' AND s.id = (SELECT max(t.id) FROM submissions t "
            "WHERE t.student_id = s.student_id AND t.problem = s.problem) ORDER BY st.name, c.check_id")
        return [tuple(row) for row in rows]

    def manual_comments(self) -> dict[tuple[str, int, str], str]:
        rows = self.db.execute("SELECT st.name, m.problem, m.key, m.comment FROM manual_scores m "
                               "JOIN students st ON st.id = m.student_id")
        return {(r["name"], r["problem"], r["key"]): r["comment"] for r in rows}
