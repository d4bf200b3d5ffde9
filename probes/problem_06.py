"""Probes of problem 6: elementary rotations, the Cardan sequence, and the sheet's frames and vectors."""

from . import module, probe


@probe(args=("", "angle"))
def elementary(pkg, axis, angle):
    rotations = module(pkg, "rotations")
    return {1: rotations.R1, 2: rotations.R2, 3: rotations.R3}[axis](angle)


@probe(args=("angle", "angle", "angle"))
def cardan(pkg, alpha, beta, gamma):
    return module(pkg, "rotations").cardan(alpha, beta, gamma)


@probe
def frames(pkg):
    return module(pkg, "problem_06").frames()


@probe
def vectors(pkg):
    return module(pkg, "problem_06").vectors()


def _own(call):
    """The student's own value of an upstream function (judged on in a later check), or None when it cannot be
    had (not implemented, raises, not numeric)."""
    try:
        import numpy as np

        value = np.asarray(call(), dtype=float)
        return value if value.shape == (3, 3) and np.all(np.isfinite(value)) else None
    except Exception:  # noqa: BLE001 - a missing upstream value is judged by its own check
        return None


@probe(args=("angle", "angle", "angle"))
def cardan_with_factors(pkg, alpha, beta, gamma):
    """``cardan(alpha, beta, gamma)`` with the package's own factors ``R1(alpha), R2(beta), R3(gamma)``."""
    rotations = module(pkg, "rotations")
    return {
        "cardan": rotations.cardan(alpha, beta, gamma),
        "R1": _own(lambda: rotations.R1(alpha)),
        "R2": _own(lambda: rotations.R2(beta)),
        "R3": _own(lambda: rotations.R3(gamma)),
    }


@probe
def frames_with_factors(pkg, alpha, beta, gamma):
    """``frames()`` with the package's own ``R3(gamma), R2(beta), R1(alpha)`` and ``cardan`` of the partial
    sequences ``(0, 0, gamma), (0, beta, gamma), (alpha, beta, gamma)``."""
    rotations = module(pkg, "rotations")
    return {
        "frames": module(pkg, "problem_06").frames(),
        "R1": _own(lambda: rotations.R1(alpha)),
        "R2": _own(lambda: rotations.R2(beta)),
        "R3": _own(lambda: rotations.R3(gamma)),
        "cardan": [_own(lambda: rotations.cardan(0.0, 0.0, gamma)), _own(lambda: rotations.cardan(0.0, beta, gamma)),
                   _own(lambda: rotations.cardan(alpha, beta, gamma))],
    }


@probe
def vectors_with_frames(pkg):
    """``vectors()`` with the package's own ``frames()`` (None when they cannot be had)."""
    problem = module(pkg, "problem_06")
    try:
        own = problem.frames()
        own = {key: _own(lambda key=key: own[key]) for key in ("A_IC1", "A_IC2", "A_IC3")}
    except Exception:  # noqa: BLE001
        own = None
    return {"vectors": problem.vectors(), "frames": own}
