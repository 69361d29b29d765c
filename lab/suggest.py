"""Name suggestions for error messages: the one place that guesses what a user meant.

Used wherever a name is looked up — a preset, a shape or its parameter, a shading, a
reflection model, a scene-file key, a command-line option, a bar, a PyVista example
file — so every message suggests the same way: the closest known name by
:func:`difflib.get_close_matches` (ratio ≥ 0.6, case ignored), or nothing.

>>> did_you_mean("spot-atenuation", ["spot-attenuation", "globe"])
" (did you mean 'spot-attenuation'?)"
>>> did_you_mean("xyz", ["globe"])
''
"""
from __future__ import annotations

import difflib
from typing import Iterable

CUTOFF = 0.6
"""Smallest similarity ratio (0..1) of a suggestion, difflib's default."""


def closest(word: str, names: Iterable[str]) -> str | None:
    """The known name closest to ``word`` (case ignored), or None when none is close."""
    names = [str(n) for n in names]
    by_folded = {}
    for n in names:
        by_folded.setdefault(n.lower(), n)
    near = difflib.get_close_matches(str(word).lower(), list(by_folded), n=1, cutoff=CUTOFF)
    return by_folded[near[0]] if near else None


def did_you_mean(word: str, names: Iterable[str]) -> str:
    """``" (did you mean 'NAME'?)"`` for the closest known name, or ``""``."""
    near = closest(word, names)
    return f" (did you mean {near!r}?)" if near is not None else ""
