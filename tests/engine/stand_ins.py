"""Stand-ins for a grading context's oracle and worker in the diagnosis engine's unit tests: the reference's and the
student's functions given by probe name, called in this process; and a made-up package of one problem that the
formula tier mutates in place of the reference."""

import contextlib
import itertools

import numpy as np
import pytest

from grader.diagnosis import mutants
from grader.errors import StudentFault
from grader.private import drop_private, private_import

__all__ = ["StandInOracle", "StandInChild", "made_up_package", "made_up_fixture", "about_3"]

_NUMBERS = itertools.count()


class StandInOracle:
    """The live oracle: the reference's functions by probe name; draws from the seed given."""

    mode = "live"

    def __init__(self, functions):
        self.functions = functions

    def reference(self, probe, args, persist=False, check=None):
        return self.functions[probe](*args)

    def draw(self, site, make, seed, check=None):
        return make(np.random.default_rng(seed))


class StandInChild:
    """The student's worker: their functions by probe name; a probe it does not hold is answered as a worker
    answers one the student's package cannot (a student fault)."""

    def __init__(self, functions):
        self.functions = functions

    def call(self, probe, *args, timeout=None):
        if probe not in self.functions:
            raise StudentFault(f"your code has no {probe}")
        return self.functions[probe](*args)


@contextlib.contextmanager
def made_up_package(tmp_path, monkeypatch, source: str, number: int, label: str, library: dict | None = None):
    """A package of one made-up problem (``problem_<number>.py`` holding ``source``, and the modules of
    ``library``, by file name), imported privately under a name of its own, that the formula tier mutates in
    place of the reference while the context lasts."""
    root = tmp_path / f"made_up_{label}"
    root.mkdir()
    (root / "__init__.py").write_text('"""A made-up package."""\n')
    (root / f"problem_{number}.py").write_text(source)
    for name, text in (library or {}).items():
        (root / name).write_text(text)
    package = private_import(f"_made_up_{label}_{next(_NUMBERS)}", root)
    monkeypatch.setattr(mutants, "_package", lambda: (root, package))
    try:
        yield package
    finally:
        drop_private(package)


def made_up_fixture(source: str, number: int, label: str):
    """A fixture ``made_up``: the package of one made-up problem ``number`` holding ``source``, which the formula
    tier mutates in place of the reference while a test lasts (``made_up_package``)."""
    @pytest.fixture
    def made_up(tmp_path, monkeypatch):
        with made_up_package(tmp_path, monkeypatch, source, number, label) as package:
            yield package

    return made_up


def about_3(angle: float) -> np.ndarray:
    """The rotation by ``angle`` about the 3-axis."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
