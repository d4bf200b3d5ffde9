"""Probes of problem 6."""

from . import module, probe


@probe
def vectors(pkg):
    return module(pkg, "problem_06").vectors()
