"""PNG files: 8-bit RGB images written atomically (Pillow only; no matplotlib).

:func:`write_png` goes through :func:`lab.atomic.atomic_file`: an interrupted write never
leaves a partial PNG behind, and an existing target stays untouched until the new file
is complete.
"""
from __future__ import annotations

import io
import os

import numpy as np
from PIL import Image

from lab.atomic import atomic_file


def _image(rgb: np.ndarray) -> Image.Image:
    rgb = np.asarray(rgb)
    if rgb.dtype != np.uint8 or rgb.ndim != 3 or rgb.shape[2] != 3:
        raise TypeError(f"expected (H, W, 3) uint8, got {rgb.dtype} {rgb.shape}")
    return Image.fromarray(np.ascontiguousarray(rgb))


def write_png(path: str | os.PathLike, rgb: np.ndarray) -> None:
    """Write an 8-bit RGB image as PNG, atomically.

    Parameters
    ----------
    path : target file name.
    rgb : (H, W, 3) uint8, sRGB-encoded, row 0 at the top.
    """
    image = _image(rgb)
    with atomic_file(path) as f:
        image.save(f, format="PNG")


def png_bytes(rgb: np.ndarray, compress_level: int = 6) -> bytes:
    """An 8-bit RGB image (as :func:`write_png` takes it) as the bytes of a PNG file;
    ``compress_level`` 0..9 trades size for time (1 is several times faster than 6,
    for images sent once over a local connection)."""
    f = io.BytesIO()
    _image(rgb).save(f, format="PNG", compress_level=compress_level)
    return f.getvalue()
