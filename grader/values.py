"""What a comparison of numbers is made of, shared by the checks' helpers (``grader.checking``) and the diagnosis
engine (``grader.diagnosis``): a named tolerance, and how an array is shown in a message."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Tol", "format_array"]


@dataclass(frozen=True)
class Tol:
    """A named tolerance: ``|got - expected| <= atol + rtol * |expected|`` entrywise."""

    name: str
    atol: float
    rtol: float = 0.0

    def __str__(self) -> str:
        rtol = f", rtol={self.rtol:g}" if self.rtol else ""
        return f"{self.name} (atol={self.atol:g}{rtol})"


def format_array(a, digits: int = 4) -> str:
    a = np.asarray(a, dtype=float)
    with np.printoptions(precision=digits, suppress=True, floatmode="fixed", linewidth=120):
        return np.array2string(a, separator=", ")
