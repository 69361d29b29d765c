"""Triangles whose box holds one pixel centre (renderer/one_pixel.py): the box's one column,
and the one centre tested alone giving the same pixel, depth and winner as a division per
edge and row; through the raster, a batch finer than the pixels drawn so gives the buffer
the same batch gives drawn by the lanes and spans."""
from __future__ import annotations

import contextlib

import numpy as np
import pytest

from renderer import raster
from renderer.fill_rules import FILL_RULES, TOP_LEFT
from renderer.jit import njit
from renderer.one_pixel import NOT_ONE_COLUMN, OUTSIDE_IMAGE, fill_one_centre, one_column
from renderer.raster import fill_row, set_up
from renderer.indexed_triangles import whole_triangles
from renderer.window import SUBPIXEL

from .pixel_soups import same_buffer_both_ways, window_of
from .single_thread import one_thread


@njit
def column_of(f, width):
    return one_column(f, width)


@pytest.mark.parametrize("xs, width, expected", [
    ((1.25, 1.5, 1.75), 10, NOT_ONE_COLUMN),  # between two columns of centres: none
    ((1.25, 1.5, 2.75), 10, 2),               # the box holds column 2 only
    ((2.0, 2.5, 2.75), 10, 2),                # a corner on the centre's column counts
    ((1.5, 2.0, 3.0), 10, NOT_ONE_COLUMN),    # columns 2 and 3: two
    ((-0.75, -0.5, -0.25), 10, NOT_ONE_COLUMN),
    ((-1.5, -1.25, -0.75), 10, OUTSIDE_IMAGE),  # column −1, left of the image
    ((9.5, 9.75, 10.25), 10, OUTSIDE_IMAGE),    # column 10, right of it
    ((9.0, 9.0, 9.0), 10, 9),                  # the last column, corners on it
])
def test_the_box_s_one_column_of_centres(xs, width, expected):
    """Pixel centre i at 256·i on the fixed-point grid: the box's column is the one centre
    between its leftmost and rightmost corner, if there is exactly one and it is in the image."""
    f = np.array([[x * SUBPIXEL, y * SUBPIXEL] for x, y in zip(xs, (0, 0, 1))], np.int64)
    assert column_of(f, width) == expected


@njit
def draw_one_centre_ones(setup, rule, depth_test, alone, depth, tri_index):
    """Draw, in order, every triangle of ``setup`` with one row of centres and one column of
    them in the image: at that centre alone (``alone``) or by one division per edge and row
    (:func:`renderer.raster.fill_row`); how many were drawn."""
    drawn = 0
    for k in range(setup.ccw.shape[0]):
        lo, hi = setup.rows[k, 0], setup.rows[k, 1]
        col = one_column(setup.ccw[k], depth.shape[1])
        if lo != hi or col < 0:
            continue
        drawn += 1
        if alone:
            fill_one_centre(setup.ccw[k], lo, col, setup.plane[k], np.int32(k), rule == TOP_LEFT, depth_test,
                            depth, tri_index)
        else:
            fill_row(k, lo, setup, rule, depth_test, 0, depth, tri_index)
    return drawn


def pixel_sized(rng, n, width, height, reach=1.0):
    """``n`` triangles about a pixel wide (``reach`` below 1: narrower), fixed (n, 3, 2): corners on pixel centres (edges
    through a centre, some horizontal or vertical: ties for the fill rule), on quarter
    pixels, anywhere; some over the image's sides; a fifth repeated with the winding turned
    (the same centre on an edge they share)."""
    kinds = rng.integers(0, 3, n)
    base = rng.integers([-1, -1], [width + 1, height + 1], (n, 1, 2)) * SUBPIXEL
    on_centres = rng.integers(-1, 2, (n, 3, 2)) * SUBPIXEL
    quarters = rng.integers(-4, 5, (n, 3, 2)) * (SUBPIXEL // 4)
    anywhere = rng.integers(-SUBPIXEL, SUBPIXEL + 1, (n, 3, 2))
    offsets = np.select([kinds[:, None, None] == 0, kinds[:, None, None] == 1], [on_centres, quarters], anywhere)
    fixed = base + (offsets * reach).astype(np.int64)
    twins = rng.choice(n, n // 5, replace=False)
    return np.concatenate([fixed, fixed[twins][:, ::-1]]).astype(np.int64)


@pytest.mark.parametrize("rule", ["top-left", "bottom-right"])
@pytest.mark.parametrize("depth_test", [True, False])
def test_one_centre_alone_fills_what_a_division_per_row_fills(rule, depth_test):
    """3,600 pixel-sized triangles over a 12×9 image, front and back faces, over one another at
    random and equal depths: tested at their one centre, the same depth and triangle at every
    pixel as their spans found by division."""
    width, height = 12, 9
    rng = np.random.default_rng(7)
    fixed = pixel_sized(rng, 3000, width, height)
    setup = set_up(fixed, window_of(rng, fixed), height, False)
    drawn, tri_index = same_buffer_both_ways(
        lambda alone, depth, tri_index: draw_one_centre_ones(setup, FILL_RULES[rule], depth_test, alone, depth,
                                                             tri_index), width, height)
    assert drawn > 500 and len(np.unique(tri_index)) > 60  # the sample really draws, and overdraws


def fine_and_coarse(rng, width, height):
    """Batches of 64: triangles of under a pixel, and last eight up to four pixels wide over the
    first eight (a fine batch: fewer rows a triangle than :data:`renderer.pixel_centres.LONE_ROWS`),
    alternating with a batch in which a quarter of the triangles reach up to eight pixels
    (most of those batches span more rows a triangle than LONE_ROWS: coarse)."""
    fine = pixel_sized(rng, 2200, width, height, 0.4)[:2560].reshape(-1, 64, 3, 2)
    fine[:, 1::2] += SUBPIXEL // 2  # about a point between four centres: mostly none in the box
    around = rng.integers(-2 * SUBPIXEL, 2 * SUBPIXEL + 1, (len(fine), 8, 3, 2))
    fine[:, -8:] = fine[:, :8, :1] + around  # last, a few of more centres over the first few
    larger_ones = pixel_sized(rng, len(fine) * 64, width, height, 8.0)[:len(fine) * 64].reshape(fine.shape)
    mixed = np.where(rng.random((len(fine), 64, 1, 1)) < 0.25, larger_ones, fine[::-1])
    return np.stack([fine, mixed], 1).reshape(-1, 3, 2)


@pytest.mark.parametrize("n_bands", [1, 2, 3])
@pytest.mark.parametrize("rule", ["top-left", "bottom-right"])
@pytest.mark.parametrize("depth_test", [True, False])
def test_a_fine_batch_fills_the_buffer_the_lanes_and_spans_fill(monkeypatch, n_bands, rule, depth_test):
    """The raster's fine batches (:data:`renderer.raster.FINE_BATCH`) test a one-centre triangle at
    its centre; with the bit never set, the same batches go to the lanes and spans. The same
    depth, triangle and coverage at every pixel, in any number of bands (a one-centre
    triangle's row drawn by its own band only), on one thread and on the default number."""
    width, height = 40, 33
    rng = np.random.default_rng(n_bands)
    fixed = fine_and_coarse(rng, width, height)
    triangles = whole_triangles(fixed, window_of(rng, fixed))
    spans, mean_rows = [], raster.mean_rows
    monkeypatch.setattr(raster, "mean_rows", lambda setup: spans.append(mean_rows(setup)) or spans[-1])
    runs = []
    for fine_bit in (raster.FINE_BATCH, 0):
        monkeypatch.setattr(raster, "FINE_BATCH", fine_bit)
        for single in (False, True):
            with one_thread() if single else contextlib.nullcontext():
                vis = raster.rasterize_visibility(triangles, width, height, rule, n_bands, depth_test=depth_test,
                                                  batch=64)
            runs.append(vis)
    for vis in runs[1:]:
        np.testing.assert_array_equal(vis.tri_index, runs[0].tri_index)
        np.testing.assert_array_equal(vis.depth, runs[0].depth)
        np.testing.assert_array_equal(vis.covered, runs[0].covered)
    fine = np.array(spans[:len(fixed) // 64]) < raster.LONE_ROWS
    assert 10 <= fine.sum() < len(fine)  # both kinds of batch were drawn
    winners = np.unique(runs[0].tri_index[runs[0].covered])
    assert fine[winners // 64].sum() > 20  # and pixels were won in fine batches

