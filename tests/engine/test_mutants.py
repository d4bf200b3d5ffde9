"""The diagnosis engine's tier of formulas (``grader.diagnosis.mutants``): one slip at a time in the reference's own
code of the check's problem, kept when it reproduces the student's value on the input shown and on a second one.

* Each operator on the reference: a mistake planted into a copy of the reference gives the "student's" values (the
  copy's probe, in this process), and the tier names the slip's diagnosis and the student's function, never the
  reference's code.
* The rules: an equivalent mutant is no cause; a value that slips of two families give is "could be", of more
  nothing; a mutant that hangs is interrupted within the tier's time and names nothing, one that raises is dropped.
* The cost: an explanation traces the compared call once for all its stages, and a grading that asks the same
  question twice measures it once (a measure that ran out of its time is made again).
* Graded as ``grade batch`` grades (``tests/engine/formulas.toml``): live the check names the slip, the kit (which
  holds no reference code) names the same or nothing and says that the graded submission may say more, and with
  the engine off no catalogue names a cause of that family.
"""

import ast
import gc
import os
import importlib
import itertools
import shutil
import sys
import threading
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from checks._diagnoses import DIAGNOSES
from grader.checking import Tol
from grader.diagnosis import engine as explaining
from grader.diagnosis import mutants
from grader.diagnosis.evidence import Evidence, Source, array_of, at
from grader.private import drop_private, private_import
from probes._codec import decode, encode

from .stand_ins import made_up_package
from ..kit_support import (  # noqa: F401 (fixtures)
    assert_named_live_and_alike,
    graded_table,
)

ROOT = Path(__file__).resolve().parents[2]
TIGHT = Tol("tight", 1e-9, 1e-9)
_NUMBERS = itertools.count()


# ------------------------------------------------------------------------------------------ on the reference


def planted_package(tmp_path: Path, file: str, old: str, new: str):
    """A copy of the reference with one mistake planted, imported in this process under a private name."""
    root = tmp_path / "planted"
    shutil.copytree(ROOT / "reference", root, ignore=shutil.ignore_patterns("__pycache__"))
    text = (root / file).read_text()
    assert text.count(old) == 1, old
    (root / file).write_text(text.replace(old, new))
    return private_import(f"_planted_formula_{next(_NUMBERS)}", root)


def probe_of(name: str):
    module_name, _, func = name.rpartition(".")
    return getattr(importlib.import_module(f"probes.{module_name}"), func)


def evidence(probe: str, args: tuple, path: tuple, student, tol: Tol = TIGHT) -> Evidence:
    """A failing comparison of ``probe(*args)``'s value at ``path``: the student's (the planted copy's) and the
    reference's."""
    import reference

    expected_root = decode(encode(probe_of(probe)(reference, *args)))
    got_root = decode(encode(probe_of(probe)(student, *args)))
    got, expected = array_of(at(got_root, path)), array_of(at(expected_root, path))
    return Evidence(got, expected, tol, "value", source=Source(probe, tuple(args), path, expected_root),
                    student=Source(probe, tuple(args), path, got_root))


def scene(check_id: str, mode: str = "live"):
    return SimpleNamespace(ctx=SimpleNamespace(check_id=check_id, oracle=SimpleNamespace(mode=mode)))


def slips_of(tmp_path, check_id, file, old, new, probe, inputs, path=()):
    student = planted_package(tmp_path, file, old, new)
    try:
        evidences = [evidence(probe, args, path, student) for args in inputs]
        assert all(e.got.shape == e.expected.shape and not np.allclose(e.got, e.expected) for e in evidences)
        return mutants.mutant_slips(scene(check_id), evidences)
    finally:
        drop_private(student)


def V(*x):
    return np.array(x, dtype=float)


ROTATIONS = [Rotation.from_rotvec(v).as_matrix() for v in ([0.3, -0.5, 0.8], [1.1, 0.2, -0.4], [-0.7, 0.9, 0.1],
                                                            [0.2, 0.3, -1.2])]
ARMS = [([0.4, 0.3, 0.7, -0.5], 0.2), ([0.9, -0.8, 0.5, 1.1, 0.3, 0.2], 0.35)]
INERTIA = np.array([[2.0, 0.1, 0.2], [0.1, 3.0, 0.0], [0.2, 0.0, 3.0]])
BEARINGS = [(INERTIA, 10.0, 5.0, 9.81, 0.8), (1.5 * INERTIA, 7.0, 3.0, 9.81, 1.2)]
IMPULSES = [(0.3, -2.0, 1.5, 0.2, 0.4, 0.1), (-0.5, -1.0, 2.5, 0.3, 0.2, 0.3)]
POINTS = [(1.0, 2.0, 0.5, 0.7), (0.3, 1.5, 1.2, 0.4)]
STEINER = [(np.diag([1.0, 2.0, 2.5]), 2.0, V(0.3, -0.2, 0.5)), (np.diag([1.3, 2.6, 3.0]), 0.7, V(-0.6, 0.1, 0.4))]
SPD = np.array([[2.0, 0.3, -0.1], [0.3, 1.5, 0.2], [-0.1, 0.2, 1.0]])
DYNAMICS = [(SPD, V(0.3, -1.0, 0.5), V(0.0, -2.0, 0.1), V(1.0, 0.4, -0.7)),
            (1.5 * SPD + np.eye(3), V(-0.8, 0.2, 1.1), V(0.5, 0.3, -1.2), V(-0.4, 0.9, 0.6))]
CUBOIDS = [("cuboid", 2.0, 0.3, 0.5, 0.7), ("cuboid", 0.8, 1.1, 0.4, 0.6)]
WALKERS = [(0.2, 0.4), (-0.3, 0.1)]

#: (slip, check, file, old, new, probe, inputs, path, diagnosis, the hint's detail)
OPERATORS = [
    ("a term's sign", "p22.loop_values", "planar.py", "y += length * np.cos(gamma)", "y -= length * np.cos(gamma)",
     "problem_22.loop", ARMS, (), "sign_flip", "one term or factor of `end_effector_loop` has the wrong sign"),
    ("a sign inside a quotient", "p18.zero_acceleration", "inertia.py", "float((a_x * r_y - a_y * r_x) / r2)",
     "float((a_y * r_x - a_x * r_y) / r2)", "problem_18.non_accelerating", POINTS, (), "sign_flip",
     "one term or factor of `non_accelerating_point` has the wrong sign"),
    ("the first term of a difference missing", "p19.parallel_axis", "inertia.py",
     "return as_matrix(I_G) + m * ((r @ r) * np.eye(3) - np.outer(r, r))",
     "return as_matrix(I_G) + m * np.outer(r, r)", "problem_19.parallel_axis", STEINER, (), "missing_term",
     "the first term of a difference in `parallel_axis` is left out"),
    ("a term missing", "p19.parallel_axis", "inertia.py",
     "return as_matrix(I_G) + m * ((r @ r) * np.eye(3) - np.outer(r, r))",
     "return m * ((r @ r) * np.eye(3) - np.outer(r, r))", "problem_19.parallel_axis", STEINER, (), "missing_term",
     "one term of a sum in `parallel_axis` is left out"),
    ("a factor missing", "p39.bearing_forces", "problem_39.py", "weight = np.array([0.0, m * g, 0.0])",
     "weight = np.array([0.0, g, 0.0])", "problem_39.bearing_forces", BEARINGS, (0,), "missing_factor",
     "one factor of a product in `bearing_forces` is left out"),
    ("a rotation missing", "p11.test_values", "bound.py", "return self.C.I_r_IC + self.C.A_IC @ self.C_r_CO",
     "return self.C.I_r_IC + self.C_r_CO", "problem_11.vector",
     [(ROTATIONS[0], V(1, 2, 3), V(0.5, -1, 2), V(0.3, 0.2, -0.7)),
      (ROTATIONS[1], V(-1, 0.4, 2), V(1.5, 1, -2), V(-0.3, 0.9, 0.4))], ("I_r_IO",), "wrong_frame",
     "a rotation is left out in `I_r_IO`"),
    ("two arguments of a call", "p43.constrained_system", "problem_43.py", "M = mass_matrix(m, theta)",
     "M = mass_matrix(theta, m)", "problem_43.constrained_system",
     [(V(0.1, 0.5, 0.3), V(0.2, -0.1, 0.4), 2.0, 0.3, 9.81), (V(-0.2, 0.6, -0.4), V(0.5, 0.3, -0.2), 1.2, 0.7, 9.81)],
     ("A",), "argument_order", "two arguments of a call in `constrained_system` are exchanged"),
    ("two names of the function", "p47.impulse", "problem_47.py", "arm = x_cog * np.cos(phi) - y_cog * np.sin(phi)",
     "arm = y_cog * np.cos(phi) - x_cog * np.sin(phi)", "problem_47.impulse", IMPULSES, (), "argument_order",
     "two of the arguments of `impulse` are exchanged"),
    ("the factors of a product", "p09.chain", "cosys.py", "else B.A_IC.T @ self.A_IC", "else self.A_IC @ B.A_IC.T",
     "problem_09.chain", [([ROTATIONS[0], ROTATIONS[1], ROTATIONS[2]],), ([ROTATIONS[3], ROTATIONS[2], ROTATIONS[0]],)],
     ("pairs", 2, 0), "factor_order", "two factors of a product in `get_transform` are multiplied the other way round"),
    ("two entries of a list", "p27.columns", "problem_27.py", "return np.array([ux, uy, 0.0])",
     "return np.array([uy, ux, 0.0])", "problem_27.prismatic_column", [(V(0.6, 0.8),), (V(-0.28, 0.96),)], (),
     "swapped", "two entries that `prismatic_column` builds are exchanged"),
    ("a number halved", "p39.bearing_forces", "problem_39.py", "return 0.5 * (weight - difference), 0.5 * (weight",
     "return 0.25 * (weight - difference), 0.5 * (weight", "problem_39.bearing_forces", BEARINGS, (0,),
     "wrong_factor", "a number in `bearing_forces` is halved"),
    ("a division for a product", "p47.impulse", "problem_47.py", "-m * theta * yd_minus / (m * arm ** 2 + theta)",
     "-m * theta * yd_minus * (m * arm ** 2 + theta)", "problem_47.impulse", IMPULSES, (), "wrong_factor",
     "`impulse` multiplies where it should divide"),
    ("a product for a division", "p47.impulse", "problem_47.py", "-m * theta * yd_minus / (m * arm ** 2 + theta)",
     "-m * theta * yd_minus / (m / arm ** 2 + theta)", "problem_47.impulse", IMPULSES, (), "wrong_factor",
     "`impulse` divides where it should multiply"),
    ("a square missing", "p47.impulse", "problem_47.py", "(m * arm ** 2 + theta)", "(m * arm + theta)",
     "problem_47.impulse", IMPULSES, (), "wrong_factor", "a square is missing in `impulse`"),
    ("a square root missing", "p18.zero_acceleration", "inertia.py", "float(np.sqrt(a_dot_r / r2))",
     "float(a_dot_r / r2)", "problem_18.non_accelerating", POINTS, (), "wrong_factor",
     "a square root is missing in `non_accelerating_point`"),
    ("sin for cos", "p22.loop_values", "planar.py", "x -= length * np.sin(gamma)", "x -= length * np.cos(gamma)",
     "problem_22.loop", ARMS, (), "sin_cos_swapped", "`end_effector_loop` takes sin where cos belongs"),
    ("degrees", "p22.loop_values", "planar.py", "x -= length * np.sin(gamma)",
     "x -= length * np.sin(np.deg2rad(gamma))", "problem_22.loop", ARMS, (), "degrees",
     "`end_effector_loop` takes an angle in degrees"),
    ("a transpose", "p39.inertia_misaligned", "problem_39.py", "return A @ np.asarray(I1, dtype=float) @ A.T",
     "return A @ np.asarray(I1, dtype=float) @ A", "problem_39.inertia_misaligned",
     [(np.diag([1.0, 3.0, 3.0]), 0.05), (np.diag([2.0, 6.0, 6.0]), -0.08)], (), "transpose",
     "a matrix in `inertia_misaligned` is transposed"),
    ("a neighbouring index", "p39.bearing_forces", "problem_39.py", "[0.0, 2.0 * moment[2] / d,",
     "[0.0, 2.0 * moment[1] / d,", "problem_39.bearing_forces", BEARINGS, (0,), "wrong_index",
     "`bearing_forces` reads an entry from a neighbouring index"),
    ("sin and cos exchanged throughout one expression", "p22.loop_values", "planar.py",
     "gamma += angle\n    return np.array([x - d * np.sin(gamma), y + d * np.cos(gamma), gamma])",
     "gamma += angle\n    return np.array([x - d * np.cos(gamma), y + d * np.sin(gamma), gamma])", "problem_22.loop",
     ARMS, (), "sin_cos_swapped", "`end_effector_loop` takes sin where cos belongs and cos where sin belongs"),
    ("an angle returned in degrees", "p22.loop_values", "planar.py",
     "gamma += angle\n    return np.array([x - d * np.sin(gamma), y + d * np.cos(gamma), gamma])",
     "gamma += angle\n    return np.array([x - d * np.sin(gamma), y + d * np.cos(gamma), np.rad2deg(gamma)])",
     "problem_22.loop", ARMS, (), "degrees", "`end_effector_loop` returns an angle in degrees"),
    ("a sum that keeps only its last term", "p22.loop_values", "planar.py", "y += length * np.cos(gamma)",
     "y = length * np.cos(gamma)", "problem_22.loop", ARMS, (), "missing_term",
     "a sum that `end_effector_loop` accumulates keeps only its last term"),
    ("a product where a solve belongs", "p37.forward_dynamics", "dynamics.py", "return np.linalg.solve(M, f + g + tau)",
     "return M @ (f + g + tau)", "_dynamics.forward_dynamics", DYNAMICS, (), "multiplied_not_solved",
     "`forward_dynamics` multiplies by a matrix where it should solve with it"),
    ("a solve left out", "p37.forward_dynamics", "dynamics.py", "return np.linalg.solve(M, f + g + tau)",
     "return f + g + tau", "_dynamics.forward_dynamics", DYNAMICS, (), "no_inverse",
     "`forward_dynamics` leaves out a solve"),
    ("a factor under a minus", "p43.forces", "problem_43.py", "np.array([0.0, -m * g, 0.0])",
     "np.array([0.0, -g, 0.0])", "problem_43.forces", [(2.0, 9.81), (0.7, 3.5)], ("g",), "missing_factor",
     "one factor of a product in `forces` is left out"),
    ("a norm for its square", "p16.cuboid", "inertia.py", "return m / 12 * np.diag([b**2 + c**2,",
     "return m / 12 * np.diag([np.sqrt(b**2 + c**2),", "problem_16.body", CUBOIDS, (), "wrong_factor",
     "`cuboid_inertia` takes a square root of a sum of squares where the sum belongs"),
    ("a rate where the quantity belongs", "p37.torques", "problem_37.py",
     "return M @ qdd_des - f - g + pd_torque(q, qd, q_des, qd_des)",
     "return M @ qdd_des - f - g + pd_torque(q, qd, q_des, qdd_des)", "problem_37.torques",
     [("computed_torques", [(SPD, V(0.3, -1.0, 0.5), V(0.0, -2.0, 0.1), V(0.2, 0.4, -0.1), V(-0.5, 0.3, 0.8),
                              V(0.1, 0.6, -0.2), V(0.9, -0.4, 0.3), V(-1.1, 0.7, 0.5))]),
      ("computed_torques", [(1.5 * SPD + np.eye(3), V(-0.8, 0.2, 1.1), V(0.5, 0.3, -1.2), V(-0.3, 0.2, 0.6),
                              V(0.4, -0.9, 0.1), V(-0.6, 0.2, 0.7), V(0.3, 0.5, -0.8), V(0.6, -0.2, 1.3))])],
     (0,), "state_row", "`computed_torque` reads a quantity where its rate belongs"),
    ("a count for a sum", "p16.second_moments", "inertia.py", "second = 0.5 * (moments.sum() - 2.0 * moments)",
     "second = 0.5 * (len(moments) - 2.0 * moments)", "problem_16.dimensions",
     [(2.0, 0.5, 0.6, 0.7), (0.5, 0.4, 0.5, 0.8)], ("cuboid",), "wrong_factor",
     "`principal_second_moments` divides by the number of entries where their sum belongs"),
    ("a loop that stops one short", "p22.loop_values", "planar.py",
     "for length, angle in np.asarray(q, dtype=float).reshape(-1, 2):",
     "for length, angle in np.asarray(q, dtype=float).reshape(-1, 2)[:-1]:", "problem_22.loop", ARMS, (),
     "missing_term", "a loop in `end_effector_loop` stops one short"),
    ("a loop of steps that starts one late", "p07.animation", "problem_07.py",
     "for _ in range(n):\n        angles = angles", "for _ in range(1, n):\n        angles = angles",
     "_rebound.rebound", [("problem_07.animate", [], []),
                          ("problem_07.animate", [["problem_07", "START_ANGLES", [0.9, 0.6, 0.45]]], [])],
     ("angles",), "step_count", "the loop of steps in `animate` takes one step too few"),
    ("a point's position left out of the keywords, its default used", "p25.sheet_values", "problem_25.py",
     "S_r_SDs=(-DX, DY, 0.0), q_index=[1])", "q_index=[1])", "problem_25.walker", WALKERS, ("x",), "offset",
     "a call in `build_walker` leaves out a point's position among its keyword arguments"),
    ("an argument converted to radians again", "p47.impulse", "problem_47.py",
     "arm = x_cog * np.cos(phi) - y_cog * np.sin(phi)",
     "arm = x_cog * np.cos(np.deg2rad(phi)) - y_cog * np.sin(np.deg2rad(phi))", "problem_47.impulse", IMPULSES, (),
     "degrees", "`impulse` converts an argument to radians that already is in radians"),
    ("a slip in a symbolic answer that its probe computes once per package", "p45.jacobian", "problem_45.py",
     "y * sp.cos(phi) - x * sp.sin(phi) - d,", "y * sp.sin(phi) - x * sp.sin(phi) - d,", "problem_45.evaluate",
     [("J", [dict(s=0.3, l=1.2, d=0.4, m=2.0, theta=0.5, phid=-1.0)]),
      ("J", [dict(s=0.7, l=0.9, d=0.25, m=1.5, theta=0.8, phid=-0.5)])], (0,), "sin_cos_swapped",
     "`impact_jacobian` takes sin where cos belongs"),
]


@pytest.mark.parametrize("operator", OPERATORS, ids=[o[0] for o in OPERATORS])
def test_each_operator_names_its_slip_and_the_students_function(operator, tmp_path):
    _, check_id, file, old, new, probe, inputs, path, diagnosis, detail = operator
    found = slips_of(tmp_path, check_id, file, old, new, probe, inputs, path)
    assert found, "no mutant reproduced the planted slip"
    assert {h.name for h in found} <= set(DIAGNOSES)
    own = [h for h in found if not h.twin]  # a twin reads the same edit another way (``mutants.rivals``)
    assert len({DIAGNOSES[h.name].family for h in own}) == 1, [(h.name, h.detail) for h in found]
    assert {h.name for h in found if h.twin} <= {"reciprocal_argument"}, [(h.name, h.detail) for h in found]
    assert diagnosis in {h.name for h in own}, [(h.name, h.detail) for h in found]
    assert any(detail in h.detail for h in found), [h.detail for h in found]
    for h in found:  # the student's function by its name, and nothing of the reference's code
        assert mutants.NAMES_A_FUNCTION.search(h.detail)
        assert old not in h.detail and "np." not in h.detail and "=" not in h.detail and "self" not in h.detail


#: (slip, check, file, old, new, probe, inputs, path, what the hint must not say): a mistake near a slip of the
#: grammar that is not that slip
NEAR_MISSES = [
    ("a loop that stops two short", "p22.loop_values", "planar.py",
     "for length, angle in np.asarray(q, dtype=float).reshape(-1, 2):",
     "for length, angle in np.asarray(q, dtype=float).reshape(-1, 2)[:-2]:", "problem_22.loop", ARMS, (),
     "a loop in"),
    ("a loop of steps that starts two late", "p07.animation", "problem_07.py",
     "for _ in range(n):\n        angles = angles", "for _ in range(2, n):\n        angles = angles",
     "_rebound.rebound", [("problem_07.animate", [], []),
                          ("problem_07.animate", [["problem_07", "START_ANGLES", [0.9, 0.6, 0.45]]], [])],
     ("angles",), "the loop of steps"),
    ("a keyword argument given another value", "p25.sheet_values", "problem_25.py",
     "S_r_SDs=(-DX, DY, 0.0), q_index=[1])", "S_r_SDs=(DX, -DY, 0.0), q_index=[1])", "problem_25.walker", WALKERS,
     ("x",), "its keyword arguments"),
    ("an argument converted by twice the factor", "p47.impulse", "problem_47.py",
     "arm = x_cog * np.cos(phi) - y_cog * np.sin(phi)",
     "arm = x_cog * np.cos(phi * np.pi / 90) - y_cog * np.sin(phi * np.pi / 90)", "problem_47.impulse", IMPULSES, (),
     "converts an argument"),
]


@pytest.mark.parametrize("near", NEAR_MISSES, ids=[n[0] for n in NEAR_MISSES])
def test_a_near_miss_of_a_slip_is_not_named_as_it(near, tmp_path):
    _, check_id, file, old, new, probe, inputs, path, said = near
    found = slips_of(tmp_path, check_id, file, old, new, probe, inputs, path)
    assert not any(said in h.detail for h in found), [(h.name, h.detail) for h in found]


def test_a_slip_inside_an_index_is_an_index_slip(tmp_path):
    """``q[2 * k - 1]`` read as ``q[2 * k - 2]``: at k = 1 dropping the factor 2 of ``2 * k`` gives the same
    entry, a coincidence of the index that was told "a number left out of a product"; every slip inside an index
    is one of the index."""
    found = slips_of(tmp_path, "p22.points_values", "planar.py", "length, angle = q[2 * k - 2], q[2 * k - 1]",
                     "length, angle = q[2 * k - 2], q[2 * k - 2]", "problem_22.points",
                     [([1.0, 0.5],), ([0.4, -0.7, 1.2, 0.3],)], (1,))
    assert found and {h.name for h in found} == {"wrong_index"}, [(h.name, h.detail) for h in found]


def test_a_slip_on_one_input_only_is_no_cause(tmp_path):
    """The second input's value is the reference's: no mutant reproduces both."""
    student = planted_package(tmp_path, "planar.py", "y += length * np.cos(gamma)", "y -= length * np.cos(gamma)")
    try:
        first, second = (evidence("problem_22.loop", args, (), student) for args in ARMS)
    finally:
        drop_private(student)
    second = Evidence(second.expected + 0.5, second.expected, TIGHT, "value", source=second.source)
    assert mutants.mutant_slips(scene("p22.loop_values"), [first, second]) == []


def test_two_mistakes_at_once_are_no_single_slip(tmp_path):
    """One entry of the bearings' difference halved and the other's sign turned: two slips of two kinds.  (Both
    entries halved is the difference halved, one slip: a lever arm ``d`` for ``d / 2``.)"""
    found = slips_of(tmp_path, "p39.bearing_forces", "problem_39.py",
                     "difference = np.array([0.0, 2.0 * moment[2] / d, -2.0 * moment[1] / d])",
                     "difference = np.array([0.0, moment[2] / d, 2.0 * moment[1] / d])", "problem_39.bearing_forces",
                     BEARINGS, (0,))
    assert found == []


def test_an_equivalent_mutant_is_no_cause(tmp_path):
    """Mutants whose value is the reference's (the symmetric ``I_G`` transposed, say) reproduce a right answer
    too: they are dropped, and a right answer names nothing."""
    import reference

    root, package = mutants._package()
    args = STEINER[0]
    made = mutants.mutants_of(package, root, 19, "problem_19.parallel_axis", args)
    expected = array_of(decode(encode(probe_of("problem_19.parallel_axis")(reference, *args))))
    equivalent = []
    for mutant in made:
        holder = mutants._live(package, mutant.module, mutant.path)
        original, holder.__code__ = holder.__code__, mutant.code
        try:
            with np.errstate(all="ignore"):
                value = array_of(probe_of("problem_19.parallel_axis")(package, *args))
        except Exception:  # noqa: BLE001 - a mutant that raises is no equivalent
            value = None
        finally:
            holder.__code__ = original
        if value is not None and np.allclose(value, expected, rtol=0, atol=1e-12):
            equivalent.append(mutant.slip)
    assert "transpose" in equivalent
    evidences = []
    for args in STEINER:
        value = array_of(decode(encode(probe_of("problem_19.parallel_axis")(reference, *args))))
        evidences.append(Evidence(value.copy(), value, TIGHT, "I_O",
                                  source=Source("problem_19.parallel_axis", args, (), value)))
    assert mutants.mutant_slips(scene("p19.parallel_axis"), evidences) == []


def test_the_kit_leaves_formulas_to_the_graded_submission(tmp_path):
    student = planted_package(tmp_path, "planar.py", "y += length * np.cos(gamma)", "y -= length * np.cos(gamma)")
    try:
        evidences = [evidence("problem_22.loop", args, (), student) for args in ARMS]
    finally:
        drop_private(student)
    assert mutants.mutant_slips(scene("p22.loop_values", mode="kit"), evidences) == []
    assert mutants.left_to_live(scene("p22.loop_values", mode="kit"), evidences)
    assert not mutants.left_to_live(scene("p22.loop_values"), evidences)


# ------------------------------------------------------------------------------------------ on a made-up package


SOURCE = '''"""A made-up problem for the tier's tests."""

import math

import numpy as np

#: where the made-up drift starts
DRIFT_START = np.array([0.1, -0.2, 0.3])
#: the made-up rotor's moments of inertia
I_AXIS = 2.0
I_ACROSS = 3.5


def rotor_inertia(I_axis=I_AXIS, I_across=I_ACROSS):
    """The rotor's inertia with its axis along 1."""
    # BEGIN SOLUTION problem 98
    return np.diag([I_axis, I_across, I_across])
    # END SOLUTION


def drift(rate, n):
    """Drift from ``DRIFT_START`` by ``rate`` for ``n`` steps: ``{"x": the end, "size": its length}``."""
    # BEGIN SOLUTION problem 98
    x = DRIFT_START.copy()
    for _ in range(n):
        x = x + rate
    return {"x": x, "size": float(np.linalg.norm(x))}
    # END SOLUTION


def difference(a, b):
    """``(a - b, a b)``."""
    # BEGIN SOLUTION problem 98
    return np.array([np.subtract(a, b), a * b])
    # END SOLUTION


def settle(a, b):
    """The first multiple of ``b`` at or past ``a``, and ``a b``."""
    # BEGIN SOLUTION problem 98
    x = 0.0
    while x < a:
        x += b
    return np.array([x, a * b])
    # END SOLUTION


def logarithm(a, b):
    """``(log a, b)``."""
    # BEGIN SOLUTION problem 98
    return np.array([math.log(a), b])
    # END SOLUTION


def rates(t, y):
    """``dy/dt`` of a run whose state is ``y = (q, qd)``."""
    # BEGIN SOLUTION problem 98
    q, qd = y[:2], y[2:]
    return np.concatenate([qd, -3.0 * q - 0.5 * qd + np.array([t, 0.0])])
    # END SOLUTION


def halves(v, w):
    """A vector ``v = (a, b)`` that is no run's state, mixed with ``w``."""
    # BEGIN SOLUTION problem 98
    a, b = v[:2], v[2:]
    return np.concatenate([b + w, 2.0 * a - b])
    # END SOLUTION


def feedback(q, qd, q_des, qd_des):
    """A PD law (given, no solution region)."""
    return 4.0 * (q_des - q) + 1.5 * (qd_des - qd)


def control(q, qd, q_des, qd_des):
    """A feedforward product and the PD law."""
    # BEGIN SOLUTION problem 98
    return q * qd + feedback(q, qd, q_des, qd_des)
    # END SOLUTION


def moment(f_x, f_y, r_x, r_y):
    """The moment of ``f`` about the origin at ``r``, and ``f . r``."""
    # BEGIN SOLUTION problem 98
    m_z = r_x * f_y - r_y * f_x
    return np.array([m_z, r_x * f_x + r_y * f_y])
    # END SOLUTION


def compliance(k1, k2):
    """The displacements of two springs in series under the loads (1, 0.5)."""
    # BEGIN SOLUTION problem 98
    K = np.array([[k1 + k2, -k2], [-k2, k2]])
    return np.linalg.inv(K) @ np.array([1.0, 0.5])
    # END SOLUTION


def gram(J, K):
    """``J.T J`` and ``J.T K``."""
    # BEGIN SOLUTION problem 98
    return J.T @ J + 2.0 * np.eye(3), J.T @ K
    # END SOLUTION


P_GAIN, D_GAIN = 4.0, 1.5


def skew(w):
    """The cross-product matrix (given)."""
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def track(q, qd, q_des, qd_des):
    """A PD law with the module's gains."""
    # BEGIN SOLUTION problem 98
    return P_GAIN * (q_des - q) + D_GAIN * (qd_des - qd)
    # END SOLUTION


def transport(r, w, v):
    """``v - r x w + r / 2`` by a cross-product matrix."""
    # BEGIN SOLUTION problem 98
    lever = skew(r)
    return v - lever @ w + 0.5 * r
    # END SOLUTION


def sextet(a, b, c, d, e, f):
    """A weighted sum of six arguments."""
    # BEGIN SOLUTION problem 98
    return weigh(a, b, c, d, 2.0 * e, f)
    # END SOLUTION


def weigh(a, b, c, d, e, f):
    """(given)"""
    return a + 2.0 * b + 3.0 * c + 5.0 * d + 7.0 * e + 11.0 * f


def loads(m1, m2, points):
    """A sum over two parts, each by its mass and point."""
    # BEGIN SOLUTION problem 98
    total = np.array([m1, 2.0 * m2])
    for m, r in zip((m1, m2), points):
        total += m * r
    return total
    # END SOLUTION


def back(v, A_IB):
    """``A_IB.T v``: a vector turned back into body coordinates."""
    # BEGIN SOLUTION problem 98
    return A_IB.T @ np.asarray(v, dtype=float)
    # END SOLUTION


def height(a, b):
    """``a b + 0.4 + b``: a product, a constant and an argument."""
    # BEGIN SOLUTION problem 98
    return np.array([a * b + 0.4 + b])
    # END SOLUTION


class Body:
    """A body's state in the course's notation (given)."""

    def __init__(self, A_IB, B_v_B, B_omega_B, B_omegaDot_B):
        self.A_IB, self.B_v_B, self.B_omega_B, self.B_omegaDot_B = A_IB, B_v_B, B_omega_B, B_omegaDot_B
        self.I_v_B = A_IB @ B_v_B


def point_velocity(body, B_r_BP):
    """``I_v_P = I_v_B + A_IB (B_omega_B x B_r_BP)``."""
    # BEGIN SOLUTION problem 98
    return body.I_v_B + body.A_IB @ np.cross(body.B_omega_B, B_r_BP)
    # END SOLUTION


def lever_position(A_IB, B_r_IB, B_r_BP):
    """``I_r_IP = A_IB (B_r_IB + B_r_BP)``."""
    # BEGIN SOLUTION problem 98
    return A_IB @ (B_r_IB + B_r_BP)
    # END SOLUTION


def mean_rate(a, b, dt):
    """``(a + b) / dt``."""
    # BEGIN SOLUTION problem 98
    return np.array([(a + b) / dt, a * b])
    # END SOLUTION


def offsets(dx, dy):
    """The offset of a hip from a stance foot."""
    # BEGIN SOLUTION problem 98
    return np.array([-dx, dy, 0.5 * dx])
    # END SOLUTION


def oscillation(m, k):
    """The period and the angular frequency of a mass on a spring."""
    # BEGIN SOLUTION problem 98
    omega = np.sqrt(k / m)
    return np.array([2.0 * np.pi / omega, omega])
    # END SOLUTION


def heading(bearing, distance):
    """The point ``distance`` away along ``bearing``, an angle given in degrees."""
    # BEGIN SOLUTION problem 98
    angle = np.deg2rad(bearing)
    return distance * np.array([np.cos(angle), np.sin(angle)])
    # END SOLUTION


def R1(a):
    """(given)"""
    return np.array([[1.0, 0.0, 0.0], [0.0, np.cos(a), -np.sin(a)], [0.0, np.sin(a), np.cos(a)]])


def R3(a):
    """(given)"""
    return np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0], [0.0, 0.0, 1.0]])


def relay(a, b, v):
    """A vector turned on by ``R1(b)`` and back by ``R3(a)``: ``R3(a).T (R1(b) v)``."""
    # BEGIN SOLUTION problem 98
    return R3(a).T @ (R1(b) @ v)
    # END SOLUTION


def zx(a, b):
    """(given) the rotation ``R3(a) R1(b)``."""
    return R3(a) @ R1(b)


def spun(angles, v):
    """A vector turned by ``zx`` of the two angles, in their order."""
    # BEGIN SOLUTION problem 98
    return zx(*angles) @ v
    # END SOLUTION


def lever(x, y):
    """A load's moment about a pivot, its arm and its weight given by name: ``3 arm - weight``."""
    # BEGIN SOLUTION problem 98
    named = {"arm": 2.0 * x, "weight": y + 1.0}
    return 3.0 * named["arm"] - named["weight"]
    # END SOLUTION


def edge(state, s):
    """The height of a tipped bar's edge over a support at ``s``, from its state ``(x, z, phi)``."""
    # BEGIN SOLUTION problem 98
    x, z, phi = state
    return z * np.cos(phi) - (x - s) * np.sin(phi)
    # END SOLUTION


def spring(x, k=2.0, c=0.5):
    """(given) a spring's force with its stiffness and its quadratic damping."""
    return -k * x - c * x ** 2


def handed(x, params):
    """The spring's force with the parameters given by name."""
    # BEGIN SOLUTION problem 98
    return spring(x, **params)
    # END SOLUTION


def scaled_inertia(m, inertia=None):
    """A body's inertia of a unit body scaled by its mass: the identity where none is given."""
    # BEGIN SOLUTION problem 98
    J = np.eye(3) if inertia is None else np.asarray(inertia, dtype=float)
    return m * J
    # END SOLUTION


def clearance(t, y, *args):
    """An event's residual for solve_ivp: the height ``y[0]`` over a step 0.2 high, less a sag that grows with t."""
    # BEGIN SOLUTION problem 98
    return y[0] - 0.2 + 0.05 * t
    # END SOLUTION


def harmonic(t):
    """Two harmonics and their rates at time ``t``."""
    # BEGIN SOLUTION problem 98
    w = np.array([1.0, 2.0])
    c, s = np.cos(w * t), np.sin(w * t)
    q = 3.0 * c + 0.5 * s
    qd = w * (0.5 * c - 3.0 * s)
    return np.concatenate([q, qd])
    # END SOLUTION


def zx_of(angles):
    """(given) the rotation ``zx`` of a list of its two angles."""
    return zx(angles[0], angles[1])


def pointed(angles, v):
    """A vector turned by ``zx_of`` of the angles, in their order."""
    # BEGIN SOLUTION problem 98
    return zx_of(angles) @ v
    # END SOLUTION


def gimbal(a, b, v):
    """A vector through the sequence z, x, z: ``R3(a) R1(b) R3(b / 2) v``."""
    # BEGIN SOLUTION problem 98
    return R3(a) @ R1(b) @ R3(0.5 * b) @ v
    # END SOLUTION


class Link:
    """A link's Jacobians in the course's notation (given)."""

    def __init__(self, B_J_S, B_J_R):
        self.B_J_S, self.B_J_R = B_J_S, B_J_R


def link_rates(B_J_S, B_J_R, qd):
    """``(B_v_B, 2 B_omega_B) = (B_J_S qd, 2 B_J_R qd)`` of a link."""
    # BEGIN SOLUTION problem 98
    link = Link(B_J_S, B_J_R)
    return np.concatenate([link.B_J_S @ qd, 2.0 * link.B_J_R @ qd])
    # END SOLUTION


def moment_about(I_r_IP, I_r_IC, I_v_P, I_v_C, f):
    """The moment of ``f`` at P about C, and the velocity of P relative to C's."""
    # BEGIN SOLUTION problem 98
    return np.concatenate([np.cross(I_r_IP - I_r_IC, f), I_v_P - I_v_C])
    # END SOLUTION


def arm(q, d):
    """The end of an arm of length ``d`` at the angle ``q``, and ``q``."""
    # BEGIN SOLUTION problem 98
    return np.array([-d * np.sin(q), d * np.cos(q), q])
    # END SOLUTION


def arm_reach(q, d):
    """The end of an arm of length ``d`` at the angle ``q``, and ``q + d``."""
    # BEGIN SOLUTION problem 98
    return np.array([-d * np.sin(q), d * np.cos(q), q + d])
    # END SOLUTION


def harmonics(c):
    """The coefficients of two harmonics (columns) of three coordinates (rows), two of them moving."""
    # BEGIN SOLUTION problem 98
    table = np.zeros((3, 2))
    table[1] = [c, 0.5 * c]
    table[2] = [-c / 4, +c / 2]
    return table
    # END SOLUTION


class Offset:
    """An offset that its owner sets anew."""

    def __init__(self, r):
        self.r = np.asarray(r, dtype=float)

    def set(self, r):
        # BEGIN SOLUTION problem 98
        self.r = np.asarray(r, dtype=float)
        # END SOLUTION


def moved(a, b):
    """An offset made at ``a``, then set to ``b``."""
    offset = Offset(a)
    offset.set(b)
    return offset.r


def shear(k, d):
    """The shear of the plane by ``k`` along its first axis, and by ``d`` of the third along the second."""
    # BEGIN SOLUTION problem 98
    return np.array([[1.0, k, 0.0], [0.0, 1.0, d], [0.0, 0.0, 1.0]])
    # END SOLUTION


def box_moment(m, a):
    """The moment of inertia of a thin rod of mass ``m`` and length ``a`` about its centre."""
    # BEGIN SOLUTION problem 98
    return m / 12 * a**2
    # END SOLUTION


def steiner(m, r):
    """The parallel-axis term of a mass ``m`` at ``r``: ``m (r.r E - r r^T)``."""
    # BEGIN SOLUTION problem 98
    return m * ((r @ r) * np.eye(3) - np.outer(r, r))
    # END SOLUTION


def turn(phi):
    """The rotation about the third axis by ``phi``, written out."""
    # BEGIN SOLUTION problem 98
    return np.array([[np.cos(phi), -np.sin(phi), 0.0], [np.sin(phi), np.cos(phi), 0.0], [0.0, 0.0, 1.0]])
    # END SOLUTION


def _spring(x, k=1.0, preload=0.0):
    return -k * x + preload


def spring_force(x, k, preload):
    """The force of a spring of stiffness ``k`` with its ``preload``."""
    # BEGIN SOLUTION problem 98
    return _spring(x, k=k, preload=preload)
    # END SOLUTION


def spin_torque(A_IB, B_I_B, w):
    """Euler's gyroscopic torque ``-w x (B_I_B w)`` in body coordinates (of a body that ``A_IB`` turns)."""
    # BEGIN SOLUTION problem 98
    return -np.cross(w, B_I_B @ w)
    # END SOLUTION


def elbow_height(q, lengths):
    """The height of the elbow of a planar arm of two links at the angles ``q``: its first link's alone."""
    # BEGIN SOLUTION problem 98
    q1, _ = np.asarray(q, dtype=float)
    l1, _ = lengths
    return l1 * np.sin(q1) + 0.1 * l1
    # END SOLUTION


def damping(D, rate_des, rate):
    """The damping torque of a PD law: ``D (rate_des - rate)``."""
    # BEGIN SOLUTION problem 98
    return D * (rate_des - rate)
    # END SOLUTION


def rod_impulse(m, a, theta):
    """The impulse on a rod of mass ``m`` hit at the arm ``a``, ``theta`` its inertia about its centre."""
    # BEGIN SOLUTION problem 98
    return -m * theta / (m * a**2 + theta)
    # END SOLUTION


def spread(S, m):
    """The distance of points of mass ``m`` whose second moment is ``S``: ``sqrt(3 S / m)``."""
    # BEGIN SOLUTION problem 98
    return np.sqrt(3 * S / m)
    # END SOLUTION


def arm_ends(r0, d):
    """The two ends of an arm about ``r0``, the second at twice its lever."""
    # BEGIN SOLUTION problem 98
    offset = np.array([d, 0.0, 0.5 * d])
    return np.concatenate([np.add(r0, offset), 2.0 * np.subtract(r0, offset)])
    # END SOLUTION


def spring_back(K, x):
    """A spring's force ``-K x`` with a light damping of the position, ``0.1 x``."""
    # BEGIN SOLUTION problem 98
    return -(K @ x) + 0.1 * x
    # END SOLUTION


def weighed(values):
    """Each value counted once in full and once at a weight of a half."""
    # BEGIN SOLUTION problem 98
    return sum(v * w for v in values for w in (1.0, 0.5))
    # END SOLUTION


def skew(w):
    """The matrix of ``w x``."""
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def euler_torque(B_I_B, w):
    """Euler's gyroscopic torque ``-w x (B_I_B w)``, with the skew matrix of ``w``."""
    # BEGIN SOLUTION problem 98
    return -skew(w) @ B_I_B @ w
    # END SOLUTION


def relaxed(K, c):
    """``E + c K``."""
    # BEGIN SOLUTION problem 98
    return np.eye(3) + c * K
    # END SOLUTION


def compliant_rates(A, B, w):
    """The rates ``x`` of ``B A x = w``, each matrix inverted in turn."""
    # BEGIN SOLUTION problem 98
    return np.linalg.inv(A) @ np.linalg.solve(B, w)
    # END SOLUTION


def step_rates(A, B, w):
    """The rates ``x`` of ``A B x = w``."""
    # BEGIN SOLUTION problem 98
    return np.linalg.solve(A @ B, w)
    # END SOLUTION
'''


@pytest.fixture
def made_up(tmp_path, monkeypatch):
    """A package of one made-up problem (98) that the tier mutates in place of the reference."""
    with made_up_package(tmp_path, monkeypatch, SOURCE, 98, "mutants") as package:
        yield package


def made_up_probe(name, number=98):
    """The probe of ``name`` in the made-up problem ``number`` of the package it is given."""
    def probe(pkg, *args):
        return getattr(importlib.import_module(f"{pkg.__name__}.problem_{number}"), name)(*args)

    return probe


def made_up_evidences(package, name, student, inputs, path=(), number=98):
    """The comparisons of ``student`` with ``name`` of the made-up problem ``number`` on each of ``inputs``."""
    probe = made_up_probe(name, number)
    return [Evidence(array_of(at(student(*args), path)), array_of(at(probe(package, *args), path)), TIGHT,
                     "value", source=Source(probe, args, path)) for args in inputs]


#: the made-up drift's start, as the made-up module binds it
DRIFT_START = np.array([0.1, -0.2, 0.3])


def test_a_value_two_families_give_is_could_be(made_up):
    """``b - a`` is ``np.subtract`` with its arguments exchanged (order) and its result negated (sign)."""
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [b - a, a * b], [(1.0, 3.0), (2.5, -0.5)])
    found = mutants.mutant_slips(scene("p98.difference"), evidences)
    assert {DIAGNOSES[h.name].family for h in found} == {"order", "sign"}
    finding = explaining._finding(found, "on the input shown and on a second one")
    assert finding.hint.startswith("Could be ") and len(finding.names) == 2


def test_after_an_explanation_rivals_of_other_families_are_tried_first(made_up, monkeypatch):
    """Where an earlier tier already explained the answer (``told``: its families), the tier tries the mutants of
    families not told yet first, then those of the families told as time allows, at most ``LATE_MUTANTS``: ``b - a``
    explained as a sign adds the exchange of the arguments (another family) and the sign's own name; with no mutant
    left to try it adds nothing."""
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [b - a, a * b], [(1.0, 3.0), (2.5, -0.5)])
    found = mutants.mutant_slips(scene("p98.difference"), evidences, told={"sign"})
    assert {DIAGNOSES[h.name].family for h in found} == {"order", "sign"}, [(h.name, h.detail) for h in found]
    monkeypatch.setattr(mutants, "LATE_MUTANTS", 0)
    assert mutants.mutant_slips(scene("p98.difference"), evidences, told={"sign"}) == []


def test_the_late_mutants_are_those_of_other_families_first():
    made = [mutants.Mutant("problem_98", ("f",), slip, None)
            for slip in ("sign", "entries", "square", "sign", "arguments", "halved")]
    order, rivals = mutants.late(made, {"sign"})
    assert [m.slip for m in order] == ["entries", "square", "arguments", "halved", "sign", "sign"] and rivals == 4
    order, rivals = mutants.late(made, {"sign", "scale"})
    assert [m.slip for m in order] == ["entries", "arguments", "sign", "square", "sign", "halved"] and rivals == 2
    order, rivals = mutants.late(made * (mutants.LATE_MUTANTS // len(made) + 1), set())
    assert len(order) == rivals == mutants.LATE_MUTANTS


def test_after_an_explanation_the_tier_has_a_smaller_time_budget(made_up, monkeypatch):
    """A mutant that hangs is interrupted within ``LATE_TIME_BUDGET`` where an earlier tier explained the answer
    (the earlier finding then stands): the budget of the whole tier is not spent on rivals."""
    monkeypatch.setattr(mutants, "TIME_BUDGET", 600.0)
    monkeypatch.setattr(mutants, "LATE_TIME_BUDGET", 0.3)
    evidences = made_up_evidences(made_up, "settle", lambda a, b: [a + 1.0, 0.5 * a * b], [(1.0, 0.3), (2.0, 0.7)])
    started = time.monotonic()
    assert mutants.mutant_slips(scene("p98.settle"), evidences, told={"order"}) == []
    assert time.monotonic() - started < 60.0  # bounded by the late budget, not the whole tier's (a loaded machine)


def test_a_third_input_rules_out_a_coincidence_of_the_two_shown(made_up):
    """Where the engine can draw another input (``another``), a slip is kept only if it gives the student's value
    there too: a value that agrees with ``b - a`` on the two inputs shown but not elsewhere names nothing."""
    def coincidence(a, b):
        return [b - a if a < 5.0 else a - b + 1.0, a * b]

    inputs = [(1.0, 3.0), (2.5, -0.5)]
    evidences = made_up_evidences(made_up, "difference", coincidence, inputs)
    (third,) = made_up_evidences(made_up, "difference", coincidence, [(7.0, 2.0)])
    assert mutants.mutant_slips(scene("p98.difference"), evidences, lambda: third) == []
    (third,) = made_up_evidences(made_up, "difference", coincidence, [(-3.0, 2.0)])
    assert mutants.mutant_slips(scene("p98.difference"), evidences, lambda: third)
    assert mutants.mutant_slips(scene("p98.difference"), evidences, lambda: None)


def test_slips_of_more_than_two_families_name_nothing():
    made = [mutants.Mutant("problem_98", ("f",), slip, None) for slip in ("sign", "entries", "square")]
    assert len({DIAGNOSES[m.name].family for m in made}) == 3
    assert mutants._hypotheses(made) == []
    assert [h.name for h in mutants._hypotheses(made[:2])] == ["sign_flip", "swapped"]


def test_a_mutant_that_hangs_is_interrupted_and_names_nothing(made_up, monkeypatch):
    """``x += b`` turned into ``x -= b`` (or left out) never ends the loop: the tier's time runs out, nothing is
    named, and the function's own code is back in place."""
    monkeypatch.setattr(mutants, "TIME_BUDGET", 0.5)
    fired = []

    class Watched(mutants._Deadline):
        def __exit__(self, *exc):
            fired.append(self.fired)
            return super().__exit__(*exc)

    monkeypatch.setattr(mutants, "_Deadline", Watched)
    evidences = made_up_evidences(made_up, "settle", lambda a, b: [a + 1.0, 0.5 * a * b], [(1.0, 0.3), (2.0, 0.7)])
    started = time.monotonic()
    assert mutants.mutant_slips(scene("p98.settle"), evidences) == []
    assert time.monotonic() - started < 60.0  # bounded (the budget is half a second; a loaded machine is slow)
    assert fired == [True]
    settle = importlib.import_module(f"{made_up.__name__}.problem_98").settle
    assert list(settle(1.0, 0.3)) == pytest.approx([1.2, 0.3])


@pytest.fixture
def measured(monkeypatch):
    """One entry for each measure of the tier (``_evaluate``)."""
    counted = []
    evaluate = mutants._evaluate

    def counting(*args, **kwargs):
        counted.append(1)
        return evaluate(*args, **kwargs)

    monkeypatch.setattr(mutants, "_evaluate", counting)
    return counted


def test_a_grading_measures_the_same_question_once(made_up, monkeypatch, measured):
    """Two explanations of one grading (one context) that ask the tier the same question (the same inputs,
    student's values and families told) measure the mutants once and hear the same slips; another grading, or
    another student's value, measures them anew; a measure that ran out of its time is measured again."""
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [b - a, a * b], [(1.0, 3.0), (2.5, -0.5)])
    grading = scene("p98.difference")
    first = mutants.mutant_slips(grading, evidences)
    assert first and measured
    count = len(measured)
    assert mutants.mutant_slips(grading, evidences) == first and len(measured) == count
    assert mutants.mutant_slips(scene("p98.difference"), evidences) == first and len(measured) > count
    count = len(measured)
    other = made_up_evidences(made_up, "difference", lambda a, b: [a - b, a * b], [(1.0, 3.0), (2.5, -0.5)])
    assert mutants.mutant_slips(grading, other) == [] and len(measured) > count

    monkeypatch.setattr(mutants, "TIME_BUDGET", 0.15)
    hanging = made_up_evidences(made_up, "settle", lambda a, b: [a + 1.0, 0.5 * a * b], [(1.0, 0.3), (2.0, 0.7)])
    grading = scene("p98.settle")
    assert mutants.mutant_slips(grading, hanging) == []
    count = len(measured)
    assert mutants.mutant_slips(grading, hanging) == [] and len(measured) > count


def test_another_submission_graded_by_the_same_oracle_measures_anew(made_up, measured):
    """A batch's worker grades every submission with one oracle: the measures belong to one grading's context
    (one submission's problem), so the next submission's same question is measured again, and the measures of a
    batch are not all kept."""
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [b - a, a * b], [(1.0, 3.0), (2.5, -0.5)])
    oracle = SimpleNamespace(mode="live")
    first = mutants.mutant_slips(SimpleNamespace(ctx=SimpleNamespace(check_id="p98.difference", oracle=oracle)),
                                 evidences)
    count = len(measured)
    assert first and count
    later = mutants.mutant_slips(SimpleNamespace(ctx=SimpleNamespace(check_id="p98.difference", oracle=oracle)),
                                 evidences)
    assert later == first and len(measured) > count


def test_an_explanation_traces_its_call_once(made_up, monkeypatch):
    """A value that no slip of a region reproduces is heard by the stages of the given code and of the constants,
    each of which reads the codes the compared call runs: the call is traced once for the explanation, and anew
    for the next one."""
    traced = []
    once = mutants._traced_once

    def counted(*args, **kwargs):
        traced.append(1)
        return once(*args, **kwargs)

    monkeypatch.setattr(mutants, "_traced_once", counted)
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [7.0, -7.0], [(1.0, 3.0), (2.5, -0.5)])
    stages = []
    monkeypatch.setattr(mutants.trace, "note", lambda what, **details: stages.append(what))
    assert mutants.mutant_slips(scene("p98.difference"), evidences) == []
    assert {"mutated", "given", "constants"} <= set(stages) and len(traced) == 1
    assert mutants.mutant_slips(scene("p98.difference"), evidences) == [] and len(traced) == 2


def test_a_deadline_that_fires_leaves_nothing_behind():
    """However the interruption meets the work (inside it, or pending as it ends), nothing is left to interrupt
    later code, and a profiled call still runs (withdrawing a pending interruption with ``SetAsyncExc(NULL)`` made
    CPython 3.11 loop forever in the next profiler): run in a child process, within a generous bound."""
    import subprocess
    import sys

    script = """
import sys
from grader.diagnosis import mutants

try:
    with mutants._Deadline(0.2):
        while True:
            pass
except mutants._Timeout:
    pass
try:
    with mutants._Deadline(60.0) as deadline:
        deadline._fire()
except mutants._Timeout:
    pass


def total(n):
    return sum(range(n))


sys.setprofile(lambda frame, event, arg: None)
print(total(10))
sys.setprofile(None)
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120, cwd=ROOT)
    assert done.returncode == 0 and done.stdout.strip() == "45", done.stderr[-2000:]


def test_a_mutant_that_raises_is_dropped(made_up):
    """``math.log(b)`` (the arguments exchanged) raises for a negative ``b``: dropped, while the slip that
    reproduces the student's value is named."""
    evidences = made_up_evidences(made_up, "logarithm", lambda a, b: [-np.log(a), b], [(2.0, -0.3), (0.5, -1.7)])
    found = mutants.mutant_slips(scene("p98.logarithm"), evidences)
    assert [h.name for h in found] == ["sign_flip"]


#: a body's state (the made-up ``Body``'s arguments) and a point on it, on two inputs
BODY_STATES = [((ROTATIONS[0], V(0.4, -0.2, 0.9), V(0.3, 1.1, -0.5), V(-0.7, 0.2, 0.6)), V(0.5, 0.1, -0.3)),
               ((ROTATIONS[1], V(-1.0, 0.6, 0.2), V(-0.8, 0.4, 0.9), V(0.3, -1.2, 0.5)), V(-0.2, 0.7, 0.4))]


def _bodies(package):
    body = importlib.import_module(f"{package.__name__}.problem_98").Body
    return [(body(*state), point) for state, point in BODY_STATES]


def _velocity(rate=False, frame=False, both=False):
    """The made-up ``point_velocity`` as a student may write it: the angular acceleration read where the angular
    velocity belongs (``rate``), the velocity in body coordinates (``frame``), or the sum of both rates
    (``both``: no single slip)."""
    def student(body, B_r_BP):
        omega = body.B_omegaDot_B if rate else body.B_omega_B + body.B_omegaDot_B if both else body.B_omega_B
        return (body.B_v_B if frame else body.I_v_B) + body.A_IB @ np.cross(omega, B_r_BP)

    return student


def test_a_rate_read_where_the_quantity_belongs_is_a_state_read(made_up):
    """``body.B_omegaDot_B`` read where ``body.B_omega_B`` belongs (an attribute of the course's notation and its
    rate): a state read from the wrong rows; the sum of both (no single slip) names no such cause."""
    evidences = made_up_evidences(made_up, "point_velocity", _velocity(rate=True), _bodies(made_up))
    found = mutants.mutant_slips(scene("p98.point_velocity"), evidences)
    assert {h.name for h in found} == {"state_row"}, [(h.name, h.detail) for h in found]
    assert any("reads a quantity where its rate belongs" in h.detail and "`point_velocity`" in h.detail
               for h in found)
    near = made_up_evidences(made_up, "point_velocity", _velocity(both=True), _bodies(made_up))
    assert "state_row" not in {h.name for h in mutants.mutant_slips(scene("p98.point_velocity"), near)}


def test_a_quantity_read_in_another_frames_coordinates_is_a_frame_slip(made_up):
    """``body.B_v_B`` read where ``body.I_v_B`` belongs (one quantity, the coordinates of another frame): a frame
    slip; the velocity left out altogether (a term, not a frame) is not told as one."""
    evidences = made_up_evidences(made_up, "point_velocity", _velocity(frame=True), _bodies(made_up))
    found = mutants.mutant_slips(scene("p98.point_velocity"), evidences)
    assert {h.name for h in found} == {"wrong_frame"}, [(h.name, h.detail) for h in found]
    assert any("in the coordinates of another frame" in h.detail for h in found)

    def without(body, B_r_BP):
        return body.A_IB @ np.cross(body.B_omega_B, B_r_BP)

    near = made_up_evidences(made_up, "point_velocity", without, _bodies(made_up))
    assert "wrong_frame" not in {h.name for h in mutants.mutant_slips(scene("p98.point_velocity"), near)}


def test_the_names_related_by_rate_and_by_frame():
    """By the course's notation: a rate's mark on one part of a name, the next of r, v, a (a position's velocity is
    that of its end point); one quantity in two frames' coordinates (the first part), or two rotations; a pair of
    sibling matrices (``B_J_S``, ``B_J_R``); not two other different quantities or points."""
    for a, b in (("q", "qd"), ("qd", "qdd"), ("B_omega_B", "B_omegaDot_B"), ("dq1", "q1"), ("x", "x_dot"),
                 ("B_v_B", "B_a_B"), ("Om", "dOm")):
        assert mutants._related(a, b) == "rates", (a, b)
    # a position from one point to another and the velocity of its end point, in the same frame's coordinates
    for a, b in (("B_r_IB", "B_v_B"), ("I_v_T", "I_r_IT"), ("I_r_E", "I_v_E")):
        assert mutants._related(a, b) == "rates", (a, b)
    for a, b in (("I_v_B", "B_v_B"), ("A_IC2", "A_IC3"), ("I_r_IB", "B_r_IB")):
        assert mutants._related(a, b) == "frames", (a, b)
    for a, b in (("B_J_R", "B_J_S"), ("S_J_S", "S_J_R")):  # the two Jacobians of a body: a pair of siblings
        assert mutants._related(a, b) == "siblings", (a, b)
    for a, b in (("Dp_r_DpDs", "Dp_r_IDp"), ("P_GAIN", "D_GAIN"), ("m1", "m2"), ("q", "q"), ("B_v_B", "B_omega_B"),
                 ("A_IB", "B_IB"), ("I_r_IB", "I_r_IC"), ("B_r_IB", "B_v_I"), ("B_r_IB", "I_v_B")):
        assert mutants._related(a, b) is None, (a, b)


def test_a_factor_applied_to_one_term_of_a_sum(made_up):
    """``A_IB @ B_r_IB + B_r_BP`` where ``A_IB @ (B_r_IB + B_r_BP)`` belongs: a rotation applied to one term only, a
    frame slip; ``a + b / dt`` for ``(a + b) / dt``: a factor of one term only.  The rotation on the other term
    turned back instead (two slips) names no such cause."""
    inputs = [(ROTATIONS[2], V(0.3, -0.4, 1.0), V(0.8, 0.1, -0.6)),
              (ROTATIONS[3], V(-0.5, 0.9, 0.2), V(0.2, -0.7, 0.4))]
    evidences = made_up_evidences(made_up, "lever_position", lambda A, r, p: A @ r + p, inputs)
    found = mutants.mutant_slips(scene("p98.lever_position"), evidences)
    assert {h.name for h in found} == {"wrong_frame"}, [(h.name, h.detail) for h in found]
    assert any("a rotation in `lever_position` is applied to one term of a sum only" in h.detail for h in found)
    near = made_up_evidences(made_up, "lever_position", lambda A, r, p: A @ r + A.T @ p, inputs)
    assert mutants.mutant_slips(scene("p98.lever_position"), near) == []
    scalars = made_up_evidences(made_up, "mean_rate", lambda a, b, dt: [a + b / dt, a * b],
                                [(1.0, 3.0, 0.5), (2.5, -0.5, 4.0)])
    found = mutants.mutant_slips(scene("p98.mean_rate"), scalars)
    assert {h.name for h in found} == {"missing_factor"}, [(h.name, h.detail) for h in found]
    assert any("multiplies one term of a sum only" in h.detail for h in found)


def test_one_entry_of_a_list_with_the_wrong_sign(made_up):
    """``[-dx, -dy, ...]`` where ``[-dx, dy, ...]`` belongs: one entry's sign; ``-2 dy`` (a sign and a factor)
    names no such cause."""
    inputs = [(0.3, 0.8), (1.2, -0.4)]
    evidences = made_up_evidences(made_up, "offsets", lambda dx, dy: [-dx, -dy, 0.5 * dx], inputs)
    found = mutants.mutant_slips(scene("p98.offsets"), evidences)
    assert {h.name for h in found} == {"sign_flip"}, [(h.name, h.detail) for h in found]
    assert any("one entry that `offsets` builds has the wrong sign" in h.detail for h in found)
    near = made_up_evidences(made_up, "offsets", lambda dx, dy: [-dx, -2.0 * dy, 0.5 * dx], inputs)
    assert mutants.mutant_slips(scene("p98.offsets"), near) == []


def test_the_mutants_are_bounded(made_up, monkeypatch):
    """More mutants than the tier may try: nothing is named (the slips were not all tried)."""
    monkeypatch.setattr(mutants, "MAX_MUTANTS", 2)
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [b - a, a * b], [(1.0, 3.0), (2.5, -0.5)])
    assert mutants.mutant_slips(scene("p98.difference"), evidences) == []


# ------------------------------------------------------------------------------------------ kinds of slip


def names_of(made_up, name, student, inputs, path=()):
    found = mutants.mutant_slips(scene("p98.made_up"), made_up_evidences(made_up, name, student, inputs, path))
    return {h.name for h in found}, found


def assert_told_not_the_near_miss(made_up, name, student, near_miss, inputs, names: set, detail: str):
    """``student``'s value of ``name`` is told ``names``, by a hint that says ``detail``; ``near_miss``'s is told
    nothing that says it."""
    told, found = names_of(made_up, name, student, inputs)
    assert told == names, [(h.name, h.detail) for h in found]
    assert any(detail in h.detail for h in found), [h.detail for h in found]
    _, found = names_of(made_up, name, near_miss, inputs)
    assert not any(detail in h.detail for h in found), [(h.name, h.detail) for h in found]


STATES = [(0.3, V(0.5, -1.0, 2.0, 0.4)), (1.1, V(-0.2, 0.7, -0.6, 1.5))]


def test_parts_of_a_runs_state_read_from_each_others_rows_are_a_state_row_slip(made_up):
    """``q, qd = y[2:], y[:2]``: the two halves of a run's state exchanged (whether the reads or the names are
    exchanged) is a state read from the wrong rows, not two names or entries swapped."""
    def exchanged(t, y):
        q, qd = y[2:], y[:2]
        return np.concatenate([qd, -3.0 * q - 0.5 * qd + np.array([t, 0.0])])

    names, found = names_of(made_up, "rates", exchanged, STATES)
    assert names == {"state_row"}, [(h.name, h.detail) for h in found]
    assert any("`rates` reads a part of the state from the wrong rows" in h.detail for h in found)


def test_a_part_of_a_runs_state_read_from_the_other_half_is_a_state_row_slip(made_up):
    """``qd = y[:2]``: the rates read from the rows of the angles (the other half of the state)."""
    def copied(t, y):
        q, qd = y[:2], y[:2]
        return np.concatenate([qd, -3.0 * q - 0.5 * qd + np.array([t, 0.0])])

    names, found = names_of(made_up, "rates", copied, STATES)
    assert names == {"state_row"}, [(h.name, h.detail) for h in found]


def test_an_open_slice_of_a_runs_state_read_one_row_early_is_a_state_row_slip(made_up):
    """``qd = y[1:3]`` for ``qd = y[2:]``: the rates read as many rows, one row early (the slice's open end
    written out one short), is a state read from the wrong rows."""
    def early(t, y):
        q, qd = y[:2], y[1:3]
        return np.concatenate([qd, -3.0 * q - 0.5 * qd + np.array([t, 0.0])])

    names, found = names_of(made_up, "rates", early, STATES)
    assert names and {DIAGNOSES[n].family for n in names} == {"state_row"}, [(h.name, h.detail) for h in found]


def test_halves_of_a_vector_that_is_no_state_exchanged_are_swapped_entries(made_up):
    """The near miss: the same exchange of a vector that is no run's state (not ``y`` of ``f(t, y)``) is an
    exchange of entries or names, never a state row."""
    def exchanged(v, w):
        a, b = v[2:], v[:2]
        return np.concatenate([b + w, 2.0 * a - b])

    names, found = names_of(made_up, "halves", exchanged, [(V(0.5, -1.0, 2.0, 0.4), V(1.0, 2.0)),
                                                            (V(-0.2, 0.7, -0.6, 1.5), V(0.3, -0.4))])
    assert names and {DIAGNOSES[n].family for n in names} == {"order"}, [(h.name, h.detail) for h in found]


def test_two_groups_of_arguments_exchanged_could_be_order_or_sign(made_up):
    """``feedback(q_des, qd_des, q, qd)``: the measured and the desired state exchanged as groups; the PD law then
    has the opposite sign, so both slips give the student's value: "could be", never the sign alone."""
    def exchanged(q, qd, q_des, qd_des):
        return q * qd + 4.0 * (q - q_des) + 1.5 * (qd - qd_des)

    names, found = names_of(made_up, "control", exchanged, [(V(0.5, -1.0), V(2.0, 0.4), V(0.1, 0.2), V(-0.3, 0.9)),
                                                             (V(1.2, 0.3), V(-0.5, 0.8), V(0.7, -1.1), V(0.4, 0.6))])
    assert "argument_order" in names and {DIAGNOSES[n].family for n in names} == {"order", "sign"}, names
    assert any("two groups of arguments of a call in `control` are exchanged" in h.detail for h in found)
    assert explaining._finding(found, "here").hint.startswith("Could be ")


def test_two_components_exchanged_in_one_expression_are_swapped(made_up):
    """``m_z = r_y f_y - r_x f_x``: r_x and r_y exchanged in one expression only (the other keeps them)."""
    def exchanged(f_x, f_y, r_x, r_y):
        return np.array([r_y * f_y - r_x * f_x, r_x * f_x + r_y * f_y])

    names, found = names_of(made_up, "moment", exchanged, [(1.0, -2.0, 0.5, 0.7), (0.3, 0.8, -1.2, 0.4)])
    assert names == {"swapped"}, [(h.name, h.detail) for h in found]
    assert any("are exchanged in one expression of `moment`" in h.detail for h in found)


def test_a_matrix_for_its_inverse_is_an_inverse_slip(made_up):
    def uninverted(k1, k2):
        return np.array([[k1 + k2, -k2], [-k2, k2]]) @ np.array([1.0, 0.5])

    names, found = names_of(made_up, "compliance", uninverted, [(3.0, 2.0), (1.5, 4.0)])
    assert names == {"no_inverse"}, [(h.name, h.detail) for h in found]


def test_a_transpose_on_the_wrong_factor_of_a_product_is_a_transpose_slip(made_up):
    """``J J.T`` for ``J.T J`` exchanges the factors too, but the slip is where the transpose sits: a transpose;
    the near miss ``K J.T`` for ``J.T K`` (two matrices) is the factors' order."""
    J = [np.array([[0.3, 1.0, -0.2], [0.5, 0.1, 0.7], [-0.4, 0.6, 0.9]]),
         np.array([[1.1, -0.3, 0.2], [0.0, 0.8, -0.5], [0.6, 0.4, 0.3]])]
    K = [np.array([[0.2, 0.1, 0.0], [1.0, -0.5, 0.3], [0.4, 0.4, -0.8]]),
         np.array([[-0.6, 0.9, 0.1], [0.3, 0.2, 1.2], [0.7, -0.1, 0.5]])]
    inputs = list(zip(J, K))
    names, found = names_of(made_up, "gram", lambda J, K: (J @ J.T + 2.0 * np.eye(3), J.T @ K), inputs, (0,))
    assert names == {"transpose"}, [(h.name, h.detail) for h in found]
    assert any("a product in `gram` transposes the wrong factor" in h.detail for h in found)
    names, found = names_of(made_up, "gram", lambda J, K: (J.T @ J + 2.0 * np.eye(3), K @ J.T), inputs, (1,))
    assert names == {"factor_order"}, [(h.name, h.detail) for h in found]


def test_an_exchange_inside_a_loops_iterable_is_tried(made_up):
    """``zip((m2, m1), points)``: the loop runs as often, its parts paired with each other's mass."""
    def exchanged(m1, m2, points):
        return np.array([m1, 2.0 * m2]) + m2 * points[0] + m1 * points[1]

    inputs = [(1.0, 2.5, [V(0.1, 0.2), V(-0.3, 0.4)]), (0.4, 1.5, [V(0.7, -0.2), V(0.3, 0.8)])]
    names, found = names_of(made_up, "loads", exchanged, inputs)
    assert names == {"swapped"}, [(h.name, h.detail) for h in found]
    assert any("two entries that `loads` builds are exchanged" in h.detail for h in found)


def test_two_gains_exchanged_in_one_expression_are_swapped(made_up):
    """``D_GAIN (q_des - q) + P_GAIN (qd_des - qd)``: two constants of one kind exchanged."""
    def exchanged(q, qd, q_des, qd_des):
        return 1.5 * (q_des - q) + 4.0 * (qd_des - qd)

    names, found = names_of(made_up, "track", exchanged, [(V(0.5, -1.0), V(2.0, 0.4), V(0.1, 0.2), V(-0.3, 0.9)),
                                                           (V(1.2, 0.3), V(-0.5, 0.8), V(0.7, -1.1), V(0.4, 0.6))])
    assert names == {"swapped"}, [(h.name, h.detail) for h in found]


def test_a_skew_matrix_transposed_is_a_sign_or_a_transpose(made_up):
    """``v + lever @ w`` for ``v - lever @ w``: the sign of a term, or ``lever.T @ w`` or ``w @ lever`` (a skew
    matrix transposed is the matrix negated, ``grammar.EQUIVALENCES``): a sign or a transpose, told both, never the
    factors' order."""
    def flipped(r, w, v):
        return v + np.cross(r, w) + 0.5 * r

    names, found = names_of(made_up, "transport", flipped, [(V(0.5, -1.0, 2.0), V(0.1, 0.2, 0.3), V(1.0, 0.0, 0.5)),
                                                             (V(1.2, 0.3, -0.4), V(-0.5, 0.8, 0.2), V(0.3, 0.3, 0.1))])
    assert names == {"sign_flip", "transpose"}, [(h.name, h.detail) for h in found]
    assert any("a skew matrix in `transport` is transposed" in h.detail for h in found)


def test_skew_matrices_bound_together_are_known_as_skew_matrices():
    """``Om, dOm = skew(w), skew(dw)`` binds two skew matrices at once: their products reordered or transposed are
    the skew matrix negated, as for one bound alone (``lever = skew(r)``); a name bound to something else is none."""
    tree = ast.parse("def f(w, dw, r):\n    Om, dOm = skew(w), skew(dw)\n    lever = skew(r)\n    a, b = w, skew\n"
                     "    c, d = skew(r)\n    return Om @ r")
    assert mutants._skews(tree.body[0]) == {"Om", "dOm", "lever"}


def test_two_late_arguments_of_a_call_exchanged_are_tried(made_up):
    """The fifth and the sixth argument of a call exchanged."""
    def exchanged(a, b, c, d, e, f):
        return a + 2.0 * b + 3.0 * c + 5.0 * d + 7.0 * f + 22.0 * e

    names, found = names_of(made_up, "sextet", exchanged, [(1.0, 2.0, 3.0, 4.0, 5.0, 6.0),
                                                            (0.5, -1.0, 0.3, 2.0, -0.7, 1.9)])
    assert "argument_order" in names and {DIAGNOSES[n].family for n in names} == {"order"}, names
    assert any("two arguments of a call in `sextet` are exchanged" in h.detail for h in found)


# ------------------------------------------------------------------------------------------ graded


FORMULAS, _, slot, test_the_graded_mistakes_are_of_their_families = graded_table(
    ROOT / "tests" / "engine" / "formulas.toml")


@pytest.mark.parametrize("mistake", FORMULAS, ids=lambda m: m.name)
def test_a_slip_inside_a_formula_is_named_live_and_left_to_the_submission_in_the_kit(
        mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch):
    _, theirs = assert_named_live_and_alike(mistake, tmp_path, kit_oracle, deferred_ids, slot, monkeypatch)
    if not theirs.diagnosis:
        assert mutants.KIT_NOTE in theirs.hint, theirs.hint


def test_the_trace_says_what_each_tier_found(made_up, tmp_path, monkeypatch):
    """With ``GRADER_DIAGNOSIS_TRACE`` set, an explanation writes one line: the mutants tried and kept and the
    finding; unset, nothing is written."""
    import json

    from grader.diagnosis import trace

    evidences = made_up_evidences(made_up, "difference", lambda a, b: [b - a, a * b], [(1.0, 3.0), (2.5, -0.5)])
    path = tmp_path / "trace.jsonl"
    monkeypatch.delenv(trace.VARIABLE, raising=False)
    trace.begin("p98.difference", "explain")
    mutants.mutant_slips(scene("p98.difference"), evidences)
    trace.end(None)
    assert not path.exists()
    monkeypatch.setenv(trace.VARIABLE, str(path))
    trace.begin("p98.difference", "explain")
    found = mutants.mutant_slips(scene("p98.difference"), evidences)
    trace.end(explaining._finding(found, "here"))
    record = json.loads(path.read_text().strip())
    notes = {n["what"]: n for n in record["notes"]}
    assert record["check"] == "p98.difference" and notes["mutated"]["count"] > 0
    assert {DIAGNOSES[name].family for name in notes["mutants"]["kept"]} == {"order", "sign"}
    assert set(record["finding"]["names"]) == {h.name for h in found}


@pytest.mark.skipif(not hasattr(time, "pthread_getcpuclockid"),
                    reason="no CPU clock of a thread here: the deadline counts wall time")
def test_the_deadline_counts_work_not_waiting():
    """The tier's budget is the explaining thread's CPU time, so that a loaded machine (where the thread waits for a
    core) tries what an idle one tries: waiting past the budget is not interrupted, working past it is."""
    with mutants._Deadline(0.2) as deadline:
        time.sleep(0.5)
    assert not deadline.fired
    with pytest.raises(mutants._Timeout):
        with mutants._Deadline(0.2):
            while True:
                pass


def test_a_deadline_interrupts_again_where_its_interruption_was_lost_in_a_garbage_collectors_callback():
    """An interruption that lands in a callback of the garbage collector (hypothesis keeps one for its own
    accounting) is lost there, as an exception of a finalizer is: the deadline interrupts again while the thread is
    still inside, and the work does not run on past its budget."""
    lost = []

    def slow_callback(phase, info):
        if phase == "start" and not lost:
            end = time.monotonic() + 10.0
            while time.monotonic() < end:  # the deadline's bound of wall time runs out in here, and interrupts
                pass

    hook = sys.unraisablehook
    sys.unraisablehook = lambda raised: lost.append(raised.exc_type)
    gc.callbacks.append(slow_callback)
    interrupted = False
    try:
        with mutants._Deadline(0.1):
            gc.collect()
            end = time.monotonic() + 5.0
            while time.monotonic() < end:
                pass
    except mutants._Timeout:
        interrupted = True
    finally:
        gc.callbacks.remove(slow_callback)
        sys.unraisablehook = hook
    assert lost and set(lost) == {mutants._Timeout}  # an interruption was lost in the callback
    assert interrupted


def test_the_deadline_does_not_count_the_garbage_collectors_time():
    """A full collection walks every object the process holds (a batch's worker, a test run's, holds many): its
    time is the process's, not the answer's, and a deadline that counted it once named a cause without its rival
    on a busy process.  Collections of a large heap, well past the budget of CPU time and within the bound of wall
    time, are not interrupted; work past the budget still is."""
    heap = [[] for _ in range(1_000_000)]
    with mutants._Deadline(0.3) as deadline:
        started = time.thread_time()
        while time.thread_time() - started < 0.6:
            gc.collect()
        assert deadline.spent()[0] < 0.3
    assert not deadline.fired
    assert threading.get_ident() not in mutants._COLLECTED  # a thread's account goes with its last deadline
    del heap
    with pytest.raises(mutants._Timeout):
        with mutants._Deadline(0.3):
            while True:
                pass


def test_a_constant_term_left_out_is_an_offset(made_up):
    """A term that is the same on every input, left out, puts every value off by it: an offset, not a missing term
    of the formula; a term that changes with the input, left out, stays a missing term."""
    inputs = [(1.0, 3.0), (2.5, -0.5), (-0.7, 1.9)]
    constant = made_up_evidences(made_up, "height", lambda a, b: [a * b + b], inputs)
    found = mutants.mutant_slips(scene("p98.height"), constant)
    assert found and {h.name for h in found} == {"offset"}, [(h.name, h.detail) for h in found]
    assert all("same on every input" in h.detail and "`height`" in h.detail for h in found)
    varying = made_up_evidences(made_up, "height", lambda a, b: [a * b + 0.4], inputs)
    found = mutants.mutant_slips(scene("p98.height"), varying)
    assert found and {DIAGNOSES[h.name].family for h in found} == {"missing_term"}, [(h.name, h.detail) for h in found]


def test_a_transposed_rotation_left_out_is_a_frame_slip(made_up):
    """``A_IB.T @ v`` as ``v``: the operand left out is a rotation (transposed), so the vector stays in the other
    frame's coordinates (wrong_frame), not a factor left out of a product."""
    turns = [Rotation.from_euler("xyz", angles).as_matrix() for angles in ((0.3, -0.5, 0.9), (1.1, 0.2, -0.4))]
    inputs = [(np.array([0.2, -1.0, 0.7]), turns[0]), (np.array([1.3, 0.4, -0.6]), turns[1])]
    evidences = made_up_evidences(made_up, "back", lambda v, A: v, inputs)
    found = mutants.mutant_slips(scene("p98.back"), evidences)
    assert found and {h.name for h in found} == {"wrong_frame"}, [(h.name, h.detail) for h in found]


@pytest.mark.skipif(not (hasattr(time, "pthread_getcpuclockid") and hasattr(os, "sched_setaffinity")
                         and os.path.exists(f"/proc/self/task/{os.getpid()}/schedstat")),
                    reason="no CPU clock or scheduler statistics of a thread here")
def test_a_thread_that_waits_for_a_core_is_not_stopped_early():
    """On a machine far busier than it has cores, the explaining thread waits for a core most of the time: that
    wait is not the waiting the deadline bounds, so the work is not stopped before its budget of CPU time is spent.
    Run in a child process pinned to one core beside twenty busy processes (also pinned there), within a generous
    bound."""
    import subprocess
    import sys

    script = """
import os, time
from grader.diagnosis import mutants

os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
hogs = []
for _ in range(20):
    pid = os.fork()
    if pid == 0:
        while True:
            pass
    hogs.append(pid)
try:
    clock = time.pthread_getcpuclockid(__import__("threading").get_ident())
    started, cpu = time.monotonic(), time.clock_gettime(clock)
    try:
        with mutants._Deadline(0.2) as deadline:
            while time.clock_gettime(clock) - cpu < 0.15:
                pass
    except mutants._Timeout:
        pass
    print(deadline.fired, time.monotonic() - started)
finally:
    for pid in hogs:
        os.kill(pid, 9)
        os.waitpid(pid, 0)
"""
    run = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    fired, wall = run.stdout.split()
    assert float(wall) > mutants.WAIT_FACTOR * 0.2  # it did wait for the core far longer than the wall-time bound
    assert fired == "False"


# ------------------------------------------------------------------------------------------ ratios, neighbours, halves


def test_a_ratio_upside_down_is_an_inverse_slip(made_up):
    """``omega / (2 pi)`` where the period ``2 pi / omega`` belongs: a ratio turned upside down, not a product for
    a division."""
    def inverted(m, k):
        omega = np.sqrt(k / m)
        return np.array([omega / (2.0 * np.pi), omega])

    names, found = names_of(made_up, "oscillation", inverted, [(2.0, 5.0), (0.7, 3.0)])
    assert names == {"ratio_inverted"}, [(h.name, h.detail) for h in found]
    assert any("a ratio in `oscillation` is upside down" in h.detail for h in found)


def test_a_ratio_without_its_numerator_of_constants_is_a_factor_left_out(made_up):
    """``1 / omega`` where the period ``2 pi / omega`` belongs: the factor 2 pi of the numerator left out (a frequency
    in cycles where radians belong); the near miss ``pi / omega`` (half of it) is no factor left out."""
    def cycles(m, k):
        omega = np.sqrt(k / m)
        return np.array([1.0 / omega, omega])

    def half(m, k):
        omega = np.sqrt(k / m)
        return np.array([np.pi / omega, omega])

    names, found = names_of(made_up, "oscillation", cycles, [(2.0, 5.0), (0.7, 3.0)])
    assert "missing_factor" in names, [(h.name, h.detail) for h in found]
    names, found = names_of(made_up, "oscillation", half, [(2.0, 5.0), (0.7, 3.0)])
    assert "missing_factor" not in names, [(h.name, h.detail) for h in found]


def test_a_product_for_a_ratio_is_not_a_ratio_upside_down(made_up):
    """The near miss: ``2 pi omega`` multiplies where the ratio divides; no ratio is upside down.  The product by
    omega where the division by it belongs uses omega as its reciprocal: told beside the factor, as its twin."""
    def multiplied(m, k):
        omega = np.sqrt(k / m)
        return np.array([2.0 * np.pi * omega, omega])

    names, found = names_of(made_up, "oscillation", multiplied, [(2.0, 5.0), (0.7, 3.0)])
    assert names == {"wrong_factor", "reciprocal_argument"}, [(h.name, h.detail) for h in found]
    assert {h.name for h in found if h.twin} == {"reciprocal_argument"}


GIMBALS = [(0.4, -0.7, V(0.3, 1.0, -0.5)), (1.2, 0.5, V(-0.8, 0.2, 0.6))]


def test_two_neighbouring_rotations_exchanged_are_rotations_in_the_wrong_order(made_up):
    """``R3(a) R3(b / 2) R1(b)``: the two inner rotations of a longer product exchanged (no exchange
    of the operands of one ``@`` gives it)."""
    def exchanged(a, b, v):
        P = importlib.import_module(f"{made_up.__name__}.problem_98")
        return P.R3(a) @ P.R3(0.5 * b) @ P.R1(b) @ v

    names, found = names_of(made_up, "gimbal", exchanged, GIMBALS)
    assert names and {DIAGNOSES[n].family for n in names} == {"order"}, [(h.name, h.detail) for h in found]
    assert "rotation_order" in names, [(h.name, h.detail) for h in found]


def test_a_product_of_rotations_reversed_is_no_neighbouring_exchange(made_up):
    """The near miss: the whole product reversed is no exchange of two neighbours."""
    def reversed_(a, b, v):
        P = importlib.import_module(f"{made_up.__name__}.problem_98")
        return P.R3(0.5 * b) @ P.R1(b) @ P.R3(a) @ v

    names, found = names_of(made_up, "gimbal", reversed_, GIMBALS)
    assert "rotation_order" not in names and "factor_order" not in names, [(h.name, h.detail) for h in found]


def test_a_runs_state_read_as_alternate_entries_is_a_state_row_slip(made_up):
    """``q, qd = y[::2], y[1::2]`` where the state is ``(q, qd)``: its parts read as interleaved pairs."""
    def interleaved(t, y):
        q, qd = y[::2], y[1::2]
        return np.concatenate([qd, -3.0 * q - 0.5 * qd + np.array([t, 0.0])])

    names, found = names_of(made_up, "rates", interleaved, STATES)
    assert names == {"state_row"}, [(h.name, h.detail) for h in found]
    assert any("`rates` reads the parts of the state from alternate entries" in h.detail for h in found)


def test_a_vector_that_is_no_state_read_as_alternate_entries_is_no_state_row_slip(made_up):
    """The near miss: the halves of a vector that is no run's state read as alternate entries."""
    def interleaved(v, w):
        a, b = v[::2], v[1::2]
        return np.concatenate([b + w, 2.0 * a - b])

    names, found = names_of(made_up, "halves", interleaved, [(V(0.5, -1.0, 2.0, 0.4), V(1.0, 2.0)),
                                                              (V(-0.2, 0.7, -0.6, 1.5), V(0.3, -0.4))])
    assert "state_row" not in names, [(h.name, h.detail) for h in found]


LINKS = [(np.array([[0.3, -1.0], [0.5, 0.2], [1.1, 0.4]]), np.array([[0.0, 0.7], [1.0, -0.3], [0.2, 0.9]]),
          V(0.8, -0.6)),
         (np.array([[-0.4, 0.6], [0.9, 1.3], [0.1, -0.8]]), np.array([[0.5, 0.0], [-0.2, 1.0], [0.7, 0.3]]),
          V(-1.2, 0.5))]


def test_a_matrix_read_for_its_sibling_is_named(made_up):
    """``B_J_R qd`` where ``B_J_S qd`` belongs: the rotational Jacobian for the translational one."""
    def sibling(B_J_S, B_J_R, qd):
        return np.concatenate([B_J_R @ qd, 2.0 * B_J_R @ qd])

    names, found = names_of(made_up, "link_rates", sibling, LINKS)
    assert names == {"sibling_matrix"}, [(h.name, h.detail) for h in found]
    assert any("`link_rates` reads a matrix where its sibling belongs" in h.detail for h in found)


def test_a_sum_of_sibling_matrices_is_no_sibling_read(made_up):
    """The near miss: ``(B_J_S + B_J_R) qd`` reads both; no one read of a sibling gives it."""
    def summed(B_J_S, B_J_R, qd):
        return np.concatenate([(B_J_S + B_J_R) @ qd, 2.0 * B_J_R @ qd])

    names, found = names_of(made_up, "link_rates", summed, LINKS)
    assert "sibling_matrix" not in names, [(h.name, h.detail) for h in found]


def test_the_siblings_by_the_course_notation():
    assert mutants._siblings("B_J_S", "B_J_R") and mutants._siblings("S_J_R", "S_J_S")
    assert not mutants._siblings("I_r_IB", "I_r_IC")  # two points' positions: no pair of matrices
    assert not mutants._siblings("B_v_B", "B_a_B")  # a rate, told as one
    assert not mutants._siblings("A_IB", "A_IC")  # two frames, told as one


MOMENTS = [(V(1.0, 0.5, -0.3), V(0.2, -0.4, 0.6), V(0.3, 1.1, -0.2), V(-0.5, 0.4, 0.9), V(0.7, -0.2, 1.3)),
           (V(-0.6, 1.2, 0.4), V(0.9, 0.3, -0.5), V(-1.0, 0.2, 0.6), V(0.4, -0.7, 0.1), V(0.2, 0.8, -0.4))]


def test_a_position_taken_from_the_origin_is_an_offset_slip(made_up):
    """``I_r_IP x f`` where ``(I_r_IP - I_r_IC) x f`` belongs: the moment about the origin, not about C; the point
    subtracted from a position is no term of a sum."""
    def about_origin(I_r_IP, I_r_IC, I_v_P, I_v_C, f):
        return np.concatenate([np.cross(I_r_IP, f), I_v_P - I_v_C])

    names, found = names_of(made_up, "moment_about", about_origin, MOMENTS)
    assert names == {"from_origin"}, [(h.name, h.detail) for h in found]
    assert any("`moment_about` measures a position from the origin" in h.detail for h in found)


def test_a_velocity_left_out_of_a_difference_is_a_missing_term(made_up):
    """The near miss: ``I_v_P`` where ``I_v_P - I_v_C`` belongs is no position: a term left out."""
    def absolute(I_r_IP, I_r_IC, I_v_P, I_v_C, f):
        return np.concatenate([np.cross(I_r_IP - I_r_IC, f), I_v_P])

    names, found = names_of(made_up, "moment_about", absolute, MOMENTS)
    assert names == {"missing_term"}, [(h.name, h.detail) for h in found]


def test_an_argument_left_out_of_every_product_is_a_missing_factor(made_up):
    """``(-sin q, cos q)`` where ``(-d sin q, d cos q)`` belongs: the length left out of both products (one slip,
    made twice)."""
    def without(q, d):
        return np.array([-np.sin(q), np.cos(q), q])

    names, found = names_of(made_up, "arm", without, [(0.4, 2.0), (-1.1, 0.7)])
    assert names == {"missing_factor"}, [(h.name, h.detail) for h in found]
    assert any("`arm` leaves one of its arguments out of every product" in h.detail for h in found)


def test_an_argument_read_also_in_a_sum_is_not_left_out_of_its_products(made_up):
    """The near miss: where the argument is also a term of a sum, leaving it out of the products alone is two
    slips, and it is not dropped everywhere."""
    def without(q, d):
        return np.array([-np.sin(q), np.cos(q), q + d])

    names, found = names_of(made_up, "arm_reach", without, [(0.4, 2.0), (-1.1, 0.7)])
    assert "missing_factor" not in names, [(h.name, h.detail) for h in found]
    assert mutants._factors_only(*_region_of(made_up, "arm_reach"), ["q", "d"]) == []
    assert mutants._factors_only(*_region_of(made_up, "arm"), ["q", "d"]) == ["d"]


def _region_of(made_up, name):
    """The definition of the made-up problem's function ``name`` and the lines of its region."""
    root, _ = mutants._package()
    function = next(f for f in mutants._functions(str(root)) if f.path[-1] == name)
    return function.node, tuple((first, last) for _, first, last in function.regions)


def test_the_second_term_of_a_difference_alone_with_its_minus_is_the_first_left_out_too(tmp_path):
    """``I_G - m r r^T``: the first term of the difference left out, the second keeping its minus (as ``-qd`` for
    ``qd_des - qd``), beside the second read as it is (``+ m r r^T``); the near miss, the second term halved as
    well, is not that slip."""
    found = slips_of(tmp_path, "p19.parallel_axis", "inertia.py",
                     "return as_matrix(I_G) + m * ((r @ r) * np.eye(3) - np.outer(r, r))",
                     "return as_matrix(I_G) - m * np.outer(r, r)", "problem_19.parallel_axis", STEINER)
    assert any("the first term of a difference" in h.detail for h in found), [(h.name, h.detail) for h in found]
    found = slips_of(tmp_path / "near", "p19.parallel_axis", "inertia.py",
                     "return as_matrix(I_G) + m * ((r @ r) * np.eye(3) - np.outer(r, r))",
                     "return as_matrix(I_G) - 0.5 * m * np.outer(r, r)", "problem_19.parallel_axis", STEINER)
    assert not any("the first term of a difference" in h.detail for h in found), [(h.name, h.detail) for h in found]


def test_a_term_written_with_a_plus_given_a_minus_is_a_sign_slip(made_up):
    """``-c / 2`` where ``+c / 2`` is written: a sign slip; ``-c`` there (a sign and a factor) names no sign."""
    inputs = [(0.8,), (-1.3,)]

    def minus(c):
        return np.array([[0.0, 0.0], [c, 0.5 * c], [-c / 4, -c / 2]])

    names, found = names_of(made_up, "harmonics", minus, inputs)
    assert names == {"sign_flip"}, [(h.name, h.detail) for h in found]
    near = names_of(made_up, "harmonics", lambda c: np.array([[0.0, 0.0], [c, 0.5 * c], [-c / 4, -c]]), inputs)
    assert near[0] == set(), [(h.name, h.detail) for h in near[1]]


def test_an_entry_written_into_a_neighbouring_row_is_a_wrong_index(made_up):
    """A row of a table written into the row before its own: an entry at a neighbouring index (a state read from
    the wrong row's family); the row written into its neighbour with one entry changed as well names nothing."""
    inputs = [(0.8,), (-1.3,)]
    names, found = names_of(made_up, "harmonics", lambda c: np.array([[c, 0.5 * c], [0.0, 0.0], [-c / 4, c / 2]]),
                            inputs)
    assert names == {"wrong_index"}, [(h.name, h.detail) for h in found]
    assert any("`harmonics` writes an entry into a neighbouring index" in h.detail for h in found)
    near = names_of(made_up, "harmonics", lambda c: np.array([[c, c], [0.0, 0.0], [-c / 4, c / 2]]), inputs)
    assert near[0] == set(), [(h.name, h.detail) for h in near[1]]


def test_a_value_an_object_keeps_added_to_where_it_is_replaced_is_an_extra_term(made_up):
    """``self.r = self.r + r`` where ``self.r = r`` belongs: the old offset kept and the new one added (an extra
    term); the new one subtracted from the old (two slips) names nothing."""
    inputs = [(V(0.3, -0.2, 0.5), V(1.0, 0.4, -0.7)), (V(-0.6, 0.1, 0.4), V(0.2, 0.9, 0.3))]
    names, found = names_of(made_up, "moved", lambda a, b: a + b, inputs)
    assert names == {"extra_term"}, [(h.name, h.detail) for h in found]
    assert any("`set` adds a new value to the one its object keeps" in h.detail for h in found)
    near = names_of(made_up, "moved", lambda a, b: a - b, inputs)
    assert near[0] == set(), [(h.name, h.detail) for h in near[1]]


def test_one_factor_of_a_product_inverted_where_the_products_inverse_belongs(made_up):
    """``inv(A) @ B @ w`` where ``solve(A @ B, w)`` belongs: one factor inverted, the other multiplied (a matrix
    used where its inverse belongs); with ``B`` transposed as well (two slips) nothing is named."""
    lopsided = SPD + np.array([[0.0, 0.6, 0.0], [0.0, 0.0, 0.0], [-0.3, 0.0, 0.0]])
    inputs = [(ROTATIONS[0], lopsided, V(0.3, -1.0, 0.5)), (ROTATIONS[1], 1.5 * lopsided, V(1.0, 0.4, -0.7))]
    names, found = names_of(made_up, "step_rates", lambda A, B, w: np.linalg.inv(A) @ B @ w, inputs)
    assert names == {"no_inverse"}, [(h.name, h.detail) for h in found]
    assert any("inverts one factor of a product where the whole product's inverse belongs" in h.detail
               for h in found)
    near = names_of(made_up, "step_rates", lambda A, B, w: np.linalg.inv(A) @ B.T @ w, inputs)
    assert near[0] == set(), [(h.name, h.detail) for h in near[1]]


def test_a_matrix_written_out_transposed_is_a_transpose(made_up):
    """A matrix written out row by row with its rows as columns: a transpose (a product with it exchanged or
    transposed gives the same, but this one is returned); its rows exchanged as well names nothing."""
    inputs = [(0.4, -1.5), (-1.2, 0.7)]
    names, found = names_of(made_up, "shear", lambda k, d: np.array([[1.0, 0.0, 0.0], [k, 1.0, 0.0], [0.0, d, 1.0]]),
                            inputs)
    assert names == {"transpose"}, [(h.name, h.detail) for h in found]
    near = names_of(made_up, "shear", lambda k, d: np.array([[k, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, d, 1.0]]), inputs)
    assert near[0] == set(), [(h.name, h.detail) for h in near[1]]


def test_a_quantity_left_out_of_a_quotients_numerator_is_a_factor_left_out(made_up):
    """``m / 12 * a**2`` written ``a**2 / 12``: the mass, the numerator of a division by a number, is left out; the
    near miss ``m / 6 * a**2`` (a number typed otherwise) is no factor left out."""
    inputs = [(2.0, 0.7), (0.6, 1.9)]
    names, found = names_of(made_up, "box_moment", lambda m, a: a**2 / 12, inputs)
    assert names == {"missing_factor"}, [(h.name, h.detail) for h in found]
    near = names_of(made_up, "box_moment", lambda m, a: m / 6 * a**2, inputs)
    assert "missing_factor" not in near[0], [(h.name, h.detail) for h in near[1]]


def test_the_identity_left_out_of_a_product_is_told_so_not_as_a_factor_left_out(made_up):
    """``(r @ r) * np.eye(3)`` written ``r @ r``: the number is added to every entry, not to the diagonal alone (a
    term of the identity's own, told beside the identity written as the number 1, a term added); the near miss
    ``2 (r @ r) E`` (the number doubled) is no identity left out."""
    inputs = [(2.0, np.array([0.3, -0.7, 1.1])), (0.6, np.array([-1.2, 0.4, 0.5]))]
    names, found = names_of(made_up, "steiner", lambda m, r: m * ((r @ r) - np.outer(r, r)), inputs)
    assert "missing_identity" in names and "missing_factor" not in names, [(h.name, h.detail) for h in found]
    assert {DIAGNOSES[n].family for n in names} <= {"missing_term", "extra_term"}, names
    assert any("the identity matrix of a product in `steiner` is left out" in h.detail for h in found)
    near = names_of(made_up, "steiner", lambda m, r: m * (2 * (r @ r) * np.eye(3) - np.outer(r, r)), inputs)
    assert "missing_identity" not in near[0], [(h.name, h.detail) for h in near[1]]


def test_the_start_read_where_the_value_computed_from_it_belongs_is_a_start_value(made_up):
    """``np.linalg.norm(DRIFT_START)`` for ``np.linalg.norm(x)``, where ``x`` is computed from ``DRIFT_START``: the
    start returned for the end (an initial state); the near miss, the end after one step fewer, is no start read."""
    inputs = [(np.array([0.3, 0.1, -0.2]), 4), (np.array([-0.5, 0.7, 0.2]), 3)]

    def told(size):  # the end compared (right) and its length (the student's ``size``)
        def student(rate, n):
            return {"x": DRIFT_START + n * rate, "size": size(rate, n)}
        evidences = [e for path in (("x",), ("size",)) for e in made_up_evidences(made_up, "drift", student, inputs,
                                                                                    path)]
        found = mutants.mutant_slips(scene("p98.made_up"), evidences)
        return {h.name for h in found}, found

    names, found = told(lambda rate, n: float(np.linalg.norm(DRIFT_START)))
    assert names == {"start_value"}, [(h.name, h.detail) for h in found]
    assert DIAGNOSES["start_value"].family == "initial_state"
    near = told(lambda rate, n: float(np.linalg.norm(DRIFT_START + (n - 1) * rate)))
    assert "start_value" not in near[0], [(h.name, h.detail) for h in near[1]]


def test_every_parameter_read_as_its_default_is_every_argument_ignored(made_up):
    """``np.diag([I_AXIS, I_ACROSS, I_ACROSS])`` for ``np.diag([I_axis, I_across, I_across])``: the module's
    constants, whatever the arguments (every argument ignored at once); the near miss, one of them read so, is the
    one argument ignored."""
    inputs = [(4.0, 6.0), (1.5, 0.5)]
    told = "reads every parameter that has a default as that default"
    names, found = names_of(made_up, "rotor_inertia", lambda a, b: np.diag([2.0, 3.5, 3.5]), inputs)
    assert names == {"ignored_argument"} and any(told in h.detail for h in found), [(h.name, h.detail) for h in found]
    names, found = names_of(made_up, "rotor_inertia", lambda a, b: np.diag([2.0, b, b]), inputs)
    assert names == {"ignored_argument"} and not any(told in h.detail for h in found), \
        [(h.name, h.detail) for h in found]


def test_a_coordinate_unpacked_into_the_slot_left_unread_is_read_from_the_wrong_row(made_up):
    """``_, q1 = np.asarray(q)`` for ``q1, _ = ...``: the angle read from the other coordinate's row (a state read
    from the wrong row); the near miss, the lengths unpacked so, is two entries exchanged.  Two names of the state
    exchanged (``q2, q1 = q``) stay two quantities exchanged (an order), as the planted suite's and the held-out
    sets' unpackings are."""
    inputs = [((0.3, 1.1), (1.0, 0.6)), ((-0.7, 0.4), (0.8, 1.3))]
    names, found = names_of(made_up, "elbow_height", lambda q, l: l[0] * np.sin(q[1]) + 0.1 * l[0], inputs)
    assert names == {"state_row"}, [(h.name, h.detail) for h in found]
    near = names_of(made_up, "elbow_height", lambda q, l: l[1] * np.sin(q[0]) + 0.1 * l[1], inputs)
    assert "state_row" not in near[0] and "swapped" in near[0], [(h.name, h.detail) for h in near[1]]
    pair = ast.parse("q2, q1 = q").body[0]
    assert not mutants._unpacked_coordinates(pair.targets[0], pair)


def test_the_first_term_of_a_difference_left_out_keeps_the_second_ones_minus(made_up):
    """``-D rate`` for ``D (rate_des - rate)``: the desired rate left out, the measured one keeping its minus (a
    term left out); the near miss, ``-D rate_des``, is no first term left out."""
    inputs = [(2.0, 0.7, -0.4), (0.5, -1.3, 0.9)]
    names, found = names_of(made_up, "damping", lambda D, rate_des, rate: -D * rate, inputs)
    assert "missing_term" in names, [(h.name, h.detail) for h in found]
    assert any("the first term of a difference" in h.detail for h in found), [h.detail for h in found]
    near = names_of(made_up, "damping", lambda D, rate_des, rate: -D * rate_des, inputs)
    assert not any("the first term of a difference" in h.detail for h in near[1]), [h.detail for h in near[1]]


def test_a_loop_of_steps_one_step_long_is_a_step_count(made_up):
    """``range(n + 1)`` for ``range(n)`` in a loop of steps: one step too many (the step count); the near miss, two
    steps more, is none."""
    inputs = [(np.array([0.3, 0.1, -0.2]), 4), (np.array([-0.5, 0.7, 0.2]), 3)]

    def after(steps):
        return lambda rate, n: {"x": DRIFT_START + (n + steps) * rate,
                                "size": float(np.linalg.norm(DRIFT_START + (n + steps) * rate))}

    names, found = names_of(made_up, "drift", after(1), inputs, ("x",))
    assert names == {"step_count"}, [(h.name, h.detail) for h in found]
    assert any("one step too many" in h.detail for h in found), [h.detail for h in found]
    assert "step_count" not in names_of(made_up, "drift", after(2), inputs, ("x",))[0]


def test_a_power_or_a_root_over_the_wrong_part_of_a_product_is_a_wrong_factor(made_up):
    """``(m a)**2`` for ``m a**2`` and ``np.sqrt(3 S) / m`` for ``np.sqrt(3 S / m)``: a bracket misplaced, a factor
    raised to the power (or out of the root) with the other; the near misses, a cube and a root of 2 S, are
    neither."""
    inputs = [(2.0, 0.7, 0.3), (0.6, 1.9, 1.1)]
    names, found = names_of(made_up, "rod_impulse", lambda m, a, theta: -m * theta / ((m * a) ** 2 + theta), inputs)
    assert names == {"wrong_factor"}, [(h.name, h.detail) for h in found]
    assert any("raises a whole product to a power" in h.detail for h in found), [h.detail for h in found]
    near = names_of(made_up, "rod_impulse", lambda m, a, theta: -m * theta / (m * a**3 + theta), inputs)
    assert not any("raises a whole product" in h.detail for h in near[1]), [h.detail for h in near[1]]
    inputs = [(2.0, 0.7), (0.6, 1.9)]
    names, found = names_of(made_up, "spread", lambda S, m: np.sqrt(3 * S) / m, inputs)
    assert any("out of a square root" in h.detail for h in found), [(h.name, h.detail) for h in found]
    near = names_of(made_up, "spread", lambda S, m: np.sqrt(2 * S / m), inputs)
    assert not any("out of a square root" in h.detail for h in near[1]), [h.detail for h in near[1]]


def test_a_vector_written_out_and_passed_with_the_wrong_sign_is_a_sign(made_up):
    """``np.add(r0, -offset)`` where ``offset = np.array([...])`` is read twice: that argument's sign alone (the
    vector's own sign would change both reads); the near miss, half the vector passed, is no sign."""
    inputs = [(np.array([0.3, -1.0, 0.5]), 0.7), (np.array([1.2, 0.4, -0.6]), -0.4)]

    def ends(r0, d, sign=-1.0, scale=1.0):
        offset = np.array([d, 0.0, 0.5 * d])
        return np.concatenate([r0 + sign * scale * offset, 2.0 * (r0 - offset)])

    names, found = names_of(made_up, "arm_ends", lambda r0, d: ends(r0, d), inputs)
    assert names == {"sign_flip"}, [(h.name, h.detail) for h in found]
    assert "sign_flip" not in names_of(made_up, "arm_ends", lambda r0, d: ends(r0, d, 1.0, 0.5), inputs)[0]


def test_a_matrix_factor_of_a_product_left_out_is_a_term_left_out_not_a_scale(made_up):
    """``-x`` for ``-(K @ x)``: the matrix of the product left out changes what the product is, not its scale (a
    missing term, as the held-out sets label it); a number left out stays a factor left out."""
    inputs = [(SPD, V(0.3, -1.0, 0.5)), (2.0 * SPD + np.eye(3), V(-0.8, 0.2, 1.1))]
    names, found = names_of(made_up, "spring_back", lambda K, x: -x + 0.1 * x, inputs)
    assert "missing_matrix_factor" in names and "missing_factor" not in names, [(h.name, h.detail) for h in found]
    assert DIAGNOSES["missing_matrix_factor"].family == "missing_term"
    names, found = names_of(made_up, "spring_back", lambda K, x: -(K @ x) + x, inputs)
    assert "missing_matrix_factor" not in names, [(h.name, h.detail) for h in found]


def test_a_comprehensions_later_loop_one_short_is_a_term_left_out(made_up):
    """``for w in (1.0,)`` for ``for w in (1.0, 0.5)``, the second loop of a comprehension one short: the terms of
    its last item are left out of the sum, as with its first loop; the near miss, every value weighed 1.4, is no
    loop cut."""
    inputs = [(np.array([0.3, 1.2, -0.7]),), (np.array([2.0, -0.4, 0.9, 1.1]),)]
    names, found = names_of(made_up, "weighed", lambda values: float(np.sum(values)), inputs)
    assert names == {"missing_term"}, [(h.name, h.detail) for h in found]
    assert any("stops one short" in h.detail for h in found), [h.detail for h in found]
    near = names_of(made_up, "weighed", lambda values: 1.4 * float(np.sum(values)), inputs)
    assert not any("stops one short" in h.detail for h in near[1]), [(h.name, h.detail) for h in near[1]]


def test_a_rotation_written_out_transposed_is_also_the_rotation_the_other_way(made_up):
    """A rotation written out with the signs of its sines exchanged is its transpose and the rotation by the
    negated angle (``grammar.EQUIVALENCES``): told both; the shear's transpose above is no rotation and is told a
    transpose alone, and so is a skew matrix written out (a zero diagonal: its transpose is its negative)."""
    inputs = [(0.4,), (-1.1,)]
    names, found = names_of(made_up, "turn", lambda phi: np.array(
        [[np.cos(phi), np.sin(phi), 0.0], [-np.sin(phi), np.cos(phi), 0.0], [0.0, 0.0, 1.0]]), inputs)
    assert names == {"transpose", "angle_sign"}, [(h.name, h.detail) for h in found]
    assert any("a rotation written out in `turn` is transposed" in h.detail for h in found), [h.detail for h in found]
    assert not mutants._turning(ast.parse("[[0, -z, y], [z, 0, -x], [-y, x, 0]]", mode="eval").body)
    assert not mutants._turning(ast.parse("[[1.0, k, 0.0], [0.0, 1.0, d], [0.0, 0.0, 1.0]]", mode="eval").body)


def test_two_arguments_exchanged_into_a_given_difference_could_be_order_or_sign(made_up):
    """``feedback(q, qd_des, q_des, qd)``: the measured and the desired rate exchanged in the region's call of the
    given PD law negate its derivative part, a sign slip that lives in the given code (``OPPOSITES``): the region's
    exchange is not told alone where the given code's sign reproduces the value as well."""
    def exchanged(q, qd, q_des, qd_des):
        return q * qd + 4.0 * (q_des - q) + 1.5 * (qd - qd_des)

    names, found = names_of(made_up, "control", exchanged, CONTROLS)
    assert {DIAGNOSES[n].family for n in names} == {"order", "sign"}, [(h.name, h.detail) for h in found]
    assert any("`feedback`" in h.detail for h in found if DIAGNOSES[h.name].family == "sign"), \
        [(h.name, h.detail) for h in found]


def test_two_arguments_exchanged_into_a_given_function_that_is_no_sign_stay_an_exchange(made_up):
    """The near miss: ``feedback(qd_des, qd, q_des, q)`` exchanges the measured position and the desired rate,
    which no sign of the given code reproduces: the exchange alone."""
    def exchanged(q, qd, q_des, qd_des):
        return q * qd + 4.0 * (q_des - qd_des) + 1.5 * (q - qd)

    names, found = names_of(made_up, "control", exchanged, CONTROLS)
    assert names and {DIAGNOSES[n].family for n in names} == {"order"}, [(h.name, h.detail) for h in found]


#: two inputs of the made-up PD law's caller ``control``
CONTROLS = [(V(0.5, -1.0), V(2.0, 0.4), V(0.1, 0.2), V(-0.3, 0.9)),
            (V(1.2, 0.3), V(-0.5, 0.8), V(0.7, -1.1), V(0.4, 0.6))]


def test_a_sign_a_check_told_has_the_exchange_that_makes_it_as_a_rival(made_up):
    """A check that tells a sign from what the value shows (``diagnosis.rival``) hears the exchanges of two operands
    whose effect that sign is (``opposite_slips``), on the input shown alone where there is no second one:
    ``np.subtract(b, a)`` for ``np.subtract(a, b)``."""
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [b - a, a * b], [(1.0, 3.0)])
    found = mutants.opposite_slips(scene("p98.difference"), evidences, "sign")
    assert {h.name for h in found} == {"argument_order"}, [(h.name, h.detail) for h in found]


def test_a_sign_no_exchange_makes_has_no_rival(made_up):
    """The near miss: the product's sign, ``-a b``, which no exchange of two operands gives, has none; nor has a
    check's name of another family than a sign."""
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [a - b, -a * b], [(1.0, 3.0)])
    assert mutants.opposite_slips(scene("p98.difference"), evidences, "sign") == []
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [b - a, a * b], [(1.0, 3.0)])
    assert mutants.opposite_slips(scene("p98.difference"), evidences, "scale") == []


def test_a_wrong_start_a_check_told_has_the_exchange_that_makes_it_as_a_rival(made_up):
    """A check that tells a wrong start from what the value shows hears the exchanges of two operands whose effect
    that start is (a signature's start values in another order): ``np.subtract(b, a)`` for ``np.subtract(a, b)``."""
    evidences = made_up_evidences(made_up, "difference", lambda a, b: [b - a, a * b], [(1.0, 3.0)])
    found = mutants.opposite_slips(scene("p98.difference"), evidences, "initial_state")
    assert {h.name for h in found} == {"argument_order"}, [(h.name, h.detail) for h in found]
    product = made_up_evidences(made_up, "difference", lambda a, b: [a - b, -a * b], [(1.0, 3.0)])
    assert mutants.opposite_slips(scene("p98.difference"), product, "initial_state") == []


def test_a_sign_a_check_told_of_a_product_with_a_skew_matrix_turned_round_has_the_exchange_as_a_rival(made_up):
    """``w @ lever`` for ``lever @ w`` (``lever = skew(r)``) is the cross product of its operands exchanged, ``w x r``
    for ``r x w``: where a check told that sign, the exchange is its rival, and not the transpose that the formula
    tier tells beside the sign (a skew matrix negated is the matrix transposed, ``test_a_skew_matrix_transposed_...``).
    The near miss, the product's sign with a term doubled, has none."""
    inputs = [(V(0.5, -1.0, 2.0), V(0.1, 0.2, 0.3), V(1.0, 0.0, 0.5)),
              (V(1.2, 0.3, -0.4), V(-0.5, 0.8, 0.2), V(0.3, 0.3, 0.1))]
    evidences = made_up_evidences(made_up, "transport", lambda r, w, v: v - np.cross(w, r) + 0.5 * r, inputs)
    found = mutants.opposite_slips(scene("p98.transport"), evidences, "sign")
    assert {h.name for h in found} == {"factor_order"}, [(h.name, h.detail) for h in found]
    assert any("cross product in `transport` are taken in the other order" in h.detail for h in found)
    doubled = made_up_evidences(made_up, "transport", lambda r, w, v: v + 2 * np.cross(r, w) + 0.5 * r, inputs)
    assert mutants.opposite_slips(scene("p98.transport"), doubled, "sign") == []


def test_a_system_solved_with_its_matrix_transposed_is_a_transpose(made_up):
    """``np.linalg.solve((A @ B).T, w)`` for ``np.linalg.solve(A @ B, w)``: the system's matrix transposed, as a
    product's factor may be; where a check told the sign its value shows, the transpose is its rival.  The near
    miss, the product's factors multiplied the other way round, is no transpose."""
    inputs = [(SPD + np.triu(np.ones((3, 3))), np.eye(3) + np.tril(np.ones((3, 3))), V(0.3, -1.0, 0.5)),
              (2.0 * SPD + np.triu(np.ones((3, 3)), 1), SPD + np.tril(np.ones((3, 3)), -1), V(-0.8, 0.2, 1.1))]
    names, found = names_of(made_up, "step_rates", lambda A, B, w: np.linalg.solve((A @ B).T, w), inputs)
    assert names == {"transpose"}, [(h.name, h.detail) for h in found]
    evidences = made_up_evidences(made_up, "step_rates", lambda A, B, w: np.linalg.solve((A @ B).T, w), inputs)
    assert {h.name for h in mutants.opposite_slips(scene("p98.step_rates"), evidences, "sign")} == {"transpose"}
    names, found = names_of(made_up, "step_rates", lambda A, B, w: np.linalg.solve(B @ A, w), inputs)
    assert "transpose" not in names, [(h.name, h.detail) for h in found]


def test_a_term_a_check_told_missing_has_the_reorder_that_makes_it_vanish_as_a_rival(made_up):
    """A check that tells a term left out from what the value shows (it vanishes) hears the reorders of two
    factors of a product whose effect that is: ``B_I_B @ skew(w) @ w`` for ``skew(w) @ B_I_B @ w`` is zero, the term
    written in an order in which it vanishes.  The near miss, half the torque, has none; nor has a check's name of
    another family."""
    inputs = [(SPD, V(0.3, -1.0, 0.5)), (2.0 * SPD + np.eye(3), V(-0.8, 0.2, 1.1))]
    evidences = made_up_evidences(made_up, "euler_torque", lambda I, w: -I @ np.cross(w, w), inputs)
    found = mutants.opposite_slips(scene("p98.euler_torque"), evidences, "missing_term")
    assert {h.name for h in found} == {"factor_order"}, [(h.name, h.detail) for h in found]
    half = made_up_evidences(made_up, "euler_torque", lambda I, w: -np.cross(w, I @ w) / 2, inputs)
    assert mutants.opposite_slips(scene("p98.euler_torque"), half, "missing_term") == []
    assert mutants.opposite_slips(scene("p98.euler_torque"), evidences, "scale") == []


#: two inputs of ``compliant_rates``
COMPLIANT = [(SPD, 1.5 * SPD + np.eye(3), V(0.3, -1.0, 0.5)), (2.0 * SPD + np.eye(3), SPD, V(-0.8, 0.2, 1.1))]


def test_every_inverse_of_a_statement_left_out_is_no_inverse(made_up):
    """``A @ B @ w`` for ``inv(A) @ solve(B, w)``: both inverses of the statement left out together; the near miss,
    one of them left out, is told as that one alone."""
    def both(A, B, w):
        return A @ B @ w

    found = mutants.mutant_slips(scene("p98.compliant_rates"), made_up_evidences(made_up, "compliant_rates", both,
                                                                                 COMPLIANT))
    assert {h.name for h in found} == {"no_inverse"}, [(h.name, h.detail) for h in found]
    assert any("every inverse" in h.detail for h in found), [h.detail for h in found]

    def one(A, B, w):
        return A @ np.linalg.solve(B, w)

    found = mutants.mutant_slips(scene("p98.compliant_rates"), made_up_evidences(made_up, "compliant_rates", one,
                                                                                 COMPLIANT))
    assert {h.name for h in found} == {"no_inverse"}, [(h.name, h.detail) for h in found]
    assert not any("every inverse" in h.detail for h in found), [h.detail for h in found]


def test_the_identity_written_as_one_is_a_term_added_and_an_offset(made_up):
    """``1.0 + c K`` for ``np.eye(3) + c K``: numpy adds the 1 to every entry, a term added that is the same on
    every input (an offset as well); the near miss, the identity's rows reversed, is no identity written as 1."""
    inputs = [(SPD, 0.5), (1.5 * SPD + np.eye(3), -1.2)]
    found = mutants.mutant_slips(scene("p98.relaxed"), made_up_evidences(made_up, "relaxed", lambda K, c: 1.0 + c * K,
                                                                         inputs))
    assert {h.name for h in found} == {"extra_term", "offset"}, [(h.name, h.detail) for h in found]
    assert any("the identity matrix as the number 1" in h.detail for h in found), [h.detail for h in found]
    found = mutants.mutant_slips(scene("p98.relaxed"), made_up_evidences(made_up, "relaxed",
                                                                         lambda K, c: np.eye(3)[::-1] + c * K, inputs))
    assert not any("the number 1" in h.detail for h in found), [(h.name, h.detail) for h in found]


def test_a_body_matrix_turned_into_inertial_coordinates_is_a_wrong_frame(made_up):
    """``A_IB @ B_I_B @ A_IB.T`` where ``B_I_B`` belongs (the rotation at hand): the body's matrix taken in inertial
    coordinates; the near miss, turned the other way (``A_IB.T @ B_I_B @ A_IB``), is not that slip."""
    inputs = [(ROTATIONS[0], INERTIA, V(0.3, -1.0, 0.5)), (ROTATIONS[1], 1.5 * INERTIA, V(-0.8, 0.2, 1.1))]

    def inertial(A_IB, B_I_B, w):
        return -np.cross(w, A_IB @ B_I_B @ A_IB.T @ w)

    found = mutants.mutant_slips(scene("p98.spin_torque"), made_up_evidences(made_up, "spin_torque", inertial,
                                                                             inputs))
    assert {DIAGNOSES[h.name].family for h in found} == {"frame"}, [(h.name, h.detail) for h in found]
    assert any("into inertial ones" in h.detail for h in found), [h.detail for h in found]

    def reversed_turn(A_IB, B_I_B, w):
        return -np.cross(w, A_IB.T @ B_I_B @ A_IB @ w)

    found = mutants.mutant_slips(scene("p98.spin_torque"), made_up_evidences(made_up, "spin_torque", reversed_turn,
                                                                             inputs))
    assert not any("into inertial ones" in h.detail for h in found), [(h.name, h.detail) for h in found]


def test_a_keyword_argument_left_out_is_a_term_left_out(made_up):
    """``_spring(x, k=k)`` for ``_spring(x, k=k, preload=preload)``: the callee's default preload (0) used, a term
    left out; the near miss, the keyword given another value (``preload=k``), is not that slip."""
    inputs = [(V(0.3, -0.2), 2.0, 0.5), (V(-0.4, 0.7), 3.0, -1.5)]
    found = mutants.mutant_slips(scene("p98.spring_force"), made_up_evidences(made_up, "spring_force",
                                                                              lambda x, k, preload: -k * x, inputs))
    assert {h.name for h in found} == {"missing_term"}, [(h.name, h.detail) for h in found]
    assert any("leaves out one of its keyword arguments" in h.detail for h in found), [h.detail for h in found]
    found = mutants.mutant_slips(scene("p98.spring_force"), made_up_evidences(made_up, "spring_force",
                                                                              lambda x, k, preload: -k * x + k, inputs))
    assert not any("keyword arguments" in h.detail for h in found), [(h.name, h.detail) for h in found]


def test_an_angle_converted_the_wrong_way_is_a_slip_of_degrees(made_up):
    """``np.rad2deg(bearing)`` where ``np.deg2rad`` belongs: the conversion the other way; the near miss, the
    bearing turned by a right angle before its conversion, is no such slip."""
    def back(bearing, distance):
        angle = np.rad2deg(bearing)
        return distance * np.array([np.cos(angle), np.sin(angle)])

    def turned(bearing, distance):
        angle = np.deg2rad(bearing + 90.0)
        return distance * np.array([np.cos(angle), np.sin(angle)])

    names, found = names_of(made_up, "heading", back, [(37.0, 2.0), (-112.0, 0.7)])
    assert names == {"degrees"}, [(h.name, h.detail) for h in found]
    assert any("`heading` converts an angle the wrong way" in h.detail for h in found), [h.detail for h in found]
    names, found = names_of(made_up, "heading", turned, [(37.0, 2.0), (-112.0, 0.7)])
    assert not any("the wrong way" in h.detail for h in found), [(h.name, h.detail) for h in found]


def test_two_rotations_exchanged_across_parentheses_are_rotations_in_the_wrong_order(made_up):
    """``R1(b) (R3(a).T v)`` where ``R3(a).T (R1(b) v)`` belongs: the factor outside the parentheses exchanged with
    the first inside; the near miss, each rotation also transposed, is none."""
    P = importlib.import_module(f"{made_up.__name__}.problem_98")

    def exchanged(a, b, v):
        return P.R1(b) @ (P.R3(a).T @ v)

    def turned(a, b, v):
        return P.R1(b).T @ (P.R3(a) @ v)

    names, found = names_of(made_up, "relay", exchanged, GIMBALS)
    assert names == {"rotation_order"}, [(h.name, h.detail) for h in found]
    names, found = names_of(made_up, "relay", turned, GIMBALS)
    assert "rotation_order" not in names, [(h.name, h.detail) for h in found]


def test_arguments_unpacked_in_reverse_order_are_arguments_in_the_wrong_order(made_up):
    """``zx(*angles[::-1])`` where ``zx(*angles)`` belongs; the near miss, the first angle read twice, is no
    reversal."""
    P = importlib.import_module(f"{made_up.__name__}.problem_98")

    def reversed_(angles, v):
        return P.zx(*angles[::-1]) @ v

    def twice(angles, v):
        return P.zx(angles[0], angles[0]) @ v

    inputs = [(V(0.4, -1.1), V(0.3, 0.5, -0.2)), (V(-0.8, 0.6), V(1.0, -0.4, 0.7))]
    assert_told_not_the_near_miss(made_up, "spun", reversed_, twice, inputs, {"argument_order"},
                                  "unpacks its arguments in reverse order")


def test_two_values_of_a_dict_exchanged_are_two_entries_exchanged(made_up):
    """``{"arm": y + 1, "weight": 2 x}`` where ``{"arm": 2 x, "weight": y + 1}`` belongs (a substitution or a table
    of named values built with two values in each other's places); the near miss, the arm's factor 3 written 2, is
    no exchange."""
    def exchanged(x, y):
        return 3.0 * (y + 1.0) - 2.0 * x

    def factor(x, y):
        return 2.0 * (2.0 * x) - (y + 1.0)

    inputs = [(0.7, -1.3), (2.1, 0.4)]
    names, found = names_of(made_up, "lever", exchanged, inputs)
    assert "swapped" in names, [(h.name, h.detail) for h in found]
    assert any("two entries that `lever` builds are exchanged" in h.detail for h in found), [h.detail for h in found]
    names, found = names_of(made_up, "lever", factor, inputs)
    assert "swapped" not in names, [(h.name, h.detail) for h in found]


def test_an_angle_the_function_binds_itself_read_in_degrees_throughout_is_a_slip_of_degrees(made_up):
    """``x, z, phi = state`` with every sine and cosine of ``phi`` taken in degrees; the near miss, ``phi`` read
    shifted by a tenth, is none of degrees."""
    def degrees(state, s):
        x, z, phi = state
        return z * np.cos(np.deg2rad(phi)) - (x - s) * np.sin(np.deg2rad(phi))

    def shifted(state, s):
        x, z, phi = state
        return z * np.cos(phi + 0.1) - (x - s) * np.sin(phi + 0.1)

    inputs = [(V(0.3, 1.2, 0.4), 0.5), (V(-0.2, 0.9, -0.7), 1.1)]
    names, found = names_of(made_up, "edge", degrees, inputs)
    assert names == {"degrees"}, [(h.name, h.detail) for h in found]
    names, found = names_of(made_up, "edge", shifted, inputs)
    assert "degrees" not in names, [(h.name, h.detail) for h in found]


def test_arguments_a_call_is_to_hand_on_left_out_are_arguments_ignored(made_up):
    """``spring(x)`` where ``spring(x, **params)`` belongs: the parameters ignored, the callee's defaults used; the
    near miss, the stiffness handed on and the damping not, is no argument ignored by this slip."""
    P = importlib.import_module(f"{made_up.__name__}.problem_98")

    def left_out(x, params):
        return P.spring(x)

    def half(x, params):
        return P.spring(x, k=params["k"])

    inputs = [(0.7, {"k": 5.0, "c": 1.5}), (-1.2, {"k": 0.5, "c": 3.0})]
    assert_told_not_the_near_miss(made_up, "handed", left_out, half, inputs, {"ignored_argument"},
                                  "leaves out the arguments it is to hand on")


def test_a_default_taken_whatever_the_argument_is_an_argument_ignored(made_up):
    """``J = np.eye(3)`` where ``np.eye(3) if inertia is None else inertia`` belongs: the argument ignored; the
    near miss, the inertia given halved, is none."""
    inertia = [np.diag([1.0, 2.0, 3.0]) + 0.1, np.diag([0.5, 0.7, 0.4])]

    def ignored(m, given):
        return m * np.eye(3)

    def halved(m, given):
        return m * 0.5 * np.asarray(given) + 0.01

    inputs = [(2.0, inertia[0]), (0.7, inertia[1])]
    names, found = names_of(made_up, "scaled_inertia", ignored, inputs)
    assert names == {"ignored_argument"}, [(h.name, h.detail) for h in found]
    names, found = names_of(made_up, "scaled_inertia", halved, inputs)
    assert "ignored_argument" not in names, [(h.name, h.detail) for h in found]


def test_a_symbolic_functions_substitutions_are_not_exchanged_nor_its_angles_converted():
    """Problem 45's impact Jacobian is built with sympy and substitutes with a dict: exchanging that dict's values,
    or converting one of its angles to degrees, gives expressions that sympy grinds on for seconds each and ran the
    tier out of its time before the problem's own slips were tried.  No mutant of it changes a dict or converts an
    angle."""
    function = next(f for f in mutants._functions(str(ROOT / "reference")) if f.node.name == "impact_jacobian")
    assert mutants._symbolic(function)
    dicts = {ast.dump(node) for node in ast.walk(function.node) if isinstance(node, ast.Dict)}
    assert dicts
    lines = tuple((region[1], region[2]) for region in function.regions)
    slips = list(mutants._mutated(function, lines))
    assert slips
    for slip, tree, _, _ in slips:
        assert {ast.dump(node) for node in ast.walk(tree) if isinstance(node, ast.Dict)} <= dicts, slip
        assert slip != "converted_radians"


def test_an_angle_converted_to_degrees_before_its_sine_is_a_slip_of_degrees(made_up):
    """``phi = np.rad2deg(phi)`` before ``np.cos(phi)`` and ``np.sin(phi)``: the angle converted to degrees where
    the sines and cosines take radians; the near miss, the angle doubled, is none of it."""
    def degrees(state, s):
        x, z, phi = state
        phi = np.rad2deg(phi)
        return z * np.cos(phi) - (x - s) * np.sin(phi)

    def doubled(state, s):
        x, z, phi = state
        return z * np.cos(2.0 * phi) - (x - s) * np.sin(2.0 * phi)

    inputs = [(V(0.3, 1.2, 0.4), 0.5), (V(-0.2, 0.9, -0.7), 1.1)]
    assert_told_not_the_near_miss(made_up, "edge", degrees, doubled, inputs, {"degrees"},
                                  "converts an angle to degrees")


def test_an_event_that_returns_a_test_or_a_magnitude_is_a_slip_of_the_event(made_up):
    """``y[0] - 0.2 + 0.05 t > 0`` and ``abs(y[0] - 0.2 + 0.05 t)`` where the residual itself belongs: solve_ivp
    finds no sign change of either; the near miss, the step at 0.3, is no slip of the event."""
    def test(t, y):
        return float(y[0] - 0.2 + 0.05 * t > 0)

    def magnitude(t, y):
        return abs(y[0] - 0.2 + 0.05 * t)

    def higher(t, y):
        return y[0] - 0.3 + 0.05 * t

    inputs = [(0.4, V(0.1, -1.0)), (1.3, V(0.5, 2.0))]
    for student in (test, magnitude):
        assert_told_not_the_near_miss(made_up, "clearance", student, higher, inputs, {"event_residual"},
                                      "returns a test or a magnitude")


def test_a_sine_and_a_cosine_exchanged_throughout_a_statement_are_sin_for_cos(made_up):
    """``q = 3 s + 0.5 c`` where ``q = 3 c + 0.5 s`` belongs, ``c, s = np.cos(w t), np.sin(w t)`` and the rates
    right: the two names exchanged in one statement (not where they are bound, which would change the rates too);
    the near miss, both harmonics of q shifted in phase, is no such exchange."""
    def exchanged(t):
        w = np.array([1.0, 2.0])
        c, s = np.cos(w * t), np.sin(w * t)
        return np.concatenate([3.0 * s + 0.5 * c, w * (0.5 * c - 3.0 * s)])

    def shifted(t):
        w = np.array([1.0, 2.0])
        c, s = np.cos(w * t), np.sin(w * t)
        return np.concatenate([3.0 * np.cos(w * t + 0.5) + 0.5 * np.sin(w * t + 0.5), w * (0.5 * c - 3.0 * s)])

    assert_told_not_the_near_miss(made_up, "harmonic", exchanged, shifted, [(0.6,), (1.7,)], {"sin_cos_swapped"},
                                  "in one expression")


def test_a_list_of_angles_passed_in_reverse_order_is_arguments_in_the_wrong_order(made_up):
    """``zx_of(angles[::-1])`` where ``zx_of(angles)`` belongs; the near miss, the first angle read twice, is no
    reversal."""
    P = importlib.import_module(f"{made_up.__name__}.problem_98")

    def reversed_(angles, v):
        return P.zx_of(angles[::-1]) @ v

    def twice(angles, v):
        return P.zx_of([angles[0], angles[0]]) @ v

    inputs = [(V(0.4, -1.1), V(0.3, 0.5, -0.2)), (V(-0.8, 0.6), V(1.0, -0.4, 0.7))]
    assert_told_not_the_near_miss(made_up, "pointed", reversed_, twice, inputs, {"argument_order"},
                                  "is given a list of angles in reverse order")


def test_the_values_a_creator_of_arrays_fills_in_are_mutated_and_its_counts_are_not():
    """A creator's counts and shapes are never mutated (``np.zeros(n)``, ``np.full(7, ...)``'s 7, ``np.linspace``'s
    number of points: a slip there changes a count, not a value), but the values it fills in or spans are, as any
    value (``np.full(6, m / 6)``'s fill, ``np.linspace(0.0, 2 * m, n)``'s ends)."""
    import ast

    tree = ast.parse("def f(m, n):\n    a = np.full(7, m / 6)\n    b = np.linspace(0.0, 2 * m, n)\n"
                     "    c = np.full(shape=(n, 2), fill_value=m / 3)\n    return a, b, c, np.zeros(n + 1)")
    guards = {ast.unparse(node): guarded for node, guarded, _ in mutants._walk(tree)
              if isinstance(node, ast.BinOp)}
    assert guards == {"m / 6": False, "2 * m": False, "m / 3": False, "n + 1": True}, guards
    counts = {ast.unparse(node): guarded for node, guarded, _ in mutants._walk(tree)
              if isinstance(node, (ast.Constant, ast.Tuple)) and ast.unparse(node) in ("7", "(n, 2)")}
    assert counts == {"7": True, "(n, 2)": True}, counts
