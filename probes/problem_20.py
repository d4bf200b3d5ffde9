"""Probes of problem 20: the validity test of inertia matrices."""

from . import module, probe


@probe
def is_inertia(pkg, matrices):
    """``[ok, reason]`` of ``is_inertia_matrix`` for each matrix."""
    out = []
    for I in matrices:
        result = module(pkg, "inertia").is_inertia_matrix(I)
        ok, reason = result if isinstance(result, (tuple, list)) else (result, "")
        out.append([bool(ok), str(reason)])
    return out
