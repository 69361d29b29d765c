"""Narrow triangles by edge functions: each row's pixels tested against all three edges at once, 8 lanes a step.

:func:`renderer.raster.scanline_span` finds a row's span by one integer division per edge.
A triangle of a large mesh is a few pixels wide and two or three rows tall, and there
those divisions, and the branches around them, were most of the raster's work (a level-4
Menger sponge at 512²: 672k triangles, 2.9 rows each). llvmpipe draws small triangles the
other way, and so does this module: the course's **inside test**. The edge function of an
edge a → b of a counter-clockwise triangle,

    E(P) = dx·(Y − ya) − dy·(X − xa),

is positive on the inner side of the edge, and a pixel centre is inside the triangle when
all three are. A triangle whose bounding box is at most :data:`renderer.spans.LANES`
columns wide fits one group of lanes: each row evaluates the three functions at the
group's 8 pixel centres (E is affine: −dy per pixel to the right, dx per row up), and
the depth test (:func:`renderer.visibility_buffer.fill_columns`'s, the same expression)
keeps only the pixels inside. No division, no branch per pixel. Measured, whole frames,
one thread: a level-4 sponge at 512² 101 → 79 ms, at 1024² 146 → 108; ico7 phong at
1024² 107 → 95 (:data:`renderer.raster.NARROW_ROWS` says which stretches come here).

**Top-left rule**, the same as :func:`renderer.raster.scanline_span`'s: a centre exactly on
an edge (E = 0) belongs to the triangle when the edge *owns* it (:func:`owns_ties`), a
left edge (dy < 0) or a bottom edge (dy = 0, dx > 0), y up. Both are exact integer tests
on the same snapped corners, so they choose the same pixels (a test draws every narrow
triangle both ways).

Coordinates: the window's fixed-point grid (y up, 1/256 pixel, pixel centre (i, j) at
(256·i, 256·j)); the clipper leaves no guard band, so E stays far inside int64.
"""
from __future__ import annotations

import numpy as np

from renderer.jit import njit
from renderer.min_max import larger, smaller
from renderer.spans import LANES, round_up_to_lanes
from renderer.visibility_buffer import depth_bits, kept_depth, nearer_or_later
from renderer.window import SUBPIXEL, SUBPIXEL_BITS


LANE_X = np.arange(LANES, dtype=np.float64)
"""Each lane's column from the group's first, as float64: ``float(start) + LANE_X[i]`` is
``float(start + i)`` exactly, read as one vector where the conversion of each lane's integer
column took eight scalar instructions."""


@njit(cache=True, inline="always")
def lanes_start(f, width):
    """The one group of lanes that holds every pixel of the counter-clockwise fixed-point
    triangle ``f`` (3, 2) in an image ``width`` wide, as ``(start, lanes)``: its first column
    and its width, the box's columns (clamped to the image) rounded up to whole
    :data:`~renderer.spans.LANES` (0 or less: no column of pixel centres). The group starts at
    the box's first column, moved left where it would pass the row's end. ``(−1, 0)`` when
    there is none: the box is wider than the lanes, or the image is narrower."""
    x_min = smaller(smaller(f[0, 0], f[1, 0]), f[2, 0])
    x_max = larger(larger(f[0, 0], f[1, 0]), f[2, 0])
    first = larger(-((-x_min) >> SUBPIXEL_BITS), 0)  # ⌈x_min / 256⌉: the first pixel centre at or right of it
    last = smaller(x_max >> SUBPIXEL_BITS, width - 1)
    if last - first >= LANES or width < LANES:
        return -1, 0
    return smaller(first, width - LANES), round_up_to_lanes(last - first + 1)


@njit(cache=True, inline="always")
def owns_ties(dx, dy, top_left):
    """Whether an edge of direction (dx, dy) (y up, counter-clockwise triangle) owns the pixel
    centres on it: the top-left rule gives them to left edges (dy < 0) and bottom edges
    (dy = 0, dx > 0); ``top_left`` False, the deliberately wrong bottom-right rule, to right
    and top edges."""
    if top_left:
        return dy < 0 or (dy == 0 and dx > 0)
    return dy > 0 or (dy == 0 and dx < 0)


@njit(cache=True, inline="always")
def edge_function(f, e, col, row, top_left):
    """Edge ``e`` (corner e → e + 1) of the counter-clockwise fixed-point triangle ``f`` as
    ``(value, per_column, per_row, bar)``: E at the centre of pixel (col, row), its step a
    column right and a row up, and the bar a centre's E must pass: E > bar (bar −1 for an
    edge that owns its ties, :func:`owns_ties`: E ≥ 0; else 0: E > 0)."""
    xa, ya = f[e, 0], f[e, 1]
    xb, yb = f[(e + 1) % 3, 0], f[(e + 1) % 3, 1]
    dx, dy = xb - xa, yb - ya
    value = dx * (row * SUBPIXEL - ya) - dy * (col * SUBPIXEL - xa)
    return value, -dy * SUBPIXEL, dx * SUBPIXEL, -1 if owns_ties(dx, dy, top_left) else 0


@njit(cache=True, inline="always")
def fill_narrow_rows(f, columns, lo, hi, plane, kk, top_left, depth_test, depth, tri_index):
    """Fill rows ``lo … hi`` of a triangle at most :data:`~renderer.spans.LANES` columns wide
    (``f`` (3, 2), counter-clockwise fixed-point corners; ``columns`` its group of lanes,
    ``(start, lanes)`` from :func:`lanes_start`), numbered ``kk`` in the visibility buffer,
    whose set-up row is ``plane`` (11,) (:class:`renderer.raster.TriangleSetup`): on each
    row, the group's pixels inside all three edges (:func:`edge_function`) whose depth
    passes the test (:func:`renderer.visibility_buffer.nearer_or_later`; every one inside
    without ``depth_test``) take the triangle's depth and number; the others keep their
    old values.

    No 64-bit arithmetic per lane (AVX2 has no vector 64-bit product, nor an int64 → float64
    conversion): the edge functions are stepped a column at a time, and a lane's column
    comes as a float from :data:`LANE_X` (the level-4 sponge at 512², one thread: 106–111 →
    84–85 ms a frame with the int32 kept depth, docs/performance.md)."""
    start, lanes = columns
    e0, c0, r0, bar0 = edge_function(f, 0, start, lo, top_left)
    e1, c1, r1, bar1 = edge_function(f, 1, start, lo, top_left)
    e2, c2, r2, bar2 = edge_function(f, 2, start, lo, top_left)
    ax, ay, az, zx, zy = plane[6], plane[7], plane[8], plane[9], plane[10]
    first_x = np.float64(start)
    for row in range(lo, hi + 1):
        z_row = az + zy * (row + 0.5 - ay)
        depth_row, index_row = depth[row], tri_index[row]
        a0, a1, a2 = e0, e1, e2  # the edge functions at the lane's centre, stepped a column at a time
        for i in range(lanes):
            col = start + i
            at = np.uint64(col)  # unsigned: numba adds no wrap-around for a negative index, which kept loops scalar
            inside = (a0 > bar0) & (a1 > bar1) & (a2 > bar2)
            z = depth_bits(z_row + zx * (first_x + LANE_X[i] + 0.5 - ax))
            a0, a1, a2 = a0 + c0, a1 + c1, a2 + c2
            old_z, old_k = depth_row[at], index_row[at]
            nearer = inside & (nearer_or_later(z, kk, old_z, old_k) | (not depth_test))
            depth_row[at] = kept_depth(z, old_z, inside) if depth_test else (z if inside else old_z)
            index_row[at] = kk if nearer else old_k
        e0, e1, e2 = e0 + r0, e1 + r1, e2 + r2
