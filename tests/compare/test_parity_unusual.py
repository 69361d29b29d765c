"""Unusual but valid input must render correctly, and as VTK draws it (issue 6).

One case per item of the issue (scenes in ``unusual_scenes.py``): degenerate and sliver
triangles, duplicate and unreferenced vertices, coordinates at 1e-6 and 1e6 scales,
inconsistent winding, open meshes, a camera inside a closed mesh, triangles crossing the
near plane, objects outside the view, zero-intensity lights and ``specular_power = 0``.
Each is drawn by both renderers and held to the parity bars, and its depth buffer to
VTK's (the depth shows that both fitted the same clipping range). Where VTK cannot be
matched for a reason of its own, the test says why and checks what can be checked.
"""
from __future__ import annotations

import numpy as np
import pytest

from compare.metrics import compare_frames, failed_bars
from compare.reference import render_reference
from renderer import render
from renderer.camera import view_to_clip, world_to_view
from renderer.shading import to_8bit

from .unusual_scenes import all_cases, build

# Largest window-depth difference to VTK on shared pixels: ours is rounded to 24 bits
# (6e-8), VTK's llvmpipe interpolates in float32. Measured ≤ 4.2e-6 on every case but the
# open tube, 1.4e-5, on its nearly edge-on side triangles. A different clipping range shows
# as far more: 0.27 when the unreferenced points still widened the fitted range.
DEPTH_TOLERANCE = 5e-5

EMPTY = ["outside/behind", "outside/beside", "outside/beyond-far", "outside/before-near"]
SPECIAL = {
    # VTK's float32 clipping of a 2e6-wide triangle puts its depth off by up to 1.8e-3
    # (the exact plane depth is known: test_huge_triangle_depth_is_exact_here_and_float32_in_vtk).
    "scales/huge-triangle",
    # coincident triangles of opposite winding: a depth tie that OpenGL leaves to the
    # implementation (test_triangles_turned_over_tie_only_where_they_coincide).
    "duplicates/phong-turned-over",
}


@pytest.fixture(scope="module")
def cases(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("unusual")
    return tmp, all_cases(tmp)


def case_names():
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as d:
        return list(all_cases(Path(d)))


NAMES = case_names()
PARITY = [n for n in NAMES if n not in EMPTY and n not in SPECIAL]


def draw(cases, name):
    tmp, data = cases
    scene = build(data[name], tmp)
    return scene, render(scene), render_reference(scene)


def test_every_item_of_the_issue_has_a_case():
    groups = {n.split("/")[0] for n in NAMES}
    assert groups == {"degenerate", "sliver", "duplicates", "unreferenced", "scales", "winding", "open", "inside",
                      "near-plane", "outside", "zero-lights", "power-zero", "power-over-128"}


@pytest.mark.parametrize("name", PARITY)
def test_unusual_scene_matches_vtk(cases, name):
    """Within the parity bars, and the same depth as VTK wherever both drew."""
    scene, ours, ref = draw(cases, name)
    m, _ = compare_frames(ours, ref)
    assert not failed_bars(m), (name, m)
    assert ours.coverage.any(), "the case should draw something"
    shared = ours.coverage & ref.coverage
    assert np.abs(ours.depth - ref.depth)[shared].max() <= DEPTH_TOLERANCE


@pytest.mark.parametrize("name", EMPTY)
def test_object_outside_the_view_gives_an_empty_image(cases, name):
    """Nothing in view: every pixel is the background, exactly, and VTK draws nothing either."""
    scene, ours, ref = draw(cases, name)
    background = to_8bit(np.asarray(scene.image.background))
    assert not ours.coverage.any() and not ref.coverage.any()
    assert (ours.rgb == background).all() and (ref.rgb == background).all()
    assert (ours.depth == 1.0).all()


def test_huge_triangle_depth_is_exact_here_and_float32_in_vtk(cases):
    """A triangle 2e6 across, crossing the near plane: colours and coverage within the bars.

    Its depth is not compared with VTK's: VTK clips and interpolates it in float32 and is
    off by up to 1.8e-3 (measured; 4.5e-5 at 2e4 across, 4e-8 at 200). Ours is checked
    against the exact depth of the plane y = −1 at each pixel centre instead.
    """
    scene, ours, ref = draw(cases, "scales/huge-triangle")
    m, _ = compare_frames(ours, ref)
    assert not failed_bars(m), m
    width, height = scene.image.size
    w2c = world_to_view(scene.camera) @ view_to_clip(scene.camera, width / height, scene.camera.clipping_range)
    rows, cols = np.nonzero(ours.coverage)
    x, y = (cols + 0.5) / width * 2 - 1, 1 - (rows + 0.5) / height * 2  # image rows: row 0 at the top
    ends = [np.column_stack([x, y, np.full_like(x, z), np.ones_like(x)]) @ np.linalg.inv(w2c) for z in (-1, 1)]
    p0, p1 = (e[:, :3] / e[:, 3:] for e in ends)
    t = (-1.0 - p0[:, 1]) / (p1[:, 1] - p0[:, 1])
    clip = np.column_stack([p0 + t[:, None] * (p1 - p0), np.ones_like(t)]) @ w2c
    exact = (clip[:, 2] / clip[:, 3] + 1) / 2
    assert np.abs(ours.depth[rows, cols] - exact).max() < 1e-7  # 24-bit rounding is 6e-8


def test_triangles_turned_over_tie_only_where_they_coincide(cases):
    """Triangles listed twice, the second time turned over (opposite winding), phong-shaded.

    Both copies have the same depth, so with LEQUAL the later one wins; it faces away,
    so its normal is flipped (two-sided lighting) and it is dark. We draw that on every
    pixel of the pair. llvmpipe interpolates depth from each triangle's first vertex in
    float32, and the copies start at different vertices, so on a few pixels VTK finds
    the later copy farther by one step and keeps the first: OpenGL promises the same depth
    only for the same vertices in the same order (its invariance rule), and with the same
    winding from another vertex (``phong-same-winding``) VTK and we agree exactly. So:
    coverage must match, and every pixel over ΔE 1 must lie on the turned-over pair.
    """
    tmp, data = cases
    scene, ours, ref = draw(cases, "duplicates/phong-turned-over")
    m, de = compare_frames(ours, ref)
    assert m["coverage_mismatch"] == 0.0
    # the footprint of the turned-over pair: the pixels those triangles win when drawn alone
    pair = scene.objects[0].mesh.triangles[-40:]
    footprint = render(_only_triangles(scene, pair)).coverage
    assert (de > 1)[~footprint].sum() == 0
    assert m["pixels_over_1"] < 0.01  # measured 0.72 %: 44 of 6112 pixels


def _only_triangles(scene, triangles):
    from dataclasses import replace

    from lab.mesh import Mesh

    obj = scene.objects[0]
    mesh = Mesh(obj.mesh.points, triangles, obj.mesh.point_normals)
    return replace(scene, objects=(replace(obj, mesh=mesh),))
