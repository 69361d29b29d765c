"""Which pixel centres a triangle's box holds: whether it can cover any at all, found at set-up.

A triangle covers the pixel centres inside it (:func:`renderer.raster.scanline_span`, the
top-left rule), and those lie in its box: between its lowest and highest corner a *row* of
centres, and between its leftmost and rightmost a *column* of them. A triangle whose box
holds none covers none, and the raster's set-up gives it no rows
(:func:`renderer.raster.set_up_range`): nothing reads its planes or corners again. On a mesh
finer than the pixels most triangles are such, and most of the rest hold one centre, which
a triangle often misses: :func:`outside_an_edge` tests it, and one that misses it is dropped
too (in batches where that pays, :data:`LONE_ROWS`).

Coordinates: the window's fixed-point grid (:mod:`renderer.window`): y up, 1/256 pixel,
pixel centre (i, j) at (256·i, 256·j).
"""
from __future__ import annotations

import numpy as np

from renderer.jit import njit
from renderer.min_max import larger, smaller
from renderer.window import LOW32, SUBPIXEL


@njit(cache=True, inline="always")
def ceil_div(a, b):
    """⌈a / b⌉ for integers, b > 0."""
    return -((-a) // b)


@njit(cache=True, inline="always")
def centre_rows(fixed, i0, i1, i2, area, height, lone_test):
    """The first and last window row of pixel centres the triangle with corners ``i0, i1, i2``
    (rows of the fixed-point table (M, 2); ``area`` its :func:`renderer.window.signed_area_corners`)
    may cover, clamped to the image's ``height``; none, (1, 0), when it surely covers none:

    - its box holds no centre: no row of centres between its lowest and highest corner, or
      no *column* of them between its leftmost and rightmost;
    - with ``lone_test``, its box holds one centre, and that centre lies strictly outside
      one of its edges (:func:`outside_an_edge`; a centre on an edge is left to the fill rule).

    A 1M-triangle scan at 512²: 68 % of its triangles have no row or no column of centres
    (42 % have no row), and 32 % hold one centre."""
    x_min = smaller(smaller(fixed[i0, 0], fixed[i1, 0]), fixed[i2, 0])
    x_max = larger(larger(fixed[i0, 0], fixed[i1, 0]), fixed[i2, 0])
    y_min = smaller(smaller(fixed[i0, 1], fixed[i1, 1]), fixed[i2, 1])
    y_max = larger(larger(fixed[i0, 1], fixed[i1, 1]), fixed[i2, 1])
    col, last_col = ceil_div(x_min, SUBPIXEL), x_max // SUBPIXEL
    row, last_row = ceil_div(y_min, SUBPIXEL), y_max // SUBPIXEL
    if col > last_col or (col == last_col and row == last_row and lone_test
                          and outside_an_edge(fixed, i0, i1, i2, area, col * SUBPIXEL, row * SUBPIXEL)):
        return 1, 0
    return larger(0, row), smaller(height - 1, last_row)


@njit(cache=True, inline="always")
def box_misses_centres(c0, c1, c2):
    """True when a triangle's box holds no pixel centre, from its corners' centre cells
    (:func:`renderer.window.centre_cell`) alone: its three x codes equal and odd (all three
    corners strictly between the same two centre columns: no column of centres between its
    leftmost and rightmost corner), or its three y codes so (no row). The same answer as
    :func:`centre_rows`'s box test, without reading the corners' coordinates: on a mesh finer
    than the pixels most triangles are dropped so (the 1M-triangle scan at 512²: 68 %)."""
    differ = (c0 ^ c1) | (c0 ^ c2)
    return ((differ >> np.int64(32)) == 0 and (c0 >> np.int64(32)) & 1 == 1) or (
        (differ & LOW32) == 0 and c0 & 1 == 1)


@njit(cache=True, inline="always")
def outside_an_edge(fixed, i0, i1, i2, area, x, y):
    """Whether the fixed-point point (x, y) lies strictly outside an edge of the triangle with
    corners ``i0, i1, i2`` (rows of ``fixed`` (M, 2)) and signed area ``area``: an edge
    function of :func:`renderer.raster.scanline_span`'s (``E = dx·(Y − ya) − dy·(X − xa)`` along corner
    order) of the wrong sign, ``E·area < 0``. No fill rule passes such a point (one on an
    edge, E = 0, is not outside: the rule decides it when the triangle is drawn)."""
    for a, b in ((i0, i1), (i1, i2), (i2, i0)):
        e = (fixed[b, 0] - fixed[a, 0]) * (y - fixed[a, 1]) - (fixed[b, 1] - fixed[a, 1]) * (x - fixed[a, 0])
        if (e < 0 < area) or (e > 0 > area):
            return True
    return False


LONE_ROWS = 1.5
"""The batch's set-up tests the lone pixel centre of a triangle's box (:data:`renderer.raster.DROP_MISSED_CENTRES`),
and first drops the triangles whose box holds none by their corners' centre cells
(:func:`box_misses_centres`, :data:`renderer.raster.DROP_EMPTY_BOXES`),
when the batch before it spanned fewer rows a triangle than this on average: a mesh finer
than the pixels, whose triangles mostly hold no centre, the rest one, and most of those
miss it. Measured, the set-up and the raster of whole frames, the test on and off
alternating in one process (ratios on/off, the same buffers): a 1M-triangle scan at 512²
(0.11–0.38 rows a triangle; drawable triangles 342k → 121k) 0.80; but the 270k one at 512²
(0.75–1.06 rows; 208k → 154k) 1.05–1.10 and the 1M one at 1024² 1.02–1.05, where the
test cost the set-up more than it saved the raster. The cells, measured the same way (40
pairs, medians, the raster stage and the whole frame): the 1M-triangle scan at 512² 0.897
and 0.934; in batches up to 1.5 rows a triangle, the 270k one at 512² 1.011 and 1.001, and
frames of ico7 at 512² (2.5 rows) and of the level-4 sponge at 512² (2.9) 1.03: so they go
with the lone test. It was 0.6 until the z-buffer's vector loops stored whole lanes
(:func:`renderer.visibility_buffer.kept_depth`); since then, 1.5 against 0.6, whole frames
alternating in one process (30 pairs, medians, four processes): the 270k scan at 512²
(0.78–1.06 rows) 0.940–0.987, the 1M one at 1024² (0.66–1.24) 0.970–0.978, and ico7 at 512²,
whose batches stay above both, 0.991–1.003; at 2.5, ico7 at 512² 1.007 and 1.018
(docs/performance.md)."""
