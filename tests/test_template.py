"""The student template is generated from the reference, is current, keeps the public API, and grades to 0."""

import ast
import subprocess
import sys
from pathlib import Path

import pytest

from grader import grade_submission
from grader.problems import problems
from grader.results import Status
from tools.make_template import TemplateError, answers_template, reference_only, strip_reference_only, stub_source

ROOT = Path(__file__).resolve().parents[1]


def test_template_is_current():
    done = subprocess.run([sys.executable, "-m", "tools.make_template", "--check"], cwd=ROOT,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def test_the_template_package_says_what_it_is():
    """The template's package docstring is its own: a student's package to fill in, not the reference solution."""
    template = ast.get_docstring(ast.parse((ROOT / "student_template" / "__init__.py").read_text()))
    reference = ast.get_docstring(ast.parse((ROOT / "reference" / "__init__.py").read_text()))
    assert reference.startswith("Reference solution")
    assert "Reference solution" not in template and "NotImplementedError" in template
    assert "answers.toml" in template and "grade problem-6" in template


def _api(source: str) -> dict:
    """Public names and signatures: module __all__, functions, classes and their methods."""
    tree = ast.parse(source)
    api = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets):
            api["__all__"] = ast.literal_eval(node.value)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            api[node.name] = ast.dump(node.args)
        elif isinstance(node, ast.ClassDef):
            api[node.name] = [ast.dump(b) for b in node.bases]
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    api[f"{node.name}.{item.name}"] = ast.dump(item.args)
    return api


#: the reference's modules that the template has (the others are reference-only as a whole)
SHARED = sorted(p.name for p in (ROOT / "reference").glob("*.py") if not reference_only(p.read_text()))
#: the reference's modules that are reference-only from their first line to their last
REFERENCE_ONLY = sorted(p.name for p in (ROOT / "reference").glob("*.py") if reference_only(p.read_text()))


@pytest.mark.parametrize("name", SHARED)
def test_public_names_and_signatures_match(name):
    reference = strip_reference_only((ROOT / "reference" / name).read_text())
    assert _api(reference) == _api((ROOT / "student_template" / name).read_text())


def test_a_reference_only_module_is_left_out_whole():
    """The tree's deliberately wrong recursions are the grader's alone: the template has no such module, and no
    module of the template (nor of the reference that the template copies) imports one."""
    assert REFERENCE_ONLY == ["tree_mistakes.py"]
    assert not [name for name in REFERENCE_ONLY if (ROOT / "student_template" / name).exists()]
    for path in (ROOT / "student_template").glob("*.py"):
        imported = {node.module for node in ast.walk(ast.parse(path.read_text()))
                    if isinstance(node, ast.ImportFrom) and node.module}
        assert not imported & {name.removesuffix(".py") for name in REFERENCE_ONLY}, path.name
    assert reference_only('# BEGIN REFERENCE ONLY\n"""Doc."""\nx = 1\n# END REFERENCE ONLY\n')
    assert not reference_only('"""Doc."""\n# BEGIN REFERENCE ONLY\nx = 1\n# END REFERENCE ONLY\n')


def _defined(source: str) -> set[str]:
    """Names bound at the top level of a module."""
    names = set()
    for node in ast.parse(source).body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names |= {n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name)}
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            names |= {(a.asname or a.name).split(".")[0] for a in node.names}
    return names


def test_reference_only_names_stay_out_of_the_public_api():
    for path in (ROOT / "reference").glob("*.py"):
        if path.name in REFERENCE_ONLY:
            continue  # the template leaves the whole module out, its names with it
        public = _api(path.read_text()).get("__all__", [])
        kept = _defined(strip_reference_only(path.read_text()))
        assert not [n for n in public if n not in kept], path.name


def test_reference_only_blocks_are_dropped():
    source = "x = 1\n# BEGIN REFERENCE ONLY\ndef key():\n    return 4\n# END REFERENCE ONLY\ny = 2\n"
    assert stub_source(source) == "x = 1\ny = 2\n"
    with pytest.raises(TemplateError):
        stub_source("# BEGIN REFERENCE ONLY\nx = 1\n")


def test_no_solution_survives_in_the_template():
    for path in (ROOT / "student_template").glob("*.py"):
        markers = [line for line in path.read_text().splitlines()
                   if line.strip().startswith(("# BEGIN SOLUTION", "# END SOLUTION"))]
        assert not markers, path.name


def test_untouched_template_scores_zero_with_clear_messages(tmp_path):
    numbers = [p.number for p in problems()]
    reports = grade_submission(ROOT / "student_template", numbers, seed=3)
    for report in reports:
        assert report.score == 0, report.problem
        for r in report.results:
            assert r.status in (Status.NOT_IMPLEMENTED, Status.SKIPPED), (r.check_id, r.status, r.message)
            if r.status is Status.NOT_IMPLEMENTED:
                assert "not implemented yet" in r.message or "not answered yet" in r.message, r.message


def test_stub_replaces_regions_with_named_errors():
    source = (
        "class Body:\n"
        "    def step(self, dt):\n"
        "        \"\"\"Doc.\"\"\"\n"
        "        # BEGIN SOLUTION problem 12\n"
        "        self.x += dt\n"
        "        # END SOLUTION\n"
    )
    stubbed = stub_source(source)
    assert 'raise NotImplementedError("Problem 12: Body.step is not implemented yet")' in stubbed
    assert "self.x += dt" not in stubbed and '"""Doc."""' in stubbed
    ast.parse(stubbed)


@pytest.mark.parametrize("source", [
    "def f():\n    # BEGIN SOLUTION problem 1\n    return 1\n",
    "def f():\n    return 1\n    # END SOLUTION\n",
    "# BEGIN SOLUTION problem 1\nx = 1\n# END SOLUTION\n",
])
def test_malformed_regions_are_refused(source):
    with pytest.raises(TemplateError):
        stub_source(source)


def test_answers_template_blanks_every_answer():
    import tomllib

    blank = tomllib.loads(answers_template('[problem_10]\na = 4\nc = [[1, 0], [0, 1]]\n[problem_10.free_text]\nwhy = "x"\n'))
    assert blank == {"problem_10": {"a": "", "c": "", "free_text": {"why": ""}}}
