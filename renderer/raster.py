"""Stage 6, window space → fragments: scanline fill, the top-left rule and the z-buffer.

Input: triangles in window space (y up), x and y also snapped to the 1/256-pixel grid
(:func:`renderer.window.snap_to_subpixel`: pixel centre (i, j) at fixed (256·i, 256·j)).
Output: a visibility buffer — for each pixel the depth, the index of the nearest triangle
and its screen-space barycentric weights — which :mod:`renderer.shading` lights.

Rules, each in one place:

- **Front face** (:func:`renderer.window.signed_area_fixed`): counter-clockwise in window coordinates
  (y up), OpenGL's default. Nothing is culled; back faces are drawn and lit two-sided.
- **Scanline fill** (:func:`scanline_span`): for each pixel row, the span of pixel
  centres between the triangle's edges at the row's centre height. Coverage is decided
  exactly, in integers, on the snapped vertices.
- **Edge walk** (:mod:`renderer.edge_walk`): for tall triangles the raster finds the spans row after
  row by stepping each edge's x by Δx/Δy, the fraction kept as an integer remainder: the
  columns of :func:`scanline_span` without a division per row (:func:`fill_rows`).
- **Narrow triangles** (:mod:`renderer.edge_functions`): a triangle at most eight columns
  wide is drawn by its three edge functions, a row's eight columns at a time in vector
  lanes: the same pixels as :func:`scanline_span`, the same tie rule, no division.
- **Top-left rule** (:func:`scanline_span`): a pixel centre lying exactly on an edge
  belongs to the triangle when the edge is a *left* edge or a *bottom* edge in window
  coordinates (y up) — a top-left rule in image coordinates (y down). So two triangles
  sharing an edge never both draw, and never both miss, a pixel on it.
- **Depth** (:func:`rasterize`): window z interpolated linearly in screen space (it is
  affine there), rounded to the 24-bit depth buffer, test LEQUAL (a later triangle at
  equal depth wins: :func:`renderer.visibility_buffer.nearer_or_later`), cleared to 1.0.
  The depth plane is set up from the corners in a canonical order (:func:`depth_plane`),
  so coincident triangles get bit-identical depths whatever order they list their corners
  in, and the tie goes to the later one everywhere.

- **Back faces last** (:mod:`renderer.hidden_back_faces`, :mod:`renderer.band_draw`): with
  the z-buffer on, a band draws a batch's front faces, then its back faces, skipping those
  a tile z-buffer shows hidden; the depth test's tie rule gives the pixels drawing in order gives.

Determinism: every pixel sees the triangles in the order given (objects in scene order,
triangles in mesh order), as OpenGL guarantees, so ties resolve the same way every run.
Parallelism deals the image's rows out to bands (:mod:`renderer.bands`), never splits the
triangle order (see :func:`rasterize`), and gives the same bytes as one thread.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from renderer.jit import njit, prange
from renderer.min_max import clamp, larger, smaller

from renderer.clip import CornerIndex, corner_row
from renderer.bands import BLOCK_ROWS, one_band_at_a_time, raster_bands
from renderer.visibility_buffer import (DEPTH_CLEAR, DEPTH_MAX, EMPTY, Visibility, clear_band, clear_visibility,
                                        depth_bits, depth_to_window, fill_columns, finish_band)
from renderer.band_draw import draw_band_from_lists, draw_band_in_order, draw_band_listed
from renderer.draw_lists import LIST_CHUNK, list_by_facing, list_on_bands
from renderer.edge_functions import fill_narrow_rows, lanes_start
from renderer.edge_walk import edge_walk, fill_walked, split_at_middle
from renderer.fill_rules import FILL_RULES, TOP_LEFT
from renderer.hidden_back_faces import BACKS_LAST_ROWS, NO_TILES, new_tiles
from renderer.pixel_centres import LONE_ROWS, box_misses_centres, ceil_div, centre_rows
from renderer.window import NO_CELLS, SUBPIXEL, WindowVertices, signed_area_corners, window_edges
from renderer.workspace import empty
from renderer.indexed_triangles import IndexedTriangles, whole_triangles


class TriangleSetup(NamedTuple):
    """Per-triangle set-up, done once (:func:`setup_triangles`).

    front (K,) bool, counter-clockwise on screen (False for a triangle dropped by its
    corners' centre cells, :data:`DROP_EMPTY_BOXES`, whose area is not worked out); ccw
    (K, 3, 2) the fixed-point vertices ordered counter-clockwise (for the span test); rows
    (K, 2) first and last window row of pixel centres it may cover (none when first >
    last); plane (K, 11): x0, y0, e1x, e1y, e2x, e2y — vertex 0 and the edges to vertices 1
    and 2 in float window coordinates, in the triangle's own vertex order (for the weights)
    — unwritten with :data:`DROP_WEIGHTS` — then the depth plane ax, ay, az, zx, zy (:func:`depth_plane`). A triangle that draws
    nothing (no area, culled, or no pixel centre it can cover: :mod:`renderer.pixel_centres`)
    gets no rows, ``ccw`` or depth plane (nor weights, when its centre cells dropped it).
    listed (K,) int32, counts (⌈K / LIST_CHUNK⌉, 2) int64: for back faces drawn last, the
    triangles that draw by facing (:func:`renderer.draw_lists.list_by_facing`). band_listed (B,
    K) int32: for each of the B bands the batch is drawn in, the triangles with rows in its
    blocks (:func:`renderer.draw_lists.list_on_bands`); tallies (C, 1 + B) int64, for each
    chunk of :data:`SETUP_CHUNK` triangles the rows they span together (column 0,
    ``row_sums``, for :func:`mean_rows`) and how many each band lists (column 1 + b).
    """

    front: np.ndarray
    ccw: np.ndarray
    rows: np.ndarray
    plane: np.ndarray
    listed: np.ndarray
    counts: np.ndarray
    band_listed: np.ndarray
    tallies: np.ndarray

    @property
    def row_sums(self) -> np.ndarray:
        """Each chunk's rows, ``tallies[:, 0]`` (a view)."""
        return self.tallies[:, 0]


@njit(cache=True, inline="always")
def scanline_span(f, row, rule=TOP_LEFT):
    """Columns [first, last] of the pixel centres inside a CCW fixed-point triangle on ``row``.

    The edge function of an edge a→b, ``E(P) = dx·(Y − ya) − dy·(X − xa)``, is positive
    left of the edge, inside a counter-clockwise triangle. On a scanline each edge bounds
    X on one side: a left edge (dy < 0) from below, a right edge (dy > 0) from above; a
    horizontal edge keeps or drops the whole row. A centre with E = 0 counts only for a
    left edge (dy < 0) or a bottom edge (dy = 0, dx > 0) — the top-left rule.
    ``rule = BOTTOM_RIGHT`` hands the tie to the opposite edges (right and top), the
    deliberately wrong rule of the parity tests. Returns first > last when the row is empty.
    """
    y = row * SUBPIXEL
    first = -(1 << 62)
    last = 1 << 62
    for e in range(3):
        xa, ya = f[e, 0], f[e, 1]
        xb, yb = f[(e + 1) % 3, 0], f[(e + 1) % 3, 1]
        dx, dy = xb - xa, yb - ya
        if dy < 0:  # left edge: E ≥ 0  ⇔  X ≥ (|dy|·xa − dx·(Y − ya)) / |dy|
            num, den = -dy * xa - dx * (y - ya), -dy * SUBPIXEL
            first = larger(first, ceil_div(num, den) if rule == TOP_LEFT else num // den + 1)
        elif dy > 0:  # right edge: E > 0  ⇔  X < (dy·xa + dx·(Y − ya)) / dy
            num, den = dy * xa + dx * (y - ya), dy * SUBPIXEL
            last = smaller(last, ceil_div(num, den) - 1 if rule == TOP_LEFT else num // den)
        else:  # horizontal: bottom edge (dx > 0) owns its centres, top edge does not
            e_val = dx * (y - ya)
            owned = dx > 0 if rule == TOP_LEFT else dx < 0
            if e_val < 0 or (e_val == 0 and not owned):
                return 1, 0
    return first, last


@njit(cache=True, inline="always")
def depth_plane(t, i0, i1, i2, out):
    """The window depth of the triangle with corners ``t[i0]``, ``t[i1]``, ``t[i2]`` (rows of
    a window-space table (M, 3)) as a plane ``z = az + zx·(x − ax) + zy·(y − ay)``: writes
    ``out`` = (ax, ay, az, zx, zy).

    The corners are first sorted (by x, then y, then z), so the same three corners give
    the same bits in any order: coincident triangles tie exactly in the z-buffer. Where
    the triangle has no area, zx = zy = 0 (it draws nothing anyway).
    """
    a, b, c = i0, i1, i2
    if (t[b, 0], t[b, 1], t[b, 2]) < (t[a, 0], t[a, 1], t[a, 2]):
        a, b = b, a
    if (t[c, 0], t[c, 1], t[c, 2]) < (t[b, 0], t[b, 1], t[b, 2]):
        b, c = c, b
    if (t[b, 0], t[b, 1], t[b, 2]) < (t[a, 0], t[a, 1], t[a, 2]):
        a, b = b, a
    e1x, e1y, dz1 = t[b, 0] - t[a, 0], t[b, 1] - t[a, 1], t[b, 2] - t[a, 2]
    e2x, e2y, dz2 = t[c, 0] - t[a, 0], t[c, 1] - t[a, 1], t[c, 2] - t[a, 2]
    a2 = e1x * e2y - e2x * e1y
    out[0], out[1], out[2] = t[a, 0], t[a, 1], t[a, 2]
    out[3] = (dz1 * e2y - dz2 * e1y) / a2 if a2 != 0.0 else 0.0
    out[4] = (dz2 * e1x - dz1 * e2x) / a2 if a2 != 0.0 else 0.0


@njit(cache=True, inline="always")
def weights_plane(window, i0, i1, i2, plane):
    """The plane of a triangle's screen-space weights into ``plane`` (≥ 6,): its
    :func:`renderer.window.window_edges`, the corners rows ``i0, i1, i2`` of the window table (M, 3)."""
    plane[0], plane[1], plane[2], plane[3], plane[4], plane[5] = window_edges(window, i0, i1, i2)


SETUP_CHUNK = np.uint64(LIST_CHUNK)
"""Triangles a parallel iteration of :func:`setup_triangles` sets up (:func:`set_up_range`): a
chunk of the bands' lists, which it writes (:mod:`renderer.draw_lists`)."""


DROP_BACK_FACES, DROP_MISSED_CENTRES, DROP_EMPTY_BOXES, DROP_WEIGHTS = 1, 2, 4, 8
"""Bits of the set-up's ``drops`` (:func:`setup_triangles`): back-face culling (a clockwise
triangle gets no rows); the test of a box's lone pixel centre (:func:`renderer.pixel_centres.centre_rows`);
first of all, a box without pixel centres told by the corners' centre cells
(:func:`renderer.pixel_centres.box_misses_centres`, set when the vertices come with them):
no rows, and no area, facing (False) or weights' plane worked out (docs/performance.md);
and the weights' plane (the first six columns of ``plane``) left unwritten for every
triangle: the opaque raster reads the depth plane alone, and shading works out the weights
of the triangles that won a pixel (:func:`weight_planes`)."""


@njit(cache=True, parallel=True)
def setup_triangles(corners, vertices, height, drops, front, ccw, rows, plane, band_listed, tallies):
    """Per-triangle set-up, once: facing, counter-clockwise fixed vertices, rows, planes, into
    ``front``, ``ccw``, ``rows`` and ``plane``, the triangles with rows into each band's list
    ``band_listed``, and each chunk's rows and counts into ``tallies`` (see :class:`TriangleSetup`). The triangles' corners are rows (``corners``, a
    :class:`~renderer.clip.CornerIndex`) of the vertex tables ``vertices``
    (:class:`renderer.window.WindowVertices`). ``drops`` (bits): with :data:`DROP_EMPTY_BOXES`
    a triangle whose corners' centre cells show a box without pixel centres gets no rows
    before anything else is worked out; with :data:`DROP_BACK_FACES` a back-facing
    (clockwise) triangle gets no rows, back-face culling; with :data:`DROP_MISSED_CENTRES`
    neither does one whose box's lone pixel centre lies outside it (:func:`renderer.pixel_centres.centre_rows`).
    :data:`SETUP_CHUNK` triangles to a parallel iteration, each chunk one
    call of :func:`set_up_range`: numba's parallel passes then type a one-line loop body
    again, not the whole set-up (a cold start's compile 0.25 s less, the same frames)."""
    for chunk in prange((np.uint64(corners.source.shape[0]) + SETUP_CHUNK - 1) // SETUP_CHUNK):
        tallies[chunk, 0] = set_up_range(np.uint64(chunk), corners, vertices, height, drops, front, ccw, rows, plane,
                                         (band_listed, tallies[chunk]))


@njit(cache=True, from_python=False, refcounts=False)
def set_up_range(chunk, corners, vertices, height, drops, front, ccw, rows, plane, lists):
    """:func:`setup_triangles` for chunk ``chunk`` (uint64; the same type in the loop numba
    types twice, so one compile): triangles ``chunk · SETUP_CHUNK`` … up to ``SETUP_CHUNK``
    more, counted as uint64, as the parallel loop's own index is (a signed index costs every
    array read a test for a negative value: measured 4 % slower). Returns the rows they span.
    ``lists`` = (``band_listed``, the chunk's row of ``tallies``): each triangle with rows is
    listed for the bands of its blocks (:func:`renderer.draw_lists.list_on_bands`).
    A triangle that draws nothing (no area, culled, no pixel centre) gets no rows, and
    neither its depth plane nor its counter-clockwise corners.

    Without reference counts (``refcounts=False``; it makes no array): each triangle's row of
    ``plane`` is a view, which would be counted with an atomic increment and decrement a
    triangle. Whole frames with and without, across processes, differ within the noise
    (igea-1m 512² 0.98, igea-270k 1024² 1.00, ico7-phong 512² 1.00, docs/performance.md)."""
    first = chunk * SETUP_CHUNK
    spanned = 0
    fixed, window, cells = vertices
    band_listed, tally = lists
    per_band = 1.0 / band_listed.shape[0]  # for list_on_bands
    for b in range(1, tally.shape[0]):
        tally[b] = 0
    for k in range(first, smaller(first + SETUP_CHUNK, np.uint64(corners.source.shape[0]))):
        i0, i1, i2 = corner_row(corners, k, 0), corner_row(corners, k, 1), corner_row(corners, k, 2)
        if drops & DROP_EMPTY_BOXES and box_misses_centres(cells[i0], cells[i1], cells[i2]):
            rows[k, 0], rows[k, 1], front[k] = 1, 0, False
            continue
        area = signed_area_corners(fixed, i0, i1, i2)
        front[k] = area > 0
        x0, y0, e1x, e1y, e2x, e2y = window_edges(window, i0, i1, i2)
        if not drops & DROP_WEIGHTS:
            plane[k, 0], plane[k, 1], plane[k, 2], plane[k, 3], plane[k, 4], plane[k, 5] = x0, y0, e1x, e1y, e2x, e2y
        lo, hi = 1, 0  # no rows: nothing to draw
        if area != 0 and e1x * e2y - e2x * e1y != 0.0 and not (
                drops & DROP_BACK_FACES and area < 0):
            lo, hi = centre_rows(fixed, i0, i1, i2, area, height, drops & DROP_MISSED_CENTRES)
        rows[k, 0], rows[k, 1] = lo, hi
        if lo <= hi:  # a row of pixel centres: the depth plane and the corners for the spans
            depth_plane(window, i0, i1, i2, plane[k, 6:])
            if area < 0:  # orient counter-clockwise for the span test; weights keep source order
                i1, i2 = i2, i1
            for c in range(2):
                ccw[k, 0, c], ccw[k, 1, c], ccw[k, 2, c] = fixed[i0, c], fixed[i1, c], fixed[i2, c]
            list_on_bands(k, lo, hi, np.int64(first), tally, band_listed, BLOCK_ROWS, per_band)
        spanned += larger(hi - lo + 1, 0)
    return spanned


@njit(cache=True, parallel=True)
def weight_planes(corners, fixed, window, front, plane):
    """The part of :func:`setup_triangles` that shading reads, for the triangles that won a
    pixel: facing into ``front`` (K,) and the weights' plane — corner 0 and the edges to
    corners 1 and 2, the first six columns of :class:`TriangleSetup`'s ``plane`` — into
    ``plane`` (K, ≥ 6), the same bits (no depth plane, spans or rows: the raster is done)."""
    for k in prange(corners.source.shape[0]):
        i0, i1, i2 = corner_row(corners, k, 0), corner_row(corners, k, 1), corner_row(corners, k, 2)
        front[k] = signed_area_corners(fixed, i0, i1, i2) > 0
        weights_plane(window, i0, i1, i2, plane[k])


@njit(cache=True, inline="always")
def row_span(k, row, ccw, width, rule):
    """Columns [first, last] of triangle ``k`` on ``row``, clamped to the image (first > last: none)."""
    first, last = scanline_span(ccw[k], row, rule)
    return larger(first, 0), smaller(last, width - 1)


@njit(cache=True, inline="always")
def screen_weights(k, row, col, plane):
    """Triangle ``k``'s screen-space weights ``l1, l2`` of its vertices 1 and 2 at the centre
    of pixel (row, col), from its set-up ``plane`` (:class:`TriangleSetup`)."""
    x0, y0, e1x, e1y, e2x, e2y = plane[k, 0], plane[k, 1], plane[k, 2], plane[k, 3], plane[k, 4], plane[k, 5]
    a2 = e1x * e2y - e2x * e1y
    py = row + 0.5 - y0
    px = col + 0.5 - x0
    return (px * e2y - e2x * py) / a2, (e1x * py - px * e1y) / a2


@njit(cache=True, inline="always")
def row_depth(k, row, plane):
    """The part of triangle ``k``'s depth plane that is constant along pixel row ``row``:
    ``az + zy·(row + 0.5 − ay)`` (see :func:`pixel_depth`)."""
    return plane[k, 8] + plane[k, 10] * (row + 0.5 - plane[k, 7])


@njit(cache=True, inline="always")
def pixel_depth(k, z_row, col, plane):
    """Triangle ``k``'s window depth at the centre of pixel column ``col`` of a row whose
    constant part is ``z_row`` (:func:`row_depth`), on the 24-bit grid (:func:`depth_bits`)."""
    return depth_bits(z_row + plane[k, 9] * (col + 0.5 - plane[k, 6]))


@njit(cache=True, inline="always")
def pixel_fragment(k, row, col, plane):
    """Triangle ``k`` at the centre of pixel (row, col): screen-space weights l1, l2 of its
    vertices 1 and 2, and the 24-bit integer depth (:func:`pixel_depth`)."""
    l1, l2 = screen_weights(k, row, col, plane)
    return l1, l2, pixel_depth(k, row_depth(k, row, plane), col, plane)


WALK_ROWS = 4
"""The fewest rows of a stretch whose spans :func:`fill_rows` finds by walking the edges: setting
up a walk costs more than it saves on fewer. Measured, one thread, the raster alone, with the
two-edge walk: 4 against 3 rows, the 270k-triangle Igea scan at 1024² 31.5 → 30.6 ms, a
level-4 Menger sponge at 512² 86.8 → 83.7; 2 rows was slower than 3 on both."""

WALK_BLOCK_ROWS = 64
"""Rows in a block of :func:`rasterize_walking`'s bands (:data:`renderer.bands.BLOCK_ROWS`, 16,
for :func:`rasterize`). Each block a triangle crosses starts its walk afresh (its corner
split, two divisions an edge), so tall triangles want tall blocks; small ones want short
blocks, which leave most of them in one band. Measured, two threads, the raster alone, 16 →
64 rows: the 1,024-segment cylinder at 512² 2.8–3.9 → 2.2 ms, ico5 at 1024² 4.9–5.0 → 4.4;
128 rows was no better."""

NARROW_ROWS = 16
"""The most rows of a stretch for which the walking kernel draws a triangle at most eight columns
wide by its edge functions (:mod:`renderer.edge_functions`) rather than walking its edges.
Measured, one thread, whole frames at 1024²: a level-4 Menger sponge 146 → 108 ms, ico7
phong 107 → 95; with no limit, the slivers of the 1,024-segment cylinder (hundreds of
rows, a pixel wide, where a walked row is one pixel) 3.9 → 4.2 ms at two threads."""

TALL_ROWS = 4
"""The rows a batch's triangles must span on average for :func:`rasterize_walking` to draw
it (:func:`mean_rows`); below it, :func:`rasterize`, one division per edge and row. The walk's
kernel holds the dividing loop too (for short stretches), and is the slower of the two
where nearly every stretch is that short. Measured, one thread, the raster alone, dividing
→ walking kernel: ico5 at 512² (9.5 rows a triangle) 5.57 → 4.86 ms, a level-3 Menger
sponge at 512² (9–11) 12.7 → 10.6, a level-4 one at 1024² (5–6) 151 → 146, ico7 at 1024²
(4.9) 52.9 → 51.4; but ico7 at 512² (2.5) 29.1 → 30.7 and a level-4 sponge at 512² (2.9)
79.2 → 86.8."""


@njit(cache=True, inline="always")
def fill_rows(k, lo, hi, setup, rule, depth_test, first_index, depth, tri_index):
    """Fill rows ``lo … hi`` of triangle ``k`` (numbered ``first_index + k`` in the
    visibility buffer) by walking its edges: split at its middle corner
    (:func:`renderer.edge_walk.split_at_middle`), each row's span bounded by the long edge and
    the low or the high one, both stepped row by row (:func:`renderer.edge_walk.fill_walked`;
    two divisions an edge for the whole stretch). A stretch of fewer than :data:`WALK_ROWS` rows, and one
    of at most :data:`NARROW_ROWS` of a triangle at most eight columns wide, goes to
    :func:`fill_rows_dividing` instead (the narrow one by its edge functions)."""
    if hi - lo < WALK_ROWS - 1 or (hi - lo + 1 <= NARROW_ROWS and lanes_start(setup.ccw[k], depth.shape[1])[0] >= 0):
        fill_rows_dividing(k, lo, hi, setup, rule, depth_test, first_index, depth, tri_index)
        return
    f, top_left = setup.ccw[k], rule == TOP_LEFT
    long_edge, low_edge, high_edge, split, lo, hi = split_at_middle(f, lo, hi, top_left)
    long_walk = edge_walk(f, long_edge, lo, 1, top_left)
    if lo < split:
        long_walk = fill_walked(lo, smaller(hi, split - 1), long_walk, edge_walk(f, low_edge, lo, 1, top_left),
                                setup.plane[k], np.int32(first_index + k), top_left, depth_test, depth, tri_index)
    top = larger(lo, split)
    if top <= hi:
        fill_walked(top, hi, long_walk, edge_walk(f, high_edge, top, 1, top_left),
                    setup.plane[k], np.int32(first_index + k), top_left, depth_test, depth, tri_index)


@njit(cache=True, inline="always")
def fill_rows_dividing(k, lo, hi, setup, rule, depth_test, first_index, depth, tri_index):
    """Fill rows ``lo … hi`` of triangle ``k``: a triangle at most eight columns wide by its
    edge functions in one group of vector lanes (:func:`renderer.edge_functions.fill_narrow_rows`),
    a wider one each row's span by one division per edge (:func:`fill_row`)."""
    columns = lanes_start(setup.ccw[k], depth.shape[1])
    if columns[0] >= 0:
        fill_narrow_rows(setup.ccw[k], columns, lo, hi, setup.plane[k], np.int32(first_index + k), rule == TOP_LEFT,
                         depth_test, depth, tri_index)
        return
    for row in range(lo, hi + 1):
        fill_row(k, row, setup, rule, depth_test, first_index, depth, tri_index)


@njit(cache=True, inline="always")
def fill_row(k, row, setup, rule, depth_test, first_index, depth, tri_index):
    """Fill one scanline of triangle ``k``: its span (:func:`row_span`), then :func:`fill_span`."""
    first, last = row_span(k, row, setup.ccw, depth.shape[1], rule)
    fill_span(k, row, first, last, setup, depth_test, first_index, depth, tri_index)


@njit(cache=True, inline="always")
def fill_span(k, row, first, last, setup, depth_test, first_index, depth, tri_index):
    """Fill columns ``first … last`` of one scanline of triangle ``k`` (numbered
    ``first_index + k`` in the visibility buffer): :func:`fill_columns` with the triangle's
    depth along the row (:func:`row_depth`, and the plane's slope in x)."""
    fill_columns(row, first, last, row_depth(k, row, setup.plane), setup.plane[k, 9], setup.plane[k, 6],
                 np.int32(first_index + k), depth_test, depth, tri_index)


@njit(cache=True, from_python=False, refcounts=False)
def band_dividing(b, setup, n_bands, rule, depth_test, first_index, ends, depth, tri_index, tiles):
    """Band ``b``'s whole share of :func:`rasterize`: its rows cleared for the first batch
    (``ends`` has :data:`FIRST_BATCH`, :func:`clear_band`), then every triangle drawn on them
    with :func:`fill_rows_dividing`, in blocks of :data:`renderer.bands.BLOCK_ROWS` rows: in
    draw order when ``tiles`` is None, else back faces last behind the tile z-buffer
    ``tiles``. Numba compiles the kernel apart for each, with one of the two loops
    (:mod:`renderer.band_draw`: why the choice is made here, not in an inlined function).

    A kernel of its own, called from the parallel loop rather than inlined into it: numba's
    parallel passes then analyse a one-line loop body, not the whole fill (measured, a cold
    start's compile: :func:`rasterize` 3.3 s → 1.0 s, plus 1.4 s for this). ``b`` comes as
    int64: the parallel loop's own index is uint64, and a second argument type would compile
    this a second time. Without reference counts (``refcounts=False``): each triangle's rows
    of the set-up are views, and counting them cost the kernel 5 % against the inlined loop
    (menger3, 512², one thread, 12.8–13.3 → 13.8–14.0 ms; without the counts 12.7–13.0)."""
    if ends & FIRST_BATCH:
        clear_band(b, n_bands, BLOCK_ROWS, depth, tri_index)
    deal, rules, buffer = (n_bands, BLOCK_ROWS), (rule, depth_test, first_index), (depth, tri_index)
    if tiles is None:  # known from the type of ``tiles`` as numba compiles: one branch is compiled
        draw_band_from_lists(b, setup, deal, rules, buffer, fill_rows_dividing, ends & FINE_BATCH != 0)
    else:
        draw_band_listed(b, setup, deal, rules, buffer, fill_rows_dividing, tiles)


@njit(cache=True, from_python=False, refcounts=False)
def band_walking(b, setup, n_bands, rule, depth_test, first_index, ends, depth, tri_index, tiles):
    """:func:`band_dividing` for :func:`rasterize_walking`: blocks of :data:`WALK_BLOCK_ROWS`
    rows, the spans found by walking the edges (:func:`fill_rows`)."""
    if ends & FIRST_BATCH:
        clear_band(b, n_bands, WALK_BLOCK_ROWS, depth, tri_index)
    deal, rules, buffer = (n_bands, WALK_BLOCK_ROWS), (rule, depth_test, first_index), (depth, tri_index)
    if tiles is None:  # as in :func:`band_dividing`
        draw_band_in_order(b, setup, deal, rules, buffer, fill_rows)
    else:
        draw_band_listed(b, setup, deal, rules, buffer, fill_rows, tiles)


FIRST_BATCH, LAST_BATCH, FINE_BATCH = 1, 2, 4
"""Bits of :func:`rasterize`'s ``ends``: the batch of triangles is the first (each band clears
its rows before drawing, :func:`clear_band`), the last (each band then writes its rows'
window depth and coverage, :func:`finish_band`), or both; and, apart from where the batch
lies, it is finer than the pixels (:data:`renderer.pixel_centres.LONE_ROWS`): a triangle
whose box holds one pixel centre is tested at that centre alone (:mod:`renderer.one_pixel`,
in draw order only; the walking kernel's batches are never fine)."""


@njit(cache=True, parallel=True)
def rasterize(setup, rule, depth_test, first_index, ends, depth, tri_index, covered, tiles):
    """Scan-convert every triangle of ``setup`` into the visibility buffer (the loop kernel).

    The image's rows are dealt out to the bands the set-up listed the triangles for (as many
    as ``setup.band_listed`` has rows, :func:`set_up_corners`) in blocks of
    :data:`renderer.bands.BLOCK_ROWS` rows (:mod:`renderer.bands`), filled in parallel; each
    band draws the triangles with rows in its blocks (its list) in order, on its own rows only (after clearing them, for the
    first batch: ``ends`` has :data:`FIRST_BATCH`). A pixel belongs to one band and sees the
    triangles in draw order, so the result is the same, bit for bit, as a serial loop
    (z-buffer ties included), also with a tile z-buffer ``tiles``: back faces last
    (:mod:`renderer.band_draw`). After the last batch (:data:`LAST_BATCH`) each band writes its rows'
    coverage into ``covered`` (H, W) bool (:func:`renderer.visibility_buffer.finish_band`).
    ``depth_test`` False draws every fragment over what is there (the painter's algorithm, or no hidden-surface removal
    at all): then the last triangle drawn wins.
    ``first_index`` is the number of the setup's first triangle in ``tri_index`` (the
    triangles arrive in batches, :func:`rasterize_visibility`). Each band's work is
    :func:`band_dividing`; :func:`rasterize_walking` is the same loop finding the spans by
    walking the edges (:func:`band_walking`).
    depth (H, W) int32, the 24-bit depth (:data:`DEPTH_CLEAR` where empty), tri_index (H, W)
    int32 (:data:`EMPTY` where none): outputs, in window rows (y up). The weights are not
    stored: shading works them out (:func:`screen_weights`) for the one visible fragment
    of each pixel. The outputs are plain arrays: numba loses writes made through a
    NamedTuple's fields inside ``prange`` (numba issues #5872, #7135); ``setup`` is only read.
    """
    n_bands = setup.band_listed.shape[0]
    for b in prange(n_bands):
        band_dividing(np.int64(b), setup, n_bands, rule, depth_test, first_index, ends, depth, tri_index, tiles)
        if ends & LAST_BATCH:
            finish_band(np.int64(b), n_bands, BLOCK_ROWS, tri_index, covered)


@njit(cache=True, parallel=True)
def rasterize_walking(setup, rule, depth_test, first_index, ends, depth, tri_index, covered, tiles):
    """:func:`rasterize`, each span found by walking the triangle's edges (:func:`fill_rows`):
    the same pixels, quicker for tall triangles (:data:`TALL_ROWS`), in as many bands (each
    goes over every triangle, as the set-up's lists are for the other kernel's blocks)."""
    n_bands = setup.band_listed.shape[0]
    for b in prange(n_bands):
        band_walking(np.int64(b), setup, n_bands, rule, depth_test, first_index, ends, depth, tri_index, tiles)
        if ends & LAST_BATCH:
            finish_band(np.int64(b), n_bands, WALK_BLOCK_ROWS, tri_index, covered)


@njit(cache=True, parallel=True)
def weights_of_visible(plane, tri_index, bary):
    """:func:`screen_weights` of every covered pixel's triangle into ``bary`` (H, W, 2)."""
    for row in prange(tri_index.shape[0]):
        for col in range(tri_index.shape[1]):
            k = tri_index[row, col]
            if k != EMPTY:
                bary[row, col, 0], bary[row, col, 1] = screen_weights(k, row, col, plane)


WEIGHTS_IN_RASTER = False
"""Whether :func:`rasterize_visibility`'s set-up works out the weights' plane of every triangle
(:data:`DROP_WEIGHTS`): nothing the raster draws reads it, shading works it out for the
triangles that won a pixel. Left out, the set-up writes 48 bytes a triangle fewer: whole
frames, off / on alternating in one process, medians of 30 pairs, two runs: the 1M-triangle
scan at 1024² 0.986 and 0.983, the other big meshes 0.98–1.01 (docs/performance.md). True
is the plain path the tests compare with: the same buffers."""

BATCH = 1 << 15
"""Triangles set up and drawn at a time: the set-up tables stay this long (about 5 MB)."""


def setup_tables(k_count: int, n_bands: int, ws=None, name: str = "raster") -> TriangleSetup:
    """Unwritten :class:`TriangleSetup` tables for ``k_count`` triangles in ``n_bands`` bands (``ws``, ``name``)."""
    chunks, lists = -(-k_count // int(SETUP_CHUNK)), -(-k_count // LIST_CHUNK)
    return TriangleSetup(front=empty(ws, f"{name}.front", k_count, np.bool_),
                         ccw=empty(ws, f"{name}.ccw", (k_count, 3, 2), np.int64),
                         rows=empty(ws, f"{name}.rows", (k_count, 2), np.int64),
                         plane=empty(ws, f"{name}.plane", (k_count, 11)),
                         listed=empty(ws, f"{name}.listed", k_count, np.int32),
                         counts=empty(ws, f"{name}.counts", (lists, 2), np.int64),
                         band_listed=empty(ws, f"{name}.band_listed", (n_bands, k_count), np.int32),
                         tallies=empty(ws, f"{name}.tallies", (chunks, 1 + n_bands), np.int64))


def set_up_corners(corners: CornerIndex, vertices: WindowVertices, height: int, cull_back: bool, ws=None,
                   name="raster", lone_test: bool = False, n_bands: int = 1, weights: bool = True,
                   tables: TriangleSetup | None = None) -> TriangleSetup:
    """Run :func:`setup_triangles` on the triangles whose corners ``corners`` names among the rows of
    ``vertices``, into ``tables`` (:func:`setup_tables` for as many triangles; None: made in ``ws``
    under ``name``). Boxes without pixel centres dropped first by the vertices' cells when they come
    with them (:data:`DROP_EMPTY_BOXES`); ``lone_test``: :data:`DROP_MISSED_CENTRES`; ``n_bands``: the
    raster's bands (``band_listed``); ``weights`` False: :data:`DROP_WEIGHTS`."""
    setup = setup_tables(len(corners.source), n_bands, ws, name) if tables is None else tables
    drops = ((DROP_BACK_FACES if cull_back else 0) | (DROP_MISSED_CENTRES if lone_test else 0)
             | (DROP_EMPTY_BOXES if len(vertices.cells) else 0) | (0 if weights else DROP_WEIGHTS))
    setup_triangles(corners, vertices, height, drops, *setup[:4], setup.band_listed, setup.tallies)
    return setup


def set_up(tri_fixed: np.ndarray, tri_window: np.ndarray, height: int, cull_back: bool, ws=None,
           name="raster", lone_test: bool = False, n_bands: int = 1) -> TriangleSetup:
    """:func:`set_up_corners` of triangles given whole: (K, 3, 2) fixed and (K, 3, 3) window corners;
    every triangle's facing and weights' plane worked out (no centre cells: the translucent
    pass reads them all)."""
    whole = whole_triangles(tri_fixed, tri_window, with_cells=False)
    return set_up_corners(whole.corners, whole.vertices, height, cull_back, ws, name, lone_test, n_bands)


def mean_rows(setup: TriangleSetup) -> float:
    """The rows the set-up triangles span on average (0.0 for none), from the chunks' sums (a
    sample of 256 triangles' rows, read after the set-up, cost 90 µs a batch in cache misses)."""
    return float(setup.row_sums.sum()) / len(setup.rows) if len(setup.rows) else 0.0


def rasterize_visibility(triangles: IndexedTriangles, width: int, height: int, fill_rule: str = "top-left",
                         n_bands: int | None = None, ws=None, depth_test: bool = True, cull_back: bool = False,
                         batch: int | None = BATCH, backs_last: bool = False) -> Visibility:
    """Set up the triangles and fill the visibility buffer (the Python wrapper the pipeline calls).

    The triangles (:class:`IndexedTriangles`) are drawn in order, ``batch`` at a time (None: all
    at once), each set up (:func:`setup_triangles`, into the same tables) and filled (:func:`rasterize`)
    over what the batches before left: the buffer one pass fills. With a workspace ``ws`` every
    array but the frame's depth and coverage lives in it. ``n_bands``: one per thread by default
    (:func:`renderer.bands.raster_bands`); ``depth_test=False``: no z-buffer test; ``cull_back``: culling.
    ``backs_last=True`` (with the depth test): in each batch whose triangles span :data:`~renderer.hidden_back_faces.BACKS_LAST_ROWS`
    rows or more on average, and in a lone batch of over :data:`BATCH` not finer than the pixels, the back faces after
    the front faces (:mod:`renderer.draw_lists`), skipping those a tile z-buffer shows hidden: the same buffer.
    A batch after one finer than the pixels (:data:`~renderer.pixel_centres.LONE_ROWS`) drops triangles
    by their corners' centre cells and tests lone centres: the same buffer. No triangles: :func:`clear_visibility`.
    """
    tri_index = empty(ws, "raster.tri_index", (height, width), np.int32)
    if triangles.count == 0:
        return clear_visibility(tri_index)
    depth, covered = np.empty((height, width), np.int32), np.empty((height, width), np.bool_)  # the frame's
    bands, rule, count = raster_bands(height, n_bands), FILL_RULES[fill_rule], triangles.count
    tiles = new_tiles(height, width, ws) if backs_last and depth_test else NO_TILES
    step = count if batch is None else int(batch)
    span = float("inf")  # the mean rows of the batch before: no batch, no lone-centre test nor drop by cells
    whole = setup_tables(step, bands, ws, "raster") if step <= count else None  # written by each whole batch
    with one_band_at_a_time():  # the set-up too, once a frame (:func:`renderer.bands.one_band_at_a_time`)
        for a in range(0, count, step):
            corners = triangles.corners.batch(a, min(a + step, count))
            vertices = triangles.vertices if span < LONE_ROWS else triangles.vertices._replace(cells=NO_CELLS)
            setup = set_up_corners(corners, vertices, height, cull_back, ws, "raster", lone_test=span < LONE_ROWS,
                                   n_bands=bands, weights=WEIGHTS_IN_RASTER,
                                   tables=whole if a + step <= count else None)
            span = mean_rows(setup)  # chooses the kernel, the order and the next batch's test, never the pixels
            kernel = rasterize_walking if span >= TALL_ROWS else rasterize
            ends = ((FIRST_BATCH if a == 0 else 0) | (LAST_BATCH if a + step >= count else 0)
                    | (FINE_BATCH if span < LONE_ROWS else 0))
            behind = tiles if span >= BACKS_LAST_ROWS or (step >= count > BATCH and span >= LONE_ROWS) else NO_TILES
            if behind is not NO_TILES:
                list_by_facing(setup.rows, setup.front, setup.listed, setup.counts)
            kernel(setup, rule, bool(depth_test), a, ends, depth, tri_index, covered, behind)
    return Visibility(depth, tri_index, covered)


def rasterize_triangles(tri_fixed: np.ndarray, tri_window: np.ndarray, width: int, height: int,
                        fill_rule: str = "top-left", n_bands: int | None = None, ws=None,
                        depth_test: bool = True, cull_back: bool = False):
    """:func:`rasterize_visibility` of triangles given whole, in the textbook's terms (for
    lessons and tests): ``tri_fixed`` (K, 3, 2) and ``tri_window`` (K, 3, 3).

    Returns ``depth`` (H, W) window depth 0..1 on the 24-bit grid, ``tri_index`` (H, W),
    ``bary`` (H, W, 2) the screen-space weights of each visible triangle's vertices 1 and 2
    (undefined where empty), all in window rows (y up), and ``front`` (K,) per triangle.
    """
    whole = whole_triangles(tri_fixed, tri_window)
    vis = rasterize_visibility(whole, width, height, fill_rule, n_bands, ws, depth_test, cull_back)
    setup = set_up(tri_fixed, tri_window, height, cull_back)
    bary = np.zeros((height, width, 2))
    weights_of_visible(setup.plane, vis.tri_index, bary)
    return depth_to_window(vis.depth), vis.tri_index, bary, setup.front
