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
``grader.faults``' table, as for ``grade``, ``grade batch`` and Gradescope.  What results.json says
(``results_json``):

* a graded submission: ``gradable: true``, ``score`` the fraction of the problem's points, one test per public
  check (its points, message, likely mistake, figures), the secret and hidden checks in one test that shows their
  points but not their messages (PrairieLearn shows every result at once: it has no "after publication");
* a submission that cannot be loaded: ``gradable: false`` with the reason in ``format_errors`` (the student's
  fault, which costs no attempt);
* a fault of the grader (a broken installation, a check the grader could not run): ``gradable: false`` too, so
  that it costs the student nothing, said plainly to be the grader's fault; the job exits with code 3;
* without bubblewrap in the container, the students' code runs as a plain process (an unprivileged uid, resource
  limits) and the message says so.

results.json stays under PrairieLearn's 1 MB: figures are drawn smaller, then left out, and long texts cut, until
it fits.
"""

from __future__ import annotations

import argparse
import base64
import io
import json
import math
import random
import sys
import time
import traceback
import uuid
from dataclasses import dataclass
from pathlib import Path

from . import __version__
from .errors import GraderFault
from .results import CheckResult, Figure, ProblemReport, Status

__all__ = ["build_fragment", "Fragment", "results_json", "fault_results", "unloadable_results", "run",
           "problem_files", "question_timeout", "grader_faults", "main", "RESULTS_BYTES", "JOB_ROOT",
           "QUESTIONS", "SERVER_FILES", "IMAGE_DIR", "PROBLEM_FILE", "ENTRYPOINT", "DEFAULT_IMAGE",
           "START_ALLOWANCE", "EXIT_GRADED", "EXIT_FAULT"]

#: PrairieLearn's bound on results.json
RESULTS_BYTES = 1_000_000
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
#: the longest text of one test (a student's traceback, a mismatch table); the rest is cut
TEXT_CHARS = 20_000
#: the resolutions a figure is drawn at, best first, until results.json fits
FIGURE_DPI = (90, 60, 40)
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
    ``answers.toml`` when the problem has answers there.  Reached: the problem's own stubs, the modules its check
    module names (``"rotations"``) and its probes load (``module(pkg, "rotations")``, also through the probes of
    another problem that its checks call), and what those import in the reference."""
    import tomllib

    from .loader import template_dir, template_index
    from .sources import named_modules, parsed, relative_imports, strings

    template, reference, probes, checks = template_dir(), *map(_package_dir, ("reference", "probes", "checks"))
    modules = {path.stem for path in template.glob("*.py")}
    written = {module for stubs in template_index()[1].values() for module, _ in stubs}
    own = f"problem_{number:02d}"
    reached = {own} | {module for module, _ in template_index()[1].get(number, ())}
    texts = strings(parsed(checks / f"{own}.py"))
    reached |= texts & modules
    probe_modules = {own} | {text.partition(".")[0] for text in texts
                             if "." in text and text.partition(".")[0].isidentifier()
                             and (probes / f"{text.partition('.')[0]}.py").is_file()}
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


def _env(autoescape: bool):
    from .render import _env as render_env

    return render_env(autoescape)


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
    html, text = _env(True), _env(False)
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


# ---------------------------------------------------------------------------------------------- results.json


def grader_faults(reports: list[ProblemReport]) -> list[str]:
    """The checks that are the grader's fault (it could not run them): a submission with any is not a grade."""
    return [r.check_id for report in reports for r in report.results if r.status is Status.GRADER_ERROR]


def _whose(reports: list[ProblemReport]) -> tuple[bool, bool]:
    """``(graded, loaded)`` by ``grader.faults``' table: a fault of the grader's makes the reports no grade; the
    loader's (the student's) makes them a submission that could not be loaded."""
    from .faults import LOADER, faults_in

    faults = faults_in(reports)
    return all(fault.student for fault in faults), LOADER not in faults


def _fmt(x: float) -> str:
    return f"{x:g}"


def _cut(text: str, limit: int = TEXT_CHARS) -> str:
    if len(text) <= limit:
        return text
    return text[:limit] + f"\n[... {len(text) - limit} more characters left out]"


def _check_message(r: CheckResult) -> str:
    """The first line a student reads of a public check: passed, or what is wrong."""
    if r.passed:
        return "passed"
    first = r.message.splitlines()[0] if r.message else r.status.value.replace("_", " ")
    return f"{first} (likely mistake: {r.diagnosis})" if r.diagnosis else first


def _check_output(r: CheckResult) -> str:
    parts = [r.message or ("passed" if r.passed else r.status.value.replace("_", " "))]
    if r.diagnosis:
        parts.append(f"likely mistake: {r.diagnosis}")
    if r.hint:
        parts.append(f"hint: {r.hint}")
    if r.seed is not None and not r.passed:
        parts.append(f"random inputs drawn with seed {r.seed}")
    return _cut("\n".join(parts))


def _withheld_test(report: ProblemReport, withheld: list[CheckResult]) -> dict:
    points = sum(r.score for r in withheld)
    maximum = sum(r.max_score for r in withheld)
    secret = [r for r in withheld if r.visibility == "visible"]
    hidden = len(withheld) - len(secret)
    lines = [f"{len(withheld)} check{'s' if len(withheld) != 1 else ''} graded now whose messages your course "
             "staff keep back (their answers would give the key away):"]
    lines += [f"  - {r.title} ({_fmt(r.max_score)} point{'s' if r.max_score != 1 else ''})" for r in secret]
    if hidden:
        lines.append(f"  - {hidden} hidden check{'s' if hidden != 1 else ''}")
    return {
        "name": f"Problem {report.problem}: checks whose details are withheld",
        "description": "graded now; only their points are shown",
        "points": float(points),
        "max_points": float(maximum),
        "message": f"{_fmt(points)} of {_fmt(maximum)} points",
        "output": "\n".join(lines),
    }


def _test(r: CheckResult, images: list[dict]) -> dict:
    test = {
        "name": f"Problem {r.problem}: {r.title}",
        "description": r.check_id,
        "points": float(r.score),
        "max_points": float(r.max_score),
        "message": _cut(_check_message(r), 2_000),
        "output": _check_output(r),
    }
    if images:
        test["images"] = images
    return test


def _manual_test(report: ProblemReport, item) -> dict:
    return {
        "name": f"Problem {item.problem}: {item.question} (scored by hand)",
        "description": f"free text: {item.key}",
        "points": 0.0,
        "max_points": 0.0,
        "message": f"scored by hand by your course staff ({_fmt(item.max_score)} points, not part of this score)",
        "output": _cut(f"Your answer:\n{item.answer or '(blank)'}"),
    }


def _png(fig: Figure, dpi: int) -> str:
    from .render import _pyplot, figure_canvas, on_grid

    canvas = figure_canvas(on_grid(fig))
    buffer = io.BytesIO()
    canvas.savefig(buffer, format="png", dpi=dpi)
    _pyplot().close(canvas)
    return base64.b64encode(buffer.getvalue()).decode()


def _images(results: list[CheckResult], dpi: int | None) -> dict[str, list[dict]]:
    """The figures of ``results`` as PrairieLearn's images (data URLs) at ``dpi``; none when ``dpi`` is None."""
    if dpi is None:
        return {}
    return {r.check_id: [{"label": fig.title, "url": "data:image/png;base64," + _png(fig, dpi)}
                         for fig in r.figures]
            for r in results if r.figures}


def _size(data: dict) -> int:
    return len(json.dumps(data).encode("utf-8"))


def _message(reports: list[ProblemReport], seed: int | None, earned: float, maximum: float, public: float,
             public_max: float, figures_left: int) -> str:
    notes = sorted({n for report in reports for n in report.notes}
                   | {report.sandbox for report in reports if not report.isolated and report.sandbox})
    return _env(False).get_template("prairielearn/message.txt.j2").render(
        reports=reports, seed=seed, earned=earned, maximum=maximum, public=public, public_max=public_max,
        notes=notes, figures_left=figures_left, fmt=_fmt).strip() + "\n"


def results_json(reports: list[ProblemReport], *, withheld_ids: set[str] | None = None, seed: int | None = None,
                 limit: int = RESULTS_BYTES) -> dict:
    """PrairieLearn's results.json of one graded submission (see the module's docstring), within ``limit``
    bytes: a submission that could not be loaded, or that the grader could not grade in full, is not gradable."""
    from .gradescope import withheld_check_ids

    graded, loaded = _whose(reports)
    if not graded:  # the grader's fault first: never the student's zero
        faults = grader_faults(reports)
        return fault_results(f"the grader could not run {len(faults)} check{'s' if len(faults) != 1 else ''} "
                             f"({', '.join(faults)})")
    if not loaded:
        return unloadable_results(next(r.load_error for r in reports if r.load_error))
    if withheld_ids is None:
        withheld_ids = withheld_check_ids([r.problem for r in reports])
    earned = sum(r.score for report in reports for r in report.results)
    maximum = sum(r.auto_max_score for r in reports)
    shown, withheld = [], []
    for report in reports:
        for r in report.results:
            (withheld if r.check_id in withheld_ids or r.visibility == "hidden" else shown).append(r)
    public = sum(r.score for r in shown)
    public_max = sum(r.max_score for r in shown)
    drawn = sum(len(r.figures) for r in shown)

    def build(dpi: int | None, chars: int) -> dict:
        images = _images(shown, dpi)
        tests = []
        for report in reports:
            mine = [r for r in shown if r.problem == report.problem]
            tests += [_test(r, images.get(r.check_id, [])) for r in mine]
            held = [r for r in withheld if r.problem == report.problem]
            if held:
                tests.append(_withheld_test(report, held))
            tests += [_manual_test(report, item) for item in report.manual]
        for test in tests:
            test["output"] = _cut(test["output"], chars)
        return {
            "gradable": True,
            "score": float(earned / maximum) if maximum else 0.0,
            "message": _message(reports, seed, earned, maximum, public, public_max,
                                drawn if dpi is None else 0),
            "tests": tests,
        }

    for dpi in (*FIGURE_DPI, None):
        data = build(dpi, TEXT_CHARS)
        if _size(data) <= limit or dpi is None:
            break
    chars = TEXT_CHARS
    while _size(data) > limit and chars > 200:  # long texts (a student's output) cut further until it fits
        chars //= 4
        data = build(None, chars)
    return data


def unloadable_results(reason: str) -> dict:
    """A submission that cannot be loaded: not gradable (it costs no attempt), the reason in ``format_errors``."""
    message = f"Your submission could not be loaded, so nothing was graded: {_cut(reason, 4_000)}"
    return {"gradable": False, "score": 0.0, "message": message, "format_errors": [message], "tests": []}


def fault_results(reason: str) -> dict:
    """A submission the grader could not grade (its fault, not the student's): not gradable, so that it costs the
    student no attempt and no score is recorded, and said plainly."""
    text = _env(False).get_template("prairielearn/fault.txt.j2").render(reason=_cut(reason, 4_000)).strip()
    return {"gradable": False, "score": 0.0, "message": text, "format_errors": [text], "tests": []}


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
    from .faults import fault_of, faults_in
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
        if isinstance(exc, GraderFault):
            say(f"grader fault: {exc}", sys.stdout)
            reason = str(exc)
        else:
            traceback.print_exc(file=sys.stdout)
            reason = f"internal error of the grader ({type(exc).__name__}); the course staff have its log"
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
