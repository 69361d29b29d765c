"""The visibility buffer: for each pixel the 24-bit depth and the triangle that won it.

Window rows (y up), as :mod:`renderer.raster` fills them. The depth is an integer: window
depth 0..1 times 2²⁴ − 1, rounded (:func:`depth_bits`), as in a 24-bit OpenGL depth buffer,
so equal depths compare equal and the z-buffer test is exact. Each of the raster's bands
clears its own rows before the first batch of triangles (:func:`clear_band`) and, after the
last, writes out their coverage for the frame (:func:`finish_band`); a
band's rows are dealt as :mod:`renderer.bands` says. A triangle's span on a row is written
into it by :func:`fill_columns`, the z-buffer test.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from renderer.jit import njit, prange
from renderer.min_max import clamp, larger, smaller
from renderer.spans import round_up_to_lanes

DEPTH_BITS = 24
DEPTH_MAX = float((1 << DEPTH_BITS) - 1)
DEPTH_CLEAR = np.int32((1 << DEPTH_BITS) - 1)
"""The integer depth buffer's clear value: window depth 1.0."""

EMPTY = -1
"""``tri_index`` of a pixel no triangle covers."""


@njit(cache=True, inline="always")
def depth_bits(z):
    """Window depth ``z`` clamped to 0..1 and rounded to the 24-bit depth buffer: an integer
    0 … 2²⁴ − 1 (the window depth times :data:`DEPTH_MAX`)."""
    return np.int32(np.floor(clamp(z, 0.0, 1.0) * DEPTH_MAX + 0.5))


@njit(cache=True, inline="always")
def nearer_or_later(z, kk, old_z, old_k):
    """The z-buffer's test: the fragment of triangle ``kk`` at depth ``z`` takes a pixel held
    by triangle ``old_k`` at ``old_z`` when it is nearer, or as near and numbered later. For
    triangles drawn in order (each numbered later than all before it) that is OpenGL's
    LEQUAL; it also decides a triangle drawn after later ones as drawing in order would
    (:mod:`renderer.hidden_back_faces`). An empty pixel is numbered :data:`EMPTY`, below all."""
    return (z < old_z) | ((z == old_z) & (kk > old_k))


@njit(cache=True, inline="always")
def kept_depth(z, old_z, inside):
    """The depth a pixel holding ``old_z`` keeps after the z-buffer test of a fragment at
    depth ``z``, where ``inside`` says the fragment is there at all: the nearer of the two
    (an equal depth is the same depth, whichever triangle takes the pixel), ``old_z`` where
    there is no fragment. Stored depths are at most :data:`DEPTH_CLEAR`, so the missing
    fragment is put there, behind or level with every stored depth, and the result is a
    minimum — with no value "as it was" that the compiler could turn into a store left
    out: a vector loop then stores whole lanes (``vmovdqu``) where it made masked stores
    (``vpmaskmovd``), slow on AMD's processors and never forwarded to the next load."""
    return smaller(old_z, larger(z, np.int32(DEPTH_CLEAR * (1 - np.int32(inside)))))


@njit(cache=True, inline="always")
def fill_lanes(first, last, z_row, zx, ax, kk, depth_row, index_row):
    """The depth test of columns ``first … last`` (two or more) of one row (``depth_row``,
    ``index_row``; see :func:`fill_columns`) in whole groups of
    :data:`renderer.spans.LANES` pixels (a vector register of int32 depths).

    The span is widened to a multiple of the lanes, to the right, or to the left where it
    would pass the row's end (in an image narrower than the lanes it stays as it is); a
    pixel outside ``first … last`` keeps its old values, as one whose test fails. The loop
    then runs in vector steps alone: a span of 2–8 pixels is one step, where the plain loop
    was scalar (below the vector loop's eight) with a branch a pixel. Measured, the raster
    alone, one thread, 512²: ico5 (spans of 4.7 pixels on average) 4.8 → 3.7 ms, a level-3
    Menger sponge 10.1 → 8.6."""
    count = last - first + 1
    lanes = round_up_to_lanes(count)
    start = first - larger(first + lanes - depth_row.shape[0], 0)
    if start < 0:
        start, lanes = first, count
    column = np.int32(start)  # the columns as int32 as well: a vector of them converts to float64 in one instruction
    first32, last32 = np.int32(first), np.int32(last)
    for i in range(lanes):
        col = start + i
        at = np.uint64(col)  # unsigned: numba adds no wrap-around for a negative index, which kept this loop scalar
        z = depth_bits(z_row + zx * (np.float64(column) + 0.5 - ax))
        old_z, old_k = depth_row[at], index_row[at]
        inside = (column >= first32) & (column <= last32)
        column = np.int32(column + 1)
        nearer = nearer_or_later(z, kk, old_z, old_k) & inside
        depth_row[at] = kept_depth(z, old_z, inside)
        index_row[at] = kk if nearer else old_k


@njit(cache=True, inline="always")
def fill_columns(row, first, last, z_row, zx, ax, kk, depth_test, depth, tri_index):
    """Fill columns ``first … last`` of scanline ``row`` with triangle ``kk``, whose depth at a
    pixel centre is :func:`pixel_depth`'s ``z_row + zx·(col + 0.5 − ax)``: depth test
    (:func:`nearer_or_later`), visibility-buffer writes.

    Each pixel is written, with its old values where the test fails, instead of branching
    on the test, so a test that passes and fails at random (deep overdraw: a Menger sponge)
    costs no mispredicted branches: one pixel in straight-line code (a min and a select;
    the slivers of a 1,024-segment cylinder are mostly empty or one pixel wide), more in
    whole vector lanes (:func:`fill_lanes`)."""
    depth_row, index_row = depth[row], tri_index[row]
    if not depth_test:
        for col in range(first, last + 1):
            depth_row[col] = depth_bits(z_row + zx * (col + 0.5 - ax))
            index_row[col] = kk
        return
    if last < first:
        return
    if last == first:
        at = np.uint64(first)
        z, old_z = depth_bits(z_row + zx * (first + 0.5 - ax)), depth_row[at]
        index_row[at] = kk if nearer_or_later(z, kk, old_z, index_row[at]) else index_row[at]
        depth_row[at] = smaller(old_z, z)
        return
    fill_lanes(first, last, z_row, zx, ax, kk, depth_row, index_row)


@njit(cache=True, inline="always")
def clear_band(b, n_bands, block_rows, depth, tri_index):
    """Clear band ``b``'s rows (blocks of ``block_rows`` rows, every ``n_bands``-th from block
    ``b``) of the visibility buffer: depth :data:`DEPTH_CLEAR`, triangle :data:`EMPTY`. A band
    clears the rows it draws, so no band waits for another."""
    height, width = depth.shape
    for block in range(b, (height + block_rows - 1) // block_rows, n_bands):
        for row in range(block * block_rows, smaller(block * block_rows + block_rows, height)):
            for col in range(width):
                depth[row, col] = DEPTH_CLEAR
                tri_index[row, col] = EMPTY


@njit(cache=True, from_python=False, refcounts=False)
def finish_band(b, n_bands, block_rows, tri_index, covered):
    """Band ``b``'s rows of the finished visibility buffer (blocks of ``block_rows`` rows, as
    :func:`clear_band`) as the frame's coverage: ``covered`` = tri_index ≠ :data:`EMPTY`. Done by
    the band that drew the rows, after the last batch, while they are still in its cache (a
    parallel pass of its own cost 0.4–0.8 ms a 1024² frame, and 0.4 s of compile on a cold start).
    The frame's window depth is not written here: the frame keeps the integer depth and
    divides it only if someone reads it (:func:`depth_to_window`, :class:`lab.frame.Frame`)."""
    height, width = tri_index.shape
    for block in range(b, (height + block_rows - 1) // block_rows, n_bands):
        for row in range(block * block_rows, smaller(block * block_rows + block_rows, height)):
            for col in range(width):
                covered[row, col] = tri_index[row, col] != EMPTY


class Visibility(NamedTuple):
    """The opaque pass's visibility buffer (window rows, y up): ``depth`` (H, W) int32, the
    24-bit integer depth (:data:`DEPTH_CLEAR` where empty), a fresh array (the frame keeps
    it); ``tri_index`` (H, W) int32, the triangle that won each pixel (:data:`EMPTY` where
    none), the workspace's; and ``covered`` (H, W) bool (tri_index ≠ EMPTY), a fresh array."""

    depth: np.ndarray
    tri_index: np.ndarray
    covered: np.ndarray


def depth_to_window(depth: np.ndarray) -> np.ndarray:
    """24-bit integer depths → window depth 0..1 as float64 (``q / (2²⁴ − 1)``, 1.0 where empty)."""
    return depth / DEPTH_MAX


def clear_visibility(tri_index: np.ndarray) -> Visibility:
    """The visibility buffer of a frame without triangles (nothing opaque in the scene): depth
    :data:`DEPTH_CLEAR`, triangle :data:`EMPTY` (written into ``tri_index`` (H, W) int32, the
    workspace's) and nothing covered. The buffers the raster's kernels leave when they draw
    no triangle, filled without setting up an empty batch (a frame of translucent objects
    only: 0.2 ms of the raster and its glue), rows in parallel (:func:`clear_frame`)."""
    depth, covered = np.empty(tri_index.shape, np.int32), np.empty(tri_index.shape, np.bool_)
    clear_frame(depth, tri_index, covered)
    return Visibility(depth, tri_index, covered)


def untested_visibility(tri_index: np.ndarray) -> Visibility:
    """The visibility buffer of a frame with nothing opaque whose translucent fragments are
    drawn without a depth test, as every one of them passes it (window depth z ≤
    :data:`DEPTH_CLEAR`, the depth of a pixel without a surface): **not written**, because
    nothing reads it — ``depth`` a fresh (H, W) int32 array and ``tri_index`` (H, W) int32 the
    workspace's, both as they come, of which the translucent pass and the shading (nothing
    to shade but the background) read the shapes only; ``covered`` None (the frame's coverage
    is the translucent pass's). The frame's depth is then :func:`cleared_depth`'s. The
    buffers :func:`clear_visibility` fills cost that frame 0.2–0.25 ms at 512² and 1024²,
    reading the depth back for the translucent pass's depth tests about as much again."""
    return Visibility(np.empty(tri_index.shape, np.int32), tri_index, None)


def cleared_depth(shape) -> np.ndarray:
    """The depth of a frame without an opaque surface: :data:`DEPTH_CLEAR` at every pixel, a fresh (H, W) int32 array."""
    return np.full(shape, DEPTH_CLEAR, np.int32)


@njit(cache=True, parallel=True)
def clear_frame(depth, tri_index, covered):
    """:func:`clear_visibility`'s buffers filled, rows in parallel: each row cleared as a band's
    rows are (:func:`clear_band`) and its coverage written as a finished band's
    (:func:`finish_band`: nothing covered), a band of one row each."""
    height = depth.shape[0]
    for row in prange(height):
        clear_band(np.int64(row), height, 1, depth, tri_index)
        finish_band(np.int64(row), height, 1, tri_index, covered)
