"""A band's share of the opaque raster: which triangles it draws, in which order, and which
blocks of their rows (:mod:`renderer.bands`).

The raster's band kernels (:func:`renderer.raster.band_dividing`, ``band_walking``) each
inline one of the two loops below with their own fill of a stretch of rows
(``fill_stretch(k, top, bottom, setup, rule, depth_test, first_index, depth, tri_index)``):
:func:`renderer.raster.fill_rows_dividing` or :func:`renderer.raster.fill_rows`. A band
draws a batch, a block of rows at a time (``deal`` = (n_bands, block_rows): block j belongs
to band j mod n_bands; ``rules`` = (rule, depth_test, first_index); ``buffer`` = the
visibility buffer's ``(depth, tri_index)``),

- **in draw order** (:func:`draw_band_in_order`), every triangle with rows, or those of the
  band's own list (:func:`draw_band_from_lists`, blocks of :data:`~renderer.bands.BLOCK_ROWS`); or
- **back faces last** (:func:`draw_band_listed`), with a tile z-buffer
  (:mod:`renderer.hidden_back_faces`): the front faces, then the back faces, each from the
  set-up's lists by facing (:mod:`renderer.draw_lists`), a back face's block of rows
  skipped where the tiles show it hidden.

Which of the two is decided as numba compiles a band kernel, from the type of its argument
``tiles``: None (:data:`renderer.hidden_back_faces.NO_TILES`) or an array. A kernel is
compiled once for each, when a frame first needs it, and each holds one loop and one copy
of the fill. The choice is made in the kernel itself, on its own argument: numba drops a
branch it can decide from the arguments' types before it inlines the functions called
there, but a branch inside an inlined function only after inlining both. (With an inlined
``draw_band`` holding the choice, the start-up scene's raster compiled in 11.4 s against 7.3
for the kernel before; with the choice in the kernel, 7.2 and 7.6 s against 9.7 and 8.6.)
The two loops in one kernel, chosen as it ran, compiled the fill twice and doubled a cold
start (23–25 s against 9–11 s); one loop for both, reading the lists in either case, made
every frame slower (1.10–1.28): docs/performance.md, "Back faces drawn last from lists by
facing".

Rows (``top``, ``bottom``, ``lo``, ``hi``) are window rows (y up), as everywhere in the raster.
"""
from __future__ import annotations

import numpy as np

from renderer.bands import first_block_of_band
from renderer.draw_lists import BACKS, LIST_CHUNK, chunk_stretch, listed_triangle
from renderer.fill_rules import TOP_LEFT
from renderer.hidden_back_faces import UNTESTED, fragment_depth_floor, hidden_in_tiles
from renderer.jit import njit
from renderer.min_max import larger, smaller
from renderer.one_pixel import NOT_ONE_COLUMN, OUTSIDE_IMAGE, fill_one_centre, one_column


@njit(cache=True, inline="always")
def draw_band_in_order(b, setup, deal, rules, buffer, fill_stretch):
    """Band ``b``'s share of a batch in draw order: every triangle with rows drawn on the
    band's (:func:`draw_on_band`)."""
    for k in range(setup.ccw.shape[0]):
        if setup.rows[k, 0] <= setup.rows[k, 1]:  # else no row of pixel centres, or nothing to draw
            draw_on_band(k, b, setup, deal, rules, buffer, fill_stretch, UNTESTED, False)


@njit(cache=True, inline="always")
def draw_band_from_lists(b, setup, deal, rules, buffer, fill_stretch, one_pixel=False):
    """:func:`draw_band_in_order` from band ``b``'s own list of the set-up's (``band_listed``,
    :func:`renderer.draw_lists.list_on_bands`, made for the same bands and blocks as ``deal``):
    the triangles with rows in its blocks, chunk after chunk, in draw order; the band does not
    read the others' rows. The same stretches, in the same order. With ``one_pixel`` (a batch
    finer than the pixels), a triangle whose box holds one pixel centre is tested at that
    centre alone (:func:`draw_one_pixel`), not filled by ``fill_stretch``: the same pixels."""
    first = np.int64(0)
    for chunk in range(setup.tallies.shape[0]):
        for j in range(setup.tallies[chunk, 1 + b]):
            k = np.int64(setup.band_listed[b, first + j])
            if not (one_pixel and draw_one_pixel(k, setup, rules, buffer)):
                draw_on_band(k, b, setup, deal, rules, buffer, fill_stretch, UNTESTED, False)
        first += LIST_CHUNK


@njit(cache=True, inline="always")
def draw_one_pixel(k, setup, rules, buffer):
    """Triangle ``k`` of a band's list when its box holds one pixel centre (one row, so
    the row is the band's; :func:`renderer.one_pixel.one_column`): that centre drawn by
    :func:`renderer.one_pixel.fill_one_centre`, and True; False for a triangle of more
    centres, left to the band's fill."""
    lo = setup.rows[k, 0]
    if lo != setup.rows[k, 1]:
        return False
    col = one_column(setup.ccw[k], buffer[0].shape[1])
    if col == NOT_ONE_COLUMN:
        return False
    if col != OUTSIDE_IMAGE:
        rule, depth_test, first_index = rules
        fill_one_centre(setup.ccw[k], lo, col, setup.plane[k], np.int32(first_index + k), rule == TOP_LEFT,
                        depth_test, buffer[0], buffer[1])
    return True


@njit(cache=True, inline="always")
def draw_band_listed(b, setup, deal, rules, buffer, fill_stretch, tiles):
    """Band ``b``'s share of a batch back faces last: from the set-up's lists
    (:mod:`renderer.draw_lists`), the front faces, then the back faces, a back face's block
    of rows skipped where the tile z-buffer ``tiles`` shows it hidden."""
    for side in range(2):
        for chunk in range(setup.counts.shape[0]):
            stretch = chunk_stretch(chunk, LIST_CHUNK, setup.ccw.shape[0])
            for j in range(setup.counts[chunk, side]):
                k = listed_triangle(setup.listed, stretch, side, j)
                draw_on_band(k, b, setup, deal, rules, buffer, fill_stretch, tiles, side == BACKS)


@njit(cache=True, inline="always")
def draw_on_band(k, b, setup, deal, rules, buffer, fill_stretch, tiles, behind_tiles):
    """Triangle ``k``'s blocks of rows that belong to band ``b`` (``deal`` = (n_bands,
    block_rows)), each filled by ``fill_stretch(k, top, bottom, setup, rule, depth_test,
    first_index, depth, tri_index)`` (``rules`` = (rule, depth_test, first_index)); with
    ``behind_tiles``, a block only where ``tiles`` do not show it hidden."""
    n_bands, block_rows = deal
    rule, depth_test, first_index = rules
    depth, tri_index = buffer
    lo, hi = setup.rows[k, 0], setup.rows[k, 1]
    block = first_block_of_band(lo, b, n_bands, block_rows)
    floor = -1  # worked out at the first block this band draws: most triangles have none here
    while block * block_rows <= hi:
        top, bottom = larger(lo, block * block_rows), smaller(hi, block * block_rows + block_rows - 1)
        if behind_tiles and floor < 0:
            floor = fragment_depth_floor(setup.ccw[k], setup.plane[k])
        if not behind_tiles or not hidden_in_tiles(floor, setup.ccw[k], top, bottom, first_index, depth, tiles):
            fill_stretch(k, top, bottom, setup, rule, depth_test, first_index, depth, tri_index)
        block += n_bands
