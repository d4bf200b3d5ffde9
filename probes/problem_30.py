"""Probes of problem 30: the class diagram as data."""

from . import module, probe


@probe
def class_diagram(pkg):
    return module(pkg, "problem_30").class_diagram()
