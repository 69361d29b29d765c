"""The visibility buffer: 24-bit depths, a span's z-buffer test, and each band clearing and
finishing its own rows."""
from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from renderer.bands import BLOCK_ROWS
from renderer.jit import njit
from renderer.spans import LANES
from renderer.window import SUBPIXEL
from renderer.edge_functions import fill_narrow_rows
from renderer.visibility_buffer import (DEPTH_CLEAR, DEPTH_MAX, EMPTY, clear_band, depth_bits, depth_to_window,
                                        fill_columns, fill_lanes, finish_band, kept_depth, nearer_or_later)
from .assembly import scalar_int64_conversions


@njit
def depth_bits_of(z, out):
    for i in range(z.shape[0]):
        out[i] = depth_bits(z[i])


def test_depth_bits_round_window_depth_to_the_24_bit_grid_clamped_to_0_1():
    z = np.array([-0.5, 0.0, 0.5 / DEPTH_MAX, 1.5 / DEPTH_MAX, 0.25, 1.0, 2.0])
    out = np.empty(len(z), np.int32)
    depth_bits_of(z, out)
    assert out.tolist() == [0, 0, 1, 2, int(np.floor(0.25 * DEPTH_MAX + 0.5)), DEPTH_CLEAR, DEPTH_CLEAR]
    assert depth_to_window(np.array([0, DEPTH_CLEAR])).tolist() == [0.0, 1.0]


def plain_fill(row, first, last, z_row, zx, ax, kk, depth, tri_index):
    """The z-buffer test as the course writes it: pixel by pixel, LEQUAL."""
    for col in range(first, last + 1):
        z = depth_bits(z_row + zx * (col + 0.5 - ax))
        if z <= depth[row, col]:
            depth[row, col], tri_index[row, col] = z, kk


def test_a_fragment_wins_when_nearer_or_as_near_and_later():
    """The z-buffer's test, on (depth, triangle): nearer wins, farther loses, and a tie goes to
    the triangle numbered later, whichever was drawn first; an empty pixel (EMPTY) loses a tie."""
    assert nearer_or_later(5, 1, 6, 9) and not nearer_or_later(7, 9, 6, 1)
    assert nearer_or_later(6, 9, 6, 1) and not nearer_or_later(6, 1, 6, 9)
    assert nearer_or_later(DEPTH_CLEAR, 0, DEPTH_CLEAR, EMPTY)
    for first, second in ((1, 2), (2, 1)):  # two fragments at one depth, either drawn first
        depth, tri_index = np.full((1, 3), DEPTH_CLEAR, np.int32), np.full((1, 3), EMPTY, np.int32)
        for kk in (first, second):
            fill_columns(0, 0, 2, 0.25, 0.0, 0.0, np.int32(kk), True, depth, tri_index)
        assert tri_index.tolist() == [[2, 2, 2]]


@pytest.mark.parametrize("width", [3, LANES, 13, 21])
def test_a_span_is_tested_in_whole_lanes_as_pixel_by_pixel(width):
    """Every span of every length and place on a row, the last pixel included (a span's
    lanes that would pass the row's end are taken to the left of it; a row narrower than
    the lanes is filled as it is), over depths that the span beats, ties and loses to at
    random: the same buffer as the plain loop, and no pixel off the span touched."""
    rng = np.random.default_rng(width)
    z_row, zx, ax, kk = 0.5, 0.01, 0.25, np.int32(7)
    for first in range(width):
        for last in range(first - 1, width):
            old = np.array([depth_bits(z_row + zx * (c + 0.5 - ax)) for c in range(width)], np.int32)
            old = old + rng.integers(-1, 2, width).astype(np.int32)  # beaten, tied or in front
            depth, tri_index = np.stack([old, old, old]), np.full((3, width), 3, np.int32)
            plain_depth, plain_index = depth.copy(), tri_index.copy()
            fill_columns(1, first, last, z_row, zx, ax, kk, True, depth, tri_index)
            plain_fill(1, first, last, z_row, zx, ax, kk, plain_depth, plain_index)
            assert np.array_equal(depth, plain_depth) and np.array_equal(tri_index, plain_index), (first, last)


@njit
def kept_depths(z, old_z, inside, out):
    for i in range(z.shape[0]):
        out[i] = kept_depth(z[i], old_z[i], inside[i])


def test_the_depth_kept_is_the_winners_and_the_old_one_where_no_fragment_is():
    """Every pair of depths on the buffer's grid near 0, the middle and the clear value, the
    fragment there or not: the depth the pixel keeps is the fragment's where it wins the test
    (by either triangle number: a tie keeps the same depth), else the old one."""
    grid = np.array([0, 1, 2, 1 << 23, (1 << 23) + 1, DEPTH_CLEAR - 1, DEPTH_CLEAR], np.int32)
    z, old_z = (a.ravel() for a in np.meshgrid(grid, grid))
    for inside in (True, False):
        out = np.empty(len(z), np.int32)
        kept_depths(z, old_z, np.full(len(z), inside), out)
        for later in (True, False):
            wins = inside & nearer_or_later(z, 5 if later else 1, old_z, 3)
            assert out.tolist() == np.where(wins, z, old_z).tolist()


@njit
def fill_row_in_lanes(first, last, z_row, zx, ax, kk, depth_row, index_row):
    fill_lanes(first, last, z_row, zx, ax, kk, depth_row, index_row)


@njit
def fill_narrow_rows_tested(f, columns, lo, hi, plane, kk, depth, tri_index):
    fill_narrow_rows(f, columns, lo, hi, plane, kk, True, True, depth, tri_index)


MASKED_STORE = re.compile(r"^\s*(vp?maskmov\w*\s+%[xy]mm\d+,\s*%[xy]mm\d+,\s*[^%\s]*\(|"
                          r"vmov\w+\s+%[xyz]mm\d+,\s*[^%\s]*\([^)]*\)\s*\{%k)", re.MULTILINE)
"""A vector store under a mask, in the assembly numba prints (AT&T order: the memory operand last):
AVX's ``vpmaskmovd``/``vmaskmovps`` to memory, or AVX-512's ``vmovdqu32 …, (…) {%k1}``."""


def lane_loops_run():
    """Both vector loops of the depth test compiled and run once (a span of columns 3 … 40 in
    lanes, a narrow triangle's rows): the kernels whose assembly the tests read, and the
    span's row of triangle numbers."""
    depth_row, index_row = np.full(64, DEPTH_CLEAR, np.int32), np.full(64, EMPTY, np.int32)
    fill_row_in_lanes(3, 40, 0.5, 0.01, 0.25, np.int32(1), depth_row, index_row)
    f = np.array([[0, 0], [8 * SUBPIXEL, 0], [0, 8 * SUBPIXEL]], np.int64)
    depth, tri_index = np.full((8, 16), DEPTH_CLEAR, np.int32), np.full((8, 16), EMPTY, np.int32)
    fill_narrow_rows_tested(f, (0, LANES), 0, 7, np.zeros(11), np.int32(1), depth, tri_index)
    return (fill_row_in_lanes, fill_narrow_rows_tested), index_row


def test_the_depth_tests_vector_loops_store_whole_lanes():
    """The z-buffer test's vector loops (a span in lanes, a narrow triangle's rows) store whole
    vectors, the lanes a fragment does not take written back as they were: a masked store is
    slow on AMD's processors (a microcoded store, and no load after it is forwarded from it).
    The depth kept is a minimum (:func:`kept_depth`): written as "the old value where the
    test fails", LLVM dropped that store and masked the rest. On a processor without vector
    masks there is nothing to find, and the test holds trivially."""
    kernels, index_row = lane_loops_run()
    assert (index_row[3:41] == 1).all() and (index_row[41:] == EMPTY).all()
    for kernel in kernels:
        asm = "\n".join(kernel.inspect_asm().values())
        assert not MASKED_STORE.findall(asm), (kernel.__name__, MASKED_STORE.findall(asm)[:4])


def test_the_lanes_columns_become_floats_a_vector_at_a_time():
    """The depth at a lane's pixel centre needs its column as a float. AVX2 converts int32 lanes
    to float64 in one instruction (``vcvtdq2pd``) but has none for int64: a column counted as
    int64 was converted lane by lane, eight scalar ``vcvtsi2sd`` a step. The span loop counts
    its columns in int32 as well, the narrow triangles' loop adds a table of lane offsets to its
    first column (the same floats); so each kernel holds fewer scalar conversions of 64-bit
    registers than there are lanes (those left convert a row or a loop's bounds)."""
    kernels, _ = lane_loops_run()
    for kernel in kernels:
        conversions = scalar_int64_conversions(kernel)
        assert len(conversions) < LANES, (kernel.__name__, conversions)


_EVERY_SPAN_AS_PYTHON = """
import numba
import numpy as np
assert numba.config.DISABLE_JIT
from renderer.spans import LANES
from renderer.visibility_buffer import fill_columns
for width in (3, LANES, 13):
    for first in range(width):
        for last in range(first, width):
            depth, tri_index = np.full((1, width), 1 << 23, np.int32), np.zeros((1, width), np.int32)
            fill_columns(0, first, last, 0.25, 0.01, 0.0, np.int32(1), True, depth, tri_index)
            assert tri_index[0].tolist() == [int(first <= c <= last) for c in range(width)]
"""


def test_no_lane_reads_or_writes_outside_the_row():
    """A lane outside the span writes back what it read, so its values cannot show a lane
    past the row's end, into the next row (another band's) or past the buffer: run as
    plain Python (NUMBA_DISABLE_JIT=1), any index past the row raises."""
    repo = Path(__file__).resolve().parents[2]
    env = dict(os.environ, NUMBA_DISABLE_JIT="1", PYTHONPATH=os.pathsep.join([str(repo), os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run([sys.executable, "-c", _EVERY_SPAN_AS_PYTHON], cwd=repo, env=env, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]


@njit
def clear_then_finish(n_bands, block_rows, depth, tri_index, covered, which):
    for b in range(n_bands):
        if which == 0:
            clear_band(b, n_bands, block_rows, depth, tri_index)
        else:
            finish_band(b, n_bands, block_rows, tri_index, covered)


@pytest.mark.parametrize("n_bands, height", [(1, 5), (3, 71), (4, 16 * 9 + 1)])
def test_the_bands_clear_and_finish_every_row_once_between_them(n_bands, height):
    """Every band clears, and later finishes, its own blocks of rows: between them every row,
    the last block cut short included; finishing is the triangle buffer compared with EMPTY."""
    width = 7
    rng = np.random.default_rng(1)
    depth, tri_index = np.full((height, width), 5, np.int32), np.full((height, width), 3, np.int32)
    covered = np.zeros((height, width), np.bool_)
    clear_then_finish(n_bands, BLOCK_ROWS, depth, tri_index, covered, 0)
    assert (depth == DEPTH_CLEAR).all() and (tri_index == EMPTY).all()
    depth[:] = rng.integers(0, DEPTH_CLEAR + 1, depth.shape)
    tri_index[:] = np.where(rng.random(depth.shape) < 0.3, EMPTY, rng.integers(0, 9, depth.shape))
    kept = depth.copy()
    clear_then_finish(n_bands, BLOCK_ROWS, depth, tri_index, covered, 1)
    np.testing.assert_array_equal(depth, kept)  # finishing leaves the depth to the frame
    np.testing.assert_array_equal(covered, tri_index != EMPTY)


def test_a_frame_without_triangles_clears_every_pixel():
    """clear_visibility (a frame with nothing opaque, rows cleared in parallel): every pixel of
    the workspace's triangle buffer EMPTY whatever it held, the depth DEPTH_CLEAR, nothing covered."""
    from renderer.visibility_buffer import DEPTH_CLEAR, EMPTY, clear_visibility

    tri_index = np.full((37, 53), 7, np.int32)
    vis = clear_visibility(tri_index)
    assert vis.tri_index is tri_index and (tri_index == EMPTY).all()
    assert vis.depth.shape == (37, 53) and (vis.depth == DEPTH_CLEAR).all() and not vis.covered.any()
