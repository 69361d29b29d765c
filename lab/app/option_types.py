"""argparse types for the scanlab command's numeric options, in one place.

Each returns the parsed value or raises ``argparse.ArgumentTypeError`` with a short reason;
argparse then prints ``scanlab <command>: error: argument --name: <reason>`` (one line,
exit status 2). The reasons say what was expected and repeat what was typed.
"""
from __future__ import annotations

import argparse
import math
from typing import Callable


def whole(least: int = 1, most: int | None = None, what: str = "a whole number",
          note: str = "") -> Callable[[str], int]:
    """A type for a whole number from ``least`` to ``most`` (no upper bound when None);
    ``what`` names it in messages (e.g. "a port number"), ``note`` follows the range."""
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected {what}, got {text!r}") from None
        if most is not None and not least <= value <= most:
            raise argparse.ArgumentTypeError(f"expected {what} from {least} to {most}{note}, got {text!r}")
        if value < least:
            raise argparse.ArgumentTypeError(f"must be at least {least}, got {text!r}")
        return value
    return parse


def number(least: float = 0.0, above: bool = False, most: float | None = None, what: str = "a number",
           unit: str = "") -> Callable[[str], float]:
    """A type for a finite number of at least ``least`` (more than ``least`` when ``above``) and
    at most ``most`` (no upper bound when None); ``what`` names it when the text is no number,
    ``unit`` follows the bound (" seconds")."""
    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected {what}, got {text!r}") from None
        if not math.isfinite(value):
            raise argparse.ArgumentTypeError(f"must be a finite number, got {text!r}")
        if value < least or (above and value == least):
            bound = f"more than {least:g}" if above else f"at least {least:g}"
            raise argparse.ArgumentTypeError(f"must be {bound}{unit}, got {text!r}")
        if most is not None and value > most:
            raise argparse.ArgumentTypeError(f"must be at most {most:g}{unit}, got {text!r}")
        return value
    return parse


seconds = number(0.0, above=True, most=1e6, what="seconds", unit=" seconds")
"""A time limit: more than 0 and at most 10⁶ seconds (timers and ``signal.alarm`` take no more)."""


def image_size(text: str) -> tuple[int, int]:
    """``WIDTHxHEIGHT`` in pixels, e.g. ``512x384``: (width, height), each at least 1."""
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT such as 512x384, got {text!r}") from None
    if w < 1 or h < 1:
        raise argparse.ArgumentTypeError(f"width and height must be at least 1, got {text!r}")
    return w, h
