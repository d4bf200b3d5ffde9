"""Gradescope's autograder (issue 9): the zip holds what the specification asks for and nothing it forbids; its
setup.sh installs the grader with the reference; its run_autograder grades a submission with fresh random inputs
and writes a results.json that the specification's JSON Schema accepts, with secret and hidden checks shown only
after publication and the grader's own faults stated as such.

The specification (Gradescope's "Autograder Specifications"): the zip has ``setup.sh`` and ``run_autograder`` at
its root and is unpacked into ``/autograder/source``; ``run_autograder`` is copied to ``/autograder`` and runs there
for each submission, which Gradescope puts in ``/autograder/submission``; it must write
``/autograder/results/results.json``.  The end-to-end test builds that layout in a temporary folder
(``AUTOGRADER_ROOT``) and runs setup.sh offline (``GRADER_OFFLINE=1``: the wheel from the zip with ``--no-deps``
into a virtual environment that sees this interpreter's packages; the real setup.sh installs bubblewrap, Python
and the dependencies itself)."""

from __future__ import annotations

import json
import os
import re
import shutil
import stat
import subprocess
import sys
import tempfile
import zipfile
from dataclasses import replace
from pathlib import Path

import jsonschema
import pytest

from grader.arguments import parse_problems
from grader.gradescope import CONFIG, FAULT, RUN, SETUP, WHEEL_PACKAGES, build_autograder
from grader.report.gradescope_results import WITHHELD, fault_results, results_json
from grader.results import CheckResult, ManualItem, ProblemReport, Status

from .environments import outside_env
from .submissions import ROOT, build_planted, copy_reference, copy_template, planted_mistakes

# ---------------------------------------------------------------------------------------------- the schema

#: Gradescope's visibility options and output formats, as the specification lists them
VISIBILITY = {"enum": ["hidden", "after_due_date", "after_published", "visible"]}
FORMAT = {"enum": ["text", "html", "simple_format", "md", "ansi"]}

#: one test case of results.json (every field optional, no other field)
TEST_SCHEMA = {
    "type": "object",
    "properties": {
        "score": {"type": "number"},
        "max_score": {"type": "number"},
        "status": {"enum": ["passed", "failed"]},
        "name": {"type": "string"},
        "name_format": FORMAT,
        "number": {"type": "string"},
        "output": {"type": "string"},
        "output_format": FORMAT,
        "tags": {"type": "array", "items": {"type": "string"}},
        "visibility": VISIBILITY,
        "extra_data": {"type": "object"},
    },
    "additionalProperties": False,
}

#: results.json: a top-level score, or a score on every test
RESULTS_SCHEMA = {
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "type": "object",
    "properties": {
        "score": {"type": "number"},
        "execution_time": {"type": "number", "minimum": 0},
        "output": {"type": "string"},
        "output_format": FORMAT,
        "test_output_format": FORMAT,
        "test_name_format": FORMAT,
        "visibility": VISIBILITY,
        "stdout_visibility": VISIBILITY,
        "extra_data": {"type": "object"},
        "tests": {"type": "array", "items": TEST_SCHEMA},
        "leaderboard": {
            "type": "array",
            "items": {
                "type": "object",
                "properties": {"name": {"type": "string"}, "value": {"type": ["number", "string"]},
                               "order": {"enum": ["asc", "desc"]}},
                "required": ["name", "value"],
                "additionalProperties": False,
            },
        },
    },
    "additionalProperties": False,
    "anyOf": [
        {"required": ["score"]},
        {"required": ["tests"], "properties": {"tests": {"items": {"required": ["score"]}}}},
    ],
}


def validate(data: dict) -> dict:
    """results.json as the specification allows it, and as this grader promises: the top-level score is the sum
    of the tests' scores, each scored test has a maximum, a status, and a score within it."""
    jsonschema.validate(data, RESULTS_SCHEMA)
    scored = [t for t in data["tests"] if "score" in t]
    assert data["score"] == pytest.approx(sum(t["score"] for t in scored))
    for test in scored:
        assert "max_score" in test and "status" in test, test["name"]
        assert 0 <= test["score"] <= test["max_score"], test["name"]
        assert (test["status"] == "passed") == (test["extra_data"]["status"] == "passed"), test["name"]
    assert data["stdout_visibility"] == "hidden"  # tracebacks and the grader's log are for the course staff
    return data


def visible_text(data: dict) -> str:
    """Everything of results.json a student sees before the grades are published."""
    parts = [data.get("output", "")]
    for test in data["tests"]:
        if test.get("visibility", data.get("visibility", "visible")) == "visible":
            parts += [test.get("name", ""), test.get("output", ""), json.dumps(test.get("extra_data", {}))]
    return "\n".join(parts)


def test_the_schema_rejects_what_the_specification_does_not_allow():
    good = {"score": 1.0, "tests": [{"name": "a", "score": 1.0, "max_score": 1.0, "status": "passed"}]}
    jsonschema.validate(good, RESULTS_SCHEMA)
    bad = [
        {"tests": [{"name": "a", "max_score": 1.0}]},  # no score anywhere
        {"score": 1.0, "tests": [{"status": "error"}]},  # a status the specification does not have
        {"score": 1.0, "tests": [{"visibility": "before_due_date"}]},
        {"score": 1.0, "tests": [{"output_format": "latex"}]},
        {"score": 1.0, "stdout_visibility": "always"},
        {"score": 1.0, "tests": [{"points": 1.0}]},  # not a field of a test
        {"score": "1"},
    ]
    for data in bad:
        with pytest.raises(jsonschema.ValidationError):
            jsonschema.validate(data, RESULTS_SCHEMA)


# ---------------------------------------------------------------------------------------------- pure parts


def test_parse_problems():
    assert parse_problems(None) is None
    assert parse_problems(["6,7", "10-12"]) == [6, 7, 10, 11, 12]
    assert parse_problems("6-8,7") == [6, 7, 8]
    assert parse_problems(["p6", "problem9"]) == [6, 9]
    for text in ("6-", "x", "8-6"):
        with pytest.raises(ValueError):
            parse_problems(text)


def _synthetic_reports() -> list[ProblemReport]:
    results = (
        CheckResult("p99.shape", 99, "returns a 3 x 3 matrix", Status.PASSED, 1, 1, seed=5),
        CheckResult("p99.values", 99, "equals the rotation", Status.FAILED, 0, 2, "got A_CI\nexpected A_IC",
                    hint="transpose it", diagnosis="transpose", seed=5),
        CheckResult("p99.choice", 99, "(a) the chosen matrix", Status.FAILED, 0, 1, "the key is option 4",
                    diagnosis="wrong_choice"),
        CheckResult("p99.deep", 99, "the deep property", Status.PASSED, 3, 3, "the hidden detail",
                    visibility="hidden"),
        CheckResult("p99.broken", 99, "a check the grader could not run", Status.GRADER_ERROR, 0, 1,
                    "internal grader error (not your fault): KeyError"),
    )
    manual = (ManualItem(99, "why", "Why is it a rotation?", "because", "THE MODEL ANSWER", 2.0),)
    return [ProblemReport(99, "Synthetic", results, manual, sandbox="bubblewrap", seed=5)]


def test_results_show_the_student_view_and_withhold_secret_and_hidden_checks():
    data = validate(results_json(_synthetic_reports(), withheld_ids={"p99.choice"}, seed=5, execution_time=2.4))
    tests = {t["extra_data"].get("check_id", t["extra_data"].get("free_text")): t for t in data["tests"]}
    assert data["score"] == 4.0 and data["extra_data"]["max_score"] == 8.0
    assert data["extra_data"]["manual_points"] == 2.0 and data["execution_time"] == 2
    assert tests["p99.values"]["visibility"] == "visible" and tests["p99.values"]["status"] == "failed"
    assert "got A_CI" in tests["p99.values"]["output"] and "hint: transpose it" in tests["p99.values"]["output"]
    assert "likely mistake: transpose" in tests["p99.values"]["output"]
    # the secret and the hidden check are graded and withheld until the grades are published
    assert tests["p99.choice"]["visibility"] == WITHHELD == tests["p99.deep"]["visibility"]
    assert tests["p99.choice"]["status"] == "failed" and tests["p99.deep"]["score"] == 3.0
    seen = visible_text(data)
    assert "the key is option 4" not in seen and "the hidden detail" not in seen
    assert "the deep property" not in seen  # a hidden check: its count and points only
    assert "1 hidden check worth 3 points" in data["output"]
    assert "(a) the chosen matrix (1 point)" in data["output"]  # a secret check is named, not graded in view
    # the points a student sees now are those of the public checks only
    assert "Problem 99 (Synthetic): 1 of the 4 points of the checks shown now." in data["output"]
    # the grader's fault is said to be the grader's, in the test and at the top
    assert tests["p99.broken"]["output"].startswith("Not graded: a fault of the grader, not of your work.")
    assert "could not be graded because of a fault of the grader, not of your work: p99.broken" in data["output"]
    assert data["extra_data"]["grader_errors"] == ["p99.broken"]
    # the free-text answer: informational (no score), the student's answer, never the model answer
    assert "score" not in tests["why"] and "status" not in tests["why"]
    assert "because" in tests["why"]["output"] and "THE MODEL ANSWER" not in json.dumps(data)


def test_fault_results_say_plainly_that_the_grader_failed():
    data = validate(fault_results("the sandbox cannot start: no bwrap"))
    assert data["extra_data"]["grader_fault"] is True and data["score"] == 0.0
    first = data["output"].splitlines()[0]
    assert "fault of the grader, not of your work" in first and "not a verdict" in first
    assert "the sandbox cannot start: no bwrap" in data["output"]
    assert [t["visibility"] for t in data["tests"]] == ["visible"]


# ---------------------------------------------------------------------------------------------- the zip

PROBLEMS = [6, 10, 12]


@pytest.fixture(scope="module")
def autograder(tmp_path_factory):
    return build_autograder(tmp_path_factory.mktemp("gradescope") / "autograder.zip", PROBLEMS)


def test_the_zip_holds_what_gradescope_needs_and_nothing_it_forbids(autograder):
    with zipfile.ZipFile(autograder.zip) as archive:
        infos = {info.filename: info for info in archive.infolist()}
        data = {name: archive.read(name) for name in infos}
    # the two files the specification requires, at the root (the files zipped, not a folder holding them)
    assert {SETUP, RUN} <= set(infos)
    assert set(infos) == {SETUP, RUN, CONFIG, FAULT, autograder.wheel}
    for name, info in infos.items():
        assert "/" not in name and "\\" not in name and not info.is_dir(), name
        assert not name.startswith(("results", "submission", ".")), name  # Gradescope's own folders
    for script in (SETUP, RUN):
        mode = infos[script].external_attr >> 16
        assert stat.S_ISREG(mode) and mode & 0o111 == 0o111, f"{script} is not executable ({oct(mode)})"
        text = data[script].decode()
        assert text.startswith("#!/usr/bin/env bash\n") and "\r" not in text
        done = subprocess.run(["bash", "-n"], input=text, capture_output=True, text=True)
        assert done.returncode == 0, f"{script}: {done.stderr}"
    setup = data[SETUP].decode()
    assert "apt-get install -y bubblewrap" in setup and 'pip install -q "$WHEEL"' in setup
    assert f"/{autograder.wheel}" in setup and "chmod -R go-rwx" in setup
    run = data[RUN].decode()
    assert "/results/results.json" in run and f"$SOURCE/{FAULT}" in run and "-I -m grader.gradescope run" in run
    config = json.loads(data[CONFIG])
    assert config["problems"] == PROBLEMS and config["withheld"] == WITHHELD
    validate(json.loads(data[FAULT]))
    # the wheel: the whole project with the reference, and no answer key (it would turn the grader into the kit)
    with zipfile.ZipFile(autograder.zip) as archive, archive.open(autograder.wheel) as handle:
        wheel = zipfile.ZipFile(handle)
        names = wheel.namelist()
        tops = {name.split("/")[0] for name in names if not name.split("/")[0].endswith(".dist-info")}
        assert tops == set(WHEEL_PACKAGES)
        for path in (ROOT / "reference").glob("*.py"):
            assert wheel.read(f"reference/{path.name}") == path.read_bytes()
        assert wheel.read("reference/answers.toml") == (ROOT / "reference" / "answers.toml").read_bytes()
        assert {f"checks/problem_{n:02d}.py" for n in PROBLEMS} <= set(names)
        assert not [n for n in names if "__pycache__" in n or n.endswith((".pyc", ".gz"))]
        assert "grader/report/templates/gradescope/setup.sh.j2" in names


def test_grade_gradescope_command(tmp_path, capsys, monkeypatch):
    from grader.cli import EXIT_OK, EXIT_USAGE, main

    out = tmp_path / "out" / "autograder.zip"
    assert main(["gradescope", str(out), "--problems", "6", "10-12"]) == EXIT_OK
    printed = capsys.readouterr().out
    assert f"wrote {out} (problems 6, 10, 11, 12;" in printed and "autograder points" in printed
    with zipfile.ZipFile(out) as archive:
        assert json.loads(archive.read(CONFIG))["problems"] == [6, 10, 11, 12]
    assert main(["gradescope", str(tmp_path / "x.zip"), "--problems", "6,98"]) == EXIT_USAGE
    assert "no checks for problem 98" in capsys.readouterr().err
    # the student kit holds no reference: it cannot build the autograder, and says so
    monkeypatch.setattr("grader.oracle.reference_available", lambda: False)
    assert main(["gradescope", str(tmp_path / "y.zip")]) == EXIT_USAGE
    assert "needs the full project" in capsys.readouterr().err
    assert not (tmp_path / "x.zip").exists() and not (tmp_path / "y.zip").exists()


# ---------------------------------------------------------------------------------------------- end to end


def _env(base: Path) -> dict:
    env = outside_env()
    env.update(AUTOGRADER_ROOT=str(base / "autograder"), GRADER_HOME=str(base / "opt"),
               GRADER_CACHE=str(base / "cache"), GRADER_OFFLINE="1", GRADER_PYTHON=sys.executable)
    return env


def _unpack(zip_path: Path, target: Path) -> None:
    """As unzip does: the files with their permissions."""
    with zipfile.ZipFile(zip_path) as archive:
        for info in archive.infolist():
            path = Path(archive.extract(info, target))
            mode = (info.external_attr >> 16) & 0o777
            if mode:
                os.chmod(path, mode)


@pytest.fixture(scope="module")
def installed(autograder):
    """An /autograder-shaped folder (under a /tmp folder every user may enter: the students' code runs under an
    unprivileged uid) with the zip unpacked into source/ and setup.sh run."""
    base = Path(tempfile.mkdtemp(prefix="grader-gradescope-", dir="/tmp"))
    os.chmod(base, 0o755)
    try:
        root = base / "autograder"
        (root / "source").mkdir(parents=True)
        _unpack(autograder.zip, root / "source")
        env = _env(base)
        done = subprocess.run(["bash", str(root / "source" / SETUP)], cwd=root / "source", env=env,
                              capture_output=True, text=True, timeout=900)
        assert done.returncode == 0, done.stdout + done.stderr
        assert "a sandboxed worker starts" in done.stdout, done.stdout
        shutil.copy2(root / "source" / RUN, root / RUN)  # where Gradescope copies it
        yield {"base": base, "root": root, "env": env, "setup": done.stdout}
    finally:
        shutil.rmtree(base, ignore_errors=True)


def _grade(installed, submission: Path | None, env: dict | None = None) -> tuple[int, dict, str]:
    """Put ``submission`` (a folder's files, or one file) into root/submission, run root/run_autograder there."""
    root = installed["root"]
    target = root / "submission"
    shutil.rmtree(target, ignore_errors=True)
    shutil.rmtree(root / "results", ignore_errors=True)
    target.mkdir()
    if submission is not None:
        if submission.is_dir():
            shutil.copytree(submission, target, dirs_exist_ok=True)
        else:
            shutil.copy2(submission, target / submission.name)
    done = subprocess.run([str(root / RUN)], cwd=root, env=env or installed["env"], capture_output=True,
                          text=True, timeout=900)
    results = root / "results" / "results.json"
    assert results.is_file(), done.stdout + done.stderr
    return done.returncode, validate(json.loads(results.read_text())), done.stdout + done.stderr


def _by_check(data: dict) -> dict:
    return {t["extra_data"]["check_id"]: t for t in data["tests"] if "check_id" in t["extra_data"]}


@pytest.mark.slow
def test_setup_installs_the_grader_with_a_private_reference(installed):
    venv = installed["base"] / "opt" / "venv"
    site = next(venv.glob("lib/python3*/site-packages"))
    assert f"grader 0.1.0 at {site}/grader, live reference" in installed["setup"]
    scores = re.search(r"the reference scores (\S+) of (\S+)", installed["setup"])
    assert scores and float(scores[1]) == float(scores[2]) > 0, installed["setup"]
    reference = site / "reference"
    assert (reference / "rotations.py").is_file()
    for path in (reference, reference / "rotations.py", reference / "answers.toml"):
        assert path.stat().st_mode & 0o077 == 0, path  # root alone: the students' uid cannot read it
    assert not (site / "grader" / "answer_key.json.gz").exists()


@pytest.mark.slow
def test_run_autograder_grades_reference_template_and_a_planted_mistake(installed, tmp_path):
    # the reference: full marks, every check passed, a fresh seed each run
    reference = copy_reference(tmp_path / "reference")
    code, first, log = _grade(installed, reference)
    assert code == 0, log
    assert f"{installed['base']}/opt/venv" in log  # graded by the installed wheel, not this checkout
    assert first["score"] == first["extra_data"]["max_score"] > 0
    assert {t["status"] for t in first["tests"] if "status" in t} == {"passed"}
    assert first["extra_data"]["problems"] == PROBLEMS and first["extra_data"]["grader_fault"] is False
    withheld = {c for c, t in _by_check(first).items() if t["visibility"] == WITHHELD}
    assert withheld == {"p10.a", "p10.b"}
    _, second, _ = _grade(installed, reference)
    assert second["extra_data"]["seed"] != first["extra_data"]["seed"] and second["score"] == first["score"]

    # the untouched template: 0, every check says what is missing, nothing is the grader's fault
    code, data, log = _grade(installed, copy_template(tmp_path / "template"))
    assert code == 0, log
    assert data["score"] == 0 and data["extra_data"]["grader_errors"] == []
    checks = _by_check(data)
    assert {t["status"] for t in checks.values()} == {"failed"}
    assert {t["extra_data"]["status"] for t in checks.values()} <= {"not_implemented", "skipped"}
    assert "not implemented" in checks["p06.elementary_shape"]["output"]
    assert all(t["output"].strip() for t in checks.values())

    # a planted mistake in problem 6 and a wrong multiple-choice answer in problem 10, in one zip upload
    order = next(m for m in planted_mistakes(6) if m.name == "p06-cardan-rotation-order")
    choice = next(m for m in planted_mistakes(10) if m.name == "p10-a-orthonormal-option")
    folder = build_planted(order, tmp_path / "planted")
    answers = folder / "answers.toml"
    answers.write_text(answers.read_text().replace(choice.old, choice.new))
    upload = tmp_path / "upload" / "mywork.zip"
    upload.parent.mkdir()
    shutil.make_archive(str(upload.with_suffix("")), "zip", tmp_path, "planted")
    code, data, log = _grade(installed, upload)
    assert code == 0, log
    checks = _by_check(data)
    failed = {c for c, t in checks.items() if t["status"] == "failed"}
    assert failed == {order.check, choice.check}, log
    assert checks[order.check]["visibility"] == "visible"
    assert f"likely mistake: {order.diagnosis}" in checks[order.check]["output"]
    assert order.message in checks[order.check]["output"]
    # the wrong choice is graded (and shown to the instructor) but no student sees why before publication
    assert checks[choice.check]["visibility"] == WITHHELD and choice.message in checks[choice.check]["output"]
    assert choice.message not in visible_text(data)
    assert data["score"] == first["score"] - checks[order.check]["max_score"] - checks[choice.check]["max_score"]


@pytest.mark.slow
def test_a_lookup_table_of_the_kit_fails_on_gradescope(installed, tmp_path):
    """The lookup table of tests/test_kit.py: built from a kit's key of problem 6, it passes the randomized checks
    with that key (the kit's local grading: its recorded inputs) and fails in Gradescope, which draws fresh
    inputs."""
    from grader import grade_problem
    from grader.kit import record_key
    from grader.oracle import KeyOracle

    from .kit_support import KIT_SEED, SEED
    from .test_kit import _lookup_submission

    key, _ = record_key([6], seed=KIT_SEED)
    submission = _lookup_submission(key, tmp_path / "lookup")
    local = grade_problem(6, submission, seed=SEED, oracle=KeyOracle(key))
    assert {r.check_id for r in local.results if r.passed} >= {"p06.elementary_values"}
    code, data, log = _grade(installed, submission)
    assert code == 0, log
    checks = _by_check(data)
    assert checks["p06.elementary_values"]["status"] == "failed"
    assert checks["p06.cardan_values"]["status"] == "failed"
    assert checks["p06.elementary_values"]["extra_data"]["status"] == "failed"
    assert sum(t["score"] for c, t in checks.items() if c.startswith("p06.")) < local.auto_max_score


@pytest.mark.slow
def test_a_broken_installation_is_never_the_students_zero(installed, tmp_path):
    # the grader's environment is gone: run_autograder puts the zip's fault results in place, exit code 3
    env = dict(installed["env"], GRADER_HOME=str(tmp_path / "nowhere"))
    code, data, log = _grade(installed, copy_reference(tmp_path / "reference"), env)
    assert code == 3, log
    assert data["extra_data"]["grader_fault"] is True
    assert "fault of the grader, not of your work" in data["output"] and "the grader wrote no results" in log
    # the grader starts but cannot grade the assigned problems: it says why
    config = installed["root"] / "source" / CONFIG
    saved = config.read_text()
    try:
        config.write_text(json.dumps(dict(json.loads(saved), problems=[6, 98])))
        code, data, log = _grade(installed, copy_reference(tmp_path / "reference2"))
    finally:
        config.write_text(saved)
    assert code == 3, log
    assert data["extra_data"]["grader_fault"] is True and "no checks for problem 98" in data["output"]
    assert data["score"] == 0 and "not a verdict" in data["output"]


@pytest.mark.slow
def test_a_defect_of_the_installed_grader_fails_setup_and_is_never_the_students_fault(installed, tmp_path):
    """A check that crashes in this installation: setup.sh's last step (the reference graded as a submission)
    fails, so the build fails before any student submits; a submission graded anyway is told that the check is
    the grader's fault, and run_autograder exits with code 3."""
    site = next((installed["base"] / "opt" / "venv").glob("lib/python3*/site-packages"))
    module = site / "checks" / "problem_06.py"
    saved = module.read_text()
    head = "def check_elementary_rotation(ctx):\n"
    assert saved.count(head) == 1
    try:
        module.write_text(saved.replace(head, head + "    raise RuntimeError('a defect of this installation')\n"))
        done = subprocess.run([str(site.parents[2] / "bin" / "python"), "-I", "-m", "grader.gradescope", "check",
                               "--config", str(installed["root"] / "source" / CONFIG)],
                              cwd=ROOT, env=installed["env"], capture_output=True, text=True, timeout=900)
        code, data, log = _grade(installed, copy_reference(tmp_path / "reference"))
    finally:
        module.write_text(saved)
    assert done.returncode == 3, done.stdout + done.stderr
    assert "the reference solution does not pass every check in this installation" in done.stderr
    assert "p06.elementary_rotation (grader_error)" in done.stderr
    assert code == 3, log
    broken_id = "p06.elementary_rotation"
    broken = _by_check(data)[broken_id]
    assert broken["status"] == "failed" and broken["score"] == 0 and broken["visibility"] == "visible"
    assert broken["output"].startswith("Not graded: a fault of the grader, not of your work.")
    assert "a defect of this installation" in broken["output"]
    assert "fault of the grader, not of your work: p06.elementary_rotation" in data["output"]
    assert "skipped" not in {t["extra_data"]["status"] for t in _by_check(data).values()}
    # the checks after it in its group did not run either: the grader's fault too, never "an earlier check failed"
    checks = _by_check(data)
    later = {c for c, t in checks.items() if t["extra_data"]["status"] == "grader_error"} - {broken_id}
    assert "p06.elementary_values" in later  # the next stage of the same group
    assert data["extra_data"]["grader_errors"] == [broken_id, *sorted(later, key=list(checks).index)]
    for check in later:
        assert checks[check]["output"].startswith("Not graded: a fault of the grader"), checks[check]["output"]
        assert "the earlier check could not run" in checks[check]["output"]
    assert {t["status"] for c, t in checks.items() if c not in later | {broken_id}} == {"passed"}


def test_results_take_seed_time_and_hand_scores_from_the_reports():
    """What ``grade problem-N --gradescope`` and the batch's export pass: reports alone (the seed, the grading time
    and the withheld checks follow from them), with a free-text answer already scored by hand."""
    first, = _synthetic_reports()
    scored = replace(first, duration=3.6, manual=(replace(first.manual[0], score=1.5),))
    other = ProblemReport(98, "Other", (CheckResult("p98.x", 98, "x", Status.PASSED, 1, 1),), seed=9, duration=1.0)
    data = validate(results_json([scored, other]))
    assert data["execution_time"] == 5 and data["extra_data"]["seed"] is None
    assert data["extra_data"]["seeds"] == {"99": 5, "98": 9}
    assert "(seeds 5 (problem 99), 9 (problem 98))" in data["output"]
    assert data["score"] == 4.0 + 1.5 + 1.0  # the checks' points and the hand-scored answer's
    why = next(t for t in data["tests"] if t["extra_data"].get("free_text") == "why")
    assert (why["score"], why["max_score"], why["status"]) == (1.5, 2.0, "failed")
    assert "1.5 of 2 points" in why["output"]
    assert "Free-text answers scored by hand (1): 1.5 of 2 points." in data["output"]
    # the hidden check is withheld by its own visibility, without any module of problem 99 or 98
    assert next(t for t in data["tests"] if t["extra_data"].get("check_id") == "p99.deep")["visibility"] == WITHHELD
    assert "fresh" not in data["output"]


@pytest.mark.slow
def test_the_source_folder_and_its_wheel_are_readable_by_root_alone(installed, tmp_path):
    """The zip's wheel holds the reference: where Landlock is missing, a student's code running as a plain process
    under an unprivileged uid could read it from the source folder.  setup.sh closes the folder to every user but
    root, and run_autograder closes it again before it grades (an image whose folder was unpacked anew)."""
    source = installed["root"] / "source"
    (wheel,) = source.glob("*.whl")

    def as_student(*argv) -> subprocess.CompletedProcess:
        return subprocess.run(["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", "--", *argv],
                              capture_output=True, timeout=60)

    def assert_closed() -> None:
        read = as_student("head", "-c", "4", str(wheel))
        assert read.returncode != 0 and b"Permission denied" in read.stderr, read
        assert as_student("ls", str(source)).returncode != 0
        assert as_student("true").returncode == 0  # the uid itself runs: only the files are closed to it
        for path in (source, wheel):
            assert path.stat().st_mode & 0o077 == 0, (path, oct(path.stat().st_mode))

    assert_closed()
    subprocess.run(["chmod", "-R", "go+rX", str(source)], check=True)  # unpacked anew, as unzip leaves it
    assert as_student("head", "-c", "4", str(wheel)).stdout == b"PK\x03\x04"  # what is open to the uid, it reads
    code, data, log = _grade(installed, copy_reference(tmp_path / "reference"))
    assert code == 0 and data["score"] == data["extra_data"]["max_score"], log
    assert_closed()


@pytest.mark.slow
def test_a_malformed_upload_is_the_students_zero_not_a_grader_fault(installed, tmp_path):
    """An upload the loader cannot lay over the template (it holds foo.py and foo.py/bar.py; this crashed the
    loader, and run_autograder then said that the installation was broken and exited 3): results.json gives 0
    with the reason, not a fault of the grader, and run_autograder exits 0."""
    upload = tmp_path / "upload" / "mywork.zip"
    upload.parent.mkdir()
    with zipfile.ZipFile(upload, "w") as archive:
        for name in ("rotations.py", "problem_06.py", "__init__.py"):
            archive.write(ROOT / "reference" / name, name)
        archive.writestr("foo.py", "x = 1\n")
        archive.writestr("foo.py/bar.py", "")
    code, data, log = _grade(installed, upload)
    assert code == 0, log
    assert data["extra_data"]["grader_fault"] is False and data["extra_data"]["grader_errors"] == []
    assert data["score"] == 0
    assert "both a file and a folder named foo.py" in data["output"]
    assert data["output"].count("both a file and a folder named foo.py") == 1
