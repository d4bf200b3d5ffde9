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
        # TODO problem 36: write your solution here
        raise NotImplementedError("Problem 36: WonderlandCharacter.__init__ is not implemented yet")


class TweedleDum(WonderlandCharacter):
    """TweedleDum creates his own foe, a TweedleDee whose foe is TweedleDum."""

    def __init__(self):
        # TODO problem 36: write your solution here
        raise NotImplementedError("Problem 36: TweedleDum.__init__ is not implemented yet")

    def TellStory(self):
        """Story telling: two lines, then the foe continues the story."""
        # TODO problem 36: write your solution here
        raise NotImplementedError("Problem 36: TweedleDum.TellStory is not implemented yet")


class TweedleDee(WonderlandCharacter):
    """TweedleDee ends the story."""

    def __init__(self, name, foe):
        # TODO problem 36: write your solution here
        raise NotImplementedError("Problem 36: TweedleDee.__init__ is not implemented yet")

    def TellStory(self):
        """Story telling: two lines."""
        # TODO problem 36: write your solution here
        raise NotImplementedError("Problem 36: TweedleDee.TellStory is not implemented yet")


def part1():
    """PART I of main.m."""
    # TODO problem 36: write your solution here
    raise NotImplementedError("Problem 36: part1 is not implemented yet")


def part2():
    """PART II of main.m."""
    # TODO problem 36: write your solution here
    raise NotImplementedError("Problem 36: part2 is not implemented yet")


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
