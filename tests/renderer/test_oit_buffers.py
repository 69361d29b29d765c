"""The ``oit`` buffers: 8-bit blending, half-float sums of a pixel's fragments, a run added in whole lanes."""
import numpy as np
import pytest

from renderer.jit import njit
from renderer.oit_buffers import (SUM_B, SUM_G, SUM_R, TRANSMIT, WEIGHT, add_run_to_oit, blend8, clear_oit_rows,
                                  mul8, oit_add)
from renderer.spans import LANES


def test_mul8_is_the_rounded_product_over_255():
    """Every pair of 8-bit values: mul8(a, b) = round(a·b/255) (no ties: a·b/255 is never k + ½)."""
    a, b = np.meshgrid(np.arange(256), np.arange(256))
    ours = np.array([[mul8(x, y) for x, y in zip(ra, rb)] for ra, rb in zip(a, b)])
    np.testing.assert_array_equal(ours, np.rint(a * b / 255.0).astype(int))


def test_blend8_saturates_at_255():
    """200·255/255 + 200·255/255 = 400 → 255; 128·128/255 + 127·255/255 = 64 + 127 = 191."""
    assert blend8(200, 255, 200, 255) == 255
    assert blend8(128, 128, 127, 255) == 191


@njit(cache=False)
def add_runs(colour, runs, alphas, seen, sums):
    """Each run (row, first pixel, pixels, first colour column) of ``runs`` through add_run_to_oit, in order."""
    for r in range(runs.shape[0]):
        add_run_to_oit(colour, runs[r, 3], alphas[r], runs[r, 0], runs[r, 1], runs[r, 2], seen, sums)


@njit(cache=False)
def cleared(sums, lo, hi):
    clear_oit_rows(sums, lo, hi)


def one_fragment_at_a_time(colour, runs, alphas, height, width):
    """The buffers as oit_add leaves them, a fragment at a time, each pixel from no fragment."""
    sums = np.zeros((5, height, width), np.float32)
    sums[TRANSMIT] = 1.0
    seen = np.zeros((height, width), np.int32)
    for (row, c0, count, first), a in zip(runs, alphas):
        for i in range(count):
            p = (row, c0 + i)
            new = oit_add(sums[SUM_R][p], sums[SUM_G][p], sums[SUM_B][p], sums[WEIGHT][p], sums[TRANSMIT][p],
                          colour[0, first + i], colour[1, first + i], colour[2, first + i], a)
            for c, v in enumerate(new):
                sums[c][p] = v
            seen[p] += 1
    return sums, seen


def test_clearing_gives_the_buffers_of_a_pixel_without_fragments():
    sums = np.full((5, 4, 9), 7.0, np.float32)
    cleared(sums, 1, 2)
    assert (sums[:TRANSMIT, 1:3] == 0.0).all() and (sums[TRANSMIT, 1:3] == 1.0).all()
    assert (sums[:, 0] == 7.0).all() and (sums[:, 3] == 7.0).all()


@pytest.mark.parametrize("width", [LANES - 3, 2 * LANES + 5, 61])
def test_runs_added_in_whole_lanes_give_the_sums_of_one_fragment_at_a_time(width):
    """Runs of every length from 1 to the row's width, overlapping in layers, at the row's start
    and end (where the lanes would pass it) and at the colour table's end (where they would
    read past it), with several alphas: the bits of oit_add a fragment at a time, and the
    pixels past each run (inside its lanes) unchanged."""
    rng = np.random.default_rng(width)
    height, runs, alphas, column = 5, [], [], 0
    for count in range(1, width + 1):
        for c0 in sorted({0, width - count, int(rng.integers(0, width - count + 1))}):
            runs.append((int(rng.integers(0, height)), c0, count, column))
            alphas.append(np.float32(rng.choice([0.3, 0.5, 0.7, 1.0])))
            column += count
    colour = rng.uniform(0.0, 1.2, (3, column)).astype(np.float32)  # the last run ends at the table's end
    sums = np.full((5, height, width), np.nan, np.float32)
    cleared(sums, 0, height - 1)
    seen = np.zeros((height, width), np.int32)
    add_runs(colour, np.array(runs, np.int64), np.array(alphas, np.float32), seen, sums)
    expected_sums, expected_seen = one_fragment_at_a_time(colour, runs, alphas, height, width)
    np.testing.assert_array_equal(seen, expected_seen)
    np.testing.assert_array_equal(sums.view(np.uint32), expected_sums.view(np.uint32))
