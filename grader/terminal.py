"""Text for a terminal: whatever a submission controls is shown there, never obeyed.

A student's output, the messages that carry their values, exception texts, file names and notebook cells all
reach ``grade``'s output.  Raw, their control characters would act on the terminal: clear the screen, move the
cursor to draw a forged line over the report, set the window's title (OSC 0) or write to the clipboard (OSC 52).
``inert`` shows every such character escaped, as Python writes it in a string literal (``\\x1b``, ``\\x9b``,
``\\u202e``): the C0 controls but newline and tab, DEL, the C1 controls (8-bit CSI and OSC among them), the
bidirectional overrides and isolates that reorder what a line seems to say, and lone surrogates (which no
terminal can be sent).  A line end ``\\r\\n`` is a newline.

Every piece of terminal text goes through ``inert``: the jinja2 environment of the terminal templates applies it
to each expression it writes (``grader.report.environment``), the batch's progress to each line, and the commands'
messages go out with ``say``.  Styling the grader adds itself (colours, bold) is ``Styled``: built from inert text,
and passed through as it is.
"""

from __future__ import annotations

import re
import sys

__all__ = ["inert", "Styled", "styled", "say", "CONTROL"]

#: the characters ``inert`` escapes: C0 but tab (\x09) and newline (\x0a), DEL and C1, the bidirectional controls
#: (ALM, LRM, RLM, the embeddings and overrides LRE..RLO, the isolates LRI..PDI) and lone surrogates
CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\ud800-\udfff]")


class Styled(str):
    """Terminal text styled by the grader (``styled``): its escape sequences are the grader's own."""


def _escaped(match: re.Match) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def inert(value) -> str:
    """``value`` as text that a terminal shows and does not obey (see the module's docstring); ``Styled`` text
    as it is."""
    if isinstance(value, Styled):
        return value
    text = value if isinstance(value, str) else str(value)
    return CONTROL.sub(_escaped, text.replace("\r\n", "\n"))


def styled(text, sgr: str) -> Styled:
    """``text``, made inert, in the graphic rendition ``sgr`` (``"1"`` bold, ``"31"`` red, ...)."""
    return Styled(f"\033[{sgr}m{inert(text)}\033[0m")


def say(text, file=None) -> None:
    """Print a line of the command's own (a message that may carry a file name or a submission's text) inert;
    on stderr unless ``file``."""
    print(inert(text), file=file if file is not None else sys.stderr)
