"""A batch's triangles that draw, listed by facing (renderer/draw_lists.py): exactly the ones
with rows, chunk by chunk, front faces and back faces apart, each in draw order; and the
raster drawing its back faces last from the lists fills the buffer one pass in order fills.
Listed by band, as the set-up writes them: each band's list holds exactly the triangles with
rows in its blocks, chunk by chunk, in draw order."""
from __future__ import annotations

import numpy as np
import pytest

from renderer.bands import BLOCK_ROWS
from renderer.draw_lists import (BACKS, FRONTS, LIST_CHUNK, block_band, chunk_stretch, list_by_facing, list_triangle,
                                 listed_triangle)
from renderer.jit import njit
from renderer.raster import rasterize_visibility, set_up
from renderer.indexed_triangles import whole_triangles

from .test_hidden_back_faces import soup


@njit(cache=False)
def listed_in_one_chunk(drawn, front):
    """Every triangle noted in one chunk as :func:`list_by_facing` notes them; the lists read back."""
    n = len(drawn)
    listed = np.full(n, -1, np.int32)
    counts = (0, 0)
    for k in range(n):
        counts = list_triangle(k, drawn[k], front[k], (0, n - 1), counts, listed)
    fronts = [listed_triangle(listed, (0, n - 1), FRONTS, j) for j in range(counts[0])]
    backs = [listed_triangle(listed, (0, n - 1), BACKS, j) for j in range(counts[1])]
    return fronts, backs


@pytest.mark.parametrize("seed", range(4))
def test_a_chunk_lists_its_drawn_front_faces_and_back_faces_each_in_draw_order(seed):
    """Random drawn and facing flags (one triangle, none drawn, all drawn, some): the fronts
    read back are the drawn front faces in order, the backs the drawn back faces."""
    rng = np.random.default_rng(seed)
    for n, p_drawn in ((1, 0.5), (37, 0.0), (37, 1.0), (200, 0.6)):
        drawn, front = rng.random(n) < p_drawn, rng.random(n) < 0.5
        fronts, backs = listed_in_one_chunk(drawn, front)
        assert list(fronts) == np.flatnonzero(drawn & front).tolist()
        assert list(backs) == np.flatnonzero(drawn & ~front).tolist()


@njit(cache=False)
def stretches(chunk_size, count):
    return [chunk_stretch(c, chunk_size, count) for c in range((count + chunk_size - 1) // chunk_size)]


def test_the_chunks_stretches_cover_the_triangles_once_in_order():
    """Chunk c of ``count`` triangles holds c·size … (c + 1)·size − 1, the last one what is left."""
    assert stretches(4, 10) == [(0, 3), (4, 7), (8, 9)]
    assert stretches(5, 10) == [(0, 4), (5, 9)]
    assert stretches(1024, 1) == [(0, 0)]


@pytest.mark.parametrize("cull_back", [False, True])
def test_a_set_up_s_triangles_with_rows_are_listed_by_facing_and_no_other(cull_back):
    """2,200 triangles of a soup (three chunks of LIST_CHUNK, the last one short): each
    chunk lists the triangles of its own stretch that have rows, front faces and back faces
    apart (no back face when they are culled)."""
    fixed, window = soup(np.random.default_rng(3), 2000, 60, 45)
    setup = set_up(fixed, window, 45, cull_back)
    list_by_facing(setup.rows, setup.front, setup.listed, setup.counts)
    drawn = setup.rows[:, 0] <= setup.rows[:, 1]
    assert len(setup.counts) == 3 and 0 < drawn.sum() < len(drawn)
    size = LIST_CHUNK
    for c in range(3):
        chunk = np.arange(c * size, min((c + 1) * size, len(drawn)))
        last = chunk[-1]
        fronts = setup.listed[c * size:c * size + setup.counts[c, FRONTS]].tolist()
        backs = setup.listed[last - np.arange(setup.counts[c, BACKS])].tolist()
        assert fronts == chunk[(drawn & setup.front)[chunk]].tolist()
        assert backs == chunk[(drawn & ~setup.front)[chunk]].tolist()
        assert (backs == []) == cull_back


@pytest.mark.parametrize("batch", [None, 13])
@pytest.mark.parametrize("seed, count", [(0, 300), (1, 300), (2, 2400)])
def test_back_faces_last_from_the_lists_fill_the_buffer_drawing_in_order_fills(monkeypatch, seed, count, batch):
    """Every batch's back faces after its front faces, read from the lists (2,400 triangles
    are three chunks): the same depth and triangle at every pixel as one pass in order, ties
    and all, with both raster kernels; each batch listed once."""
    from renderer import raster
    from renderer.workspace import Workspace

    monkeypatch.setattr(raster, "BACKS_LAST_ROWS", 0)
    listed = []
    real = raster.list_by_facing
    monkeypatch.setattr(raster, "list_by_facing", lambda *args: listed.append(real(*args)))
    width, height = 70, 53
    fixed, window = soup(np.random.default_rng(seed), count, width, height)
    for tall in (False, True):
        monkeypatch.setattr(raster, "TALL_ROWS", 0 if tall else 10**9)
        in_order = rasterize_visibility(whole_triangles(fixed, window), width, height, batch=batch)
        assert listed == []
        last = rasterize_visibility(whole_triangles(fixed, window), width, height, ws=Workspace(), batch=batch,
                                    backs_last=True)
        assert len(listed) == (1 if batch is None else -(-len(fixed) // batch))
        listed.clear()
        np.testing.assert_array_equal(last.tri_index, in_order.tri_index)
        np.testing.assert_array_equal(last.depth, in_order.depth)


def band_lists(setup):
    """Each band's list read back from the set-up: the triangles of every chunk, in order."""
    n_bands = setup.band_listed.shape[0]
    return [[int(setup.band_listed[b, c * LIST_CHUNK + j]) for c in range(len(setup.tallies))
             for j in range(setup.tallies[c, 1 + b])] for b in range(n_bands)]


def owners(lo, hi, n_bands):
    """The bands that own a block of rows lo … hi (block j: band j mod n_bands)."""
    return {block % n_bands for block in range(lo // BLOCK_ROWS, hi // BLOCK_ROWS + 1)}


@pytest.mark.parametrize("n_bands", [1, 2, 3, 5])
def test_each_band_lists_the_triangles_with_rows_in_its_blocks_in_draw_order(n_bands):
    """2,500 triangles (three chunks) of a soup over 8 blocks of rows, some tall enough to reach
    every band, some in one block, many with no rows: band b's list is exactly, in draw order,
    the triangles with a row in a block of band b, whatever the number of bands."""
    fixed, window = soup(np.random.default_rng(11), 2500, 70, 8 * BLOCK_ROWS + 5)
    fixed[:40, 2, 1] = fixed[:40, 0, 1] + 7 * BLOCK_ROWS * 256  # tall: blocks of every band
    window[:40, 2, 1] = fixed[:40, 2, 1] / 256 + 0.5
    setup = set_up(fixed, window, 8 * BLOCK_ROWS + 5, False, n_bands=n_bands)
    rows = setup.rows
    drawn = rows[:, 0] <= rows[:, 1]
    assert len(setup.tallies) == 3 and 50 < (~drawn).sum() and (rows[:, 1] - rows[:, 0] >= 4 * BLOCK_ROWS).sum() > 10
    expected = [[k for k in np.flatnonzero(drawn) if b in owners(rows[k, 0], rows[k, 1], n_bands)]
                for b in range(n_bands)]
    assert band_lists(setup) == expected


@njit(cache=False)
def bands_of_blocks(blocks, n_bands):
    return [block_band(block, n_bands, 1.0 / n_bands) for block in blocks]


@pytest.mark.parametrize("n_bands", [1, 2, 3, 7, 49, 64, 103, 1000])
def test_a_block_s_band_by_the_reciprocal_is_the_remainder(n_bands):
    """block_band (a multiplication by 1 / B) is block mod B for every block below 2¹⁸ and
    for the largest ones it is asked of (up to 2³¹); among the B, 49 and 103, where block · (1 / B)
    falls below the quotient for some multiples of B (without the half block's margin)."""
    blocks = np.concatenate([np.arange(1 << 18), np.arange((1 << 31) - 5000, 1 << 31)]).astype(np.int64)
    np.testing.assert_array_equal(bands_of_blocks(blocks, n_bands), blocks % n_bands)
