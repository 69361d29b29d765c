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
from renderer.jit import njit

from renderer.workspace import empty

SUBPIXEL_BITS = 8
SUBPIXEL = 1 << SUBPIXEL_BITS  # 256 steps per pixel


def clip_to_window(tri_clip, width, height, ws=None):
    """(K, 3, 4) clip-space triangles → window space.

    Returns ``tri_window`` (K, 3, 3) float (x, y up, z in 0..1) and ``tri_fixed``
    (K, 3, 2) int64, x and y snapped to the 1/256 grid:
    ``x_fixed = round_half_even((x − 0.5)·256)``, so multiples of 256 are pixel centres.
    With a workspace ``ws`` the outputs live in it.
    """
    tri_clip = np.ascontiguousarray(tri_clip, dtype=np.float64).reshape(-1, 3, 4)
    tri_window = empty(ws, "window.window", (len(tri_clip), 3, 3))
    tri_fixed = empty(ws, "window.fixed", (len(tri_clip), 3, 2), np.int64)
    window_into(tri_clip, width, height, tri_window, tri_fixed)
    return tri_window, tri_fixed


@njit(cache=True)
def window_into(tri_clip, width, height, tri_window, tri_fixed):
    """The loop kernel of :func:`clip_to_window`."""
    k_count = tri_clip.shape[0]
    for k in range(k_count):
        for v in range(3):
            w = tri_clip[k, v, 3]
            x = (tri_clip[k, v, 0] / w + 1.0) * (width / 2.0)
            y = (tri_clip[k, v, 1] / w + 1.0) * (height / 2.0)
            tri_window[k, v, 0] = x
            tri_window[k, v, 1] = y
            tri_window[k, v, 2] = (tri_clip[k, v, 2] / w + 1.0) / 2.0
            tri_fixed[k, v, 0] = np.int64(np.rint((x - 0.5) * SUBPIXEL))
            tri_fixed[k, v, 1] = np.int64(np.rint((y - 0.5) * SUBPIXEL))


def window_rows_to_image_rows(a: np.ndarray) -> np.ndarray:
    """Window row j (y up) → image row H − 1 − j (row 0 at the top). The only y flip.

    Returns a reversed view (no copy).
    """
    return a[::-1]
