"""The ``oit`` buffers: 8-bit blending, half-float sums of a pixel's fragments, a run of fragments added."""
import numpy as np
import pytest

from renderer.jit import njit
from renderer.oit_buffers import (OIT_VALUES, SUM_B, SUM_G, SUM_R, TRANSMIT, WEIGHT, add_run_to_oit, blend8,
                                  clear_oit_strip, mul8, oit_add, oit_resolve, resolve_oit_row, resolve_scratch)


def test_mul8_is_the_rounded_product_over_255():
    """Every pair of 8-bit values: mul8(a, b) = round(a·b/255) (no ties: a·b/255 is never k + ½)."""
    a, b = np.meshgrid(np.arange(256), np.arange(256))
    ours = np.array([[mul8(x, y) for x, y in zip(ra, rb)] for ra, rb in zip(a, b)])
    np.testing.assert_array_equal(ours, np.rint(a * b / 255.0).astype(int))


def test_nothing_blended_over_a_byte_leaves_it_as_it_was():
    """blend8(0, 0, v, 255) = v for every 8-bit v: what a pixel without fragments (clear
    buffers: colour 0, coverage 0) gives, so resolve_oit_row blends every pixel without a branch."""
    v = np.arange(256)
    np.testing.assert_array_equal([blend8(0, 0, x, 255) for x in v], v)


def test_blend8_saturates_at_255():
    """200·255/255 + 200·255/255 = 400 → 255; 128·128/255 + 127·255/255 = 64 + 127 = 191."""
    assert blend8(200, 255, 200, 255) == 255
    assert blend8(128, 128, 127, 255) == 191


@njit(cache=False)
def add_runs(colour, runs, alphas, seen, strip):
    """Each run (row, first pixel, pixels, first colour column) of ``runs`` through add_run_to_oit, in order."""
    for r in range(runs.shape[0]):
        row = runs[r, 0]
        add_run_to_oit(colour, runs[r, 3], alphas[r], runs[r, 1], runs[r, 2], seen[row], strip[row])


@njit(cache=False)
def cleared(strip):
    clear_oit_strip(strip)


def one_fragment_at_a_time(colour, runs, alphas, height, width):
    """The buffers as oit_add leaves them, a fragment at a time, each pixel from no fragment."""
    sums = np.zeros((height, width, OIT_VALUES), np.float32)
    sums[:, :, TRANSMIT] = 1.0
    seen = np.zeros((height, width), np.int32)
    for (row, c0, count, first), a in zip(runs, alphas):
        for i in range(count):
            v = sums[row, c0 + i]
            new = oit_add(v[SUM_R], v[SUM_G], v[SUM_B], v[WEIGHT], v[TRANSMIT],
                          colour[0, first + i], colour[1, first + i], colour[2, first + i], a)
            v[:] = new
            seen[row, c0 + i] += 1
    return sums, seen


def test_clearing_gives_the_buffers_of_pixels_without_fragments():
    strip = np.full((4, 9, OIT_VALUES), 7.0, np.float32)
    cleared(strip)
    assert (strip[:, :, :TRANSMIT] == 0.0).all() and (strip[:, :, TRANSMIT] == 1.0).all()


@pytest.mark.parametrize("width", [5, 21, 61])
def test_runs_give_the_sums_of_one_fragment_at_a_time(width):
    """Runs of every length from 1 to the row's width, overlapping in layers, at the row's start
    and end and at the colour table's end, with several alphas: the bits of oit_add a fragment
    at a time, and the pixels outside every run untouched."""
    rng = np.random.default_rng(width)
    height, runs, alphas, column = 5, [], [], 0
    for count in range(1, width + 1):
        for c0 in sorted({0, width - count, int(rng.integers(0, width - count + 1))}):
            runs.append((int(rng.integers(0, height)), c0, count, column))
            alphas.append(np.float32(rng.choice([0.3, 0.5, 0.7, 1.0])))
            column += count
    colour = rng.uniform(0.0, 1.2, (3, column)).astype(np.float32)  # the last run ends at the table's end
    strip = np.full((height, width, OIT_VALUES), np.nan, np.float32)
    cleared(strip)
    seen = np.zeros((height, width), np.int32)
    add_runs(colour, np.array(runs, np.int64), np.array(alphas, np.float32), seen, strip)
    expected_sums, expected_seen = one_fragment_at_a_time(colour, runs, alphas, height, width)
    np.testing.assert_array_equal(seen, expected_seen)
    np.testing.assert_array_equal(strip.view(np.uint32), expected_sums.view(np.uint32))


@njit(cache=False)
def resolved(buffers, rgb_row, first, last):
    resolve_oit_row(buffers, rgb_row, resolve_scratch(rgb_row.shape[0]), first, last)


@pytest.mark.parametrize("width, first, last", [(12, 3, 9), (12, 0, 11), (40, 5, 38), (12, 4, 4), (12, 6, 5)])
def test_a_row_resolves_its_touched_columns_over_the_frame_and_leaves_them_clear(width, first, last):
    """The touched columns ``first … last`` of a row (one, all, a stretch longer than a vector
    register, none), some of them without a fragment (their buffers clear, as the strip keeps
    them): the pixels with one get oit_resolve's colour over the frame's, the others keep
    theirs; the touched columns' buffers come back clear, the rest as they were."""
    rng = np.random.default_rng(width + first)
    buffers = np.full((width, OIT_VALUES), 5.0, np.float32)
    n = max(last - first + 1, 0)
    buffers[first:last + 1, :TRANSMIT] = rng.uniform(0.0, 1.0, (n, TRANSMIT)).astype(np.float32)
    buffers[first:last + 1, TRANSMIT] = rng.uniform(0.1, 0.9, n).astype(np.float32)
    empty = [c for c in range(first, last + 1) if c % 3 == 2]  # no fragment: clear buffers
    buffers[empty, :TRANSMIT], buffers[empty, TRANSMIT] = 0.0, 1.0
    before = buffers.copy()
    rgb = rng.integers(0, 256, (width, 3)).astype(np.uint8)
    frame = rgb.copy()
    resolved(buffers, rgb, first, last)
    for col in range(width):
        if first <= col <= last and col not in empty:
            out = np.zeros(3, np.int64)
            oit_resolve(*before[col], frame[col].astype(np.int64), out)
            np.testing.assert_array_equal(rgb[col], out)
        else:
            np.testing.assert_array_equal(rgb[col], frame[col])
    assert (buffers[first:last + 1, :TRANSMIT] == 0.0).all() and (buffers[first:last + 1, TRANSMIT] == 1.0).all()
    np.testing.assert_array_equal(buffers[:first], before[:first])
    np.testing.assert_array_equal(buffers[last + 1:], before[last + 1:])
