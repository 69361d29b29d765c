"""PNG files: 8-bit RGB images written atomically (Pillow only; no matplotlib).

:func:`write_png` goes through :func:`lab.atomic.atomic_file`: an interrupted write never
leaves a partial PNG behind, and an existing target stays untouched until the new file
is complete.
"""
from __future__ import annotations

import os

import numpy as np
from PIL import Image

from lab.atomic import atomic_file


def write_png(path: str | os.PathLike, rgb: np.ndarray) -> None:
    """Write an 8-bit RGB image as PNG, atomically.

    Parameters
    ----------
    path : target file name.
    rgb : (H, W, 3) uint8, sRGB-encoded, row 0 at the top.
    """
    rgb = np.asarray(rgb)
    if rgb.dtype != np.uint8 or rgb.ndim != 3 or rgb.shape[2] != 3:
        raise TypeError(f"expected (H, W, 3) uint8, got {rgb.dtype} {rgb.shape}")
    image = Image.fromarray(np.ascontiguousarray(rgb))
    with atomic_file(path) as f:
        image.save(f, format="PNG")
