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

from typing import NamedTuple

import numpy as np
from renderer.jit import njit, prange

from renderer.workspace import empty

SUBPIXEL_BITS = 8
SUBPIXEL = 1 << SUBPIXEL_BITS  # 256 steps per pixel


class WindowVertices(NamedTuple):
    """Vertices in window space, as the raster's set-up reads them: ``fixed`` (M, 2) int64, x
    and y on the 1/256 grid; ``window`` (M, 3) float, x, y up and z in 0..1; ``cells`` (M,)
    int64, each vertex's :func:`centre_cell`, or empty where none were worked out."""

    fixed: np.ndarray
    window: np.ndarray
    cells: np.ndarray


NO_CELLS = np.empty(0, np.int64)
"""The centre cells of vertices that come without them: the set-up then drops nothing by them."""


def clip_to_window(tri_clip, width, height, ws=None, name="window.mapped"):
    """Clip-space points (..., 4) → window space: (K, 3, 4) triangles, or (M, 4) vertices.

    Returns ``window`` (..., 3) float (x, y up, z in 0..1) and ``fixed`` (..., 2) int64,
    x and y snapped to the 1/256 grid: ``x_fixed = round_half_even((x − 0.5)·256)``, so
    multiples of 256 are pixel centres. Each point is mapped on its own, so a vertex
    shared by many triangles is mapped once and gives them all the same bits. With a
    workspace ``ws`` the outputs live in it (under ``name``).
    """
    tri_clip = np.ascontiguousarray(tri_clip, dtype=np.float64)
    shape = tri_clip.shape[:-1]
    window = empty(ws, f"{name}.window", shape + (3,))
    fixed = empty(ws, f"{name}.fixed", shape + (2,), np.int64)
    cells = empty(ws, f"{name}.cells", shape, np.int64)
    window_into(tri_clip.reshape(-1, 4), width, height, window.reshape(-1, 3), fixed.reshape(-1, 2), cells.reshape(-1))
    return window, fixed


@njit(cache=True, parallel=True)
def window_into(points_clip, width, height, window, fixed, cells):
    """The loop kernel of :func:`clip_to_window`, point by point: (M, 4) → (M, 3), (M, 2), and
    each point's :func:`centre_cell` into ``cells`` (M,).
    Each point on its own, so a parallel loop gives the same bits on any number of threads.
    Serial, it was 5 % of a frame of the 1M-triangle scan at 512²; measured, the kernel alone
    on a frame's vertices, two threads against one: its 537k vertices 1.09 against 2.13 ms,
    the level-4 Menger sponge's 284k 0.57 against 1.10."""
    for i in prange(points_clip.shape[0]):
        map_point(points_clip, i, width, height, window, fixed, cells)


@njit(cache=True, inline="always")
def map_point(points_clip, i, width, height, window, fixed, cells):
    """Row ``i`` of ``points_clip`` (M, 4) mapped to the window: its row of ``window`` (x, y up,
    z in 0..1), of ``fixed`` (x, y on the 1/256 grid, rounded half to even) and its
    :func:`centre_cell`. The one definition of the mapping: :func:`window_into` runs it for
    every point, :func:`renderer.transform.transform_vertices` for each vertex it has
    transformed (the same bits)."""
    w = points_clip[i, 3]
    x = (points_clip[i, 0] / w + 1.0) * (width / 2.0)
    y = (points_clip[i, 1] / w + 1.0) * (height / 2.0)
    window[i, 0] = x
    window[i, 1] = y
    window[i, 2] = (points_clip[i, 2] / w + 1.0) / 2.0
    x_fixed, y_fixed = np.int64(np.rint((x - 0.5) * SUBPIXEL)), np.int64(np.rint((y - 0.5) * SUBPIXEL))
    fixed[i, 0], fixed[i, 1] = x_fixed, y_fixed
    cells[i] = centre_cell(x_fixed, y_fixed)


@njit(cache=True, inline="always")
def centre_axis(v):
    """One axis of :func:`centre_cell`: ``2·⌊v / 256⌋``, plus 1 when ``v`` lies between two
    pixel centres rather than on one (an arithmetic shift is the floor for negative ``v`` too)."""
    return np.int64(2) * (v >> np.int64(SUBPIXEL_BITS)) + np.int64((v & np.int64(SUBPIXEL - 1)) != 0)


LOW32 = np.int64(0xFFFFFFFF)


@njit(cache=True, inline="always")
def centre_cell(x_fixed, y_fixed):
    """Where a fixed-point vertex lies among the pixel centres, in one int64: x's
    :func:`centre_axis` in the high 32 bits, y's in the low 32 (two's complement, cut to 32
    bits). Odd: strictly between two centres of that axis; even: on one. Three corners
    whose x codes are equal and odd lie strictly between the same two centre columns, so
    their box holds no column of centres (:func:`renderer.pixel_centres.box_misses_centres`,
    from the three codes alone: a twelfth of the bytes of their fixed and window rows)."""
    return (centre_axis(x_fixed) << np.int64(32)) | (centre_axis(y_fixed) & LOW32)


@njit(cache=True, parallel=True)
def centre_cells(fixed, cells):
    """:func:`centre_cell` of every row of ``fixed`` (M, 2) into ``cells`` (M,), for vertex
    tables made without :func:`window_into` (triangles given whole)."""
    for i in prange(fixed.shape[0]):
        cells[i] = centre_cell(fixed[i, 0], fixed[i, 1])


@njit(cache=True, inline="always")
def window_edges(window, i0, i1, i2):
    """The triangle whose corners are rows ``i0, i1, i2`` of a window-space table (M, ≥ 2) as
    ``(x0, y0, e1x, e1y, e2x, e2y)``: corner 0 and the edges to corners 1 and 2, in its own
    corner order (the plane of its screen-space weights)."""
    x0, y0 = window[i0, 0], window[i0, 1]
    return x0, y0, window[i1, 0] - x0, window[i1, 1] - y0, window[i2, 0] - x0, window[i2, 1] - y0


@njit(cache=True, inline="always")
def signed_area_fixed(f):
    """Twice the signed area of a fixed-point triangle (3, 2), in the grid's units; > 0 =
    counter-clockwise in window coordinates (y up): a front face (OpenGL's default)."""
    return (f[1, 0] - f[0, 0]) * (f[2, 1] - f[0, 1]) - (f[2, 0] - f[0, 0]) * (f[1, 1] - f[0, 1])


@njit(cache=True, inline="always")
def signed_area_corners(fixed, i0, i1, i2):
    """:func:`signed_area_fixed` of the triangle whose corners are rows ``i0, i1, i2`` of a
    fixed-point vertex table (M, 2)."""
    return ((fixed[i1, 0] - fixed[i0, 0]) * (fixed[i2, 1] - fixed[i0, 1])
            - (fixed[i2, 0] - fixed[i0, 0]) * (fixed[i1, 1] - fixed[i0, 1]))


def window_rows_to_image_rows(a: np.ndarray) -> np.ndarray:
    """Window row j (y up) → image row H − 1 − j (row 0 at the top). The only y flip.

    Returns a reversed view (no copy).
    """
    return a[::-1]
