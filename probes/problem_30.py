"""Probes of problem 30: the class diagram as data."""

from . import module, probe
from ._forms import ANY


@probe(returns=ANY, says="class_diagram()")
def class_diagram(pkg):
    return module(pkg, "problem_30").class_diagram()
