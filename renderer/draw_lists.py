"""A batch's triangles that draw, listed: by facing (front faces first, then back faces),
and by band (the triangles each band of the raster draws).

A batch whose back faces are drawn last (:mod:`renderer.hidden_back_faces`) is drawn in
two passes, its front faces and then its back faces. Each pass used to go over every
triangle asking which kind it was: neighbours in mesh order face either way at random,
so half the answers were mispredicted branches, twice. Now a pass over the set-up
(:func:`list_by_facing`) lists them, chunk by chunk, and each pass reads its list.

Layout (``listed`` (K,) int32, ``counts`` (C, 2) int64, C chunks of :data:`LIST_CHUNK`
triangles): chunk c's triangles are listed in its own stretch of ``listed``, the places
its triangles occupy (:func:`chunk_stretch`): its front faces from the stretch's start
forward, its back faces from the stretch's end backward, each in draw order as
:func:`listed_triangle` reads them; ``counts[c]`` says how many of each. A triangle with no
rows (:func:`renderer.raster.set_up_range`) is not listed.

Front faces before back faces is the same z-buffer, bit for bit, as drawing in order with
the depth test on: a fragment replaces the pixel's when it is nearer, or as near and its
triangle is numbered later (:func:`renderer.visibility_buffer.nearer_or_later`), whatever
came first.

The bands read the lists in :func:`renderer.band_draw.draw_band_listed`; a batch not drawn
backs last is drawn by a loop in draw order, compiled apart (:mod:`renderer.band_draw`).
Measured: docs/performance.md, "Back faces drawn last from lists, each loop compiled where a
frame needs it".

**By band** (:func:`list_on_bands`, as the set-up goes, :func:`renderer.raster.set_up_range`):
each band of the raster's (:mod:`renderer.bands`, blocks of :data:`~renderer.bands.BLOCK_ROWS`
rows) gets a list of the triangles with rows in its blocks, so a band in draw order reads its
own triangles only, not every triangle of the batch and its rows
(:func:`renderer.band_draw.draw_band_from_lists`). Layout: ``band_listed`` (B, K) int32, row b
band b's list, chunk c's entries in the stretch of its triangles' places (from its start
forward, in draw order); ``tallies`` (C, 1 + B) int64, column 1 + b how many band b lists
of chunk c (column 0 is the rows the chunk spans, :class:`renderer.raster.TriangleSetup`).
A triangle in blocks of several bands is in each of their lists.
"""
from __future__ import annotations

import numpy as np

from renderer.jit import njit, prange
from renderer.min_max import smaller

LIST_CHUNK = 1024
"""Triangles a parallel iteration of :func:`list_by_facing` lists: a chunk of the lists."""

FRONTS, BACKS = 0, 1
"""Columns of ``counts``, and the raster's two passes over a chunk's lists."""


@njit(cache=True, parallel=True)
def list_by_facing(rows, front, listed, counts):
    """List the triangles that draw (``rows`` (K, 2): first ≤ last) by facing (``front``
    (K,) bool) into ``listed`` (K,) int32 and ``counts`` (C, 2) int64, chunk by chunk of
    :data:`LIST_CHUNK` (the layout of the module docstring), one parallel iteration a chunk."""
    for chunk in prange(counts.shape[0]):
        first, last = chunk_stretch(chunk, LIST_CHUNK, rows.shape[0])
        fronts, backs = 0, 0
        for k in range(first, last + 1):
            fronts, backs = list_triangle(k, rows[k, 0] <= rows[k, 1], front[k], (first, last), (fronts, backs),
                                          listed)
        counts[chunk, FRONTS], counts[chunk, BACKS] = fronts, backs


@njit(cache=True, inline="always")
def chunk_stretch(chunk, chunk_size, count):
    """The stretch ``(first, last)`` (int64) of chunk ``chunk`` of ``count`` triangles taken
    ``chunk_size`` at a time: the places of its triangles, and of its lists."""
    first = np.int64(chunk) * np.int64(chunk_size)
    return first, smaller(first + np.int64(chunk_size), np.int64(count)) - 1


@njit(cache=True, inline="always")
def list_triangle(k, drawn, front, stretch, counts, listed):
    """Note triangle ``k`` of a chunk whose stretch of ``listed`` is ``stretch`` = (first,
    last) and whose counts so far are ``counts`` = (fronts, backs); returns the new counts.
    Branch-free: ``k`` is written either way, at the next free place of its kind (a front
    face's when it does not draw), and only counted when ``drawn``; a place written and not
    counted is written over by the next triangle, or lies past the counts."""
    first, last = stretch
    fronts, backs = counts
    at = first + fronts if front or not drawn else last - backs
    listed[at] = np.int32(k)
    return fronts + np.int64(drawn and front), backs + np.int64(drawn and not front)


@njit(cache=True, inline="always")
def listed_triangle(listed, stretch, side, j):
    """The ``j``-th triangle in draw order of a chunk's front faces (``side`` :data:`FRONTS`)
    or back faces (:data:`BACKS`), its stretch of ``listed`` being ``stretch`` = (first, last)."""
    first, last = stretch
    return listed[first + j] if side == FRONTS else listed[last - j]


@njit(cache=True, inline="always")
def list_on_bands(k, lo, hi, first, tally, band_listed, block_rows, per_band):
    """Note triangle ``k``, whose rows are ``lo`` … ``hi`` (window rows, 0 ≤ lo ≤ hi), in the
    list of each band that owns one of its blocks of ``block_rows`` rows (block j: band j mod
    B, B the rows of ``band_listed``): at place ``first`` + its count so far, ``tally[1 + b]``
    (the chunk's row of ``tallies``), which goes up by one. Branch-free, as :func:`list_triangle`:
    ``k`` is written at every band's next place and counted where its blocks reach that band
    (band b is ``(b − top) mod B`` blocks on from its top block's band). The top block's band
    without a division: ``per_band`` = 1 / B (:func:`block_band`)."""
    n_bands = band_listed.shape[0]
    top = lo // block_rows
    reach = hi // block_rows - top  # blocks after its top one
    top_band = block_band(top, n_bands, per_band)
    for b in range(n_bands):
        ahead = b - top_band + (n_bands if b < top_band else 0)
        band_listed[b, first + tally[1 + b]] = np.int32(k)
        tally[1 + b] += np.int64(ahead <= reach)


@njit(cache=True, inline="always")
def block_band(block, n_bands, per_band):
    """``block mod n_bands`` for 0 ≤ block < 2³¹ by a multiplication with ``per_band`` = 1 /
    n_bands: the quotient ⌊(block + ½) / n_bands⌋ is exact, as (block + ½) / n_bands lies at
    least 1 / (2·n_bands) from an integer, far more than the product's rounding. (A 64-bit
    division a triangle made the level-4 sponge's set-up at 512² 1.5–3.8 ms slower.)"""
    return block - n_bands * np.int64((block + 0.5) * per_band)
