"""Checks of problem 9: coordinate systems defined relative to each other."""

import numpy as np

from checks._figures import add_vectors
from checks._real import require_real, rotation_flaw
from checks._rigid import ROTATIONS
from grader import strategies as st
from grader.checking import EXACT, STAGE_RANDOM, STAGE_VALUES, Mistake, as_array, assert_close, check, close, fail
from probes import problem_06 as p06, problem_09 as p09

TITLE = "A better coordinate-system class (relative transformations)"

CHAINS = st.lists(ROTATIONS, min_size=2, max_size=4).map(lambda rs: (rs,))
SHEET_VECTORS = {"I_v": (1.6319, 0.5195, 0.2588), "C1_v": (1.6730, -0.3660, 0.2588),
                 "C2_v": (1.0, -0.3660, 1.3660), "C3_v": (1.0, 1.0, 1.0)}


#: the check that grades the chain the sheet's vectors are judged on
CHAIN = "p09.chain"


def _absolute(relatives):
    """Each frame as if its A_BC were given relative to I."""
    return {"to_inertial": [np.asarray(A) for A in relatives],
            "pairs": [[np.asarray(b).T @ np.asarray(c) for b in relatives] for c in relatives]}


def _reversed_product(relatives):
    """A_IC = A_BC @ A_IB instead of A_IB @ A_BC."""
    absolute = []
    for A in relatives:
        absolute.append(np.asarray(A) if not absolute else np.asarray(A) @ absolute[-1])
    return {"to_inertial": absolute, "pairs": [[b.T @ c for b in absolute] for c in absolute]}


def _list_of(value, n, what):
    """``value`` as a list of ``n`` entries, or a failure that says what came back instead."""
    if not isinstance(value, list) or len(value) != n:
        fail(f"{what} must give {n} entries (one per frame of the chain), got {str(value)[:200]}")
    return value


def _compare_chain(got, expected, args):
    absolute, reversed_ = _absolute(args[0]), _reversed_product(args[0])
    n = len(expected["to_inertial"])
    if not isinstance(got, dict) or "pairs" not in got or "to_inertial" not in got:
        fail("the probe could not read the chain's transformations.")
    _list_of(got["to_inertial"], n, "get_transform() over the chain")
    for row in _list_of(got["pairs"], n, "get_transform(B) over the chain"):
        _list_of(row, n, "get_transform(B) over the chain")
    for i in range(n):
        assert_close(got["to_inertial"][i], expected["to_inertial"][i], f"C{i + 1}.get_transform()", EXACT, [
            Mistake("ignores_parent", absolute["to_inertial"][i],
                    "The constructor ignored the parent frame B: with B, A_IC = B.A_IC @ A_BC."),
            Mistake("rotation_order", reversed_["to_inertial"][i],
                    "The product is reversed: A_IC = A_IB @ A_BC (adjacent letters cancel), not A_BC @ A_IB."),
        ])
    for i in range(n):
        for j in range(n):
            e = np.asarray(expected["pairs"][i][j])
            assert_close(got["pairs"][i][j], e, f"C{i + 1}.get_transform(C{j + 1})", EXACT, [
                Mistake("transpose", e.T, f"You returned A_C{i + 1}C{j + 1} transposed: get_transform(B) returns "
                        f"A_BC = B.A_IC.T @ A_IC (from this frame C to B)."),
            ])


@check(3, title="frames built relative to each other report the right A_IC and A_BC for every pair",
       stage=STAGE_RANDOM, group="chain")
def check_chain(ctx):
    ctx.compare_random(p09.chain, CHAINS, name="transformations", tol=EXACT, compare=_compare_chain,
                       examples=15, describe=lambda args: f"a chain of {len(args[0])} random relative rotations")


@check(1, title="set_transform(A_BC, B) places an existing frame relative to B", stage=STAGE_RANDOM,
       group="set")
def check_set_transform(ctx):
    def compare(got, expected, args):
        A_IB, A_BC = (np.asarray(a) for a in args)
        if not isinstance(got, dict) or "A_IC" not in got or "A_BC" not in got:
            fail(f"the probe could not read A_IC and A_BC after set_transform, got {str(got)[:200]}")
        assert_close(got["A_IC"], expected["A_IC"], "A_IC after set_transform(A_BC, B)", EXACT, [
            Mistake("ignores_parent", A_BC, "set_transform ignored B: A_IC = B.A_IC @ A_BC."),
            Mistake("rotation_order", A_BC @ A_IB, "The product is reversed: A_IC = A_IB @ A_BC."),
        ])
        assert_close(got["A_BC"], expected["A_BC"], "get_transform(B) after set_transform(A_BC, B)", EXACT)

    ctx.compare_random(p09.set_later, st.tuples(ROTATIONS, ROTATIONS),
                       name="set_transform", tol=EXACT, compare=compare, examples=10)


#: the transformations of the student's own ``build_chain()`` that ``vectors()`` is judged on (probe order)
CHAIN_TRANSFORMS = ("C3.get_transform()", "C3.get_transform(C1)", "C3.get_transform(C2)", "C3.get_transform(C3)")

TYPED_HINT = (
    "These are the sheet's printed numbers (four decimals), not computed ones: compute them with get_transform "
    "over the chain; they are compared at full precision."
)


@check(1, title="the relative chain I → C1 → C2 → C3 reproduces problem 6's vectors (at full precision)",
       stage=STAGE_VALUES, group="sheet")
def check_vectors(ctx):
    reference = ctx.reference(p09.vectors_with_chain)
    answer = ctx.student(p09.vectors_with_chain)
    got = answer["vectors"]
    add_vectors(ctx, "Problem 9: V from its coordinates in I, C1, C2, C3 (mapped to I by problem 6's frames)", got,
                ctx.reference(p06.frames), SHEET_VECTORS["I_v"])
    if not isinstance(got, dict):
        fail(f"vectors() must return a dict with keys {sorted(SHEET_VECTORS)}.")
    for key in SHEET_VECTORS:
        if key not in got:
            fail(f"vectors() has no entry {key!r}.")
    vectors = {key: as_array(got[key], key, (3,)) for key in SHEET_VECTORS}
    expected = {key: np.asarray(reference["vectors"][key], dtype=float) for key in SHEET_VECTORS}
    if all(close(vectors[key], expected[key], EXACT) for key in SHEET_VECTORS):
        return
    chain = answer["chain"]
    if chain is not None and not all(close(a, b, EXACT) for a, b in zip(chain, reference["chain"])):
        v = np.ones(3)
        own = dict(zip(SHEET_VECTORS, (np.asarray(T, dtype=float) @ v for T in chain)))
        if all(close(vectors[key], own[key], EXACT) for key in SHEET_VECTORS):
            require_real("vectors()", "frames of build_chain()", [
                (name, rotation_flaw(T, ours)) for name, T, ours in zip(CHAIN_TRANSFORMS, chain, reference["chain"])])
            ctx.carry_forward(CHAIN, "frames of build_chain()")
            return
    for key, target in SHEET_VECTORS.items():
        typed = [Mistake("typed_numbers", target, TYPED_HINT)] if key != "C3_v" else []
        assert_close(vectors[key], expected[key], key, EXACT, typed, context="(the sheet's value at full precision)")
