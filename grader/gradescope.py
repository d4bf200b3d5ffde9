"""``grade gradescope OUT.zip``: the autograder that Gradescope runs.

The zip follows Gradescope's autograder specification: ``setup.sh`` and ``run_autograder`` at its root, the rest
unpacked next to them in ``/autograder/source``.  It holds

* ``setup.sh``: run once, as root, while Gradescope builds the image: installs bubblewrap, a Python recent enough,
  and a wheel of this project *with* the reference solution (the grader runs on the instructor's side) into a
  virtual environment of its own, makes the reference readable by root alone, and checks the installation;
* ``run_autograder``: run for every submission: grades ``/autograder/submission`` (a folder, or the one ``.zip``
  or ``.ipynb`` a student uploaded, as ``grade batch`` takes a student) on the assigned problems with a fresh
  seed and every check, and writes ``/autograder/results/results.json``;
* the wheel, ``autograder.json`` (the assigned problems) and ``fault_results.json`` (what ``run_autograder`` puts
  in place when the grader cannot even start).

What results.json says, and what a student sees of it, is ``grader.report.gradescope_results``.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import sys
import time
import zipfile
from dataclasses import dataclass
from pathlib import Path

from . import __version__
from .errors import GraderFault
from .problems import NoChecks, require_problems, withheld_check_ids
from .report.environment import environment
from .report.gradescope_results import WITHHELD, fault_results, results_json
from .results import Status
from .terminal import say

__all__ = ["build_autograder", "Autograder", "find_student", "check_installation", "run", "main", "WHEEL_NAME",
           "WHEEL_PACKAGES", "SETUP", "RUN", "CONFIG", "FAULT", "GRADER_HOME", "PYTHON_MIN", "EXIT_GRADED",
           "EXIT_FAULT"]

#: the distribution of the wheel in the zip: the whole project, reference included
WHEEL_NAME = "mbd_autograder"
WHEEL_PACKAGES = ("grader", "checks", "probes", "reference", "student_template")
#: the files of the zip
SETUP, RUN, CONFIG, FAULT = "setup.sh", "run_autograder", "autograder.json", "fault_results.json"
#: where setup.sh puts the grader's virtual environment (outside /autograder, readable by every user)
GRADER_HOME = "/opt/mbd-autograder"
PYTHON_MIN = (3, 11)
#: run_autograder's exit codes (Gradescope reads results.json; the code is for the log)
EXIT_GRADED, EXIT_FAULT = 0, 3


# ---------------------------------------------------------------------------------------------- the run


def find_student(folder: Path) -> Path:
    """What a student submitted: the one ``.zip`` or ``.ipynb`` they uploaded, else the folder itself (the loader
    takes a folder, one folder inside it, or notebooks in it)."""
    from .batch.discover import SUBMISSION_SUFFIXES

    entries = [p for p in folder.iterdir() if not p.name.startswith(".") and p.name != "__MACOSX"] \
        if folder.is_dir() else []
    if len(entries) == 1 and entries[0].is_file() and not entries[0].is_symlink() \
            and entries[0].suffix in SUBMISSION_SUFFIXES:
        return entries[0]
    return folder


def check_installation(problems: list[int], *, sandbox: bool = False, reference: bool = False) -> str:
    """Raise ``GraderFault`` unless this installation can grade ``problems``: the reference is importable, no
    answer key replaces it (that is the student kit), every problem has checks, (``sandbox``) a sandboxed worker
    starts and (``reference``) the reference solution, graded as a submission, passes every check (which also
    fills the grader's cache with the values of the sheet's cases).  Returns a line that says what was checked."""
    from .oracle import current, reference_available

    if not reference_available():
        raise GraderFault("the reference solution is not installed with the grader (the autograder's setup.sh "
                          "installs the wheel of the full project)")
    if current().mode != "live":
        raise GraderFault("an answer key is installed: this is the student kit, which cannot grade submissions "
                          "(the autograder needs the full project)")
    try:
        require_problems(problems)
    except NoChecks as exc:
        raise GraderFault(f"the assigned problems cannot be graded: {exc}") from exc
    line = f"grader {__version__} at {Path(__file__).parent}, live reference, problems {problems}"
    if sandbox:
        from .sandbox import canary, sandbox_mode

        mode = sandbox_mode()
        canary(mode=mode)
        line += f"; a sandboxed worker starts ({mode.note})"
    if reference:
        import importlib.util

        from .runner import grade_submission

        folder = Path(importlib.util.find_spec("reference").origin).parent
        reports = grade_submission(folder, problems)
        failures = [f"{r.check_id} ({r.status.value}): {r.message.splitlines()[0] if r.message else ''}"
                    for report in reports for r in report.results if r.status is not Status.PASSED]
        if failures:
            raise GraderFault("the reference solution does not pass every check in this installation:\n  "
                              + "\n  ".join(failures))
        line += (f"; the reference scores {sum(r.score for r in reports):g} of "
                 f"{sum(r.auto_max_score for r in reports):g}")
    return line


def _write_json(path: Path, data: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    tmp.replace(path)


def run(root: Path, problems: list[int], *, seed: int | None = None) -> int:
    """Grade ``root/submission`` on ``problems`` and write ``root/results/results.json``; returns the exit code
    (``EXIT_GRADED``, or ``EXIT_FAULT`` when the grader failed on any check or could not grade).  Whose fault a
    failure is, is ``grader.faults``' table: the student's is graded (a submission that cannot be loaded scores 0
    with the reason), the grader's is said to be the grader's (``fault_results``, or the check's own test)."""
    from .faults import fault_of, faults_in, grader_fault_reason
    from .runner import grade_submission, unloadable_reports

    start = time.monotonic()
    results_path = root / "results" / "results.json"
    seed = random.SystemRandom().randrange(2**31) if seed is None else int(seed)
    try:
        print(check_installation(problems))
        student = find_student(root / "submission")
        say(f"grading {student} with seed {seed}", sys.stdout)
        reports = grade_submission(student, problems, seed=seed)
    except Exception as exc:  # noqa: BLE001 - whose fault it is, is the table's: the unforeseen is the grader's
        fault = fault_of(exc)
        if not fault.student:
            reason = grader_fault_reason(exc, sys.stdout)
            _write_json(results_path, fault_results(reason, execution_time=time.monotonic() - start))
            return fault.autograder_exit
        reports = unloadable_reports(root / "submission", problems, str(exc), seed=seed)
    data = results_json(reports, withheld_ids=withheld_check_ids(problems), seed=seed,
                        execution_time=time.monotonic() - start, fresh_inputs=True)
    _write_json(results_path, data)
    for report in reports:
        say(f"problem {report.problem}: {report.score:g} / {report.auto_max_score:g} ({report.sandbox})"
            + (f"; not loaded: {report.load_error}" if report.load_error else ""), sys.stdout)
    errors = data["extra_data"]["grader_errors"]
    if errors:
        print(f"grader errors (the student was told, and gets 0 for them until a regrade): {errors}")
    return max((fault.autograder_exit for fault in faults_in(reports)), default=EXIT_GRADED)


# ---------------------------------------------------------------------------------------------- the zip


@dataclass(frozen=True)
class Autograder:
    zip: Path
    problems: tuple[int, ...]
    wheel: str
    points: float  # the automatically graded points: the autograder's points in Gradescope
    manual_points: float  # free-text answers, scored by hand
    files: tuple[str, ...]


def _points(problems: list[int]) -> tuple[float, float]:
    from .listing import problem_list

    infos = {p["number"]: p for p in problem_list()}
    return (sum(infos[n]["points"] for n in problems if n in infos),
            sum(infos[n]["manual_points"] or 0 for n in problems if n in infos))


def _zip_entry(name: str, mode: int) -> zipfile.ZipInfo:
    info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
    info.external_attr = (0o100000 | mode) << 16  # a regular file with these permissions (run_autograder: 0755)
    info.create_system = 3  # Unix, so that unzip applies the permissions
    info.compress_type = zipfile.ZIP_DEFLATED
    return info


def build_autograder(out: str | Path, problems: list[int] | None = None) -> Autograder:
    """Write Gradescope's autograder zip for ``problems`` (default: every problem with checks) to ``out``."""
    import tempfile

    from .kit import KitError, kit_files, runtime_dependencies, write_wheel
    from .oracle import KEY_FILE, reference_available

    if not reference_available():
        raise KitError("grade gradescope needs the full project, the instructor's installation with the reference "
                       "solution: the reference is not installed here (the student kit cannot build the "
                       "autograder). Run it where the course's project is installed (`pip install -e .` in its "
                       "folder).")
    numbers = require_problems(problems)
    files = kit_files(WHEEL_PACKAGES)
    if f"grader/{KEY_FILE}" in files or not any(name.startswith("reference/") for name in files):
        raise GraderFault("the autograder's wheel must hold the reference and no answer key")
    with tempfile.TemporaryDirectory(prefix="grader-gradescope-") as tmp:
        wheel = write_wheel(tmp, files, runtime_dependencies(), name=WHEEL_NAME, packages=WHEEL_PACKAGES,
                            summary="The multibody-dynamics course's grader with its reference solution "
                                    "(instructors only: Gradescope's autograder)")
        wheel_bytes, wheel_name = wheel.read_bytes(), wheel.name
    values = {"wheel": wheel_name, "version": __version__, "problems": ", ".join(map(str, numbers)),
              "config": CONFIG, "fault": FAULT, "grader_home": GRADER_HOME,
              "python_min": ".".join(map(str, PYTHON_MIN)), "python_min_tuple": ", ".join(map(str, PYTHON_MIN))}
    env = environment("text")
    config = {"problems": numbers, "grader_version": __version__, "wheel": wheel_name, "withheld": WITHHELD}
    fault = fault_results("the grader did not start in the autograder (its installation is broken; the "
                          "autograder's log says why)")
    contents = [
        (SETUP, env.get_template("gradescope/setup.sh.j2").render(**values).encode(), 0o755),
        (RUN, env.get_template("gradescope/run_autograder.j2").render(**values).encode(), 0o755),
        (wheel_name, wheel_bytes, 0o644),
        (CONFIG, (json.dumps(config, indent=2) + "\n").encode(), 0o644),
        (FAULT, (json.dumps(fault, indent=2) + "\n").encode(), 0o644),
    ]
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp_zip = out.with_name(out.name + ".tmp")
    with zipfile.ZipFile(tmp_zip, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for name, data, mode in contents:
            archive.writestr(_zip_entry(name, mode), data)
    tmp_zip.replace(out)
    points, manual = _points(numbers)
    return Autograder(out, tuple(numbers), wheel_name, points, manual, tuple(name for name, _, _ in contents))


# ---------------------------------------------------------------------------------------------- entry point


def _config(path: str) -> list[int]:
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"))
        return [int(n) for n in data["problems"]]
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise GraderFault(f"the autograder's configuration {path} cannot be read: {exc}") from exc


def main(argv: list[str] | None = None) -> int:
    """``python -m grader.gradescope run|check``: what run_autograder and setup.sh call."""
    parser = argparse.ArgumentParser(prog="python -m grader.gradescope")
    sub = parser.add_subparsers(dest="command", required=True)
    p_run = sub.add_parser("run", help="grade ROOT/submission and write ROOT/results/results.json")
    p_run.add_argument("--root", default=os.environ.get("AUTOGRADER_ROOT", "/autograder"))
    p_run.add_argument("--config", required=True)
    p_run.add_argument("--seed", type=int, default=None, help="reproduce a run (default: a fresh seed)")
    p_check = sub.add_parser("check", help="check the installation (setup.sh's last step)")
    p_check.add_argument("--config", required=True)
    args = parser.parse_args(argv)
    if args.command == "check":
        try:
            print(check_installation(_config(args.config), sandbox=True, reference=True))
        except GraderFault as exc:
            print(f"the autograder's installation is broken: {exc}", file=sys.stderr)
            return EXIT_FAULT
        return EXIT_GRADED
    root = Path(args.root)
    try:
        problems = _config(args.config)
    except GraderFault as exc:
        print(f"grader fault: {exc}")
        _write_json(root / "results" / "results.json", fault_results(str(exc)))
        return EXIT_FAULT
    return run(root, problems, seed=args.seed)


if __name__ == "__main__":
    sys.exit(main())
