"""Coverage agrees with VTK on random valid scenes and random triangle soups (hypothesis).

Colours are the parity tests' business (``test_parity*.py``); here the claim is about
geometry only: whatever the scene, the pixels we draw are the pixels VTK draws, within
the coverage bar. Random scenes have small images (16–80 px a side, at most 6400 pixels),
where the bar of 0.02 % allows at most one pixel. Examples are fewer than in the
renderer's properties, since each one is a VTK render (profiles: ``tests/conftest.py``).
"""
from __future__ import annotations

from hypothesis import given, settings

from compare.metrics import PARITY_BARS, measure
from compare.reference import render_reference
from renderer import render

from ..scene_strategies import any_scene

VTK_EXAMPLES = max(10, settings.default.max_examples * 3 // 4)


@settings(max_examples=VTK_EXAMPLES)
@given(any_scene())
def test_coverage_matches_vtk(scene):
    """Coverage mismatch within the bar (0.02 % of the pixels)."""
    m = measure(render(scene), render_reference(scene))
    assert m["coverage_mismatch"] <= PARITY_BARS["coverage_mismatch"], m


def test_a_cut_edge_through_a_pixel_centre_moves_as_llvmpipe_moves_it():
    """Found by the thorough profile. A thin triangle with corners on pixel centres (0, 0),
    (1, −4), (−1, 6) — in pixels, y up, 16×16 — has pixel centre (0, 1) exactly on its right
    edge. Inside the image (moved by whole pixels) the top-left rule leaves it out. Poking
    out past the border, the triangle is cut at the viewport and the new corners are
    snapped to 1/256 pixel, which moves the cut edge just past that centre: llvmpipe (no
    guard band) then draws it, and so do we, since we cut at the viewport too."""
    import numpy as np

    from lab.mesh import Mesh
    from lab.scene import Camera, Image, Scene, SceneObject, headlight

    def coverage(shift):
        c = np.array([[0, 0], [1, -4], [-1, 6]]) + shift
        pts = np.column_stack([(c + 0.5) * 2 / 16 - 1, -np.ones(3)])
        scene = Scene(image=Image(size=(16, 16)), lights=(headlight(),),
                      camera=Camera(position=(0, 0, 5.0), parallel=True, parallel_scale=1.0,
                                    clipping_range=(1.0, 10.0)),
                      objects=(SceneObject(mesh=Mesh(pts, np.array([[0, 1, 2]]))),))
        return render(scene).coverage[::-1], render_reference(scene).coverage[::-1]  # window rows, y up

    ours, vtk = coverage((4, 5))
    assert (ours == vtk).all() and ours[5, 4] and not ours[6, 4]  # inside the image: the top-left rule
    ours, vtk = coverage((0, 0))
    assert (ours == vtk).all() and ours[0, 0] and ours[1, 0]  # cut at the border: the centre is in
