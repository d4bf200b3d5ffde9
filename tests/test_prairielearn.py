"""PrairieLearn (issue 30): ``grade prairielearn OUT_DIR`` writes a course fragment (questions with external grading,
the grader's wheel in the course files, the image's recipe and its entry point), and the entry point grades a job
folder shaped like PrairieLearn's ``/grade`` into a results.json that the JSON Schema below accepts.

The schema is written from PrairieLearn's documentation of external grading: the job folder holds ``student/``
(the uploaded files), ``tests/`` (the question's own ``tests/`` folder), ``data/data.json`` and
``serverFilesCourse/`` (the course files that info.json lists); the grader writes ``results/results.json`` with
``gradable`` (bool), ``score`` (0 to 1, the one required field), ``message``, ``output``, ``format_errors``,
``tests`` (each ``name``, ``description``, ``points``, ``max_points``, ``message``, ``output``, ``images``) and
``images`` (each ``label`` and ``url``, a data URL), 1 MB at most.  A question's info.json has ``uuid``, ``title``,
``topic``, ``type: "v3"``, ``gradingMethod: "External"``, ``singleVariant`` and ``externalGradingOptions``
(``enabled``, ``image``, ``entrypoint``, ``serverFilesCourse``, ``timeout``).

The end-to-end tests run the entry point as PrairieLearn would, outside Docker: a virtual environment that sees
this interpreter's packages stands for the image's (``GRADER_HOME``), and the job folder is a temporary folder."""

from __future__ import annotations

import json
import shutil
import stat
import subprocess
import sys
import uuid
import zipfile
from dataclasses import replace
from pathlib import Path

import jsonschema
import pytest

from grader.prairielearn import (ENTRYPOINT, FAULT_FILE, IMAGE_DIR, PROBLEM_FILE, QUESTIONS, SERVER_FILES,
                                 build_fragment, problem_files, question_timeout)
from grader.report.prairielearn_results import RESULTS_BYTES, fault_results, results_json, unloadable_results
from grader.results import CheckResult, Figure, ManualItem, ProblemReport, Series, Status

from .environments import outside_env, public_tmp_dir
from .submissions import ROOT, build_planted, copy_reference, copy_template, planted_mistakes

# ---------------------------------------------------------------------------------------------- the schemas

IMAGE_SCHEMA = {
    "type": "object",
    "properties": {"label": {"type": "string"},
                   "url": {"type": "string",
                           "pattern": r"^data:image/(png|jpeg|gif|svg\+xml);base64,[A-Za-z0-9+/=]+$"}},
    "required": ["url"],
    "additionalProperties": False,
}

TEST_SCHEMA = {
    "type": "object",
    "properties": {
        "name": {"type": "string"},
        "description": {"type": "string"},
        "points": {"type": "number"},
        "max_points": {"type": "number"},
        "message": {"type": "string"},
        "output": {"type": "string"},
        "images": {"type": "array", "items": IMAGE_SCHEMA},
    },
    "required": ["name"],
    "additionalProperties": False,
}

RESULTS_SCHEMA = {
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "type": "object",
    "properties": {
        "gradable": {"type": "boolean"},
        "score": {"type": "number", "minimum": 0, "maximum": 1},
        "message": {"type": "string"},
        "output": {"type": "string"},
        "format_errors": {"anyOf": [{"type": "string"}, {"type": "array", "items": {"type": "string"}},
                                    {"type": "object", "additionalProperties": {"type": "string"}}]},
        "tests": {"type": "array", "items": TEST_SCHEMA},
        "images": {"type": "array", "items": IMAGE_SCHEMA},
    },
    "required": ["score"],
    "additionalProperties": False,
}

INFO_SCHEMA = {
    "type": "object",
    "properties": {
        "uuid": {"type": "string", "pattern": "^[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}$"},
        "title": {"type": "string", "minLength": 1},
        "topic": {"type": "string", "minLength": 1},
        "tags": {"type": "array", "items": {"type": "string"}},
        "type": {"const": "v3"},
        "gradingMethod": {"const": "External"},
        "singleVariant": {"type": "boolean"},
        "externalGradingOptions": {
            "type": "object",
            "properties": {
                "enabled": {"type": "boolean"},
                "image": {"type": "string", "minLength": 1},
                "entrypoint": {"type": "string", "minLength": 1},
                "serverFilesCourse": {"type": "array", "items": {"type": "string"}},
                "timeout": {"type": "integer", "minimum": 1},
            },
            "required": ["enabled", "image", "entrypoint", "timeout"],
            "additionalProperties": False,
        },
    },
    "required": ["uuid", "title", "topic", "type", "gradingMethod", "externalGradingOptions"],
    "additionalProperties": False,
}


def validate(data: dict) -> dict:
    """results.json as PrairieLearn's documentation allows it, and as this grader promises: within 1 MB; not
    gradable only with the reason in ``format_errors`` and no tests; gradable with a score that is the fraction of
    the tests' points, each within its maximum."""
    jsonschema.validate(data, RESULTS_SCHEMA)
    assert len(json.dumps(data).encode()) <= RESULTS_BYTES
    if not data["gradable"]:
        assert data["format_errors"] and data["tests"] == [] and data["score"] == 0
        return data
    points = sum(t["points"] for t in data["tests"])
    maximum = sum(t["max_points"] for t in data["tests"])
    assert data["score"] == pytest.approx(points / maximum if maximum else 0.0)
    for test in data["tests"]:
        assert 0 <= test["points"] <= test["max_points"], test["name"]
    return data


def test_the_schema_rejects_what_the_documentation_does_not_allow():
    jsonschema.validate({"score": 0.5}, RESULTS_SCHEMA)
    jsonschema.validate({"gradable": False, "score": 0, "format_errors": ["why"]}, RESULTS_SCHEMA)
    bad = [
        {"gradable": True},  # no score
        {"score": 1.5},  # outside 0..1
        {"score": "1"},
        {"score": 1, "tests": [{"points": 1}]},  # a test without a name
        {"score": 1, "tests": [{"name": "a", "score": 1}]},  # Gradescope's field, not PrairieLearn's
        {"score": 1, "images": [{"label": "x", "url": "https://example.org/x.png"}]},  # not a data URL
        {"score": 1, "visibility": "visible"},
    ]
    for data in bad:
        with pytest.raises(jsonschema.ValidationError):
            jsonschema.validate(data, RESULTS_SCHEMA)


# ---------------------------------------------------------------------------------------------- results.json


def _figure(points: int = 40) -> Figure:
    xs = tuple(float(i) for i in range(points))
    return Figure("the student's curve over the reference's", "t [s]", "q [rad]",
                  (Series("yours", xs, tuple(x * x for x in xs), "student"),
                   Series("reference", xs, tuple(x * (x + 1) for x in xs), "reference")))


def _reports(**changes) -> list[ProblemReport]:
    results = (
        CheckResult("p99.shape", 99, "returns a 3 x 3 matrix", Status.PASSED, 1, 1, seed=5),
        CheckResult("p99.values", 99, "equals the rotation", Status.FAILED, 0, 2, "got A_CI\nexpected A_IC",
                    hint="transpose it", diagnosis="transpose", seed=5, figures=(_figure(),)),
        CheckResult("p99.choice", 99, "(a) the chosen matrix", Status.FAILED, 0, 1, "the key is option 4",
                    diagnosis="wrong_choice"),
        CheckResult("p99.deep", 99, "the deep property", Status.PASSED, 3, 3, "the hidden detail",
                    visibility="hidden"),
    )
    manual = (ManualItem(99, "why", "Why is it a rotation?", "because", "THE MODEL ANSWER", 2.0),)
    return [replace(ProblemReport(99, "Synthetic", results, manual, sandbox="bubblewrap", seed=5), **changes)]


def test_results_score_the_problem_and_keep_secret_and_hidden_checks_back():
    data = validate(results_json(_reports(), withheld_ids={"p99.choice"}, seed=5))
    assert data["gradable"] is True and data["score"] == pytest.approx(4 / 7)
    tests = {t["description"]: t for t in data["tests"]}
    values = tests["p99.values"]
    assert values["points"] == 0 and values["max_points"] == 2
    assert values["message"] == "got A_CI (likely mistake: transpose)"
    assert "expected A_IC" in values["output"] and "hint: transpose it" in values["output"]
    assert "seed 5" in values["output"]
    (image,) = values["images"]
    assert image["url"].startswith("data:image/png;base64,") and image["label"].startswith("the student's curve")
    # the secret and the hidden check: their points in one test, never their messages
    withheld = tests["graded now; only their points are shown"]
    assert (withheld["points"], withheld["max_points"]) == (3, 4)
    assert "(a) the chosen matrix" in withheld["output"] and "1 hidden check" in withheld["output"]
    text = json.dumps(data)
    assert "the key is option 4" not in text and "the hidden detail" not in text and "the deep property" not in text
    assert "THE MODEL ANSWER" not in text
    # the free-text answer: the student's answer, scored by hand apart from this score
    manual = tests["free text: why"]
    assert (manual["points"], manual["max_points"]) == (0, 0) and "because" in manual["output"]
    assert "Score: 4 of 7 points." in data["message"] and "seed 5" in data["message"]
    assert "scored by hand" in data["message"]


def test_a_plain_process_is_said_in_the_results():
    note = "plain process under an unprivileged uid: bubblewrap is not available"
    data = validate(results_json(_reports(isolated=False, sandbox=note), withheld_ids=set(), seed=5))
    assert note in data["message"]
    bwrap = validate(results_json(_reports(), withheld_ids=set(), seed=5))
    assert "Notes" not in bwrap["message"]


def test_an_unloadable_submission_is_not_gradable_and_says_why():
    data = validate(results_json(_reports(load_error="mywork.zip is not a valid zip archive"), seed=5))
    assert data["gradable"] is False
    assert "could not be loaded" in data["format_errors"][0]
    assert "mywork.zip is not a valid zip archive" in data["format_errors"][0]
    assert "grader" not in data["message"]  # the student's fault, never said to be the grader's
    assert unloadable_results("why")["gradable"] is False


def test_a_fault_of_the_grader_costs_the_student_nothing():
    first = _reports()[0]
    broken = replace(first, results=first.results + (
        CheckResult("p99.broken", 99, "a check the grader could not run", Status.GRADER_ERROR, 0, 1,
                    "internal grader error (not your fault): KeyError"),))
    data = validate(results_json([broken], seed=5))
    assert data["gradable"] is False and data["score"] == 0
    assert "fault of the grader, not of your work" in data["message"]
    assert "costs you no attempt" in data["message"] and "p99.broken" in data["message"]
    assert data["format_errors"] == [data["message"]]
    data = validate(fault_results("the sandbox cannot start"))
    assert "the sandbox cannot start" in data["message"] and data["gradable"] is False


def test_results_stay_within_the_size_bound():
    """Many figures and a student's flood of output: the figures are drawn smaller, then left out, and long texts
    cut, until results.json fits (here a bound of 200 kB stands for PrairieLearn's 1 MB)."""
    first = _reports()[0]
    many = tuple(CheckResult(f"p99.plot{i}", 99, f"plot {i}", Status.FAILED, 0, 1, "x" * 50_000,
                             figures=(_figure(200), _figure(200))) for i in range(12))
    report = replace(first, results=first.results + many)
    limit = 200_000
    data = results_json([report], withheld_ids=set(), seed=5, limit=limit)
    validate(data)
    assert len(json.dumps(data).encode()) <= limit
    assert "left out to keep these results within PrairieLearn's size limit" in data["message"]
    assert any("more characters left out" in t["output"] for t in data["tests"])
    # with room enough, the figures are drawn, smaller than at full size when needed
    roomy = results_json([report], withheld_ids=set(), seed=5, limit=RESULTS_BYTES)
    validate(roomy)
    assert sum(len(t.get("images", ())) for t in roomy["tests"]) == 25
    assert "left out" not in roomy["message"]


# ---------------------------------------------------------------------------------------------- the fragment

PROBLEMS = [6, 10]


@pytest.fixture(scope="module")
def fragment(tmp_path_factory):
    return build_fragment(tmp_path_factory.mktemp("prairielearn") / "course", PROBLEMS, image="example/mbd:1")


def test_the_fragment_holds_questions_course_files_and_the_image(fragment):
    out = fragment.out
    assert fragment.problems == tuple(PROBLEMS) and fragment.image == "example/mbd:1"
    uuids = set()
    for number in PROBLEMS:
        folder = out / QUESTIONS / f"problem-{number:02d}"
        assert sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if p.is_file()) == \
            ["info.json", "question.html", f"tests/{PROBLEM_FILE}"]
        info = json.loads((folder / "info.json").read_text())
        jsonschema.validate(info, INFO_SCHEMA)
        options = info["externalGradingOptions"]
        assert options == {"enabled": True, "image": "example/mbd:1", "entrypoint": ENTRYPOINT,
                           "serverFilesCourse": [f"{SERVER_FILES}/"], "timeout": question_timeout(number)}
        uuids.add(uuid.UUID(info["uuid"]))
        assert json.loads((folder / "tests" / PROBLEM_FILE).read_text())["problem"] == number
        html = (folder / "question.html").read_text()
        assert f'<pl-file-upload file-names="{", ".join(problem_files(number))}"></pl-file-upload>' in html
        assert "<pl-external-grader-results></pl-external-grader-results>" in html
        assert "<pl-submission-panel>" in html
    assert len(uuids) == len(PROBLEMS)
    # the same problem keeps its UUID in every build (PrairieLearn identifies a question by it)
    again = build_fragment(out.parent / "again", [6])
    assert json.loads((again.out / QUESTIONS / "problem-06" / "info.json").read_text())["uuid"] == \
        json.loads((out / QUESTIONS / "problem-06" / "info.json").read_text())["uuid"]
    # the course files: the wheel with the reference and no answer key, and the results of a grader that fails
    server = out / "serverFilesCourse" / SERVER_FILES
    assert sorted(p.name for p in server.iterdir()) == sorted([fragment.wheel, FAULT_FILE])
    validate(json.loads((server / FAULT_FILE).read_text()))
    with zipfile.ZipFile(server / fragment.wheel) as wheel:
        names = wheel.namelist()
        assert wheel.read("reference/rotations.py") == (ROOT / "reference" / "rotations.py").read_bytes()
        assert "grader/report/templates/prairielearn/entrypoint.sh.j2" in names
        assert not [n for n in names if n.endswith("answer_key.json.gz")]
    # the image: no code of the project (it is public), the entry point in it, executable
    image = out / IMAGE_DIR
    dockerfile = (image / "Dockerfile").read_text()
    assert "bubblewrap" in dockerfile and f"COPY mbd-prairielearn {ENTRYPOINT}" in dockerfile
    instructions = [line for line in dockerfile.splitlines() if line.strip() and not line.startswith("#")]
    copied = [line for line in instructions if line.startswith(("COPY", "ADD"))]
    assert copied == [f"COPY mbd-prairielearn {ENTRYPOINT}"]
    assert not [line for line in instructions if "reference" in line or ".whl" in line]
    entry = image / "mbd-prairielearn"
    assert entry.stat().st_mode & 0o111 == 0o111
    text = entry.read_text()
    assert text.startswith("#!/usr/bin/env bash\n")
    assert subprocess.run(["bash", "-n", str(entry)], capture_output=True).returncode == 0
    assert "-m grader.cli prairielearn --run" in text and 'chmod -R go-rwx "$SITE/reference"' in text


def test_a_problem_asks_for_the_files_its_checks_use():
    assert problem_files(6) == ["problem_06.py", "rotations.py"]
    assert problem_files(7) == ["problem_07.py", "problem_06.py", "rotations.py"]  # builds on R1, R2, R3, cardan
    assert problem_files(10) == ["problem_10.py", "answers.toml"]  # multiple-choice answers
    # a check that reads a value's "inertia" key does not ask for inertia.py, which these problems never use
    assert problem_files(2) == ["problem_02.py", "problem_03.py", "answers.toml"]
    assert problem_files(5) == ["problem_05.py", "answers.toml"]
    assert problem_files(22) == ["problem_22.py", "planar.py"]
    tree = problem_files(31)
    assert "tree.py" in tree and "dynamics.py" in tree and "conventions.py" not in tree  # given, nothing to write


def test_grade_prairielearn_command(tmp_path, capsys, monkeypatch):
    from grader.cli import EXIT_GRADER, EXIT_OK, EXIT_USAGE, main

    assert main(["prairielearn", str(tmp_path / "course"), "--problems", "6", "--image", "me/mbd:2"]) == EXIT_OK
    printed = capsys.readouterr().out
    assert "wrote 1 questions (problems 6" in printed and "docker build -t me/mbd:2" in printed
    assert (tmp_path / "course" / QUESTIONS / "problem-06" / "info.json").is_file()
    assert main(["prairielearn", str(tmp_path / "x"), "--problems", "6,98"]) == EXIT_USAGE
    assert "no checks for problem 98" in capsys.readouterr().err
    assert main(["prairielearn"]) == EXIT_USAGE
    assert main(["prairielearn", str(tmp_path / "y"), "--run", str(tmp_path)]) == EXIT_USAGE
    # a job folder whose tests/ names no problem: the question was not built here, the grader's fault
    job = tmp_path / "job"
    (job / "student").mkdir(parents=True)
    assert main(["prairielearn", "--run", str(job)]) == EXIT_GRADER
    data = validate(json.loads((job / "results" / "results.json").read_text()))
    assert data["gradable"] is False and f"tests/{PROBLEM_FILE} cannot be read" in data["message"]
    monkeypatch.setattr("grader.oracle.reference_available", lambda: False)
    assert main(["prairielearn", str(tmp_path / "z")]) == EXIT_USAGE
    assert "needs the full project" in capsys.readouterr().err


# ---------------------------------------------------------------------------------------------- end to end


@pytest.fixture(scope="module")
def image(fragment):
    """What the image holds, outside Docker: a virtual environment (seeing this interpreter's packages, as the
    image's has the dependencies) in a folder every user may read, and the entry point."""
    with public_tmp_dir("grader-prairielearn-") as base:
        subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(base / "venv")], check=True,
                       capture_output=True, timeout=300)
        yield {"base": base, "home": base, "entry": fragment.out / IMAGE_DIR / "mbd-prairielearn"}


def _env(image, **changes) -> dict:
    env = outside_env()
    env.update(GRADER_HOME=str(image["home"]), GRADER_CACHE=str(image["base"] / "cache"))
    env.update(changes)
    return env


def _job(fragment, image, number: int, student: Path | None, name: str) -> Path:
    """A folder shaped like PrairieLearn's /grade for ``number``: the uploaded files of ``student`` (those the
    question asks for, or the one file given), the question's tests/, data/data.json and the course files."""
    job = image["base"] / "jobs" / name
    question = fragment.out / QUESTIONS / f"problem-{number:02d}"
    (job / "student").mkdir(parents=True)
    shutil.copytree(question / "tests", job / "tests")
    shutil.copytree(fragment.out / "serverFilesCourse" / SERVER_FILES, job / "serverFilesCourse" / SERVER_FILES)
    files = {}
    if student is not None and student.is_dir():
        for file in problem_files(number):
            shutil.copy2(student / file, job / "student" / file)
            files[file] = (student / file).read_text()
    elif student is not None:
        shutil.copy2(student, job / "student" / student.name)
    (job / "data").mkdir()
    data = {"params": {}, "correct_answers": {}, "submitted_answers": {"_files": sorted(files)},
            "format_errors": {}, "partial_scores": {}, "score": 0, "feedback": {}, "variant_seed": 1,
            "options": {}, "raw_submitted_answers": {}, "gradable": True}
    (job / "data" / "data.json").write_text(json.dumps(data))
    return job


def _grade(image, job: Path, **env) -> tuple[int, dict, str]:
    done = subprocess.run(["bash", str(image["entry"]), str(job)], env=_env(image, **env), capture_output=True,
                          text=True, timeout=900)
    results = job / "results" / "results.json"
    assert results.is_file(), done.stdout + done.stderr
    return done.returncode, validate(json.loads(results.read_text())), done.stdout + done.stderr


@pytest.mark.slow
def test_the_entry_point_grades_reference_template_a_mistake_and_an_unloadable_upload(fragment, image, tmp_path):
    # the reference: every check passed, score 1.0, graded by the wheel of the course files
    code, data, log = _grade(image, _job(fragment, image, 6, copy_reference(tmp_path / "reference"), "ref"))
    assert code == 0, log
    assert data["gradable"] is True and data["score"] == 1.0, log
    assert all(t["points"] == t["max_points"] > 0 for t in data["tests"])
    assert f"at {image['base']}/venv/lib" in log  # the installed wheel, not this checkout
    site = next((image["base"] / "venv").glob("lib/python3*/site-packages"))
    for path in (site / "reference", site / "reference" / "rotations.py"):
        assert path.stat().st_mode & 0o077 == 0, path  # root's alone: the students' uid cannot read it
    job = image["base"] / "jobs" / "ref"
    assert stat.S_IMODE(job.stat().st_mode) == 0o700

    # the untouched template: gradable, 0, every check says what is missing
    code, data, log = _grade(image, _job(fragment, image, 6, copy_template(tmp_path / "template"), "template"))
    assert code == 0, log
    assert data["gradable"] is True and data["score"] == 0
    assert any("not implemented" in t["message"] for t in data["tests"])

    # a planted mistake: its check fails with its diagnosis; the rest keep their points
    order = next(m for m in planted_mistakes(6) if m.name == "p06-cardan-rotation-order")
    code, data, log = _grade(image, _job(fragment, image, 6, build_planted(order, tmp_path / "planted"), "planted"))
    assert code == 0, log
    failed = {t["description"]: t for t in data["tests"] if t["points"] < t["max_points"]}
    assert set(failed) == {order.check}, log
    assert f"likely mistake: {order.diagnosis}" in failed[order.check]["message"]
    assert order.message in failed[order.check]["output"]
    assert 0 < data["score"] < 1

    # a multiple-choice problem: graded, the key kept back
    code, data, log = _grade(image, _job(fragment, image, 10, copy_reference(tmp_path / "ref10"), "ref10"))
    assert code == 0 and data["score"] == 1.0, log
    assert any(t["name"].endswith("checks whose details are withheld") for t in data["tests"])

    # an upload that cannot be loaded: not gradable (no attempt), the reason in format_errors
    broken = tmp_path / "upload" / "mywork.zip"
    broken.parent.mkdir()
    broken.write_bytes(b"PK\x03\x04 this is not a zip archive")
    code, data, log = _grade(image, _job(fragment, image, 6, broken, "unloadable"))
    assert code == 0, log
    assert data["gradable"] is False and "could not be loaded" in data["format_errors"][0]
    assert "mywork.zip" in data["format_errors"][0] and "fault of the grader" not in data["message"]


@pytest.mark.slow
def test_a_broken_installation_is_never_the_students_fault(fragment, image, tmp_path):
    # no grader environment at all: the course files' fault results, exit code 3
    code, data, log = _grade(image, _job(fragment, image, 6, copy_reference(tmp_path / "a"), "nohome"),
                             GRADER_HOME=str(tmp_path / "nowhere"))
    assert code == 3, log
    assert data["gradable"] is False and "fault of the grader, not of your work" in data["message"]
    assert "the grader's installation is broken" in log
    # the grader starts but the question names a problem it has no checks for
    job = _job(fragment, image, 6, copy_reference(tmp_path / "b"), "noproblem")
    (job / "tests" / PROBLEM_FILE).write_text(json.dumps({"problem": 98}))
    code, data, log = _grade(image, job)
    assert code == 3, log
    assert data["gradable"] is False and "no checks for problem 98" in data["message"]
    assert "costs you no attempt" in data["message"]
