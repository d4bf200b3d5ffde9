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
        # BEGIN SOLUTION problem 28
        self.child = None
        self.color = color
        self.isLeaf = False
        # END SOLUTION

    def Rainbow(self):
        """Print this color and recurse into the child; a leaf prints 'Sandwich' instead and stops."""
        # BEGIN SOLUTION problem 28
        if self.isLeaf:
            print("Sandwich")
        else:
            print(self.color)
            self.child.Rainbow()
        # END SOLUTION


def main():
    """The script main.m."""
    # BEGIN SOLUTION problem 28
    green = ColorCLASS("green")
    blue = ColorCLASS("blue")
    purple = ColorCLASS("purple")
    red = ColorCLASS("red")
    yellow = ColorCLASS("yellow")
    green.child = purple
    blue.child = green
    yellow.child = blue
    red.child = yellow
    green.isLeaf = True
    # clc: clears the command window, no output
    print("Rainbow:")
    red.Rainbow()
    # END SOLUTION


def expected_output():
    """Everything ``main()`` prints."""
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        main()
    return buffer.getvalue()
