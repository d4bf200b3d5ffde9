"""The student kit (issue 9): built from the tree, its wheel holds no reference code, no solution line and no value
of a secret or hidden check; installed into a fresh virtual environment, ``grade problem-6`` grades a student
folder from its answer key; and a lookup-table submission built from the key passes in the kit but fails live,
where the inputs are fresh."""

from __future__ import annotations

import base64
import csv
import dataclasses
import gzip
import hashlib
import io
import json
import subprocess
import tomllib
import zipfile
from pathlib import Path

import numpy as np
import pytest

from grader import grade_problem
from grader.kit import KIT_DEPENDENCIES, KIT_NAME, build_kit, kit_dependencies, record_key, runtime_dependencies
from grader.oracle import KEY_FILE, LiveOracle
from grader.results import Status

from .environments import outside_env, public_tmp_dir, venv_on_site
from .kit_support import KIT_SEED, SEED
from .submissions import ROOT, copy_reference

#: a solution line shorter than this is too generic to be specific ("q = np.asarray(q, dtype=float)")
SPECIFIC = 32
@pytest.fixture(scope="session")
def kit(tmp_path_factory, answer_key):
    return build_kit(tmp_path_factory.mktemp("kit"), key=answer_key)


@pytest.fixture(scope="session")
def wheel_files(kit) -> dict[str, bytes]:
    with zipfile.ZipFile(kit.wheel) as wheel:
        return {name: wheel.read(name) for name in wheel.namelist()}


def _texts(files: dict[str, bytes]) -> dict[str, str]:
    """Every file of the wheel as text; the answer key decompressed."""
    texts = {}
    for name, data in files.items():
        if name.endswith(".gz"):
            data = gzip.decompress(data)
        texts[name] = data.decode("utf-8", "replace")
    return texts


def _regions(source: str) -> list[str]:
    """The stripped lines inside SOLUTION regions and REFERENCE ONLY blocks."""
    lines, inside = [], False
    for line in source.splitlines():
        text = line.strip()
        if text.startswith("# BEGIN SOLUTION") or text == "# BEGIN REFERENCE ONLY":
            inside = True
        elif text.startswith("# END SOLUTION") or text == "# END REFERENCE ONLY":
            inside = False
        elif inside and text and not text.startswith("#"):
            lines.append(text)
    return lines


# ---------------------------------------------------------------------------------------------- the wheel


def test_the_wheel_is_a_wheel(kit, wheel_files):
    dist_info = f"{KIT_NAME}-{kit.wheel.name.split('-')[1]}.dist-info"
    metadata = wheel_files[f"{dist_info}/METADATA"].decode()
    assert f"Name: {KIT_NAME}" in metadata
    required = sorted(line.removeprefix("Requires-Dist: ") for line in metadata.splitlines()
                      if line.startswith("Requires-Dist: ") and "extra ==" not in line)
    assert required == sorted(kit_dependencies())
    # what a student's grading needs, not the instructor's cluster
    assert {r.split(">")[0] for r in required} == set(KIT_DEPENDENCIES)
    assert any(r.startswith("dask") for r in runtime_dependencies())  # the instructor's install keeps the cluster
    assert "dask" not in metadata.lower()
    assert "Provides-Extra: jupyter" in metadata and 'Requires-Dist: jupyterlab>=4; extra == "jupyter"' in metadata
    assert "Root-Is-Purelib: true" in wheel_files[f"{dist_info}/WHEEL"].decode()
    assert "grade = grader.cli:main" in wheel_files[f"{dist_info}/entry_points.txt"].decode()
    rows = list(csv.reader(io.StringIO(wheel_files[f"{dist_info}/RECORD"].decode())))
    assert {row[0] for row in rows} == set(wheel_files)
    for name, digest, size in rows:
        if name.endswith("RECORD"):
            continue
        data = wheel_files[name]
        assert digest == "sha256=" + base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
        assert int(size) == len(data)
    assert f"grader/{KEY_FILE}" in wheel_files


def test_no_module_of_the_reference_is_in_the_kit(wheel_files):
    assert not [n for n in wheel_files if n.split("/")[0] == "reference"]
    # a module of the reference that holds solutions (it differs from the template's) is nowhere, under any name
    template = {p.name: p.read_bytes() for p in (ROOT / "student_template").glob("*.py")}
    copies = {hashlib.sha256(p.read_bytes()).hexdigest(): p.name for p in (ROOT / "reference").glob("*.py")
              if p.read_bytes() != template.get(p.name)}
    assert len(copies) > 10 and "tree_mistakes.py" in copies.values()  # reference-only modules count too
    assert not [n for n, data in wheel_files.items() if hashlib.sha256(data).hexdigest() in copies]
    # the only answers.toml is the blank one of the template
    answers = [n for n in wheel_files if n.endswith("answers.toml")]
    assert answers == ["student_template/answers.toml"]
    assert wheel_files[answers[0]] == (ROOT / "student_template" / "answers.toml").read_bytes()


def test_no_solution_line_is_in_the_kit(wheel_files):
    template = "\n".join(p.read_text() for p in (ROOT / "student_template").glob("*.py"))
    lines = {line for path in (ROOT / "reference").glob("*.py") for line in _regions(path.read_text())
             if len(line) >= SPECIFIC and line not in template}
    assert len(lines) > 200  # the search is not empty
    found = {(name, line) for name, text in _texts(wheel_files).items() for line in lines if line in text}
    leaks = sorted(f"{name}: {line}" for name, line in found)
    assert not leaks, "solution lines in the kit:\n" + "\n".join(leaks)


def _reference_answers() -> dict:
    return tomllib.loads((ROOT / "reference" / "answers.toml").read_text())


def _normalized(text: str) -> str:
    return " ".join(text.split())


def _strings(value):
    """Every string inside decoded JSON data."""
    if isinstance(value, str):
        yield value
    elif isinstance(value, dict):
        for item in value.values():
            yield from _strings(item)
    elif isinstance(value, list):
        for item in value:
            yield from _strings(item)


def _found(files: dict[str, bytes], needles: dict[str, str]) -> list[str]:
    texts = {name: _normalized(text) for name, text in _texts(files).items()}
    key = json.loads(gzip.decompress(files[f"grader/{KEY_FILE}"]))
    strings = [_normalized(s) for s in _strings(key)]
    return sorted(label for label, needle in needles.items()
                  if any(_normalized(needle) in t for t in texts.values())
                  or any(_normalized(needle) in s for s in strings))


def test_no_model_answer_is_in_the_kit(wheel_files):
    model = {f"{problem} free_text {key}": text for problem, table in _reference_answers().items()
             for key, text in table.get("free_text", {}).items()}
    assert model
    assert _found(wheel_files, model) == []


PREDICTED_OUTPUTS = {"problem_28 output": ("problem_28", "output"), "problem_36 part1": ("problem_36", "part1"),
                     "problem_36 part2": ("problem_36", "part2")}


def test_no_predicted_output_is_in_the_kit(wheel_files):
    answers = _reference_answers()
    texts = {label: answers[problem][key] for label, (problem, key) in PREDICTED_OUTPUTS.items()}
    assert _found(wheel_files, texts) == []


def test_key_holds_nothing_of_secret_or_hidden_checks(answer_key, deferred_ids):
    from grader.problems import secret_check_ids

    secret = secret_check_ids()
    assert {"p10.a", "p10.b", "p20.part_a", "p20.part_b"} <= secret
    recorded_by = {check for entry in answer_key.calls.values() for check in entry["checks"]}
    assert recorded_by and not recorded_by & deferred_ids
    sites = {site.rpartition("#")[0] for site in (*answer_key.pools, *answer_key.draws)}
    assert sites and not sites & deferred_ids
    # every value a secret check uses (learnt by running them on the reference) is absent from the key
    from grader.context import Context
    from grader.kit import ReferenceChild
    from grader.kit import _reference_answers as reference_answers
    from grader.oracle import RecordingOracle
    from grader.runner import _run_checks
    from grader.problems import problem_module

    shadow = RecordingOracle(KIT_SEED, secret=True)
    for number in (10, 20):
        _run_checks(problem_module(number), Context(number, ReferenceChild(shadow), reference_answers(), None, 1,
                                                    shadow), number)
    used = set(shadow.key.calls)
    assert {k.partition("[")[0] for k in used} >= {"problem_10.key_a", "problem_10.key_b", "problem_20.key_a",
                                                   "problem_20.key_b"}
    assert not used & set(answer_key.calls)


def test_a_public_check_sharing_a_secret_value_is_withheld(monkeypatch):
    """Problem 28's prediction is secret; were its port (which prints the same output) declared public, it would be
    withheld with the prediction: the key holds neither the output nor anything of the port."""
    import checks.problem_28 as p28

    assert p28.check_prediction.check_spec.secret
    spec = p28.check_port.check_spec
    monkeypatch.setattr(p28.check_port, "check_spec", dataclasses.replace(spec, secret=False))
    key, _ = record_key([28], seed=KIT_SEED)
    assert key.withheld == ["p28.port"]
    text = json.dumps(key.to_json())
    assert "Sandwich" not in text and "Rainbow" not in text
    assert not [entry for entry in key.calls.values() if set(entry["checks"]) & {"p28.port", "p28.prediction"}]


def test_a_key_recorded_side_by_side_is_the_key_one_process_records():
    """``grade kit --jobs``: problems recorded in processes of their own and joined in order give, byte for byte, the
    key one process records (here problems 6, 8 and 9, which ask the reference some of the same calls; 8's checks
    are judged on the student's functions of earlier problems)."""
    alone, reports = record_key([6, 8, 9], seed=KIT_SEED)
    side_by_side, parallel_reports = record_key([6, 8, 9], seed=KIT_SEED, jobs=2)
    assert alone.upstream and any(len({check.split(".")[0] for check in entry["checks"]}) > 1
                                  for entry in alone.calls.values())
    assert side_by_side.dumps() == alone.dumps()
    assert [r.problem for r in parallel_reports] == [r.problem for r in reports] == [6, 8, 9]
    assert [[(r.check_id, r.status) for r in report.results] for report in parallel_reports] == [
        [(r.check_id, r.status) for r in report.results] for report in reports]


# ---------------------------------------------------------------------------------------------- installed


def _run(argv, cwd, env, timeout=600):
    return subprocess.run(argv, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)


@pytest.mark.slow
def test_the_kit_installs_and_grades_problem_6(kit, kit_site):
    with public_tmp_dir("grader-kit-") as tmp_path:
        _kit_installed_grades_problem_6(kit, kit_site, tmp_path)


def _kit_installed_grades_problem_6(kit, site, tmp_path):
    """The kit in a fresh virtual environment (of a Python the sandbox's unprivileged uid can read, in a folder it can
    enter) that sees the kit's dependencies installed in ``site``, graded in whatever sandbox this machine has."""
    venv = tmp_path / "venv"
    env = outside_env()
    venv_on_site(venv, site, env)
    python, grade = venv / "bin" / "python", venv / "bin" / "grade"
    done = _run([str(python), "-m", "pip", "install", "-q", str(kit.wheel)], tmp_path, env, timeout=1200)
    assert done.returncode == 0, done.stdout + done.stderr

    # nothing of the reference is importable there
    done = _run([str(python), "-c", "import reference"], tmp_path, env)
    assert done.returncode != 0 and "No module named 'reference'" in done.stderr
    done = _run([str(python), "-c", "from grader.oracle import current; print(current().mode)"], tmp_path, env)
    assert done.stdout.strip() == "kit", done.stderr

    work = tmp_path / "mywork"
    done = _run([str(grade), "init", str(work)], tmp_path, env)
    assert done.returncode == 0, done.stderr
    # the student fills in the rotations (R1, R2, R3 and cardan), with R3 transposed
    source = (ROOT / "reference" / "rotations.py").read_text()
    wrong = source.replace("return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])",
                           "return np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])")
    assert wrong != source
    (work / "rotations.py").write_text(wrong)
    done = _run([str(grade), "problem-6", "--json", "report.json", "--seed", "3"], work, env)
    assert done.returncode == 1, done.stdout + done.stderr
    results = {r["check_id"]: r for r in json.loads((work / "report.json").read_text())["reports"][0]["results"]}
    assert results["p06.elementary_shape"]["status"] == "passed"
    assert results["p06.elementary_values"]["status"] == "failed"
    assert results["p06.elementary_values"]["diagnosis"] == "transpose or angle_sign"
    assert "recorded random inputs" in results["p06.elementary_values"]["message"]
    assert results["p06.frames"]["status"] == "not_implemented"
    assert "grader_error" not in {r["status"] for r in results.values()}

    # corrected, the filled functions pass from the key alone
    (work / "rotations.py").write_text(source)
    (work / "report.json").unlink()
    done = _run([str(grade), "problem-6", "--json", "report.json"], work, env)
    results = {r["check_id"]: r for r in json.loads((work / "report.json").read_text())["reports"][0]["results"]}
    assert {r["status"] for k, r in results.items() if k not in ("p06.frames", "p06.vectors")} == {"passed"}
    assert "Problem 6" in done.stdout

    # the demo needs the full project, and says so
    done = _run([str(grade), "demo"], work, env)
    assert done.returncode == 2 and "needs the full project" in done.stderr
    # problem 10's multiple-choice checks are recorded, not graded, in the kit
    done = _run([str(grade), "problem-10"], work, env)
    assert "graded when you submit" in done.stdout, done.stdout


# ---------------------------------------------------------------------------------------------- lookup tables


def _lookup_submission(key, dest: Path) -> Path:
    """A reference copy whose R1, R2, R3 and cardan return the key's recorded outputs for the recorded inputs
    (and one fixed rotation for any other input)."""
    from probes._codec import decode

    copy_reference(dest)
    table = {}
    for call, entry in key.calls.items():
        probe, _, args = call.partition("[")
        args = decode(json.loads("[" + args))
        if probe == "problem_06.elementary":
            table[(int(args[0]), float(args[1]))] = np.asarray(decode(entry["value"])).tolist()
        elif probe == "problem_06.cardan":
            table[("cardan", *map(float, args))] = np.asarray(decode(entry["value"])).tolist()
        elif probe == "problem_06.cardan_with_factors":  # cardan and its own factors at the same angles
            value = decode(entry["value"])
            table[("cardan", *map(float, args))] = np.asarray(value["cardan"]).tolist()
            for axis, angle in zip((1, 2, 3), args):
                table[(axis, float(angle))] = np.asarray(value[f"R{axis}"]).tolist()
    assert len(table) > 50
    fallback = max((v for k, v in table.items() if k[0] == "cardan"),
                   key=lambda v: float(np.abs(np.asarray(v) - np.eye(3)).max()))  # a rotation that rotates
    lines = ["", "", "# A lookup table of the answer key: recorded inputs -> recorded outputs.",
             f"_TABLE = {table!r}", f"_FALLBACK = {fallback!r}", "",
             "def _look(*args):", "    return np.array(_TABLE.get(args, _FALLBACK))", ""]
    for axis in (1, 2, 3):
        lines += [f"def R{axis}(angle):", f"    return _look({axis}, float(angle))", ""]
    lines += ["def cardan(alpha, beta, gamma):",
              "    return _look('cardan', float(alpha), float(beta), float(gamma))", ""]
    path = dest / "rotations.py"
    path.write_text(path.read_text() + "\n".join(lines))
    return dest


def test_a_lookup_table_of_the_key_passes_in_the_kit_and_fails_live(answer_key, kit_oracle, tmp_path):
    """The key's random inputs (recorded at full precision) let the lookup pass the kit's randomized checks; the
    sheet's fixed case, held at the sheet's digits only, does not even pass locally (its rotation is orthonormal to
    four decimals, not to 1e-6); live, where the inputs are fresh, the randomized checks fail too."""
    submission = _lookup_submission(answer_key, tmp_path / "pkg")
    kit = grade_problem(6, submission, seed=SEED, oracle=kit_oracle)
    assert [r.check_id for r in kit.results if r.status is Status.FAILED] == ["p06.cardan_rotation"]
    assert {r.check_id for r in kit.results if r.passed} >= {"p06.elementary_shape", "p06.elementary_rotation",
                                                            "p06.elementary_values"}
    live = grade_problem(6, submission, seed=SEED, oracle=LiveOracle())
    failed = {r.check_id for r in live.results if r.status is Status.FAILED}
    assert {"p06.elementary_values", "p06.cardan_rotation"} <= failed
    assert not {r.check_id for r in live.results if r.passed} & {"p06.cardan_values", "p06.frames", "p06.vectors"}
    assert live.score < kit.score


def test_deferred_checks_are_rendered_and_do_not_fail_the_exit_code(kit_oracle, tmp_path):
    from grader import grade_submission
    from grader.cli import EXIT_OK, _exit_code
    from grader.report.data import render_json
    from grader.report.html import render_html
    from grader.report.text import render_terminal

    submission = copy_reference(tmp_path / "pkg")
    reports = grade_submission(submission, [10, 20], seed=SEED, oracle=kit_oracle)
    deferred = {r.check_id for report in reports for r in report.results if r.status is Status.DEFERRED}
    assert deferred == {"p10.a", "p10.b", "p20.part_a", "p20.part_b"}
    assert all(r.score == 0 for report in reports for r in report.results if r.status is Status.DEFERRED)
    assert _exit_code(reports) == EXIT_OK
    text = render_terminal(reports)
    assert text.count("graded when you submit]") == 4 and "◇ 2 checks worth 2 points are graded when you submit" in text
    html = render_html(reports)
    assert 'class="deferred"' in html and "graded when you submit" in html
    statuses = {r["check_id"]: r["status"] for report in json.loads(render_json(reports, show_hidden=False))["reports"]
                for r in report["results"]}
    assert {statuses[c] for c in deferred} == {"deferred"}
