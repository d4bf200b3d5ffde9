"""The student's own upstream functions, called one by one: error carried forward across problems.

A later problem's check may judge the student's answer on the student's own functions of earlier problems (their
``R3`` inside problem 8's steps, their ``accelerations`` of problem 43 inside problem 44's run).  The grader then
runs the reference's logic of the later problem in its own process, and every call that logic makes of a shared
function owned by an earlier problem comes here: the student's function, with the same arguments, in the sandbox.
"""

from . import module, probe
from ._forms import ANY

__all__ = ["call"]


@probe(returns=ANY, says="{0}.{1}")
def call(pkg, module_name, function, args):
    """``module_name.function(*args)`` of the package (the value of any plain-data function: the grader compares it
    with the reference's value of the same call)."""
    return getattr(module(pkg, module_name), function)(*args)
