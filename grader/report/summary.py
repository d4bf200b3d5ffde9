"""The class summary of a batch (``summary.html``): the score distributions, the checks failed most often and the
mistakes diagnosed behind them ("35% of students transposed a matrix (A_BI for A_IB) in problem 6", counted by
family of the vocabulary of diagnoses, ``checks._diagnoses``, each student once per family and problem), the
students whose code errored or timed out, the free-text answers to score, and the gradebook.  It is written from the gradebook's rows (``grader.batch.gradebook.Graded``), without their plots."""

from __future__ import annotations

import statistics
from collections import Counter, defaultdict
from datetime import datetime, timezone

from checks._diagnoses import DIAGNOSES, FAMILIES, names_of

from ..results import Graded, Status, possible, problem_possible, rows_by_student, scored_items
from .environment import environment
from .figures import png

__all__ = ["class_summary", "TROUBLE"]

TROUBLE = (Status.ERROR, Status.TIMEOUT, Status.GRADER_ERROR)


def _now() -> str:
    return datetime.now(timezone.utc).isoformat(timespec="microseconds")


def _png(draw, height: float = 3.4) -> str:
    return png(draw, height)


def _histogram(scores: list[float], top: float, title: str, xlabel: str) -> str:
    def draw(ax):
        edges = [x - 0.5 for x in range(int(top) + 2)] if top <= 25 else 20
        ax.hist(scores, bins=edges, range=None if top <= 25 else (0, top), color="#4c72b0", edgecolor="white")
        ax.set_xlim(-0.5, top + 0.5)
        ax.set_title(title)
        ax.set_xlabel(xlabel)
        ax.set_ylabel("students")
        ax.yaxis.get_major_locator().set_params(integer=True)

    return _png(draw)


def _failure_bars(labels: list[str], rates: list[float]) -> str:
    def draw(ax):
        ax.barh(labels[::-1], [100 * r for r in rates[::-1]], color="#c44e52")
        ax.set_xlim(0, 100)
        ax.set_xlabel("students who did not pass (%)")
        ax.set_title("Checks failed most often")
        ax.tick_params(axis="y", labelsize=8)

    return _png(draw, height=1.2 + 0.32 * len(labels))


def _percent(n: int, total: int) -> str:
    return f"{100 * n / total:.0f}" if total else "0"


def _distributions(graded: list[Graded], images: dict) -> tuple[list[dict], float]:
    """Per problem: statistics and a histogram of the scores; and a histogram of the students' totals."""
    by_problem: dict[int, list[Graded]] = defaultdict(list)
    for g in graded:
        by_problem[g.report.problem].append(g)
    scored = scored_items(graded)
    problems = []
    for number, items in sorted(by_problem.items()):
        scores = [g.report.score for g in items]
        top = max(problem_possible(g.report, scored) for g in items)
        problems.append({
            "number": number, "title": items[0].report.title, "students": len(items), "max": top,
            "mean": statistics.fmean(scores), "median": statistics.median(scores), "min": min(scores),
            "full": sum(1 for s in scores if s >= top), "image": f"problem-{number}",
        })
        images[f"problem-{number}"] = _histogram(scores, top, f"Problem {number}: score distribution", "points")
    students = rows_by_student(graded).values()
    top = max((possible(items, scored) for items in students), default=0.0)
    if students:
        totals = [sum(g.report.score for g in items) for items in students]
        images["totals"] = _histogram(totals, top, "Total score distribution", "points")
    return problems, top


def _family(diagnosis: str) -> str:
    """The family a diagnosis is counted under in the class summary: its names' family (families joined by " or "
    for a diagnosis that could be several); a name the vocabulary does not know (a gradebook of an older grader)
    counts as a family of its own."""
    families: list[str] = []
    for name in names_of(diagnosis):
        family = DIAGNOSES[name].family if name in DIAGNOSES else name
        if family not in families:
            families.append(family)
    return " or ".join(families)


def _phrase(family: str, names: Counter) -> str:
    """How the summary words a family of mistakes: the one diagnosis's phrase when its students all have the same
    one, else the family's phrase and the diagnoses behind it."""
    def words(name: str) -> str:
        known = [DIAGNOSES[n].summary for n in names_of(name) if n in DIAGNOSES]
        return " or ".join(known) if known else f"made the mistake “{name.replace('_', ' ')}”"

    if len(names) == 1:
        return words(next(iter(names)))
    parts = [FAMILIES[f].summary if f in FAMILIES else words(f) for f in family.split(" or ")]
    behind = ", ".join(f"{name.replace('_', ' ')} {count}" for name, count in names.most_common())
    return f"{' or '.join(parts)} ({behind})"


def _failures(graded: list[Graded], images: dict, top: int) -> tuple[list[dict], list[dict]]:
    """The checks that students did not pass, most frequent first (with a bar chart), and the diagnosed mistakes
    behind them, per problem and family of the vocabulary (``checks._diagnoses``): "31% of students transposed ...
    in problem 6", each student counted once per family and problem."""
    checks: dict[str, dict] = {}
    diagnosed: dict[tuple[int, str], dict] = {}
    per_problem = Counter(g.report.problem for g in graded)
    for g in graded:
        for r in g.report.results:
            stat = checks.setdefault(r.check_id, {"check_id": r.check_id, "problem": r.problem, "title": r.title,
                                                  "visibility": r.visibility, "students": 0, "how": Counter()})
            stat["students"] += 1
            if not r.passed:
                stat["how"][r.status.value] += 1
            if r.diagnosis:
                entry = diagnosed.setdefault((r.problem, _family(r.diagnosis)),
                                             {"students": set(), "names": {}, "checks": Counter()})
                entry["students"].add(g.student)
                entry["names"].setdefault(r.diagnosis, set()).add(g.student)
                entry["checks"][r.check_id] += 1
    failing = sorted((c for c in checks.values() if c["how"]), key=lambda c: (-c["how"].total(), c["check_id"]))
    for c in failing:
        c["not_passed"] = c["how"].total()
        c["percent"] = _percent(c["not_passed"], c["students"])
        c["statuses"] = ", ".join(f"{status} {n}" for status, n in c["how"].most_common())
    if failing:
        shown = failing[:top]
        images["failures"] = _failure_bars([c["check_id"] for c in shown],
                                           [c["not_passed"] / c["students"] for c in shown])
    mistakes = []
    for (problem, family), entry in diagnosed.items():
        names = Counter({name: len(students) for name, students in entry["names"].items()})
        mistakes.append({
            "problem": problem, "family": family, "diagnosis": ", ".join(sorted(names)),
            "count": len(entry["students"]), "percent": _percent(len(entry["students"]), per_problem[problem]),
            "phrase": _phrase(family, names),
            "checks": [{"check_id": check_id, "title": checks[check_id]["title"], "count": n,
                        "percent": _percent(n, checks[check_id]["students"])}
                       for check_id, n in sorted(entry["checks"].items(), key=lambda item: (-item[1], item[0]))]})
    mistakes.sort(key=lambda m: (-m["count"], m["problem"], m["family"]))
    return failing, mistakes


def _trouble(graded: list[Graded]) -> list[dict]:
    """The results in which the student's code errored or timed out, or that the batch stopped; a submission that
    could not be loaded once, with the problems it stopped (the reason is the same for every problem)."""
    trouble, unloadable = [], {}
    for g in graded:
        if g.report.load_error:
            key = (g.student, g.report.load_error)
            if key in unloadable:
                unloadable[key]["numbers"].append(g.report.problem)
                continue
            message = g.report.load_error.strip()
            unloadable[key] = row = {
                "student": g.student, "numbers": [g.report.problem], "outcome": g.outcome,
                "statuses": "could not be loaded", "message": message.splitlines()[0] if message else "",
            }
            trouble.append(row)
            continue
        bad = [r for r in g.report.results if r.status in TROUBLE]
        if bad or g.outcome != "graded":
            message = bad[0].message.strip() if bad else ""
            trouble.append({
                "student": g.student, "numbers": [g.report.problem], "outcome": g.outcome,
                "statuses": ", ".join(sorted({r.status.value for r in bad})),
                "message": message.splitlines()[0] if message else "",
            })
    for row in trouble:
        row["problem"] = _ranges(sorted(row.pop("numbers")))
    return trouble


def _ranges(numbers: list[int]) -> str:
    """Problem numbers as runs: "1–5, 8, 10–12"."""
    runs: list[list[int]] = []
    for n in numbers:
        if runs and n == runs[-1][-1] + 1:
            runs[-1].append(n)
        else:
            runs.append([n])
    return ", ".join(f"{r[0]}–{r[-1]}" if len(r) > 2 else ", ".join(map(str, r)) for r in runs)


def _versions(graded: list[Graded]) -> dict:
    """The grader's versions, folded: the releases (what a reader needs), and per problem the versions of its
    checks (a digest each), flagging a problem whose students were graded by different versions of its checks."""
    by_problem: dict[int, Counter] = defaultdict(Counter)
    for g in graded:
        by_problem[g.report.problem][g.grader_version] += 1
    return {
        "releases": sorted({version.split("+")[0] for version in (g.grader_version for g in graded)}),
        "problems": [{"number": n, "versions": dict(sorted(c.items()))} for n, c in sorted(by_problem.items())],
        "mixed": [n for n, c in sorted(by_problem.items()) if len(c) > 1],
    }


def class_summary(graded: list[Graded], top_checks: int = 12, top_mistakes: int = 8,
                  generated: str | None = None) -> str:
    """The class summary (HTML): score distributions, the checks failed most often and their diagnoses, the
    students whose grading errored or timed out, the free-text answers to score, and the gradebook; ``generated``:
    when, as the gradebook writes times (default: now)."""
    images: dict[str, str] = {}
    problems, possible = _distributions(graded, images)
    failing, mistakes = _failures(graded, images, top_checks)
    table = [{"student": name, "scores": {g.report.problem: g.report.score for g in items},
              "total": sum(g.report.score for g in items)} for name, items in rows_by_student(graded).items()]
    trouble = _trouble(graded)
    return environment("html").get_template("class_summary.html.j2").render(
        generated=generated or _now(), students=len(table), problems=problems, numbers=[p["number"] for p in problems],
        problem_runs=_ranges([p["number"] for p in problems]),
        possible=possible, images=images, failing=failing, mistakes=mistakes, top_mistakes=top_mistakes,
        trouble=trouble, trouble_students=len({t["student"] for t in trouble}), version=_versions(graded),
        answers=[{"student": g.student, "item": m} for g in graded for m in g.report.manual], table=table,
        sandboxes=sorted({g.report.sandbox for g in graded if not g.report.isolated}),
    )
