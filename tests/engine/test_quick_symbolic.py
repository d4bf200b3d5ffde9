"""The formula tier screens a symbolic answer's mutants cheaply: without sympy's simplifications, and with the
expressions read by ``probes._symbolic.quick`` rather than compiled by sympy's ``lambdify``.

* The quick reading gives sympy's values (up to rounding) and hands what it does not know to sympy; an answer read
  by its symbols' names gives the values of its symbols replaced by plain ones, without the replacing.
* A simplifier's call is replaced by what it simplifies, a simplifier passed as a value by the identity; a call
  that may be no sympy's is left as it is.
* Problem 40's mutants, screened so, give the values they give as they are; the slips of the functions its module
  gives whole (``particle_positions``) are screened as the regions' are.
"""

import ast
import textwrap

import numpy as np
import pytest
import sympy as sp

from grader.checking import Tol
from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, Source, array_of
from probes._symbolic import lambdify, named, quick

x, y = sp.symbols("x y", real=True)


def test_the_quick_reading_gives_sympys_values():
    matrix = sp.Matrix([[sp.Rational(1, 3) * x ** 2 - sp.pi * sp.sin(x * y), sp.sqrt(x) / y],
                        [sp.atan2(y, x) + sp.exp(-x), sp.Abs(y) * sp.cos(x + y) ** 3]])
    expected = sp.lambdify([x, y], matrix, "numpy")
    with quick():
        read = lambdify([x, y], matrix, "numpy")
    assert read is not expected and "lambdifygenerated" not in getattr(read, "__code__").co_filename
    for point in ((0.7, -1.3), (2.5, 0.4), (1e-3, 3.0)):
        assert np.allclose(read(*point), expected(*point), rtol=1e-13, atol=1e-13)
    assert np.asarray(read(0.7, -1.3)).shape == (2, 2)


def test_what_the_quick_reading_does_not_know_is_sympys():
    piecewise = sp.Piecewise((x, x > 0), (-y, True))
    with quick():
        function = lambdify([x, y], piecewise, "numpy")
    assert "lambdifygenerated" in function.__code__.co_filename
    assert function(-1.0, 2.0) == -2.0


def test_an_answer_read_by_its_symbols_names_is_the_plain_answers():
    plain_x = sp.Symbol("x")
    length = sp.Symbol("l", positive=True)
    matrix = sp.Matrix([x * plain_x + length * sp.sin(y), sp.cos(x) - plain_x ** 2 / length])
    expected = named(("x", "y", "l"), matrix)
    assert "lambdifygenerated" in expected.__code__.co_filename
    with quick():
        read = named(("x", "y", "l"), matrix)
        unknown = named(("x", "l"), matrix)  # y is no argument: sympy's lambdify, whose function cannot use it
    assert "lambdifygenerated" not in read.__code__.co_filename
    for point in ((0.7, -1.3, 2.0), (2.5, 0.4, 0.3)):
        assert np.allclose(read(*point), expected(*point), rtol=1e-13, atol=1e-13)
        a, b, c = point
        assert np.allclose(np.ravel(read(*point)), [a * a + c * np.sin(b), np.cos(a) - a * a / c], rtol=1e-13)
    assert "lambdifygenerated" in unknown.__code__.co_filename
    with pytest.raises(TypeError):
        unknown(0.7, 2.0)


SOURCE = textwrap.dedent('''
    def f():
        import sympy as sp
        a = sp.trigsimp(sp.expand(e), method="fu")
        b = M.simplify()
        c = M.applyfunc(sp.simplify)
        d = e.factor(x)
        return a, b, c, d
''')


def test_a_simplification_is_left_out_and_a_foreign_call_kept():
    node = ast.parse(SOURCE).body[0]
    unsimplified = mutants._Unsimplified(mutants._sympy_names([node]))
    text = ast.unparse(unsimplified.visit(node))
    assert unsimplified.changed
    assert "a = e" in text and "b = M\n" in text and "M.applyfunc(lambda _expression" in text
    assert "d = e.factor(x)" in text and "trigsimp" not in text and "simplify" not in text


@pytest.fixture(scope="module")
def problem_40():
    root, package = mutants._package()
    twins = mutants._twins(package, root, 40)
    assert [holder.__name__ for holder, _ in twins] == ["equations_of_motion_symbolic"]
    return root, package, twins


def test_problem_40s_mutants_screened_give_their_own_values(problem_40):
    root, package, twins = problem_40
    rng = np.random.default_rng(4)
    names = ("q1", "q2", "dq1", "dq2", "l1", "l2", "m1", "m2", "g")
    args = mutants._kept_once(([{n: float(v) for n, v in zip(names, rng.uniform(0.3, 1.7, 9))}],))
    made = mutants.mutants_of(package, root, 40, "problem_40.evaluate", args, twins)
    assert made and all(m.quick is not None for m in made if m.slip != "parameter")
    (holder, twin), = twins
    own = holder.__code__
    compared = 0
    try:
        for mutant in made[::12]:  # a few of them: each as it is costs a quarter of a second
            holder.__code__ = mutant.code
            try:
                slow = mutants._call(package, "problem_40.evaluate", args, ("M",))
            except Exception:  # noqa: BLE001 - a mutant that raises is dropped either way
                continue
            holder.__code__ = mutant.quick or mutant.code
            fast = mutants._call(package, "problem_40.evaluate", args, ("M",), quick=True)
            if slow is None:  # a mutant whose answer holds no numbers gives none either way, and is dropped
                assert fast is None, mutant.slip
                continue
            assert fast is not None and np.allclose(fast, slow, rtol=1e-9, atol=1e-9), mutant.slip
            compared += 1
    finally:
        holder.__code__ = own
    assert compared >= 3


def test_problem_40s_given_functions_are_screened_too(problem_40, monkeypatch):
    """A value no slip gives (the mass matrix a third larger) runs through the regions' slips and then the given
    functions' (``particle_positions``, ``symbols``): both screened with the simplifications left out, and nothing
    is named."""
    root, package, twins = problem_40
    names = ("q1", "q2", "dq1", "dq2", "l1", "l2", "m1", "m2", "g")
    screened, evaluate = [], mutants._evaluate

    def spy(package, found, *args, **keywords):
        screened.append(({m.function for m in found}, bool(keywords.get("twins"))))
        return evaluate(package, found, *args, **keywords)

    monkeypatch.setattr(mutants, "_evaluate", spy)
    evidences = []
    for values in ((0.3, 0.7, 1.1, -0.4, 1.0, 0.8, 1.5, 0.9, 9.81), (-0.5, 1.2, 0.2, 0.6, 1.3, 0.6, 0.7, 2.0, 9.81)):
        args = ([dict(zip(names, values))],)
        expected = array_of(mutants._call(package, "problem_40.evaluate", args, ("M", 0)))
        evidences.append(Evidence(1.3 * expected, expected, Tol("tight", 1e-9, 1e-9), "M",
                                  source=Source("problem_40.evaluate", args, ("M", 0))))
    kept = mutants._kept(40, evidences)
    assert not kept
    assert ({"equations_of_motion_symbolic"}, True) in screened, screened
    assert ({"particle_positions", "symbols"}, True) in screened, screened
