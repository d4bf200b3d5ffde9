"""Probes of problem 20: the validity test of inertia matrices."""

from . import module, probe
from ._forms import Flag, Seq, Text, Tup


@probe(returns=Seq(Tup(Flag(), Text()), length=lambda matrices: len(matrices)), says="is_inertia_matrix")
def is_inertia(pkg, matrices):
    """``[ok, reason]`` of ``is_inertia_matrix`` for each matrix."""
    out = []
    for I in matrices:
        result = module(pkg, "inertia").is_inertia_matrix(I)
        ok, reason = result if isinstance(result, (tuple, list)) else (result, "")
        out.append([bool(ok), str(reason)])
    return out


@probe(reference_only=True)
def sheet_matrices(pkg):
    """The four matrices of part (a) as printed."""
    return module(pkg, "problem_20").MATRICES_A


@probe(reference_only=True)
def key_a(pkg):
    """The options of (a) that are not inertia matrices, and the verdict on every option."""
    p20 = module(pkg, "problem_20")
    return {"keys": p20.key_a(), "classify": {k: [bool(ok), str(reason)] for k, (ok, reason) in p20.classify().items()}}


@probe(reference_only=True)
def key_b(pkg):
    """The key of (b), from the package's answers.toml."""
    import tomllib
    from pathlib import Path

    answers = tomllib.loads(Path(pkg.__file__).with_name("answers.toml").read_text())
    return answers["problem_20"]["b"]
