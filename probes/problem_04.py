"""Probes of problem 4: the four-bar's assembly (angles, or the error it raised), its balanced configuration, and
its MJCF loaded by MuJoCo in the sandbox with the acceleration along the linkage's free motion."""

from . import _mjcf, module, probe
from ._forms import Arr, Dict, Either, Num, Text


@probe(
    returns=Either(Dict({"raised": Text(), "message": Text(), "kind": Text()}), Dict({"q": Arr(4)})),
    says="assemble({0}, {1})",
)
def assemble(pkg, targets, fixed_point):
    """``{"q": angles}``, or the exception ``assemble`` raised: ``{"raised": type, "message", "kind"}`` where kind
    is ``"overconstrained"``, ``"unreachable"``, ``"assembly"`` (another AssemblyError) or ``"other"``."""
    p4 = module(pkg, "problem_04")
    try:
        return {"q": p4.assemble(list(targets), fixed_point)}
    except NotImplementedError:
        raise
    except Exception as exc:  # noqa: BLE001 - which exception it is, is what the check grades
        kind = "other"
        for name, cls in (("overconstrained", "OverconstrainedError"), ("unreachable", "UnreachableError"),
                          ("assembly", "AssemblyError")):
            declared = getattr(p4, cls, None)
            if isinstance(declared, type) and isinstance(exc, declared):
                kind = name
                break
        return {"raised": type(exc).__name__, "message": str(exc)[:1000], "kind": kind}


@probe(returns=Arr(4), says="balanced_configuration({0})")
def balanced(pkg, fixed_point):
    return module(pkg, "problem_04").balanced_configuration(fixed_point)


@probe(
    returns=Either(
        _mjcf.REFUSED,
        Dict(
            {
                **_mjcf.DESCRIPTION.fields,
                "at_rest": Either(
                    _mjcf.REFUSED, Dict({"alpha": Num(), "tangent": Arr(None), "violation": Num(), "qacc": Arr(None)})
                ),
            }
        ),
    ),
    says="four_bar({0}, {1}, {2}, {3})",
)
def model(pkg, density, gravity, q, fixed_point):
    """What ``four_bar(...)`` declares, and the acceleration along the linkage's free motion at rest
    (``_mjcf.tangent_acceleration``); or ``{"error": ...}``."""
    xml = module(pkg, "problem_04").four_bar(density, gravity, q, fixed_point)

    def build():
        model, data = _mjcf.load(xml)
        return {**_mjcf.describe(model, data), "at_rest": _mjcf.tangent_acceleration(model, data)}

    return _mjcf.guarded(build)


# The reference's own computation (its planar dynamics, independent of MuJoCo): called on the reference only.


@probe(reference_only=True)
def tangent_acceleration(pkg, q, density, gravity):
    p4 = module(pkg, "problem_04")
    return {"alpha": p4.tangent_acceleration(q, density, gravity), "tangent": p4.loop_tangent(q)}
