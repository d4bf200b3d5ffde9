"""The formula tier's reads of one name for another of its kind (``grader.diagnosis.mutants``), on a made-up problem: an
angle read where another angle belongs (told as ``wrong_angle``), a parameter read as its default's constant or as its
module's constant of that name (the argument ignored), a gravity read as the Earth's, a slice's axes exchanged (a
transpose), a list of names that starts with its last (entries in the wrong order) and a length taken where its square
belongs; on the reference, a coordinate read where another unpacked with it belongs (a state row) and a number of
another formula of the module typed into one (a factor off).  Each slip is named; a near miss of each (a value that no
single read reproduces) is not told in the slip's family.  The graded mistakes on the reference are in
``tests/engine/names.toml``.
"""

import ast
import importlib

import numpy as np
import pytest

from checks._diagnoses import families_of
from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, Source, array_of

from .stand_ins import made_up_package
from .test_mutants import TIGHT, scene


SOURCE = '''"""A made-up problem of names read for one another."""

import numpy as np

GRAVITY = 3.7
SPAN = 2.0
START0 = np.array([0.5, -0.25])


def R1(x):
    """(given)"""
    return np.array([[1.0, 0.0, 0.0], [0.0, np.cos(x), -np.sin(x)], [0.0, np.sin(x), np.cos(x)]])


def R3(x):
    """(given)"""
    return np.array([[np.cos(x), -np.sin(x), 0.0], [np.sin(x), np.cos(x), 0.0], [0.0, 0.0, 1.0]])


def tilt(phi, theta, v):
    """``R3(theta) R1(phi) v``: angles passed to rotations only."""
    # BEGIN SOLUTION problem 97
    return R3(theta) @ R1(phi) @ v
    # END SOLUTION


def end(q1, q2, d):
    """The end of a link at ``q1 + q2``, and the orientation ``q1`` of the link before it."""
    # BEGIN SOLUTION problem 97
    g_e = q1 + q2
    return np.array([d * np.cos(g_e) + np.cos(q1), d * np.sin(g_e), q1])
    # END SOLUTION


def seat(alpha, gamma, r):
    """A point at radius ``r``, turned by ``alpha`` and lifted by ``gamma``."""
    # BEGIN SOLUTION problem 97
    return np.array([r * np.cos(alpha), r * np.sin(alpha), r * np.sin(gamma)])
    # END SOLUTION


def weight(m, g=GRAVITY):
    """The weight of ``m`` along ``-y``."""
    # BEGIN SOLUTION problem 97
    return np.array([0.0, -m * g, 0.0])
    # END SOLUTION


def sag(load, span):
    """The sag of a beam under a load at its middle, and the load per length."""
    # BEGIN SOLUTION problem 97
    return np.array([load * span**3 / 48.0, load / span])
    # END SOLUTION


def advanced(start, rate, dt):
    """One explicit Euler step from ``start``."""
    # BEGIN SOLUTION problem 97
    start = np.asarray(start, dtype=float)
    return start + dt * rate * start
    # END SOLUTION


def spread(m, r):
    """``m |r|^2``."""
    # BEGIN SOLUTION problem 97
    return np.array([m * (r @ r)])
    # END SOLUTION


def weighted(x, y, phi):
    """The coordinates ``(x, y, phi)`` weighted by 1, 2 and 3."""
    # BEGIN SOLUTION problem 97
    return np.diag([1.0, 2.0, 3.0]) @ np.array([x, y, phi])
    # END SOLUTION


def handed(V):
    """``V`` with its third column negated."""
    # BEGIN SOLUTION problem 97
    V = np.array(V, dtype=float)
    V[:, 2] = -V[:, 2]
    return V
    # END SOLUTION
'''


@pytest.fixture
def made_up(tmp_path, monkeypatch):
    """A package of one made-up problem (97) that the tier mutates in place of the reference."""
    with made_up_package(tmp_path, monkeypatch, SOURCE, 97, "names") as package:
        yield package


def R1(x):
    return np.array([[1.0, 0.0, 0.0], [0.0, np.cos(x), -np.sin(x)], [0.0, np.sin(x), np.cos(x)]])


def R3(x):
    return np.array([[np.cos(x), -np.sin(x), 0.0], [np.sin(x), np.cos(x), 0.0], [0.0, 0.0, 1.0]])


def V(*x):
    return np.array(x, dtype=float)


def made_up_probe(name):
    def probe(pkg, *args):
        return getattr(importlib.import_module(f"{pkg.__name__}.problem_97"), name)(*args)

    return probe


def told(package, name, student, inputs):
    """The names and details the tier tells of ``student``'s values of the made-up ``name``."""
    probe = made_up_probe(name)
    evidences = [Evidence(array_of(student(*args)), array_of(probe(package, *args)), TIGHT, "value",
                          source=Source(probe, args, ())) for args in inputs]
    found = mutants.mutant_slips(scene(f"p97.{name}"), evidences)
    return {h.name for h in found}, [h.detail for h in found]


TILTS = [(0.4, -1.1, V(0.3, 0.8, -0.5)), (1.3, 0.6, V(-0.7, 0.2, 0.9))]
SEATS = [(0.4, -1.1, 2.0), (1.3, 0.6, 0.7)]
WEIGHTS = [(2.0, 9.0), (0.7, 1.6)]
SAGS = [(3.0, 1.5), (0.8, 2.6)]
SPREADS = [(2.0, V(0.3, -0.2, 0.5)), (0.7, V(-0.6, 0.1, 1.4))]
BASES = [(np.array([[0.3, 0.5, -0.2], [0.9, -0.1, 0.4], [0.2, 0.7, 0.8]]),),
         (np.array([[-0.6, 0.1, 0.3], [0.4, 0.2, -0.9], [0.5, -0.8, 0.1]]),)]


def _families(names) -> set:
    return {family for name in names for family in families_of(name)}


def test_an_angle_read_where_another_belongs_is_a_wrong_angle(made_up):
    """An angle passed to a rotation where another belongs (``R1(theta)`` for ``R1(phi)``: an angle by the rotation's
    own use of it), and one read in a sine where another belongs, are told as one angle for another, an order slip;
    a sine of the sum of both angles, which no single read gives, is not."""
    names, details = told(made_up, "tilt", lambda phi, theta, v: R3(theta) @ R1(theta) @ v, TILTS)
    assert names == {"wrong_angle"}, details
    assert any("`tilt` reads one angle where another belongs" in d for d in details)
    names, details = told(made_up, "seat", lambda a, g, r: V(r * np.cos(a), r * np.sin(g), r * np.sin(g)), SEATS)
    assert names == {"wrong_angle"}, details
    names, details = told(made_up, "seat", lambda a, g, r: V(r * np.cos(a), r * np.sin(a + g), r * np.sin(g)),
                          SEATS)
    assert "order" not in _families(names), details


def test_an_angle_read_as_a_sum_of_it_and_more_is_also_a_term_added(made_up):
    """``g_e = q1 + q2`` read where ``q1`` belongs adds ``q2``: told as one angle for another and, beside it, as a
    term added; ``q1`` read where ``g_e`` belongs leaves ``q2`` out: one angle for another and a term left out."""
    ends = [(0.4, -1.1, 2.0), (1.3, 0.6, 0.7)]
    names, details = told(made_up, "end", lambda a, b, d: V(d * np.cos(a + b) + np.cos(a), d * np.sin(a + b), a + b),
                          ends)
    assert names == {"wrong_angle", "extra_term"}, details
    assert any("reads a sum of angles where one of its terms belongs" in d for d in details)
    names, details = told(made_up, "end", lambda a, b, d: V(d * np.cos(a + b) + np.cos(a), d * np.sin(a), a), ends)
    assert names == {"wrong_angle", "missing_term"}, details


def test_a_parameter_read_as_its_default_or_its_modules_constant_is_ignored(made_up):
    """A parameter read as the constant of its default (``GRAVITY`` for ``g``) or as the module's constant of its
    name in capitals (``SPAN`` for ``span``, at one read), or of its name and a number (``START0`` for ``start``)
    ignores the argument there; a value between the argument and the constant is not told as an argument
    ignored."""
    names, details = told(made_up, "weight", lambda m, g: V(0.0, -m * 3.7, 0.0), WEIGHTS)
    assert names == {"ignored_argument"}, details
    assert any("where its argument belongs" in d for d in details)
    names, details = told(made_up, "sag", lambda load, span: V(load * 2.0**3 / 48.0, load / span), SAGS)
    assert names == {"ignored_argument"}, details
    names, details = told(made_up, "sag", lambda load, span: V(load * (span * 2.0)**1.5 / 48.0, load / span),
                          SAGS)
    assert "ignored_argument" not in _families(names), details
    steps = [(V(1.0, 2.0), 0.3, 0.1), (V(-0.4, 0.9), 1.2, 0.05)]
    start = V(0.5, -0.25)  # the module's START0: the value at the start, of the argument's name and a number
    names, details = told(made_up, "advanced", lambda s, rate, dt: s + dt * rate * start, steps)
    assert names == {"ignored_argument"}, details


def test_a_gravity_read_as_the_earths_is_told(made_up):
    """A gravity argument read as 9.81 is the Earth's gravity where another is given (an argument ignored); 9.0 is
    no read of either."""
    names, details = told(made_up, "weight", lambda m, g: V(0.0, -m * 9.81, 0.0), WEIGHTS)
    assert names == {"earth_gravity"}, details
    names, details = told(made_up, "weight", lambda m, g: V(0.0, -m * 9.0, 0.0), WEIGHTS)
    assert "ignored_argument" not in _families(names), details


def test_a_slices_axes_exchanged_is_a_transpose(made_up):
    """``V[2, :] = -V[2, :]`` for ``V[:, 2] = -V[:, 2]`` (a row where the column belongs, on both sides) is a
    transpose; the neighbouring column negated is not."""
    def row(V):
        V = np.array(V, dtype=float)
        V[2, :] = -V[2, :]
        return V

    def column(V):
        V = np.array(V, dtype=float)
        V[:, 1] = -V[:, 1]
        return V

    names, details = told(made_up, "handed", row, BASES)
    assert names == {"transpose"}, details
    assert any("a row of a matrix where its column belongs" in d for d in details)
    names, details = told(made_up, "handed", column, BASES)
    assert "transpose" not in _families(names), details


def test_a_length_where_its_square_belongs_is_a_scale(made_up):
    """``np.sqrt(r @ r)`` for ``r @ r`` is a wrong factor; the cube of the length is not."""
    names, details = told(made_up, "spread", lambda m, r: V(m * np.sqrt(r @ r)), SPREADS)
    assert names == {"wrong_factor"}, details
    names, details = told(made_up, "spread", lambda m, r: V(m * (r @ r) ** 1.5), SPREADS)
    assert "scale" not in _families(names), details


def test_a_list_of_names_that_starts_with_its_last_is_in_the_wrong_order(made_up):
    """``[phi, x, y]`` for ``[x, y, phi]`` is told as entries in the wrong order; ``[phi, y, y]`` is not."""
    weights = np.diag([1.0, 2.0, 3.0])
    names, details = told(made_up, "weighted", lambda x, y, phi: weights @ V(phi, x, y), SEATS)
    assert names == {"swapped"}, details
    assert any("lists quantities in another order" in d for d in details)
    names, details = told(made_up, "weighted", lambda x, y, phi: weights @ V(phi, y, y), SEATS)
    assert "order" not in _families(names), details


def test_the_reads_of_names_are_bounded_and_come_last(made_up):
    """The angles are the names a function reads in a sine or a cosine or passes where a function of the module
    takes one; the reads of names for others are made after every other slip of the function, so that the tier's
    budget reaches the older slips first."""
    functions = {f.path[-1]: f for f in mutants._functions(str(mutants._package()[0]))}
    assert mutants._angles(functions["tilt"]) == {"phi", "theta"}
    assert mutants._angles(functions["seat"]) == {"alpha", "gamma"}
    assert mutants._angles(functions["end"]) == {"g_e", "q1"}
    assert set(mutants._defaults(functions["weight"])) == {"g"}
    assert {ast.unparse(v) for _, v in mutants._defaults(functions["sag"])["span"]} == {"SPAN"}
    for function in functions.values():
        lines = tuple((first, last) for _, first, last in function.regions)
        slips = [slip for slip, *_ in mutants._mutated(function, lines)]
        late = [k for k, slip in enumerate(slips) if slip in mutants.LATE_SLIPS]
        assert not late or late == list(range(late[0], len(slips))), (function.path, slips)


def test_the_reads_of_names_take_only_the_room_the_bound_leaves(made_up, monkeypatch):
    """Where the other slips fill ``MAX_MUTANTS``, the reads of names are left out and the others are all tried
    (not nothing, as where the other slips alone are past the bound)."""
    root, package = mutants._package()
    probe, args = made_up_probe("seat"), SEATS[0]
    every = mutants.mutants_of(package, root, 97, probe, args)
    others = [m for m in every if m.slip not in mutants.LATE_SLIPS]
    assert others and len(others) < len(every)
    monkeypatch.setattr(mutants, "MAX_MUTANTS", len(others))
    assert [m.slip for m in mutants.mutants_of(package, root, 97, probe, args)] == [m.slip for m in others]
    monkeypatch.setattr(mutants, "MAX_MUTANTS", len(others) - 1)
    assert mutants.mutants_of(package, root, 97, probe, args) is None


# ------------------------------------------------------------------------------------------ on the reference


def _reference_slips(tmp_path, check_id, file, old, new, probe, inputs):
    from .test_mutants import slips_of

    return {h.name for h in slips_of(tmp_path, check_id, file, old, new, probe, inputs)}


CHAIN_A = [("a", np.array([0.7, 1.3]), 0.8), ("a", np.array([-0.4, 0.5]), 1.2)]


def test_a_coordinate_read_where_another_unpacked_with_it_belongs_is_a_state_row(tmp_path):
    """Problem 21's chain a, ``q2 + d cos(q2)`` for ``q1 + d cos(q2)`` where ``q1, q2 = q``: one coordinate read from
    another's row (``mutants._unpacked_together``).  The near miss, ``2 q1``, is no read of another coordinate."""
    names = _reference_slips(tmp_path / "a", "p21.chain_a_values", "planar.py", "q1 + d * np.cos(q2)",
                             "q2 + d * np.cos(q2)", "problem_21.chain", CHAIN_A)
    assert names == {"state_row"}, names
    near = _reference_slips(tmp_path / "b", "p21.chain_a_values", "planar.py", "q1 + d * np.cos(q2)",
                            "2 * q1 + d * np.cos(q2)", "problem_21.chain", CHAIN_A)
    assert "state_row" not in near, near


ELLIPSOIDS = [("ellipsoid", 2.0, 0.4, 0.7, 1.1), ("ellipsoid", 3.5, 1.2, 0.3, 0.8)]


def test_a_number_of_another_formula_of_the_module_is_a_factor_off(tmp_path):
    """Problem 16's ellipsoid with ``m / 6``, the six points' share, for ``m / 20``: a number that another formula of
    the module divides by, typed into this one (``mutants._factor_numbers``), a factor off.  The near miss, ``m / 7``,
    is no number of the module: named nothing."""
    old = "return m / 20 * np.diag([b**2 + c**2, a**2 + c**2, a**2 + b**2])"
    names = _reference_slips(tmp_path / "a", "p16.bodies", "inertia.py", old, old.replace("m / 20", "m / 6"),
                             "problem_16.body", ELLIPSOIDS)
    assert names == {"wrong_factor"}, names
    near = _reference_slips(tmp_path / "b", "p16.bodies", "inertia.py", old, old.replace("m / 20", "m / 7"),
                            "problem_16.body", ELLIPSOIDS)
    assert near == set(), near


def test_the_coordinates_unpacked_together_are_those_of_one_vector():
    """Names unpacked from one vector (a name, an index or slice of one, or one converted) are read one for another;
    names bound at once to several values, or unpacked from another call's results (sympy's ``symbols()``), are not:
    each reads a quantity of its own."""
    tree = ast.parse("def f(q, y):\n    q1, q2 = np.asarray(q, dtype=float)\n    x, h, _ = y[:3]\n"
                     "    a, b = f(q), g(y)\n    s, l = symbols()\n    return q1")
    assert mutants._unpacked_together(tree.body[0]) == {"q1": ("q2",), "q2": ("q1",), "x": ("h",), "h": ("x",)}
