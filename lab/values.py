"""Checking single values read from a scene file, shared by the loader and the CSG parser.

Conventions: a number in a scene file is a TOML integer or float, never a boolean; it
must be finite and within ±MAX_MAGNITUDE. Error messages show values with :func:`show`,
so a message stays one short line whatever the file holds.
"""
from __future__ import annotations

import math
import os
import stat

MAX_MAGNITUDE = 1e15
"""Largest absolute value of any number in a scene file: products of two coordinates,
as in a cross product or a squared length, then stay far from float overflow."""


def show(value, width: int = 60) -> str:
    """A value's repr for an error message, on one line, cut to ``width`` characters.

    >>> show("a\\nb"), show(list(range(100)), 12)
    ("'a\\\\nb'", '[0, 1, 2, 3…')
    """
    try:
        text = repr(value)
    except ValueError:  # an int of more digits than Python will convert to text
        text = "a number of more than 4300 digits"
    text = " ".join(text.split())
    return text if len(text) <= width else text[:width - 1] + "…"


def real(x) -> float | None:
    """``x`` as a float, or None if it is not a number (a bool is not one).

    An int too large for a float becomes ±inf (``float()`` would raise OverflowError).
    """
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        return None
    try:
        return float(x)
    except OverflowError:
        return math.inf if x > 0 else -math.inf


def finite(x) -> float | None:
    """``x`` as a float if it is a finite number within ±MAX_MAGNITUDE, else None."""
    v = real(x)
    return v if v is not None and math.isfinite(v) and abs(v) <= MAX_MAGNITUDE else None


IS_A_FOLDER = "is a folder, not a regular file"
"""What :func:`file_problem` says of a folder (callers compare with it to say more)."""


def file_problem(path) -> str | None:
    """Why ``path`` cannot be read as a regular file ("No such file or directory", "File
    name too long", "is a folder, not a regular file", "not a regular file" for a device or
    pipe ...), or None."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError) as exc:  # ValueError: a NUL byte in the name
        return getattr(exc, "strerror", None) or str(exc)
    if stat.S_ISDIR(mode):
        return IS_A_FOLDER
    return None if stat.S_ISREG(mode) else "not a regular file"
