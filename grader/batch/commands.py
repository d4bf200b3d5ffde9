"""The batch commands: ``grade batch``, ``grade import-manual`` and ``grade export`` (their parsers and what they
run).  Nothing heavy is imported until a command runs."""

from __future__ import annotations

import sys
from pathlib import Path

__all__ = ["add_batch_parser", "cmd_batch", "cmd_import_manual", "cmd_export"]


def cmd_batch(args) -> int:
    from ..errors import EXIT_GRADER, EXIT_OK, EXIT_USAGE, SubmissionError
    from ..problems import NoChecks, require_problem
    from ..sandbox import Limits
    from ..terminal import say
    from .cluster import ClusterRefused, Credentials
    from .course import CourseError
    from .discover import BAD_NAME
    from .lms import RosterError
    from .run import BatchLocked, NotInstructorInstallation, instructor_installation, run_batch

    refused = instructor_installation()
    if refused is not None:  # before anything is looked at: the kit cannot grade a class
        print(f"error: {refused}", file=sys.stderr)
        return EXIT_USAGE
    try:
        for number in args.problems or ():
            require_problem(number)
    except NoChecks as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    try:
        course = batch_course(args)
    except CourseError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    problems = args.problems or (course.problems if course is not None else None)
    defaults = Limits()
    limits = Limits(
        call_timeout=args.timeout or defaults.call_timeout,
        import_timeout=args.import_timeout or defaults.import_timeout,
    )
    credentials = Credentials(args.tls_ca_file, args.tls_cert, args.tls_key, args.insecure)
    if args.cluster is None and (any(credentials.files) or credentials.insecure):
        say("error: --tls-ca-file, --tls-cert, --tls-key and --insecure are options of --cluster ADDRESS")
        return EXIT_USAGE
    try:
        report = run_batch(args.submissions, args.out, problems=problems, jobs=args.jobs, force=args.force,
                           limits=limits, student_timeout=args.student_timeout, progress=not args.quiet,
                           no_sandbox=args.no_sandbox, cluster=args.cluster, course=course,
                           credentials=credentials)
    except (SubmissionError, BatchLocked, NotInstructorInstallation, CourseError, RosterError,
            ClusterRefused) as exc:
        say(f"error: {exc}")
        return EXIT_USAGE
    except RuntimeError as exc:  # the workers cannot start: a broken installation
        say(f"error: {exc}")
        return EXIT_GRADER
    except OSError as exc:  # the Dask scheduler cannot be reached
        print(f"error: the Dask cluster {args.cluster} cannot be reached: {exc}", file=sys.stderr)
        return EXIT_USAGE
    for name in report.ignored:
        why = "" if name.endswith(BAD_NAME) else " (not a folder, a .zip archive or a .ipynb notebook)"
        say(f"note: ignored {name}{why}")
    print(report.end_line, file=sys.stderr)
    for name, reason in report.not_graded.items():
        say(f"  not graded: {name}: {reason}")
    if report.interrupted:
        print("interrupted: every student graded so far is saved; rerun the same command to finish.",
              file=sys.stderr)
        return 130
    for note in report.notes:
        say(note)
    print(f"results in {args.out}/: grades.csv, summary.html, manual_answers.csv, students/NAME/", file=sys.stderr)
    return EXIT_GRADER if report.not_graded else EXIT_OK


def batch_course(args):
    """The course of a batch: --course FILE, else SUBMISSIONS/course.toml where there is one, else none."""
    from ..listing import problem_list
    from .course import COURSE_FILE, load_course, roster_times

    path = args.course or (Path(args.submissions) / COURSE_FILE)
    if args.course is None and not path.is_file():
        return None
    course = load_course(path, {p["number"] for p in problem_list()})
    roster_times(course)  # a roster of submission times that cannot be read is said before anyone is graded
    return course


def cmd_import_manual(args) -> int:
    from ..errors import EXIT_OK, EXIT_USAGE
    from .course import CourseError
    from .exports import export_results
    from .gradebook import GRADEBOOK_NAME, Gradebook, ManualScoreError
    from .lms import RosterError
    from .run import BatchLocked, _locked

    out = Path(args.results)
    if not (out / GRADEBOOK_NAME).exists():
        print(f"error: {out} holds no gradebook (run `grade batch` first)", file=sys.stderr)
        return EXIT_USAGE
    notes = []
    try:
        with _locked(out), Gradebook.in_folder(out) as book:
            with open(args.scores, encoding="utf-8-sig", newline="") as handle:  # csv reads its own line ends
                count = book.import_manual(handle.read(), source=str(args.scores))
            try:
                export_results(out, book, notes=notes)
            except (CourseError, RosterError) as exc:  # the scores are in: the exports wait for the fix
                print(f"imported {count} manual scores, but the exports cannot be written:\nerror: {exc}\nFix it, "
                      f"then run `grade export {out}`.", file=sys.stderr)
                return EXIT_USAGE
    except (ManualScoreError, BatchLocked, OSError, UnicodeDecodeError) as exc:
        print(f"error: {args.scores}: nothing imported:\n{exc}", file=sys.stderr)
        return EXIT_USAGE
    for note in notes:
        print(note, file=sys.stderr)
    print(f"imported {count} manual scores; the exports in {out}/ are updated", file=sys.stderr)
    return EXIT_OK


def cmd_export(args) -> int:
    from ..errors import EXIT_OK, EXIT_USAGE
    from .course import CourseError
    from .exports import LMS_META, RECORDED, export_results
    from .gradebook import GRADEBOOK_NAME, Gradebook
    from .lms import RosterError, read_roster
    from .run import BatchLocked, _locked

    out = Path(args.results)
    if not (out / GRADEBOOK_NAME).exists():
        print(f"error: {out} holds no gradebook (run `grade batch` first)", file=sys.stderr)
        return EXIT_USAGE
    if args.roster and not (args.canvas or args.moodle):
        print("error: --roster names the students of --canvas or --moodle: add the one you export to",
              file=sys.stderr)
        return EXIT_USAGE
    notes = []
    try:
        if args.roster:
            read_roster(args.roster)  # a roster that cannot be read changes nothing
        with _locked(out), Gradebook.in_folder(out) as book:
            for kind in ("canvas", "moodle"):
                if getattr(args, kind):  # written from now on by every export, with this roster
                    book.set_meta(LMS_META[kind], str(Path(args.roster).resolve()) if args.roster else "")
            paths = export_results(out, book, course=args.course or RECORDED, notes=notes)
    except (BatchLocked, CourseError, RosterError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    for note in notes:
        print(note, file=sys.stderr)
    print(f"wrote the exports in {out}/: {', '.join(p.name for p in paths.values())}, students/NAME/",
          file=sys.stderr)
    return EXIT_OK


def add_batch_parser(sub) -> None:
    from ..arguments import positive_int, problem_number

    p = sub.add_parser(
        "batch",
        help="grade every submission of a folder",
        description="Grade every student of a folder (one folder, .zip or .ipynb per student) in parallel into a "
                    "gradebook; an interrupted batch resumes where it stopped when run again.",
    )
    p.add_argument("submissions", help="the folder of submissions")
    p.add_argument("--out", required=True, help="the results folder (gradebook, grades.csv, reports, summary)")
    p.add_argument("--problems", type=problem_number, nargs="+", default=None, metavar="N",
                   help="problems to grade (default: every problem with checks)")
    p.add_argument("--jobs", "-j", type=positive_int, default=None, metavar="N",
                   help="parallel workers (default: the number of CPUs)")
    p.add_argument("--force", action="store_true", help="regrade students whose submission is unchanged")
    p.add_argument("--timeout", type=float, default=None, help="seconds per call of a student's code (default 10)")
    p.add_argument("--import-timeout", type=float, default=None,
                   help="seconds for importing a student's package (default 20)")
    p.add_argument("--student-timeout", type=float, default=None,
                   help="seconds for grading one student in all (default: the import time-out plus twice the call "
                        "time-out per check)")
    p.add_argument("--cluster", default=None, metavar="ADDRESS",
                   help="grade on a Dask cluster: the scheduler's address (tls://host:8786) or scheduler file, or "
                        "local:N for N worker processes on this machine, with TLS and temporary credentials (see "
                        "docs/instructors.md); instead of --jobs")
    p.add_argument("--tls-ca-file", default=None, metavar="PEM",
                   help="the certificate authority of a tls:// cluster (as `dask scheduler --tls-ca-file`)")
    p.add_argument("--tls-cert", default=None, metavar="PEM", help="this client's certificate for a tls:// cluster")
    p.add_argument("--tls-key", default=None, metavar="PEM", help="the key of that certificate")
    p.add_argument("--insecure", action="store_true",
                   help="use a tcp:// cluster without TLS: anyone who reaches its scheduler runs code as its workers' "
                        "user (recorded in the gradebook)")
    p.add_argument("--course", type=Path, default=None, metavar="FILE",
                   help="the course's assignments, due dates, extensions and late policy (default: course.toml in "
                        "the submissions folder, when there is one); its problems are graded unless --problems")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress display")
    p.add_argument("--no-sandbox", action="store_true",
                   help="grade even when bubblewrap is not available: students' code runs as plain processes "
                        "(under unprivileged uids when run as root); recorded in the gradebook and every report")
    p.set_defaults(func=cmd_batch)

    p = sub.add_parser("import-manual", help="merge a CSV of manual scores into a gradebook",
                       description="Merge manual scores (columns student, problem, key, score, optional comment; "
                                   "the file manual_answers.csv with its score column filled in) into the gradebook "
                                   "of RESULTS and update its exports.")
    p.add_argument("results", help="the results folder of `grade batch`")
    p.add_argument("scores", help="the CSV file of scores")
    p.set_defaults(func=cmd_import_manual)

    p = sub.add_parser("export", help="rewrite the exports of a gradebook; grades for Canvas or Moodle",
                       description="Rewrite grades.csv, the class summary and the students' reports from the "
                                   "gradebook of RESULTS, with the assignments' late penalties of the course file "
                                   "(recomputed without grading anyone again); with --canvas or --moodle, also the "
                                   "LMS's grade import file (rewritten by every export from then on).")
    p.add_argument("results", help="the results folder of `grade batch`")
    p.add_argument("--course", type=Path, default=None, metavar="FILE",
                   help="the course file (default: the one the batch used, or course.toml in its submissions folder)")
    p.add_argument("--canvas", action="store_true", help="write RESULTS/canvas.csv for Canvas's gradebook import")
    p.add_argument("--moodle", action="store_true", help="write RESULTS/moodle.csv for Moodle's CSV grade import")
    p.add_argument("--roster", type=Path, default=None, metavar="FILE",
                   help="the LMS's gradebook export (CSV): its students' ids, sections and assignment ids")
    p.set_defaults(func=cmd_export)
