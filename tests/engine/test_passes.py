"""The passes of state that the mutants' calls share (``grader.diagnosis.passes``): a kinematic tree's forward
kinematics, computed once for a tree and coordinates and set again for the later mutants.

* Every mutant of the code that problem 37's ``M, f, g``, problem 38's walker and problem 46's constraint terms run
  (the solution regions, the module's given code and the library's, the forward kinematics among them) gives, with
  the passes shared, the value it gives without them, bit for bit, or raises as it does; the passes are heard
  (kept ones set again) and a mutant of the forward kinematics' own code runs it as it is.
* A pass keeps only what it sets on the tree, its bodies and its joints, and a pass that writes into a container
  in place is not kept.
"""

import numpy as np
import pytest

from checks._dynamics import rich_case
from grader.diagnosis import mutants
from grader.diagnosis.passes import Shared


def _plain(package, probe, args, path):
    try:
        return mutants._call(package, probe, args, path)
    except Exception as exc:  # noqa: BLE001 - a mutant that raises: compared by its kind
        return type(exc)


def _alike(a, b) -> bool:
    if isinstance(a, type) or isinstance(b, type):
        return a is b
    if a is None or b is None:
        return a is b
    return a.shape == b.shape and np.array_equal(a, b, equal_nan=True)


CALLS = {
    37: ("_dynamics.mfg", lambda: rich_case(), ("f",)),
    38: ("problem_38.walker_ode", lambda: ([(0.0, np.array([0.3, -0.2, 0.7, 1.1])), (0.1, np.array([-0.4, 0.5, 0.2,
                                                                                                   -0.9]))],), (1,)),
    46: ("problem_46.constraint_terms", lambda: ([(np.array([0.4, -0.3, 0.8]), np.array([0.5, 1.2, -0.7]), True)],),
         (0, "sigma")),
}


@pytest.mark.filterwarnings("ignore::RuntimeWarning")
@pytest.mark.parametrize("problem", sorted(CALLS))
def test_every_mutant_gives_with_the_passes_shared_what_it_gives_without(problem):
    probe, make_args, path = CALLS[problem]
    root, package = mutants._package()
    args = mutants._kept_once(make_args())
    ran = mutants._traced(package, root, probe, args)
    made = [m for given, library in ((False, False), (True, False), (True, True))
            for m in mutants.mutants_of(package, root, problem, probe, args, (), ran, given=given, library=library)
            or ()]
    made = [m for m in made if not m.bindings]
    assert len(made) > 50
    originals: dict = {}
    shared = Shared(package, originals, str(root))
    of_the_pass = 0
    try:
        for mutant in made:
            holder = mutants._live(package, mutant.module, mutant.path)
            originals.setdefault(id(holder), (holder, holder.__code__))
            holder.__code__ = mutant.code
            try:
                without = _plain(package, probe, args, path)
                with shared.around(holder):
                    first = _plain(package, probe, args, path)
                    again = _plain(package, probe, args, path)
            finally:
                holder.__code__ = originals[id(holder)][1]
            assert _alike(first, without) and _alike(again, without), (mutant.function, mutant.slip, mutant.detail)
            of_the_pass += mutant.function == "forward_kinematics"
    finally:
        mutants._restore(originals)
    assert shared.hits > len(made) // 2, (shared.hits, shared.misses)
    if problem == 37:  # the library's forward kinematics is mutated too: those mutants ran it as they are
        assert of_the_pass > 0


def test_a_pass_that_writes_into_a_container_is_not_kept():
    root, package = mutants._package()
    tree_module = __import__(f"{package.__name__}.tree", fromlist=["KinematicTree"])
    shared = Shared(package, {}, str(root))
    original = tree_module.KinematicTree.forward_kinematics
    description = rich_case()[0]

    from probes._trees import build

    def appending(tree, q, qd=None, qdd=None):
        original(tree, q, qd, qdd)
        tree.bodies[1].child_joints.append(None)
        tree.bodies[1].child_joints.pop()
        tree.bodies[2].child_joints.append("x")
        return tree

    tree = build(tree_module, description)
    q = np.linspace(0.1, 0.5, tree.nq)
    kept_pass = shared._wrapped(appending)
    kept_pass(tree, q, q, q)
    assert shared.kept == {} and shared.misses == 1

    plain_pass = shared._wrapped(original)
    for _ in range(2):
        fresh = build(tree_module, description)
        plain_pass(fresh, q, q, q)
    assert len(shared.kept) == 1 and shared.hits == 1
    reached = build(tree_module, description)
    original(reached, q, q, q)
    for a, b in zip(fresh.bodies, reached.bodies):
        for name in ("A_IB", "B_r_IB", "B_v_B", "B_omega_B", "B_a_B", "B_omegaDot_B", "B_J_S", "B_J_R"):
            assert np.array_equal(getattr(a, name), getattr(b, name)), name


def test_the_pass_is_put_back_by_the_restoring_of_the_explanation():
    """The shared pass is kept in the explanation's ``originals`` as a constant's binding is: where the deadline's
    interruption cuts the block's own restoring short, ``mutants._restore`` (after the deadline) puts it back."""
    root, package = mutants._package()
    tree_module = __import__(f"{package.__name__}.tree", fromlist=["KinematicTree"])
    original = tree_module.KinematicTree.__dict__["forward_kinematics"]
    originals: dict = {}
    shared = Shared(package, originals, str(root))
    blocked = shared.around(None)
    blocked.__enter__()  # entered and never left: its own restoring cut short
    try:
        assert tree_module.KinematicTree.__dict__["forward_kinematics"] is not original
    finally:
        mutants._restore(originals)
    assert tree_module.KinematicTree.__dict__["forward_kinematics"] is original
