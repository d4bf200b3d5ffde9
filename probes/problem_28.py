"""Probes of problem 28: what the port of main.m prints."""

import contextlib
import io

from . import module, probe
from ._forms import Text


@probe(returns=Text(), says="main()")
def output(pkg):
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        module(pkg, "problem_28").main()
    return buffer.getvalue()
