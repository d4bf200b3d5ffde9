"""``grade list`` reads the problems' metadata from a cache keyed by the check sources: it imports no check module
(nor numpy) while the checks are unchanged, and lists what importing them lists."""

import json
import os
import subprocess
import sys

from grader.problems import problems

from .submissions import ROOT

PROBE = ("import sys; from grader.cli import main; main(['list']); "
         "print('IMPORTED', sorted(m for m in sys.modules if m.startswith('checks.') or m == 'numpy'))")


def list_in_subprocess(cache) -> tuple[str, list]:
    env = {**os.environ, "GRADER_CACHE": str(cache)}
    done = subprocess.run([sys.executable, "-c", PROBE], cwd=ROOT, env=env, capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    listing, _, imported = done.stdout.rpartition("IMPORTED ")
    return listing, json.loads(imported.replace("'", '"'))


def test_grade_list_imports_no_check_module_once_cached(tmp_path):
    first, imported_first = list_in_subprocess(tmp_path)
    second, imported_second = list_in_subprocess(tmp_path)
    assert first == second
    assert imported_first and imported_second == []  # computed once, then read from the cache
    infos = problems()
    assert f"{len(infos)} problems have checks; {sum(p.points for p in infos):g} points" in second
    for info in infos:
        assert f"{info.title}" in second


def test_the_readme_states_what_grade_list_lists():
    """The README's count of graded problems, their automatic points and the problems without checks are
    those of the check modules."""
    import re

    text = " ".join((ROOT / "README.md").read_text().split())
    infos = problems()
    numbers = {p.number for p in infos}
    stated = re.search(r"Of the course's 47 problems in seven exercises, (\d+) are graded \((\d+) points by automatic "
                       r"checks.*?\); (\d+) and (\d+) are reading only", text)
    assert stated, "the README no longer states the problem count"
    graded, points, *reading = (int(x) for x in stated.groups())
    assert graded == len(infos)
    assert points == round(sum(p.points for p in infos))
    assert set(reading) == set(range(1, 48)) - numbers


def test_a_cache_that_cannot_be_replaced_leaves_nothing_behind(tmp_path, monkeypatch):
    """On Windows, replacing a file that another process has open fails (another ``grade list`` reading the
    cache): the list is still given, and the temporary file is not left in the cache's folder."""
    from grader import listing

    def refused(src, dst):
        raise PermissionError(13, "The process cannot access the file because it is being used by another process")

    monkeypatch.setenv("GRADER_CACHE", str(tmp_path))
    monkeypatch.setattr(os, "replace", refused)
    assert [p["number"] for p in listing.problem_list()] == [info.number for info in problems()]
    assert [p.name for p in tmp_path.rglob("*") if p.is_file()] == []
