"""The strategies of the randomized comparisons: the part of hypothesis's strategy API that the checks use (same
names, same arguments), as descriptions that draw their examples from a seeded numpy ``Generator`` without
importing hypothesis, and become hypothesis strategies (``Strategy.hypothesis()``) when a failure is shrunk.

A check module writes ``from grader import strategies as st`` and uses ``st.floats(-1.0, 1.0)``,
``st.tuples(...)``, ``@st.composite`` and ``st.assume(...)`` as with hypothesis.  ``draw_examples(strategy, n,
seed)`` gives ``n`` examples: the first is the simplest (every number at its simplest value: zero where the range
holds it, the shortest lists, the first of a ``sampled_from``), as hypothesis tries first; the others are drawn
uniformly from the ranges.  Passing a comparison therefore costs no hypothesis import and no hypothesis engine;
only a failure brings hypothesis in, to shrink it.

Every range must be bounded: a grader draws inputs a course can state, never unbounded floats.
"""

from __future__ import annotations

import math

__all__ = [
    "Strategy",
    "Rejected",
    "floats",
    "integers",
    "booleans",
    "just",
    "sampled_from",
    "tuples",
    "lists",
    "permutations",
    "fixed_dictionaries",
    "composite",
    "assume",
    "draw_examples",
    "to_hypothesis",
]

#: draws that a filter may reject before it gives up on the example
MAX_REJECTIONS = 1000
#: examples in a row that filters or ``assume`` may reject before the strategy is called unsatisfiable
MAX_REJECTED_EXAMPLES = 100


class Rejected(Exception):
    """An example that a filter or ``assume`` rejected: it is drawn again."""


class _Source:
    """Where a draw takes its randomness from: a numpy ``Generator``, and whether the simplest value is wanted."""

    __slots__ = ("rng", "simplest")

    def __init__(self, rng, simplest: bool):
        self.rng = rng
        self.simplest = simplest

    def random(self) -> "_Source":
        return self if not self.simplest else _Source(self.rng, False)


class Strategy:
    """A description of random data: ``draw(source)`` draws one value; ``hypothesis()`` is the equivalent
    hypothesis strategy (built, and hypothesis imported, on first use)."""

    _built = None

    def draw(self, source: _Source):
        raise NotImplementedError

    def build(self):
        raise NotImplementedError

    def hypothesis(self):
        if self._built is None:
            self._built = self.build()
        return self._built

    def map(self, func) -> "Strategy":
        return _Mapped(self, func)

    def filter(self, condition) -> "Strategy":
        return _Filtered(self, condition)

    def __repr__(self) -> str:
        return f"{type(self).__name__.lstrip('_').lower()}(...)"


def to_hypothesis(strategy):
    """The hypothesis strategy of ``strategy`` (one of ours, or already a hypothesis strategy)."""
    return strategy.hypothesis() if isinstance(strategy, Strategy) else strategy


def _st():
    from hypothesis import strategies

    return strategies


def _bounded(name: str, low, high) -> tuple:
    if low is None or high is None or not (math.isfinite(low) and math.isfinite(high)) or low > high:
        raise ValueError(f"{name} needs finite bounds min_value <= max_value, got {low!r} and {high!r}")
    return low, high


class _Floats(Strategy):
    def __init__(self, min_value, max_value, options):
        self.low, self.high = map(float, _bounded("floats", min_value, max_value))
        self.options = options
        if options.get("exclude_min") or options.get("exclude_max"):
            raise ValueError("floats: exclude_min and exclude_max are not supported")

    def draw(self, source):
        if source.simplest:
            return _simplest_float(self.low, self.high)
        return float(min(self.high, max(self.low, source.rng.uniform(self.low, self.high))))

    def build(self):
        return _st().floats(self.low, self.high, **self.options)


def _simplest_float(low: float, high: float) -> float:
    """The simplest float in [low, high]: zero, else the integer nearest zero, else the bound nearest zero."""
    if low <= 0.0 <= high:
        return 0.0
    if low > 0.0:
        return float(math.ceil(low)) if math.ceil(low) <= high else low
    return float(math.floor(high)) if math.floor(high) >= low else high


class _Integers(Strategy):
    def __init__(self, min_value, max_value):
        self.low, self.high = map(int, _bounded("integers", min_value, max_value))

    def draw(self, source):
        if source.simplest:
            return min(self.high, max(self.low, 0))
        return int(source.rng.integers(self.low, self.high, endpoint=True))

    def build(self):
        return _st().integers(self.low, self.high)


class _Booleans(Strategy):
    def draw(self, source):
        return False if source.simplest else bool(source.rng.integers(2))

    def build(self):
        return _st().booleans()


class _Just(Strategy):
    def __init__(self, value):
        self.value = value

    def draw(self, source):
        return self.value

    def build(self):
        return _st().just(self.value)


class _SampledFrom(Strategy):
    def __init__(self, elements):
        self.elements = tuple(elements)
        if not self.elements:
            raise ValueError("sampled_from needs at least one element")

    def draw(self, source):
        return self.elements[0 if source.simplest else int(source.rng.integers(len(self.elements)))]

    def build(self):
        return _st().sampled_from(self.elements)


class _Tuples(Strategy):
    def __init__(self, parts):
        self.parts = tuple(parts)

    def draw(self, source):
        return tuple(part.draw(source) for part in self.parts)

    def build(self):
        return _st().tuples(*(to_hypothesis(part) for part in self.parts))


class _Lists(Strategy):
    def __init__(self, elements, min_size, max_size):
        self.elements = elements
        self.min_size, self.max_size = _bounded("lists", min_size, max_size)

    def draw(self, source):
        size = self.min_size if source.simplest else int(source.rng.integers(self.min_size, self.max_size,
                                                                              endpoint=True))
        return [self.elements.draw(source) for _ in range(size)]

    def build(self):
        return _st().lists(to_hypothesis(self.elements), min_size=self.min_size, max_size=self.max_size)


class _Permutations(Strategy):
    def __init__(self, values):
        self.values = list(values)

    def draw(self, source):
        if source.simplest:
            return list(self.values)
        return [self.values[int(i)] for i in source.rng.permutation(len(self.values))]

    def build(self):
        return _st().permutations(self.values)


class _FixedDictionaries(Strategy):
    def __init__(self, mapping):
        self.mapping = dict(mapping)

    def draw(self, source):
        return {key: part.draw(source) for key, part in self.mapping.items()}

    def build(self):
        return _st().fixed_dictionaries({key: to_hypothesis(part) for key, part in self.mapping.items()})


class _Mapped(Strategy):
    def __init__(self, inner: Strategy, func):
        self.inner, self.func = inner, func

    def draw(self, source):
        return self.func(self.inner.draw(source))

    def build(self):
        return to_hypothesis(self.inner).map(self.func)


class _Filtered(Strategy):
    def __init__(self, inner: Strategy, condition):
        self.inner, self.condition = inner, condition

    def draw(self, source):
        for attempt in range(MAX_REJECTIONS):
            value = self.inner.draw(source if attempt == 0 else source.random())
            if self.condition(value):
                return value
        raise Rejected(f"no value satisfied the filter in {MAX_REJECTIONS} draws")

    def build(self):
        return to_hypothesis(self.inner).filter(self.condition)


class _Composite(Strategy):
    def __init__(self, func, args, kwargs):
        self.func, self.args, self.kwargs = func, args, kwargs

    def draw(self, source):
        return self.func(lambda strategy: strategy.draw(source), *self.args, **self.kwargs)

    def build(self):
        st = _st()
        from hypothesis import reject

        func, args, kwargs = self.func, self.args, self.kwargs

        @st.composite
        def built(draw):
            try:
                return func(lambda strategy: draw(to_hypothesis(strategy)), *args, **kwargs)
            except Rejected:
                reject()

        return built()


# ---------------------------------------------------------------------------------------------- the API


def floats(min_value, max_value, **options) -> Strategy:
    """Floats in [min_value, max_value] (both finite); ``allow_nan``/``allow_infinity``/``width`` are passed to
    hypothesis when it shrinks (a bounded range holds neither NaN nor infinity)."""
    return _Floats(min_value, max_value, options)


def integers(min_value, max_value) -> Strategy:
    return _Integers(min_value, max_value)


def booleans() -> Strategy:
    return _Booleans()


def just(value) -> Strategy:
    return _Just(value)


def sampled_from(elements) -> Strategy:
    return _SampledFrom(elements)


def tuples(*parts: Strategy) -> Strategy:
    return _Tuples(parts)


def lists(elements: Strategy, *, min_size: int = 0, max_size: int | None = None) -> Strategy:
    return _Lists(elements, min_size, max_size)


def permutations(values) -> Strategy:
    return _Permutations(values)


def fixed_dictionaries(mapping: dict) -> Strategy:
    return _FixedDictionaries(mapping)


def composite(func):
    """``@composite def cases(draw, ...)``: ``cases(...)`` is a strategy whose values ``func`` builds with
    ``draw(strategy)``; it may call ``assume(condition)`` to reject a draw."""

    def make(*args, **kwargs) -> Strategy:
        return _Composite(func, args, kwargs)

    make.__name__ = getattr(func, "__name__", "composite")
    make.__doc__ = getattr(func, "__doc__", None)
    make.__wrapped__ = func
    return make


def assume(condition) -> bool:
    """Reject the example being drawn unless ``condition`` holds (inside a ``composite`` strategy)."""
    if not condition:
        raise Rejected("assume() rejected the example")
    return True


def draw_examples(strategy: Strategy, examples: int, seed: int) -> list:
    """``examples`` values of ``strategy`` from ``seed``: the simplest first, then uniform draws.  A rejected
    example (a filter, ``assume``) is drawn again, at random."""
    import numpy as np

    rng = np.random.default_rng(int(seed) % 2**128)
    drawn: list = []
    rejected = in_a_row = 0
    while len(drawn) < examples:
        try:
            drawn.append(strategy.draw(_Source(rng, simplest=not drawn and rejected == 0)))
            in_a_row = 0
        except Rejected:
            rejected += 1
            in_a_row += 1
            if in_a_row >= MAX_REJECTED_EXAMPLES:
                raise ValueError(f"the strategy rejected {in_a_row} examples in a row: it is unsatisfiable") from None
    return drawn
