"""Probes of problem 36: what the port's two parts print, and the class hierarchy read off the port."""

import contextlib
import io

from . import module, probe
from ._forms import ANY, Text


@probe(returns=Text(), says="{0}()")
def output(pkg, part):
    script = getattr(module(pkg, "problem_36"), part)
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        script()
    return buffer.getvalue()


@probe(returns=ANY, says="class_hierarchy()")
def class_hierarchy(pkg):
    return module(pkg, "problem_36").class_hierarchy()
