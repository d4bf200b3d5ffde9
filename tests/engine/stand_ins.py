"""Stand-ins for a grading context's oracle and worker in the diagnosis engine's unit tests: the reference's and the
student's functions given by probe name, called in this process."""

import numpy as np

from grader.errors import StudentFault

__all__ = ["StandInOracle", "StandInChild"]


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
