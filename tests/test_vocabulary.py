"""One vocabulary of diagnoses (``checks/_diagnoses.py``): every name once with its family and phrases, every name a
check writes held to it, an unknown name refused as the grader's fault, and the class summary counting by family."""

import ast
import tomllib
from pathlib import Path

import pytest

from checks._diagnoses import (
    DIAGNOSES,
    FAMILIES,
    TERMS,
    families_of,
    family_of,
    is_known,
    literal_diagnoses,
    names_of,
    student_phrase,
    summary_phrase,
)
from grader.checking import EXACT, CheckFailure, Mistake, assert_close, check, fail
from grader.errors import GraderFault

ROOT = Path(__file__).resolve().parents[1]
CHECKS = sorted((ROOT / "checks").glob("*.py"))
GRADER = sorted((ROOT / "grader").rglob("*.py"))

#: the families the diagnosis engine's grammar and the checks' catalogues need
REQUIRED_FAMILIES = {
    "transpose", "sign", "order", "scale", "frame", "missing_term", "extra_term", "ignored_argument",
    "initial_state", "time_shift", "offset", "step_size", "event", "state_row", "inverse", "precision",
    "shape", "not_finite", "not_orthonormal", "typed_numbers", "identity", "stub",
}


# ------------------------------------------------------------------------------------------ the table


def test_every_name_has_a_known_family_and_both_phrases():
    assert REQUIRED_FAMILIES <= set(FAMILIES)
    for name, diagnosis in DIAGNOSES.items():
        assert diagnosis.name == name and diagnosis.family in FAMILIES
        assert diagnosis.student.strip() and diagnosis.summary.strip()
        assert family_of(name) == diagnosis.family
    assert len({d.summary for d in DIAGNOSES.values()}) > len(DIAGNOSES) * 0.9  # phrases say which mistake


def test_every_family_has_a_name_and_every_declared_term_its_three_names():
    used = {d.family for d in DIAGNOSES.values()}
    assert used == set(FAMILIES)
    for term in TERMS:
        assert family_of(f"missing_{term}") == "missing_term"
        assert family_of(f"{term}_sign") == "sign"
        assert family_of(f"extra_{term}") == "extra_term"


def test_could_be_x_or_y_has_the_families_of_its_names():
    assert names_of("") == () and family_of("") == ""
    assert names_of("transpose or angle_sign") == ("transpose", "angle_sign")
    assert family_of("transpose or angle_sign") == "transpose or sign"
    assert family_of("gravity_sign or sign_flip") == "sign"  # one family named once
    assert families_of("wrong_frame or transpose or omega_frame") == ("frame", "transpose")
    both = f"{DIAGNOSES['transpose'].student} or {DIAGNOSES['degrees'].student}"
    assert student_phrase("transpose or degrees") == both
    assert summary_phrase("transpose") == DIAGNOSES["transpose"].summary
    assert is_known("transpose or degrees") and not is_known("transpose or sideways")
    with pytest.raises(KeyError):
        family_of("sideways")


def test_the_merged_synonyms_are_gone():
    """One name per cause: the frame, order and term synonyms that split the class summary's counts."""
    for old in ("body_coordinates", "inertial_coordinates", "inertial_frame", "body_frame", "inertial",
                "swapped_names", "swapped_columns", "rows_swapped", "centripetal", "no_centripetal",
                "no_gyroscopic", "no_gravity", "no_bias", "no_mass", "integrator", "coriolis"):
        assert old not in DIAGNOSES, old
    assert family_of("wrong_frame") == "frame" and family_of("swapped") == "order"


# ------------------------------------------------------------------------------------------ refusing unknown names


def test_mistake_fail_and_check_failure_refuse_an_unknown_name_as_the_graders_fault():
    with pytest.raises(GraderFault, match="sideways"):
        Mistake("sideways", 1.0, "hint")
    with pytest.raises(GraderFault, match="transpose or sign_flip"):
        Mistake("transpose or sign_flip", 1.0, "hint")  # a mistake is one cause
    with pytest.raises(GraderFault, match="sideways"):
        fail("message", "hint", "sideways")
    with pytest.raises(GraderFault, match="sideways"):
        CheckFailure("message", "hint", "transpose or sideways")
    with pytest.raises(CheckFailure):
        fail("message", "hint", "transpose or angle_sign")
    with pytest.raises(CheckFailure) as caught:
        assert_close([2.0], [1.0], "x", EXACT, [Mistake("factor_two", [2.0], "twice")])
    assert caught.value.diagnosis == "factor_two"


def test_a_check_that_names_an_unknown_diagnosis_is_a_grader_error_not_a_failure():
    from grader.results import Status
    from grader.runner import _run_check

    @check(1, title="a check with a typo in its diagnosis")
    def check_typo(ctx):
        fail("the value is wrong", "hint", "tranpose")

    class Ctx:
        oracle = None
        figures = []
        last_seed = None

        def begin(self, check_id):
            pass

    result = _run_check(check_typo.check_spec, Ctx(), 99)
    assert result.status is Status.GRADER_ERROR and "tranpose" in result.message
    assert "not your fault" in result.message and result.score == 0


# ------------------------------------------------------------------------------------------ names in the code


def _helpers() -> dict:
    """Functions of the check modules with a parameter named ``diagnosis``, and its index."""
    found = {}
    for path in CHECKS:
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.FunctionDef):
                arguments = [a.arg for a in node.args.args]
                if "diagnosis" in arguments:
                    found[node.name] = arguments.index("diagnosis")
    return found


def test_the_scanner_finds_every_form_of_a_literal_diagnosis():
    source = '''
def helper(x, hint="", diagnosis=""):
    pass
Mistake("transpose", value, "hint")
Model(name="swapped", hint="...")
fail("message", "hint", "degrees")
fail("message", diagnosis="a" if flag else "b or c")
CheckFailure(message, hint, "shape")
helper(1, "hint", "reflection")
anything(diagnosis="none")
DEGENERATE = "degenerate"
fail("message", "hint", DEGENERATE)
Hypothesis("sign:row:1", "sign_flip", 1, "row 1")
'''
    found = [name for _, name in literal_diagnoses(source)]
    assert sorted(found) == sorted(["transpose", "swapped", "degrees", "a", "b", "c", "shape", "reflection", "none",
                                    "degenerate", "sign_flip"])


def test_every_literal_diagnosis_in_the_checks_is_in_the_table():
    helpers = _helpers()
    assert {"assert_run", "compare_traces"} <= set(helpers)
    unknown, count = [], 0
    for path in CHECKS:
        for line, name in literal_diagnoses(path.read_text(), helpers):
            count += 1
            if name not in DIAGNOSES:
                unknown.append(f"{path.name}:{line}: {name}")
    assert count > 300
    assert not unknown, "diagnoses that are not in checks/_diagnoses.py:\n" + "\n".join(unknown)


def test_every_literal_diagnosis_in_the_grader_is_in_the_table():
    """The grader's own diagnoses (a shape, NaN entries) and the diagnosis engine's hypotheses."""
    unknown, found = [], set()
    for path in GRADER:
        for line, name in literal_diagnoses(path.read_text()):
            found.add(name)
            if name not in DIAGNOSES:
                unknown.append(f"{path.relative_to(ROOT)}:{line}: {name}")
    assert {"shape", "not_finite", "step_size", "time_shift", "state_row"} <= found
    assert not unknown, "diagnoses that are not in checks/_diagnoses.py:\n" + "\n".join(unknown)


def _literal_collection(node, scopes):
    """A dict, list or tuple literal that ``node`` is or names (in the function's scope or the module's; a
    parameter by its default value)."""
    if isinstance(node, (ast.Dict, ast.List, ast.Tuple)):
        return node
    if isinstance(node, ast.Name):
        for scope in scopes:
            for statement in ast.walk(scope):
                if isinstance(statement, ast.Assign) and any(
                        isinstance(target, ast.Name) and target.id == node.id for target in statement.targets):
                    if isinstance(statement.value, (ast.Dict, ast.List, ast.Tuple)):
                        return statement.value
        for scope in scopes:
            for function in ast.walk(scope):
                if not isinstance(function, ast.FunctionDef):
                    continue
                positional = function.args.args[len(function.args.args) - len(function.args.defaults):]
                for parameter, default in zip([*positional, *function.args.kwonlyargs],
                                              [*function.args.defaults, *function.args.kw_defaults]):
                    if parameter.arg == node.id and default is not None and default is not node:
                        return _literal_collection(default, scopes)
    return None


def _position(target, name):
    """The index path of ``name`` inside a loop target (``name`` -> (); ``(name, hint)`` -> (0,))."""
    if isinstance(target, ast.Name):
        return () if target.id == name else None
    if isinstance(target, ast.Tuple):
        for i, element in enumerate(target.elts):
            inner = _position(element, name)
            if inner is not None:
                return (i, *inner)
    return None


def _at(node, path):
    for i in path:
        if not isinstance(node, (ast.Tuple, ast.List)) or len(node.elts) <= i:
            return None
        node = node.elts[i]
    return node


def _resolved(name, function, module):
    """The string constants a variable of a loop over a literal collection takes: ``for name, hint in
    HINTS.items()``, ``[... for name, value, hint in ((...), (...))]``; None when it cannot be told from the code."""
    for node in ast.walk(function):
        loops = [(node.target, node.iter)] if isinstance(node, ast.For) else [
            (g.target, g.iter) for g in getattr(node, "generators", ())]
        for target, iterable in loops:
            path = _position(target, name)
            if path is None:
                continue
            items = isinstance(iterable, ast.Call) and isinstance(iterable.func, ast.Attribute) and \
                iterable.func.attr == "items"
            collection = _literal_collection(iterable.func.value if items else iterable, (function, module))
            if collection is None:
                continue
            if isinstance(collection, ast.Dict):
                rows = [ast.Tuple([k, v]) for k, v in zip(collection.keys, collection.values)] if items else \
                    [ast.Tuple([k]) for k in collection.keys]
                path = path if items else (0, *path)
            else:
                rows = collection.elts
            values = [_at(row, path) for row in rows]
            return [v.value for v in values if isinstance(v, ast.Constant) and isinstance(v.value, str)]
    return None


def test_names_taken_from_literal_tables_are_in_the_table():
    """A diagnosis written as a variable of a loop over a literal table (``for name, hint in HINTS.items()``) is
    held to the vocabulary too; names that come from a probe's reply or a helper's argument are refused when the
    mistake is made (the kit's recording makes every catalogue of the reference)."""
    resolved, unknown = set(), []
    for path in CHECKS:
        module = ast.parse(path.read_text())
        functions = [n for n in ast.walk(module) if isinstance(n, (ast.FunctionDef, ast.Lambda))]
        for function in functions:
            for node in ast.walk(function):
                if not isinstance(node, ast.Call):
                    continue
                called = node.func.id if isinstance(node.func, ast.Name) else getattr(node.func, "attr", None)
                if called == "Mistake" and node.args and isinstance(node.args[0], ast.Name):
                    variable = node.args[0].id
                elif called == "fail" and len(node.args) > 2 and isinstance(node.args[2], ast.Name):
                    variable = node.args[2].id
                else:
                    continue
                names = _resolved(variable, function, module)
                if names is None:
                    continue
                resolved.add((path.name, node.lineno))
                unknown += [f"{path.name}:{node.lineno}: {name}" for name in names if name not in DIAGNOSES]
    assert len(resolved) >= 5
    assert not unknown, "diagnoses that are not in checks/_diagnoses.py:\n" + "\n".join(unknown)


def test_every_planted_diagnosis_is_in_the_table():
    for path in sorted((ROOT / "tests" / "planted").glob("*.toml")):
        for mistake in tomllib.loads(path.read_text()).get("mistake", []):
            assert is_known(mistake.get("diagnosis", "")), (path.name, mistake["name"], mistake["diagnosis"])


# ------------------------------------------------------------------------------------------ the class summary


def test_the_class_summary_counts_a_family_once_per_student_and_names_the_diagnoses():
    from grader.report.summary import class_summary
    from grader.results import Graded
    from grader.results import CheckResult, ProblemReport, Status

    def report(*diagnoses):
        results = tuple(CheckResult(f"p43.c{i}", 43, f"check {i}", Status.FAILED, 0.0, 1.0, "wrong", "",
                                    diagnosis) for i, diagnosis in enumerate(diagnoses))
        return ProblemReport(43, "Problem 43", results)

    graded = [Graded("ann", "h", "v", 1, "now", "graded", report("gravity_sign", "sign_flip")),
              Graded("bob", "h", "v", 1, "now", "graded", report("jacobian_sign", "")),
              Graded("cat", "h", "v", 1, "now", "graded", report("", "transpose")),
              Graded("dan", "h", "v", 1, "now", "graded", report("", ""))]
    html = class_summary(graded)
    assert f"50% of students</strong> {FAMILIES['sign'].summary} (" in html  # ann once, bob: 2 of 4
    assert "gravity sign 1" in html and "jacobian sign 1" in html and "sign flip 1" in html
    assert f"25% of students</strong> {DIAGNOSES['transpose'].summary} in problem 43" in html
