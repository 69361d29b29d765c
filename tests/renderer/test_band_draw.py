"""A band's share of the opaque raster (renderer/band_draw.py): in draw order without tiles;
with a tile z-buffer the front faces first, then the back faces, each in draw order, a back
face's block skipped where the tiles show it hidden; each block of rows a band's own; and
numba compiles a band kernel apart for each kind of ``tiles``.

The fill here is a log: each ``fill_stretch(k, top, bottom, …)`` the band makes is written
as a row of ``log`` (its row 0 holds the count), so the tests see which triangle's rows the
band asked for, in which order, and nothing else."""
from __future__ import annotations

import numpy as np
import pytest

from renderer.band_draw import draw_band_from_lists, draw_band_in_order, draw_band_listed
from renderer.bands import BLOCK_ROWS
from renderer.draw_lists import list_by_facing
from renderer.hidden_back_faces import NO_TILES, new_tiles
from renderer.jit import njit
from renderer.raster import set_up

from .test_hidden_back_faces import soup

WIDTH, HEIGHT = 70, 90


@njit(cache=False, inline="always")
def log_stretch(k, top, bottom, setup, rule, depth_test, first_index, depth, log):
    """A fill that notes ``(k, top, bottom)`` in ``log`` instead of drawing."""
    n = log[0, 0] + 1
    log[n, 0], log[n, 1], log[n, 2] = k, top, bottom
    log[0, 0] = n


@njit(cache=False)
def band_log(b, n_bands, setup, tiles, depth, log):
    """Band ``b``'s stretches, chosen as the raster's band kernels choose (on ``tiles is None``)."""
    log[0, 0] = 0
    deal, rules, buffer = (n_bands, BLOCK_ROWS), (0, True, 0), (depth, log)
    if tiles is None:
        draw_band_in_order(b, setup, deal, rules, buffer, log_stretch)
    else:
        draw_band_listed(b, setup, deal, rules, buffer, log_stretch, tiles)
    return log[1:log[0, 0] + 1].copy()


@njit(cache=False)
def band_log_from_lists(b, n_bands, setup, depth, log):
    """Band ``b``'s stretches drawn from its own list (as the dividing kernel draws)."""
    log[0, 0] = 0
    draw_band_from_lists(b, setup, (n_bands, BLOCK_ROWS), (0, True, 0), (depth, log), log_stretch)
    return log[1:log[0, 0] + 1].copy()


def blocks_of(setup, ks, b, n_bands):
    """What a band should ask for: each triangle of ``ks``'s rows in the blocks band ``b`` owns."""
    out = []
    for k in ks:
        lo, hi = setup.rows[k]
        for block in range(lo // BLOCK_ROWS, hi // BLOCK_ROWS + 1):
            if block % n_bands == b:
                out.append((k, max(lo, block * BLOCK_ROWS), min(hi, block * BLOCK_ROWS + BLOCK_ROWS - 1)))
    return out


@pytest.fixture(scope="module")
def batch():
    fixed, window = soup(np.random.default_rng(5), 1500, WIDTH, HEIGHT)
    setup = set_up(fixed, window, HEIGHT, False)
    list_by_facing(setup.rows, setup.front, setup.listed, setup.counts)
    drawn = setup.rows[:, 0] <= setup.rows[:, 1]
    assert 100 < (drawn & setup.front).sum() and 100 < (drawn & ~setup.front).sum()
    return setup, drawn


def run(setup, tiles, n_bands):
    depth = np.zeros((HEIGHT, WIDTH), np.int32)
    log = np.zeros((2 * len(setup.front) * (HEIGHT // BLOCK_ROWS + 2), 3), np.int32)
    return [[tuple(row) for row in band_log(b, n_bands, setup, tiles, depth, log)] for b in range(n_bands)]


@pytest.mark.parametrize("n_bands", [1, 3])
def test_without_tiles_a_band_draws_every_triangle_with_rows_in_draw_order(batch, n_bands):
    setup, drawn = batch
    for b, got in enumerate(run(setup, NO_TILES, n_bands)):
        assert got == blocks_of(setup, np.flatnonzero(drawn), b, n_bands)


@pytest.mark.parametrize("n_bands", [1, 2, 3])
def test_from_its_list_a_band_draws_the_same_stretches_in_the_same_order(n_bands):
    """The set-up's list of each band's triangles (made for these bands): the band asks for
    what it asks for going over every triangle, in the same order."""
    fixed, window = soup(np.random.default_rng(5), 1500, WIDTH, HEIGHT)
    setup = set_up(fixed, window, HEIGHT, False, n_bands=n_bands)
    drawn = setup.rows[:, 0] <= setup.rows[:, 1]
    depth = np.zeros((HEIGHT, WIDTH), np.int32)
    log = np.zeros((2 * len(setup.front) * (HEIGHT // BLOCK_ROWS + 2), 3), np.int32)
    for b in range(n_bands):
        got = [tuple(row) for row in band_log_from_lists(b, n_bands, setup, depth, log)]
        assert got == blocks_of(setup, np.flatnonzero(drawn), b, n_bands) and len(got) > 100


@pytest.mark.parametrize("n_bands", [1, 3])
def test_with_tiles_a_band_draws_the_front_faces_then_the_back_faces(batch, n_bands):
    """Tiles worked out for this batch (0) and deeper than any fragment hide nothing: every
    block is drawn, the front faces' first, each kind in draw order."""
    setup, drawn = batch
    tiles = new_tiles(HEIGHT, WIDTH)
    tiles[0], tiles[1] = 1 << 24, 0
    for b, got in enumerate(run(setup, tiles, n_bands)):
        assert got == (blocks_of(setup, np.flatnonzero(drawn & setup.front), b, n_bands)
                       + blocks_of(setup, np.flatnonzero(drawn & ~setup.front), b, n_bands))


def test_tiles_nearer_than_every_fragment_hide_every_back_face_and_no_front_face(batch):
    setup, drawn = batch
    tiles = new_tiles(HEIGHT, WIDTH)
    tiles[0], tiles[1] = -1, 0
    for b, got in enumerate(run(setup, tiles, 2)):
        assert got == blocks_of(setup, np.flatnonzero(drawn & setup.front), b, 2)


@pytest.mark.parametrize("walking", [False, True])
def test_the_raster_s_band_kernels_are_compiled_apart_for_no_tiles_and_for_tiles(monkeypatch, walking):
    """The choice of loop is numba's, from the type of ``tiles``: a frame drawn in order and
    one drawn back faces last leave the raster kernel with two compiled versions, one for
    None and one for the tile z-buffer, and so its band kernel too. (The parallel kernel's
    versions are asked for: a band kernel's are listed only where it was compiled in this
    process, not where its caller came from the kernel cache.)"""
    from renderer import raster

    monkeypatch.setattr(raster, "TALL_ROWS", 0 if walking else 10**9)
    monkeypatch.setattr(raster, "BACKS_LAST_ROWS", 0)
    fixed, window = soup(np.random.default_rng(5), 300, WIDTH, HEIGHT)
    for backs_last in (False, True):
        raster.rasterize_visibility(raster.whole_triangles(fixed, window), WIDTH, HEIGHT, backs_last=backs_last)
    kernel = raster.rasterize_walking if walking else raster.rasterize
    kinds = sorted(str(sig[-1]) for sig in kernel.signatures)
    assert len(kinds) == 2 and kinds[1] == "none" and kinds[0].startswith("array(int32, 3d")
