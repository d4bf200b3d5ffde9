"""Problem 36 (Understanding Inheritance): a port of the sheet's three classes and main.m.

The identifiers and strings are the sheet's (including the script's 'figthing'), so the port reads line by line
against the MATLAB code; the second lines of the story are indented by four spaces inside the strings.  The
classes are handle classes in MATLAB; Python objects are references already.  ``disp([a, b, c])`` prints the
concatenated string and a newline.
"""

import contextlib
import io

__all__ = [
    "WonderlandCharacter",
    "TweedleDum",
    "TweedleDee",
    "part1",
    "part2",
    "part1_output",
    "part2_output",
    "class_hierarchy",
    "ANSWER_C",
]

#: model answer of (c)
ANSWER_C = (
    "No. WonderlandCharacter's constructor takes the foe as an argument, but when the Red Queen is constructed "
    "alice does not exist yet (alice is constructed with the Red Queen as her foe), so the Red Queen's foe can "
    "only be set after alice has been created."
)


class WonderlandCharacter:
    """A character with a ``name`` (string) and a ``foe`` (another WonderlandCharacter or None)."""

    def __init__(self, name, foe):
        # BEGIN SOLUTION problem 36
        self.foe = foe
        self.name = name
        # END SOLUTION


class TweedleDum(WonderlandCharacter):
    """TweedleDum creates his own foe, a TweedleDee whose foe is TweedleDum."""

    def __init__(self):
        # BEGIN SOLUTION problem 36
        super().__init__("TweedleDum", None)
        tweedleDee = TweedleDee("TweedleDee", self)
        self.foe = tweedleDee
        # END SOLUTION

    def TellStory(self):
        """Story telling: two lines, then the foe continues the story."""
        # BEGIN SOLUTION problem 36
        print(self.name + " and " + self.foe.name)
        print("    Agreed to have a battle")
        self.foe.TellStory()
        # END SOLUTION


class TweedleDee(WonderlandCharacter):
    """TweedleDee ends the story."""

    def __init__(self, name, foe):
        # BEGIN SOLUTION problem 36
        super().__init__(name, foe)
        # END SOLUTION

    def TellStory(self):
        """Story telling: two lines."""
        # BEGIN SOLUTION problem 36
        print("For " + self.name + " said " + self.foe.name)
        print("    Had spoiled his nice new rattle")
        # END SOLUTION


def part1():
    """PART I of main.m."""
    # BEGIN SOLUTION problem 36
    redQueen = WonderlandCharacter("The Red Queen", None)
    alice = WonderlandCharacter("Alice", redQueen)
    redQueen.foe = alice
    print(alice.name + " is figthing " + redQueen.name)
    print(alice.foe.name + " is fighting " + redQueen.foe.name)
    # END SOLUTION


def part2():
    """PART II of main.m."""
    # BEGIN SOLUTION problem 36
    tweedleDum = TweedleDum()
    tweedleDum.TellStory()
    # END SOLUTION


def _captured(script):
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        script()
    return buffer.getvalue()


def part1_output():
    """Everything PART I prints."""
    return _captured(part1)


def part2_output():
    """Everything PART II prints."""
    return _captured(part2)


def class_hierarchy():
    """(a): ``(subclass, base)`` pairs of the three classes, read off the port."""
    return [(cls.__name__, base.__name__) for cls in (TweedleDum, TweedleDee) for base in cls.__bases__]
