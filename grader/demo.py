"""``grade demo``: grade the bundled sample submissions (the reference, the untouched template, planted
mistakes and hostile code) and print one line per submission."""

from __future__ import annotations

import importlib.util
import sys
import tempfile
import time
from pathlib import Path

from .problems import problems
from .report.environment import environment
from .report.gradescope_results import render_results
from .report.html import render_html
from .report.text import render_terminal
from .results import Status
from .runner import grade_submission
from .workers import Fresh
from .sandbox import Limits, sandbox_mode

PROJECT_ROOT = Path(__file__).resolve().parents[1]
#: planted mistakes and hostile submissions shown by the demo
PLANTED = ("p06-cardan-rotation-order", "p06-R3-transpose", "p07-omega-body-in-inertial-frame",
           "p08-exponential-is-euler", "p09-get-transform-transposed", "p10-b-reflection")
HOSTILE = ("syntax_error", "infinite_loop_call", "memory_bomb", "fake_json", "steal_reference_import",
           "terminal_escapes")
#: how much of a failure's first line a row shows, where the failure names no diagnosis (enough for "cannot be
#: graded: frames()['A_IC3'] must be numeric, got ..." to show what it got)
FINDING_LENGTH = 100


def _samples_module():
    path = PROJECT_ROOT / "tests" / "submissions.py"
    if not path.exists():
        raise FileNotFoundError("the sample submissions live in the project's tests/ folder: run `grade demo` "
                                "from a checkout installed with `pip install -e .`")
    spec = importlib.util.spec_from_file_location("_grader_samples", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def _finding(reports) -> str:
    for report in reports:
        for r in report.results:
            if r.status in (Status.FAILED, Status.ERROR, Status.TIMEOUT) and r.visibility == "visible":
                detail = r.diagnosis or r.message.splitlines()[0][:FINDING_LENGTH]
                return f"P{report.problem} {r.status.value}: {detail}"
    if all(r.status is Status.NOT_IMPLEMENTED or r.status is Status.SKIPPED
           for report in reports for r in report.results):
        return "not implemented yet (0 points, clear messages)"
    return "all checks passed"


def run_demo(args) -> int:
    samples = _samples_module()
    numbers = args.problems or [p.number for p in problems() if p.number <= 10]
    limits = Limits(call_timeout=3.0, import_timeout=5.0, memory_mb=1024)
    rows = []
    out = Path(args.out) if args.out else None
    with tempfile.TemporaryDirectory(prefix="grade-demo-") as tmp:
        tmp = Path(tmp)
        builds = [("reference", lambda d: samples.copy_reference(d)),
                  ("template (untouched)", lambda d: samples.copy_template(d))]
        planted = {m.name: m for m in samples.planted_mistakes()}
        builds += [(f"planted: {name}", lambda d, m=planted[name]: samples.build_planted(m, d))
                   for name in PLANTED if name in planted]
        builds += [(f"hostile: {name}", lambda d, n=name: samples.build_hostile(n, d))
                   for name in HOSTILE if name in samples.hostile_names()]
        for index, (name, build) in enumerate(builds):
            start = time.perf_counter()
            path = build(tmp / f"s{index}")
            reports = grade_submission(path, numbers, seed=2024, workers=Fresh(limits))
            rows.append({
                "name": name,
                "scores": [f"{r.score:g}/{r.auto_max_score:g}" for r in reports],
                "total": f"{sum(r.score for r in reports):g}/{sum(r.auto_max_score for r in reports):g}",
                "finding": _finding(reports),
            })
            print(f"  graded {name} in {time.perf_counter() - start:.1f} s", file=sys.stderr)
            if out:
                slug = name.replace(": ", "-").replace(" ", "_").replace("(", "").replace(")", "")
                (out / slug).mkdir(parents=True, exist_ok=True)
                (out / slug / "report.txt").write_text(render_terminal(reports))
                (out / slug / "report.html").write_text(render_html(reports, title=f"Demo: {name}"))
                (out / slug / "results.json").write_text(render_results(reports))
    text = environment("terminal").get_template("demo.txt.j2").render(
        rows=rows, width=max(len(r["name"]) for r in rows) + 2, problems=numbers, sandbox=sandbox_mode().note, out=out)
    print(text.rstrip("\n"))
    return 0
