"""Back faces drawn last behind a tile z-buffer (renderer/hidden_back_faces.py): the same
buffer as drawing in order, on triangle soups made for ties and overdraw and on scenes
seen from outside, from inside and in a mirror; and hidden ones really are skipped."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from lab import load_scene
from lab.mesh import Mesh
from lab.presets import preset_names
from renderer import RenderOptions, render
from renderer.window import SUBPIXEL


def soup(rng, n, width, height):
    """``n`` triangles (fixed (n, 3, 2), window (n, 3, 3)): big ones near the viewer over
    small and large ones behind, half of each kind wound clockwise (back faces), some
    repeated with the winding turned and the same depths (exact ties), some steep in depth."""
    size = max(width, height)
    fixed = rng.integers(-2 * SUBPIXEL, (size + 2) * SUBPIXEL, (n, 3, 2))
    small = rng.random(n) < 0.5
    centre = rng.integers(0, size * SUBPIXEL, (n, 1, 2))
    fixed[small] = centre[small] + rng.integers(-3 * SUBPIXEL, 3 * SUBPIXEL, (int(small.sum()), 3, 2))
    z = rng.uniform(0.3, 1.0, (n, 3))
    near = rng.random(n) < 0.2
    z[near] = rng.uniform(0.0, 0.1, (int(near.sum()), 3))
    steep = rng.random(n) < 0.1
    z[steep] = np.stack([np.zeros(int(steep.sum())), np.ones(int(steep.sum())), rng.random(int(steep.sum()))], 1)
    twins = rng.choice(n, n // 8, replace=False)
    fixed = np.concatenate([fixed, fixed[twins][:, ::-1]])
    z = np.concatenate([z, z[twins][:, ::-1]])
    window = np.concatenate([fixed / SUBPIXEL + 0.5, z[..., None]], axis=2)
    return fixed.astype(np.int64), window


@pytest.mark.parametrize("batch", [None, 13])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_back_faces_drawn_last_fill_the_buffer_drawing_in_order_fills(monkeypatch, seed, batch):
    """Every batch's back faces drawn after its front faces, the hidden ones skipped: the same
    depth and triangle at every pixel as one pass in order, ties and all, with both raster
    kernels (small and tall triangles) and with the batches each set up apart; and the tiles
    were consulted."""
    from renderer import raster
    from renderer.raster import rasterize_visibility
    from renderer.indexed_triangles import whole_triangles
    from renderer.workspace import Workspace

    monkeypatch.setattr(raster, "BACKS_LAST_ROWS", 0)  # every batch, small triangles too
    width, height = 70, 53
    fixed, window = soup(np.random.default_rng(seed), 300, width, height)
    ws = Workspace()
    for tall in (False, True):
        monkeypatch.setattr(raster, "TALL_ROWS", 0 if tall else 10**9)
        in_order = rasterize_visibility(whole_triangles(fixed, window), width, height, batch=batch)
        backs_last = rasterize_visibility(whole_triangles(fixed, window), width, height, ws=ws, batch=batch,
                                          backs_last=True)
        np.testing.assert_array_equal(backs_last.tri_index, in_order.tri_index)
        np.testing.assert_array_equal(backs_last.depth, in_order.depth)
        np.testing.assert_array_equal(backs_last.covered, in_order.covered)
        assert (ws.array("raster.tiles", (2, 4, 5), np.int32)[1] >= 0).any()
    shown = np.unique(in_order.tri_index[in_order.covered])
    e1, e2 = fixed[:, 1] - fixed[:, 0], fixed[:, 2] - fixed[:, 0]
    area = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]
    assert (area[shown] < 0).sum() > 10 and (area[shown] > 0).sum() > 10  # back and front faces both win pixels


def test_the_floor_is_no_deeper_than_any_fragment_of_the_triangle():
    """fragment_depth_floor is at or below the depth of every pixel each of 400 triangles
    (steep ones included) draws alone, and close to the nearest of them."""
    from renderer.hidden_back_faces import fragment_depth_floor
    from renderer.raster import rasterize_visibility, set_up
    from renderer.indexed_triangles import whole_triangles

    fixed, window = soup(np.random.default_rng(7), 400, 40, 30)
    setup = set_up(fixed, window, 30, False)
    gaps = []
    for k in range(len(fixed)):
        vis = rasterize_visibility(whole_triangles(fixed[k:k + 1], window[k:k + 1]), 40, 30)
        if vis.covered.any():
            floor = fragment_depth_floor(setup.ccw[k], setup.plane[k])
            assert floor <= vis.depth[vis.covered].min(), k
            gaps.append(int(vis.depth[vis.covered].min()) - floor)
    assert len(gaps) > 200 and np.median(gaps) < 2**24 // 8


def test_a_tile_holds_its_deepest_pixel_worked_out_once_a_batch():
    from renderer.hidden_back_faces import TILE, hidden_in_tiles, new_tiles, tile_depth

    depth = np.full((2 * TILE, 3 * TILE), 100, np.int32)
    depth[TILE + 3, 2 * TILE + 5] = 900
    tiles = new_tiles(*depth.shape)
    assert tiles.shape == (2, 2, 3) and (tiles[1] == -1).all()
    assert tile_depth(1, 2, 0, depth, tiles) == 900 and tile_depth(0, 2, 0, depth, tiles) == 100
    depth[TILE + 3, 2 * TILE + 5] = 50
    assert tile_depth(1, 2, 0, depth, tiles) == 900, "kept for the batch"
    assert tile_depth(1, 2, 7, depth, tiles) == 100, "worked out again for the next"
    f = np.array([[0, 0], [5 * SUBPIXEL, 0], [0, 5 * SUBPIXEL]], np.int64)  # columns 0 … 5: tile column 0
    assert hidden_in_tiles(np.int32(101), f, 0, 5, 7, depth, tiles)
    assert not hidden_in_tiles(np.int32(100), f, 0, 5, 7, depth, tiles), "a tie is not hidden"
    wide = f * 8  # columns 0 … 40: tile columns 0 … 2
    depth[2, 2 * TILE + 1] = 500
    assert not hidden_in_tiles(np.int32(101), wide, 0, 5, 8, depth, tiles)


def inside_the_sphere():
    """An icosphere seen from its centre: every face the camera sees is a back face."""
    scene = load_scene("icosphere:level=3").with_overrides(size=(96, 80))
    return replace(scene, camera=replace(scene.camera, position=(0.0, 0.0, 0.2), focal_point=(0.0, 0.0, -1.0),
                                         clipping_range=(0.01, 10.0)))


def in_a_mirror():
    scene = load_scene("icosphere:level=3").with_overrides(size=(96, 80))
    return replace(scene, objects=tuple(replace(o, model_to_world=np.diag([-1.0, 1.0, 1.0, 1.0]) @ o.model_to_world)
                                        for o in scene.objects))


@pytest.mark.parametrize("case", [*preset_names(), "inside the sphere", "in a mirror"])
def test_a_frame_with_back_faces_last_is_the_frame_drawn_in_order(monkeypatch, case):
    """The whole pipeline, back faces last or not, for every preset, for a closed surface seen
    from inside (nothing is hidden there: a wrong skip leaves a hole) and in a mirror, with
    the raster asked to put back faces last in every batch: the same bytes."""
    from renderer import raster

    monkeypatch.setattr(raster, "BACKS_LAST_ROWS", 0)
    scene = {"inside the sphere": inside_the_sphere, "in a mirror": in_a_mirror}.get(case, lambda: load_scene(case))()
    plain, fast = render(scene, RenderOptions(backs_last=False)), render(scene)
    assert 0.03 < plain.coverage.mean()
    for name in ("rgb", "depth", "coverage"):
        np.testing.assert_array_equal(getattr(fast, name), getattr(plain, name), err_msg=name)


def test_the_pipeline_asks_for_back_faces_last_with_the_z_buffer_on(monkeypatch):
    """Closed or open, unless told not to; not for the painter's algorithm (no depth test) or
    with back faces culled (none left to draw last)."""
    from renderer import pipeline

    asked = []
    real = pipeline.rasterize_visibility

    def spy(*args, **kwargs):
        asked.append(kwargs["backs_last"])
        return real(*args, **kwargs)

    monkeypatch.setattr(pipeline, "rasterize_visibility", spy)
    sphere = load_scene("icosphere:level=2").with_overrides(size=(32, 32))
    render(sphere)
    render(sphere, RenderOptions(backs_last=False))
    render(replace(sphere, render=replace(sphere.render, hidden_surface="painter")))
    render(replace(sphere, render=replace(sphere.render, cull_backfaces=True)))
    mesh = sphere.objects[0].mesh
    render(replace(sphere, objects=(replace(sphere.objects[0], mesh=Mesh(mesh.points, mesh.triangles[1:])),)))
    assert asked == [True, False, False, False, True]


@pytest.mark.parametrize("walking", [False, True])
def test_a_back_face_the_tiles_call_hidden_is_not_drawn(walking):
    """The raster kernels consult the tiles for back faces only: with tiles that (falsely) hold
    a depth nearer than any (−1) everywhere for this batch, every back face is skipped and
    every front face drawn; with no tiles the back faces show. With tiles the kernels read
    the triangles from their lists by facing (renderer/draw_lists.py), made first."""
    from renderer.bands import raster_bands
    from renderer.hidden_back_faces import NO_TILES, new_tiles
    from renderer.draw_lists import list_by_facing
    from renderer.raster import FIRST_BATCH, LAST_BATCH, rasterize, rasterize_walking, set_up

    width, height = 70, 53
    fixed, window = soup(np.random.default_rng(3), 200, width, height)
    setup = set_up(fixed, window, height, False, n_bands=raster_bands(height))
    list_by_facing(setup.rows, setup.front, setup.listed, setup.counts)
    kernel = rasterize_walking if walking else rasterize
    shown = {}
    for case in ("plain", "lying tiles"):
        tiles = NO_TILES if case == "plain" else new_tiles(height, width)
        if tiles is not NO_TILES:
            tiles[0], tiles[1] = -1, 0  # every tile "worked out" for batch 0, nearer than any fragment
        depth, tri_index = np.empty((height, width), np.int32), np.empty((height, width), np.int32)
        kernel(setup, 0, True, 0, FIRST_BATCH | LAST_BATCH, depth, tri_index,
               np.empty((height, width), np.bool_), tiles)
        won = np.unique(tri_index[tri_index >= 0])
        shown[case] = (setup.front[won].sum(), (~setup.front[won]).sum())
    assert shown["plain"][1] > 10 and shown["lying tiles"][1] == 0
    assert shown["lying tiles"][0] >= shown["plain"][0] > 10


def test_the_deepest_of_a_stretch_of_a_row_is_its_largest_depth_and_0_for_none():
    from renderer.hidden_back_faces import deepest_in_row

    row = np.random.default_rng(3).integers(0, 1 << 24, 100).astype(np.int32)
    for first, end in [(0, 100), (3, 19), (17, 18), (96, 100), (40, 40)]:
        assert deepest_in_row(row, first, end) == (row[first:end].max() if end > first else 0)


def small_soup(rng, n, width, height):
    """``n`` small triangles (about two rows each) at random depths over the image, half of
    them wound clockwise, with their windows (see :func:`soup`)."""
    centre = rng.integers(0, min(width, height) * SUBPIXEL, (n, 1, 2))
    fixed = centre + rng.integers(-2 * SUBPIXEL, 2 * SUBPIXEL, (n, 3, 2))
    z = rng.uniform(0.0, 1.0, (n, 3))
    window = np.concatenate([fixed / SUBPIXEL + 0.5, z[..., None]], axis=2)
    return fixed.astype(np.int64), window


def test_a_lone_batch_draws_its_back_faces_last_however_few_rows_its_triangles_span(monkeypatch):
    """Triangles of about two rows (under BACKS_LAST_ROWS, over LONE_ROWS): drawn as one batch
    of more than BATCH with back faces last, the raster consults the tiles; drawn in batches,
    or as a batch no larger than BATCH, it does not. Each fills the buffer drawing in order fills."""
    from renderer import raster
    from renderer.hidden_back_faces import BACKS_LAST_ROWS
    from renderer.indexed_triangles import whole_triangles
    from renderer.pixel_centres import LONE_ROWS
    from renderer.raster import mean_rows, rasterize_visibility, set_up
    from renderer.workspace import Workspace

    width, height = 64, 48
    fixed, window = small_soup(np.random.default_rng(3), 3000, width, height)
    assert LONE_ROWS <= mean_rows(set_up(fixed, window, height, False)) < BACKS_LAST_ROWS
    in_order = rasterize_visibility(whole_triangles(fixed, window), width, height)
    for lone, batch, consulted in ((1000, None, True), (1000, len(fixed), True), (1000, 500, False),
                                   (len(fixed), None, False)):
        monkeypatch.setattr(raster, "BATCH", lone)
        ws = Workspace()
        vis = rasterize_visibility(whole_triangles(fixed, window), width, height, ws=ws, batch=batch, backs_last=True)
        tiles = ws.array("raster.tiles", (2, 3, 4), np.int32)
        assert (tiles[1] >= 0).any() == consulted, batch
        for name in ("tri_index", "depth", "covered"):
            np.testing.assert_array_equal(getattr(vis, name), getattr(in_order, name), err_msg=f"{batch} {name}")
