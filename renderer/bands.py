"""Rows dealt out like cards: how the parallel loops share an image's rows among threads.

Every parallel loop over an image (:func:`renderer.raster.rasterize`,
:func:`renderer.shading.shade_rows`, :mod:`renderer.translucency`) splits the rows into
``n_bands`` **bands**: row r belongs to band r mod n_bands, and the bands are shared among
the threads. Every band gets rows from all over the image; in contiguous blocks, a floor
filling the lower half landed on one thread and the sky on the other (measured: 1 thread
12.7 ms, 2 threads 11.5 ms on ``near-plane``).

A pixel belongs to exactly one band and each band works through its rows in order, so the
number of bands never changes a byte: a test renders with one band and with many.
How many bands pay depends on the loop: the scan-conversion loops walk every triangle once
per band (:func:`raster_bands`: one per thread), shading has no such cost
(:data:`SHADING_BANDS`).

The opaque raster deals **blocks** of :data:`BLOCK_ROWS` rows instead of single rows
(:func:`first_block_of_band`): a small triangle then lies in one band, which reads its
set-up once, and the others pass over it. Dealt row by row, each of the four bands of two
threads set up nearly every triangle of a 672k-triangle Menger sponge again (measured, one
thread: 147 ms a frame with one band, 156 with two, 182 with four).
"""
from __future__ import annotations

import numba

from renderer.jit import njit

BAND_CHUNK = 1
"""Bands a thread takes at a time in a loop over bands (numba's parallel chunk size): one, so
threads take the next band as they come free. Left to numba, the bands are cut into one
fixed share per thread, and when another process holds a core, the thread that shares it
holds up the whole loop (:func:`one_band_at_a_time`)."""

SHADING_BANDS = 64
"""Bands for the shading loops: many, so that two threads get even shares of costly rows."""


def raster_bands(height: int, n_bands: int | None = None) -> int:
    """Bands for a scan-conversion loop over ``height`` rows: ``n_bands``, by default one per
    thread, at least 1 and at most one per row.

    Each band walks the whole triangle list (passing over the triangles that miss its rows),
    so fewer bands, less walking. Measured in one process, frames alternating, one band a
    thread against two (two threads, the same bytes): igea-270k at 512² 0.94, igea-1m at
    1024² 0.95, menger4 at 512² 0.96, ico7-flat at 512² 0.98, the small scenes 0.99–1.00.
    Two per thread were kept while a frame could start two threads on a core another
    process held (one band then waits for the thread that shares its core); a frame now
    takes no more threads than the cores left free (:mod:`renderer.free_cores`)."""
    if n_bands is None:
        n_bands = numba.get_num_threads()
    return max(1, min(int(n_bands), height))


def shading_bands(height: int) -> int:
    """Bands for a shading loop over ``height`` rows: :data:`SHADING_BANDS`, at most one per row."""
    return max(1, min(height, SHADING_BANDS))


def one_band_at_a_time():
    """A ``with`` block in which numba's parallel loops hand out :data:`BAND_CHUNK` iterations
    at a time: the calls of loops over bands go in one (a loop over triangles does not: taken
    one by one, each triangle pays the hand-out). Measured on 2 cores, another process
    spinning, 2 threads / 1 thread: shading of igea-270k at 512² 1.01 in fixed shares, 0.83
    one band at a time. Which thread takes a band never changes a byte (a band's rows are its own).

    The raster enters one block for a frame's batches, their set-up's loop over chunks of
    :data:`renderer.raster.SETUP_CHUNK` triangles included, not one a batch around its fill
    (frames alternating in one process, 20 pairs: the 1M scan 0.92 at 512² and 0.94 at 1024²,
    the level-4 sponge 0.95 at 512², the 270k scan 0.96 and 0.98; one-batch frames 0.97–1.01).
    The set-up alone, taken a chunk at a time: 0.96 of its time on the 1M scan at 512², 1.01 on
    the sponge and the 270k scan."""
    return numba.parallel_chunksize(BAND_CHUNK)


BLOCK_ROWS = 16
"""Rows in a block of the opaque raster's bands: block j holds rows 16j … 16j + 15 and
belongs to band j mod n_bands (the walking kernel deals blocks of 64,
:data:`renderer.raster.WALK_BLOCK_ROWS`)."""


@njit(cache=True, inline="always")
def first_block_of_band(lo, band, n_bands, block_rows=BLOCK_ROWS):
    """The first block (of ``block_rows`` rows, :data:`BLOCK_ROWS` unless told) that ``band``
    owns among the blocks from the one holding row ``lo`` on (block j belongs to band j mod n_bands)."""
    first = lo // block_rows
    return first + band_offset(band - first, n_bands)


@njit(cache=True, inline="always")
def first_row_of_band(lo, band, n_bands):
    """The first row ≥ ``lo`` that ``band`` owns (rows r with r mod n_bands = band)."""
    return lo + band_offset(band - lo, n_bands)


@njit(cache=True, inline="always")
def band_offset(d, n_bands):
    """``d mod n_bands`` (0 … n_bands − 1, also for a negative ``d``): a mask when ``n_bands``
    is a power of two, as :func:`raster_bands` gives by default (one per thread on one or
    two threads), else a division. The scan-conversion loops ask this once per triangle
    and band: an integer division each time took 4–5 % of a frame of the 270k-triangle
    Igea scan and of a level-4 Menger sponge (two threads, four bands)."""
    if n_bands & (n_bands - 1) == 0:
        return d & (n_bands - 1)
    return d % n_bands


