"""Back faces drawn last, behind a tile z-buffer: skipped where they are certainly hidden.

Seen from outside, a closed surface shows its front faces (counter-clockwise on screen): a
ray enters it before it leaves. So about half of such a mesh's triangles are drawn for
nothing. Culling them on that argument alone is not exact: at a silhouette a back face
can win a pixel, its depth extrapolated a little past the front face's snapped edge (a
level-3 Menger sponge at 512² has six such pixels, and VTK gives all six to the back face).
So nothing is culled on trust. In each band the raster draws a batch's front faces first,
then its back faces, and skips a back face's rows in a block only where the tiles prove
every fragment of it farther than what is already drawn there. The frame is the same,
byte for byte, as one drawn in plain order.

- **Order** (:func:`renderer.visibility_buffer.nearer_or_later`): a fragment replaces the
  pixel's when it is nearer, or as near and its triangle is numbered later. In draw order
  that is the LEQUAL test; it also decides a back face drawn after later front faces as
  drawing in order would have.
- **Tiles** (:data:`TILE` × :data:`TILE` pixels, window rows): the largest depth in a
  tile, worked out when a back face first asks for it in a batch (marked with the batch's
  first triangle number, so a later batch works it out again), after the band has drawn
  the batch's front faces. A tile's rows lie in one block of one band
  (:data:`renderer.bands.BLOCK_ROWS` is a multiple of :data:`TILE`), so only that band
  reads or writes it. Back faces drawn afterwards only lower the depths: the value stays
  an upper bound.
- **Floor** (:func:`fragment_depth_floor`): no fragment of a triangle is nearer than its
  depth plane at its nearest *snapped* corner (each pixel centre it covers lies inside
  the snapped triangle), less 10⁻⁹ for rounding, on the 24-bit grid. A block of rows is
  skipped when the floor is deeper than every tile under the triangle's columns there
  (:func:`hidden_in_tiles`): each of its fragments would fail the test.
- **Which frames**: every frame with the z-buffer on, in every batch whose triangles span
  :data:`BACKS_LAST_ROWS` rows or more on average, and in a frame of more than
  :data:`renderer.raster.BATCH` triangles drawn as one batch (:data:`renderer.pipeline.ONE_BATCH`)
  whatever its rows, unless its triangles are finer than the pixels
  (:data:`renderer.pixel_centres.LONE_ROWS`): there the tiles hold every front face of the
  frame and hide most back faces however small (in batches, the front faces drawn before a
  batch's back faces hide too little). A smaller frame keeps its order, and a cold start
  its kernels (the tiles' raster loop took 57 % of the start-up frame's compile, against
  50 % for the loop in order). Where back faces do
  show (an open surface, a camera inside a sphere) the second pass skips nothing and
  costs little: measured, whole frames, two threads, back faces last against in order,
  the presets ``open-box`` 1.005, ``tilted-plane`` 1.001, ``globe`` 0.996,
  ``icosahedron-fractal`` 1.026, ``csg`` 0.926. A choice of speed only: both give the
  same image.
"""
from __future__ import annotations

import numpy as np

from renderer.jit import njit
from renderer.min_max import clamp, larger, smaller
from renderer.visibility_buffer import depth_bits
from renderer.window import SUBPIXEL
from renderer.workspace import empty

TILE = 16
"""Rows and columns of a tile of the tile z-buffer."""

BACKS_LAST_ROWS = 4
"""The rows a batch's triangles must span on average (:func:`renderer.raster.mean_rows`) for
the raster to draw its back faces last: for smaller ones the tiles' tests cost more than
the hidden ones save. Measured, two threads, whole frames, back faces last against in
order: a 1,024-segment cylinder (127 rows) at 512² 0.78; ico5 at 1024² (19 rows) 0.83;
but ico7 at 512² (2.5 rows) 1.15–1.18, and the 270k-triangle Igea scan 1.23 (before the
passes read lists by facing, :mod:`renderer.draw_lists`). With the lists, from 2 rows: ico7
at 512² 1.00–1.03, the level-4 sponge at 512² (2.9 rows) 0.98 and 1.13. It was 8 until the
z-buffer's vector loops stored whole lanes (``kept_depth``); since then, from 4 rows against
from 8, frames alternating in one process (30 pairs, medians): ico7 at 1024² (4.9 rows)
0.88, 0.91 flat and 0.90 phong, the level-4 sponge at 1024² (5–6 rows) 0.94 and 1.02; its
raster alone ico7 0.75–0.86, the sponge 0.88–1.00 (docs/performance.md)."""

NO_BATCH = -1
"""The mark of a tile worked out for no batch yet (batches are marked with their first
triangle's number, ≥ 0)."""


def new_tiles(height: int, width: int, ws=None) -> np.ndarray:
    """The tile z-buffer for a frame of ``height`` × ``width`` pixels: (2, ⌈H/16⌉, ⌈W/16⌉)
    int32, plane 0 each tile's largest depth, plane 1 the batch it was worked out for (all
    :data:`NO_BATCH`)."""
    tiles = empty(ws, "raster.tiles", (2, -(-height // TILE), -(-width // TILE)), np.int32)
    tiles[1] = NO_BATCH
    return tiles


NO_TILES = None
"""The tile z-buffer of a frame drawn in plain order (no back faces last): the raster's band
kernels compile a loop of their own for it (:func:`renderer.raster.band_dividing`)."""

UNTESTED = np.empty((2, 0, 0), np.int32)
"""Tiles no block is tested against (a front face's, or any in plain order)."""


@njit(cache=True, inline="always")
def fragment_depth_floor(f, plane):
    """A 24-bit depth no fragment of a triangle is nearer than: its depth plane (``plane``
    (11,), :class:`renderer.raster.TriangleSetup`; z = az + zx·(x − ax) + zy·(y − ay), window
    coordinates) at its nearest snapped corner (``f`` (3, 2), fixed point: window x = f/256 +
    0.5), less 10⁻⁹."""
    ax, ay, az, zx, zy = plane[6], plane[7], plane[8], plane[9], plane[10]
    low = np.inf
    for c in range(3):
        low = smaller(low, az + zx * (f[c, 0] / SUBPIXEL + 0.5 - ax) + zy * (f[c, 1] / SUBPIXEL + 0.5 - ay))
    return depth_bits(low - 1e-9)


@njit(cache=True, inline="always")
def tile_depth(tile_row, tile_col, batch, depth, tiles):
    """The largest depth of tile (``tile_row``, ``tile_col``) of ``depth`` (H, W), worked out
    once for batch ``batch`` and kept in ``tiles``."""
    if tiles[1, tile_row, tile_col] != batch:
        height, width = depth.shape
        deepest = np.int32(0)
        first, end = tile_col * TILE, smaller(tile_col * TILE + TILE, width)
        for row in range(tile_row * TILE, smaller(tile_row * TILE + TILE, height)):
            deepest = larger(deepest, deepest_in_row(depth[row], first, end))
        tiles[0, tile_row, tile_col], tiles[1, tile_row, tile_col] = deepest, batch
    return tiles[0, tile_row, tile_col]


@njit(cache=True, inline="always")
def deepest_in_row(depth_row, first, end):
    """The largest of ``depth_row[first:end]`` (int32, 0 for none), read with unsigned
    indices: a signed one costs each read a test for a negative index (numba wraps it
    around), and LLVM then read the values one by one through a vector gather
    (``vpgatherqd``, 9 % of the raster's time for the 1,024-segment cylinder at 1024²)
    instead of loading them side by side."""
    deepest = np.int32(0)
    for col in range(first, end):
        deepest = larger(deepest, depth_row[np.uint64(col)])
    return deepest


@njit(cache=True, inline="always")
def hidden_in_tiles(floor, f, top, bottom, batch, depth, tiles):
    """True when a triangle whose fragments are no nearer than ``floor`` draws nothing on
    rows ``top … bottom``: its columns there (from its fixed-point corners ``f``, pixel
    centre at 256·col) meet only tiles whose largest depth is nearer than ``floor``."""
    width = depth.shape[1]
    first = clamp(-((-smaller(smaller(f[0, 0], f[1, 0]), f[2, 0])) // SUBPIXEL), 0, width - 1)
    last = clamp(larger(larger(f[0, 0], f[1, 0]), f[2, 0]) // SUBPIXEL, 0, width - 1)
    for tile_row in range(top // TILE, bottom // TILE + 1):
        for tile_col in range(first // TILE, last // TILE + 1):
            if tile_depth(tile_row, tile_col, batch, depth, tiles) >= floor:
                return False
    return True
