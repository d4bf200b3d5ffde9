"""How a user writes problems and counts on the command line (``grade``, ``grade batch``) and in ``check(6)``: the
argument types that the commands share."""

from __future__ import annotations

import argparse
import re

__all__ = ["problem_number", "positive_int", "parse_problems"]


def problem_number(text: str) -> int:
    """``"problem-6"``, ``"problem6"``, ``"p6"`` or ``"6"`` (any case) → 6."""
    match = re.fullmatch(r"(?:problem-?|p)?(\d{1,2})", text.strip().lower())
    if not match:
        raise argparse.ArgumentTypeError(f"{text!r} is not a problem (write e.g. problem-6)")
    return int(match.group(1))


def positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of at least 1")
    return value


def parse_problems(texts: list[str] | str | None) -> list[int] | None:
    """``["6,7", "10-12"]`` → ``[6, 7, 10, 11, 12]`` (sorted, each once); None or empty: None (every problem)."""
    if texts is None:
        return None
    if isinstance(texts, str):
        texts = [texts]
    numbers: set[int] = set()
    for text in texts:
        for part in text.replace(" ", ",").split(","):
            if not part:
                continue
            first, dash, last = part.partition("-")
            try:
                low = int(first.lower().removeprefix("problem").removeprefix("p"))
                high = int(last) if dash else low
            except ValueError:
                raise ValueError(f"{part!r} is not a problem or a range of problems (write e.g. 6,7 or 6-20)")
            if high < low:
                raise ValueError(f"{part!r} is an empty range")
            numbers.update(range(low, high + 1))
    return sorted(numbers) or None
