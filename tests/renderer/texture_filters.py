"""The texture filters written plainly, per channel in Python, for tests to compare the
renderer's sampling with: no lanes, no fixed-point shortcut, no fast path.

Not a test file.
"""
from __future__ import annotations

import numpy as np

from renderer.texture_sampling import NEAREST, REPEAT


def by_definition(texels, width, height, filt, wrap, s, t):
    """The texel value at (s, t) of ``texels`` ((W·H, 3) uint8, rows from the bottom) as
    :mod:`renderer.texture_sampling`'s docstring defines the filters (``filt``, ``wrap`` its
    codes): 0..255 integers, [r, g, b]."""
    def wrapped(i, size):
        return i % size if wrap == REPEAT else min(max(i, 0), size - 1)

    def at(i, j):
        return [int(v) for v in texels[wrapped(j, height) * width + wrapped(i, width)]]

    if filt == NEAREST:
        return at(int(np.floor(s * width)), int(np.floor(t * height)))
    u, v = s * width - 0.5, t * height - 0.5
    i0, j0 = int(np.floor(u)), int(np.floor(v))
    wa, wb = int(np.floor((u - i0) * 256.0)), int(np.floor((v - j0) * 256.0))
    lerp = lambda a, b, w: a + (((b - a) * w + 128) >> 8)  # noqa: E731
    return [lerp(lerp(a, b, wa), lerp(c, d, wa), wb)
            for a, b, c, d in zip(at(i0, j0), at(i0 + 1, j0), at(i0, j0 + 1), at(i0 + 1, j0 + 1))]
