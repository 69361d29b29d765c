"""Stage 5, clip space → window space: perspective division and the viewport.

Window coordinates follow OpenGL: x to the right, **y up**, in pixels, with pixel (i, j)
covering [i, i+1] × [j, j+1] and its centre at (i + 0.5, j + 0.5); depth
``z_window = (z_ndc + 1) / 2`` in 0..1 (near → 0). Vertex x and y are also snapped to a
1/256-pixel grid (8 sub-pixel bits, as llvmpipe does), as integers ``x_fixed`` measured
from the pixel-centre lattice: pixel centre (i, j) sits at (256·i, 256·j).

The flip from window rows (y up) to image rows (row 0 at the top) happens in one place,
:func:`window_rows_to_image_rows`.
"""
from __future__ import annotations

import numpy as np

SUBPIXEL_BITS = 8
SUBPIXEL = 1 << SUBPIXEL_BITS  # 256 steps per pixel


def clip_to_window(verts_clip: np.ndarray, width: int, height: int) -> np.ndarray:
    """(..., 4) clip-space rows → (..., 3) window (x, y, z); y up, z in 0..1."""
    ndc = verts_clip[..., :3] / verts_clip[..., 3:4]
    out = np.empty_like(ndc)
    out[..., 0] = (ndc[..., 0] + 1.0) * (width / 2.0)
    out[..., 1] = (ndc[..., 1] + 1.0) * (height / 2.0)
    out[..., 2] = (ndc[..., 2] + 1.0) / 2.0
    return out


def snap_to_subpixel(verts_window: np.ndarray) -> np.ndarray:
    """Window x, y → int64 fixed point on the 1/256 grid, origin at pixel centre (0, 0).

    ``x_fixed = round((x − 0.5)·256)``, so integer multiples of 256 are pixel centres.
    """
    return np.rint((verts_window[..., :2] - 0.5) * SUBPIXEL).astype(np.int64)


def window_rows_to_image_rows(a: np.ndarray) -> np.ndarray:
    """Window row j (y up) → image row H − 1 − j (row 0 at the top). The only y flip."""
    return np.ascontiguousarray(a[::-1])
