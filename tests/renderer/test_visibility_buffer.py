"""The visibility buffer: 24-bit depths, and each band clearing and finishing its own rows."""
from __future__ import annotations

import numpy as np
import pytest

from renderer.bands import BLOCK_ROWS
from renderer.jit import njit
from renderer.visibility_buffer import (DEPTH_CLEAR, DEPTH_MAX, EMPTY, clear_band, depth_bits, depth_to_window,
                                        finish_band)


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


@njit
def clear_then_finish(n_bands, block_rows, depth, tri_index, window_depth, covered, which):
    for b in range(n_bands):
        if which == 0:
            clear_band(b, n_bands, block_rows, depth, tri_index)
        else:
            finish_band(b, n_bands, block_rows, depth, tri_index, window_depth, covered)


@pytest.mark.parametrize("n_bands, height", [(1, 5), (3, 71), (4, 16 * 9 + 1)])
def test_the_bands_clear_and_finish_every_row_once_between_them(n_bands, height):
    """Every band clears, and later finishes, its own blocks of rows: between them every row,
    the last block cut short included; finishing is the buffer divided and compared."""
    width = 7
    rng = np.random.default_rng(1)
    depth, tri_index = np.full((height, width), 5, np.int32), np.full((height, width), 3, np.int32)
    window_depth, covered = np.full((height, width), np.nan), np.zeros((height, width), np.bool_)
    clear_then_finish(n_bands, BLOCK_ROWS, depth, tri_index, window_depth, covered, 0)
    assert (depth == DEPTH_CLEAR).all() and (tri_index == EMPTY).all()
    depth[:] = rng.integers(0, DEPTH_CLEAR + 1, depth.shape)
    tri_index[:] = np.where(rng.random(depth.shape) < 0.3, EMPTY, rng.integers(0, 9, depth.shape))
    clear_then_finish(n_bands, BLOCK_ROWS, depth, tri_index, window_depth, covered, 1)
    np.testing.assert_array_equal(window_depth, depth_to_window(depth))
    np.testing.assert_array_equal(covered, tri_index != EMPTY)
