"""``grade prairielearn OUT_DIR``: a PrairieLearn course fragment whose questions this grader grades, and
``grade prairielearn --run JOB_DIR``: the grading of one job, which the fragment's entry point runs.

PrairieLearn's external grader runs a Docker image for each submission with the job folder mounted at ``/grade``:
``student/`` (the uploaded files), ``tests/`` (the question's own ``tests/`` folder), ``data/data.json`` (the
question's data) and ``serverFilesCourse/`` (the course files the question lists); the grader writes
``/grade/results/results.json``.  The fragment holds

* ``questions/mbd-autograder/problem-NN/``: per problem, ``info.json`` (external grading with the image, the entry
  point and a time-out from the problem's own budget), ``question.html`` (an upload of the problem's files and
  the results panel) and ``tests/problem.json``, which names the problem;
* ``serverFilesCourse/mbd-autograder/``: the grader's wheel **with the reference solution** (course files are never
  served to students; the image is public and holds none of it) and the results that say the grader failed,
  for a job in which it cannot even start;
* ``grader-image/``: the Dockerfile of the image (Python, bubblewrap and the dependencies, no project code) and
  its entry point, which installs the wheel from the course files, closes the reference and the job folder to
  every user but root, and runs ``grade prairielearn --run /grade``.

A job is graded as a batch grades a student: one worker with a warm sandboxed process, the problem's own time
bound (``grader.batch.run.default_student_timeout``), a fresh seed each submission.  Whose fault a failure is, is
``grader.faults``' table, as for ``grade``, ``grade batch`` and Gradescope.  What results.json says is
``grader.report.prairielearn_results``.
"""

from __future__ import annotations

import argparse
import json
import math
import random
import sys
import time
import uuid
from dataclasses import dataclass
from pathlib import Path

from . import __version__
from .errors import GraderFault
from .report.environment import environment
from .report.prairielearn_results import fault_results, grader_faults, results_json, unloadable_results
from .results import ProblemReport, Status

__all__ = ["build_fragment", "Fragment", "run", "problem_files", "question_timeout", "main", "JOB_ROOT",
           "QUESTIONS", "SERVER_FILES", "IMAGE_DIR", "PROBLEM_FILE", "ENTRYPOINT", "DEFAULT_IMAGE",
           "START_ALLOWANCE", "EXIT_GRADED", "EXIT_FAULT"]

#: where PrairieLearn mounts the job
JOB_ROOT = "/grade"
#: the fragment's folders: the questions, the course files the jobs receive, the image's recipe
QUESTIONS = "questions/mbd-autograder"
SERVER_FILES = "mbd-autograder"
IMAGE_DIR = "grader-image"
#: the file of a question's tests/ folder that names its problem
PROBLEM_FILE = "problem.json"
FAULT_FILE = "fault_results.json"
#: the entry point inside the image
ENTRYPOINT = "/usr/local/bin/mbd-prairielearn"
DEFAULT_IMAGE = f"mbd-autograder/prairielearn:{__version__}"
#: seconds a job needs besides grading: the container's start, the wheel's installation, the grader's imports and
#: its worker's start (measured at 5-9 s on a loaded two-core machine; twice that, rounded up)
START_ALLOWANCE = 20
#: the namespace of the questions' UUIDs: the same problem has the same UUID in every build
UUID_NAMESPACE = uuid.UUID("3f6c1f5e-4a52-5b8e-9a55-6d8c0e2b7a10")
#: run's exit codes (PrairieLearn reads results.json; the code is for the job's log)
EXIT_GRADED, EXIT_FAULT = 0, 3


# ---------------------------------------------------------------------------------------------- the fragment


def _package_dir(name: str) -> Path:
    import importlib.util

    spec = importlib.util.find_spec(name)
    if spec is None or spec.origin is None:
        raise GraderFault(f"the package {name} is not installed")
    return Path(spec.origin).parent


def problem_files(number: int) -> list[str]:
    """The files a student uploads for ``number``: its own module first, then the template's modules holding code
    the student writes that its checks reach (``rotations.py`` for problem 7, which builds on R1, R2, R3), and
    ``answers.toml`` when the problem has answers there.  Reached: the problem's own stubs, the modules its
    probes load (``module(pkg, "rotations")``, also through the probes of another problem
    that its checks import), and what those import in the reference."""
    import tomllib

    from .loader import template_dir, template_index
    from .sources import named_modules, parsed, project_imports, relative_imports

    template, reference, probes, checks = template_dir(), *map(_package_dir, ("reference", "probes", "checks"))
    written = {module for stubs in template_index()[1].values() for module, _ in stubs}
    own = f"problem_{number:02d}"
    reached = {own} | {module for module, _ in template_index()[1].get(number, ())}
    check_tree = parsed(checks / f"{own}.py")
    imported = {name.split(".")[1] for name in project_imports(check_tree, "checks")
                if name.startswith("probes.") and len(name.split(".")) == 2}
    probe_modules = {own} | {name for name in imported if (probes / f"{name}.py").is_file()}
    for name in sorted(probe_modules):
        if (probes / f"{name}.py").is_file():
            reached |= named_modules(parsed(probes / f"{name}.py"))
    queue, seen = sorted(reached), set()
    while queue:
        name = queue.pop()
        if name in seen or not (reference / f"{name}.py").is_file():
            continue
        seen.add(name)
        queue += sorted(relative_imports(parsed(reference / f"{name}.py")))
    files = [f"{own}.py"] if (template / f"{own}.py").is_file() else []
    files += sorted(f"{name}.py" for name in seen & written if name != own)
    answers = tomllib.loads((template / "answers.toml").read_text(encoding="utf-8"))
    if own in answers:
        files.append("answers.toml")
    return files


def question_timeout(number: int) -> int:
    """PrairieLearn's time-out of a problem's job, in whole seconds: the problem's own bound (the import time-out
    plus twice the call time-out per check, as a batch bounds a student) and the job's start-up."""
    from .batch.run import default_student_timeout
    from .sandbox import Limits

    return int(math.ceil(default_student_timeout(Limits(), [number]))) + START_ALLOWANCE


@dataclass(frozen=True)
class Fragment:
    out: Path
    problems: tuple[int, ...]
    image: str
    wheel: str
    questions: tuple[str, ...]  # the questions' folders, relative to ``out``
    points: float  # the automatically graded points of the problems


def _write(path: Path, text: str | bytes, mode: int = 0o644) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    if isinstance(text, bytes):
        tmp.write_bytes(text)
    else:
        tmp.write_text(text, encoding="utf-8")
    tmp.chmod(mode)
    tmp.replace(path)


def _info(number: int, title: str, image: str) -> dict:
    return {
        "uuid": str(uuid.uuid5(UUID_NAMESPACE, f"mbd-autograder problem {number}")),
        "title": f"Problem {number}: {title}",
        "topic": "Multibody dynamics",
        "tags": ["mbd-autograder", f"problem-{number}"],
        "type": "v3",
        "gradingMethod": "External",
        "singleVariant": True,
        "externalGradingOptions": {
            "enabled": True,
            "image": image,
            "entrypoint": ENTRYPOINT,
            "serverFilesCourse": [f"{SERVER_FILES}/"],
            "timeout": question_timeout(number),
        },
    }


def build_fragment(out: str | Path, problems: list[int] | None = None, *, image: str = DEFAULT_IMAGE) -> Fragment:
    """Write the PrairieLearn course fragment for ``problems`` (default: every problem with checks) into ``out``."""
    import tempfile

    from .gradescope import WHEEL_NAME, WHEEL_PACKAGES, _points
    from .kit import KitError, kit_files, runtime_dependencies, write_wheel
    from .oracle import KEY_FILE, reference_available
    from .problems import problem_module, require_problems

    if not reference_available():
        raise KitError("grade prairielearn needs the full project: the reference solution is not installed here "
                       "(the student kit cannot build the questions' grader)")
    numbers = require_problems(problems)
    files = kit_files(WHEEL_PACKAGES)
    if f"grader/{KEY_FILE}" in files or not any(name.startswith("reference/") for name in files):
        raise GraderFault("the grader's wheel must hold the reference and no answer key")
    out = Path(out)
    server = out / "serverFilesCourse" / SERVER_FILES
    with tempfile.TemporaryDirectory(prefix="grader-prairielearn-") as tmp:
        wheel = write_wheel(tmp, files, runtime_dependencies(), name=WHEEL_NAME, packages=WHEEL_PACKAGES,
                            summary="The multibody-dynamics course's grader with its reference solution "
                                    "(instructors only: PrairieLearn's course files)")
        for old in server.glob(f"{WHEEL_NAME}-*.whl"):  # one wheel: the entry point installs the one it finds
            old.unlink()
        _write(server / wheel.name, wheel.read_bytes())
        wheel_name = wheel.name
    fault = fault_results("the grader did not start in the grading container (its installation is broken; the "
                          "job's log says why)")
    _write(server / FAULT_FILE, json.dumps(fault, indent=2) + "\n")
    html, text = environment("html"), environment("text")
    values = {"version": __version__, "server_files": SERVER_FILES, "wheel_name": WHEEL_NAME,
              "fault_file": FAULT_FILE, "entrypoint": ENTRYPOINT, "job_root": JOB_ROOT,
              "dependencies": runtime_dependencies(), "image": image}
    _write(out / IMAGE_DIR / "Dockerfile", text.get_template("prairielearn/Dockerfile.j2").render(**values))
    _write(out / IMAGE_DIR / Path(ENTRYPOINT).name,
           text.get_template("prairielearn/entrypoint.sh.j2").render(**values), 0o755)
    questions = []
    for number in numbers:
        folder = out / QUESTIONS / f"problem-{number:02d}"
        title = problem_module(number).TITLE
        _write(folder / "info.json", json.dumps(_info(number, title, image), indent=2) + "\n")
        _write(folder / "question.html", html.get_template("prairielearn/question.html.j2").render(
            number=number, title=title, files=problem_files(number)))
        _write(folder / "tests" / PROBLEM_FILE,
               json.dumps({"problem": number, "grader_version": __version__}, indent=2) + "\n")
        questions.append(folder.relative_to(out).as_posix())
    points, _ = _points(numbers)
    return Fragment(out, tuple(numbers), image, wheel_name, tuple(questions), points)


# ---------------------------------------------------------------------------------------------- the job


def _problem_of(tests: Path) -> int:
    path = tests / PROBLEM_FILE
    try:
        number = json.loads(path.read_text(encoding="utf-8"))["problem"]
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise GraderFault(f"the question's tests/{PROBLEM_FILE} cannot be read ({exc}): the question was not "
                          "built by `grade prairielearn`") from exc
    if isinstance(number, bool) or not isinstance(number, int):
        raise GraderFault(f"the question's tests/{PROBLEM_FILE} names no problem ({number!r})")
    return number


def _grade(student: Path, number: int, seed: int) -> list[ProblemReport]:
    """Grade ``student`` on ``number`` as a batch grades one student: a worker with a warm sandboxed process,
    bounded by the problem's own time bound; a student stopped there is graded as stopped (their fault)."""
    import multiprocessing

    from .batch.discover import Entry, submission_hash
    from .batch.pool import Slot, Task, stopped_reports
    from .batch.run import default_student_timeout
    from .sandbox import Limits, sandbox_mode

    limits = Limits()
    budget = default_student_timeout(limits, [number])
    task = Task(Entry("student", student, submission_hash(student), seed=seed), (number,))
    slot = Slot(multiprocessing.get_context("spawn"), 1, limits, sandbox_mode(), (number,))
    try:
        kind, payload, seconds = slot.outcome(task, budget)
    except RuntimeError as exc:  # the worker cannot start: the installation's fault
        raise GraderFault(str(exc)) from exc
    finally:
        slot.stop()
    if kind == "ok":
        return payload
    if kind == "timeout":
        message = (f"grading this submission took longer than its limit of {budget:g} s and was stopped: look "
                   "for very slow or endless loops.")
        return stopped_reports(task, Status.TIMEOUT, message, seconds)
    last = str(payload).strip().splitlines()[-1] if payload and str(payload).strip() else ""
    raise GraderFault(f"the grading process failed ({kind}): {last}")


def _write_json(path: Path, data: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    tmp.replace(path)


def run(job: str | Path = JOB_ROOT, *, seed: int | None = None) -> int:
    """Grade the job folder ``job`` (``student/``, ``tests/``, ``data/``) and write ``job/results/results.json``;
    returns the exit code (``EXIT_GRADED``, or ``EXIT_FAULT`` when the grader failed).  Whose fault a failure is,
    is ``grader.faults``' table: the student's is graded (a submission that cannot be loaded is not gradable, with
    the reason), the grader's is never a grade (``fault_results``)."""
    from .faults import fault_of, faults_in, grader_fault_reason
    from .gradescope import check_installation, find_student
    from .terminal import say

    job = Path(job)
    results_path = job / "results" / "results.json"
    seed = random.SystemRandom().randrange(2**31) if seed is None else int(seed)
    start = time.monotonic()
    try:
        number = _problem_of(job / "tests")
        print(check_installation([number]))
        student = find_student(job / "student")
        say(f"grading {student} on problem {number} with seed {seed}", sys.stdout)
        reports = _grade(student, number, seed)
        data = results_json(reports, seed=seed)
    except Exception as exc:  # noqa: BLE001 - whose fault it is, is the table's: the unforeseen is the grader's
        fault = fault_of(exc)
        if fault.student:  # the submission cannot be loaded
            _write_json(results_path, unloadable_results(str(exc)))
            return fault.autograder_exit
        reason = grader_fault_reason(exc, sys.stdout)
        _write_json(results_path, fault_results(reason))
        return fault.autograder_exit
    _write_json(results_path, data)
    for report in reports:
        say(f"problem {report.problem}: {report.score:g} / {report.auto_max_score:g} ({report.sandbox}) in "
            f"{time.monotonic() - start:.1f} s" + (f"; not loaded: {report.load_error}" if report.load_error else ""),
            sys.stdout)
    faults = grader_faults(reports)
    if faults:
        print(f"grader errors (the submission was not graded and costs the student nothing): {faults}")
    return max((fault.autograder_exit for fault in faults_in(reports)), default=EXIT_GRADED)


def main(argv: list[str] | None = None) -> int:
    """``python -m grader.prairielearn [JOB_DIR]``: grade a job (what ``grade prairielearn --run`` does)."""
    parser = argparse.ArgumentParser(prog="python -m grader.prairielearn")
    parser.add_argument("job", nargs="?", default=JOB_ROOT)
    parser.add_argument("--seed", type=int, default=None)
    args = parser.parse_args(argv)
    return run(args.job, seed=args.seed)


if __name__ == "__main__":
    sys.exit(main())
