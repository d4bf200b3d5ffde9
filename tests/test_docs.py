"""The front door and the guides: the README is short and leads to the guides, every link among them lands on a
file and a heading that exist, the architecture page names files that exist, and its problem index is current."""

import re
import subprocess
import sys
from pathlib import Path

import pytest

from tools.problem_index import DOCUMENT, current, problem_row, render

ROOT = Path(__file__).resolve().parents[1]
GUIDES = ["docs/students.md", "docs/instructors.md", "docs/authoring.md", "docs/architecture.md"]
PAGES = ["README.md", *GUIDES]
#: a link of markdown: [text](target)
LINK = re.compile(r"\[[^\]\n]*\]\(([^)\s]+)\)")


def _slug(heading: str) -> str:
    """The anchor a forge gives a heading: lower case, punctuation but hyphens and underscores dropped, spaces to
    hyphens."""
    text = heading.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def _anchors(path: Path) -> set[str]:
    text = re.sub(r"```.*?```", "", path.read_text(encoding="utf-8"), flags=re.S)
    return {_slug(line.lstrip("#")) for line in text.splitlines() if line.startswith("#")}


def test_the_readme_is_a_front_door():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    assert len(text.splitlines()) < 100
    lines = text.splitlines()
    assert lines[2].split("#")[0].strip() == "pip install -e . && grade demo"
    assert lines[3].split("#")[0].strip() == 'pip install -e ".[dev]" && pytest'
    for heading in ("## A student", "## An instructor", "## A course author", "## Read on"):
        assert heading in lines
    linked = set(LINK.findall(text))
    for guide in GUIDES:
        assert guide in linked and (ROOT / guide).is_file(), guide


def test_ci_runs_the_readmes_test_command():
    command = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()[3].split("#")[0].strip()
    script = [line.strip() for line in (ROOT / ".ci" / "run").read_text().splitlines()]
    assert command in script


@pytest.mark.parametrize("page", PAGES)
def test_every_link_lands(page):
    path = ROOT / page
    broken = []
    for target in LINK.findall(path.read_text(encoding="utf-8")):
        if re.match(r"[a-z]+://", target):
            continue
        file, _, anchor = target.partition("#")
        landing = (path.parent / file).resolve() if file else path
        if not landing.exists():
            broken.append(target)
        elif anchor and anchor not in _anchors(landing):
            broken.append(target)
    assert not broken, f"{page}: links that land nowhere: {broken}"


def test_the_architecture_page_names_files_that_exist():
    text = DOCUMENT.read_text(encoding="utf-8")
    named = set(re.findall(r"`((?:grader|checks|probes|reference|tools|tests)/[\w/.]+?)`", text))
    assert "grader/runner.py" in named and "grader/sandbox/" in named
    missing = sorted(name for name in named if "NN" not in name and not (ROOT / name).exists())
    assert not missing, f"docs/architecture.md names what is not there: {missing}"


def test_the_architecture_page_answers_a_newcomers_questions():
    text = " ".join(DOCUMENT.read_text(encoding="utf-8").split())
    assert "A probe runs in two places" in text
    assert "A verdict is decided in the check function" in text
    assert "A new output format" in text


def test_the_problem_index_is_current():
    assert current(DOCUMENT.read_text(encoding="utf-8")) == render(), "run: python -m tools.problem_index"
    done = subprocess.run([sys.executable, "-m", "tools.problem_index", "--check"], cwd=ROOT, capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr


def test_the_problem_index_follows_what_the_checks_use():
    """Problem 22's row: its reference module and the library it is built on, its checks and the shared ones they
    import, and the probes they call, including those of another problem (21's, by the arm's shared checks)."""
    row = problem_row(22)
    assert row["title"] == ["Recursive Kinematics"]
    assert row["reference"][0] == "problem_22" and "planar" in row["reference"]
    assert row["checks"][0] == "problem_22" and "_planar" in row["checks"]
    assert row["probes"][0] == "problem_22" and "problem_21" in row["probes"]
    assert problem_row(23) is None  # reading only
