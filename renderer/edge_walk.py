"""The edge walk: a fixed-point triangle's spans found row after row without a division per row.

:func:`renderer.raster.scanline_span` bounds each row's columns by one integer quotient per
edge. Walking, each edge's quotient is divided once for a stretch of rows and then stepped
by Δx/Δy a row, the fraction kept as an exact integer remainder (the course's edge
increments, kept exact as in Bresenham's algorithm): the same columns as
:func:`~renderer.raster.scanline_span`, the top-left rule included (``top_left`` True; False
is the deliberately wrong bottom-right rule). :func:`renderer.raster.fill_rows` walks the
edges of tall triangles. Coordinates: the window's fixed-point grid (y up, 1/256 pixel,
pixel centre (i, j) at (256·i, 256·j)); a triangle's corners counter-clockwise.
"""
from __future__ import annotations

from renderer.jit import njit
from renderer.min_max import larger, smaller
from renderer.visibility_buffer import fill_columns
from renderer.window import SUBPIXEL

LEFT, RIGHT = 0, 1
"""What an edge of a counter-clockwise triangle bounds on a scanline (:func:`renderer.raster.scanline_span`):
a left edge (going down, dy < 0) the first column, a right edge (dy > 0) the last."""


@njit(cache=True, inline="always")
def edge_walk(f, e, row, stride, top_left):
    """Edge ``e`` (corner e → e + 1, not horizontal) of a counter-clockwise fixed-point
    triangle ``f`` (3, 2) set up to be walked from pixel row ``row`` up, ``stride`` rows a
    step: the scanline algorithm's edge increments, in exact integers.

    :func:`renderer.raster.scanline_span` bounds a row's columns by one quotient per edge, ``num / den``
    with ``num`` linear in the row's height. Walking, the quotient is divided once here,
    as ``q·den + r`` (0 ≤ r < den), and then moved by a fixed step ``dq·den + dr`` per row
    (:func:`edge_step`): the x of the edge advances by Δx/Δy a row as in the course's
    algorithm, the fraction kept as a remainder, so every row gets the same column as
    :func:`renderer.raster.scanline_span` (Bresenham's way: no division, no rounding error).
    Returns ``(kind, q, r, den, dq, dr)``, ``kind`` :data:`LEFT` or :data:`RIGHT`
    (:func:`column_bound` reads the column from it)."""
    xa, ya = f[e, 0], f[e, 1]
    xb, yb = f[(e + 1) % 3, 0], f[(e + 1) % 3, 1]
    dx, dy = xb - xa, yb - ya
    y = row * SUBPIXEL
    if dy < 0:  # left edge: X ≥ (|dy|·xa − dx·(Y − ya)) / |dy|
        kind, num, den, step = LEFT, -dy * xa - dx * (y - ya), -dy * SUBPIXEL, -dx * SUBPIXEL * stride
    else:  # right edge: X < (dy·xa + dx·(Y − ya)) / dy
        kind, num, den, step = RIGHT, dy * xa + dx * (y - ya), dy * SUBPIXEL, dx * SUBPIXEL * stride
    if top_left:  # the bound is a ceiling: ⌈n / d⌉ = −⌊−n / d⌋, so walk −n
        num, step = -num, -step
    q, dq = num // den, step // den
    return kind, q, num - q * den, den, dq, step - dq * den


@njit(cache=True, inline="always")
def edge_step(q, r, den, dq, dr):
    """One step of an edge walk (:func:`edge_walk`): ``q·den + r`` plus ``dq·den + dr``, the
    remainder carried into the quotient when it reaches ``den``."""
    q, r = q + dq, r + dr
    if r >= den:
        q, r = q + 1, r - den
    return q, r


@njit(cache=True, inline="always")
def walk_on(w):
    """An edge walk (:func:`edge_walk`) one step on."""
    q, r = edge_step(w[1], w[2], w[3], w[4], w[5])
    return w[0], q, r, w[3], w[4], w[5]


@njit(cache=True, inline="always")
def column_bound(w, top_left):
    """The column a walked edge (:func:`edge_walk`) bounds its row by, as
    :func:`renderer.raster.scanline_span` has it: a left edge's first column inside, a right
    edge's first column past the span (its last column + 1)."""
    return -w[1] if top_left else w[1] + 1


@njit(cache=True, inline="always")
def split_at_middle(f, lo, hi, top_left):
    """The course's split of a counter-clockwise fixed-point triangle ``f`` (3, 2) at its middle
    corner (by height), for walking rows ``lo … hi`` of it: on every row one edge bounds the
    span on the left and one on the right, so two edges are walked instead of three.

    The *long* edge joins the lowest and the highest corner and bounds every row on one
    side; on the other, the *low* edge (lowest → middle corner) bounds the rows below the
    middle corner and the *high* edge (middle → highest) the rows from it up. The third
    edge's bound never narrows a row it does not cross (the triangle is convex: it lies on
    the inner side of that edge's line), so the span is :func:`renderer.raster.scanline_span`'s, to the column.

    Returns ``(long, low, high, split, lo, hi)``: the three edges' numbers (edge e runs from
    corner e to e + 1), ``split`` the first row walked with the high edge, and ``lo … hi``
    narrowed by a horizontal edge's rule (the row exactly on a horizontal edge belongs to the
    triangle only if the edge is a bottom one, top-left rule; a top one, bottom-right rule).
    A horizontal edge is never walked: it is the low edge of a flat-bottomed triangle, whose
    rows all lie at or above the middle corner, or the high edge of a flat-topped one, whose
    rows are then all walked with the low edge."""
    y0, y1, y2 = f[0, 1], f[1, 1], f[2, 1]
    low = 0 if y0 <= y1 and y0 <= y2 else (1 if y1 <= y2 else 2)
    high = (low + 1) % 3 if f[(low + 1) % 3, 1] >= f[(low + 2) % 3, 1] else (low + 2) % 3
    mid = 3 - low - high
    y_low, y_mid, y_high = f[low, 1], f[mid, 1], f[high, 1]
    long_edge = low if (low + 1) % 3 == high else high
    low_edge = low if (low + 1) % 3 == mid else mid
    high_edge = mid if (mid + 1) % 3 == high else high
    if y_mid == y_high:  # flat top: the low edge bounds every row
        split = hi + 1
        if top_left and y_high % SUBPIXEL == 0:  # a top edge does not own the row on it
            hi = smaller(hi, y_high // SUBPIXEL - 1)
    else:
        split = -((-y_mid) // SUBPIXEL)  # the first row at or above the middle corner
    if y_mid == y_low and not top_left and y_low % SUBPIXEL == 0:  # bottom-right: a bottom edge does not own its row
        lo = larger(lo, y_low // SUBPIXEL + 1)
    return long_edge, low_edge, high_edge, split, lo, hi


@njit(cache=True, inline="always")
def walked_columns(long_walk, short_walk, top_left, width):
    """Columns [first, last] of a row from the walks (:func:`edge_walk`) of its two bounding
    edges (:func:`split_at_middle`), clamped to the image (first > last: none)."""
    long_bound, short_bound = column_bound(long_walk, top_left), column_bound(short_walk, top_left)
    if long_walk[0] == LEFT:
        return larger(long_bound, 0), smaller(short_bound - 1, width - 1)
    return larger(short_bound, 0), smaller(long_bound - 1, width - 1)


@njit(cache=True, inline="always")
def fill_walked(lo, hi, long_walk, short_walk, plane, kk, top_left, depth_test, depth, tri_index):
    """Fill rows ``lo … hi`` of the triangle numbered ``kk`` in the visibility buffer, whose
    set-up row is ``plane`` (11,) (:class:`renderer.raster.TriangleSetup`), each row's span
    between its two walked edges at row ``lo`` (:func:`walked_columns`), then both edges a
    row on; returns the long edge's walk at row ``hi + 1``. The depth plane is read once for
    the stretch; each row's constant part is :func:`renderer.raster.row_depth`'s expression
    on those values."""
    width = depth.shape[1]
    ax, ay, az, zx, zy = plane[6], plane[7], plane[8], plane[9], plane[10]
    for row in range(lo, hi + 1):
        first, last = walked_columns(long_walk, short_walk, top_left, width)
        fill_columns(row, first, last, az + zy * (row + 0.5 - ay), zx, ax, kk, depth_test, depth, tri_index)
        long_walk, short_walk = walk_on(long_walk), walk_on(short_walk)
    return long_walk
