"""Window space → pixel mask: which pixel centres one triangle covers, by the renderer's own rule.

The question the scanline fill answers for each triangle, asked for one triangle alone:
the vertices are snapped to the 1/256-pixel grid exactly as stage 5 snaps them
(:func:`renderer.window.clip_to_window`: ``x_fixed = round_half_even((x − 0.5)·256)``),
the triangle is put in counter-clockwise order, and every pixel row takes the span of
:func:`renderer.raster.scanline_span` — the top-left rule included. So the mask is
exactly the set of pixels the renderer (and llvmpipe, which VTK draws with) fills for
this triangle; ``tests/renderer/test_coverage.py`` checks it against
:func:`renderer.raster.rasterize_triangles`.

Conventions: window coordinates, x to the right and **y up**, in pixels; pixel (x, y)
has its centre at (x + 0.5, y + 0.5); ``mask[y, x]`` in window rows (row 0 at the
bottom). A triangle of zero area (after snapping) covers nothing; both windings draw.
"""
from __future__ import annotations

import numpy as np
from renderer.jit import njit
from renderer.min_max import larger, smaller

from renderer.fill_rules import FILL_RULES
from renderer.pixel_centres import ceil_div
from renderer.raster import scanline_span
from renderer.window import SUBPIXEL, signed_area_fixed


def window_to_fixed(xy) -> np.ndarray:
    """(..., 2) window x, y (pixels, y up) → int64 fixed point on the 1/256 grid, pixel
    centre (i, j) at (256·i, 256·j): the rounding of :func:`renderer.window.window_into`."""
    return np.rint((np.asarray(xy, dtype=np.float64) - 0.5) * SUBPIXEL).astype(np.int64)


@njit(cache=True)
def coverage_into(fixed, width, height, rule, mask):
    """The loop kernel: set ``mask[row, col]`` for every pixel centre the fixed-point
    triangle ``fixed`` (3, 2) covers under ``rule`` (a code of :data:`renderer.raster.FILL_RULES`)."""
    f = fixed.copy()
    area = signed_area_fixed(f)
    if area == 0:
        return
    if area < 0:  # counter-clockwise for the span test, as setup_triangles does
        f[1, 0], f[1, 1], f[2, 0], f[2, 1] = fixed[2, 0], fixed[2, 1], fixed[1, 0], fixed[1, 1]
    first_row = larger(0, ceil_div(smaller(smaller(f[0, 1], f[1, 1]), f[2, 1]), SUBPIXEL))
    last_row = smaller(height - 1, larger(larger(f[0, 1], f[1, 1]), f[2, 1]) // SUBPIXEL)
    for row in range(first_row, last_row + 1):
        first, last = scanline_span(f, row, rule)
        for col in range(larger(first, 0), smaller(last, width - 1) + 1):
            mask[row, col] = True


def triangle_coverage(v0, v1, v2, width: int, height: int, fill_rule: str = "top-left") -> np.ndarray:
    """The (height, width) bool mask of the pixel centres the triangle covers (window rows, y up).

    Parameters
    ----------
    v0, v1, v2 : window-space (x, y) pairs, pixels, y up.
    width, height : the window, pixels.
    fill_rule : "top-left" (the renderer's and VTK's) or "bottom-right" (deliberately wrong).

    Examples
    --------
    >>> triangle_coverage((0, 0), (2, 0), (0, 2), 2, 2).astype(int).tolist()
    [[1, 0], [0, 0]]
    """
    fixed = window_to_fixed(np.array([v0, v1, v2], dtype=np.float64).reshape(3, 2))
    mask = np.zeros((int(height), int(width)), np.bool_)
    coverage_into(fixed, int(width), int(height), FILL_RULES[fill_rule], mask)
    return mask
