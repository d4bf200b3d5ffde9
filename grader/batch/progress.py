"""The progress display of a batch: counts, rate and time left."""

from __future__ import annotations

import sys
import time

from ..terminal import inert

__all__ = ["Progress"]

def _clock(seconds: float) -> str:
    seconds = int(round(seconds))
    return f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}" if seconds >= 3600 else \
        f"{seconds // 60}:{seconds % 60:02d}"


class Progress:
    """Counts, rate and time left on stderr: one redrawn line on a terminal, a line per student otherwise (the
    student's name and what became of them, made inert: a name or a reason may hold control characters)."""

    WIDTH = 28

    def __init__(self, total: int, skipped: int = 0, stream=None, enabled: bool = True):
        self.stream = stream or sys.stderr
        self.total, self.skipped, self.done, self.enabled = total, skipped, 0, enabled
        self.tty = self.stream.isatty()
        self.start = time.monotonic()

    def line(self) -> str:
        elapsed = time.monotonic() - self.start
        rate = self.done / elapsed if elapsed > 0 else 0.0
        eta = _clock((self.total - self.done) / rate) if rate else "?"
        skipped = f" ({self.skipped} unchanged, skipped)" if self.skipped else ""
        return (f"{self.done}/{self.total} done{skipped} · {rate * 60:.1f}/min · {_clock(elapsed)} elapsed"
                f" · ETA {eta}")

    def advance(self, name: str, note: str) -> None:
        self.done += 1
        if not self.enabled:
            return
        if self.tty:
            filled = self.WIDTH * self.done // max(self.total, 1)
            bar = "█" * filled + "░" * (self.WIDTH - filled)
            self.stream.write(f"\r\033[K{bar} {self.line()}")
        else:
            self.stream.write(inert(f"[{self.done}/{self.total}] {name}: {note} · {self.line()}") + "\n")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled and self.tty and self.done:
            self.stream.write("\n")
            self.stream.flush()

