"""A rendered frame: what both renderers return.

Conventions: image rows, row 0 at the top (as in a PNG); ``rgb`` is 8-bit sRGB-encoded
values exactly as written to the framebuffer (no gamma applied anywhere); ``depth`` is
window depth in 0..1 (``(z_ndc + 1) / 2``), 1.0 where nothing was drawn; ``coverage`` is
True where some triangle was drawn.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(eq=False)
class Frame:
    """An H×W rendered image with its depth and coverage.

    Parameters
    ----------
    rgb : (H, W, 3) uint8, row 0 at the top.
    depth : (H, W) float, window depth 0..1, 1.0 where empty.
    coverage : (H, W) bool, True where a triangle was drawn.
    """

    rgb: np.ndarray
    depth: np.ndarray
    coverage: np.ndarray

    @property
    def size(self) -> tuple[int, int]:
        """(width, height) in pixels."""
        return int(self.rgb.shape[1]), int(self.rgb.shape[0])
