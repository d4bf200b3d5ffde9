"""Problem 1: a working installation.

The course needs Python 3.11 or newer with numpy, scipy, sympy and MuJoCo (``pip install -e .`` in the course's
folder installs them all).  ``grade problem-1`` checks, inside the grader's sandbox, that every package imports
and that a tiny MuJoCo model loads and runs; ``versions`` is your own look at what is installed.
"""

__all__ = ["PACKAGES", "versions"]

#: the packages the course uses, by their import names (numerics, ODE solvers, symbolic maths, the simulator)
PACKAGES = ("numpy", "scipy", "sympy", "mujoco")


def versions():
    """The versions of Python and of the course's packages, as strings:
    ``{"python": "3.11.7", "numpy": "...", "scipy": "...", "sympy": "...", "mujoco": "..."}``, with ``None`` for a
    package that is not installed.  Read them with ``importlib.metadata.version(name)`` (it raises
    ``importlib.metadata.PackageNotFoundError`` for a missing package) and ``platform.python_version()``.
    """
    # TODO problem 1: write your solution here
    raise NotImplementedError("Problem 1: versions is not implemented yet")
