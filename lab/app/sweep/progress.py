"""The terminal progress bar of a sweep: cases done, failed, and the time left.

On a terminal the bar is redrawn in place (``\\r``); into a file or a pipe a line is written
at most every ``every`` seconds, and once at the end. The rate counts this run's cases only,
from its first finished case on (so the workers' start and warm-up do not drag it down);
cases finished by an earlier run show in the count but not in the rate.

Example line::

    [##########....................] 171/500 · 4 failed (1 error) · 2.3 cases/s · 2 min 23 s left
"""
from __future__ import annotations

import sys
import time
from typing import Callable, TextIO


def duration(seconds: float) -> str:
    """``"42 s"``, ``"3 min 05 s"``, ``"1 h 02 min"``."""
    seconds = max(0, round(seconds))
    if seconds < 60:
        return f"{seconds} s"
    if seconds < 3600:
        return f"{seconds // 60} min {seconds % 60:02d} s"
    return f"{seconds // 3600} h {seconds % 3600 // 60:02d} min"


class Progress:
    """Counts finished cases out of ``total`` (``done`` of them finished by an earlier run)."""

    def __init__(self, total: int, done: int = 0, failed: int = 0, errors: int = 0, stream: TextIO | None = None,
                 every: float = 10.0, clock: Callable[[], float] = time.monotonic, width: int = 30):
        self.total, self.done, self.failed, self.errors = total, done, failed, errors
        self.stream = stream or sys.stderr
        self.every, self.clock, self.width = every, clock, width
        self.this_run = 0
        self.first: float | None = None
        self.last_line = -float("inf")
        self._width_shown = 0
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()

    def rate(self) -> float | None:
        """This run's cases per second since its first finished case (None before the second)."""
        if self.first is None or self.this_run < 2 or self.clock() <= self.first:
            return None
        return (self.this_run - 1) / (self.clock() - self.first)

    def line(self) -> str:
        filled = int(self.width * self.done / self.total) if self.total else self.width
        parts = [f"[{'#' * filled}{'.' * (self.width - filled)}] {self.done}/{self.total}",
                 f"{self.failed} failed" + (f" ({self.errors} error{'s' if self.errors != 1 else ''})"
                                            if self.errors else "")]
        rate = self.rate()
        if self.done >= self.total:
            parts.append("done")
        elif rate:
            parts += [f"{rate:.2f} cases/s", f"{duration((self.total - self.done) / rate)} left"]
        else:
            parts.append("estimating the time left")
        return " · ".join(parts)

    def case_finished(self, failed: bool = False, error: bool = False) -> None:
        """Count one finished case: ``failed`` (a FAIL verdict or an error), ``error`` (no verdict)."""
        if self.first is None:
            self.first = self.clock()
        self.this_run += 1
        self.done += 1
        self.failed += bool(failed or error)
        self.errors += bool(error)
        self.show()

    def show(self, final: bool = False) -> None:
        if self.tty:
            line = self.line()
            self.stream.write("\r" + line.ljust(self._width_shown) + ("\n" if final else ""))
            self._width_shown = len(line)
        elif final or self.clock() - self.last_line >= self.every:
            self.stream.write(self.line() + "\n")
            self.last_line = self.clock()
        self.stream.flush()
