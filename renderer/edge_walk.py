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
from renderer.window import SUBPIXEL

LEFT, RIGHT, HORIZONTAL = 0, 1, 2
"""What an edge of a counter-clockwise triangle bounds on a scanline (:func:`renderer.raster.scanline_span`)."""

NO_STEP = 1 << 62
"""The divisor a horizontal edge's walk carries: its remainder never reaches it, so the walk
never moves (:func:`edge_walk`)."""


@njit(cache=True, inline="always")
def edge_walk(f, e, row, stride, top_left):
    """Edge ``e`` (corner e → e + 1) of a counter-clockwise fixed-point triangle ``f`` (3,
    2) set up to be walked from pixel row ``row`` up, ``stride`` rows a step: the scanline
    algorithm's edge increments, in exact integers.

    :func:`renderer.raster.scanline_span` bounds a row's columns by one quotient per edge, ``num / den``
    with ``num`` linear in the row's height. Walking, the quotient is divided once here,
    as ``q·den + r`` (0 ≤ r < den), and then moved by a fixed step ``dq·den + dr`` per row
    (:func:`edge_step`): the x of the edge advances by Δx/Δy a row as in the course's
    algorithm, the fraction kept as a remainder, so every row gets the same column as
    :func:`renderer.raster.scanline_span` (Bresenham's way: no division, no rounding error).
    Returns ``(kind, q, r, den, dq, dr)``: ``kind`` :data:`LEFT`, :data:`RIGHT` or
    :data:`HORIZONTAL` (then ``q, r`` are the edge's dx and its corner's y, for
    :func:`walk_span`'s test, and the walk never moves)."""
    xa, ya = f[e, 0], f[e, 1]
    xb, yb = f[(e + 1) % 3, 0], f[(e + 1) % 3, 1]
    dx, dy = xb - xa, yb - ya
    if dy == 0:
        return HORIZONTAL, dx, ya, NO_STEP, 0, 0
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
def edge_bound(kind, q, r, row, top_left, first, last):
    """The row's span ``[first, last]`` narrowed by one walked edge (:func:`edge_walk`), as
    :func:`renderer.raster.scanline_span` narrows it; a horizontal edge that keeps nothing empties it."""
    if kind == LEFT:
        return max(first, -q if top_left else q + 1), last
    if kind == RIGHT:
        return first, min(last, -q - 1 if top_left else q)
    e_val = q * (row * SUBPIXEL - r)  # the horizontal edge's function: dx·(Y − ya)
    owned = q > 0 if top_left else q < 0
    if e_val < 0 or (e_val == 0 and not owned):
        return 1, 0
    return first, last


@njit(cache=True, inline="always")
def walk_on(w):
    """An edge walk (:func:`edge_walk`) one step on."""
    q, r = edge_step(w[1], w[2], w[3], w[4], w[5])
    return w[0], q, r, w[3], w[4], w[5]


@njit(cache=True, inline="always")
def walk_span(walks, row, top_left, width):
    """Columns [first, last] on ``row`` of a triangle whose three edges are walked
    (``walks``: their :func:`edge_walk` tuples, at this row), clamped to the image; the
    same as :func:`renderer.raster.row_span`."""
    first, last = -(1 << 62), 1 << 62
    for w in walks:
        first, last = edge_bound(w[0], w[1], w[2], row, top_left, first, last)
    return max(first, 0), min(last, width - 1)
