"""``grade kit OUT_DIR``: the student kit.

The kit is a wheel holding the grader, the checks, the probes, the student template and an *answer key*, and no
reference code.  The key is recorded by grading the reference itself (in this process: it is trusted) with a
``RecordingOracle``: every reference call of the public checks, the pool of random inputs of every randomized
comparison (drawn once per kit from the kit's seed) and every random draw.  Secret checks (multiple choice,
predicted output) and hidden checks do not run while recording, so nothing of their keys is in the kit; the
reference's answers.toml (model answers) is not in it either.

The wheel is written with ``zipfile`` (a wheel is a zip with a ``.dist-info`` folder: METADATA, WHEEL,
entry_points.txt, RECORD), so building it needs neither a network nor a build backend.
"""

from __future__ import annotations

import base64
import csv
import hashlib
import importlib.util
import io
import json
import random
import re
import time
import tomllib
import zipfile
from dataclasses import dataclass
from pathlib import Path

from . import __version__
from .context import Context
from .errors import GraderFault
from .oracle import KEY_FILE, AnswerKey, RecordingOracle, reference_available
from .results import ProblemReport, Status

__all__ = ["ReferenceChild", "Kit", "record_key", "build_kit", "write_wheel", "kit_files",
           "KitError", "KIT_NAME", "KIT_PACKAGES", "KIT_DEPENDENCIES", "KIT_EXTRAS", "kit_dependencies", "kit_extras"]

#: the distribution name of the kit
KIT_NAME = "mbd_autograder_kit"
#: the packages the kit holds (never ``reference``)
KIT_PACKAGES = ("grader", "checks", "probes", "student_template")
#: what a student's grading needs: the kit requires these of the project's dependencies, and no other (no Dask:
#: a cluster is the instructor's)
KIT_DEPENDENCIES = ("numpy", "scipy", "sympy", "matplotlib", "mujoco", "jinja2", "nbformat", "hypothesis")
#: the kit's extras, from the project's optional dependencies of the same names: ``[jupyter]`` brings JupyterLab
KIT_EXTRAS = ("jupyter",)
#: files of those packages that are not copied
SKIPPED_SUFFIXES = (".pyc", ".pyo", ".tmp")
PROJECT_ROOT = Path(__file__).resolve().parents[1]


class KitError(Exception):
    """The kit cannot be built (no reference, or the reference fails a public check)."""


class ReferenceChild:
    """The "student" side while the key is recorded: the probes run on the reference in this process (the
    reference is trusted; no sandbox is needed).  Its calls share the oracle's caches but are not recorded."""

    def __init__(self, oracle: RecordingOracle):
        self.oracle = oracle
        self.calls = 0

    def call(self, probe: str, *args, timeout: float | None = None):
        from probes._codec import decode

        from .checking import in_random_input

        self.calls += 1
        key, encoded, _ = self.oracle.compute(probe, args)
        fixed = getattr(self.oracle, "student_fixed_keys", None)  # a recording oracle's (_answers_to_the_student)
        if fixed is not None and not in_random_input():
            fixed.add(key)
        return decode(encoded)

    def output(self) -> tuple[str, str]:
        return "", ""


def _reference_answers() -> dict:
    from .loader import read_answers

    spec = importlib.util.find_spec("reference")
    answers, error = read_answers(Path(spec.origin).parent)
    if error:
        raise KitError(f"the reference's answers.toml cannot be read: {error}")
    return answers


def record_key(problems: list[int] | None = None, seed: int | None = None,
               progress=None, jobs: int = 1) -> tuple[AnswerKey, list[ProblemReport]]:
    """Grade the reference on ``problems`` (default: every problem) while recording the answer key.  Every public
    check must pass: a key recorded from a failing reference would grade students wrongly.  With ``jobs`` > 1 the
    problems are recorded side by side in that many processes and their recordings joined in the problems' order:
    the key is the one a single process records."""
    from .problems import problems as all_problems

    if not reference_available():
        raise KitError("grade kit needs the full project: the reference solution is not installed here")
    seed = random.randrange(2**31) if seed is None else int(seed)
    numbers = problems or [p.number for p in all_problems()]
    oracle = RecordingOracle(seed)  # the public checks: the key
    shadow = RecordingOracle(seed, secret=True)  # the secret and hidden checks: what the key must not hold
    answers = _reference_answers()
    reports, failures = [], []
    if jobs > 1 and len(numbers) > 1:
        recorded = _recorded_side_by_side(numbers, seed, jobs, progress)
        for number in numbers:
            public, secret, report, failed = recorded[number]
            oracle.absorb(public)
            shadow.absorb(secret)
            reports.append(report)
            failures += failed
    else:
        for number in numbers:
            report, failed = _record_problem(number, oracle, shadow, answers, seed)
            reports.append(report)
            failures += failed
            if progress:
                progress(number, report.duration)
    if failures:
        raise KitError("the reference does not pass every check, so no key is recorded:\n  "
                       + "\n  ".join(failures))
    key = oracle.key
    # A public check that uses a value of a secret check would carry that value into the kit: withhold it too.
    shared = set(shadow.key.calls) & set(key.calls)
    key.withheld = sorted({check for call in shared for check in key.calls[call]["checks"]})
    for call in shared:
        del key.calls[call]
    key.drop_checks(key.withheld)
    for call in _answers_to_the_student(oracle) & set(key.calls):
        del key.calls[call]
    _hold_at_sheet_digits(key, oracle, numbers, answers, seed)
    return key, reports


def _record_problem(number: int, oracle: RecordingOracle, shadow: RecordingOracle, answers: dict,
                    seed: int) -> tuple[ProblemReport, list[str]]:
    """Grade the reference on one problem into ``oracle`` (public checks) and ``shadow`` (secret and hidden ones):
    its report and the checks it did not pass."""
    from .problems import problem_module
    from .runner import _run_checks

    start = time.perf_counter()
    module = problem_module(number)
    results = _run_checks(module, Context(number, ReferenceChild(oracle), answers, None, seed, oracle), number)
    secret = _run_checks(module, Context(number, ReferenceChild(shadow), answers, None, seed, shadow), number)
    failures = [f"{r.check_id} ({r.status.value}): {r.message.splitlines()[0] if r.message else ''}"
                for r in (*results, *secret) if r.status not in (Status.PASSED, Status.DEFERRED)]
    report = ProblemReport(number, module.TITLE, tuple(results), sandbox="the reference, in process", seed=seed,
                           duration=time.perf_counter() - start, grader_version=__version__)
    return report, failures


def _record_alone(task: tuple[int, int]):
    """One problem recorded in a process of its own (``record_key`` with jobs): what its two oracles recorded, its
    report and the checks it did not pass."""
    number, seed = task
    oracle, shadow = RecordingOracle(seed), RecordingOracle(seed, secret=True)
    report, failures = _record_problem(number, oracle, shadow, _reference_answers(), seed)
    return number, oracle.recorded(), shadow.recorded(), report, failures


def _recorded_side_by_side(numbers: list[int], seed: int, jobs: int, progress) -> dict:
    """Every problem of ``numbers`` recorded in ``jobs`` fresh processes (the later, longer problems first):
    number → (public recording, secret recording, report, failures)."""
    import multiprocessing

    recorded = {}
    context = multiprocessing.get_context("spawn")  # never a fork of a process that may hold threads
    with context.Pool(min(jobs, len(numbers))) as pool:
        for number, public, secret, report, failures in pool.imap_unordered(
                _record_alone, [(n, seed) for n in sorted(numbers, reverse=True)]):
            recorded[number] = (public, secret, report, failures)
            if progress:
                progress(number, report.duration)
    return recorded


def _answers_to_the_student(oracle: RecordingOracle) -> set[str]:
    """Calls the key must not hold at all: the diagnosis engine's calls of the reference on the arguments of a
    fixed case asked of the student that no check asks of the reference (the engine traces a student's value to
    such a call), which a lookup of the key would answer with a value of the right kind (a shape check earns its
    point with any)."""
    return (oracle.student_fixed_keys & oracle.diagnosis_keys) - oracle.fixed_keys


def _kit_failures(key: AnswerKey, student: RecordingOracle, numbers, answers, seed) -> tuple[set[str], list]:
    """The public checks that the reference does not pass when graded as the kit grades, from ``key``, and the calls
    they asked that the key does not hold."""
    from .oracle import KeyOracle
    from .problems import problem_module
    from .runner import _run_checks

    kit = KeyOracle(key, check_fingerprint=False)
    failing = set()
    for number in numbers:
        context = Context(number, ReferenceChild(student), answers, None, seed, kit)
        failing |= {r.check_id for r in _run_checks(problem_module(number), context, number)
                    if r.status not in (Status.PASSED, Status.DEFERRED)}
    return failing, kit.missing


def _telling(data) -> bool:
    """Numbers that a call key holds only when they were passed on: three or more, two of them not whole
    (``[0.0, 0.0, 1.0]`` is anyone's)."""
    return len(data) >= 3 and sum(1 for x in data if type(x) is float and not x.is_integer()) >= 2


def _numbers_in(encoded) -> list[str]:
    """The texts of the arrays of an encoded value (``_telling`` ones), as they appear in a call key."""
    if isinstance(encoded, dict) and "__array__" in encoded:
        return [json.dumps(encoded["data"])[1:-1]] if _telling(encoded["data"]) else []
    if isinstance(encoded, dict):
        return [text for value in encoded.values() for text in _numbers_in(value)]
    if isinstance(encoded, list):
        if all(type(x) is float for x in encoded):
            return [json.dumps(encoded)[1:-1]] if _telling(encoded) else []
        return [text for value in encoded for text in _numbers_in(value)]
    return []


def _hold_at_sheet_digits(key: AnswerKey, oracle: RecordingOracle, numbers, answers, seed) -> None:
    """Hold the fixed cases at the sheet's digits (``AnswerKey.round_fixed_cases``), then grade the reference as
    the kit grades: a value that a check passes on to another call (problem 32's desired trajectory, sent to the
    student's torques) gets its full precision back, since the kit looks that call up by it (and when the call
    cannot be told, every rounded value of a check that no longer passes).  Every public check of the reference
    passes in the kit, or no key is written."""
    rounded = key.round_fixed_cases(oracle.fixed_keys)
    for _ in range(4):
        failing, missing = _kit_failures(key, oracle, numbers, answers, seed)
        if not failing:
            return
        passed_on = [call for call in rounded
                     if any(text in asked for text in _numbers_in(key.calls[call]["value"]) for asked in missing)]
        restore = passed_on or [call for call in rounded if set(key.calls[call]["checks"]) & failing]
        if not restore:
            break
        for call in restore:
            key.calls[call]["value"] = rounded.pop(call)
            del key.calls[call]["sheet"]
    raise KitError("the reference does not pass every check from the answer key:\n  " + "\n  ".join(sorted(failing)))


# ---------------------------------------------------------------------------------------------- the wheel


def _package_root(name: str) -> Path:
    here = PROJECT_ROOT / name
    if (here / "__init__.py").is_file():
        return here
    spec = importlib.util.find_spec(name)
    if spec is None or spec.origin is None:
        raise KitError(f"the package {name} is not installed")
    return Path(spec.origin).parent


def kit_files(packages: tuple[str, ...] = KIT_PACKAGES) -> dict[str, bytes]:
    """The files of ``packages`` (default: the kit's), by their path in the wheel (no caches, no answer key of
    another kit)."""
    files = {}
    for package in packages:
        root = _package_root(package)
        for path in sorted(root.rglob("*")):
            relative = path.relative_to(root)
            if not path.is_file() or "__pycache__" in relative.parts or path.suffix in SKIPPED_SUFFIXES:
                continue
            if package == "grader" and relative.as_posix() == KEY_FILE:
                continue
            files[f"{package}/{relative.as_posix()}"] = path.read_bytes()
    return files


def runtime_dependencies() -> list[str]:
    """The project's runtime dependencies (``[project] dependencies`` of pyproject.toml)."""
    pyproject = PROJECT_ROOT / "pyproject.toml"
    if pyproject.is_file():
        return list(tomllib.loads(pyproject.read_text())["project"]["dependencies"])
    from importlib.metadata import PackageNotFoundError, requires

    for name in ("mbd-autograder", KIT_NAME):
        try:
            return [r for r in (requires(name) or []) if "extra ==" not in r]
        except PackageNotFoundError:
            continue
    raise KitError("the project's dependencies are unknown (no pyproject.toml, no installed metadata)")


def _requirement_name(requirement: str) -> str:
    return re.split(r"[\s\[<>=!~;]", requirement.strip(), maxsplit=1)[0].lower().replace("_", "-")


def kit_dependencies() -> list[str]:
    """The kit's requirements: the project's runtime dependencies named in ``KIT_DEPENDENCIES``, with their
    version bounds."""
    chosen = [r for r in runtime_dependencies() if _requirement_name(r) in KIT_DEPENDENCIES]
    missing = sorted(set(KIT_DEPENDENCIES) - {_requirement_name(r) for r in chosen})
    if missing:
        raise KitError(f"the project's dependencies lack what the kit needs: {', '.join(missing)}")
    return chosen


def kit_extras() -> dict[str, list[str]]:
    """The kit's extras (``KIT_EXTRAS``), as the project's ``[project.optional-dependencies]`` declares them."""
    pyproject = PROJECT_ROOT / "pyproject.toml"
    if pyproject.is_file():
        optional = tomllib.loads(pyproject.read_text())["project"].get("optional-dependencies", {})
        return {extra: list(optional[extra]) for extra in KIT_EXTRAS if extra in optional}
    from importlib.metadata import PackageNotFoundError, requires

    for name in ("mbd-autograder", KIT_NAME):
        try:
            found = requires(name) or []
        except PackageNotFoundError:
            continue
        extras: dict[str, list[str]] = {}
        for requirement in found:
            match = re.search(r"""extra\s*==\s*["']([\w-]+)["']""", requirement)
            if match and match.group(1) in KIT_EXTRAS:
                extras.setdefault(match.group(1), []).append(requirement.split(";")[0].strip())
        return extras
    return {}


def _record_hash(data: bytes) -> str:
    return "sha256=" + base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()


KIT_SUMMARY = ("Student kit of the multibody-dynamics course: the grader, its checks and the student template "
               "(no reference solution)")


def _metadata(dependencies: list[str], name: str = KIT_NAME, summary: str = KIT_SUMMARY,
              extras: dict[str, list[str]] | None = None) -> str:
    lines = [
        "Metadata-Version: 2.1",
        f"Name: {name}",
        f"Version: {__version__}",
        f"Summary: {summary}",
        "Requires-Python: >=3.11",
        *(f"Requires-Dist: {dependency}" for dependency in dependencies),
    ]
    for extra, requirements in (extras or {}).items():
        lines.append(f"Provides-Extra: {extra}")
        lines += [f'Requires-Dist: {requirement}; extra == "{extra}"' for requirement in requirements]
    return "\n".join(lines) + "\n"


def write_wheel(out_dir: str | Path, files: dict[str, bytes], dependencies: list[str], *, name: str = KIT_NAME,
                packages: tuple[str, ...] = KIT_PACKAGES, summary: str = KIT_SUMMARY,
                extras: dict[str, list[str]] | None = None) -> Path:
    """Write ``files`` (path in the wheel → bytes) as a pure-Python wheel ``name`` (default: the kit) of the
    top-level ``packages``, with the ``grade`` command; ``extras`` maps an extra's name to its requirements."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    dist_info = f"{name}-{__version__}.dist-info"
    path = out_dir / f"{name}-{__version__}-py3-none-any.whl"
    files = dict(files)
    files[f"{dist_info}/METADATA"] = _metadata(dependencies, name, summary, extras).encode()
    files[f"{dist_info}/WHEEL"] = (
        "Wheel-Version: 1.0\nGenerator: mbd-autograder grade kit\nRoot-Is-Purelib: true\nTag: py3-none-any\n"
    ).encode()
    files[f"{dist_info}/entry_points.txt"] = b"[console_scripts]\ngrade = grader.cli:main\n"
    files[f"{dist_info}/top_level.txt"] = ("\n".join(packages) + "\n").encode()
    record = io.StringIO()
    writer = csv.writer(record, lineterminator="\n")
    for name in sorted(files):
        writer.writerow([name, _record_hash(files[name]), len(files[name])])
    writer.writerow([f"{dist_info}/RECORD", "", ""])
    files[f"{dist_info}/RECORD"] = record.getvalue().encode()
    tmp = path.with_suffix(".tmp")
    with zipfile.ZipFile(tmp, "w", compression=zipfile.ZIP_DEFLATED) as wheel:
        for name in sorted(files, key=lambda n: (n.startswith(dist_info), n)):  # the .dist-info folder last
            info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = 0o644 << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(info, files[name])
    tmp.replace(path)
    return path


@dataclass(frozen=True)
class Kit:
    wheel: Path
    key: AnswerKey
    key_bytes: int
    reports: tuple[ProblemReport, ...]


def build_kit(out_dir: str | Path, *, seed: int | None = None, problems: list[int] | None = None,
              progress=None, key: AnswerKey | None = None, jobs: int = 1) -> Kit:
    """Record the answer key (unless ``key`` is given, recorded already; in ``jobs`` processes) and write the kit's
    wheel into ``out_dir``."""
    reports: list = []
    if key is None:
        key, reports = record_key(problems, seed, progress, jobs=jobs)
    data = key.dumps()
    files = kit_files()
    leaked = sorted(name for name in files if name.split("/")[0] == "reference")
    if leaked:
        raise GraderFault(f"the kit would hold reference files: {leaked}")
    files[f"grader/{KEY_FILE}"] = data
    wheel = write_wheel(out_dir, files, kit_dependencies(), extras=kit_extras())
    return Kit(wheel, key, len(data), tuple(reports))
