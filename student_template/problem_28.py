"""Problem 28 (Understanding Recursion): a port of the sheet's ColorCLASS.m and main.m.

The identifiers are the sheet's, so the port reads line by line against the MATLAB code.  ``ColorCLASS`` is a
handle class in MATLAB; Python objects are references already.  ``disp(s)`` prints ``s`` and a newline; ``clc``
clears the command window and prints nothing.
"""

import contextlib
import io

__all__ = ["ColorCLASS", "main", "expected_output"]


class ColorCLASS:
    """A color in a singly linked list: ``child`` is the next color, ``isLeaf`` ends the recursion."""

    def __init__(self, color):
        # TODO problem 28: write your solution here
        raise NotImplementedError("Problem 28: ColorCLASS.__init__ is not implemented yet")

    def Rainbow(self):
        """Print this color and recurse into the child; a leaf prints 'Sandwich' instead and stops."""
        # TODO problem 28: write your solution here
        raise NotImplementedError("Problem 28: ColorCLASS.Rainbow is not implemented yet")


def main():
    """The script main.m."""
    # TODO problem 28: write your solution here
    raise NotImplementedError("Problem 28: main is not implemented yet")


def expected_output():
    """Everything ``main()`` prints."""
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        main()
    return buffer.getvalue()
