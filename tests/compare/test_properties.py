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


def test_known_difference_an_edge_through_a_pixel_centre_past_the_viewport():
    """Found by the thorough profile, not fixed: a thin triangle with corners on pixel
    centres (0, 0), (1, −4), (−1, 6) — in pixels, y up, 16×16 — has pixel centre (0, 1)
    exactly on its right edge. We leave it out (top-left rule), and so does VTK when the
    same triangle is moved whole pixels into the image; where it pokes out past the left
    border, llvmpipe draws that pixel. Its handling of triangles crossing the viewport
    edge is not modelled yet, so the two differ by that one pixel."""
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
    assert (ours == vtk).all() and ours[5, 4] and not ours[6, 4]  # inside the image: the same pixels
    ours, vtk = coverage((0, 0))
    assert ours[0, 0] and not ours[1, 0]
    assert vtk[1, 0]  # llvmpipe's extra pixel at the viewport's edge
