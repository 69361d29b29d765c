"""A rendered frame: what both renderers return.

Conventions: image rows, row 0 at the top (as in a PNG); ``rgb`` is 8-bit sRGB-encoded
values exactly as written to the framebuffer (no gamma applied anywhere); ``depth`` is
window depth in 0..1 (``(z_ndc + 1) / 2``), 1.0 where nothing was drawn; ``coverage`` is
True where some triangle was drawn.

A renderer may hand over the depth as a function that makes it, run the first time
``depth`` is read: a float depth image is a pass over every pixel (8 bytes each) that a
caller who only wants the picture never looks at.
"""
from __future__ import annotations

from typing import Callable, Union

import numpy as np

DepthSource = Union[np.ndarray, Callable[[], np.ndarray]]
"""A frame's depth as given: the (H, W) array, or a function of no arguments returning it."""


class Frame:
    """An H×W rendered image with its depth and coverage.

    Parameters
    ----------
    rgb : (H, W, 3) uint8, row 0 at the top.
    depth : (H, W) float, window depth 0..1, 1.0 where empty; or a function of no arguments
        that returns it, called once, when :attr:`depth` is first read.
    coverage : (H, W) bool, True where a triangle was drawn.

    >>> f = Frame(np.zeros((2, 3, 3), np.uint8), lambda: np.ones((2, 3)), np.zeros((2, 3), bool))
    >>> f.size, float(f.depth.max())
    ((3, 2), 1.0)
    """

    __slots__ = ("rgb", "coverage", "_depth")

    def __init__(self, rgb: np.ndarray, depth: DepthSource, coverage: np.ndarray):
        self.rgb = rgb
        self.coverage = coverage
        self._depth = depth

    @property
    def depth(self) -> np.ndarray:
        """(H, W) window depth 0..1, 1.0 where empty (made now if it was handed over as a function)."""
        if callable(self._depth):
            self._depth = self._depth()
        return self._depth

    @property
    def size(self) -> tuple[int, int]:
        """(width, height) in pixels."""
        return int(self.rgb.shape[1]), int(self.rgb.shape[0])

    def __repr__(self) -> str:
        width, height = self.size
        return f"Frame({width}×{height})"
