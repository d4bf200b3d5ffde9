"""The ``grade`` command.

    grade problem-N [--submission P]   grade problem N of the submission in P (default: the current folder);
                                       also understood: grade 6, grade p6, grade problem 6
    grade init DIR [--notebook]        copy the student template to DIR (and write it as notebooks)
    grade list                         every problem, its points, and whether checks exist for it
    grade demo                         grade the bundled sample submissions
    grade kit OUT_DIR                  build the student kit (grader, checks, template, answer key; no reference)
    grade gradescope OUT.zip           build Gradescope's autograder (grader with the reference, setup.sh, ...)
    grade prairielearn OUT_DIR         build PrairieLearn questions and their grader (with the reference)
    grade prairielearn --run [JOB]     grade a PrairieLearn job folder (default /grade): the questions' entry point
    grade similarity RESULTS           after a batch: pairs of students whose answers or code agree (evidence only)
    grade batch SUBMISSIONS --out DIR  grade every student of a folder (see ``grade batch --help``)

In the student kit (no reference), ``grade --help`` lists the student's commands only (``INSTRUCTOR_COMMANDS``
are left out of it).

Exit codes: 0 all checks passed, 1 some checks did not pass, 2 usage error or a submission that cannot be
loaded, 3 an internal grader error, 130 interrupted by Ctrl-C (a batch also by SIGTERM), 143 stopped by SIGTERM.
"""

from __future__ import annotations

import argparse
import codecs
import os
import re
import shutil
import signal
import sys
from pathlib import Path

from .arguments import parse_problems, positive_int, problem_number
from .errors import EXIT_FAILED, EXIT_GRADER, EXIT_OK, EXIT_USAGE, GraderFault  # noqa: F401 - the command's codes
from .problems import NoChecks, require_problem

#: commands for the instructor: not listed by the student kit's help
INSTRUCTOR_COMMANDS = ("demo", "kit", "gradescope", "prairielearn", "similarity", "batch", "import-manual",
                       "export")
#: the first words that ask for a problem: problem-6, problem6, p6, 6 (any case)
_PROBLEM_WORD = re.compile(r"(?:problem-?|p)?\d{1,2}", re.IGNORECASE)


def _write(path: str | None, text: str) -> None:
    if path:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        Path(path).write_text(text, encoding="utf-8")
        print(f"wrote {path}", file=sys.stderr)


def cmd_init(args) -> int:
    from .loader import template_dir

    target = Path(args.dir)
    if target.exists() and any(target.iterdir()):
        print(f"error: {target} exists and is not empty; choose a new folder", file=sys.stderr)
        return EXIT_USAGE
    shutil.copytree(template_dir(), target, dirs_exist_ok=True, ignore=shutil.ignore_patterns("__pycache__"))
    if args.notebook:
        import nbformat

        from .loader import template_notebooks

        for name, book in template_notebooks().items():
            nbformat.write(book, target / name)
        print(f"Created {target}/ from the student template, with a notebook per problem (problem_06.ipynb, ...): "
              f"write your solutions in the notebooks (or in the .py files).\nNext: cd {target} && jupyter lab; "
              "in a notebook, `from grader import check; check(6)` (or, in a terminal, grade problem-6)")
        return EXIT_OK
    print(f"Created {target}/ from the student template.\nNext: cd {target} && grade problem-6")
    return EXIT_OK


def cmd_list(args) -> int:
    from types import SimpleNamespace

    from .listing import problem_list  # cached: no check module is imported while the checks are unchanged

    infos = [SimpleNamespace(**p) for p in problem_list()]
    print(f"{'problem':>8}  {'points':>6}  {'by hand':>7}  {'checks':>6}  title")
    for p in infos:
        manual = f"{p.manual_points:g}" if p.manual_points else "-"
        print(f"{p.number:>8}  {p.points:>6g}  {manual:>7}  {p.checks:>6}  {p.title}")
    print(f"\n{len(infos)} problems have checks; {sum(p.points for p in infos):g} points graded automatically.")
    return EXIT_OK


def _exit_code(reports) -> int:
    """The command's exit code for its reports: whose fault each failure is decides it (``grader.faults``)."""
    from .faults import exit_code

    return exit_code(reports)


def _workers(source: Path, limits, count: int):
    """The submission's workers (``count``, each with a copy of its own), started before the grader imports what
    grading needs (numpy, the checks) so that their start-up overlaps those imports (``grader.workers.Started``);
    fresh ones when the submission cannot be loaded (grading then says why).  The started copies are removed when
    the command ends."""
    from .oracle import reference_available
    from .sandbox import student_mode
    from .workers import Fresh, Started

    started = Started.start(source, limits, student_mode(kit=not reference_available()), count)
    if started is None:
        return Fresh(limits, count=count)
    _LEFT_TO_REMOVE.extend(started.submissions)
    return started


def default_workers(problems: int) -> int:
    """Workers for ``grade problem-N ...``: two for several problems on a machine with two cores or more, else
    one (a single problem gains nothing from a second worker's start-up)."""
    return 2 if problems > 1 and _cores() >= 2 else 1


def _cores() -> int:
    """The cores this process may run on (all of the machine's where the system cannot say: macOS, Windows)."""
    affinity = getattr(os, "sched_getaffinity", None)
    return len(affinity(0)) if affinity is not None else (os.cpu_count() or 1)


def cmd_problem(args) -> int:
    from .sandbox import Limits

    numbers = args.problems
    try:
        for number in numbers:
            require_problem(number)
    except NoChecks as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    submission = Path(args.submission)
    if not submission.exists():
        print(f"error: {submission} does not exist", file=sys.stderr)
        return EXIT_USAGE
    limits = Limits(call_timeout=args.timeout) if args.timeout else None
    workers = _workers(submission, limits, min(args.workers or default_workers(len(numbers)), len(numbers)))
    from .report.data import render_json
    from .report.gradescope_results import render_results
    from .report.html import render_html
    from .report.text import render_terminal
    from .runner import grade_submission

    reports = grade_submission(submission, numbers, seed=args.seed, workers=workers)
    print(render_terminal(reports, colour=_colours(sys.stdout)), end="")
    if args.html:
        _write(args.html, render_html(reports, title=f"Problem {', '.join(map(str, numbers))}"))
    _write(args.json, render_json(reports, show_hidden=False))
    _write(args.gradescope, render_results(reports))
    return _exit_code(reports)  # a submission that cannot be loaded: 2, said once in the report with the fix


def _colours(stream) -> bool:
    """Whether the report is coloured on ``stream``: a terminal, unless NO_COLOR is set; on Windows, a console
    that was asked to read escape sequences and could (``ENABLE_VIRTUAL_TERMINAL_PROCESSING``, Windows 10 and
    later: an older console would print them as they are)."""
    try:
        terminal = stream.isatty()
    except (AttributeError, ValueError, OSError):
        return False
    if not terminal or "NO_COLOR" in os.environ:
        return False
    return os.name != "nt" or _windows_escapes(stream)


def _windows_escapes(stream) -> bool:
    """Ask the Windows console of ``stream`` to read escape sequences; whether it does."""
    try:
        import ctypes
        import msvcrt
        from ctypes import wintypes

        kernel32 = ctypes.WinDLL("kernel32", use_last_error=True)
        kernel32.GetConsoleMode.argtypes = (wintypes.HANDLE, ctypes.POINTER(wintypes.DWORD))
        kernel32.SetConsoleMode.argtypes = (wintypes.HANDLE, wintypes.DWORD)
        handle = msvcrt.get_osfhandle(stream.fileno())
        mode = wintypes.DWORD()
        if not kernel32.GetConsoleMode(handle, ctypes.byref(mode)):
            return False
        if mode.value & _VIRTUAL_TERMINAL:
            return True
        return bool(kernel32.SetConsoleMode(handle, mode.value | _VIRTUAL_TERMINAL))
    except (ImportError, AttributeError, OSError, ValueError):
        return False


#: ENABLE_VIRTUAL_TERMINAL_PROCESSING, the mode of a Windows console that reads escape sequences
_VIRTUAL_TERMINAL = 0x0004


def _readable_output() -> None:
    """Let every character of a report reach the output (the marks ✔ and ✘, a student's own text): where the
    encoding of standard output or error cannot write them all (Windows writes a pipe or a file in its ANSI
    code page, cp1252 say; a terminal of a Latin-1 locale), a pipe or a file gets UTF-8, and a terminal keeps
    its encoding with what it cannot show replaced."""
    for stream in (sys.stdout, sys.stderr):
        try:
            if codecs.lookup(stream.encoding).name.startswith("utf"):
                continue
            if stream.isatty():
                stream.reconfigure(errors="replace")
            else:
                stream.reconfigure(encoding="utf-8")
        except (AttributeError, LookupError, TypeError, ValueError, OSError):
            continue


def cmd_demo(args) -> int:
    from .oracle import current

    if current().mode == "kit":
        print("grade demo needs the full project (the reference solution and the sample submissions): this is the "
              "student kit, which holds neither.\nGrade your own work with `grade problem-6` in your folder "
              "(`grade init mywork` makes one).", file=sys.stderr)
        return EXIT_USAGE
    from .demo import run_demo

    return run_demo(args)


def cmd_kit(args) -> int:
    from .kit import KitError, build_kit

    def progress(number, seconds):
        print(f"  recorded problem {number} in {seconds:.1f} s", file=sys.stderr)

    try:
        kit = build_kit(args.out_dir, seed=args.seed, problems=args.problems, progress=progress,
                        jobs=args.jobs or os.cpu_count() or 1)
    except KitError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    key = kit.key
    print(f"wrote {kit.wheel}\nanswer key: {len(key.calls)} reference values, {len(key.pools)} pools of random "
          f"inputs, {len(key.draws)} random draws, {kit.key_bytes / 1024:.0f} KiB compressed (kit seed {key.seed})."
          f"\nStudents install it with `pip install {kit.wheel.name}`; it holds no reference code.")
    return EXIT_OK


def cmd_gradescope(args) -> int:
    from .gradescope import build_autograder
    from .kit import KitError

    try:
        built = build_autograder(args.out_zip, parse_problems(args.problems))
    except (KitError, ValueError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    manual = (f"\nFree-text answers worth {built.manual_points:g} points are scored by hand: add them to the "
              "assignment as manually graded questions." if built.manual_points else "")
    print(f"wrote {built.zip} (problems {', '.join(map(str, built.problems))}; {', '.join(built.files)})\n"
          f"Upload it as the autograder of a Gradescope programming assignment worth {built.points:g} autograder "
          f"points.{manual}\nIt holds the reference solution: keep it on the instructors' side.")
    return EXIT_OK


def cmd_problem_spelling(args) -> int:
    print("error: write the problem's number: grade problem-6 (several: grade problem-6 problem-7)", file=sys.stderr)
    return EXIT_USAGE


def cmd_prairielearn(args) -> int:
    from .kit import KitError
    from .prairielearn import build_fragment, run

    if args.run is not None:
        if args.out_dir or args.problems:
            print("error: --run grades a job folder; OUT_DIR and --problems are for building questions",
                  file=sys.stderr)
            return EXIT_USAGE
        return run(args.run, seed=args.seed)
    if not args.out_dir:
        print("error: give OUT_DIR (the folder of the course fragment to write) or --run JOB_DIR", file=sys.stderr)
        return EXIT_USAGE
    try:
        built = build_fragment(args.out_dir, parse_problems(args.problems), image=args.image)
    except (KitError, ValueError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    print(f"wrote {len(built.questions)} questions (problems {', '.join(map(str, built.problems))}, "
          f"{built.points:g} points) into {built.out}/: questions/, serverFilesCourse/ (the grader's wheel "
          f"{built.wheel}, with the reference solution) and grader-image/.\n"
          f"Build and push the image: docker build -t {built.image} {built.out}/grader-image && "
          f"docker push {built.image}\nThen copy questions/ and serverFilesCourse/ into your course repository. "
          "The course files hold the reference solution: keep the repository private.")
    return EXIT_OK


def cmd_similarity(args) -> int:
    from .batch.gradebook import GRADEBOOK_NAME
    from .similarity import write_similarity

    results = Path(args.results)
    if not (results / GRADEBOOK_NAME).exists():
        print(f"error: {results} holds no gradebook (run `grade batch` first)", file=sys.stderr)
        return EXIT_USAGE
    try:
        found = write_similarity(results, top=args.top)
    except ModuleNotFoundError as exc:
        if exc.name != "copydetect":
            raise
        print("error: grade similarity needs copydetect, a dependency of this project: pip install copydetect",
              file=sys.stderr)
        return EXIT_GRADER
    print(f"{found.students} students, {len(found.pairs)} pairs with any evidence ({found.seconds:.1f} s): "
          f"{results}/similarity.csv and {results}/similarity.html.\nEvidence for a person to read, never a "
          "verdict: nothing in it changes a score.")
    for note in found.notes:
        print(f"note: {note}", file=sys.stderr)
    return EXIT_OK


def build_parser(kit: bool = False) -> argparse.ArgumentParser:
    """The command's parser; ``kit``: the student kit's, whose help leaves the instructor's commands out."""
    parser = argparse.ArgumentParser(
        prog="grade",
        description="Autograder of the multibody-dynamics course." + (" (Student kit.)" if kit else ""),
        epilog="Grade a problem with `grade problem-6` inside your work folder (`grade init mywork` makes one); "
               "in Jupyter: `from grader import check; check(6)`.",
    )
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")

    p_problem = sub.add_parser("problem-N", help="grade problem N of your work: grade problem-6 (several: grade "
                               "problem-6 problem-7; see grade problem-6 --help)")
    p_problem.set_defaults(func=cmd_problem_spelling)

    p_init = sub.add_parser("init", help="copy the student template to a new folder")
    p_init.add_argument("dir", help="the folder to create")
    p_init.add_argument("--notebook", action="store_true",
                        help="also write the template as Jupyter notebooks, one per problem (problem_06.ipynb, ...)")
    p_init.set_defaults(func=cmd_init)

    p_list = sub.add_parser("list", help="list the problems, their points and checks")
    p_list.set_defaults(func=cmd_list)

    p_demo = sub.add_parser("demo", help="grade the bundled sample submissions")
    p_demo.add_argument("--problems", type=problem_number, nargs="+", default=None,
                        help="problems to grade (default: those with checks)")
    p_demo.add_argument("--out", default=None, help="also write the demo's reports into this folder")
    p_demo.set_defaults(func=cmd_demo)

    p_kit = sub.add_parser("kit", help="build the student kit (a wheel without the reference) into OUT_DIR")
    p_kit.add_argument("out_dir", help="the folder to write the wheel into")
    p_kit.add_argument("--seed", type=int, default=None, help="the kit's seed (pools of random inputs)")
    p_kit.add_argument("--problems", type=problem_number, nargs="+", default=None,
                       help="problems whose public checks the key covers (default: all)")
    p_kit.add_argument("--jobs", "-j", type=positive_int, default=None, metavar="N",
                       help="problems recorded side by side (default: the number of CPUs); the key is the same")
    p_kit.set_defaults(func=cmd_kit)

    p_gs = sub.add_parser("gradescope", help="build Gradescope's autograder zip (it holds the reference)")
    p_gs.add_argument("out_zip", help="the zip to write, e.g. autograder.zip")
    p_gs.add_argument("--problems", nargs="+", default=None, metavar="LIST",
                      help="the assigned problems, e.g. 6,7,10 or 6-20 (default: every problem with checks)")
    p_gs.set_defaults(func=cmd_gradescope)

    from .prairielearn import DEFAULT_IMAGE, JOB_ROOT

    p_pl = sub.add_parser("prairielearn", help="build PrairieLearn questions and their grader (it holds the "
                          "reference), or grade a job with --run")
    p_pl.add_argument("out_dir", nargs="?", default=None, help="the folder of the course fragment to write")
    p_pl.add_argument("--problems", nargs="+", default=None, metavar="LIST",
                      help="the problems, e.g. 6,7,10 or 6-20 (default: every problem with checks)")
    p_pl.add_argument("--image", default=DEFAULT_IMAGE,
                      help=f"the Docker image the questions name (default {DEFAULT_IMAGE}): build it from "
                           "OUT_DIR/grader-image and push it there")
    p_pl.add_argument("--run", nargs="?", const=JOB_ROOT, default=None, metavar="JOB_DIR",
                      help=f"grade a PrairieLearn job folder (default {JOB_ROOT}) and write its "
                           "results/results.json: what the questions' entry point runs")
    p_pl.add_argument("--seed", type=int, default=None, help="with --run: the seed of the random inputs "
                      "(default: a fresh one)")
    p_pl.set_defaults(func=cmd_prairielearn)

    p_sim = sub.add_parser("similarity", help="after a batch: pairs of students whose wrong answers, diagnosed "
                           "mistakes or code agree (evidence for a person, never a verdict)")
    p_sim.add_argument("results", help="the results folder of `grade batch`")
    p_sim.add_argument("--top", type=positive_int, default=50, help="pairs the HTML report shows (default 50)")
    p_sim.set_defaults(func=cmd_similarity)

    from .batch import add_batch_parser

    add_batch_parser(sub)
    if kit:  # still understood, but not listed: argparse has no public way to leave a command out of the help
        sub._choices_actions = [a for a in sub._choices_actions if a.dest not in INSTRUCTOR_COMMANDS]
    return parser


def _spelled(argv: list[str]) -> list[str] | None:
    """``argv`` of ``grade problem-N ...`` when it asks for problems in any of the spellings understood
    (``problem-6``, ``problem6``, ``p6``, ``6``, ``problem 6``), else None."""
    if len(argv) >= 2 and argv[0].lower() in ("problem", "problems") and _PROBLEM_WORD.fullmatch(argv[1]):
        argv = [argv[1], *argv[2:]]
    if argv and _PROBLEM_WORD.fullmatch(argv[0]):
        return argv
    return None


def _suggestion(word: str) -> str | None:
    """The right spelling for a first word that looks like a problem but is not understood (``problem_6``,
    ``prob6``, ``exercise-6``)."""
    match = re.fullmatch(r"[a-z_.\- ]*?(\d{1,2})", word.strip().lower())
    if match and word.lower() not in ("problem-n",):
        return f"grade problem-{int(match.group(1))}"
    return None


def _problem_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="grade problem-N", description="Grade one problem of a submission.")
    parser.add_argument("problems", type=problem_number, nargs="+", help="problem-N (several allowed)")
    parser.add_argument("--submission", "-s", default=".",
                        help="a folder, a .zip archive or a .ipynb notebook (default: the current folder)")
    parser.add_argument("--html", help="write an HTML report with plots to this file")
    parser.add_argument("--json", help="write a JSON report to this file")
    parser.add_argument("--gradescope", help="write a Gradescope results.json to this file")
    parser.add_argument("--seed", type=int, default=None, help="seed of the randomized checks (to reproduce)")
    parser.add_argument("--timeout", type=float, default=None, help="seconds allowed per call of your code")
    parser.add_argument("--workers", type=positive_int, default=None,
                        help="sandboxed workers grading the problems side by side (default: 2 for several problems "
                             "on two cores or more, else 1)")
    parser.set_defaults(func=cmd_problem)
    return parser


#: materialized submissions that the command removes when it is done
_LEFT_TO_REMOVE: list = []
#: commands that hold nothing to wind down at exit (no pools, threads or clients): run as the ``grade`` command,
#: they leave without the interpreter's shutdown
_QUICK_EXIT = ("cmd_problem", "cmd_list")


#: the exit code after SIGTERM (128 + 15, as a shell reports a process ended by it)
EXIT_TERMINATED = 143


class _Terminated(KeyboardInterrupt):
    """SIGTERM, raised where the command is so that it ends as after Ctrl-C: the student's worker stopped, the
    copy of the submission and the temporary folders removed."""


def _terminate(signum, frame):
    signal.signal(signal.SIGTERM, signal.SIG_IGN)  # once: the clean-up that follows is not cut short
    raise _Terminated


def main(argv: list[str] | None = None) -> int:
    """Run the ``grade`` command on ``argv``.  Run as the command itself (``argv`` None: the ``grade`` script,
    ``python -m grader.cli``), ``grade problem-N`` and ``grade list`` end the process as soon as their output is
    written (``_leave``), and SIGTERM ends it as Ctrl-C does (exit code 143) rather than leaving its folders in the
    temporary directory."""
    if argv is None:
        signal.signal(signal.SIGTERM, _terminate)
    _readable_output()
    try:
        code, command = _run(sys.argv[1:] if argv is None else list(argv))
        if argv is None and command in _QUICK_EXIT:
            _leave(code)
    finally:
        _remove_now()
    return code


def _run(argv: list[str]) -> tuple[int, str | None]:
    command = None
    try:
        problems = _spelled(argv)
        if problems is not None:
            args = _problem_parser().parse_args(problems)
        else:
            if argv and argv[0].lower() in ("problem", "problems"):  # the number is missing
                return cmd_problem_spelling(None), None
            suggestion = _suggestion(argv[0]) if argv else None
            if suggestion is not None:
                print(f"error: {argv[0]!r} is not a command; to grade that problem, write: {suggestion}",
                      file=sys.stderr)
                return EXIT_USAGE, None
            from .oracle import reference_available

            parser = build_parser(kit=not reference_available())
            args = parser.parse_args(argv)
            if args.command is None:
                parser.print_help()
                return EXIT_USAGE, None
        command = getattr(args.func, "__name__", None)
        return args.func(args), command
    except SystemExit as exc:  # argparse's usage errors
        return (EXIT_USAGE if exc.code not in (0, None) else EXIT_OK), command
    except GraderFault as exc:  # the installation's fault (e.g. the sandbox cannot start): nothing was graded
        from .faults import fault_of
        from .terminal import say

        say(f"error: {exc}")
        return fault_of(exc).exit_code, command
    except KeyboardInterrupt as exc:
        terminated = isinstance(exc, _Terminated)
        print("terminated" if terminated else "interrupted", file=sys.stderr)
        return (EXIT_TERMINATED if terminated else 130), command


def _remove_now() -> None:
    from .loader import cleanup

    while _LEFT_TO_REMOVE:
        cleanup(_LEFT_TO_REMOVE.pop())


def _leave(code: int) -> None:
    """End the process now that the output is written: its temporary folders (the submission's copy, the
    worker's runtime folder, hypothesis's home) are removed by a detached process of their own, and the
    interpreter's shutdown (module teardown, exit handlers) is skipped.  Every worker has ended already."""
    import shutil

    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass
    paths = [str(Path(s.path).parent) for s in _LEFT_TO_REMOVE]
    paths += _temporary_folders()
    if paths:
        try:
            pid = os.fork() if hasattr(os, "fork") else -1  # no fork (Windows): removed here, before leaving
        except OSError:
            pid = -1
        if pid == 0:  # the remover: detached from the terminal and from whoever waits for the command's output
            try:
                os.setsid()
                null = os.open(os.devnull, os.O_RDWR)
                for fd in (0, 1, 2):
                    os.dup2(null, fd)
                for path in paths:
                    shutil.rmtree(path, ignore_errors=True)
            finally:
                os._exit(0)
        if pid < 0:
            for path in paths:
                shutil.rmtree(path, ignore_errors=True)
    os._exit(code)


def _temporary_folders() -> list[str]:
    """The process's own temporary folders that exit handlers would remove: the worker's runtime folder and
    hypothesis's home, where they were made."""
    folders = []
    launch = sys.modules.get("grader.sandbox.launch")
    if launch is not None and launch.runtime_dir.cache_info().currsize:
        folders.append(str(launch.runtime_dir()))
    oracle = sys.modules.get("grader.oracle")
    if oracle is not None and oracle._HYPOTHESIS_HOME is not None:
        folders.append(str(oracle._HYPOTHESIS_HOME))
    return folders


if __name__ == "__main__":
    sys.exit(main())
