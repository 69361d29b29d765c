"""Texture images for scene objects, loaded once and handed to both renderers.

Convention: ``texels[j, i]`` is the texel at column i (s increasing) and row j counted
from the *bottom* of the image (t increasing), as OpenGL stores a texture; loading flips
the image file's rows (file row 0 is the top) exactly once, here. Values are the file's
8-bit values divided by 255 (linear, no sRGB decoding, as VTK samples them).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np

from lab.values import file_problem

FILTERS = ("nearest", "linear")
WRAPS = ("repeat", "clamp")


@dataclass(frozen=True, eq=False)
class Texture:
    """An RGB texture with its sampling rules.

    texels : (H, W, 3) float64 in 0..1, row 0 at t = 0 (the image's bottom row).
    filter : "nearest" (VTK's default) or "linear" (bilinear, no mipmaps).
    wrap : "repeat" (VTK's default) or "clamp" (to the edge texels).
    source : the file it came from.
    """

    texels: np.ndarray
    filter: str = "nearest"
    wrap: str = "repeat"
    source: str = ""

    @cached_property
    def texels_8bit(self) -> np.ndarray:
        """(H, W, 3) uint8 ``round(texel·255)``, row 0 at t = 0: what VTK uploads and both
        renderers sample. Worked out once per texture."""
        return np.ascontiguousarray(np.rint(self.texels * 255.0).astype(np.uint8))

    @property
    def image_rows(self) -> np.ndarray:
        """The texels as 8-bit image rows, row 0 at the top (what an image file holds)."""
        return self.texels_8bit[::-1]


def load_texture(path, filter: str = "nearest", wrap: str = "repeat") -> Texture:
    """Read an image file with Pillow into a :class:`Texture` (alpha is dropped).

    Raises ValueError with the path in its message when the file cannot be read.
    """
    from PIL import Image, UnidentifiedImageError

    problem = file_problem(path)
    if problem:
        raise ValueError(f"{path}: cannot read the texture image ({problem})")
    try:
        with Image.open(path) as im:
            rgb = np.asarray(im.convert("RGB"), dtype=np.float64) / 255.0
    except UnidentifiedImageError:
        raise ValueError(f"{path}: not an image file Pillow can read") from None
    except (OSError, Image.DecompressionBombError) as exc:  # missing, a folder, truncated, too many pixels
        reason = getattr(exc, "strerror", None) or " ".join(str(exc).split())[:100] or type(exc).__name__
        raise ValueError(f"{path}: cannot read the texture image ({reason})") from None
    if rgb.ndim != 3 or rgb.shape[0] < 1 or rgb.shape[1] < 1:
        raise ValueError(f"{path}: the texture image has no pixels")
    return Texture(texels=np.ascontiguousarray(rgb[::-1]), filter=filter, wrap=wrap, source=str(Path(path)))
